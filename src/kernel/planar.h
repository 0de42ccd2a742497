// Small planar primitives every layer uses: boxes of point sets, convexity, half-plane clipping.
// One definition each, so that front-ends and writers do not keep local copies that drift apart.
#pragma once

#include <span>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

// The box of `points` (empty for none). Inline: the floor-plan prefilters take the box of every
// cell of a storey.
inline Bounds2 bounds(std::span<const Vec2> points) {
  Bounds2 b;
  for (const Vec2 p : points) {
    b.min.x = std::min(b.min.x, p.x);
    b.min.y = std::min(b.min.y, p.y);
    b.max.x = std::max(b.max.x, p.x);
    b.max.y = std::max(b.max.y, p.y);
  }
  return b;
}

// Widens `box` to hold `points`.
inline void add(Bounds2& box, std::span<const Vec2> points) {
  const Bounds2 b = bounds(points);
  box.min = {std::min(box.min.x, b.min.x), std::min(box.min.y, b.min.y)};
  box.max = {std::max(box.max.x, b.max.x), std::max(box.max.y, b.max.y)};
}

// The closed boxes meet or come within `margin` of each other (touching counts).
inline bool touches(const Bounds2& a, const Bounds2& b, double margin = 0) {
  return a.min.x <= b.max.x + margin && b.min.x <= a.max.x + margin &&
         a.min.y <= b.max.y + margin && b.min.y <= a.max.y + margin;
}

enum class Winding {
  kCounterClockwise,  // convex and counter-clockwise
  kEither,            // convex, either way round
};
// Convexity with straight corners allowed: no corner of `ring` turns against `winding` by more
// than `tolerance` (the cross product of the two edges at the corner, m^2). kEither takes the way
// of the first bent corner. Rings of fewer than 3 vertices count as convex. A ring that winds
// more than once (a pentagram) passes: callers hold simple rings.
bool is_convex(std::span<const Vec2> ring, Winding winding = Winding::kCounterClockwise,
               double tolerance = 0);

// The half-plane {p : dot(p - origin, normal) >= offset}.
struct HalfPlane {
  Vec2 origin;
  Vec2 normal;
  double offset = 0;
};
// Sutherland & Hodgman 1974: the part of the convex ring inside `half`, into `out` (cleared; its
// storage is reused by callers cutting many times). Vertices on the line stay; a vertex is added
// only where an edge crosses the line strictly, so none repeats. When the line is axis-parallel
// and offset is 0 the crossings take the origin's coordinate exactly, so cells cut by one line
// share it bit for bit.
void clip(std::span<const Vec2> ring, const HalfPlane& half, Ring& out);

}  // namespace insula::kernel
