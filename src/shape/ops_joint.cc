// Joint extrusion of adjacent faces (seed 001 §3.4.3 "Extruding" and Fig. 6): when a set of 2D
// components is extruded together, "each edge shared by two adjacent 2D components is extruded in
// a single direction computed from these 2D components, thus generating two new 3D components
// which share a face". Every vertex moves by the offset o that keeps the extrusion distance d from
// the plane of each face of the set meeting there (dot(o, n_f) = d for each such face f): one
// face gives d n, two faces their mitre, three a corner. Walls, floors and ceilings grown this way
// meet without overlapping or leaving gaps (§4.2).
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "kernel/extrude.h"
#include "shape/component_ops.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec2;
using kernel::Vec3;

namespace {

constexpr double kWeld = 1e-6;  // meters: vertices of different faces this close are one

struct Face {
  std::vector<std::vector<Vec3>> rings;  // world; outer counter-clockwise seen from the normal
  Vec3 normal;
  FaceTag tag;
};

using Key = std::tuple<long long, long long, long long>;
Key key_of(Vec3 p) {
  return {std::llround(p.x / kWeld), std::llround(p.y / kWeld), std::llround(p.z / kWeld)};
}

// Solves dot(o, n_i) = d for the distinct normals meeting at a vertex (least squares through the
// normal equations; the minimum-norm solution in span(n_i) when they are fewer than three).
Vec3 joint_offset(const std::vector<Vec3>& normals, double d) {
  std::vector<Vec3> ns;
  for (const Vec3& n : normals) {
    const bool known =
        std::any_of(ns.begin(), ns.end(), [&](Vec3 m) { return dot(m, n) > 1 - 1e-9; });
    if (!known) ns.push_back(n);
  }
  // Keep an independent subset (at most 3) so the Gram matrix is invertible.
  std::vector<Vec3> basis;
  for (const Vec3& n : ns) {
    if (basis.size() == 3) break;
    if (basis.size() == 1 && length(cross(basis[0], n)) < 1e-6) continue;
    if (basis.size() == 2 && std::fabs(dot(cross(basis[0], basis[1]), n)) < 1e-6) continue;
    basis.push_back(n);
  }
  if (basis.size() == 1) return basis[0] * d;
  // o = sum a_j n_j with G a = d 1, G_ij = n_i . n_j.
  const std::size_t k = basis.size();
  double g[3][4] = {};
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) g[i][j] = dot(basis[i], basis[j]);
    g[i][3] = d;
  }
  for (std::size_t c = 0; c < k; ++c) {  // Gauss-Jordan with partial pivoting
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < k; ++r) {
      if (std::fabs(g[r][c]) > std::fabs(g[pivot][c])) pivot = r;
    }
    for (int col = 0; col < 4; ++col) std::swap(g[c][col], g[pivot][col]);
    for (std::size_t r = 0; r < k; ++r) {
      if (r == c) continue;
      const double f = g[r][c] / g[c][c];
      for (std::size_t col = c; col < 4; ++col) g[r][col] -= f * g[c][col];
    }
  }
  Vec3 o;
  for (std::size_t i = 0; i < k; ++i) o += basis[i] * (g[i][3] / g[i][i]);
  return o;
}

// The visible (moved) surface: inward growth shows floors, ceilings and interior walls; outward
// growth exterior walls, roofs and soffits (world z is up).
SemanticClass visible_class(Vec3 normal, double d) {
  if (d < 0) {
    if (normal.z < -0.7) return SemanticClass::kFloorSurface;
    if (normal.z > 0.7) return SemanticClass::kCeilingSurface;
    return SemanticClass::kInteriorWallSurface;
  }
  if (normal.z > 0.7) return SemanticClass::kRoofSurface;
  if (normal.z < -0.7) return SemanticClass::kOuterCeilingSurface;
  return SemanticClass::kWallSurface;
}

// Adds a quad, split in two triangles when it is not planar.
void add_quad(Mesh& mesh, std::array<std::uint32_t, 4> q, FaceTag tag) {
  const Vec3 a = mesh.position(q[0]);
  const Vec3 n = cross(mesh.position(q[1]) - a, mesh.position(q[2]) - a);
  const double l = length(n);
  if (l > 0 && std::fabs(dot(n / l, mesh.position(q[3]) - a)) > 1e-9) {
    mesh.add_face({q[0], q[1], q[2]}, tag);
    mesh.add_face({q[0], q[2], q[3]}, tag);
    return;
  }
  mesh.add_face(std::span<const std::uint32_t>(q), tag);
}

