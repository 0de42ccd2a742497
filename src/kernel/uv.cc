#include "kernel/uv.h"

#include <cmath>

namespace insula::kernel {

Vec2 planar_uv(Vec3 p, Vec3 normal, double scale) {
  const double s = scale > 0 ? scale : 1;
  if (std::fabs(normal.z) > 0.9) return {p.x / s, (normal.z > 0 ? p.y : -p.y) / s};
  // u runs along the face seen from outside (up x normal points to the viewer's right).
  const Vec3 u = normalized(cross(Vec3{0, 0, 1}, normal));
  const Vec3 v = cross(normal, u);
  return {dot(p, u) / s, dot(p, v) / s};
}

}  // namespace insula::kernel
