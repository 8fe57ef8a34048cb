// InputError as data: each form's message written from the fault's fields, and the fields
// kept through a context, a head and a relocation.
#include <gtest/gtest.h>

#include <string>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

TEST(InputErrorTest, PlacesAreWrittenToTheirPrecision) {
  EXPECT_EQ(PlaceText({"a.yaml", 3, 7}), "a.yaml:3:7");
  EXPECT_EQ(PlaceText({"data.csv", 12}), "data.csv:12");  // a row: no column
  EXPECT_EQ(PlaceText({"--set"}), "--set");
  EXPECT_FALSE(InputPlace{"--set"}.positioned());
}

TEST(InputErrorTest, TheStandardFormNamesKeyValuePlaceAndRule) {
  const InputError e(
      InputFault{InputPlace{"s.yaml", 4, 9}, "model.velocity.n", "0", "must be an integer >= 1"});
  EXPECT_STREQ(e.what(), "model.velocity.n = 0 (s.yaml:4:9): must be an integer >= 1");
  EXPECT_EQ(e.fault().key, "model.velocity.n");
  EXPECT_EQ(e.fault().value, "0");
  EXPECT_EQ(e.fault().place->line, 4);
  EXPECT_EQ(e.fault().place->column, 9);
  EXPECT_EQ(e.fault().rule, "must be an integer >= 1");
}

TEST(InputErrorTest, MissingPartsLeaveTheirPlaceInTheMessage) {
  EXPECT_STREQ(InputError(InputFault{InputPlace{"s.yaml", 2, 1}, "load[0].aftr", std::nullopt,
                                     "unknown key"})
                   .what(),
               "load[0].aftr (s.yaml:2:1): unknown key");
  EXPECT_STREQ(
      InputError(InputFault{InputPlace{"s.yaml", 1, 1}, "", "[1]", "must be a map"}).what(),
      "(top level) = [1] (s.yaml:1:1): must be a map");
  EXPECT_STREQ(
      InputError(InputFault{InputPlace{"s.yaml", 5, 3}, "", std::nullopt, "YAML syntax error"})
          .what(),
      "s.yaml:5:3: YAML syntax error");
  EXPECT_STREQ(
      InputError(InputFault{std::nullopt, "controls", std::nullopt, "at least one"}).what(),
      "controls: at least one");
}

TEST(InputErrorTest, AHeadLeadsTheRuleAndTheFieldsStay) {
  const InputError e("--set model.nothing.n=3: ",
                     InputFault{InputPlace{"--set"}, "model.nothing.n", "3", "does not exist"});
  EXPECT_STREQ(e.what(), "--set model.nothing.n=3: does not exist");
  EXPECT_EQ(e.fault().key, "model.nothing.n");
  EXPECT_FALSE(e.fault().place->positioned());
}

TEST(InputErrorTest, AContextKeepsTheInnerFault) {
  const InputError inner(InputFault{InputPlace{"d.csv", 3}, "", std::nullopt, "t = nan"});
  const InputError outer("series[0].csv = d.csv (d.yaml:4:10)", inner);
  EXPECT_STREQ(outer.what(), "series[0].csv = d.csv (d.yaml:4:10): d.csv:3: t = nan");
  EXPECT_EQ(outer.fault().place->file, "d.csv");
  EXPECT_EQ(outer.fault().place->line, 3);
  // and a second context goes before the first
  const InputError outermost("muscle 'a'", outer);
  EXPECT_STREQ(outermost.what(),
               "muscle 'a': series[0].csv = d.csv (d.yaml:4:10): d.csv:3: t = nan");
}

TEST(InputErrorTest, RelocatingRewritesThePlaceInTheSameForm) {
  const InputError found(
      InputFault{InputPlace{"b.yaml", 1, 1}, "model.f_iso", "-1", "must be > 0"});
  InputFault fault = found.fault();
  fault.place = InputPlace{"b.yaml", 6, 10};
  const InputError placed = InputError("b.yaml (the base)", found).WithFault(fault);
  EXPECT_STREQ(placed.what(), "b.yaml (the base): model.f_iso = -1 (b.yaml:6:10): must be > 0");
}

TEST(InputErrorTest, AComposedMessageStaysAsWrittenWhenFieldsAreAdded) {
  const InputError composed("passive: 2 points, fewer than 4");
  EXPECT_TRUE(composed.fault().key.empty());
  InputFault fault = composed.fault();
  fault.key = "passive";
  const InputError keyed = composed.WithFault(fault);
  EXPECT_STREQ(keyed.what(), "passive: 2 points, fewer than 4");
  EXPECT_EQ(keyed.fault().key, "passive");
}

TEST(InputErrorTest, ControlCharactersAreEscapedInTheMessageNotInTheFields) {
  const InputError e(InputFault{InputPlace{"s.yaml", 1, 7}, "name", "a\x1b[2Jb", "printable"});
  EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos);
  EXPECT_EQ(e.fault().value, "a\x1b[2Jb");
}

}  // namespace
}  // namespace musclesim
