#include "kernel/planar.h"

namespace insula::kernel {

bool is_convex(std::span<const Vec2> ring, Winding winding, double tolerance) {
  const std::size_t n = ring.size();
  int way = winding == Winding::kCounterClockwise ? 1 : 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[(i + 1) % n];
    const Vec2 c = ring[(i + 2) % n];
    const double turn = cross(b - a, c - b);
    const int sign = turn > tolerance ? 1 : (turn < -tolerance ? -1 : 0);
    if (sign == 0) continue;
    if (way == 0) way = sign;
    if (sign != way) return false;
  }
  return true;
}

void clip(std::span<const Vec2> ring, const HalfPlane& half, Ring& out) {
  out.clear();
  const std::size_t n = ring.size();
  out.reserve(n + 1);  // a convex ring cut by a line gains at most one vertex
  const bool vertical = half.normal.y == 0 && half.offset == 0;
  const bool horizontal = half.normal.x == 0 && half.offset == 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i];
    const Vec2 q = ring[i + 1 < n ? i + 1 : 0];
    const double fp = dot(p - half.origin, half.normal) - half.offset;
    const double fq = dot(q - half.origin, half.normal) - half.offset;
    if (fp >= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      Vec2 x = p + (q - p) * (fp / (fp - fq));
      if (vertical) x.x = half.origin.x;
      if (horizontal) x.y = half.origin.y;
      out.push_back(x);
    }
  }
}

}  // namespace insula::kernel
