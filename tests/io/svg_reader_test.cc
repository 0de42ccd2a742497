// The SVG outline reader (io/svg_reader.h): the geometry elements, path commands, transforms, and
// exact diagnostics for bad input (an element's position is the start of its name).
#include "io/svg_reader.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insula::io {
namespace {

std::string first_error(const std::string& text) {
  const auto r = read_svg(text, "t.svg");
  return r.ok() ? "" : base::render(r.diagnostics().front());
}

std::vector<SvgOutline> outlines(const std::string& body) {
  const auto r = read_svg("<svg xmlns='http://www.w3.org/2000/svg'>" + body + "</svg>", "t.svg");
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : base::render(r.diagnostics().front()));
  return r.ok() ? r.value() : std::vector<SvgOutline>{};
}

void expect_points(const SvgOutline& o, const std::vector<kernel::Vec2>& expected) {
  ASSERT_EQ(o.points.size(), expected.size()) << o.id;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(o.points[i].x, expected[i].x, 1e-9) << o.id << " point " << i;
    EXPECT_NEAR(o.points[i].y, expected[i].y, 1e-9) << o.id << " point " << i;
  }
}

TEST(SvgReader, ElementsInDocumentOrder) {
  const auto o = outlines(
      "<rect id='a' x='1' y='2' width='3' height='4'/>"
      "<polygon points='0,0 10,0 10,10 0,0'/>"
      "<polyline id='p' points='0 0, 1 1 2 0'/><line x1='1' y1='1' x2='2' y2='3'/>");
  ASSERT_EQ(o.size(), 4U);
  EXPECT_EQ(o[0].id, "a");
  EXPECT_TRUE(o[0].closed);
  expect_points(o[0], {{1, 2}, {4, 2}, {4, 6}, {1, 6}});
  EXPECT_EQ(o[1].id, "polygon#2");
  expect_points(o[1], {{0, 0}, {10, 0}, {10, 10}});  // the repeated closing point dropped
  EXPECT_FALSE(o[2].closed);
  expect_points(o[2], {{0, 0}, {1, 1}, {2, 0}});
  expect_points(o[3], {{1, 1}, {2, 3}});
}

TEST(SvgReader, PathCommandsAndSubpaths) {
  const auto o = outlines("<path id='q' d='M0 0 h10 v5 H0 z m 20 0 l 5 5 L 30 0'/>");
  ASSERT_EQ(o.size(), 2U);
  EXPECT_TRUE(o[0].closed);
  expect_points(o[0], {{0, 0}, {10, 0}, {10, 5}, {0, 5}});
  EXPECT_FALSE(o[1].closed);
  expect_points(o[1], {{20, 0}, {25, 5}, {30, 0}});
  // A cubic from (0,0) to (8,0) through controls (0,8) and (8,8): 8 segments, the midpoint at
  // (4, 6) (the Bezier's value at t = 1/2).
  const auto c = outlines("<path d='M0 0 C 0 8 8 8 8 0'/>");
  ASSERT_EQ(c.size(), 1U);
  ASSERT_EQ(c[0].points.size(), 9U);
  EXPECT_NEAR(c[0].points[4].x, 4, 1e-12);
  EXPECT_NEAR(c[0].points[4].y, 6, 1e-12);
}

// A half circle by an arc: every point at distance 5 from the centre (5, 0), the middle at (5, -5)
// for sweep 1 (clockwise on screen, y down); a circle element of 32 points.
TEST(SvgReader, ArcsCirclesAndEllipses) {
  const auto o = outlines("<path d='M 0 0 A 5 5 0 0 1 10 0'/><circle cx='1' cy='2' r='3'/>");
  ASSERT_EQ(o.size(), 2U);
  ASSERT_EQ(o[0].points.size(), 17U);
  for (const kernel::Vec2& p : o[0].points) EXPECT_NEAR(std::hypot(p.x - 5, p.y), 5, 1e-9);
  EXPECT_NEAR(o[0].points[8].x, 5, 1e-9);
  EXPECT_NEAR(o[0].points[8].y, -5, 1e-9);
  EXPECT_TRUE(o[1].closed);
  ASSERT_EQ(o[1].points.size(), 32U);
  for (const kernel::Vec2& p : o[1].points) EXPECT_NEAR(std::hypot(p.x - 1, p.y - 2), 3, 1e-9);
  // Radii too small for the end points grow to fit: a half ellipse through both.
  const auto small = outlines("<path d='M 0 0 a 1 1 0 0 0 4 0'/>");
  EXPECT_NEAR(small[0].points.back().x, 4, 1e-9);
  EXPECT_NEAR(small[0].points[8].y, 2, 1e-9);
}

TEST(SvgReader, TransformsOfElementsAndGroups) {
  const auto o = outlines(
      "<g transform='translate(10, 0)'><g transform='scale(2)'>"
      "<line x1='1' y1='1' x2='2' y2='1' transform='rotate(90)'/></g></g>");
  ASSERT_EQ(o.size(), 1U);
  // rotate(90) sends (1,1) to (-1,1), scale 2 to (-2,2), translate to (8,2).
  expect_points(o[0], {{8, 2}, {8, 4}});
  const auto m = outlines("<line x1='1' y1='0' x2='0' y2='1' transform='matrix(1 0 0 1 5 6)'/>");
  expect_points(m[0], {{6, 6}, {5, 7}});
}

TEST(SvgReader, BadInputHasExactDiagnostics) {
  EXPECT_EQ(first_error("<svg><rect"),
            "t.svg:1:10: error[SVG001]: not well-formed XML: Error parsing start element tag");
  EXPECT_EQ(first_error("<html/>"),
            "t.svg:1:2: error[SVG002]: the root element is <html>, not <svg>");
  EXPECT_EQ(first_error("<svg>\n<polygon points='1,2 x'/></svg>"),
            "t.svg:2:2: error[SVG003]: malformed number in '1,2 x'");
  EXPECT_EQ(first_error("<svg><path d='M 0 0 X 3'/></svg>"),
            "t.svg:1:7: error[SVG003]: unknown path command 'X'");
  EXPECT_EQ(first_error("<svg><rect width='3em' height='1'/></svg>"),
            "t.svg:1:7: error[SVG003]: attribute width=\"3em\" is not a number in user units");
  EXPECT_EQ(first_error("<svg><g transform='skew(3)'><rect width='1' height='1'/></g></svg>"),
            "t.svg:1:7: error[SVG003]: unknown transform 'skew'");
  EXPECT_EQ(first_error("<svg><circle r='0'/></svg>"),
            "t.svg: error[SVG004]: no outline: the file has no polygon, polyline, line, rect, "
            "circle, ellipse or path");
}

}  // namespace
}  // namespace insula::io
