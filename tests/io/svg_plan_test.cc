// SVG floor plans (shape::Building::plans, seed 000 "look at its plan"): a panel per storey, side
// by side at one scale, rooms labelled with name and area, walls, doors with their swing, windows
// and stairs; golden file tests/data/golden/plan.svg (INSULA_UPDATE_GOLDEN=1 regenerates it).
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "io/svg_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

kernel::Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// A 10 x 8 m house: storey 0 with a kitchen and a hall (door between, entrance, window, stair),
// storey 1 with one bedroom.
shape::Scene plan_scene() {
  shape::Scene scene;
  shape::Building b;
  b.id = "house";
  b.parts.push_back({"base",
                     shape::PartKind::kBuildingPart,
                     {},
                     testing::prism({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, 0, 0.3)});
  shape::StoreyPlan s0;
  s0.name = "storey 0";
  s0.level = 0;
  s0.elevation = 0.3;
  s0.rooms = {{"kitchen_1", "kitchen", rect(0.3, 0.3, 4.94, 7.7), 34.336},
              {"hall", "hall", rect(5.06, 0.3, 9.7, 7.7), 34.336}};
  s0.walls = {{rect(0, 0, 10, 0.3), true},
              {rect(4.94, 0.3, 5.06, 3.5), false},
              {rect(4.94, 4.5, 5.06, 7.7), false}};
  s0.openings = {{shape::PlanOpeningKind::kDoor, {4.94, 3.5}, {4.94, 4.5}, {-1, 0}},
                 {shape::PlanOpeningKind::kEntrance, {2, 0.3}, {3, 0.3}, {0, 1}},
                 {shape::PlanOpeningKind::kWindow, {9.85, 3}, {9.85, 4.2}, {-1, 0}}};
  s0.stairs = {{rect(6, 1, 7, 5), {6.5, 1}, {6.5, 5}}};
  shape::StoreyPlan s1;
  s1.name = "storey 1";
  s1.level = 1;
  s1.elevation = 3.3;
  s1.rooms = {{"bedroom", "bedroom", rect(0.3, 0.3, 9.7, 7.7), 69.56}};
  b.plans = {s0, s1};
  scene.buildings.push_back(std::move(b));
  return scene;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgPlan, MatchesGoldenFile) {
  testing::expect_golden("plan.svg", svg_text(plan_scene()));
}

TEST(SvgPlan, OnePanelPerStoreyWithTitles) {
  const std::string svg = svg_text(plan_scene());
  EXPECT_EQ(count(svg, "<g class=\"storey\""), 2U);
  EXPECT_NE(svg.find(">storey 0</text>"), std::string::npos);
  EXPECT_NE(svg.find(">storey 1</text>"), std::string::npos);
  // Footprints mode is off: no building label, no footprint group.
  EXPECT_EQ(svg.find("id=\"footprints\""), std::string::npos);
  EXPECT_EQ(count(svg, "id=\"scale-bar\""), 1U);
  EXPECT_EQ(count(svg, "id=\"north-arrow\""), 1U);
}

TEST(SvgPlan, RoomsAreLabelledWithNameAndArea) {
  const std::string svg = svg_text(plan_scene());
  EXPECT_NE(svg.find(">kitchen_1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">hall</text>"), std::string::npos);
  EXPECT_NE(svg.find(">bedroom</text>"), std::string::npos);
  EXPECT_EQ(count(svg, ">34.3 m²</text>"), 2U);
  EXPECT_EQ(count(svg, ">69.6 m²</text>"), 1U);
  // Each room's floor names it, for pages that show the plan (the studio) and for hover titles.
  EXPECT_EQ(
      count(svg,
            " data-room=\"kitchen_1\" data-type=\"kitchen\"><title>kitchen_1, 34.3 m²</title>"),
      1U);
  EXPECT_EQ(count(svg, " data-room="), 3U);
}

TEST(SvgPlan, StoreysShareOneScaleSideBySide) {
  // The extent is 10 x 8 m with a 1 m gap: storey 1's title starts 11 m east of storey 0's.
  const std::string svg = svg_text(plan_scene());
  const std::regex title("<text x=\"([-0-9.]+)\" y=\"[-0-9.]+\"[^>]*>storey ([01])</text>");
  double x[2] = {0, 0};
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), title); it != std::sregex_iterator();
       ++it) {
    x[std::stoi((*it)[2])] = std::stod((*it)[1]);
  }
  EXPECT_NEAR(x[1] - x[0], 11, 1e-9);
}

TEST(SvgPlan, WallsDoorsWindowsAndStairs) {
  const std::string svg = svg_text(plan_scene());
  EXPECT_EQ(count(svg, "fill=\"#2b2b2b\""), 1U);  // one exterior wall piece
  EXPECT_EQ(count(svg, "fill=\"#6b6b6b\""), 2U);  // the inner wall on both sides of its door
  EXPECT_EQ(count(svg, "<g class=\"door\""), 1U);
  EXPECT_EQ(count(svg, "<g class=\"entrance\""), 1U);
  EXPECT_EQ(count(svg, "<g class=\"window\""), 1U);
  EXPECT_EQ(count(svg, "<g class=\"stair\""), 1U);
  // A swing arc per door: radius = the door's width (1 m).
  EXPECT_EQ(count(svg, " A1 1 0 0 "), 2U);
  // The 4 m flight: 13 treads of about 0.3 m, so 12 lines between them.
  const std::size_t stair = svg.find("<g class=\"stair\"");
  const std::string flight = svg.substr(stair, svg.find("</g>", stair) - stair);
  EXPECT_EQ(count(flight, "<path d=\"M"), 1U + 12U + 1U + 2U);  // outline, treads, arrow
}

TEST(SvgPlan, SectionOptionKeepsTheFootprintDrawing) {
  SvgOptions options;
  options.section_height = 1.5;
  const std::string svg = svg_text(plan_scene(), options);
  EXPECT_NE(svg.find("id=\"footprints\""), std::string::npos);
  EXPECT_EQ(svg.find("<g class=\"storey\""), std::string::npos);
}

TEST(SvgPlan, ScenesWithoutPlansAreUnchanged) {
  EXPECT_EQ(svg_text(testing::test_scene()).find("<g class=\"storey\""), std::string::npos);
}

}  // namespace
}  // namespace insula::io
