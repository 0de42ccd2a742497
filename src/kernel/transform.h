// Affine transforms of 3D space: p' = L p + t, with the linear part L stored as its three column
// axes. A scope (origin P, axes X Y Z, size S; design.md "The shared shape model") maps to the
// transform frame(P, X * S.x, Y * S.y, Z * S.z), and scope-space geometry becomes world geometry by
// applying it. Angles are in degrees (the unit every front-end uses); lengths in meters.
#pragma once

#include <optional>

#include "kernel/mesh.h"
#include "kernel/vec.h"

namespace insula::kernel {

struct Transform {
  Vec3 x{1, 0, 0};  // image of the unit x axis (first column of L)
  Vec3 y{0, 1, 0};  // image of the unit y axis
  Vec3 z{0, 0, 1};  // image of the unit z axis
  Vec3 t{};         // translation (image of the origin)

  friend bool operator==(const Transform&, const Transform&) = default;
};

// The identity.
Transform identity_transform();
Transform translation(Vec3 offset);
// Scale about the origin by `factors` per axis (any sign; a zero factor makes it singular).
Transform scaling(Vec3 factors);
// Right-handed rotation by `degrees` about the line through the origin along `axis` (any non-zero
// length; a zero axis gives the identity). Multiples of 90 degrees are exact (no 6e-17 residues),
// so rotated boxes keep exactly axis-aligned faces.
Transform rotation(Vec3 axis, double degrees);
// Rotation about the line through `pivot` along `axis`.
Transform rotation_about(Vec3 pivot, Vec3 axis, double degrees);
// Maps local coordinates onto a frame: local (1,0,0) -> origin + x_axis, and so on. The axes need
// not be unit or orthogonal.
Transform frame(Vec3 origin, Vec3 x_axis, Vec3 y_axis, Vec3 z_axis);

// `outer` after `inner`: compose(a, b) applied to p equals a applied to (b applied to p).
Transform compose(const Transform& outer, const Transform& inner);
inline Transform operator*(const Transform& outer, const Transform& inner) {
  return compose(outer, inner);
}
// The inverse, or nothing when |det L| is below 1e-300 or any entry is not finite.
std::optional<Transform> inverse(const Transform& transform);
// det L: negative for a mirroring transform, zero for a singular one.
double determinant(const Transform& transform);

Vec3 apply_point(const Transform& transform, Vec3 point);
// Directions and offsets: the linear part only.
Vec3 apply_vector(const Transform& transform, Vec3 vector);
// Surface normals transform by the inverse transpose (cofactor matrix); the result is unit length,
// or zero for a singular transform.
Vec3 apply_normal(const Transform& transform, Vec3 normal);

// Transforms every vertex in place. When det L < 0 every face loop is reversed so faces stay
// counter-clockwise seen from outside (a closed mesh keeps a positive volume). Tags are kept.
void transform_mesh(Mesh& mesh, const Transform& transform);
Mesh transformed(const Mesh& mesh, const Transform& transform);

}  // namespace insula::kernel
