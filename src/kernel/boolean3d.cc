// CGAL translation unit #2: corefinement booleans (CGAL Polygon Mesh Processing,
// corefine_and_compute_union/intersection/difference) on Surface_mesh with
// Exact_predicates_inexact_constructions_kernel.
#include "kernel/boolean3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string operand(int which) {
  return which == 0 ? "first operand" : "second operand";
}

// Welded copy of `mesh` as a triangulated Surface_mesh; a status other than kOk when unusable.
Boolean3dStatus to_surface_mesh(const Mesh& mesh, double tolerance, SurfaceMesh& out) {
  const Mesh welded = weld(mesh, tolerance);
  const MeshCheck c = check(welded);
  if (!c.closed || welded.empty()) return Boolean3dStatus::kNotClosed;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve(welded.vertex_count());
  for (const Vec3& p : welded.positions()) vertices.push_back(out.add_vertex({p.x, p.y, p.z}));
  std::vector<SurfaceMesh::Vertex_index> loop;
  for (std::size_t f = 0; f < welded.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t v : welded.face(f)) loop.push_back(vertices[v]);
    if (out.add_face(loop) == SurfaceMesh::null_face()) return Boolean3dStatus::kNotClosed;
  }
  if (!PMP::triangulate_faces(out) || !CGAL::is_closed(out)) return Boolean3dStatus::kNotClosed;
  if (PMP::does_self_intersect(out)) return Boolean3dStatus::kSelfIntersecting;
  if (!PMP::does_bound_a_volume(out) || !PMP::is_outward_oriented(out)) {
    return Boolean3dStatus::kNotAVolume;
  }
  return Boolean3dStatus::kOk;
}

// Point-in-face test in the face's plane (projected on the dominant axis plane).
bool face_contains(const Mesh& mesh, std::size_t f, Vec3 normal, Vec3 p) {
  const int drop = std::abs(normal.x) > std::abs(normal.y)
                       ? (std::abs(normal.x) > std::abs(normal.z) ? 0 : 2)
                       : (std::abs(normal.y) > std::abs(normal.z) ? 1 : 2);
  auto flat = [drop](Vec3 v) -> Vec2 {
    return drop == 0 ? Vec2{v.y, v.z} : drop == 1 ? Vec2{v.z, v.x} : Vec2{v.x, v.y};
  };
  Ring ring;
  for (std::uint32_t v : mesh.face(f)) ring.push_back(flat(mesh.position(v)));
  return locate(Polygon{ring, {}}, flat(p), 1e-7) != PointLocation::kOutside;
}

// The unit normals of a mesh's faces, computed once per boolean (every result face looks for
// its input face among all of them).
std::vector<Vec3> face_normals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) normals[f] = face_normal(mesh, f);
  return normals;
}

// The tag of the input face (of a, then b) whose plane holds `p` with a parallel normal, preferring
// one that contains p.
FaceTag find_tag(const Mesh* const (&inputs)[2], const std::vector<Vec3> (&normals)[2], Vec3 p,
                 Vec3 normal) {
  FaceTag fallback;
  bool found = false;
  for (int i = 0; i < 2; ++i) {
    const Mesh& m = *inputs[i];
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      const Vec3 n = normals[i][f];
      if (std::abs(dot(n, normal)) < 1 - 1e-6) continue;
      if (std::abs(dot(p - m.position(m.face(f)[0]), n)) > 1e-6) continue;
      if (face_contains(m, f, n, p)) return m.tag(f);
      if (!found) fallback = m.tag(f), found = true;
    }
  }
  return fallback;
}

bool untagged(const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const FaceTag t = mesh.tag(f);
    if (t.semantic != SemanticClass::kNone || t.material != 0 || t.face_id != 0) return false;
  }
  return true;
}

Mesh from_surface_mesh(const SurfaceMesh& sm, const Mesh& a, const Mesh& b) {
  Mesh out;
  const Mesh* const inputs[2] = {&a, &b};
  // Faces of untagged operands (PLaSM's solids) get the default tag whichever face they lie on:
  // the search, a scan of every input face per result face, is skipped.
  const bool search = !untagged(a) || !untagged(b);
  std::vector<Vec3> normals[2];
  if (search) {
    normals[0] = face_normals(a);
    normals[1] = face_normals(b);
  }
  std::vector<std::uint32_t> ids(sm.number_of_vertices() + sm.number_of_removed_vertices(), 0);
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    ids[v] = out.add_vertex({p.x(), p.y(), p.z()});
  }
  std::vector<std::uint32_t> loop;
  for (auto f : sm.faces()) {
    loop.clear();
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) loop.push_back(ids[v]);
    const Vec3 p0 = out.position(loop[0]);
    const Vec3 n = normalized(cross(out.position(loop[1]) - p0, out.position(loop[2]) - p0));
    const Vec3 c = (p0 + out.position(loop[1]) + out.position(loop[2])) / 3;
    out.add_face(loop, search ? find_tag(inputs, normals, c, n) : FaceTag{});
  }
  return out;
}

bool run(SurfaceMesh& a, SurfaceMesh& b, BooleanOp op, SurfaceMesh& out) {
  switch (op) {
    case BooleanOp::kUnion:
      return PMP::corefine_and_compute_union(a, b, out);
    case BooleanOp::kIntersection:
      return PMP::corefine_and_compute_intersection(a, b, out);
    case BooleanOp::kDifference:
      return PMP::corefine_and_compute_difference(a, b, out);
  }
  return false;
}

std::string describe(Boolean3dStatus status) {
  switch (status) {
    case Boolean3dStatus::kNotClosed:
      return " is not a closed, oriented 2-manifold";
    case Boolean3dStatus::kSelfIntersecting:
      return " intersects itself";
    case Boolean3dStatus::kNotAVolume:
      return " does not bound a volume";
    default:
      return " could not be used";
  }
}

}  // namespace

Boolean3dResult boolean3d(const Mesh& a, const Mesh& b, BooleanOp op, double weld_tolerance) {
  Boolean3dResult result;
  try {
    SurfaceMesh sa, sb, out;
    const Mesh* inputs[] = {&a, &b};
    SurfaceMesh* converted[] = {&sa, &sb};
    for (int i = 0; i < 2; ++i) {
      const Boolean3dStatus s = to_surface_mesh(*inputs[i], weld_tolerance, *converted[i]);
      if (s != Boolean3dStatus::kOk) {
        result.status = s;
        result.message = operand(i) + describe(s);
        return result;
      }
    }
    if (!run(sa, sb, op, out)) {
      result.message = "corefinement could not produce a manifold result";
      return result;
    }
    result.mesh = from_surface_mesh(out, a, b);
    result.status = Boolean3dStatus::kOk;
  } catch (const std::exception& e) {
    result = Boolean3dResult{};
    result.message = std::string("corefinement failed: ") + e.what();
  } catch (...) {
    result = Boolean3dResult{};
    result.message = "corefinement failed";
  }
  return result;
}

}  // namespace insula::kernel
