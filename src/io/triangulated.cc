#include "io/triangulated.h"

#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

#include "kernel/contract_loop.h"
#include "kernel/planar.h"
#include "kernel/polygon.h"
#include "kernel/triangulate.h"

namespace insula::io {
namespace {

using kernel::Vec2;
using kernel::Vec3;

// The coordinate plane most perpendicular to a normal, with the axis order that keeps the loop
// counter-clockwise when seen against the normal (x = y × z, y = z × x, z = x × y).
enum class Plane { kXY, kYX, kYZ, kZY, kZX, kXZ };

Plane plane_of(Vec3 normal) {
  const double ax = std::abs(normal.x);
  const double ay = std::abs(normal.y);
  const double az = std::abs(normal.z);
  if (az >= ax && az >= ay) return normal.z > 0 ? Plane::kXY : Plane::kYX;
  if (ax >= ay) return normal.x > 0 ? Plane::kYZ : Plane::kZY;
  return normal.y > 0 ? Plane::kZX : Plane::kXZ;
}

Vec2 project(Vec3 p, Plane plane) {
  switch (plane) {
    case Plane::kXY:
      return {p.x, p.y};
    case Plane::kYX:
      return {p.y, p.x};
    case Plane::kYZ:
      return {p.y, p.z};
    case Plane::kZY:
      return {p.z, p.y};
    case Plane::kZX:
      return {p.z, p.x};
    case Plane::kXZ:
      break;
  }
  return {p.x, p.z};
}

// Sine of the smallest turn a strictly convex corner must make. Corners closer to straight (a
// vertex splitting an edge, up to rounding) go to kernel::triangulate, which may clip around them
// in another order, so both paths agree whatever the rounding of the turn test.
constexpr double kMinTurn = 1e-9;

// Whether the corner at b (from a, on to c) turns left by more than kMinTurn: cross(u, v) >
// kMinTurn |u| |v|, squared (no square roots, hypot being the costliest part here).
bool turns_left(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = b - a;
  const Vec2 v = c - b;
  const double turn = kernel::cross(u, v);
  return turn > 0 && turn * turn > kMinTurn * kMinTurn * kernel::dot(u, u) * kernel::dot(v, v);
}

// Every corner turns left by more than kMinTurn and the boundary winds once: the x component of
// the edge direction changes sign at most twice (a ring with only left turns that winds k times
// changes it 2k times, e.g. a pentagram). Coordinates are taken relative to the first corner, as
// the triangulator takes them relative to a corner of the bounds, to keep the tests well scaled.
bool is_strictly_convex(const kernel::Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  int sign_changes = 0;
  int last_sign = 0;
  // Corners i, j = i + 1 and k = i + 2 around the ring, stepped without a modulo (two integer
  // divisions a corner cost more than the turn test; n >= 3, so j and k start at 1 and 2).
  for (std::size_t i = 0, j = 1, k = 2; i < n; ++i, j = k, k = k + 1 == n ? 0 : k + 1) {
    const Vec2 a = ring[i] - ring[0];
    const Vec2 b = ring[j] - ring[0];
    const Vec2 c = ring[k] - ring[0];
    if (!turns_left(a, b, c)) return false;
    const double dx = b.x - a.x;
    const int sign = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
    if (sign != 0) {
      if (last_sign != 0 && sign != last_sign) ++sign_changes;
      last_sign = sign;
    }
  }
  return sign_changes <= 2;
}

// is_strictly_convex for a quad, the commonest face, on the stack: four left turns are enough (a
// ring's turns add up to whole turns, and four turns of less than a half-turn each to one).
bool is_strictly_convex_quad(const std::array<Vec2, 4>& quad) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (!turns_left(quad[i] - quad[0], quad[(i + 1) & 3U] - quad[0],
                    quad[(i + 2) & 3U] - quad[0])) {
      return false;
    }
  }
  return true;
}

