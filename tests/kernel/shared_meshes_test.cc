// kernel::same_content, content_hash and SharedMeshes: meshes alike in every vertex, face and tag
// become one; any difference keeps them apart.
#include <gtest/gtest.h>

#include <memory>

#include "kernel/mesh.h"
#include "kernel/shared_meshes.h"

namespace insula::kernel {
namespace {

Mesh triangle(double x, MaterialId material = 0) {
  Mesh mesh;
  mesh.add_vertex({x, 0, 0});
  mesh.add_vertex({x + 1, 0, 0});
  mesh.add_vertex({x, 1, 0});
  mesh.add_face({0, 1, 2}, {SemanticClass::kRoofSurface, material, 0});
  return mesh;
}

TEST(SharedMeshes, AlikeMeshesHashAndCompareEqual) {
  EXPECT_TRUE(same_content(triangle(0), triangle(0)));
  EXPECT_EQ(content_hash(triangle(0)), content_hash(triangle(0)));
  EXPECT_FALSE(same_content(triangle(0), triangle(0.5)));   // a position
  EXPECT_FALSE(same_content(triangle(0), triangle(0, 3)));  // a tag
  EXPECT_NE(content_hash(triangle(0)), content_hash(triangle(0, 3)));
  Mesh turned = triangle(0);
  Mesh other;
  other.add_vertex({0, 0, 0});
  other.add_vertex({1, 0, 0});
  other.add_vertex({0, 1, 0});
  other.add_face({1, 2, 0}, turned.tag(0));  // the same corners, another loop start
  EXPECT_FALSE(same_content(turned, other));
}

TEST(SharedMeshes, ShareReturnsTheFirstAlikeMesh) {
  SharedMeshes shared;
  const auto a = std::make_shared<const Mesh>(triangle(0));
  const auto b = std::make_shared<const Mesh>(triangle(0));
  const auto c = std::make_shared<const Mesh>(triangle(2));
  EXPECT_EQ(shared.share(a), a);
  EXPECT_EQ(shared.share(b), a);
  EXPECT_EQ(shared.share(c), c);
}

}  // namespace
}  // namespace insula::kernel
