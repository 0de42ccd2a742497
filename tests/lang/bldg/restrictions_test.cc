// Restriction rules (seed 000, §3.3): defaults, a full file, every error code at its token, and
// print_restrictions reading back to the same values.
#include <gtest/gtest.h>

#include "lang/bldg/restrictions.h"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

base::Result<Restrictions> parse(const std::string& text) {
  const base::Source source("r.rules", text);
  return parse_restrictions(source);
}

std::string first_error(const std::string& text) {
  const auto result = parse(text);
  return result.diagnostics().empty() ? "" : base::render(result.diagnostics().front());
}

TEST(BldgRestrictions, EmptyFileGivesTheDocumentedDefaults) {
  const auto r = parse("# nothing\n");
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r->initial_weight, 0.001);
  EXPECT_DOUBLE_EQ(r->growth[0], 1.5);
  EXPECT_DOUBLE_EQ(r->growth[1], 2.0);
  EXPECT_DOUBLE_EQ(r->growth[2], 2.5);
  EXPECT_DOUBLE_EQ(r->step, 0.01);
  EXPECT_DOUBLE_EQ(r->door_width, 0.9);
  EXPECT_DOUBLE_EQ(r->entrance_width, 1.0);
  EXPECT_DOUBLE_EQ(r->door_width_fraction, 0);
  EXPECT_DOUBLE_EQ(r->door_min_width, 0.9);
  EXPECT_DOUBLE_EQ(r->storey_height, 3.0);
  EXPECT_TRUE(r->colors.empty());
}

TEST(BldgRestrictions, RomanFile) {
  const base::Source source("roman.rules", testing::read_file(testing::data_dir() / "roman.rules"));
  const auto r = parse_restrictions(source);
  ASSERT_TRUE(r.ok()) << (r.diagnostics().empty() ? "" : base::render(r.diagnostics()[0]));
  EXPECT_DOUBLE_EQ(r->growth[0], 1.4);
  EXPECT_DOUBLE_EQ(r->growth[1], 2.0);  // not given: default
  EXPECT_DOUBLE_EQ(r->growth[2], 3.0);
  EXPECT_DOUBLE_EQ(r->door_min_width, 1.1);
  EXPECT_DOUBLE_EQ(r->storey_height, 4.2);
  EXPECT_DOUBLE_EQ(r->door_height, 2.6);
  EXPECT_DOUBLE_EQ(r->step, 0.005);
  ASSERT_EQ(r->colors.size(), 3U);
  EXPECT_EQ(r->colors[0].first, "RoofSurface");
  EXPECT_FLOAT_EQ(r->colors[0].second[0], 0xa4 / 255.0F);
  EXPECT_FLOAT_EQ(r->colors[0].second[3], 1.0F);
  EXPECT_EQ(r->colors[1].first, "WallSurface");
  EXPECT_FLOAT_EQ(r->colors[1].second[1], 0.88F);
  EXPECT_FLOAT_EQ(r->colors[2].second[3], 1.0F);
}

TEST(BldgRestrictions, ErrorsAtTheOffendingToken) {
  EXPECT_EQ(first_error("storey_hieght = 3\n"),
            "r.rules:1:1: error[BLD301]: unknown restriction key 'storey_hieght'");
  EXPECT_EQ(first_error("color.Roof = \"#ff0000\"\n"),
            "r.rules:1:1: error[BLD301]: unknown semantic class 'Roof' in a colour key "
            "(WallSurface, RoofSurface, FloorSurface, Door, Window, ...)");
  EXPECT_EQ(first_error("step = fast\n"),
            "r.rules:1:8: error[BLD302]: 'step' expects a number, found identifier 'fast'");
  EXPECT_EQ(first_error("color.Door = \"#12345\"\n"),
            "r.rules:1:14: error[BLD302]: 'color.Door' expects a colour \"#rrggbb\" or "
            "\"#rrggbbaa\", found string \"#12345\"");
  EXPECT_EQ(first_error("growth.big = 1\n"),
            "r.rules:1:14: error[BLD303]: 'growth.big' = 1 is out of range (1, 100]");
  EXPECT_EQ(first_error("\n\nborrow_limit = -0.5\n"),
            "r.rules:3:16: error[BLD303]: 'borrow_limit' = -0.5 is out of range [0, 0.9]");
  EXPECT_EQ(first_error("color.Window = (0.2, 1.5, 0)\n"),
            "r.rules:1:22: error[BLD303]: colour component 1.5 of 'color.Window' is out of [0, 1]");
  EXPECT_EQ(first_error("color.Window = (0.2, 0.5)\n"),
            "r.rules:1:25: error[BLD302]: 'color.Window' needs 3 or 4 colour components");
  EXPECT_EQ(first_error("step = 0.1\nstep = 0.2\n"),
            "r.rules:2:1: error[BLD304]: restriction key 'step' is given twice");
  EXPECT_EQ(first_error("storey_height = 2\n"),
            "r.rules:1:17: error[BLD305]: door_height 2.1 must be below storey_height 2");
  EXPECT_EQ(first_error("window_sill = 1.5\nwindow_height = 1.6\n"),
            "r.rules:2:17: error[BLD305]: window_sill + window_height = 3.1 must be below "
            "storey_height 3");
  EXPECT_EQ(first_error("= 3\n"),
            "r.rules:1:1: error[BLD101]: expected a restriction key (e.g. 'storey_height'), "
            "found '='");
  EXPECT_EQ(first_error("step 0.1\n"),
            "r.rules:1:6: error[BLD101]: expected '=' after the key 'step', found number 0.1");
}

TEST(BldgRestrictions, EveryErrorIsReported) {
  const auto r = parse("step = 9\nfoo = 1\ndoor_min_width = 0\ncolor.Door = blue\n");
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 4U);
  EXPECT_EQ(r.diagnostics()[0].code, "BLD303");
  EXPECT_EQ(r.diagnostics()[1].code, "BLD301");
  EXPECT_EQ(r.diagnostics()[2].code, "BLD303");
  EXPECT_EQ(r.diagnostics()[3].code, "BLD302");
}

TEST(BldgRestrictions, PrintReadsBack) {
  Restrictions rules;
  rules.growth = {1.25, 1.75, 3.5};
  rules.step = 0.001;
  rules.storey_height = 3.3;
  rules.colors.push_back({"WallSurface", {0.1F, 0.2F, 0.3F, 1.0F}});
  const std::string text = print_restrictions(rules);
  const auto back = parse(text);
  ASSERT_TRUE(back.ok()) << text;
  EXPECT_EQ(back->growth, rules.growth);
  EXPECT_EQ(back->step, rules.step);
  EXPECT_EQ(back->storey_height, rules.storey_height);
  ASSERT_EQ(back->colors.size(), 1U);
  EXPECT_EQ(back->colors[0].second, rules.colors[0].second);
  EXPECT_EQ(print_restrictions(back.value()), text);
}

TEST(BldgRestrictions, AnyBytes) {
  for (const std::string& text :
       {std::string("\xFF\xFE"), std::string("a.b.c.d = (((("), std::string("x = -"),
        std::string(3000, '.'), std::string("color.Door = (1,1,1,1,1)")}) {
    const auto r = parse(text);
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.diagnostics().empty());
    EXPECT_GE(r.diagnostics()[0].span.line, 1U);
  }
}

}  // namespace
}  // namespace insula::lang::bldg
