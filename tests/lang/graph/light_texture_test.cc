// Lights and textures (graph-format.md §11): lights placed in their actor's scope with their
// parameters, text drawn into images in the bitmap font, inversion and combination per pixel.
#include <gtest/gtest.h>

#include <array>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

std::string graph(const std::string& nodes, const std::string& edges) {
  return R"({"format": "insula-graph", "version": 1, "nodes": [)" + nodes + R"(], "edges": [)" +
         edges + "]}";
}

using Pixel = std::array<int, 4>;

Pixel pixel(const Texture& t, int x, int y) {
  const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(t.width) +
                             static_cast<std::size_t>(x));
  return {t.rgba[i], t.rgba[i + 1], t.rgba[i + 2], t.rgba[i + 3]};
}

const Texture& texture(const TestRun& t, const std::string& port, std::size_t k = 0) {
  return *t.run->entities[t.at(port).at(k)].texture;
}

// A 10 (x) by 20 (y) lot extruded 30 high: its mass scope has x along the lot's first edge, y up.
const std::string kBox = R"(
  { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 20 } },
  { "id": "mass", "type": "shape.extrude", "params": { "height": 30 } },)";

TEST(Lights, DefaultPositionIsTheScopeCentre) {
  const TestRun t = run_text(graph(kBox + R"(
    { "id": "lamp", "type": "light.create" })",
                                   R"("lot.out -> mass.in", "mass.out -> lamp.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("lamp.out").size(), 1U);
  const Entity& e = t.run->entities[t.at("lamp.out")[0]];
  EXPECT_EQ(e.type, EntityType::kLight);
  EXPECT_EQ(e.position, (kernel::Vec3{5, 10, 15}));
  ASSERT_NE(e.light, nullptr);
  EXPECT_EQ(e.light->kind, "point");
  EXPECT_EQ(e.light->intensity, 100);
  EXPECT_EQ(e.light->color, (kernel::Vec3{1, 1, 0.8}));
  EXPECT_EQ(e.light->range, 0);
  // The light descends from the mass (§9.10).
  EXPECT_TRUE(t.run->entities.descends_from(t.at("lamp.out")[0], e.parent));
  EXPECT_EQ(t.run->entities[e.parent].type, EntityType::kShape);
}

