#include "kernel/mesh_sample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "kernel/polygon.h"
#include "kernel/triangulate.h"

namespace insula::kernel {

namespace {

// Two unit vectors spanning the plane with unit normal n, so that (e1, e2, n) is right-handed:
// a loop counter-clockwise seen from n stays counter-clockwise in (e1, e2).
void plane_axes(Vec3 n, Vec3& e1, Vec3& e2) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  e1 = normalized(cross(helper, n));
  e2 = cross(n, e1);
}

// The point of segment ab nearest to p.
Vec3 closest_on_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double len2 = dot(d, d);
  if (!(len2 > 0)) return a;
  const double t = std::clamp(dot(p - a, d) / len2, 0.0, 1.0);
  return a + d * t;
}

double distance2(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return dot(d, d);
}

}  // namespace

// Project p onto the triangle's plane; when the projection's barycentric coordinates are all
// non-negative it is the answer, otherwise the nearest point lies on the boundary, so the nearest
// of the three edges' nearest points.
Vec3 closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 n = cross(ab, ac);
  const double n2 = dot(n, n);
  if (n2 > 0) {
    const Vec3 q = p - n * (dot(p - a, n) / n2);
    const double u = dot(cross(q - a, ac), n) / n2;  // weight of b
    const double v = dot(cross(ab, q - a), n) / n2;  // weight of c
    if (u >= 0 && v >= 0 && u + v <= 1) return a + ab * u + ac * v;
  }
  Vec3 best = closest_on_segment(p, a, b);
  for (const Vec3 candidate : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)}) {
    if (distance2(p, candidate) < distance2(p, best)) best = candidate;
  }
  return best;
}

MeshSurface::MeshSurface(const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) add_face(mesh, f);
}

void MeshSurface::add_triangle(Vec3 a, Vec3 b, Vec3 c, Vec3 normal, std::size_t face) {
  const double area = 0.5 * length(cross(b - a, c - a));
  if (!(area > 0) || !std::isfinite(area)) return;
  triangles_.push_back({a, b, c, normal, face});
  cumulative_.push_back(this->area() + area);
}

// A triangle directly; a larger face by ear clipping in its own plane (faces are simple planar
// loops, mesh.h), so concave faces are covered exactly.
void MeshSurface::add_face(const Mesh& mesh, std::size_t face) {
  const auto loop = mesh.face(face);
  const Vec3 n = face_normal(mesh, face);
  if (loop.size() < 3 || !(length(n) > 0)) return;
  if (loop.size() == 3) {
    add_triangle(mesh.position(loop[0]), mesh.position(loop[1]), mesh.position(loop[2]), n, face);
    return;
  }
  Vec3 e1;
  Vec3 e2;
  plane_axes(n, e1, e2);
  Polygon polygon;
  for (std::uint32_t v : loop) {
    const Vec3 p = mesh.position(v);
    polygon.outer.push_back({dot(p, e1), dot(p, e2)});
  }
  Triangulation t;
  if (!triangulate(polygon, t)) return;
  for (const auto& tri : t.triangles) {
    add_triangle(mesh.position(loop[tri[0]]), mesh.position(loop[tri[1]]),
                 mesh.position(loop[tri[2]]), n, face);
  }
}

// Folding (u, v) across the diagonal when u + v > 1 maps the unit square onto the triangle
// twice over with constant density, so uniform (u, v) give a uniform point in the triangle.
SurfacePoint MeshSurface::at(double pick, double u, double v) const {
  const double target = std::clamp(pick, 0.0, 1.0) * area();
  auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  if (it == cumulative_.end()) --it;
  const Triangle& t = triangles_[static_cast<std::size_t>(it - cumulative_.begin())];
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  return {t.a + (t.b - t.a) * u + (t.c - t.a) * v, t.normal, t.face};
}

SurfacePoint MeshSurface::nearest(Vec3 p) const {
  SurfacePoint best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles_) {
    const Vec3 q = closest_point_on_triangle(p, t.a, t.b, t.c);
    const double d2 = distance2(p, q);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = {q, t.normal, t.face};
    }
  }
  return best;
}

// Solid angle of a triangle seen from the origin (Van Oosterom, Strackee: "The Solid Angle of a
// Plane Triangle", IEEE Trans. Biomed. Eng. 30(2), 1983), signed by the triangle's orientation.
double MeshSurface::winding_number(Vec3 p) const {
  double sum = 0;
  for (const Triangle& t : triangles_) {
    const Vec3 a = t.a - p;
    const Vec3 b = t.b - p;
    const Vec3 c = t.c - p;
    const double la = length(a);
    const double lb = length(b);
    const double lc = length(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    sum += 2 * std::atan2(numerator, denominator);
  }
  return sum / (4 * std::numbers::pi);
}

}  // namespace insula::kernel
