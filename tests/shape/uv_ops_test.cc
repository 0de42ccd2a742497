// CityEngine's texturing operations in the registry (shape/ops_uv.cc, shape/uv_map.h):
// setupProjection's axes and sizes, projectUV, the uv transforms, tileUV, normalizeUV, deleteUV,
// texture, and the texture coordinates collect() gives the parts.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "shape/collect.h"
#include "shape/ops.h"
#include "shape/uv_map.h"

namespace insula::shape {
namespace {

using kernel::Polygon;
using kernel::Vec2;
using kernel::Vec3;

ShapeId run(ShapeTree& tree, ShapeId id, std::string_view op, std::vector<ArgInput> args,
            std::string* warning = nullptr) {
  const OpResult r = registry().run(tree, id, op, args);
  EXPECT_TRUE(r.ok()) << op << ": " << r.error;
  EXPECT_EQ(r.children.size(), 1U);
  if (warning != nullptr) *warning = r.warning;
  return r.children.empty() ? kNoShape : r.children[0];
}

// The 10 m wide, 4 m high front façade of a 10 x 6 m lot extruded 4 m.
ShapeId facade(ShapeTree& tree) {
  const RootResult lot = tree.create_root(Polygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}});
  EXPECT_TRUE(lot.ok()) << lot.error;
  const ShapeId mass = run(tree, lot.id, "extrude", {{"height", 4.0}});
  const OpResult r = registry().run(tree, mass, "comp", {{"select", std::string("front")}});
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.children.size(), 1U);
  return r.children.empty() ? kNoShape : r.children[0];
}

std::optional<UvMap> uv0(const ShapeTree& tree, ShapeId id) {
  const Value* v = tree.attribute(id, uv_set_attribute(0));
  return v != nullptr ? decode_uv_map(*v) : std::nullopt;
}

// {u min, v min, u max, v max} of the shape's vertices under its uv set 0.
UvRange range_of(const ShapeTree& tree, ShapeId id) {
  std::vector<Vec3> points;
  for (const Vec3& p : tree[id].mesh->positions()) points.push_back(tree[id].scope.to_world(p));
  const std::optional<UvMap> map = uv0(tree, id);
  EXPECT_TRUE(map.has_value());
  return map ? *uv_range(*map, points) : UvRange{};
}

void expect_range(const UvRange& r, Vec2 min, Vec2 max) {
  EXPECT_NEAR(r.min.x, min.x, 1e-9);
  EXPECT_NEAR(r.min.y, min.y, 1e-9);
  EXPECT_NEAR(r.max.x, max.x, 1e-9);
  EXPECT_NEAR(r.max.y, max.y, 1e-9);
}

ShapeId projected(ShapeTree& tree, ShapeId id, std::string axes, SizeSpec w, SizeSpec h) {
  const ShapeId set = run(tree, id, "setupProjection",
                          {{"", std::int64_t{0}}, {"", std::move(axes)}, {"", w}, {"", h}});
  return run(tree, set, "projectUV", {{"", std::int64_t{0}}});
}

TEST(UvOps, FacadeScopeXyRepeatsOncePerTextureWidth) {
  ShapeTree tree;
  const ShapeId f = facade(tree);
  ASSERT_NEAR(tree[f].scope.size.x, 10, 1e-9);
  const ShapeId p =
      projected(tree, f, "scope.xy", {2, SizeMode::kAbsolute}, {1, SizeMode::kAbsolute});
  // 10 m at 2 m per repeat: u spans 5; 4 m at 1 m: v spans 4, starting at the scope origin.
  expect_range(range_of(tree, p), {0, 0}, {5, 4});
}

TEST(UvOps, RelativeAndFloatingSizes) {
  ShapeTree tree;
  const ShapeId f = facade(tree);
  // '0.5: half the extent per repeat (twice across); ~3 on 10 m: three repeats of 3.33 m.
  expect_range(range_of(tree, projected(tree, f, "scope.xy", {0.5, SizeMode::kRelative},
                                        {3, SizeMode::kFloating})),
               {0, 0}, {2, 1});
  ShapeTree tree2;
  const ShapeId g = facade(tree2);
  expect_range(range_of(tree2, projected(tree2, g, "scope.xy", {3, SizeMode::kFloating},
                                         {1, SizeMode::kRelative})),
               {0, 0}, {3, 1});
}

