// Roofs as closed solids (seed 000 §4.1 "the geometry of the roof is created according to the type
// of roof defined for each building part. Flat, pyramidal, hipped, mansard, holed mansard"): the
// roof of roof.h closed underneath over the wall-top vertices, its gable ends closed by their
// triangles, a flat roof as a slab with a thickness, a holed mansard's compluvium opened through
// the solid, and the roof's height above the eaves given directly instead of through the pitch.
// The .bldg builder and the shape operation `roof` (closed = true, CGA roofFlat with a thickness)
// build their roofs here, so both give the same solid.
#pragma once

#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/roof.h"

namespace insula::kernel {

struct RoofSolidSpec {
  RoofSpec roof;  // type, pitch, overhang, mansard slopes
  // > 0: the roof is scaled in z so its soffit lies at the eaves and its top `height` (meters)
  // above them (scale_roof_height in roof.h). 0: the height the pitch gives.
  double height = 0;
  // Flat roofs: a slab this thick (meters, > 0) over the outline grown by the overhang (the
  // kernel's flat roof is a single face, which without overhang would enclose no volume).
  double flat_thickness = 0.25;
  // Holed mansard: the compluvium goes through the solid (true), or is closed by a floor at the
  // eaves (false).
  bool open_compluvium = true;
};

struct RoofSolid {
  Mesh mesh;  // closed, faces outward; empty when kFailed
  RoofStatus status = RoofStatus::kFailed;
  std::string message;  // why the roof fell back or failed
  // A holed mansard's opened compluvium: the opening's outline at the eaves (counter-clockwise),
  // so the rooms below can leave their ceilings open under it.
  std::vector<Polygon> openings;
};

// The closed roof solid over `footprint` (valid, normalized) with its eaves at `eave_z`. Tags: roof
// faces RoofSurface, gable ends and fascias WallSurface, the bottom ClosureSurface (a flat slab:
// OuterCeilingSurface below, RoofSurface on top, WallSurface around).
RoofSolid build_roof_solid(const Polygon& footprint, const RoofSolidSpec& spec, double eave_z);

}  // namespace insula::kernel
