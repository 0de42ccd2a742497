// Triangulation of planar polygons with holes by ear clipping with hole bridging (D. Eberly,
// "Triangulation by Ear Clipping", Geometric Tools, 2002; M. Held, "FIST: Fast Industrial-Strength
// Triangulation of Polygons", Algorithmica 30, 2001). Holes are joined to the outer ring by
// bridges to their nearest visible vertex, then ears are clipped with a uniform grid over the
// vertices so each ear test only looks at nearby points. When no ear is found (degenerate input)
// the clipper escalates: drop zero-width spikes, cut a figure-eight list at a repeated vertex,
// split edges that a vertex touches, split the polygon along any valid diagonal, and finally drop
// a straight-angle vertex; it never loops and reports failure as a status.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

enum class TriangulationStatus {
  kOk,
  kTooFewVertices,  // the outer ring has fewer than 3 distinct vertices
  kNonFinite,       // a NaN or infinite coordinate
  kZeroArea,        // the outer ring encloses no area
  kFailed,          // no valid triangulation (self-intersecting rings, holes crossing, ...)
};

std::string_view to_string(TriangulationStatus status);

struct Triangulation {
  // The polygon's own vertices, in order: polygon.outer, then polygon.holes[0], holes[1], ...,
  // exactly as given (a closing vertex equal to the first is kept, and simply never referenced).
  // No vertex is ever added, so a caller that owns 3D vertices for the same rings (extrusion caps,
  // roofs, exporters) maps triangle indices straight back to its own vertex ids.
  std::vector<Vec2> vertices;
  // Counter-clockwise (positive area) triangles over `vertices`, none degenerate. Every vertex is
  // used unless it repeats the position of another, or (rare fallback for nearly degenerate input)
  // it is a straight-angle vertex the clipper had to drop.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  TriangulationStatus status = TriangulationStatus::kOk;
};

// Triangulates `polygon` whatever the orientation of its rings (the outer ring may be clockwise;
// holes of fewer than 3 distinct vertices or zero area are ignored). Expects a valid polygon (see
// repair() in polygon.h): holes inside the outer ring, no crossings; rings may touch at vertices
// and contain collinear vertices. Returns true when the triangles cover exactly the polygon's area
// (checked to 1e-9 relative); on false, `out.status` tells why and `out.triangles` is empty.
// Cost: about O(n log n + n k) for n vertices with k vertices near each ear.
bool triangulate(const Polygon& polygon, Triangulation& out);

}  // namespace insula::kernel
