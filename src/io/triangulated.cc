#include "io/triangulated.h"

#include <cmath>
#include <set>
#include <utility>

#include "kernel/polygon.h"
#include "kernel/triangulate.h"

namespace insula::io {
namespace {

using kernel::Vec2;
using kernel::Vec3;

// Projects onto the coordinate plane most perpendicular to `normal`, choosing the axis order that
// keeps the loop counter-clockwise when seen against the normal (x = y × z, y = z × x, z = x × y).
Vec2 project(Vec3 p, Vec3 normal) {
  const double ax = std::abs(normal.x);
  const double ay = std::abs(normal.y);
  const double az = std::abs(normal.z);
  if (az >= ax && az >= ay) return normal.z > 0 ? Vec2{p.x, p.y} : Vec2{p.y, p.x};
  if (ax >= ay) return normal.x > 0 ? Vec2{p.y, p.z} : Vec2{p.z, p.y};
  return normal.y > 0 ? Vec2{p.z, p.x} : Vec2{p.x, p.z};
}

bool is_convex(const kernel::Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[(i + 1) % n];
    const Vec2 c = ring[(i + 2) % n];
    if (kernel::cross(b - a, c - b) < 0) return false;
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
  std::vector<CornerTriangle> mapped;
  mapped.reserve(result.triangles.size());
  for (const auto& triangle : result.triangles) {
    CornerTriangle t{triangle[0], triangle[1], triangle[2]};
    if (t[0] >= ring.size() || t[1] >= ring.size() || t[2] >= ring.size()) return false;
    if (kernel::cross(ring[t[1]] - ring[t[0]], ring[t[2]] - ring[t[0]]) < 0) std::swap(t[1], t[2]);
    mapped.push_back(t);
  }
  triangles.insert(triangles.end(), mapped.begin(), mapped.end());
  return !mapped.empty();
}

}  // namespace

bool triangulate_face(const kernel::Mesh& mesh, std::size_t face,
                      std::vector<CornerTriangle>& triangles) {
  const auto loop = mesh.face(face);
  const Vec3 normal = kernel::face_normal(mesh, face);
  if (loop.size() < 3 || kernel::length(normal) == 0) return false;
  if (loop.size() == 3) {
    triangles.push_back({0, 1, 2});
    return true;
  }
  kernel::Polygon polygon;
  polygon.outer.reserve(loop.size());
  for (std::uint32_t vertex : loop) polygon.outer.push_back(project(mesh.position(vertex), normal));
  kernel::Triangulation result;
  if (kernel::triangulate(polygon, result) && map_back(polygon.outer, result, triangles)) {
    return true;
  }
  if (!is_convex(polygon.outer)) return false;
  append_fan(loop.size(), triangles);
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

MaterialTable::MaterialTable(const shape::Scene& scene)
    : scene_material_count_(scene.materials.size()) {
  std::set<std::uint32_t> keys;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (std::size_t f = 0; f < part.mesh.face_count(); ++f) keys.insert(key(part.mesh.tag(f)));
    }
  }
  std::set<std::string> used;
  for (std::uint32_t k : keys) {
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
    index_by_key_.emplace(k, static_cast<std::uint32_t>(materials_.size()));
    materials_.push_back(std::move(material));
  }
}

// Scene materials keep their id; faces showing a class default get scene size + class index.
std::uint32_t MaterialTable::key(const kernel::FaceTag& tag) const {
  if (tag.material != 0 && tag.material < scene_material_count_) return tag.material;
  return static_cast<std::uint32_t>(scene_material_count_) +
         static_cast<std::uint32_t>(tag.semantic);
}

std::uint32_t MaterialTable::index(const kernel::FaceTag& tag) const {
  const auto found = index_by_key_.find(key(tag));
  return found == index_by_key_.end() ? 0 : found->second;
}

}  // namespace insula::io
