#include "kernel/mesh_unify.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <unordered_map>

#include "base/union_find.h"

namespace insula::kernel {
namespace {

// Below this, weld's grid cells (tolerance-sized) would overflow 64-bit cell indices for
// coordinates of a few thousand kilometres.
constexpr double kMinTolerance = 1e-9;

std::uint64_t undirected_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

bool same_tag(const FaceTag& a, const FaceTag& b) {
  return a.semantic == b.semantic && a.material == b.material && a.face_id == b.face_id;
}

// Step 1's thinness test: the face's area is at most that of a strip `tolerance` wide along its
// longest edge.
bool degenerate(const Mesh& mesh, std::size_t face, double tolerance) {
  const auto loop = mesh.face(face);
  double longest = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    longest = std::max(longest,
                       length(mesh.position(loop[(i + 1) % loop.size()]) - mesh.position(loop[i])));
  }
  return face_area(mesh, face) <= tolerance * longest / 2;
}

// The loop rotated to start at its least index (a key equal for every rotation of one cycle).
std::vector<std::uint32_t> rotated(std::vector<std::uint32_t> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

// Step 2: the faces to keep, in order.
std::vector<std::uint32_t> distinct_faces(const Mesh& mesh, double tolerance) {
  struct Cycle {
    std::uint32_t first = 0;
    std::array<bool, 2> directions{false, false};  // seen as the key, seen reversed
  };
  std::map<std::vector<std::uint32_t>, Cycle> cycles;
  std::vector<std::pair<std::uint32_t, const Cycle*>> faces;
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    if (degenerate(mesh, f, tolerance)) continue;
    const auto loop = mesh.face(f);
    std::vector<std::uint32_t> forward = rotated({loop.begin(), loop.end()});
    std::vector<std::uint32_t> backward = rotated({loop.rbegin(), loop.rend()});
    const bool reversed = backward < forward;
    auto [it, added] = cycles.try_emplace(reversed ? std::move(backward) : std::move(forward));
    if (added) it->second.first = f;
    it->second.directions[reversed ? 1 : 0] = true;
    faces.emplace_back(f, &it->second);
  }
  std::vector<std::uint32_t> kept;
  for (const auto& [f, cycle] : faces) {
    if (cycle->first == f && !(cycle->directions[0] && cycle->directions[1])) kept.push_back(f);
  }
  return kept;
}

// A growing joined face: its boundary as a map from each vertex to the next (one simple loop, so
// every vertex has one successor).
class Piece {
 public:
  explicit Piece(std::span<const std::uint32_t> loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) next_[loop[i]] = loop[(i + 1) % loop.size()];
  }

  // Adds face `loop` when the union stays one simple loop: the edges it shares with the boundary
  // (run the other way) form one chain, and its other vertices are not on the boundary. Then the
  // chain's inner vertices leave the boundary and the face's other edges replace the chain.
  bool join(std::span<const std::uint32_t> loop) {
    const std::size_t n = loop.size();
    std::vector<bool> shared(n);
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = next_.find(loop[(i + 1) % n]);
      shared[i] = it != next_.end() && it->second == loop[i];
      count += shared[i] ? 1 : 0;
    }
    if (count == 0 || count == n) return false;
    std::size_t starts = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (shared[i] && !shared[(i + n - 1) % n]) {
        ++starts;
        start = i;
      }
    }
    if (starts != 1) return false;
    std::size_t end = start;
    while (shared[end]) end = (end + 1) % n;
    for (std::size_t i = (end + 1) % n; i != start; i = (i + 1) % n) {
      if (next_.count(loop[i]) != 0) return false;
    }
    for (std::size_t i = start; i != end; i = (i + 1) % n) next_.erase(loop[(i + 1) % n]);
    for (std::size_t i = end; i != start; i = (i + 1) % n) next_[loop[i]] = loop[(i + 1) % n];
    return true;
  }

  // The boundary loop from its least vertex.
  std::vector<std::uint32_t> loop() const {
    std::uint32_t first = next_.begin()->first;
    for (const auto& [v, w] : next_) first = std::min(first, v);
    std::vector<std::uint32_t> out{first};
    for (std::uint32_t v = next_.at(first); v != first; v = next_.at(v)) out.push_back(v);
    return out;
  }

 private:
  std::unordered_map<std::uint32_t, std::uint32_t> next_;
};