TEST(Lights, PositionIsInTheActorsScopeAndParametersAreKept) {
  // (Raw strings with a delimiter: the expressions contain `)"`.)
  const TestRun t = run_text(graph(kBox + R"j(
    { "id": "top", "type": "light.create",
      "params": { "position": "= vec(sx()/2, sy(), sz()/2)", "kind": "spot", "intensity": 250,
                  "color": [1, 0.5, 0.25], "range": 12 } },
    { "id": "corner", "type": "light.create", "params": { "position": [0, 0, 0] } },
    { "id": "front", "type": "light.create", "params": { "position": "= vec(sx()/2, 1, sz())" } })j",
                                   R"("lot.out -> mass.in", "mass.out -> top.in",
                                      "mass.out -> corner.in", "mass.out -> front.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const Entity& top = t.run->entities[t.at("top.out").at(0)];
  EXPECT_EQ(top.position, (kernel::Vec3{5, 10, 30}));
  EXPECT_EQ(top.light->kind, "spot");
  EXPECT_EQ(top.light->intensity, 250);
  EXPECT_EQ(top.light->color, (kernel::Vec3{1, 0.5, 0.25}));
  EXPECT_EQ(top.light->range, 12);
  // The scope's origin is the lot's first corner; its z (depth) axis points out of the front
  // face, which is the lot's first edge (y = 0): scope z = sz() lies on it.
  EXPECT_EQ(t.run->entities[t.at("corner.out").at(0)].position, (kernel::Vec3{0, 20, 0}));
  EXPECT_EQ(t.run->entities[t.at("front.out").at(0)].position, (kernel::Vec3{5, 0, 1}));
}

TEST(Lights, APointsScopeIsThePoint) {
  const TestRun t = run_text(graph(R"(
    { "id": "p", "type": "create.points", "params": { "points": [[1, 2, 3], [4, 5, 6]] } },
    { "id": "lamp", "type": "light.create" },
    { "id": "above", "type": "light.create", "params": { "position": [0, 0, 2] } })",
                                   R"("p.out -> lamp.in", "p.out -> above.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("lamp.out").size(), 2U);
  EXPECT_EQ(t.run->entities[t.at("lamp.out")[0]].position, (kernel::Vec3{1, 2, 3}));
  EXPECT_EQ(t.run->entities[t.at("lamp.out")[1]].position, (kernel::Vec3{4, 5, 6}));
  EXPECT_EQ(t.run->entities[t.at("above.out")[1]].position, (kernel::Vec3{4, 5, 8}));
}

TEST(Lights, ColourOutsideTheUnitRangeDropsTheEntity) {
  const TestRun t = run_text(graph(kBox + R"(
    { "id": "lamp", "type": "light.create", "params": { "color": [2, 0, 0] } })",
                                   R"("lot.out -> mass.in", "mass.out -> lamp.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_TRUE(t.at("lamp.out").empty());
  EXPECT_NE(t.errors.find("warning[W040]: node 'lamp': 1 entity dropped; light colour components "
                          "must lie in [0, 1]; got [2, 0, 0]"),
            std::string::npos)
      << t.errors;
}

// "A" at size 16 in a 64 x 32 image: one font dot is 2 x 2 pixels, the 5 x 8 glyph 10 x 16,
// centred at (27, 8).
const std::string kSign = R"(
  { "id": "sign", "type": "texture.text",
    "params": { "text": "A", "name": "sign", "width": 64, "height": 32, "size": 16,
                "color": [0.6, 0.2, 1], "background": [0.2, 0.4, 0.8] } })";
const Pixel kInk = {153, 51, 255, 255};
const Pixel kPaper = {51, 102, 204, 255};

TEST(Textures, TextIsDrawnInTheFontCentredAndScaled) {
  const TestRun t = run_text(graph(kSign, ""));
  ASSERT_TRUE(t.ok()) << t.errors;
  const Texture& s = texture(t, "sign.out");
  EXPECT_EQ(s.name, "sign");
  EXPECT_EQ(s.text, "A");
  ASSERT_EQ(s.width, 64);
  ASSERT_EQ(s.height, 32);
  ASSERT_EQ(s.rgba.size(), 64U * 32U * 4U);
  // Row 0 of "A" is .###. : pixels 29..34 of rows 8 and 9; row 3 is ##### (rows 14, 15).
  for (int x = 29; x <= 34; ++x) {
    EXPECT_EQ(pixel(s, x, 8), kInk) << x;
    EXPECT_EQ(pixel(s, x, 9), kInk) << x;
  }
  EXPECT_EQ(pixel(s, 28, 8), kPaper);
  EXPECT_EQ(pixel(s, 35, 8), kPaper);
  EXPECT_EQ(pixel(s, 29, 7), kPaper);
  for (int x = 27; x <= 36; ++x) EXPECT_EQ(pixel(s, x, 14), kInk) << x;
  EXPECT_EQ(pixel(s, 26, 14), kPaper);
  EXPECT_EQ(pixel(s, 37, 14), kPaper);
  // The glyph has 18 dots, 4 pixels each; everything else is background.
  int ink = 0;
  int paper = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      ink += pixel(s, x, y) == kInk ? 1 : 0;
      paper += pixel(s, x, y) == kPaper ? 1 : 0;
    }
  }
  EXPECT_EQ(ink, 72);
  EXPECT_EQ(paper, 64 * 32 - 72);
}

