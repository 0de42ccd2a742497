#include "io/float32_weld.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <tuple>

#include "kernel/contract_loop.h"

namespace insula::io {
Float3 to_y_up(kernel::Vec3 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.z), static_cast<float>(-p.y)};
}

namespace {

// The position `p` is written at, to compare: float32 or a multiple of `grid` (glTF's Y-up frame).
Float3 rounded(kernel::Vec3 p, double grid) {
  if (grid <= 0) return to_y_up(p);
  return {static_cast<float>(std::round(p.x / grid)), static_cast<float>(std::round(p.z / grid)),
          static_cast<float>(std::round(-p.y / grid))};
}

}  // namespace

bool Float32Weld::run(const kernel::Mesh& mesh, double grid) {
  const auto n = static_cast<std::uint32_t>(mesh.vertex_count());
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0U);
  active_ = false;
  if (!collapses(mesh, grid)) return false;
  std::vector<Entry>& order = order_;
  order.clear();
  for (std::uint32_t v = 0; v < n; ++v)
    order.push_back({rounded(mesh.position(v), grid), mesh.position(v), v});
  std::sort(order.begin(), order.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.rounded, a.p.x, a.p.y, a.p.z, a.vertex) <
           std::tie(b.rounded, b.p.x, b.p.y, b.p.z, b.vertex);
  });
  bool collapsed = false;
  for (std::size_t i = 1; i < order.size(); ++i) {
    collapsed =
        collapsed || (order[i].rounded == order[i - 1].rounded && !(order[i].p == order[i - 1].p));
  }
  if (!collapsed) return false;
  same_.resize(n);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const bool same = i > 0 && order[i].p == order[i - 1].p;
    same_[order[i].vertex] = same ? same_[order[i - 1].vertex] : order[i].vertex;
    if (i > 0 && order[i].rounded == order[i - 1].rounded)
      unite(order[i].vertex, order[i - 1].vertex);
  }
  active_ = true;
  flatten();
  triangulate_all(mesh);
  // Only a shell that was closed and oriented can be kept so; an open or non-manifold mesh (a
  // triangle soup, an open surface) is contracted face by face and left as it is otherwise.
  if (!closed_and_oriented(mesh)) return true;
  for (int pass = 0; pass < kMaxPasses && unite_bad_edges(); ++pass) {
    flatten();
    triangulate_all(mesh);
  }
  return true;
}

// Whether two vertices at different positions round to one: the usual answer, no, found with a
// hash table of the rounded positions rather than by sorting the vertices.
bool Float32Weld::collapses(const kernel::Mesh& mesh, double grid) {
  const std::size_t n = mesh.vertex_count();
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  slots_.assign(capacity, kFree);
  rounded_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    Float3& r = rounded_[v];
    r = rounded(mesh.position(v), grid);
    std::uint64_t hash = 0;
    for (float& c : r) {
      c += 0.0F;  // -0 as +0: they compare equal
      hash = (hash ^ std::bit_cast<std::uint32_t>(c)) * 0x9E3779B97F4A7C15ULL;
    }
    std::size_t slot = (hash >> 32U) & (capacity - 1);
    for (; slots_[slot] != kFree; slot = (slot + 1) & (capacity - 1)) {
      const std::uint32_t u = slots_[slot];
      if (rounded_[u] == r && !(mesh.position(u) == mesh.position(v))) return true;
    }
    slots_[slot] = v;
  }
  return false;
}

std::uint32_t Float32Weld::find(std::uint32_t v) {
  while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
  return v;
}

// The group's representative is its lowest vertex id, whatever the order of unions.
bool Float32Weld::unite(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  parent_[std::max(a, b)] = std::min(a, b);
  return true;
}

void Float32Weld::flatten() {
  for (std::uint32_t v = 0; v < parent_.size(); ++v) parent_[v] = find(v);
}

bool Float32Weld::closed_and_oriented(const kernel::Mesh& mesh) const {
  kernel::EdgeUses uses;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = same_[loop[i]];
      const std::uint32_t b = same_[loop[(i + 1) % loop.size()]];
      if (a != b) uses.add(a, b);
    }
  }
  return mesh.face_count() > 0 && uses.unpaired().empty();
}

void Float32Weld::triangulate_all(const kernel::Mesh& mesh) {
  triangles_.clear();
  offsets_.assign(1, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    keys_.clear();
    for (std::uint32_t v : mesh.face(f)) keys_.push_back(parent_[v]);
    for (const std::vector<std::uint32_t>& piece : kernel::contract_loop(keys_)) {
      triangulate_piece(mesh, f, piece);
    }
    offsets_.push_back(triangles_.size());
  }
}

// A piece the triangulator rejects (it may overlap itself after rounding) still closes the shell
// as a fan: every fan triangle follows the loop's orientation.
void Float32Weld::triangulate_piece(const kernel::Mesh& mesh, std::size_t face,
                                    std::span<const std::uint32_t> corners) {
  piece_ = kernel::Mesh();
  ids_.clear();
  for (std::uint32_t corner : corners) {
    ids_.push_back(piece_.add_vertex(mesh.position(keys_[corner])));
  }
  piece_.add_face(ids_, mesh.tag(face));
  corner_triangles_.clear();
  if (!triangulator_.triangulate(piece_, 0, kernel::face_normal(mesh, face), corner_triangles_)) {
    for (std::uint32_t i = 1; i + 1 < corners.size(); ++i)
      corner_triangles_.push_back({0, i, i + 1});
  }
  for (const CornerTriangle& t : corner_triangles_) {
    triangles_.push_back({keys_[corners[t[0]]], keys_[corners[t[1]]], keys_[corners[t[2]]]});
  }
}

// Besides the pinches of kernel::EdgeUses, triangulating a contracted, nearly degenerate piece
// can run a diagonal along an edge of another face; contracting that edge removes it as well.
bool Float32Weld::unite_bad_edges() {
  kernel::EdgeUses uses;
  for (const auto& t : triangles_) uses.add_loop(t);
  bool united = false;
  for (const auto& [a, b] : uses.unpaired()) united = unite(a, b) || united;
  return united;
}

}  // namespace insula::io
