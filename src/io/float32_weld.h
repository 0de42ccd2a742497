// Float32 output of a kernel mesh without breaking its shell (issue 12 item 10). glTF stores
// positions as float32: distinct vertices closer than float32 resolves at their coordinates (0.24
// mm at 3 km from the scene origin; the near-coincident skeleton nodes of a fine roof) land on one
// position, and a closed, oriented shell then gets degenerate triangles and edges used by four
// triangles once a reader welds by position. Float32Weld decides which vertices are written as one
// and triangulates the faces over them so that the written triangles stay closed and consistently
// oriented wherever the mesh was.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "io/triangulated.h"
#include "kernel/mesh.h"

namespace insula::io {

using Float3 = std::array<float, 3>;

// glTF's Y-up frame: (x, y, z) Z-up local meters -> (x, z, -y) as float32.
Float3 to_y_up(kernel::Vec3 p);

class Float32Weld {
 public:
  // For a mesh two of whose vertices at different positions round to one float32 position (the
  // caller finds them as it looks its positions up). Only a shell that was closed and consistently
  // oriented can be kept so: for one, vertices at one float32 position form a group, every face is
  // contracted over the groups (FaceTriangulator::triangulate_contracted) and its pieces
  // triangulated; then the two end points of every triangle edge used more than once in a
  // direction or without its reverse are grouped too, and the faces triangulated again, until no
  // such edge is left (at most kMaxPasses passes). Returns whether it did so (active()). An open
  // or non-manifold mesh (a triangle soup, an open surface: most meshes asked) is left to the
  // caller, which contracts each face over its own rounded corners. With `grid` > 0 (meters),
  // positions are rounded to multiples of `grid` instead: the grid of quantized glTF positions
  // (KHR_mesh_quantization), where the same holds at a coarser step.
  bool run(const kernel::Mesh& mesh, double grid = 0);
  // Forgets the last mesh: no vertex is grouped.
  void clear() { active_ = false; }

  bool active() const { return active_; }
  // The vertex whose float32 position `vertex` is written at (itself unless grouped).
  std::uint32_t representative(std::uint32_t vertex) const {
    return active_ ? parent_[vertex] : vertex;
  }
  // When active: the triangles of face `face`, as representative vertex ids, each wound like the
  // face; empty when the whole face contracted away.
  std::span<const std::array<std::uint32_t, 3>> triangles(std::size_t face) const {
    return std::span(triangles_).subspan(offsets_[face], offsets_[face + 1] - offsets_[face]);
  }

 private:
  static constexpr int kMaxPasses = 8;

  void group(const kernel::Mesh& mesh, double grid);
  std::uint32_t find(std::uint32_t v);
  bool unite(std::uint32_t a, std::uint32_t b);
  void flatten();
  void find_same(const kernel::Mesh& mesh);
  bool closed_and_oriented(const kernel::Mesh& mesh);
  std::uint64_t edge_sum(const kernel::Mesh& mesh);
  void triangulate_all(const kernel::Mesh& mesh);
  // Groups the end points of every triangle edge used wrongly; false when there is none.
  bool unite_bad_edges();

  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> same_;  // per vertex, the first vertex at its exact position
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<std::size_t> offsets_;  // face f's triangles: [offsets_[f], offsets_[f + 1])
  bool active_ = false;
  // Scratch reused from mesh to mesh and face to face.
  static constexpr std::uint32_t kFree = UINT32_MAX;
  std::vector<std::uint32_t> slots_;        // group(): vertices by rounded position
  std::vector<std::uint32_t> exact_slots_;  // find_same(): vertices by exact position
  std::vector<Float3> rounded_;
  std::vector<std::uint32_t> keys_;
  std::vector<std::uint64_t> edges_;  // closed_and_oriented(): directed edges as (a << 32 | b)
  std::vector<std::array<std::uint64_t, 2>> mixes_;  // edge_sum(): per vertex
  std::vector<kernel::Vec3> positions_;              // a face's corners' positions
  std::vector<CornerTriangle> corner_triangles_;
  FaceTriangulator triangulator_;
};

}  // namespace insula::io