TEST(Textures, NonIntegerScaleAndClipping) {
  // size 12: a dot is 1.5 pixels, the text "MM" (11 x 8 dots) 16.5 x 12 pixels in 10 x 10, so
  // the image is clipped on every side and still nearest-neighbour: only ink and paper occur.
  const TestRun t = run_text(graph(R"(
    { "id": "sign", "type": "texture.text",
      "params": { "text": "MM", "width": 10, "height": 10, "size": 12 } })",
                                   ""));
  ASSERT_TRUE(t.ok()) << t.errors;
  const Texture& s = texture(t, "sign.out");
  int ink = 0;
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const Pixel p = pixel(s, x, y);
      EXPECT_TRUE(p == (Pixel{0, 0, 0, 255}) || p == (Pixel{255, 255, 255, 255}));
      ink += p[0] == 0 ? 1 : 0;
    }
  }
  EXPECT_GT(ink, 10);
  EXPECT_LT(ink, 90);
}

TEST(Textures, InvertKeepsAlphaAndNamesTheCopy) {
  const TestRun t = run_text(graph(kSign + R"(,
    { "id": "neg", "type": "texture.invert" })",
                                   R"("sign.out -> neg.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const Texture& n = texture(t, "neg.out");
  EXPECT_EQ(n.name, "sign_inverted");
  EXPECT_EQ(pixel(n, 29, 8), (Pixel{102, 204, 0, 255}));
  EXPECT_EQ(pixel(n, 0, 0), (Pixel{204, 153, 51, 255}));
  const Texture& s = *t.run->entities[t.run->entities[t.at("neg.out")[0]].parent].texture;
  ASSERT_EQ(s.rgba.size(), n.rgba.size());
  for (std::size_t i = 0; i < s.rgba.size(); ++i) {
    EXPECT_EQ(n.rgba[i], i % 4 == 3 ? s.rgba[i] : 255 - s.rgba[i]) << i;
  }
}

std::string combined(const std::string& op, int b_width) {
  return graph(kSign + R"(,
    { "id": "grey", "type": "texture.text",
      "params": { "text": "", "name": "grey", "width": )" +
                   std::to_string(b_width) + R"(, "height": 32, "background": [0.5, 0.5, 0.5] } },
    { "id": "mix", "type": "texture.combine", "params": { "op": ")" +
                   op + R"(" } })",
               R"("sign.out -> mix.a", "grey.out -> mix.b")");
}

TEST(Textures, CombineAddSubtractMultiplyClamped) {
  // a: ink (153, 51, 255), paper (51, 102, 204); b: grey 128 everywhere.
  struct Case {
    std::string op;
    Pixel ink;
    Pixel paper;
  };
  const Case cases[] = {
      {"add", {255, 179, 255, 255}, {179, 230, 255, 255}},
      {"subtract", {25, 0, 127, 255}, {0, 0, 76, 255}},
      {"multiply", {77, 26, 128, 255}, {26, 51, 102, 255}},
  };
  for (const Case& c : cases) {
    const TestRun t = run_text(combined(c.op, 64));
    ASSERT_TRUE(t.ok()) << t.errors;
    const Texture& m = texture(t, "mix.out");
    EXPECT_EQ(m.name, "sign_" + c.op + "_grey");
    EXPECT_EQ(pixel(m, 29, 8), c.ink) << c.op;
    EXPECT_EQ(pixel(m, 0, 0), c.paper) << c.op;
    EXPECT_EQ(pixel(m, 63, 31), c.paper) << c.op;
  }
}

TEST(Textures, CombineOfDifferentSizesFailsWithW040) {
  const TestRun t = run_text(combined("add", 32));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_TRUE(t.at("mix.out").empty());
  EXPECT_NE(t.errors.find("warning[W040]: node 'mix': 1 entity dropped; texture.combine needs "
                          "textures of one size; 'sign' is 64 x 32, 'grey' is 32 x 32"),
            std::string::npos)
      << t.errors;
}

TEST(Textures, OversizedTextureStopsTheRun) {
  const TestRun t = run_text(graph(R"(
    { "id": "sign", "type": "texture.text", "params": { "text": "x", "width": 10000 } })",
                                   ""));
  EXPECT_FALSE(t.ok());
  EXPECT_NE(t.errors.find("error[G052]: a texture is at most 8192 x 8192 pixels; got 10000 x 128"),
            std::string::npos)
      << t.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing
