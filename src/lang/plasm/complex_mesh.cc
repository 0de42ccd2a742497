#include "lang/plasm/complex_mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "kernel/convex_hull.h"

namespace insula::lang::plasm {
namespace {

using kernel::Vec2;
using kernel::Vec3;

// Mesh vertices by position, rounded to a nanometre grid: coordinates that differ by rounding
// only (cos 2 pi against cos 0 on a closed MAP seam) become one vertex.
class Welder {
 public:
  explicit Welder(kernel::Mesh& mesh) : mesh_(mesh) {}

  std::uint32_t vertex(Vec3 p) {
    const Key key{snap(p.x), snap(p.y), snap(p.z)};
    const auto [it, added] = index_.emplace(key, 0U);
    if (added) it->second = mesh_.add_vertex(p);
    return it->second;
  }

 private:
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL;
      h ^= static_cast<std::uint64_t>(k.y) + 0x632BE59BD9B4E019ULL + (h << 6) + (h >> 2);
      h ^= static_cast<std::uint64_t>(k.z) + 0x8CB92BA72F3D8DD7ULL + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  static std::int64_t snap(double x) {
    return std::abs(x) < 1e9 ? std::llround(x * 1e9) : static_cast<std::int64_t>(x * 1e3);
  }

  kernel::Mesh& mesh_;
  std::unordered_map<Key, std::uint32_t, Hash> index_;
};

// Faces of solid cells, waiting for their twins: a face met again with the opposite side lies
// between two cells and is dropped. Loops are kept rotated to start at their least vertex, so a
// twin is the same first vertex followed by the others in reverse; open loops are found by hash.
class Boundary {
 public:
  void add(std::vector<std::uint32_t> loop) {
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    // The last open twin goes (the earlier open copies of it stay, in first-seen order).
    auto twin = open_.end();
    const auto [first, last] = open_.equal_range(hash(loop, true));
    for (auto it = first; it != last; ++it)
      if (is_twin(loops_[it->second], loop) && (twin == open_.end() || it->second > twin->second))
        twin = it;
    if (twin != open_.end()) {
      alive_[twin->second] = false;
      open_.erase(twin);
      return;
    }
    open_.emplace(hash(loop, false), static_cast<std::uint32_t>(loops_.size()));
    loops_.push_back(std::move(loop));
    alive_.push_back(true);
  }

  void emit(kernel::Mesh& mesh, kernel::FaceTag tag) {
    for (std::size_t i = 0; i < loops_.size(); ++i)
      if (alive_[i]) mesh.add_face(loops_[i], tag);
  }

 private:
  // The hash of the loop, or of its reverse (also starting at the least vertex).
  static std::uint64_t hash(const std::vector<std::uint32_t>& loop, bool reverse) {
    std::uint64_t h = 0xCBF29CE484222325ULL;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t v = reverse && i > 0 ? loop[n - i] : loop[i];
      h = (h ^ v) * 0x100000001B3ULL;
    }
    return h ^ (h >> 29);
  }
  static bool is_twin(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    const std::size_t n = a.size();
    if (b.size() != n || a[0] != b[0]) return false;
    for (std::size_t i = 1; i < n; ++i)
      if (a[i] != b[n - i]) return false;
    return true;
  }

  std::unordered_multimap<std::uint64_t, std::uint32_t> open_;  // hash -> index of an open loop
  std::vector<std::vector<std::uint32_t>> loops_;  // first-seen order keeps the output stable
  std::vector<bool> alive_;
};

Vec3 newell(const std::vector<Vec3>& loop) {
  Vec3 n{};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = loop[i];
    const Vec3 b = loop[(i + 1) % loop.size()];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

// A planar cell as one convex face: its points projected into their plane, hulled, and turned
// to face along `preferred` (the cell's own winding, or +z for cells of the plane).
bool add_planar(const std::vector<Vec3>& points, Vec3 preferred, Welder& welder, kernel::Mesh& mesh,
                kernel::FaceTag tag) {
  const Vec3 origin = points.front();
  Vec3 far = origin;
  for (const Vec3& p : points)
    if (length(p - origin) > length(far - origin)) far = p;
  Vec3 normal{};
  for (const Vec3& p : points) {
    const Vec3 n = cross(far - origin, p - origin);
    if (length(n) > length(normal)) normal = n;
  }
  const double scale = length(far - origin);
  if (scale == 0 || length(normal) <= 1e-12 * scale * scale) return false;
  if (dot(normal, preferred) < 0) normal = -normal;
  const Vec3 u = normalized(far - origin);
  const Vec3 v = normalized(cross(normalized(normal), u));
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) flat.push_back({dot(p - origin, u), dot(p - origin, v)});
  const kernel::Hull2Result hull = kernel::convex_hull_2d(flat);
  if (!hull.ok()) return false;
  std::vector<std::uint32_t> loop;
  for (const Vec2& q : hull.ring) loop.push_back(welder.vertex(origin + u * q.x + v * q.y));
  loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
  while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  if (loop.size() < 3) return false;
  mesh.add_face(loop, tag);
  return true;
}

// The outward faces of a solid convex cell as loops of indices into `points`; false with the
// hull's status when the points bound no solid. A tetrahedron (MAP's cells) needs no hull: its
// faces follow from the sign of its volume, unless it is nearly flat.
bool solid_loops(const std::vector<Vec3>& points, std::vector<std::vector<std::uint32_t>>& loops,
                 kernel::HullStatus& status) {
  loops.clear();
  if (points.size() == 4) {
    const Vec3& p = points[0];
    const double volume = dot(cross(points[1] - p, points[2] - p), points[3] - p);
    double longest = 0;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        longest = std::max(longest, length(points[j] - points[i]));
    if (std::abs(volume) > 1e-9 * longest * longest * longest) {
      loops = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
      if (volume < 0)
        for (std::vector<std::uint32_t>& loop : loops) std::reverse(loop.begin(), loop.end());
      return true;
    }
  }
  const kernel::Hull3Result hull = kernel::convex_hull_3d(points);
  status = hull.status;
  if (!hull.ok()) return false;
  // The hull keeps the input coordinates: its vertices are found among the points.
  std::vector<std::uint32_t> local(hull.mesh.vertex_count(), 0);
  for (std::uint32_t v = 0; v < hull.mesh.vertex_count(); ++v) {
    const Vec3 q = hull.mesh.position(v);
    const auto it = std::find_if(points.begin(), points.end(), [&](const Vec3& p) {
      return p.x == q.x && p.y == q.y && p.z == q.z;
    });
    if (it == points.end()) {
      status = kernel::HullStatus::kNumericalFailure;
      return false;
    }
    local[v] = static_cast<std::uint32_t>(it - points.begin());
  }
  for (std::size_t f = 0; f < hull.mesh.face_count(); ++f) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v : hull.mesh.face(f)) loop.push_back(local[v]);
    loops.push_back(std::move(loop));
  }
  return true;
}

}  // namespace

