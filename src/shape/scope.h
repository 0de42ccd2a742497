// The scope of a shape: an oriented box (origin P, orthonormal right-handed axes X Y Z, size S),
// after CGA shape grammars (seed 004, "Shape"; Müller et al. 2006). A shape's geometry is stored in
// scope space: local point (u, v, w) is world point P + u X + v Y + w Z, and the geometry of a
// well-formed shape lies in [0, S.x] x [0, S.y] x [0, S.z].
//
// Conventions (docs/shape-model.md, "Scope conventions"):
// - mass (volume) shapes: x runs along the front edge, y is up (world +Z for a mass extruded from a
//   footprint), z = x cross y is the depth axis and points out of the front face, so the front face
//   is the face at z = S.z with outward normal +z (as CityEngine's comp "front").
// - face (flat) shapes: the face lies in the scope's xy plane (S.z = 0) and z is its outward
// normal;
//   x runs along the face's bottom edge (horizontal for vertical and sloped faces) and y = z cross
//   x.
// - a footprint root: z = world +Z, x along the footprint's first (or longest) edge, y = z cross x
//   points into the footprint.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "kernel/mesh.h"
#include "kernel/transform.h"
#include "kernel/vec.h"

namespace insula::shape {

enum class Axis : std::uint8_t { kX, kY, kZ };

// Component `axis` of `v`.
double component(kernel::Vec3 v, Axis axis);
void set_component(kernel::Vec3& v, Axis axis, double value);

struct Scope {
  kernel::Vec3 origin;
  kernel::Vec3 x{1, 0, 0};
  kernel::Vec3 y{0, 1, 0};
  kernel::Vec3 z{0, 0, 1};
  kernel::Vec3 size;

  kernel::Vec3 axis(Axis a) const;
  double extent(Axis a) const { return component(size, a); }

  // Scope space <-> world space for points (meters) and directions (unit vectors stay unit).
  kernel::Vec3 to_world(kernel::Vec3 local) const;
  kernel::Vec3 to_local(kernel::Vec3 world) const;
  kernel::Vec3 direction_to_world(kernel::Vec3 local) const;
  kernel::Vec3 direction_to_local(kernel::Vec3 world) const;

  // World-space centre of the box.
  kernel::Vec3 center() const;
  double volume() const { return size.x * size.y * size.z; }
  // World-space corners, index bit 0 = x, bit 1 = y, bit 2 = z.
  std::array<kernel::Vec3, 8> corners() const;
  // A child scope: this scope's frame moved by `local_offset` (scope space) with `new_size`.
  Scope sub(kernel::Vec3 local_offset, kernel::Vec3 new_size) const;
};

// The rigid transform taking scope space (meters, not normalised by the size) to world space.
kernel::Transform scope_transform(const Scope& scope);
// Transforms every vertex of `mesh` from scope space to world space (or back).
kernel::Mesh mesh_to_world(const kernel::Mesh& mesh, const Scope& scope);
// The same into `out`, whose storage is reused (a scratch mesh per terminal of an export).
void mesh_to_world(const kernel::Mesh& mesh, const Scope& scope, kernel::Mesh& out);
kernel::Mesh mesh_to_local(const kernel::Mesh& mesh, const Scope& scope);

// Right-handed orthonormal frame from a preferred x direction and a z direction (z wins when they
// are not perpendicular). Returns false when either is zero or they are parallel.
bool make_frame(kernel::Vec3 x_hint, kernel::Vec3 z, kernel::Vec3& x, kernel::Vec3& y,
                kernel::Vec3& out_z);

// The scope with axes (x, y, z) (orthonormal, right-handed) that tightly bounds `points` (world).
Scope fit_scope(std::span<const kernel::Vec3> points, kernel::Vec3 x, kernel::Vec3 y,
                kernel::Vec3 z);
// Fits a scope with the given axes around a world-space mesh.
Scope fit_scope(const kernel::Mesh& world_mesh, kernel::Vec3 x, kernel::Vec3 y, kernel::Vec3 z);

// The scope of face `face` of `mesh` (any space; the scope is in that same space): z = the face's
// outward normal; x = horizontal along the face (up cross normal, with `up` the space's up
// direction) or, for faces facing along `up`, `x_hint`; y = z cross x. Size z is 0. Returns false
// for a degenerate face.
bool face_scope(const kernel::Mesh& mesh, std::size_t face, kernel::Vec3 up, kernel::Vec3 x_hint,
                Scope& out);

// Rotates the scope's axes by `degrees` about its own axis `axis` (right-hand rule), keeping
// `pivot` (scope space, e.g. the origin or the centre) fixed in the world.
Scope rotated(const Scope& scope, Axis axis, double degrees, kernel::Vec3 pivot);

// Rodrigues rotation of `v` about unit axis `k` by `radians`.
kernel::Vec3 rotate_about(kernel::Vec3 v, kernel::Vec3 k, double radians);

}  // namespace insula::shape