// Step 3 over the kept faces: each unjoined face in order seeds a piece, which grows breadth first
// over shared edges. A face refused once (it would have closed a hole) is tried again whenever a
// neighbour joins, since the hole may have been filled meanwhile.
Mesh join_coplanar(const Mesh& mesh, const std::vector<std::uint32_t>& faces, double tolerance) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> by_edge;
  for (std::uint32_t f : faces) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      by_edge[undirected_key(loop[i], loop[(i + 1) % loop.size()])].push_back(f);
    }
  }
  std::vector<bool> joined(mesh.face_count(), false);
  Mesh out;
  out.positions() = mesh.positions();
  std::deque<std::uint32_t> queue;
  const auto push_neighbours = [&](std::uint32_t f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      for (std::uint32_t g : by_edge[undirected_key(loop[i], loop[(i + 1) % loop.size()])]) {
        if (!joined[g]) queue.push_back(g);
      }
    }
  };
  for (std::uint32_t seed : faces) {
    if (joined[seed]) continue;
    joined[seed] = true;
    const Vec3 normal = face_normal(mesh, seed);
    const double offset = dot(normal, mesh.position(mesh.face(seed)[0]));
    const auto fits = [&](std::uint32_t g) {
      if (!same_tag(mesh.tag(g), mesh.tag(seed)) || dot(face_normal(mesh, g), normal) <= 0) {
        return false;
      }
      return std::all_of(mesh.face(g).begin(), mesh.face(g).end(), [&](std::uint32_t v) {
        return std::abs(dot(normal, mesh.position(v)) - offset) <= tolerance;
      });
    };
    Piece piece(mesh.face(seed));
    std::size_t members = 1;
    queue.clear();
    push_neighbours(seed);
    while (!queue.empty()) {
      const std::uint32_t g = queue.front();
      queue.pop_front();
      if (joined[g] || !fits(g) || !piece.join(mesh.face(g))) continue;
      joined[g] = true;
      ++members;
      push_neighbours(g);
    }
    if (members == 1) {
      out.add_face(mesh.face(seed), mesh.tag(seed));
    } else {
      out.add_face(piece.loop(), mesh.tag(seed));
    }
  }
  return out;
}

// Step 4.
Mesh drop_straight_vertices(const Mesh& mesh, double tolerance) {
  constexpr std::uint32_t kNone = 0xffffffffU;
  struct Neighbours {
    std::array<std::uint32_t, 2> v{kNone, kNone};
    bool more = false;
    void add(std::uint32_t w) {
      if (v[0] == w || v[1] == w) return;
      if (v[0] == kNone) {
        v[0] = w;
      } else if (v[1] == kNone) {
        v[1] = w;
      } else {
        more = true;
      }
    }
  };
  std::vector<Neighbours> neighbours(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      neighbours[loop[i]].add(loop[(i + loop.size() - 1) % loop.size()]);
      neighbours[loop[i]].add(loop[(i + 1) % loop.size()]);
    }
  }
  std::vector<bool> straight(mesh.vertex_count(), false);
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const Neighbours& n = neighbours[v];
    if (n.more || n.v[1] == kNone) continue;
    const Vec3 a = mesh.position(n.v[0]);
    const Vec3 b = mesh.position(n.v[1]);
    const Vec3 p = mesh.position(v);
    const double run = length(b - a);
    straight[v] =
        run > 0 && dot(p - a, b - p) > 0 && length(cross(b - a, p - a)) / run <= tolerance;
  }
  Mesh out;
  out.positions() = mesh.positions();
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t v : mesh.face(f)) {
      if (!straight[v]) loop.push_back(v);
    }
    if (loop.size() >= 3) out.add_face(loop, mesh.tag(f));
  }
  return out;
}

// Step 5.
Mesh compact(const Mesh& mesh) {
  constexpr std::uint32_t kUnused = 0xffffffffU;
  std::vector<std::uint32_t> index(mesh.vertex_count(), kUnused);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (std::uint32_t v : mesh.face(f)) index[v] = 0;
  }
  Mesh out;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    if (index[v] != kUnused) index[v] = out.add_vertex(mesh.position(v));
  }
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t v : mesh.face(f)) loop.push_back(index[v]);
    out.add_face(loop, mesh.tag(f));
  }
  return out;
}

}  // namespace

Mesh unify(const Mesh& mesh, double tolerance) {
  tolerance = std::max(tolerance, kMinTolerance);
  const Mesh welded = weld(mesh, tolerance);
  const Mesh joined = join_coplanar(welded, distinct_faces(welded, tolerance), tolerance);
  return compact(drop_straight_vertices(joined, tolerance));
}

std::vector<std::vector<std::size_t>> group_by_shared_edges(std::span<const Mesh> meshes,
                                                            double tolerance) {
  // One mesh of all faces, each tagged with its mesh's index, welded at once: shared edges are
  // then shared vertex pairs.
  Mesh all;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::size_t first = all.face_count();
    all.append(meshes[m]);
    for (std::size_t f = first; f < all.face_count(); ++f) {
      all.tag(f).face_id = static_cast<std::uint32_t>(m);
    }
  }
  const Mesh welded = weld(all, std::max(tolerance, kMinTolerance));
  base::UnionFind sets(meshes.size());
  std::unordered_map<std::uint64_t, std::uint32_t> owner;
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    const std::uint32_t m = welded.tag(f).face_id;
    const auto loop = welded.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto [it, added] =
          owner.emplace(undirected_key(loop[i], loop[(i + 1) % loop.size()]), m);
      if (!added) sets.unite(m, it->second);
    }
  }
  std::vector<std::vector<std::size_t>> groups;
  std::unordered_map<std::uint32_t, std::size_t> group_of;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const auto [it, added] =
        group_of.emplace(sets.find(static_cast<std::uint32_t>(m)), groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(m);
  }
  return groups;
}

}  // namespace insula::kernel
