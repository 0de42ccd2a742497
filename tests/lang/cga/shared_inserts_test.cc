// Issue 21 item 2: equal i() results share one mesh (DeriveOptions::share_inserts) and become
// instances of it in the export model (to_scene(..., true)), placed where each terminal stands,
// so a GLB can place them with EXT_mesh_gpu_instancing; without the option nothing changes.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "../../common/map_assets.h"
#include "derive_util.h"
#include "kernel/mesh.h"
#include "shape/part_mesh.h"

namespace insula::lang::cga {
namespace {

using kernel::Vec3;
using testing::compile_text;
using testing::derive_all;
using testing::rectangle_lot;

// A unit box with outward faces.
std::shared_ptr<const kernel::Mesh> unit_box() {
  auto mesh = std::make_shared<kernel::Mesh>();
  for (int i = 0; i < 8; ++i)
    mesh->add_vertex({static_cast<double>(i & 1), static_cast<double>((i >> 1) & 1),
                      static_cast<double>(i >> 2)});
  const kernel::FaceTag tag{kernel::SemanticClass::kWallSurface, 0, 0};
  for (const auto& f : {std::vector<std::uint32_t>{0, 2, 3, 1},
                        {4, 5, 7, 6},
                        {0, 1, 5, 4},
                        {2, 6, 7, 3},
                        {0, 4, 6, 2},
                        {1, 3, 7, 5}}) {
    mesh->add_face(f, tag);
  }
  return mesh;
}

struct Derived {
  shape::Scene plain;
  shape::Scene shared;
};

// Ten posts of 2 x 10 x 3 m along a 20 m lot, the last two red; and one wider post.
Derived derive_posts() {
  const auto program = compile_text(
      "version \"2019.0\"\n"
      "Lot --> extrude(3) split(x) { 2 : Post }* \n"
      "Post --> case split.index >= 8 : i(\"post\") color(\"#aa0000\") Red\n"
      "         else : i(\"post\") Post.\n");
  EXPECT_TRUE(program);
  insula::testing::MapAssets assets;
  assets.meshes["post"] = unit_box();
  Derived out;
  for (const bool share : {false, true}) {
    DeriveOptions options;
    options.assets = &assets;
    options.share_inserts = share;
    const std::vector<Lot> lots{rectangle_lot(20, 10)};
    const std::vector<LotResult> results = derive_all(*program, lots, options);
    EXPECT_TRUE(results[0].ok);
    (share ? out.shared : out.plain) = to_scene(*program, lots, results, share);
  }
  return out;
}

TEST(SharedInserts, EqualInsertsBecomeInstancesOfOneMeshPerColour) {
  const Derived d = derive_posts();
  ASSERT_EQ(d.plain.buildings.size(), 1U);
  ASSERT_EQ(d.shared.buildings.size(), 1U);
  const std::vector<shape::Part>& plain = d.plain.buildings[0].parts;
  const std::vector<shape::Part>& shared = d.shared.buildings[0].parts;
  ASSERT_EQ(plain.size(), 10U);
  ASSERT_EQ(shared.size(), 10U);
  std::set<const kernel::Mesh*> meshes;
  for (const shape::Part& part : plain) EXPECT_EQ(part.instance_of, nullptr);
  for (const shape::Part& part : shared) {
    ASSERT_NE(part.instance_of, nullptr) << part.name;
    EXPECT_TRUE(part.mesh.empty());
    meshes.insert(part.instance_of.get());
  }
  EXPECT_EQ(meshes.size(), 2U);  // one plain, one red
  EXPECT_NE(shared[9].instance_of->tag(0).material, 0U);
  EXPECT_EQ(shared[0].instance_of->tag(0).material, 0U);
}

TEST(SharedInserts, InstancesStandWhereThePlainPartsStand) {
  const Derived d = derive_posts();
  for (std::size_t p = 0; p < 10; ++p) {
    const kernel::Mesh a = shape::part_world_mesh(d.plain.buildings[0].parts[p]);
    const kernel::Mesh b = shape::part_world_mesh(d.shared.buildings[0].parts[p]);
    ASSERT_EQ(a.vertex_count(), b.vertex_count());
    for (std::size_t v = 0; v < a.vertex_count(); ++v) {
      const Vec3 pa = a.position(v);
      const Vec3 pb = b.position(v);
      EXPECT_NEAR(pa.x, pb.x, 1e-9);
      EXPECT_NEAR(pa.y, pb.y, 1e-9);
      EXPECT_NEAR(pa.z, pb.z, 1e-9);
    }
    EXPECT_EQ(a.tag(0).material, b.tag(0).material);
  }
  // Post p spans x 2p .. 2p + 2.
  const kernel::Bounds3 b = shape::part_world_mesh(d.shared.buildings[0].parts[3]).bounds();
  EXPECT_NEAR(b.min.x, 6, 1e-9);
  EXPECT_NEAR(b.max.x, 8, 1e-9);
  EXPECT_NEAR(b.max.z, 3, 1e-9);
}

}  // namespace
}  // namespace insula::lang::cga
