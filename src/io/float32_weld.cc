#include "io/float32_weld.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "kernel/contract_loop.h"

namespace insula::io {
Float3 to_y_up(kernel::Vec3 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.z), static_cast<float>(-p.y)};
}

namespace {

// A slot of an open-addressing table of `capacity` (a power of two) for a position's bits.
template <typename Coordinate>
std::size_t hash_slot(const std::array<Coordinate, 3>& position, std::size_t capacity) {
  using Bits = std::conditional_t<sizeof(Coordinate) == 4, std::uint32_t, std::uint64_t>;
  std::uint64_t hash = 0;
  for (const Coordinate c : position) {
    hash = (hash ^ static_cast<std::uint64_t>(std::bit_cast<Bits>(c))) * 0x9E3779B97F4A7C15ULL;
  }
  return (hash >> 32U) & (capacity - 1);
}

// Slots for an open-addressing table of `n` entries: a power of two, at least twice `n`.
std::size_t table_capacity(std::size_t n) {
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  return capacity;
}

// The position `p` is written at, to compare: float32 or a multiple of `grid` (glTF's Y-up frame).
Float3 rounded(kernel::Vec3 p, double grid) {
  if (grid <= 0) return to_y_up(p);
  return {static_cast<float>(std::round(p.x / grid)), static_cast<float>(std::round(p.z / grid)),
          static_cast<float>(std::round(-p.y / grid))};
}

}  // namespace

bool Float32Weld::run(const kernel::Mesh& mesh, double grid) {
  active_ = false;
  if (!closed_and_oriented(mesh)) return false;
  const auto n = static_cast<std::uint32_t>(mesh.vertex_count());
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0U);
  group(mesh, grid);
  active_ = true;
  flatten();
  triangulate_all(mesh);
  for (int pass = 0; pass < kMaxPasses && unite_bad_edges(); ++pass) {
    flatten();
    triangulate_all(mesh);
  }
  return true;
}

// Every vertex united with the first (lowest) vertex at its rounded position: a hash table filled
// in vertex order (a sort of the vertices by position gave the same and cost more than the rest of
// the weld).
void Float32Weld::group(const kernel::Mesh& mesh, double grid) {
  const std::size_t n = mesh.vertex_count();
  const std::size_t capacity = table_capacity(n);
  slots_.assign(capacity, kFree);
  rounded_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    Float3& r = rounded_[v];
    r = rounded(mesh.position(v), grid);
    for (float& c : r) c += 0.0F;  // -0 as +0: they compare equal
    std::size_t slot = hash_slot(r, capacity);
    for (; slots_[slot] != kFree && rounded_[slots_[slot]] != r;
         slot = (slot + 1) & (capacity - 1)) {
    }
    if (slots_[slot] == kFree) slots_[slot] = v;
    unite(v, slots_[slot]);
  }
}

// same_[v]: the first vertex at exactly v's position.
void Float32Weld::find_same(const kernel::Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  const std::size_t capacity = table_capacity(n);
  exact_slots_.assign(capacity, kFree);
  same_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    const kernel::Vec3 p = mesh.position(v);
    std::size_t slot = hash_slot(std::array<double, 3>{p.x + 0.0, p.y + 0.0, p.z + 0.0}, capacity);
    for (; exact_slots_[slot] != kFree && !(mesh.position(exact_slots_[slot]) == p);
         slot = (slot + 1) & (capacity - 1)) {
    }
    if (exact_slots_[slot] == kFree) exact_slots_[slot] = v;
    same_[v] = exact_slots_[slot];
  }
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

// Every directed edge (vertices at one position taken as one) used once, and its reverse once
// (kernel::EdgeUses::unpaired() empty). Most meshes asked here are open (a building's alike
// terminals as one part): a sum over the directed edges of f(a, b) - f(b, a), with f mixing the
// bits of the end points' positions, is 0 when every edge has its reverse, and almost never
// otherwise, so one pass answers them. Only a mesh that passes is checked exactly, its edges as
// sorted keys.
bool Float32Weld::closed_and_oriented(const kernel::Mesh& mesh) {
  if (mesh.face_count() == 0 || edge_sum(mesh) != 0) return false;
  find_same(mesh);
  edges_.clear();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint64_t a = same_[loop[i]];
      const std::uint64_t b = same_[loop[(i + 1) % loop.size()]];
      if (a != b) edges_.push_back(a << 32U | b);
    }
  }
  std::sort(edges_.begin(), edges_.end());
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    if (i > 0 && edges_[i] == edges_[i - 1]) return false;  // used twice
    const std::uint64_t reverse = edges_[i] << 32U | edges_[i] >> 32U;
    if (!std::binary_search(edges_.begin(), edges_.end(), reverse)) return false;
  }
  return true;
}

namespace {

// Two mixes of a position's bits (-0 as +0): equal positions give equal values.
std::array<std::uint64_t, 2> position_mixes(kernel::Vec3 p) {
  std::uint64_t h = 0;
  for (const double c : {p.x + 0.0, p.y + 0.0, p.z + 0.0}) {
    h = (h ^ std::bit_cast<std::uint64_t>(c)) * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 31U;
  }
  return {h * 0xC2B2AE3D27D4EB4FULL, (h ^ (h >> 29U)) * 0x165667B19E3779F9ULL};
}

}  // namespace

// The sum over every directed edge (a, b) of f(a) g(b) - f(b) g(a), wrapping: each edge met with
// its reverse cancels, and an edge between two vertices at one position adds 0.
std::uint64_t Float32Weld::edge_sum(const kernel::Mesh& mesh) {
  mixes_.resize(mesh.vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    mixes_[v] = position_mixes(mesh.position(v));
  }
  std::uint64_t sum = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto& a = mixes_[loop[i]];
      const auto& b = mixes_[loop[i + 1 == loop.size() ? 0 : i + 1]];
      sum += a[0] * b[1] - b[0] * a[1];
    }
  }
  return sum;
}

// Each face contracted over the groups and triangulated at its representatives' positions.
void Float32Weld::triangulate_all(const kernel::Mesh& mesh) {
  triangles_.clear();
  offsets_.assign(1, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    keys_.clear();
    positions_.clear();
    for (std::uint32_t v : mesh.face(f)) {
      keys_.push_back(parent_[v]);
      positions_.push_back(mesh.position(parent_[v]));
    }
    corner_triangles_.clear();
    triangulator_.triangulate_contracted(keys_, positions_, kernel::face_normal(mesh, f),
                                         corner_triangles_);
    for (const CornerTriangle& t : corner_triangles_) {
      triangles_.push_back({keys_[t[0]], keys_[t[1]], keys_[t[2]]});
    }
    offsets_.push_back(triangles_.size());
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