TEST(UvOps, OffsetsInMetersOrRelative) {
  // 2 m per repeat along u with an offset of 1 m, or of '0.1 of the 10 m extent: u starts at
  // -0.5 either way; the v offset of '0.5 of 4 m at 1 m per repeat moves v by -2.
  for (const SizeSpec offset :
       {SizeSpec{1, SizeMode::kAbsolute}, SizeSpec{0.1, SizeMode::kRelative}}) {
    ShapeTree tree;
    const ShapeId f = facade(tree);
    const ShapeId set = run(tree, f, "setupProjection",
                            {{"", std::int64_t{0}},
                             {"", std::string("scope.xy")},
                             {"", SizeSpec{2, SizeMode::kAbsolute}},
                             {"", SizeSpec{1, SizeMode::kAbsolute}},
                             {"", offset},
                             {"", SizeSpec{0.5, SizeMode::kRelative}}});
    expect_range(range_of(tree, run(tree, set, "projectUV", {{"", std::int64_t{0}}})), {-0.5, -2},
                 {4.5, 2});
  }
}

TEST(UvOps, LotScopeXzAndWorldAxes) {
  ShapeTree tree;
  const RootResult lot = tree.create_root(Polygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}});
  ASSERT_TRUE(lot.ok());
  // A lot read as CityEngine reads it: x along the first edge, z = -y (toward the street).
  const UvRange r = range_of(tree, projected(tree, lot.id, "scope.xz", {1, SizeMode::kAbsolute},
                                             {2, SizeMode::kAbsolute}));
  expect_range(r, {0, -3}, {10, 0});
  // world.xz is the ground: x east, z south.
  ShapeTree tree2;
  const RootResult lot2 = tree2.create_root(Polygon{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}});
  expect_range(range_of(tree2, projected(tree2, lot2.id, "world.xz", {5, SizeMode::kAbsolute},
                                         {3, SizeMode::kAbsolute})),
               {0, -2}, {2, 0});
}

TEST(UvOps, ProjectionIsInheritedAndSplitsInterpolate) {
  ShapeTree tree;
  const ShapeId f = facade(tree);
  const ShapeId p =
      projected(tree, f, "scope.xy", {2, SizeMode::kAbsolute}, {1, SizeMode::kAbsolute});
  // The right 4 m of the façade after a split keep the façade's coordinates.
  const OpResult split = registry().run(
      tree, p, "split",
      {{"axis", std::string("x")},
       {"sizes", std::vector<SizeSpec>{{6, SizeMode::kAbsolute}, {4, SizeMode::kAbsolute}}}});
  ASSERT_TRUE(split.ok()) << split.error;
  ASSERT_EQ(split.children.size(), 2U);
  expect_range(range_of(tree, split.children[1]), {3, 0}, {5, 4});
}

TEST(UvOps, TranslateScaleRotate) {
  ShapeTree tree;
  const ShapeId p =
      projected(tree, facade(tree), "scope.xy", {2, SizeMode::kAbsolute}, {1, SizeMode::kAbsolute});
  const ShapeId t = run(tree, p, "translateUV", {{"", std::int64_t{0}}, {"", 0.5}, {"", -1.0}});
  expect_range(range_of(tree, t), {0.5, -1}, {5.5, 3});
  const ShapeId s = run(tree, t, "scaleUV", {{"", std::int64_t{0}}, {"", 2.0}, {"", 0.5}});
  expect_range(range_of(tree, s), {1, -0.5}, {11, 1.5});
  const ShapeId r = run(tree, p, "rotateUV", {{"", std::int64_t{0}}, {"", 90.0}});
  // (u, v) -> (-v, u).
  expect_range(range_of(tree, r), {-4, 0}, {0, 5});
}

TEST(UvOps, TileAndNormalize) {
  ShapeTree tree;
  const ShapeId p =
      projected(tree, facade(tree), "scope.xy", {1, SizeMode::kRelative}, {1, SizeMode::kRelative});
  expect_range(range_of(tree, p), {0, 0}, {1, 1});
  // Tiles of 2.5 m x 2 m: 4 across, 2 up; 0 leaves an axis alone; ~3 fits 3 tiles in 10 m.
  expect_range(range_of(tree, run(tree, p, "tileUV",
                                  {{"", std::int64_t{0}},
                                   {"", SizeSpec{2.5, SizeMode::kAbsolute}},
                                   {"", SizeSpec{2, SizeMode::kAbsolute}}})),
               {0, 0}, {4, 2});
  expect_range(range_of(tree, run(tree, p, "tileUV",
                                  {{"", std::int64_t{0}},
                                   {"", SizeSpec{3, SizeMode::kFloating}},
                                   {"", SizeSpec{0, SizeMode::kAbsolute}}})),
               {0, 0}, {3, 1});
  const ShapeId moved = run(tree, p, "translateUV", {{"", std::int64_t{0}}, {"", 3.0}, {"", 1.0}});
  const ShapeId big = run(tree, moved, "scaleUV", {{"", std::int64_t{0}}, {"", 4.0}, {"", 2.0}});
  expect_range(range_of(tree, run(tree, big, "normalizeUV",
                                  {{"", std::int64_t{0}}, {"", std::string("uv")}})),
               {0, 0}, {1, 1});
  // uvUniform keeps the aspect: u spans 4, v 2, both divided by 4.
  expect_range(range_of(tree, run(tree, big, "normalizeUV",
                                  {{"", std::int64_t{0}}, {"", std::string("uvuniform")}})),
               {0, 0}, {1, 0.5});
  expect_range(range_of(tree, run(tree, big, "normalizeUV",
                                  {{"", std::int64_t{0}}, {"", std::string("v")}})),
               {12, 0}, {16, 1});
}

