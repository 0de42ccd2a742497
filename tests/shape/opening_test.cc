#include <gtest/gtest.h>

#include "shape/component_ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;
using kernel::Vec3;

ShapeId room(ShapeTree& tree, Vec3 size) {
  Scope scope;
  scope.x = {1, 0, 0};
  scope.y = {0, 0, 1};
  scope.z = {0, -1, 0};
  scope.size = size;
  return tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
}

double world_volume(const ShapeTree& tree, ShapeId id) {
  return kernel::volume(mesh_to_world(*tree[id].mesh, tree[id].scope));
}

// The front (+z scope) face of the room as a flat component.
ShapeId front_face(ShapeTree& tree, ShapeId r) {
  for (std::size_t f = 0; f < tree[r].mesh->face_count(); ++f) {
    if (face_matches(FaceSelector::kFront, kernel::face_normal(*tree[r].mesh, f))) {
      return face_component(tree, r, f).children.at(0);
    }
  }
  return kNoShape;
}

TEST(Opening, DoorAndWindowCutThroughASlabWall) {
  ShapeTree tree;
  const ShapeId r = room(tree, {5, 3, 4});
  const ShapeId face = front_face(tree, r);
  const ShapeId wall = extrude_joint(tree, std::span(&face, 1), -0.2).children.at(0);
  OpeningSpec door;
  door.u = 1.5;
  door.width = 1;
  door.height = 2;
  const ShapeId d = add_opening(tree, face, door).children.at(0);
  OpeningSpec window;
  window.kind = OpeningKind::kWindow;
  window.u = 3.5;
  window.sill = 1;
  window.width = 1.2;
  window.height = 1.5;
  const ShapeId w = add_opening(tree, face, window).children.at(0);
  EXPECT_TRUE(tree.has_label(d, "door"));
  EXPECT_TRUE(tree.has_label(w, "opening"));
  const auto cut = opening_in_wall(tree, wall, d);
  ASSERT_TRUE(cut.has_value());
  EXPECT_NEAR(cut->width, 1, 1e-12);
  EXPECT_NEAR(cut->height, 2, 1e-12);
  SolidOptions options;
  options.openings = {d, w};
  const OpResult s = solid_geometry(tree, wall, options);
  ASSERT_TRUE(s.ok()) << s.error;
  const ShapeId solid = s.children.at(0);
  EXPECT_TRUE(tree.has_label(solid, "solid"));
  EXPECT_TRUE(kernel::is_watertight(*tree[solid].mesh));
  EXPECT_NEAR(world_volume(tree, solid), 0.2 * (15 - 2 - 1.8), 1e-9);
  int jambs = 0;
  for (std::size_t k = 0; k < tree[solid].mesh->face_count(); ++k) {
    jambs += tree[solid].mesh->tag(k).semantic == SemanticClass::kJamb ? 1 : 0;
  }
  EXPECT_EQ(jambs, 4);  // two per opening
  EXPECT_EQ(std::get<double>(*tree.attribute(solid, "openings_cut")), 2);
  // The door's own geometry: frame and leaf (the union half), watertight pieces.
  EXPECT_EQ(tree[d].mesh->face_count(), 4U * 6U);
  EXPECT_EQ(tree[w].mesh->face_count(), 5U * 6U);
}

TEST(Opening, DoorInAMitredRoomWallIsANotchAboveTheFloor) {
  ShapeTree tree;
  const ShapeId r = room(tree, {5, 3, 4});
  std::vector<ShapeId> faces;
  for (std::size_t f = 0; f < tree[r].mesh->face_count(); ++f) {
    const Vec3 n = kernel::face_normal(*tree[r].mesh, f);
    if (face_matches(FaceSelector::kSide, n) || face_matches(FaceSelector::kBottom, n)) {
      faces.push_back(face_component(tree, r, f).children.at(0));
    }
  }
  const OpResult walls = extrude_joint(tree, faces, -0.1);
  ASSERT_TRUE(walls.ok());
  ShapeId front = kNoShape;
  ShapeId front_wall = kNoShape;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (dot(tree[faces[i]].scope.z, Vec3{0, -1, 0}) > 0.99) {
      front = faces[i];
      front_wall = walls.children[i];
    }
  }
  ASSERT_NE(front, kNoShape);
  OpeningSpec door;
  door.u = 2.5;
  door.width = 1;
  door.height = 2.1;
  const ShapeId d = add_opening(tree, front, door).children.at(0);
  const double before = world_volume(tree, front_wall);
  SolidOptions options;
  options.openings = {d};
  const ShapeId solid = solid_geometry(tree, front_wall, options).children.at(0);
  EXPECT_TRUE(kernel::is_watertight(*tree[solid].mesh, 1e-7) ||
              kernel::check(kernel::weld(*tree[solid].mesh)).boundary_edges == 0);
  // The notch starts on top of the 0.1 m floor: 1 x 2.0 x 0.1 removed.
  EXPECT_NEAR(world_volume(tree, solid), before - 1 * 2.0 * 0.1, 1e-9);
}

