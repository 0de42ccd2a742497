// SVG writer: golden file, well-formed XML (checked by a small tag/entity checker here; xmllint
// runs in validators_test), scale (viewBox in meters, y flipped), label placement inside the
// footprint, escaping, scale bar, north arrow and the horizontal section.
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/svg_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using testing::test_scene;

// Well-formedness essentials: balanced and properly nested elements, quoted attributes, only the
// five predefined entities, no raw '<' or '&' in text. Returns "" or the first problem.
std::string check_xml(const std::string& text) {
  std::vector<std::string> open;
  std::size_t i = 0;
  const std::regex entity("^&(amp|lt|gt|quot|apos);");
  while (i < text.size()) {
    if (text[i] == '&') {
      if (!std::regex_search(text.substr(i, 8), entity))
        return "bad entity at " + std::to_string(i);
      ++i;
      continue;
    }
    if (text[i] != '<') {
      ++i;
      continue;
    }
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos) return "unterminated tag at " + std::to_string(i);
    const std::string tag = text.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.front() == '?' || tag.front() == '!') continue;
    if (tag.find('<') != std::string::npos) return "'<' inside tag " + tag;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in " + tag;
    const std::string name = tag.substr(tag.front() == '/' ? 1 : 0,
                                        tag.find_first_of(" /", 1) - (tag.front() == '/' ? 1 : 0));
    if (tag.front() == '/') {
      if (open.empty() || open.back() != name) return "mismatched </" + name + ">";
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(name);
    }
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

std::vector<std::pair<double, double>> text_positions(const std::string& svg,
                                                      const std::string& label) {
  std::vector<std::pair<double, double>> out;
  const std::regex pattern("<text x=\"([-0-9.]+)\" y=\"([-0-9.]+)\"[^>]*>" + label + "</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), pattern);
       it != std::sregex_iterator(); ++it) {
    out.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  }
  return out;
}

TEST(SvgWriter, MatchesGoldenFiles) {
  testing::expect_golden("scene.svg", svg_text(test_scene()));
  SvgOptions section;
  section.section_height = 1.5;
  testing::expect_golden("scene_section.svg", svg_text(test_scene(), section));
}

TEST(SvgWriter, IsWellFormedXml) {
  EXPECT_EQ(check_xml(svg_text(test_scene())), "");
  EXPECT_NE(check_xml("<svg><g></svg>"), "");  // the checker itself can fail
  EXPECT_NE(check_xml("<svg>a & b</svg>"), "");
}

TEST(SvgWriter, ViewBoxIsInMetersAndSizeFollowsTheScale) {
  // Content spans 16 x 5 m; margin 10% of 16 m; one extra margin below for the scale bar.
  SvgOptions options;
  options.pixels_per_meter = 10;
  const std::string svg = svg_text(test_scene(), options);
  EXPECT_NE(svg.find("width=\"192\" height=\"98\" viewBox=\"-1.6 -1.6 19.2 9.8\""),
            std::string::npos);
}

TEST(SvgWriter, NorthIsUp) {
  // The box spans local y 0..3 of 0..5: drawn at picture y 2..5 (y grows downwards).
  const std::string svg = svg_text(test_scene());
  EXPECT_NE(svg.find("<path d=\"M0 2 L4 2 L4 5 L0 5 Z\" fill=\"#e8dcc4\""), std::string::npos);
}

TEST(SvgWriter, LabelsSitInsideTheirFootprints) {
  const std::string svg = svg_text(test_scene());
  const auto box = text_positions(svg, "b1");
  ASSERT_EQ(box.size(), 1U);
  EXPECT_NEAR(box[0].first, 2, 0.05);
  EXPECT_NEAR(box[0].second, 3.5, 0.05);
  // The L (local x 10..16, y 0..5, drawn with x - 0 and 5 - y): its label must be in an arm, at
  // least ~1 m from the outline (the arms are 2 m wide), not at the bounding-box centre (13, 2.5).
  const auto l = text_positions(svg, "L-2");
  ASSERT_EQ(l.size(), 1U);
  const double x = l[0].first - 10;
  const double y = 5 - l[0].second;
  // Points at least 0.9 m inside the L lie near the middle line of one of its two arms.
  const bool in_arm = (x >= 0.9 && x <= 5.1 && y >= 0.9 && y <= 1.3) ||
                      (x >= 0.9 && x <= 1.3 && y >= 0.9 && y <= 4.1);
  EXPECT_TRUE(in_arm) << x << " " << y;
}

