#include "kernel/transform.h"

#include <cmath>

namespace insula::kernel {

namespace {

// sin and cos of an angle in degrees, exact at multiples of 90 degrees so that quarter turns map
// axis-aligned geometry onto axis-aligned geometry without rounding residues.
void sin_cos_degrees(double degrees, double& s, double& c) {
  const double reduced = std::fmod(degrees, 360.0);
  const double quarter = reduced / 90.0;
  if (quarter == std::floor(quarter)) {
    const int q = (static_cast<int>(quarter) % 4 + 4) % 4;
    constexpr double kSin[4] = {0, 1, 0, -1};
    constexpr double kCos[4] = {1, 0, -1, 0};
    s = kSin[q];
    c = kCos[q];
    return;
  }
  const double radians = reduced * (M_PI / 180.0);
  s = std::sin(radians);
  c = std::cos(radians);
}

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

Transform identity_transform() {
  return Transform{};
}

Transform translation(Vec3 offset) {
  Transform t;
  t.t = offset;
  return t;
}

Transform scaling(Vec3 factors) {
  return Transform{{factors.x, 0, 0}, {0, factors.y, 0}, {0, 0, factors.z}, {}};
}

Transform rotation(Vec3 axis, double degrees) {
  const Vec3 k = normalized(axis);
  if (k == Vec3{}) return Transform{};
  double s = 0;
  double c = 1;
  sin_cos_degrees(degrees, s, c);
  // Rodrigues: R v = v c + (k x v) s + k (k . v)(1 - c), evaluated on the unit axes.
  const auto rotate = [&](Vec3 v) { return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c)); };
  return Transform{rotate({1, 0, 0}), rotate({0, 1, 0}), rotate({0, 0, 1}), {}};
}

Transform rotation_about(Vec3 pivot, Vec3 axis, double degrees) {
  return translation(pivot) * rotation(axis, degrees) * translation(-pivot);
}

Transform frame(Vec3 origin, Vec3 x_axis, Vec3 y_axis, Vec3 z_axis) {
  return Transform{x_axis, y_axis, z_axis, origin};
}

Transform compose(const Transform& outer, const Transform& inner) {
  return Transform{apply_vector(outer, inner.x), apply_vector(outer, inner.y),
                   apply_vector(outer, inner.z), apply_point(outer, inner.t)};
}

double determinant(const Transform& transform) {
  return dot(transform.x, cross(transform.y, transform.z));
}

std::optional<Transform> inverse(const Transform& m) {
  if (!finite(m.x) || !finite(m.y) || !finite(m.z) || !finite(m.t)) return std::nullopt;
  const double det = determinant(m);
  if (!(std::abs(det) > 1e-300)) return std::nullopt;
  // The rows of L^-1 are the cross products of pairs of columns divided by det L.
  const Vec3 r0 = cross(m.y, m.z) / det;
  const Vec3 r1 = cross(m.z, m.x) / det;
  const Vec3 r2 = cross(m.x, m.y) / det;
  Transform inv{{r0.x, r1.x, r2.x}, {r0.y, r1.y, r2.y}, {r0.z, r1.z, r2.z}, {}};
  inv.t = -apply_vector(inv, m.t);
  return inv;
}

Vec3 apply_point(const Transform& m, Vec3 p) {
  return m.x * p.x + m.y * p.y + m.z * p.z + m.t;
}

Vec3 apply_vector(const Transform& m, Vec3 v) {
  return m.x * v.x + m.y * v.y + m.z * v.z;
}

Vec3 apply_normal(const Transform& m, Vec3 n) {
  // Cofactor matrix C = det(L) L^-T: its rows are the column cross products, so
  // C n = (y x z) n.x + (z x x) n.y + (x x y) n.z. Multiplying by sign(det) keeps it outward for
  // mirroring transforms.
  const Vec3 c = cross(m.y, m.z) * n.x + cross(m.z, m.x) * n.y + cross(m.x, m.y) * n.z;
  return normalized(determinant(m) < 0 ? -c : c);
}

void transform_mesh(Mesh& mesh, const Transform& transform) {
  for (Vec3& p : mesh.positions()) p = apply_point(transform, p);
  if (determinant(transform) < 0) mesh.flip();
}

Mesh transformed(const Mesh& mesh, const Transform& transform) {
  Mesh out = mesh;
  transform_mesh(out, transform);
  return out;
}

}  // namespace insula::kernel
