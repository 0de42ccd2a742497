// How high a roof of a given pitch rises above its eave over a footprint: what splits a building's
// total height (OpenStreetMap's `height`, the top of the roof) between walls and roof when the data
// gives no roof height (docs/osm-buildings.md, "Heights").
#pragma once

#include "kernel/polygon.h"
#include "kernel/roof.h"

namespace insula::kernel {

// The rise in meters: 0 for flat roofs; for a shed the footprint's extent across its longest outer
// edge times tan(pitch); for the others the straight skeleton's deepest point times tan(pitch)
// (exact for hip, gable and pyramid roofs on convex footprints, an upper bound for a mansard,
// whose upper part is flatter). 0 when the footprint has no skeleton.
double roof_rise(const Polygon& footprint, RoofType type, double pitch_deg);

}  // namespace insula::kernel
