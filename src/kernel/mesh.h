// A polygon mesh with n-gon faces. Every face is one simple planar loop of vertex indices
// (counter-clockwise seen from outside, so the right-hand normal points out) and carries a tag:
// semantic class, material id and face id. A region with holes is stored as several hole-free faces
// that share its face id (docs/kernel.md), so every consumer (OBJ, glTF, CityJSON, the renderer)
// handles only simple loops. Storage is flat (one index array plus offsets) to keep meshes small.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "kernel/semantic.h"
#include "kernel/vec.h"

namespace insula::kernel {

using MaterialId = std::uint16_t;  // index into the scene's material table; 0 = default by class

struct FaceTag {
  SemanticClass semantic = SemanticClass::kNone;
  MaterialId material = 0;
  std::uint32_t face_id = 0;  // the logical face this piece belongs to (seed 001, §3.1.1)
};

struct Bounds3 {
  Vec3 min{1e300, 1e300, 1e300};
  Vec3 max{-1e300, -1e300, -1e300};
  void add(Vec3 p);
  bool empty() const { return min.x > max.x; }
  Vec3 size() const { return empty() ? Vec3{} : max - min; }
};

class Mesh {
 public:
  // add_vertex and add_face are defined inline below: every mesh builder calls them in its inner
  // loop (a building's boxes alone make tens of thousands of faces).
  std::uint32_t add_vertex(Vec3 position);
  // Adds a face over existing vertex indices (at least 3). Returns the face index.
  std::uint32_t add_face(std::span<const std::uint32_t> loop, FaceTag tag);
  std::uint32_t add_face(std::initializer_list<std::uint32_t> loop, FaceTag tag);
  // Adds corners.size() / n faces of n vertices each, all tagged `tag`: face f runs over
  // base + corners[f n], ..., base + corners[f n + n - 1]. The same faces as that many add_face
  // calls, with one size check per array instead of one per face (boxes and other fixed solids
  // whose face loops are a constant table).
  void add_faces(std::span<const std::uint32_t> corners, std::uint32_t n, std::uint32_t base,
                 FaceTag tag);
  // Room for `faces` new faces holding `indices` vertex indices in all, for builders that compute
  // their loops in place (no loop vector per face). The caller fills every slot: face f's loop goes
  // into indices[...] right after face f - 1's, ends[f] is the absolute end of face f's loop
  // (first_index + the number of indices written up to and including face f), tags[f] its tag.
  struct FaceSlots {
    std::span<std::uint32_t> indices;
    std::span<std::uint32_t> ends;
    std::span<FaceTag> tags;
    std::uint32_t first_index = 0;  // the number of face indices the mesh held before the call
  };
  FaceSlots add_face_slots(std::size_t faces, std::size_t indices);
  // Adds a face with its own new vertices.
  std::uint32_t add_polygon(std::span<const Vec3> loop, FaceTag tag);
  // Appends all of `other`'s vertices and faces.
  void append(const Mesh& other);
  void reserve(std::size_t vertices, std::size_t faces, std::size_t indices);
  // Empty again, keeping the storage (a scratch mesh refilled face after face).
  void clear();

  std::size_t vertex_count() const { return positions_.size(); }
  std::size_t face_count() const { return tags_.size(); }
  bool empty() const { return tags_.empty(); }

  const std::vector<Vec3>& positions() const { return positions_; }
  std::vector<Vec3>& positions() { return positions_; }
  Vec3 position(std::uint32_t vertex) const { return positions_[vertex]; }
  std::span<const std::uint32_t> face(std::size_t face) const {
    return {indices_.data() + offsets_[face], offsets_[face + 1] - offsets_[face]};
  }
  const FaceTag& tag(std::size_t face) const { return tags_[face]; }
  FaceTag& tag(std::size_t face) { return tags_[face]; }

  // Reverses every face loop (turns the mesh inside out).
  void flip();
  Bounds3 bounds() const;
  // Number of triangles a fan/ear triangulation of all faces produces (sum of n - 2).
  std::size_t triangle_count() const;