void append_fan(std::size_t n, std::vector<CornerTriangle>& triangles) {
  for (std::uint32_t i = 1; i + 1 < n; ++i) triangles.push_back({0, i, i + 1});
}

// Triangle indices are the loop's corners (kernel::Triangulation keeps the input vertices in
// order); each triangle is re-checked counter-clockwise so the glTF winding matches the normal.
bool map_back(const kernel::Ring& ring, const kernel::Triangulation& result,
              std::vector<CornerTriangle>& triangles) {
  const std::size_t first = triangles.size();
  for (const auto& triangle : result.triangles) {
    CornerTriangle t{triangle[0], triangle[1], triangle[2]};
    if (t[0] >= ring.size() || t[1] >= ring.size() || t[2] >= ring.size()) {
      triangles.resize(first);
      return false;
    }
    if (kernel::cross(ring[t[1]] - ring[t[0]], ring[t[2]] - ring[t[0]]) < 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  return triangles.size() > first;
}

}  // namespace

// For a strictly convex ring every corner is an ear, so kernel::triangulate's clipper (start at
// corner 0, clip, continue two corners on) runs without a failed ear test: replaying that walk on
// a linked list gives its triangles at a fraction of the cost (no grid, no allocation per face),
// and the output does not depend on which path a face took.
bool FaceTriangulator::triangulate(const kernel::Mesh& mesh, std::size_t face, Vec3 normal,
                                   std::vector<CornerTriangle>& triangles) {
  const auto loop = mesh.face(face);
  return triangulate_corners(
      loop.size(), [&](std::size_t i) { return mesh.position(loop[i]); }, normal, triangles);
}

bool FaceTriangulator::triangulate(std::span<const Vec3> corners, Vec3 normal,
                                   std::vector<CornerTriangle>& triangles) {
  return triangulate_corners(
      corners.size(), [&](std::size_t i) { return corners[i]; }, normal, triangles);
}

namespace {

// Whether no two of a loop's keys are equal (a face has a handful of corners; a long loop is
// left to contract_loop).
bool distinct(std::span<const std::uint32_t> keys) {
  if (keys.size() < 3 || keys.size() > 16) return false;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (keys[i] == keys[j]) return false;
    }
  }
  return true;
}

}  // namespace

void FaceTriangulator::triangulate_contracted(std::span<const std::uint32_t> keys,
                                              std::span<const Vec3> positions, Vec3 normal,
                                              std::vector<CornerTriangle>& triangles) {
  if (distinct(keys)) {
    whole_.resize(keys.size());
    std::iota(whole_.begin(), whole_.end(), 0U);
    triangulate_piece(whole_, positions, normal, triangles);
    return;
  }
  for (const std::vector<std::uint32_t>& piece : kernel::contract_loop(keys)) {
    triangulate_piece(piece, positions, normal, triangles);
  }
}

// The triangles of one piece (`corners`: its corners' positions in the loop), as loop corners.
void FaceTriangulator::triangulate_piece(std::span<const std::uint32_t> corners,
                                         std::span<const Vec3> positions, Vec3 normal,
                                         std::vector<CornerTriangle>& triangles) {
  piece_.clear();
  for (std::uint32_t corner : corners) piece_.push_back(positions[corner]);
  piece_triangles_.clear();
  if (!triangulate(piece_, normal, piece_triangles_)) {
    for (std::uint32_t i = 1; i + 1 < corners.size(); ++i)
      piece_triangles_.push_back({0, i, i + 1});
  }
  for (const CornerTriangle& t : piece_triangles_) {
    triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
  }
}

