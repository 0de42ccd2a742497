#include "shape/scope.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace insula::shape {

using kernel::Mesh;
using kernel::Vec3;

double component(Vec3 v, Axis axis) {
  switch (axis) {
    case Axis::kX:
      return v.x;
    case Axis::kY:
      return v.y;
    case Axis::kZ:
      return v.z;
  }
  return 0;
}

void set_component(Vec3& v, Axis axis, double value) {
  switch (axis) {
    case Axis::kX:
      v.x = value;
      break;
    case Axis::kY:
      v.y = value;
      break;
    case Axis::kZ:
      v.z = value;
      break;
  }
}

Vec3 Scope::axis(Axis a) const {
  switch (a) {
    case Axis::kX:
      return x;
    case Axis::kY:
      return y;
    case Axis::kZ:
      return z;
  }
  return x;
}

Vec3 Scope::to_world(Vec3 local) const {
  return origin + direction_to_world(local);
}

Vec3 Scope::to_local(Vec3 world) const {
  return direction_to_local(world - origin);
}

Vec3 Scope::direction_to_world(Vec3 local) const {
  return x * local.x + y * local.y + z * local.z;
}

Vec3 Scope::direction_to_local(Vec3 world) const {
  // The axes are orthonormal, so the inverse rotation is the transpose.
  return {dot(world, x), dot(world, y), dot(world, z)};
}

Vec3 Scope::center() const {
  return to_world(size * 0.5);
}

std::array<Vec3, 8> Scope::corners() const {
  std::array<Vec3, 8> out;
  for (int i = 0; i < 8; ++i) {
    out[static_cast<std::size_t>(i)] =
        to_world({(i & 1) ? size.x : 0, (i & 2) ? size.y : 0, (i & 4) ? size.z : 0});
  }
  return out;
}

Scope Scope::sub(Vec3 local_offset, Vec3 new_size) const {
  Scope s = *this;
  s.origin = to_world(local_offset);
  s.size = new_size;
  return s;
}

kernel::Transform scope_transform(const Scope& scope) {
  return kernel::frame(scope.origin, scope.x, scope.y, scope.z);
}

Mesh mesh_to_world(const Mesh& mesh, const Scope& scope) {
  Mesh out;
  mesh_to_world(mesh, scope, out);
  return out;
}

void mesh_to_world(const Mesh& mesh, const Scope& scope, Mesh& out) {
  out = mesh;
  kernel::transform_mesh(out, scope_transform(scope));
}

Mesh mesh_to_local(const Mesh& mesh, const Scope& scope) {
  Mesh out = mesh;
  for (Vec3& p : out.positions()) p = scope.to_local(p);
  return out;
}

bool make_frame(Vec3 x_hint, Vec3 z, Vec3& x, Vec3& y, Vec3& out_z) {
  const Vec3 zn = normalized(z);
  // Gram-Schmidt: remove the z part of the hint.
  const Vec3 xn = normalized(x_hint - zn * dot(x_hint, zn));
  if (length(zn) == 0 || length(xn) < 0.5) return false;
  x = xn;
  out_z = zn;
  y = cross(zn, xn);
  return true;
}

Scope fit_scope(std::span<const Vec3> points, Vec3 x, Vec3 y, Vec3 z) {
  Scope s;
  s.x = x;
  s.y = y;
  s.z = z;
  if (points.empty()) return s;
  kernel::Bounds3 b;
  for (Vec3 p : points) b.add(s.direction_to_local(p));
  s.origin = s.direction_to_world(b.min);
  s.size = b.max - b.min;
  return s;
}

Scope fit_scope(const Mesh& world_mesh, Vec3 x, Vec3 y, Vec3 z) {
  return fit_scope(std::span<const Vec3>(world_mesh.positions()), x, y, z);
}

bool face_scope(const Mesh& mesh, std::size_t face, Vec3 up, Vec3 x_hint, Scope& out) {
  const Vec3 n = kernel::face_normal(mesh, face);
  if (length(n) == 0) return false;
  Vec3 horizontal = cross(normalized(up), n);
  // Faces (nearly) facing along `up` have no horizontal direction: use the hint.
  if (length(horizontal) < 1e-6) horizontal = x_hint;
  Vec3 x;
  Vec3 y;
  Vec3 z;
  if (!make_frame(horizontal, n, x, y, z)) return false;
  std::vector<Vec3> loop;
  for (std::uint32_t v : mesh.face(face)) loop.push_back(mesh.position(v));
  out = fit_scope(loop, x, y, z);
  out.size.z = 0;  // a planar face: drop the rounding thickness
  return true;
}

Vec3 rotate_about(Vec3 v, Vec3 k, double radians) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

Scope rotated(const Scope& scope, Axis axis, double degrees, Vec3 pivot) {
  const double radians = degrees * std::numbers::pi / 180.0;
  const Vec3 k = scope.axis(axis);
  const Vec3 pivot_world = scope.to_world(pivot);
  Scope s = scope;
  s.x = normalized(rotate_about(scope.x, k, radians));
  s.y = normalized(rotate_about(scope.y, k, radians));
  s.z = normalized(rotate_about(scope.z, k, radians));
  // Keep the pivot fixed: the pivot's local coordinates map to the same world point.
  s.origin = pivot_world - s.direction_to_world(pivot);
  return s;
}

}  // namespace insula::shape
