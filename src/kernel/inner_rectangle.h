// The largest axis-aligned rectangle inside a polygon with holes (CityEngine's innerRectangle),
// found on a grid whose lines are the polygon's vertex coordinates plus `steps` even divisions of
// its bounds, then grown side by side up to the boundary: exact for rectilinear polygons (every
// side of the best rectangle lies on a vertex coordinate), otherwise within one grid cell and
// usually closer.
#pragma once

#include <optional>

#include "kernel/polygon.h"

namespace insula::kernel {

struct Rect2 {
  Vec2 min;
  Vec2 max;
  double area() const { return (max.x - min.x) * (max.y - min.y); }
};

// Nullopt when the polygon has no area.
std::optional<Rect2> largest_inner_rectangle(const Polygon& polygon, int steps = 64);

}  // namespace insula::kernel