 private:
  std::vector<Vec3> positions_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::uint32_t> offsets_{0};
  std::vector<FaceTag> tags_;
};

inline std::uint32_t Mesh::add_vertex(Vec3 position) {
  positions_.push_back(position);
  return static_cast<std::uint32_t>(positions_.size() - 1);
}

inline std::uint32_t Mesh::add_face(std::span<const std::uint32_t> loop, FaceTag tag) {
  indices_.insert(indices_.end(), loop.begin(), loop.end());
  offsets_.push_back(static_cast<std::uint32_t>(indices_.size()));
  tags_.push_back(tag);
  return static_cast<std::uint32_t>(tags_.size() - 1);
}

inline std::uint32_t Mesh::add_face(std::initializer_list<std::uint32_t> loop, FaceTag tag) {
  return add_face(std::span<const std::uint32_t>(loop.begin(), loop.size()), tag);
}

inline void Mesh::add_faces(std::span<const std::uint32_t> corners, std::uint32_t n,
                            std::uint32_t base, FaceTag tag) {
  const std::size_t first_index = indices_.size();
  const std::size_t first_face = offsets_.size();
  const std::size_t faces = corners.size() / n;
  indices_.resize(first_index + faces * n);
  offsets_.resize(first_face + faces);
  std::uint32_t* index = indices_.data() + first_index;
  for (std::size_t i = 0; i < faces * n; ++i) index[i] = base + corners[i];
  auto end = static_cast<std::uint32_t>(first_index);
  for (std::size_t f = 0; f < faces; ++f) offsets_[first_face + f] = end += n;
  tags_.insert(tags_.end(), faces, tag);
}

inline Mesh::FaceSlots Mesh::add_face_slots(std::size_t faces, std::size_t indices) {
  const std::size_t first_index = indices_.size();
  const std::size_t first_face = tags_.size();
  indices_.resize(first_index + indices);
  offsets_.resize(first_face + 1 + faces);
  tags_.resize(first_face + faces);
  return {{indices_.data() + first_index, indices},
          {offsets_.data() + first_face + 1, faces},
          {tags_.data() + first_face, faces},
          static_cast<std::uint32_t>(first_index)};
}

// Newell normal of a face (unit length; zero for a degenerate face).
Vec3 face_normal(const Mesh& mesh, std::size_t face);
double face_area(const Mesh& mesh, std::size_t face);
double surface_area(const Mesh& mesh);
// Signed volume by the divergence theorem; positive for a closed, outward-oriented mesh.
double volume(const Mesh& mesh);

// Merges vertices closer than `tolerance` (grid hashing), removes repeated indices inside loops and
// faces left with fewer than 3 vertices.
Mesh weld(const Mesh& mesh, double tolerance = 1e-7);

// The same mesh in an order that depends only on its geometry: vertices sorted by position
// (x, then y, then z), each face loop rotated to start at its least vertex, faces sorted by loop
// then tag. For results whose order comes from a library's internal numbering (CGAL's
// corefinement), so equal geometry gives equal bytes.
Mesh canonical_order(const Mesh& mesh);

// Whether `a` and `b` have the same vertices (positions, exactly), face loops and tags, in the
// same order; and a hash of the same (FNV-1a), equal for such meshes. For sharing meshes that
// different operations made alike (equal i() results become instances of one mesh).
bool same_content(const Mesh& a, const Mesh& b);
std::uint64_t content_hash(const Mesh& mesh);

struct MeshCheck {
  bool closed = false;    // every directed edge has exactly one opposite partner
  bool oriented = false;  // no directed edge is used twice (consistent orientation)
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  int euler_characteristic = 0;  // V - E + F over vertices used by faces
  std::size_t components = 0;
};
// Topological check on vertex indices (weld first when faces do not share indices).
MeshCheck check(const Mesh& mesh);
// Closed, oriented, manifold and of positive volume after welding: a solid a validator accepts.
bool is_watertight(const Mesh& mesh, double tolerance = 1e-7);

}  // namespace insula::kernel