// The prism of one face with per-vertex offsets, closed and outward (world space).
Mesh face_prism(const Face& face, const std::map<Key, Vec3>& offsets, double d) {
  Mesh mesh;
  kernel::Polygon region;  // in a 2D frame of the face plane for the caps
  Vec3 u = std::fabs(face.normal.z) < 0.9 ? cross(Vec3{0, 0, 1}, face.normal) : Vec3{1, 0, 0};
  u = normalized(u - face.normal * dot(u, face.normal));
  const Vec3 v = cross(face.normal, u);
  std::vector<std::uint32_t> base_ids;
  std::vector<std::uint32_t> moved_ids;
  for (std::size_t r = 0; r < face.rings.size(); ++r) {
    kernel::Ring ring;
    for (const Vec3& p : face.rings[r]) {
      base_ids.push_back(mesh.add_vertex(p));
      moved_ids.push_back(mesh.add_vertex(p + offsets.at(key_of(p))));
      ring.push_back({dot(p, u), dot(p, v)});
    }
    if (r == 0)
      region.outer = std::move(ring);
    else
      region.holes.push_back(std::move(ring));
  }
  const FaceTag closure{SemanticClass::kClosureSurface, face.tag.material, face.tag.face_id};
  const FaceTag visible{visible_class(face.normal, d), face.tag.material, face.tag.face_id};
  // d > 0: the base faces against the normal, the moved cap along it; d < 0 the reverse.
  const bool out = d > 0;
  kernel::add_region_faces(mesh, region, base_ids, out, out ? closure : visible);
  kernel::add_region_faces(mesh, region, moved_ids, !out, out ? visible : closure);
  std::size_t at = 0;
  for (const auto& ring : face.rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::size_t j = (i + 1) % ring.size();
      const std::uint32_t a = base_ids[at + i], b = base_ids[at + j];
      const std::uint32_t am = moved_ids[at + i], bm = moved_ids[at + j];
      if (out)
        add_quad(mesh, {a, b, bm, am}, closure);
      else
        add_quad(mesh, {b, a, am, bm}, closure);
    }
    at += ring.size();
  }
  if (kernel::volume(mesh) < 0) mesh.flip();
  return mesh;
}

}  // namespace

OpResult extrude_joint(ShapeTree& tree, std::span<const ShapeId> ids, double distance) {
  if (!(std::fabs(distance) > 0) || !std::isfinite(distance)) {
    return OpResult::failure("distance must be finite and not 0");
  }
  std::vector<Face> faces;
  std::map<Key, std::vector<Vec3>> normals_at;
  for (ShapeId id : ids) {
    if (!tree.contains(id) || !tree[id].is_flat()) {
      return OpResult::failure("component " + std::to_string(id) + " is not flat");
    }
    const Shape& s = tree[id];
    Face face;
    face.normal = normalized(s.scope.z);
    face.tag = s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : FaceTag{};
    kernel::Polygon outline = *s.outline;
    kernel::normalize(outline);
    const auto lift = [&](const kernel::Ring& ring) {
      std::vector<Vec3> out;
      for (Vec2 p : ring) out.push_back(s.scope.to_world(kernel::lift(p, 0)));
      return out;
    };
    face.rings.push_back(lift(outline.outer));
    for (const auto& hole : outline.holes) face.rings.push_back(lift(hole));
    for (const auto& ring : face.rings) {
      for (const Vec3& p : ring) normals_at[key_of(p)].push_back(face.normal);
    }
    faces.push_back(std::move(face));
  }
  std::map<Key, Vec3> offsets;
  for (const auto& [key, normals] : normals_at) offsets[key] = joint_offset(normals, distance);
  OpResult result;
  for (std::uint32_t i = 0; i < faces.size(); ++i) {
    const Mesh world = face_prism(faces[i], offsets, distance);
    const Shape& s = tree[ids[i]];
    const Scope scope = fit_scope(world, s.scope.x, s.scope.y, s.scope.z);
    auto mesh = std::make_shared<Mesh>(mesh_to_local(world, scope));
    result.add(tree.add_child(ids[i], scope, std::move(mesh)), i);
  }
  return result;
}

}  // namespace insula::shape
