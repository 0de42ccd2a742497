// A polygon (with holes) cut into convex pieces: its triangulation (triangulate.h) with diagonals
// removed while the merged piece stays convex (Hertel and Mehlhorn, "Fast triangulation of simple
// polygons", 1983: at most four times the optimal number of pieces). CityEngine's convexify.
#pragma once

#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {

// Counter-clockwise convex rings that tile `polygon`. With `max_length` > 0, diagonals at least
// that long are removed first whatever the result (CityEngine: only split lines shorter than
// maxLength are applied), so a piece may stay concave. Empty when the polygon cannot be
// triangulated.
std::vector<Ring> convex_partition(const Polygon& polygon, double max_length = 0);

}  // namespace insula::kernel
