#include <gtest/gtest.h>

#include <map>

#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

// Assets by name, as the app's OBJ-backed provider would serve them.
class MapAssets : public AssetProvider {
 public:
  std::map<std::string, std::shared_ptr<const kernel::Mesh>, std::less<>> meshes;
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    auto it = meshes.find(name);
    if (it != meshes.end()) return it->second;
    error = "cannot open '" + std::string(name) + ".obj'";
    return nullptr;
  }
};

// A 1 x 2 x 0.5 box asset whose corner sits at (-0.5, 0, -0.25).
std::shared_ptr<const kernel::Mesh> door() {
  auto box = box_mesh({1, 2, 0.5}, mass_box_tags());
  return std::make_shared<kernel::Mesh>(
      kernel::transformed(*box, kernel::translation({-0.5, 0, -0.25})));
}

TEST(Insert, AssetFillsTheScope) {
  MapAssets assets;
  assets.meshes["door"] = door();
  ShapeTree tree;
  Scope s;
  s.size = {2, 3, 1};
  const ShapeId root = tree.add_root(s);
  const OpResult r =
      registry().run(tree, root, "insert", {{"", std::string("door")}}, Context{&assets});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& c = tree[r.children[0]];
  const kernel::Bounds3 b = c.mesh->bounds();
  EXPECT_NEAR(b.min.x, 0, 1e-12);
  EXPECT_NEAR(b.max.x, 2, 1e-12);
  EXPECT_NEAR(b.max.y, 3, 1e-12);
  EXPECT_NEAR(b.max.z, 1, 1e-12);
  EXPECT_NEAR(kernel::volume(*c.mesh), 6, 1e-9);
}

TEST(Insert, ZeroSizeAxesKeepProportions) {
  ShapeTree tree;
  Scope s;
  s.size = {2, 0, 0};  // only the width is given
  const ShapeId root = tree.add_root(s);
  const OpResult r = insert(tree, root, *door());
  ASSERT_TRUE(r.ok());
  const Shape& c = tree[r.children[0]];
  EXPECT_NEAR(c.scope.size.x, 2, 1e-12);
  EXPECT_NEAR(c.scope.size.y, 4, 1e-12);
  EXPECT_NEAR(c.scope.size.z, 1, 1e-12);
}

TEST(Insert, MissingProviderOrAsset) {
  MapAssets assets;
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{});
  EXPECT_EQ(registry().run(tree, root, "insert", {{"asset", std::string("x")}}).error,
            "insert: no asset provider");
  EXPECT_EQ(
      registry().run(tree, root, "insert", {{"asset", std::string("x")}}, Context{&assets}).error,
      "insert: cannot open 'x.obj'");
  EXPECT_EQ(insert(tree, root, kernel::Mesh{}).error, "the asset has no faces");
}

}  // namespace
}  // namespace insula::shape
