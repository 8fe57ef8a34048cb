#include "musclesim/io/readers/csv_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

using ::testing::ElementsAre;

// Writes `text` to a file named after the running test under TEST_TMPDIR and reads it.
std::string WriteCsv(const std::string& text) {
  const std::string path = ::testing::TempDir() + "csv_table_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The InputError message of reading `text`, the file's path shown as FILE.
std::string ReadError(const std::string& text) {
  const std::string path = WriteCsv(text);
  try {
    ReadCsv(path);
  } catch (const InputError& e) {
    std::string message = e.what();
    if (message.rfind(path, 0) == 0) message.replace(0, path.size(), "FILE");
    return message;
  }
  return "accepted";
}

TEST(CsvTable, ReadsHeaderRowsAndTheirLineNumbers) {
  const CsvTable table = ReadCsv(WriteCsv("t,length\n0,0.1\n0.5,0.09\n"));
  EXPECT_THAT(table.header, ElementsAre("t", "length"));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_THAT(table.rows[1], ElementsAre("0.5", "0.09"));
  EXPECT_THAT(table.lines, ElementsAre(2u, 3u));
  EXPECT_EQ(table.Find("length"), 1);
  EXPECT_EQ(table.Find("phase"), -1);
}

TEST(CsvTable, QuotedFieldsKeepCommasAndDoubledQuotes) {
  // RFC 4180: a quoted field may hold commas; "" inside it is one quote
  const CsvTable table =
      ReadCsv(WriteCsv("index,message,status\n"
                       "0,\"CVODE failed at t = 0.1, flag \"\"CV_TOO_MUCH_WORK\"\"\",failed\n"
                       "1,\"\",ok\n"
                       "2,plain,\"ok\"\n"));
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_THAT(table.rows[0],
              ElementsAre("0", "CVODE failed at t = 0.1, flag \"CV_TOO_MUCH_WORK\"", "failed"));
  EXPECT_THAT(table.rows[1], ElementsAre("1", "", "ok"));
  EXPECT_THAT(table.rows[2], ElementsAre("2", "plain", "ok"));
}

TEST(CsvTable, SkipsCommentsAndBlankLinesAndCarriageReturns) {
  const CsvTable table =
      ReadCsv(WriteCsv("# source: a paper\n"
                       "\n"
                       "length,tension\r\n"
                       "# a comment between rows\n"
                       "0.1,1\r\n"
                       "\r\n"
                       "0.2,2\n"));
  EXPECT_THAT(table.header, ElementsAre("length", "tension"));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_THAT(table.rows[0], ElementsAre("0.1", "1"));
  EXPECT_THAT(table.rows[1], ElementsAre("0.2", "2"));
  EXPECT_THAT(table.lines, ElementsAre(5u, 7u));  // the file's own line numbers
}

TEST(CsvTable, RejectsAWrongFieldCountNamingTheLine) {
  EXPECT_EQ(ReadError("a,b\n1,2\n# note\n1,2,3\n"), "FILE:4: 3 fields where the header has 2");
  EXPECT_EQ(ReadError("a,b\n1\n"), "FILE:2: 1 fields where the header has 2");
  // a comma inside quotes is not a separator
  EXPECT_EQ(ReadError("a,b\n\"1,2\"\n"), "FILE:2: 1 fields where the header has 2");
}

TEST(CsvTable, RejectsMissingAndEmptyFiles) {
  EXPECT_EQ(ReadError(""), "FILE: empty file, no header");
  EXPECT_EQ(ReadError("# only a comment\n\n"), "FILE: empty file, no header");
  const std::string missing = ::testing::TempDir() + "csv_table_no_such_file.csv";
  EXPECT_THAT([&] { ReadCsv(missing); }, ::testing::ThrowsMessage<InputError>(::testing::HasSubstr(
                                             missing + ": cannot open the file for reading")));
}

TEST(CsvTable, NumberParsesEveryFormADoubleIsWrittenIn) {
  const CsvTable table =
      ReadCsv(WriteCsv("x\n0.10000000000000001\n-1e-300\n1.7976931348623157e308\n-0\n42\n"));
  EXPECT_EQ(table.Number(0, 0), 0.1);
  EXPECT_EQ(table.Number(1, 0), -1e-300);
  EXPECT_EQ(table.Number(2, 0), 1.7976931348623157e308);
  EXPECT_EQ(table.Number(3, 0), 0.0);
  EXPECT_EQ(table.Number(4, 0), 42.0);
}

// The writers print every double with 17 digits (FormatFull), subnormal ones included, and
// this reader is for the files they write: each number must read back.
TEST(CsvTable, NumberReadsBackTheSubnormalNumbersTheWritersPrint) {
  const CsvTable table =
      ReadCsv(WriteCsv("x\n4.9406564584124654e-324\n-9.9999999999999694e-311\n"));
  EXPECT_EQ(table.Number(0, 0), 4.9406564584124654e-324);
  EXPECT_EQ(table.Number(1, 0), -1e-310);  // printed by %.17g as the line above
}

TEST(CsvTable, NumberRejectsTextNamingFileLineAndColumn) {
  const std::string path = WriteCsv("length,tension\n0.1,heavy\n0.2,\n0.3,1.5x\n0.4,1e999\n");
  const CsvTable table = ReadCsv(path);
  const auto error = [&](std::size_t row) {
    try {
      table.Number(row, 1);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error(0), path + ":2: column tension = 'heavy': must be a number");
  EXPECT_EQ(error(1), path + ":3: column tension = '': must be a number");
  EXPECT_EQ(error(2), path + ":4: column tension = '1.5x': must be a number");
  EXPECT_EQ(error(3), path + ":5: column tension = '1e999': must be a number");  // overflow
}

TEST(CsvTable, RequireNamesEveryMissingColumn) {
  const CsvTable table = ReadCsv(WriteCsv("t,length\n0,0.1\n"));
  EXPECT_NO_THROW(table.Require({"t", "length"}, "a trajectory"));
  EXPECT_THAT(
      [&] {
        table.Require({"t", "phase", "load"}, "a trajectory");
      },
      ::testing::ThrowsMessage<InputError>(
          ::testing::EndsWith(": missing columns: phase, load (a trajectory)")));
}

}  // namespace
}  // namespace musclesim
