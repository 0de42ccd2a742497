// CityEngine's insertAlongUV in the registry (shape/ops_insert_along_uv.cc): the asset's x over u,
// z over -v, y over the height, repeated per whole uv tile, cut at the faces' uv edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../common/map_assets.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Polygon;
using kernel::Vec3;

using testing::MapAssets;

std::shared_ptr<const kernel::Mesh> box_at(Vec3 corner, Vec3 size) {
  return std::make_shared<kernel::Mesh>(
      kernel::transformed(*box_mesh(size, mass_box_tags()), kernel::translation(corner)));
}

// A step: a 1 m high block over z in [0, 1] and a 0.5 m high one over z in [1, 2].
std::shared_ptr<const kernel::Mesh> step() {
  auto mesh = std::make_shared<kernel::Mesh>(*box_at({0, 0, 0}, {1, 1, 1}));
  mesh->append(*box_at({0, 0, 1}, {1, 0.5, 1}));
  return mesh;
}

ShapeId run(ShapeTree& tree, ShapeId id, std::string_view op, std::vector<ArgInput> args) {
  const OpResult r = registry().run(tree, id, op, std::move(args));
  EXPECT_TRUE(r.ok()) << op << ": " << r.error;
  EXPECT_EQ(r.children.size(), 1U);
  return r.children.empty() ? kNoShape : r.children[0];
}

// A 10 x 2 m lot whose uv set 0 repeats every `tile` meters along x and once across y.
ShapeId strip(ShapeTree& tree, double tile) {
  const RootResult lot = tree.create_root(Polygon{{{0, 0}, {10, 0}, {10, 2}, {0, 2}}, {}});
  EXPECT_TRUE(lot.ok()) << lot.error;
  const ShapeId projected = run(tree, lot.id, "setupProjection",
                                {{"uvSet", 0.0},
                                 {"axes", std::string("scope.xy")},
                                 {"textureWidth", SizeSpec{tile, SizeMode::kAbsolute}},
                                 {"textureHeight", SizeSpec{1, SizeMode::kRelative}}});
  return run(tree, projected, "projectUV", {{"uvSet", 0.0}});
}

OpResult along(ShapeTree& tree, ShapeId id, const MapAssets& assets, double height,
               std::vector<ArgInput> more = {}) {
  std::vector<ArgInput> args = {{"uvSet", 0.0},
                                {"asset", std::string("asset")},
                                {"height", height},
                                {"heightDirection", std::string("scope.z")}};
  for (ArgInput& a : more) {
    auto same =
        std::find_if(args.begin(), args.end(), [&](const ArgInput& b) { return b.name == a.name; });
    if (same != args.end()) *same = std::move(a);
    if (same == args.end()) args.push_back(std::move(a));
  }
  return registry().run(tree, id, "insertAlongUV", args, Context{&assets});
}

// The child's mesh in the lot's space (the root's scope is the world here).
kernel::Mesh placed(const ShapeTree& tree, const OpResult& r) {
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.children.size(), 1U);
  const Shape& c = tree[r.children.at(0)];
  EXPECT_NE(c.mesh, nullptr);
  return c.mesh ? mesh_to_world(*c.mesh, c.scope) : kernel::Mesh{};
}

TEST(InsertAlongUvTest, OneTileFillsTheFaceAndStaysClosed) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({-0.5, 0, -0.25}, {1, 2, 0.5});
  ShapeTree tree;
  const kernel::Mesh m = placed(tree, along(tree, strip(tree, 10), assets, 3));
  const kernel::Bounds3 b = m.bounds();
  EXPECT_NEAR(b.min.x, 0, 1e-9);
  EXPECT_NEAR(b.max.x, 10, 1e-9);
  EXPECT_NEAR(b.min.y, 0, 1e-9);
  EXPECT_NEAR(b.max.y, 2, 1e-9);
  EXPECT_NEAR(b.min.z, 0, 1e-9);
  EXPECT_NEAR(b.max.z, 3, 1e-9);
  // Cut along the lot's diagonal (two uv triangles) and joined again: one closed box.
  EXPECT_NEAR(kernel::volume(m), 60, 1e-6);
  EXPECT_TRUE(kernel::is_watertight(m));
}

TEST(InsertAlongUvTest, RepeatsPerWholeTileAndCutsTheLastOne) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 0, 0}, {1, 1, 1});
  ShapeTree tree;
  // 4 m tiles over 10 m: two whole copies and half of a third, each 2 m deep and 1 m high.
  const kernel::Mesh m = placed(tree, along(tree, strip(tree, 4), assets, 1));
  EXPECT_NEAR(m.bounds().max.x, 10, 1e-9);
  double top = 0;  // the copies' tops cover the lot; the last one is open where it was cut
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    if (kernel::face_normal(m, f).z > 0.999) top += kernel::face_area(m, f);
  }
  EXPECT_NEAR(top, 20, 1e-9);
  EXPECT_FALSE(kernel::check(kernel::weld(m)).closed);
  std::size_t at_cut = 0;  // vertices on the tile boundaries x = 4 and x = 8
  for (const Vec3& p : m.positions()) {
    if (std::fabs(p.x - 4) < 1e-9 || std::fabs(p.x - 8) < 1e-9) ++at_cut;
  }
  EXPECT_GE(at_cut, 8U);
}

