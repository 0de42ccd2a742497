// Mesh::add_faces and Mesh::add_face_slots must give exactly the faces add_face gives.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/mesh.h"

namespace insula::kernel {
namespace {

bool same_faces(const Mesh& a, const Mesh& b) {
  if (a.face_count() != b.face_count()) return false;
  for (std::size_t f = 0; f < a.face_count(); ++f) {
    const auto fa = a.face(f);
    const auto fb = b.face(f);
    if (!std::equal(fa.begin(), fa.end(), fb.begin(), fb.end())) return false;
    const FaceTag& ta = a.tag(f);
    const FaceTag& tb = b.tag(f);
    if (ta.semantic != tb.semantic || ta.material != tb.material || ta.face_id != tb.face_id) {
      return false;
    }
  }
  return true;
}

Mesh with_cube_vertices(int cubes) {
  Mesh m;
  for (int c = 0; c < cubes; ++c) {
    for (int i = 0; i < 8; ++i) {
      m.add_vertex({double(i & 1) + 2 * c, double((i >> 1) & 1), double((i >> 2) & 1)});
    }
  }
  return m;
}

constexpr std::array<std::uint32_t, 24> kCube{0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                              2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

TEST(MeshBulkFaces, AddFacesMatchesAddFaceAfterExistingFaces) {
  const FaceTag first{SemanticClass::kRoofSurface, 3, 7};
  const FaceTag tag{SemanticClass::kWindow, 2, 9};
  Mesh bulk = with_cube_vertices(2);
  Mesh single = with_cube_vertices(2);
  bulk.add_face({0, 1, 2}, first);  // faces already present shift the new offsets
  single.add_face({0, 1, 2}, first);
  bulk.add_faces(kCube, 4, 8, tag);
  for (std::size_t f = 0; f < 6; ++f) {
    single.add_face(
        {8 + kCube[4 * f], 8 + kCube[4 * f + 1], 8 + kCube[4 * f + 2], 8 + kCube[4 * f + 3]}, tag);
  }
  EXPECT_EQ(bulk.face_count(), 7U);
  EXPECT_TRUE(same_faces(bulk, single));
  EXPECT_EQ(bulk.face(6).size(), 4U);
  EXPECT_EQ(bulk.face(6)[0], 9U);  // the last quad starts at 8 + kCube[20] = 8 + 1
}

TEST(MeshBulkFaces, AddFacesBuildsAClosedBox) {
  Mesh m = with_cube_vertices(1);
  m.add_faces(kCube, 4, 0, {SemanticClass::kWallSurface, 0, 0});
  const MeshCheck check = kernel::check(m);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.oriented);
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
}

TEST(MeshBulkFaces, FaceSlotsHoldMixedSizesAndTags) {
  Mesh slots = with_cube_vertices(1);
  Mesh single = with_cube_vertices(1);
  const FaceTag a{SemanticClass::kWallSurface, 1, 4};
  const FaceTag b{SemanticClass::kJamb, 0, 5};
  single.add_face({0, 1, 3}, a);
  slots.add_face({0, 1, 3}, a);
  const std::vector<std::vector<std::uint32_t>> loops{{4, 5, 7, 6}, {0, 2, 6}, {1, 3, 7, 5, 4}};
  const Mesh::FaceSlots s = slots.add_face_slots(3, 12);
  EXPECT_EQ(s.first_index, 3U);
  std::size_t written = 0;
  for (std::size_t f = 0; f < loops.size(); ++f) {
    for (std::uint32_t v : loops[f]) s.indices[written++] = v;
    s.ends[f] = s.first_index + static_cast<std::uint32_t>(written);
    s.tags[f] = f == 1 ? b : a;
    single.add_face(loops[f], f == 1 ? b : a);
  }
  EXPECT_EQ(written, 12U);
  EXPECT_TRUE(same_faces(slots, single));
  EXPECT_EQ(slots.face(3).size(), 5U);
  EXPECT_EQ(slots.tag(2).semantic, SemanticClass::kJamb);
}

}  // namespace
}  // namespace insula::kernel
