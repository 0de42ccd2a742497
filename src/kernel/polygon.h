// Planar polygons with holes, in meters. Invariant after normalize(): the outer ring runs
// counter-clockwise, every hole clockwise, no ring repeats its first vertex at the end.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "kernel/vec.h"

namespace insula::kernel {

using Ring = std::vector<Vec2>;

struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

// Twice-signed shoelace area / 2: positive for counter-clockwise rings.
double signed_area(const Ring& ring);
// Outer area minus hole areas, whatever the orientation.
double area(const Polygon& polygon);
double perimeter(const Polygon& polygon);
// Area centroid of the region (holes subtracted).
Vec2 centroid(const Polygon& polygon);
// Outer counter-clockwise, holes clockwise; drops a closing vertex equal to the first.
void normalize(Polygon& polygon);
// Moves every vertex by `offset`.
void translate(Polygon& polygon, Vec2 offset);

// Distance from p to the closed segment ab (to a when the segment has zero length).
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b);

// The square of that distance, without the root: for tests against a squared tolerance in hot
// loops (the wall validation, the builder's corner tests). Inline for the same reason.
inline double squared_distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + ab * t);
  return dot(d, d);
}

// Segments ab and cd cross at a point interior to both (strict orientation tests: touching,
// collinear overlap and shared endpoints do not count).
bool segments_cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

enum class PointLocation { kOutside, kBoundary, kInside };
// `tolerance` is the distance within which a point counts as on the boundary.
PointLocation locate(const Polygon& polygon, Vec2 point, double tolerance = 1e-9);

struct Bounds2 {
  Vec2 min{1e300, 1e300};
  Vec2 max{-1e300, -1e300};
  void add(Vec2 p);
  bool empty() const { return min.x > max.x; }
};
Bounds2 bounds(const Polygon& polygon);

// Validation and repair (polygon_repair.cc).
enum class PolygonIssueKind {
  kTooFewVertices,    // a ring with fewer than 3 distinct vertices (not repairable)
  kNonFinite,         // NaN or infinite coordinate (not repairable)
  kDuplicateVertex,   // consecutive equal vertices (repaired: removed)
  kCollinearVertex,   // a vertex on the line through its neighbours (repaired: removed)
  kZeroArea,          // a ring of (near) zero area (not repairable)
  kSelfIntersection,  // edges of one ring cross (repaired only when unambiguous, see docs)
  kRingsIntersect,    // a hole crosses the outer ring or another hole
  kHoleOutside,       // a hole lies outside the outer ring
  kWrongOrientation,  // repaired: reversed
};

struct PolygonIssue {
  PolygonIssueKind kind;
  int ring = 0;  // 0 = outer, i > 0 = hole i-1
  int vertex = -1;
  bool repaired = false;
  std::string message;
};

struct RepairResult {
  Polygon polygon;                   // the repaired polygon (valid only if ok)
  std::vector<PolygonIssue> issues;  // everything found, repaired or not
  bool ok = false;                   // true when the result is a valid polygon
};

// Removes duplicate and collinear vertices, fixes orientation, and reports self-intersections,
// zero area and misplaced holes. `tolerance` in meters.
RepairResult repair(const Polygon& polygon, double tolerance = 1e-7);
std::vector<PolygonIssue> validate(const Polygon& polygon, double tolerance = 1e-7);

// Rings that pass twice through the same point (docs/kernel-polygons.md, "Touching rings"): each
// is cut there into two loops, repeatedly. Outer loops winding like their ring become polygons of
// their own (two buildings meeting at a corner); loops winding the other way, inside one of them,
// become its holes (a courtyard pinched off at one point); holes split into holes. Anything else
// (a loop crossing over at the point, nested loops of one winding, a hole pinching off an island)
// is ambiguous and left as it was, for repair() to report. Exact coordinate equality; consecutive
// repeats are ignored, as are cuts that would leave a loop of fewer than 3 vertices or no area (a
// spike: repair() removes those).
struct TouchSplit {
  std::vector<Polygon> polygons;  // the input unchanged when `points` is empty
  std::vector<Vec2> points;       // where the cuts were made
};
TouchSplit split_touching_rings(const Polygon& polygon);

// For a polygon repair() accepts whose rings still meet at single points (a hole touching the
// outer ring or another hole): moves each hole vertex lying on another ring `distance` into its
// hole along its corner's bisector, then each outer vertex lying on a hole `distance` outwards.
// Expects normalized orientation (outer counter-clockwise, holes clockwise). Returns the
// original positions of the moved vertices; the caller checks the result is simple.
std::vector<Vec2> separate_touching_rings(Polygon& polygon, double distance);

}  // namespace insula::kernel