TEST(Opening, AnOpeningInTheMitredEndIsCutByCorefinement) {
  // Walls meeting at corners, grown inward together: the window reaches from the corner into
  // the mitred end, where the wall is not a prism through its face; the planar path cannot cut
  // it and CGAL cuts the box out of the end piece and the slab.
  ShapeTree tree;
  const ShapeId r = room(tree, {5, 3, 4});
  std::vector<ShapeId> faces;
  for (std::size_t f = 0; f < tree[r].mesh->face_count(); ++f) {
    if (face_matches(FaceSelector::kSide, kernel::face_normal(*tree[r].mesh, f))) {
      faces.push_back(face_component(tree, r, f).children.at(0));
    }
  }
  const OpResult walls = extrude_joint(tree, faces, -0.2);
  ShapeId front = kNoShape;
  ShapeId front_wall = kNoShape;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (dot(tree[faces[i]].scope.z, Vec3{0, -1, 0}) > 0.99) {
      front = faces[i];
      front_wall = walls.children[i];
    }
  }
  ASSERT_NE(front, kNoShape);
  OpeningSpec window;
  window.kind = OpeningKind::kWindow;
  window.u = 0.55;  // [0.1, 1.0]: starts inside the 0.2 m mitre
  window.sill = 1;
  window.width = 0.9;
  window.height = 1;
  const ShapeId w = add_opening(tree, front, window).children.at(0);
  const double before = world_volume(tree, front_wall);
  SolidOptions options;
  options.openings = {w};
  const ShapeId solid = solid_geometry(tree, front_wall, options).children.at(0);
  EXPECT_EQ(std::get<double>(*tree.attribute(solid, "openings_cut")), 1);
  // The box [0.1, 1.0] x [1, 2] through the wall removes 0.9 x 0.2 of section, less the corner of
  // the mitre triangle (legs 0.1) that is not wall: 1 m high.
  EXPECT_NEAR(before - world_volume(tree, solid), 1.0 * (0.9 * 0.2 - 0.5 * 0.1 * 0.1), 1e-6);
}

TEST(Opening, OpeningsElsewhereLeaveTheGeometryShared) {
  ShapeTree tree;
  const ShapeId r = room(tree, {5, 3, 4});
  const ShapeId face = front_face(tree, r);
  const ShapeId wall = extrude_joint(tree, std::span(&face, 1), -0.2).children.at(0);
  SolidOptions options;
  options.uv_scale = 2;
  const ShapeId solid = solid_geometry(tree, wall, options).children.at(0);
  EXPECT_EQ(tree[solid].mesh, tree[wall].mesh);
  EXPECT_EQ(std::get<double>(*tree.attribute(solid, "uv_scale")), 2);
}

