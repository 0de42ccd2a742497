// The treemap subdivision of a container's region into its children's cells (seed 000, §3.2,
// Fig. 2, Eqs. 1-5).
//
// For child i along the arrangement axis an auxiliary rectangle starts where the previous one ended
// (Eq. 1) with the container's minimum rectangle's extent times the child's relative weight (Eq.
// 2); it is intersected with the container's region (Eq. 3) and scaled by +-step of the minimum
// rectangle's extent (Eqs. 4-5) until the intersection's area crosses the child's target. The
// paper stops there, within one step; we then bisect inside that last step so the cell's area
// matches its target to 1e-9 of the region's area, which makes areas exact and testable. The last
// child takes the remainder (§3.2). Targets are cumulative, so errors never add up along a row.
// On concave or holed regions a cut within 1 m of an inner corner moves onto it (no slivers).
//
// The region may be concave, hold holes, or consist of several pieces: a slab of the region is
// whatever the intersection gives, possibly several pieces (floorplan.cc decides what to do with a
// room that falls apart; docs/bldg-floorplan.md).
#pragma once

#include <vector>

#include "kernel/polygon.h"

namespace insula::lang::bldg::plan {

struct TreemapStats {
  int area_evaluations = 0;  // half-plane area evaluations (Eq. 3 areas)
  int scaling_steps = 0;     // Eqs. 4-5 steps taken before the bracket closed
};

// Cells of `region` for `weights` (positive, any sum) along x (along_x) or y, in order. `step` is
// the Eq. 5 step as a fraction of the minimum rectangle's extent along the axis (0 < step <= 0.5;
// other values act as 0.01). Returns one (possibly empty) list of polygons per weight.
std::vector<std::vector<kernel::Polygon>> split_region(const std::vector<kernel::Polygon>& region,
                                                       const std::vector<double>& weights,
                                                       bool along_x, double step,
                                                       TreemapStats* stats = nullptr);

}  // namespace insula::lang::bldg::plan
