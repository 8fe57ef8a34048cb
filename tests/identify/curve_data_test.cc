#include "musclesim/identify/curve_data.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/identify/identify.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

// The message CheckedCurve gives for columns x, y (source "active"), or "accepted".
std::string MemoryError(const std::vector<double>& x, const std::vector<double>& y,
                        std::size_t min_points = 4) {
  try {
    CheckedCurve("active", x, y, "length", "tension", min_points);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// The same columns written to a CSV (one header line, so row r is on line r + 1) and read by
// ReadCurveCsv, its message with the location written as CheckedCurve writes it: the rules
// shared, only the place named differently.
std::string CsvError(const std::vector<double>& x, const std::vector<double>& y,
                     std::size_t min_points = 4) {
  std::string text = "length,tension\n";
  for (std::size_t i = 0; i < x.size(); ++i) {
    text += FormatNumber(x[i]) + "," + FormatNumber(y[i]) + "\n";
  }
  const std::string path = testing::WriteTempFile("curve.csv", text);
  std::string message =
      testing::InputErrorOf(path, [&] { ReadCurveCsv(path, "length", "tension", min_points); });
  if (message.rfind("FILE:", 0) == 0 && std::isdigit(static_cast<unsigned char>(message[5]))) {
    const std::size_t end = message.find(": ", 5);
    const int line = std::stoi(message.substr(5, end - 5));
    return "active: row " + std::to_string(line - 1) + message.substr(end);
  }
  if (message.rfind("FILE", 0) == 0) return "active" + message.substr(4);
  return message;
}

TEST(CheckedCurve, KeepsThePointsInOrder) {
  const std::vector<DataPoint> data =
      CheckedCurve("passive", {0.1, 0.2, 0.3, 0.4}, {0.0, 1.0, -2.0, 3.0}, "length", "tension", 4);
  ASSERT_EQ(data.size(), 4u);
  EXPECT_EQ(data[2].x, 0.3);
  EXPECT_EQ(data[2].y, -2.0);  // a negative tension is data (noise), not an error
}

TEST(CheckedCurve, NamesSourceRowAndRule) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(MemoryError({0.1, 0.2}, {1, 2}), "active: too few points: 2, need at least 4");
  EXPECT_EQ(MemoryError({0.1, 0.2, 0.3, 0.4}, {1, nan, 1, 1}),
            "active: row 2: length = 0.2, tension = nan: values must be finite");
  EXPECT_EQ(MemoryError({0.1, 0.3, 0.2, 0.4}, {1, 2, 1, 1}),
            "active: row 3: length = 0.2 is not greater than the row before (0.3): rows must be "
            "sorted by length, without duplicates");
  EXPECT_EQ(MemoryError({0.1, 0.1, 0.2, 0.4}, {1, 2, 1, 1}),
            "active: row 2: length = 0.1 is not greater than the row before (0.1): rows must be "
            "sorted by length, without duplicates");
  EXPECT_EQ(MemoryError({0.1, 0.2, 0.3, 0.4}, {0, 0, 0, 0}),
            "active: every tension is zero: nothing to fit");
  EXPECT_EQ(MemoryError({0.1, 0.2, 0.3}, {1, 2}),
            "active: 3 length values and 2 tension values: give one tension per length");
}

TEST(CheckedCurve, RefusesWhatTheCsvReaderRefusesInItsWords) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::vector<double>, std::vector<double>>> cases = {
      {{0.1, 0.2}, {1, 2}},                    // too few
      {{0.1, 0.2, 0.3, 0.4}, {1, 1, nan, 1}},  // not finite
      {{0.1, 0.3, 0.2, 0.4}, {1, 2, 1, 1}},    // unsorted
      {{0.1, 0.2, 0.2, 0.4}, {1, 2, 1, 1}},    // duplicated
      {{0.1, 0.2, 0.3, 0.4}, {0, 0, 0, 0}},    // zero everywhere
      {{0.1, 0.2, 0.3, 0.4}, {0, 1, 0, 0}},    // accepted by both
  };
  for (const auto& [x, y] : cases) {
    EXPECT_EQ(MemoryError(x, y), CsvError(x, y)) << FormatNumber(x[1]);
  }
}

TEST(CheckedCurve, FewestPointsAreParametersPlusOne) {
  EXPECT_EQ(kMinPassivePoints, 4u);   // k_p, alpha, slack_length
  EXPECT_EQ(MinActivePoints(1), 4u);  // a, b, d
  EXPECT_EQ(MinActivePoints(12), 37u);
  EXPECT_EQ(MinVelocityPoints(false), 3u);  // f_iso, v_max
  EXPECT_EQ(MinVelocityPoints(true), 2u);   // v_max
}

}  // namespace
}  // namespace musclesim
