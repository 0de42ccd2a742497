#include "kernel/mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_map>

#include "base/union_find.h"

namespace insula::kernel {

void Bounds3::add(Vec3 p) {
  min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
  max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

std::uint32_t Mesh::add_polygon(std::span<const Vec3> loop, FaceTag tag) {
  const auto first = static_cast<std::uint32_t>(positions_.size());
  positions_.insert(positions_.end(), loop.begin(), loop.end());
  for (std::uint32_t i = 0; i < loop.size(); ++i) indices_.push_back(first + i);
  offsets_.push_back(static_cast<std::uint32_t>(indices_.size()));
  tags_.push_back(tag);
  return static_cast<std::uint32_t>(tags_.size() - 1);
}

void Mesh::append(const Mesh& other) {
  const auto shift = static_cast<std::uint32_t>(positions_.size());
  const auto index_shift = static_cast<std::uint32_t>(indices_.size());
  positions_.insert(positions_.end(), other.positions_.begin(), other.positions_.end());
  for (std::uint32_t index : other.indices_) indices_.push_back(index + shift);
  for (std::size_t f = 1; f < other.offsets_.size(); ++f) {
    offsets_.push_back(other.offsets_[f] + index_shift);
  }
  tags_.insert(tags_.end(), other.tags_.begin(), other.tags_.end());
}

void Mesh::reserve(std::size_t vertices, std::size_t faces, std::size_t indices) {
  positions_.reserve(vertices);
  tags_.reserve(faces);
  offsets_.reserve(faces + 1);
  indices_.reserve(indices);
}

void Mesh::clear() {
  positions_.clear();
  indices_.clear();
  offsets_.assign(1, 0);
  tags_.clear();
}

void Mesh::flip() {
  for (std::size_t f = 0; f < tags_.size(); ++f) {
    std::reverse(indices_.begin() + offsets_[f], indices_.begin() + offsets_[f + 1]);
  }
}

Bounds3 Mesh::bounds() const {
  Bounds3 b;
  for (const Vec3& p : positions_) b.add(p);
  return b;
}

std::size_t Mesh::triangle_count() const {
  std::size_t count = 0;
  for (std::size_t f = 0; f < tags_.size(); ++f) count += offsets_[f + 1] - offsets_[f] - 2;
  return count;
}

namespace {

// Newell's method: twice the vector area of a planar (or nearly planar) loop.
Vec3 newell(const Mesh& mesh, std::size_t face) {
  const auto loop = mesh.face(face);
  // Edges (i, i + 1), the last one back to corner 0; no modulo, which cost more than the sum.
  // Three scalar sums rather than a Vec3 (the same additions): GCC kept the Vec3 temporaries on
  // the stack and stalled reloading them.
  const std::vector<Vec3>& positions = mesh.positions();
  double x = 0;
  double y = 0;
  double z = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = positions[loop[i]];
    const Vec3& b = positions[loop[i + 1 < loop.size() ? i + 1 : 0]];
    x += (a.y - b.y) * (a.z + b.z);
    y += (a.z - b.z) * (a.x + b.x);
    z += (a.x - b.x) * (a.y + b.y);
  }
  return {x, y, z};
}

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) {
  return (static_cast<std::uint64_t>(from) << 32) | to;
}

}  // namespace

Vec3 face_normal(const Mesh& mesh, std::size_t face) {
  return normalized(newell(mesh, face));
}

double face_area(const Mesh& mesh, std::size_t face) {
  return length(newell(mesh, face)) / 2;
}

double surface_area(const Mesh& mesh) {
  double total = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) total += face_area(mesh, f);
  return total;
}

double volume(const Mesh& mesh) {
  // Divergence theorem: V = 1/3 * sum over faces of (point on face . vector area).
  double total = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    total += dot(mesh.position(loop[0]), newell(mesh, f) / 2);
  }
  return total / 3;
}

Mesh weld(const Mesh& mesh, double tolerance) {
  // Hash on a grid of cell `tolerance`; look up the 27 neighbouring cells so near points merge.
  struct CellHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
      // Unsigned arithmetic: cell indices of far-away points would overflow a signed product.
      const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
      return static_cast<std::size_t>(u(c[0]) * 73856093U ^ u(c[1]) * 19349663U ^
                                      u(c[2]) * 83492791U);
    }
  };
  const double cell = std::max(tolerance, 1e-12);
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>, CellHash> grid;
  Mesh out;
  std::vector<std::uint32_t> remap(mesh.vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = mesh.position(v);
    const std::array<std::int64_t, 3> c = {static_cast<std::int64_t>(std::floor(p.x / cell)),
                                           static_cast<std::int64_t>(std::floor(p.y / cell)),
                                           static_cast<std::int64_t>(std::floor(p.z / cell))};
    std::int64_t found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx) {
      for (int dy = -1; dy <= 1 && found < 0; ++dy) {
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (std::uint32_t candidate : it->second) {
            if (length(out.position(candidate) - p) <= tolerance) {
              found = candidate;
              break;
            }
          }
        }
      }
    }
    if (found < 0) {
      found = out.add_vertex(p);
      grid[c].push_back(static_cast<std::uint32_t>(found));
    }
    remap[v] = static_cast<std::uint32_t>(found);
  }
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t v : mesh.face(f)) {
      const std::uint32_t w = remap[v];
      if (loop.empty() || loop.back() != w) loop.push_back(w);
    }
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    if (loop.size() >= 3) out.add_face(loop, mesh.tag(f));
  }
  return out;
}

