// Measures and point location for polygons with holes (polygon.h). Sums are taken relative to the
// first outer vertex so that projected coordinates (UTM, x ~ 5e5, y ~ 5e6) do not cancel
// catastrophically in the shoelace formula.
#include "kernel/polygon.h"

#include <algorithm>
#include <cmath>

namespace insula::kernel {
namespace {

// Twice the signed area of `ring` and its first moments, all relative to `origin`.
struct RingMoments {
  double twice_area = 0;
  Vec2 moment;  // sum over edges of (p + q) * cross(p, q), relative to origin
};

// Edges (i, i + 1) with the last back to 0, stepped without a modulo: an integer division a
// vertex cost more than the shoelace term (signed_area runs for every ring the kernel makes).
RingMoments moments(const Ring& ring, Vec2 origin) {
  RingMoments m;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i] - origin;
    const Vec2 q = ring[i + 1 < n ? i + 1 : 0] - origin;
    const double c = cross(p, q);
    m.twice_area += c;
    m.moment += (p + q) * c;
  }
  return m;
}

// moments()' twice_area alone, the same sums in the same order.
double twice_signed_area(const Ring& ring, Vec2 origin) {
  double twice_area = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i] - origin;
    const Vec2 q = ring[i + 1 < n ? i + 1 : 0] - origin;
    twice_area += cross(p, q);
  }
  return twice_area;
}

double ring_length(const Ring& ring) {
  double total = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; n > 1 && i < n; ++i) total += length(ring[(i + 1) % n] - ring[i]);
  return total;
}

// Crossing-number test (Shimrat's algorithm, half-open rule so a vertex is counted once), with a
// first pass that reports points within `tolerance` of an edge as on the boundary.
PointLocation locate_in_ring(const Ring& ring, Vec2 p, double tolerance) {
  const std::size_t n = ring.size();
  if (n == 0) return PointLocation::kOutside;
  for (std::size_t i = 0; i < n; ++i) {
    if (distance_to_segment(p, ring[i], ring[(i + 1) % n]) <= tolerance)
      return PointLocation::kBoundary;
  }
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside ? PointLocation::kInside : PointLocation::kOutside;
}

void drop_closing_vertex(Ring& ring) {
  while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
}

}  // namespace

bool segments_cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = cross(b - a, c - a);
  const double o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c);
  const double o4 = cross(d - c, b - c);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(p - (a + ab * t));
}

double signed_area(const Ring& ring) {
  if (ring.size() < 3) return 0;
  return 0.5 * twice_signed_area(ring, ring.front());
}

double area(const Polygon& polygon) {
  double total = std::abs(signed_area(polygon.outer));
  for (const Ring& hole : polygon.holes) total -= std::abs(signed_area(hole));
  return total;
}

double perimeter(const Polygon& polygon) {
  double total = ring_length(polygon.outer);
  for (const Ring& hole : polygon.holes) total += ring_length(hole);
  return total;
}

void translate(Polygon& polygon, Vec2 offset) {
  for (Vec2& v : polygon.outer) v += offset;
  for (Ring& hole : polygon.holes) {
    for (Vec2& v : hole) v += offset;
  }
}

Vec2 centroid(const Polygon& polygon) {
  if (polygon.outer.empty()) return {};
  const Vec2 origin = polygon.outer.front();
  // Each ring contributes with the sign that makes the outer positive and the holes negative,
  // whatever orientation the rings were given in.
  double twice_area = 0;
  Vec2 moment;
  auto accumulate = [&](const Ring& ring, double sign) {
    const RingMoments m = moments(ring, origin);
    const double s = (m.twice_area >= 0 ? 1.0 : -1.0) * sign;
    twice_area += s * m.twice_area;
    moment += m.moment * s;
  };
  accumulate(polygon.outer, 1.0);
  for (const Ring& hole : polygon.holes) accumulate(hole, -1.0);
  if (std::abs(twice_area) <= 0) {
    // Degenerate region: fall back to the mean of the outer vertices.
    Vec2 sum;
    for (const Vec2& p : polygon.outer) sum += p - origin;
    return origin + sum / double(polygon.outer.size());
  }
  // Centroid of a polygon: C = sum (p_i + p_{i+1}) cross_i / (6 A), with 2A = twice_area.
  return origin + moment / (3.0 * twice_area);
}

void normalize(Polygon& polygon) {
  drop_closing_vertex(polygon.outer);
  if (signed_area(polygon.outer) < 0) std::reverse(polygon.outer.begin(), polygon.outer.end());
  for (Ring& hole : polygon.holes) {
    drop_closing_vertex(hole);
    if (signed_area(hole) > 0) std::reverse(hole.begin(), hole.end());
  }
}

PointLocation locate(const Polygon& polygon, Vec2 point, double tolerance) {
  const PointLocation outer = locate_in_ring(polygon.outer, point, tolerance);
  if (outer != PointLocation::kInside) return outer;
  for (const Ring& hole : polygon.holes) {
    switch (locate_in_ring(hole, point, tolerance)) {
      case PointLocation::kInside:
        return PointLocation::kOutside;
      case PointLocation::kBoundary:
        return PointLocation::kBoundary;
      case PointLocation::kOutside:
        break;
    }
  }
  return PointLocation::kInside;
}

void Bounds2::add(Vec2 p) {
  min.x = std::min(min.x, p.x);
  min.y = std::min(min.y, p.y);
  max.x = std::max(max.x, p.x);
  max.y = std::max(max.y, p.y);
}

Bounds2 bounds(const Polygon& polygon) {
  Bounds2 b;
  for (const Vec2& p : polygon.outer) b.add(p);
  for (const Ring& hole : polygon.holes)
    for (const Vec2& p : hole) b.add(p);
  return b;
}

}  // namespace insula::kernel