kernel::Mesh complex_mesh(const FlatComplex& flat, std::span<const std::uint32_t> cells,
                          kernel::FaceTag tag, MeshStats& stats, HullCache* cache) {
  kernel::Mesh mesh;
  Welder welder(mesh);
  Boundary boundary;
  const std::size_t count = cells.empty() ? flat.cells.size() : cells.size();
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> fresh;
  if (cache != nullptr && cache->entries.size() < flat.origins) cache->entries.resize(flat.origins);
  // Without a cache, points are remembered only when all cells are asked for (not one at a time).
  std::vector<std::uint32_t> own;
  std::vector<std::uint32_t>* vertex =
      cache != nullptr ? &cache->vertex : (cells.empty() ? &own : nullptr);
  if (vertex != nullptr) vertex->resize(flat.point_count(), HullCache::kNone);
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t index = cells.empty() ? static_cast<std::uint32_t>(k) : cells[k];
    const Cell& cell = flat.cells[index];
    if (flat.dim > 3 || cell.size() < 3) {
      ++stats.skipped_cells;
      continue;
    }
    points.clear();
    for (std::uint32_t v : cell) {
      const double* p = flat.point(v);
      points.push_back({p[0], flat.dim > 1 ? p[1] : 0.0, flat.dim > 2 ? p[2] : 0.0});
    }
    if (flat.dim == 3 && cell.size() >= 4) {
      const std::uint32_t origin =
          cache == nullptr || flat.origin.empty() ? FlatComplex::kNoOrigin : flat.origin[index];
      HullCache::Entry* entry = origin == FlatComplex::kNoOrigin
                                    ? nullptr
                                    : &cache->entries[origin & ~FlatComplex::kMirrored];
      const bool mirrored = (origin & FlatComplex::kMirrored) != 0;
      kernel::HullStatus status = kernel::HullStatus::kOk;
      const std::vector<std::vector<std::uint32_t>>* loops = nullptr;
      if (entry != nullptr && entry->known) {
        loops = &entry->loops;
      } else if (solid_loops(points, fresh, status)) {
        loops = &fresh;
        if (entry != nullptr) *entry = {true, mirrored, fresh};
      }
      if (loops != nullptr) {
        ++stats.solid_cells;
        const bool reverse = entry != nullptr && entry->mirrored != mirrored;
        for (const std::vector<std::uint32_t>& face : *loops) {
          std::vector<std::uint32_t> loop;
          loop.reserve(face.size());
          for (std::uint32_t v : face) {
            if (vertex == nullptr) {
              loop.push_back(welder.vertex(points[v]));
              continue;
            }
            std::uint32_t& known = (*vertex)[cell[v]];
            if (known == HullCache::kNone) known = welder.vertex(points[v]);
            loop.push_back(known);
          }
          if (reverse) std::reverse(loop.begin(), loop.end());
          loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
          while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
          if (loop.size() >= 3) boundary.add(std::move(loop));
        }
        continue;
      }
      if (status != kernel::HullStatus::kCoplanar) {
        ++stats.skipped_cells;
        continue;
      }
    }
    // A surface faces the way its cell's vertices turn; a mirror above the cell turns them the
    // other way, so the side is taken back (the outside of a closed MAP surface stays outside).
    Vec3 preferred = flat.dim < 3 ? Vec3{0, 0, 1} : newell(points);
    if (!flat.origin.empty() && flat.origin[index] != FlatComplex::kNoOrigin &&
        (flat.origin[index] & FlatComplex::kMirrored) != 0)
      preferred = -preferred;
    if (add_planar(points, length(preferred) > 0 ? preferred : Vec3{0, 0, 1}, welder, mesh, tag)) {
      ++stats.surface_cells;
    } else {
      ++stats.skipped_cells;
    }
  }
  boundary.emit(mesh, tag);
  return mesh;
}

}  // namespace insula::lang::plasm