// The street facade of 40 row houses (examples/lua/row_house.lua): a 249 m shell wall grown
// outward with its neighbours, so its ends are mitred. The 2D boolean that finds the wall's core
// rounds (3e-7 m at 249 m); the core planes must still land on the mitre's vertices so the core
// is a slab and every window goes through the planar path (it went to corefinement, one opening
// at a time on the whole facade: seconds, and some openings were left uncut).
ShapeId long_facade(ShapeTree& tree, ShapeId& front) {
  const ShapeId r = room(tree, {248.77516131086429, 5.85, 10});
  std::vector<ShapeId> faces;
  for (std::size_t f = 0; f < tree[r].mesh->face_count(); ++f) {
    const Vec3 n = kernel::face_normal(*tree[r].mesh, f);
    if (face_matches(FaceSelector::kSide, n) || face_matches(FaceSelector::kBottom, n)) {
      faces.push_back(face_component(tree, r, f).children.at(0));
    }
  }
  const OpResult walls = extrude_joint(tree, faces, 0.25);
  EXPECT_TRUE(walls.ok());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (dot(tree[faces[i]].scope.z, Vec3{0, -1, 0}) > 0.99) {
      front = faces[i];
      return walls.children[i];
    }
  }
  return kNoShape;
}

TEST(Opening, WindowsAlongALongMitredFacadeAreAllCut) {
  ShapeTree tree;
  ShapeId front = kNoShape;
  const ShapeId wall = long_facade(tree, front);
  ASSERT_NE(wall, kNoShape);
  SolidOptions options;
  constexpr int kWindows = 80;
  for (int i = 0; i < kWindows; ++i) {
    OpeningSpec window;
    window.kind = OpeningKind::kWindow;
    window.u = 2 + 3 * i;
    window.sill = 0.9;
    window.width = 1.2;
    window.height = 1.4;
    options.openings.push_back(add_opening(tree, front, window).children.at(0));
  }
  const double before = world_volume(tree, wall);
  const ShapeId solid = solid_geometry(tree, wall, options).children.at(0);
  EXPECT_EQ(std::get<double>(*tree.attribute(solid, "openings_cut")), kWindows);
  EXPECT_NEAR(before - world_volume(tree, solid), kWindows * 1.2 * 1.4 * 0.25, 1e-5);
  EXPECT_EQ(kernel::check(kernel::weld(*tree[solid].mesh)).boundary_edges, 0u);
  // The planar path (kernel::build_wall): 4 reveal faces per window, the slab's 23 other faces
  // (front and back with 80 holes, the ends and their closures); corefinement's pieces have more.
  EXPECT_EQ(tree[solid].mesh->face_count(), 4u * kWindows + 23u);
}

TEST(Opening, OverlappingOpeningsAlongALongWallAreSweptInGroups) {
  // Pairs of overlapping windows: the planar path skips one of each pair, corefinement cuts it
  // in the group of its neighbour (the groups are swept along u over a slab split as it goes).
  ShapeTree tree;
  const ShapeId r = room(tree, {120, 3, 4});
  const ShapeId face = front_face(tree, r);
  const ShapeId wall = extrude_joint(tree, std::span(&face, 1), -0.2).children.at(0);
  SolidOptions options;
  constexpr int kPairs = 30;
  for (int i = 0; i < kPairs; ++i) {
    for (double shift : {0.0, 0.6}) {
      OpeningSpec window;
      window.kind = OpeningKind::kWindow;
      window.u = 2 + 4 * i + shift;
      window.sill = 1;
      window.width = 1;
      window.height = 1;
      options.openings.push_back(add_opening(tree, face, window).children.at(0));
    }
  }
  const double before = world_volume(tree, wall);
  const ShapeId solid = solid_geometry(tree, wall, options).children.at(0);
  EXPECT_EQ(std::get<double>(*tree.attribute(solid, "openings_cut")), 2 * kPairs);
  // Each pair removes the union [u - 0.5, u + 1.1] x [1, 2] through 0.2 m.
  EXPECT_NEAR(before - world_volume(tree, solid), kPairs * 1.6 * 1.0 * 0.2, 1e-6);
  EXPECT_EQ(kernel::check(kernel::weld(*tree[solid].mesh)).boundary_edges, 0u);
}

TEST(Opening, BadSizeIsAnError) {
  ShapeTree tree;
  const ShapeId r = room(tree, {5, 3, 4});
  const ShapeId face = front_face(tree, r);
  OpeningSpec bad;
  bad.width = 0;
  EXPECT_EQ(add_opening(tree, face, bad).error, "width, height and depth must be > 0");
  EXPECT_EQ(add_opening(tree, r, OpeningSpec{}).error, "an opening needs a flat wall component");
}

}  // namespace
}  // namespace insula::shape