MeshCheck check(const Mesh& mesh) {
  MeshCheck result;
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.face_count() * 8);
  std::vector<std::uint8_t> used(mesh.vertex_count(), 0);
  base::UnionFind components(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i];
      const std::uint32_t b = loop[(i + 1) % loop.size()];
      ++directed[edge_key(a, b)];
      used[a] = 1;
      components.unite(a, b);
    }
  }
  bool oriented = true;
  std::size_t undirected = 0;
  for (const auto& [key, count] : directed) {
    const auto from = static_cast<std::uint32_t>(key >> 32);
    const auto to = static_cast<std::uint32_t>(key & 0xffffffffU);
    if (count > 1) oriented = false;
    auto twin = directed.find(edge_key(to, from));
    const int twin_count = twin == directed.end() ? 0 : twin->second;
    if (twin_count == 0) ++result.boundary_edges;
    if (count > 1 || twin_count > 1) ++result.non_manifold_edges;
    if (from < to || twin_count == 0) ++undirected;
  }
  std::size_t vertices = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!used[v]) continue;
    ++vertices;
    if (components.find(v) == v) ++result.components;
  }
  result.oriented = oriented;
  result.closed = result.boundary_edges == 0 && result.non_manifold_edges == 0 && oriented;
  result.euler_characteristic = static_cast<int>(vertices) - static_cast<int>(undirected) +
                                static_cast<int>(mesh.face_count());
  return result;
}

bool is_watertight(const Mesh& mesh, double tolerance) {
  const Mesh welded = weld(mesh, tolerance);
  const MeshCheck c = check(welded);
  return c.closed && volume(welded) > 0;
}

Mesh canonical_order(const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t v = 0; v < n; ++v) order[v] = v;
  const auto key = [&](std::uint32_t v) {
    const Vec3 p = mesh.position(v);
    return std::make_tuple(p.x, p.y, p.z);
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::uint32_t> rank(n);
  Mesh out;
  out.reserve(n, mesh.face_count(), 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    rank[order[i]] = i;
    out.add_vertex(mesh.position(order[i]));
  }
  std::vector<std::vector<std::uint32_t>> loops(mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (std::uint32_t v : mesh.face(f)) loops[f].push_back(rank[v]);
    std::rotate(loops[f].begin(), std::min_element(loops[f].begin(), loops[f].end()),
                loops[f].end());
  }
  std::vector<std::size_t> faces(mesh.face_count());
  for (std::size_t f = 0; f < faces.size(); ++f) faces[f] = f;
  const auto tag_key = [&](std::size_t f) {
    const FaceTag& t = mesh.tag(f);
    return std::make_tuple(static_cast<int>(t.semantic), t.material, t.face_id);
  };
  std::stable_sort(faces.begin(), faces.end(), [&](std::size_t a, std::size_t b) {
    if (loops[a] != loops[b]) return loops[a] < loops[b];
    return tag_key(a) < tag_key(b);
  });
  for (std::size_t f : faces) out.add_face(loops[f], mesh.tag(f));
  return out;
}

bool same_content(const Mesh& a, const Mesh& b) {
  if (a.vertex_count() != b.vertex_count() || a.face_count() != b.face_count()) return false;
  for (std::size_t v = 0; v < a.vertex_count(); ++v) {
    if (!(a.position(v) == b.position(v))) return false;
  }
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

std::uint64_t content_hash(const Mesh& mesh) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&h](std::uint64_t v) {
    for (int b = 0; b < 8; ++b) {
      h ^= (v >> (8 * b)) & 0xFFU;
      h *= 1099511628211ULL;
    }
  };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = mesh.position(v);
    for (double c : {p.x, p.y, p.z}) mix(std::bit_cast<std::uint64_t>(c));
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    mix(mesh.face(f).size());
    for (std::uint32_t corner : mesh.face(f)) mix(corner);
    const FaceTag& tag = mesh.tag(f);
    mix(static_cast<std::uint64_t>(tag.semantic) | std::uint64_t{tag.material} << 8 |
        std::uint64_t{tag.face_id} << 32);
  }
  return h;
}

}  // namespace insula::kernel
