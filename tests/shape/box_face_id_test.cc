// Box faces carry no face id: a face id is a name interned by the shape tree
// (ShapeTree::face_id = intern(name) + 1, seed 001 §3.1.1), so a box numbering its sides 0-5 would
// make its roof read as the first name a tree interned.
#include <gtest/gtest.h>

#include <string>

#include "shape/ops.h"
#include "shape/shape_tree.h"

namespace insula::shape {
namespace {

TEST(BoxFaceId, NamedFaceIdsNeverEqualBoxFaceIds) {
  ShapeTree tree;
  const auto box = box_mesh({2, 3, 4}, mass_box_tags());
  ASSERT_EQ(box->face_count(), 6u);
  // The first names a program interns get the smallest ids (1, 2, ...).
  for (const char* name : {"front", "back", "left", "right", "top", "bottom", "a", "b"}) {
    const std::uint32_t id = tree.face_id(name);
    EXPECT_NE(id, 0u);
    for (std::size_t f = 0; f < box->face_count(); ++f) {
      EXPECT_NE(box->tag(f).face_id, id) << name << " equals the id of box side " << f;
    }
  }
  for (std::size_t f = 0; f < box->face_count(); ++f) {
    EXPECT_EQ(box->tag(f).face_id, 0u);
    EXPECT_TRUE(tree.face_name(box->tag(f).face_id).empty());
  }
}

TEST(BoxFaceId, RootBoxSidesHaveNoNames) {
  ShapeTree tree;
  (void)tree.face_id("roof");  // id 1: the raw number the old box gave its +y side
  Scope scope;
  scope.size = {3, 2, 1};
  const ShapeId root = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  std::array<kernel::FaceTag, 6> tags{};
  ASSERT_TRUE(is_box(*tree[root].mesh, scope.size, &tags, 1e-9));
  for (const kernel::FaceTag& tag : tags) EXPECT_EQ(tree.face_name(tag.face_id), "");
  // The semantic classes stay: ground below, roof above, walls around.
  EXPECT_EQ(tags[2].semantic, kernel::SemanticClass::kGroundSurface);
  EXPECT_EQ(tags[3].semantic, kernel::SemanticClass::kRoofSurface);
  EXPECT_EQ(tags[0].semantic, kernel::SemanticClass::kWallSurface);
}

}  // namespace
}  // namespace insula::shape