TEST(InsertAlongUvTest, AssetDepthRunsAgainstV) {
  MapAssets assets;
  assets.meshes["asset"] = step();
  ShapeTree tree;
  const kernel::Mesh m = placed(tree, along(tree, strip(tree, 10), assets, 2));
  // The asset's near end (z in [0, 1], 1 m high) maps to v in [0.5, 1]: the lot's far half.
  for (const Vec3& p : m.positions()) {
    if (p.y < 1 - 1e-9) {
      EXPECT_LE(p.z, 1 + 1e-9) << p.y;
    }
  }
  EXPECT_NEAR(m.bounds().max.z, 2, 1e-9);
  EXPECT_NEAR(kernel::volume(m), 10 * 1 * 2 + 10 * 1 * 1, 1e-6);
}

TEST(InsertAlongUvTest, KeepPositionLiftsByTheAssetsOrigin) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 1, 0}, {1, 1, 1});  // floats 1 m above its origin
  ShapeTree tree;
  const ShapeId lot = strip(tree, 10);
  const kernel::Mesh aligned = placed(tree, along(tree, lot, assets, 3));
  EXPECT_NEAR(aligned.bounds().min.z, 0, 1e-9);
  EXPECT_NEAR(aligned.bounds().max.z, 3, 1e-9);
  ShapeTree tree2;
  const kernel::Mesh kept =
      placed(tree2, along(tree2, strip(tree2, 10), assets, 3,
                          {{"heightAlignment", std::string("keepposition")}}));
  EXPECT_NEAR(kept.bounds().min.z, 3, 1e-9);
  EXPECT_NEAR(kept.bounds().max.z, 6, 1e-9);
}

TEST(InsertAlongUvTest, NegativeHeightHangsBelowAndStaysOutward) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 0, 0}, {1, 1, 1});
  ShapeTree tree;
  const kernel::Mesh m = placed(tree, along(tree, strip(tree, 10), assets, -2));
  EXPECT_NEAR(m.bounds().min.z, -2, 1e-9);
  EXPECT_NEAR(m.bounds().max.z, 0, 1e-9);
  EXPECT_NEAR(kernel::volume(m), 40, 1e-6);  // positive: faces turned back outwards
}

TEST(InsertAlongUvTest, VertexNormalsOfAFlatShapeAreItsNormal) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 0, 0}, {1, 1, 1});
  ShapeTree tree;
  const kernel::Mesh m = placed(tree, along(tree, strip(tree, 10), assets, 1,
                                            {{"heightDirection", std::string("vertex.normal")}}));
  EXPECT_NEAR(m.bounds().max.z, 1, 1e-9);
  EXPECT_NEAR(kernel::volume(m), 20, 1e-6);
}

TEST(InsertAlongUvTest, WithoutUvsOrAssetsNothingIsInserted) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 0, 0}, {1, 1, 1});
  assets.meshes["empty"] = std::make_shared<kernel::Mesh>();
  ShapeTree tree;
  const RootResult lot = tree.create_root(Polygon{{{0, 0}, {10, 0}, {10, 2}, {0, 2}}, {}});
  const OpResult bare = along(tree, lot.id, assets, 1);
  ASSERT_TRUE(bare.ok()) << bare.error;
  EXPECT_EQ(bare.warning,
            "the shape has no texture coordinates in uv set 0 (projectUV first); nothing inserted");
  EXPECT_EQ(tree[bare.children.at(0)].mesh, nullptr);
  ShapeTree tree2;
  const OpResult empty = registry().run(
      tree2, strip(tree2, 10), "insertAlongUV",
      {{"uvSet", 0.0}, {"asset", std::string("empty")}, {"height", 1.0}}, Context{&assets});
  ASSERT_TRUE(empty.ok()) << empty.error;
  EXPECT_EQ(tree2[empty.children.at(0)].mesh, nullptr);
  EXPECT_EQ(
      registry()
          .run(tree2, strip(tree2, 10), "insertAlongUV",
               {{"uvSet", 0.0}, {"asset", std::string("gone")}, {"height", 1.0}}, Context{&assets})
          .error,
      "insertAlongUV: cannot open 'gone.obj'");
}

TEST(InsertAlongUvTest, ALargeAssetOnManyTilesIsAnError) {
  // 100 copies (the strip is one convex region, 100 tiles long) of a 25,000-face asset: 2.5
  // million faces, past the bound of 2 million.
  auto big = std::make_shared<kernel::Mesh>();
  for (int k = 0; k < 25000; ++k) {
    const double x = (k % 500) / 500.0, z = (k / 500) / 500.0;
    big->add_polygon(std::vector<Vec3>{{x, 0, z}, {x + 0.001, 0, z}, {x, 1, z}}, {});
  }
  MapAssets assets;
  assets.meshes["asset"] = big;
  ShapeTree tree;
  const OpResult r = along(tree, strip(tree, 0.1), assets, 1);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("faces to cut"), std::string::npos) << r.error;
}

TEST(InsertAlongUvTest, ARunawayUvScaleIsAnError) {
  MapAssets assets;
  assets.meshes["asset"] = box_at({0, 0, 0}, {1, 1, 1});
  ShapeTree tree;
  const OpResult r = along(tree, strip(tree, 1e-5), assets, 1);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("the uv set repeats the asset"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace insula::shape
