// 2D booleans and offsets of polygons with holes, a thin wrapper over Clipper 1 (A. Johnson,
// libpolyclipping; Vatti's clipping algorithm, CACM 35(7), 1992) that hides its integer
// coordinates.
//
// Scaling: coordinates are shifted by the centre of the inputs' bounding box, then multiplied by
// kBooleanScale (1e6, i.e. 1 micrometre resolution) and rounded to 64-bit integers. Results are
// exact on that grid, so UTM-sized inputs (x ~ 5e5, y ~ 5e6 m) keep 1e-6 m precision. Inputs
// whose extent (plus twice the offset distance) exceeds kBooleanMaxExtent, or that hold NaN or
// infinite coordinates, give an empty result with a status instead of overflowing.
//
// Inputs: each Polygon is one region (outer ring minus holes) of any orientation; it is
// normalised before use. Overlapping polygons within one input are united (non-zero fill).
// Outputs: polygons with holes assigned to the right outer ring (from Clipper's PolyTree),
// normalised (outer counter-clockwise, holes clockwise), strictly simple (no ring touches
// itself), sorted by descending area then by lowest vertex for determinism.
#pragma once

#include <string_view>
#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {

inline constexpr double kBooleanScale = 1e6;       // integer units per metre
inline constexpr double kBooleanMaxExtent = 1e12;  // metres; far below Clipper's 4.6e18 units

enum class BooleanStatus {
  kOk,
  kNonFinite,      // a NaN or infinite coordinate or parameter
  kRangeTooLarge,  // extent (plus offset) beyond kBooleanMaxExtent
  kClipperFailed,  // Clipper reported failure (should not happen for finite input)
};

std::string_view to_string(BooleanStatus status);

struct BooleanResult {
  std::vector<Polygon> polygons;
  BooleanStatus status = BooleanStatus::kOk;
  bool ok() const { return status == BooleanStatus::kOk; }
};

BooleanResult unite(const std::vector<Polygon>& a, const std::vector<Polygon>& b);
BooleanResult intersect(const std::vector<Polygon>& a, const std::vector<Polygon>& b);
// a minus b.
BooleanResult subtract(const std::vector<Polygon>& a, const std::vector<Polygon>& b);
// a minus b, snapped in the integer frame of `frame` (widened to the operands' bounds) rather
// than of the operands' bounds alone. A caller may then leave out of `b` the polygons that only
// touch `a` (no common interior) and, passing the bounds of the full set, still get the vertices
// subtract(a, full set) gives (Clipper may start a ring at another of them).
BooleanResult subtract(const std::vector<Polygon>& a, const std::vector<Polygon>& b,
                       const Bounds2& frame);
BooleanResult exclusive_or(const std::vector<Polygon>& a, const std::vector<Polygon>& b);

// The union of all polygons, e.g. merging touching or overlapping footprints into blocks. Empty
// when the input is empty or cannot be represented (use unite() to learn why).
std::vector<Polygon> union_all(const std::vector<Polygon>& polygons);

enum class JoinType { kMiter, kRound, kSquare };

// Offsets the union of `polygons` by `delta` metres: positive grows (outer rings outward, holes
// shrink), negative shrinks; regions that vanish are dropped. `miter_limit` (in multiples of
// |delta|; values below 2 act as 2, Clipper's minimum) bounds how far a miter corner may reach
// before it is squared off; `arc_tolerance`
// (metres, > 0) is the largest distance between a true round join and its polygonal
// approximation. A square of side s offset by +d with kMiter has area (s + 2d)^2.
BooleanResult offset(const std::vector<Polygon>& polygons, double delta,
                     JoinType join = JoinType::kMiter, double miter_limit = 2.0,
                     double arc_tolerance = 1e-3);

}  // namespace insula::kernel