// The face of `n` corners, corner i at position(i).
template <typename Position>
bool FaceTriangulator::triangulate_corners(std::size_t n, Position position, Vec3 normal,
                                           std::vector<CornerTriangle>& triangles) {
  // A zero normal: its squared length is 0 exactly when its length is (no square root).
  if (n < 3 || kernel::dot(normal, normal) == 0) return false;
  if (n == 3) {
    triangles.push_back({0, 1, 2});
    return true;
  }
  kernel::Ring& ring = polygon_.outer;
  const Plane plane = plane_of(normal);  // once a face, not once a corner
  if (n == 4) {
    std::array<Vec2, 4> quad;
    for (std::size_t i = 0; i < 4; ++i) quad[i] = project(position(i), plane);
    if (is_strictly_convex_quad(quad)) {
      triangles.push_back({3, 0, 1});  // triangulate_ring's walk for a convex quad
      triangles.push_back({1, 2, 3});
      return true;
    }
    ring.assign(quad.begin(), quad.end());
    return triangulate_ring(triangles);
  }
  ring.clear();
  for (std::size_t i = 0; i < n; ++i) ring.push_back(project(position(i), plane));
  return triangulate_ring(triangles);
}

bool FaceTriangulator::triangulate_ring(std::vector<CornerTriangle>& triangles) {
  const kernel::Ring& ring = polygon_.outer;
  const auto n = static_cast<std::uint32_t>(ring.size());
  if (is_strictly_convex(ring)) {
    if (n == 4) {
      triangles.push_back({3, 0, 1});  // the walk below, unrolled for the most common face
      triangles.push_back({1, 2, 3});
      return true;
    }
    next_.resize(n);
    prev_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      next_[i] = i + 1 == n ? 0 : i + 1;
      prev_[i] = i == 0 ? n - 1 : i - 1;
    }
    for (std::uint32_t ear = 0; prev_[ear] != next_[ear];) {
      const std::uint32_t a = prev_[ear];
      const std::uint32_t c = next_[ear];
      triangles.push_back({a, ear, c});
      next_[a] = c;
      prev_[c] = a;
      ear = next_[c];
    }
    return true;
  }
  if (kernel::triangulate(polygon_, result_) && map_back(ring, result_, triangles)) return true;
  if (!kernel::is_convex(ring)) return false;
  append_fan(n, triangles);
  return true;
}

std::string safe_name(std::string_view name, std::string_view fallback) {
  if (name.empty()) return std::string(fallback);
  std::string out(name);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) <= ' ' || c == '\x7f') c = '_';
  }
  return out;
}

MaterialTable::MaterialTable(const shape::Scene& scene, bool by_class)
    : by_class_(by_class),
      scene_material_count_(scene.materials.size()),
      index_by_key_(scene_material_count_ + kKeysPerClass, kNone) {
  std::vector<bool> used_keys(index_by_key_.size(), false);
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      // Instance parts keep their faces in the shared mesh (shape/part_mesh.h).
      const kernel::Mesh& mesh = part.instance_of ? *part.instance_of : part.mesh;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) used_keys[key(mesh.tag(f))] = true;
    }
  }
  std::set<std::string> used;
  for (std::uint32_t k = 0; k < used_keys.size(); ++k) {
    if (!used_keys[k]) continue;
    shape::Material material = k < scene_material_count_
                                   ? scene.materials[k]
                                   : shape::default_material(static_cast<kernel::SemanticClass>(
                                         k - scene_material_count_));
    const std::string base = safe_name(material.name, "material");
    material.name = base;
    for (int suffix = 2; used.contains(material.name); ++suffix) {
      material.name = base + "_" + std::to_string(suffix);
    }
    used.insert(material.name);
    index_by_key_[k] = static_cast<std::uint32_t>(materials_.size());
    materials_.push_back(std::move(material));
  }
}

// Scene materials keep their id; faces showing a class default get scene size + class index.
std::uint32_t MaterialTable::key(const kernel::FaceTag& tag) const {
  if (!by_class_ && tag.material != 0 && tag.material < scene_material_count_) return tag.material;
  return static_cast<std::uint32_t>(scene_material_count_) +
         static_cast<std::uint32_t>(tag.semantic);
}

std::uint32_t MaterialTable::index(const kernel::FaceTag& tag) const {
  const std::uint32_t found = index_by_key_[key(tag)];
  return found == kNone ? 0 : found;
}

}  // namespace insula::io