TEST(UvOps, DeleteAndMissingProjection) {
  ShapeTree tree;
  const ShapeId f = facade(tree);
  std::string warning;
  const ShapeId none = run(tree, f, "projectUV", {{"", std::int64_t{0}}}, &warning);
  EXPECT_EQ(warning,
            "no projection set up for uv set 0 (setupProjection first); no texture coordinates");
  EXPECT_FALSE(uv0(tree, none).has_value());
  run(tree, none, "scaleUV", {{"", std::int64_t{0}}, {"", 2.0}, {"", 2.0}}, &warning);
  EXPECT_EQ(warning,
            "the shape has no texture coordinates in uv set 0 (projectUV first); nothing changed");
  const ShapeId p =
      projected(tree, f, "scope.xy", {2, SizeMode::kAbsolute}, {1, SizeMode::kAbsolute});
  ASSERT_TRUE(uv0(tree, p).has_value());
  const ShapeId d = run(tree, p, "deleteUV", {{"", std::int64_t{0}}});
  EXPECT_FALSE(uv0(tree, d).has_value());
  // The projection stays: projectUV gives the coordinates back.
  EXPECT_TRUE(uv0(tree, run(tree, d, "projectUV", {{"", std::int64_t{0}}})).has_value());
  const OpResult zero = registry().run(tree, f, "setupProjection",
                                       {{"", std::int64_t{0}},
                                        {"", std::string("scope.xy")},
                                        {"", SizeSpec{0, SizeMode::kAbsolute}},
                                        {"", SizeSpec{1, SizeMode::kAbsolute}}});
  EXPECT_EQ(zero.error, "setupProjection: texture width and height must be finite and not 0");
}

TEST(UvOps, TextureSetsTheColormapAndCollectGivesTheParts) {
  ShapeTree tree;
  const ShapeId f = facade(tree);
  const ShapeId t = run(tree, f, "texture", {{"", std::string("brick.png")}});
  const ShapeId p =
      projected(tree, t, "scope.xy", {2, SizeMode::kAbsolute}, {1, SizeMode::kAbsolute});
  const Value* map = tree.attribute(p, kColormapAttribute);
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(*map, Value{std::string("brick.png")});
  const Scene scene = collect(tree);
  const Part* part = nullptr;
  for (const Building& b : scene.buildings) {
    for (const Part& candidate : b.parts) {
      if (candidate.uv) part = &candidate;
    }
  }
  ASSERT_NE(part, nullptr);
  EXPECT_EQ(part->attributes.count(uv_set_attribute(0)), 0U);  // texture state is no attribute
  ASSERT_GE(part->mesh.face_count(), 1U);
  const kernel::MaterialId m = part->mesh.tag(0).material;
  ASSERT_LT(m, scene.materials.size());
  EXPECT_EQ(scene.materials[m].texture, "brick.png");
  double u_max = -1;
  for (const Vec3& v : part->mesh.positions()) u_max = std::max(u_max, part->uv->at(v).x);
  EXPECT_NEAR(u_max, 5, 1e-9);
}

TEST(UvMap, MovedWithItsGeometry) {
  const UvMap map{{0.5, 0, 0}, 1, {0, 0, 1}, 0};  // u = x / 2 + 1, v = z
  // A quarter turn about z, then 10 m east: the old point (2, 0, 3) lands on (10, 2, 3).
  const kernel::Transform t{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {10, 0, 0}};
  const Vec2 before = map.at({2, 0, 3});
  const Vec2 after = map.moved(t).at({10, 2, 3});
  EXPECT_NEAR(after.x, before.x, 1e-12);
  EXPECT_NEAR(after.y, before.y, 1e-12);
  EXPECT_NEAR(before.x, 2, 1e-12);
}

}  // namespace
}  // namespace insula::shape