// Label placement must stay cheap on slivers: the search once seeded (long / short)^2 cells (a
// 1000 m x 10 µm footprint took 48 s and 5.2 GB). The test only has to finish (ctest's timeout);
// the label must still be inside the footprint's bounding box (3 decimals: 1 mm rounding).
TEST(SvgWriter, LabelsOnSliversStayInsideTheBoundingBox) {
  for (const auto& [length, width] : {std::pair{1000.0, 1e-5}, std::pair{10000.0, 0.01}}) {
    shape::Scene scene;
    scene.buildings.push_back(
        {"sliver",
         {},
         {{"p",
           shape::PartKind::kBuildingPart,
           {},
           testing::prism({{0, 0}, {length, 0}, {length, width}, {0, width}}, 0, 3)}}});
    const std::string svg = svg_text(scene);
    EXPECT_EQ(check_xml(svg), "");
    const auto at = text_positions(svg, "sliver");
    ASSERT_EQ(at.size(), 1U) << length;
    EXPECT_GE(at[0].first, 0) << length;
    EXPECT_LE(at[0].first, length) << length;
    EXPECT_GE(at[0].second, -0.0005) << length;
    EXPECT_LE(at[0].second, width + 0.0005) << length;
  }
}

TEST(SvgWriter, EscapesLabels) {
  shape::Scene scene = test_scene();
  scene.buildings[0].id = "A&B <\"x\"> 'y'";
  const std::string svg = svg_text(scene);
  EXPECT_NE(svg.find(">A&amp;B &lt;&quot;x&quot;&gt; &apos;y&apos;</text>"), std::string::npos);
  EXPECT_NE(svg.find("data-id=\"A&amp;B &lt;&quot;x&quot;&gt; &apos;y&apos;\""), std::string::npos);
  EXPECT_EQ(check_xml(svg), "");
}

TEST(SvgWriter, EscapeReplacesControlCharactersAndBrokenUtf8) {
  EXPECT_EQ(xml_escape("Stra\xc3\x9f"
                       "e"),
            "Stra\xc3\x9f"
            "e");
  EXPECT_EQ(xml_escape("a\x01z\xff\xc3"), "a?z??");
  EXPECT_EQ(xml_escape("tab\there"), "tab\there");
}

TEST(SvgWriter, HasScaleBarAndNorthArrow) {
  const std::string svg = svg_text(test_scene());
  EXPECT_NE(svg.find("<g id=\"scale-bar\""), std::string::npos);
  EXPECT_NE(svg.find(">2 m</text>"), std::string::npos);  // 1/4 of 16 m rounded down to 1-2-5
  EXPECT_NE(svg.find("<g id=\"north-arrow\">"), std::string::npos);
  EXPECT_NE(svg.find(">N</text>"), std::string::npos);
}

TEST(SvgWriter, SectionCutsEveryWall) {
  SvgOptions options;
  options.section_height = 1.5;
  const std::string svg = svg_text(test_scene(), options);
  const std::size_t at = svg.find("<g id=\"section\">");
  ASSERT_NE(at, std::string::npos);
  const std::string section = svg.substr(at, svg.find("</g>", at) - at);
  // 4 box walls + 6 L walls; the floor at z 0.1 and the roofs are not cut.
  EXPECT_EQ(std::count(section.begin(), section.end(), 'M'), 10);
  options.section_height = 10;
  EXPECT_EQ(svg_text(test_scene(), options).find("<g id=\"section\">"), std::string::npos);
}

TEST(SvgWriter, FallsBackToDownwardFacesWithoutGroundTags) {
  shape::Scene scene;
  kernel::Mesh mesh = testing::prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3);
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    mesh.tag(f).semantic = kernel::SemanticClass::kNone;
  scene.buildings.push_back({"plain", {}, {{"p", shape::PartKind::kBuildingPart, {}, mesh}}});
  const std::string svg = svg_text(scene);
  EXPECT_EQ(text_positions(svg, "plain").size(), 1U);
  EXPECT_NE(svg.find("<path d=\"M0 0 L4 0 L4 3 L0 3 Z\" fill=\"none\""), std::string::npos);
}

TEST(SvgWriter, EmptySceneStillDrawsAValidPicture) {
  const std::string svg = svg_text(shape::Scene{});
  EXPECT_EQ(check_xml(svg), "");
  EXPECT_NE(svg.find("viewBox="), std::string::npos);
}

TEST(SvgWriter, WritesAtomically) {
  const auto dir = testing::temp_dir("svg_write");
  ASSERT_EQ(write_svg(test_scene(), dir / "plan.svg"), "");
  EXPECT_EQ(testing::read_file(dir / "plan.svg"), svg_text(test_scene()));
  EXPECT_NE(write_svg(test_scene(), dir / "no" / "plan.svg").find("plan.svg"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace insula::io
