// "Is oriented to" (seed 003, §4.5, Fig. 1), in the ground plane: which walls see a street.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "kernel/context_query.h"
#include "kernel/context_query_grid.h"
#include "kernel/triangulate.h"

namespace insula::kernel {

namespace {

// Differences of street or sight-line parameters (0 to 1), and relative sines of angles, at or
// below this count as none.
constexpr double kParameterEpsilon = 1e-12;

Vec2 rotated(Vec2 v, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return {v.x * c - v.y * s, v.x * s + v.y * c};
}

Bounds3 segment_bounds(Vec2 a, Vec2 b) {
  Bounds3 box;
  box.add({a.x, a.y, 0});
  box.add({b.x, b.y, 0});
  return box;
}

// ---- sight lines ----

// The parameters s in [0, 1] where segment pq meets an edge of `polygon`'s rings (touching and
// collinear overlaps included).
void meeting_parameters(const Ring& ring, Vec2 p, Vec2 q, std::vector<double>& out) {
  const Vec2 d = q - p;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const Vec2 e = b - a;
    const double denom = cross(d, e);
    if (denom != 0) {
      const double s = cross(a - p, e) / denom, u = cross(a - p, d) / denom;
      if (s >= 0 && s <= 1 && u >= 0 && u <= 1) out.push_back(s);
      continue;
    }
    if (cross(a - p, d) != 0 || dot(d, d) == 0) continue;  // parallel, not on one line
    for (const Vec2 x : {a, b}) {
      const double s = dot(x - p, d) / dot(d, d);
      if (s >= 0 && s <= 1) out.push_back(s);
    }
  }
}

// Segment pq passes through the interior of `polygon`: between consecutive points where it
// meets the boundary it is entirely inside or entirely outside, so one midpoint per stretch
// decides.
bool crosses_interior(const Polygon& polygon, Vec2 p, Vec2 q) {
  std::vector<double> s{0, 1};
  meeting_parameters(polygon.outer, p, q, s);
  for (const Ring& hole : polygon.holes) meeting_parameters(hole, p, q, s);
  std::sort(s.begin(), s.end());
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i + 1] - s[i] <= kParameterEpsilon) continue;
    const Vec2 m = p + (q - p) * ((s[i] + s[i + 1]) / 2);
    if (locate(polygon, m) == PointLocation::kInside) return true;
  }
  return false;
}

// ---- is oriented to ----

struct Wedge {
  Vec2 apex;
  Vec2 axis;   // unit horizontal normal
  Vec2 left;   // axis turned by +tolerance
  Vec2 right;  // axis turned by -tolerance
  double radius = 0;
};

// The interval [t0, t1] of a + t (b - a), t in [0, 1], inside the wedge and its disc; false when
// empty. The wedge of at most 90 degrees either side is the intersection of three half-planes.
bool clip_to_wedge(const Wedge& w, Vec2 a, Vec2 b, double radius, double& t0, double& t1) {
  t0 = 0;
  t1 = 1;
  const Vec2 d = b - a, o = a - w.apex;
  // f(t) = f0 + t f1 >= 0 for each half-plane.
  const double half[3][2] = {{cross(w.right, o), cross(w.right, d)},
                             {cross(o, w.left), cross(d, w.left)},
                             {dot(o, w.axis), dot(d, w.axis)}};
  for (const auto& f : half) {
    if (f[1] == 0) {
      if (f[0] < 0) return false;
    } else if (f[1] > 0) {
      t0 = std::max(t0, -f[0] / f[1]);
    } else {
      t1 = std::min(t1, -f[0] / f[1]);
    }
  }
  // |o + t d|^2 <= radius^2.
  const double qa = dot(d, d), qb = 2 * dot(o, d), qc = dot(o, o) - radius * radius;
  if (qa == 0) return qc <= 0 && t0 <= t1;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  t0 = std::max(t0, (-qb - root) / (2 * qa));
  t1 = std::min(t1, (-qb + root) / (2 * qa));
  return t0 <= t1;
}

// The box of the wedge's sector of radius r: apex, the two boundary ends, and the arc's extreme
// points along the world axes that lie inside the wedge.
Bounds3 sector_bounds(const Wedge& w, double r) {
  Bounds3 box = segment_bounds(w.apex, w.apex + w.left * r);
  box.add({w.apex.x + w.right.x * r, w.apex.y + w.right.y * r, 0});
  for (const Vec2 axis : {Vec2{1, 0}, Vec2{-1, 0}, Vec2{0, 1}, Vec2{0, -1}}) {
    if (cross(w.right, axis) >= 0 && cross(axis, w.left) >= 0 && dot(axis, w.axis) >= 0) {
      box.add({w.apex.x + axis.x * r, w.apex.y + axis.y * r, 0});
    }
  }
  return box;
}

class OrientedSearch {
 public:
  OrientedSearch(std::span<const StreetSegment> streets, std::span<const Polygon> occluders,
                 const SkipPredicate& skip);
  bool oriented(std::size_t face, const Wedge& wedge);

 private:
  bool piece_visible(std::size_t face, const Wedge& wedge, Vec2 a, Vec2 b, double t0, double t1);
  bool sight_clear(Vec2 from, Vec2 to, const std::vector<std::size_t>& near) const;
  bool blocked_beyond(std::size_t face, const Wedge& wedge, double radius);
  const std::vector<std::array<Vec2, 3>>& triangles(std::size_t occluder);

  std::span<const StreetSegment> streets_;
  std::span<const Polygon> occluders_;
  const SkipPredicate& skip_;
  detail::BoxGrid street_grid_;
  detail::BoxGrid occluder_grid_;
  double first_radius_ = 1;
  // Each occluder's triangulation, made when the occluder is first needed; an untriangulable
  // footprint gets none and never ends a search early.
  std::vector<std::vector<std::array<Vec2, 3>>> triangles_;
  std::vector<bool> triangulated_;
};

std::vector<Bounds3> street_boxes(std::span<const StreetSegment> streets) {
  std::vector<Bounds3> boxes;
  for (const StreetSegment& s : streets) boxes.push_back(segment_bounds(s.a, s.b));
  return boxes;
}

std::vector<Bounds3> polygon_boxes(std::span<const Polygon> polygons) {
  std::vector<Bounds3> boxes;
  for (const Polygon& p : polygons) boxes.push_back(detail::flat_bounds(p.outer));
  return boxes;
}

OrientedSearch::OrientedSearch(std::span<const StreetSegment> streets,
                               std::span<const Polygon> occluders, const SkipPredicate& skip)
    : streets_(streets),
      occluders_(occluders),
      skip_(skip),
      street_grid_(street_boxes(streets)),
      occluder_grid_(polygon_boxes(occluders)),
      triangles_(occluders.size()),
      triangulated_(occluders.size(), false) {
  // About one street per cell, or twice the mean footprint when that is smaller, so that a wall
  // hidden by its neighbour is found hidden in the first rounds.
  const Vec3 extent = street_grid_.bounds().size();
  const double n = static_cast<double>(std::max<std::size_t>(streets.size(), 1));
  first_radius_ = std::max({extent.x / std::sqrt(n), extent.y / std::sqrt(n), 1e-3});
  double mean = 0;
  for (std::size_t o = 0; o < occluders.size(); ++o) {
    const Vec3 size = occluder_grid_.box(o).size();
    mean += std::max(size.x, size.y) / static_cast<double>(occluders.size());
  }
  if (mean > 0) first_radius_ = std::min(first_radius_, 2 * mean);
}

// Searches sectors of doubling radius, so a face that sees a near street stops early; each round
// re-tests the streets of the last, a constant factor on the final round.
bool OrientedSearch::oriented(std::size_t face, const Wedge& wedge) {
  const Bounds3& all = street_grid_.bounds();
  if (all.empty()) return false;
  const double reach = std::max({std::hypot(all.min.x - wedge.apex.x, all.min.y - wedge.apex.y),
                                 std::hypot(all.max.x - wedge.apex.x, all.min.y - wedge.apex.y),
                                 std::hypot(all.min.x - wedge.apex.x, all.max.y - wedge.apex.y),
                                 std::hypot(all.max.x - wedge.apex.x, all.max.y - wedge.apex.y)});
  struct Piece {
    double near;
    std::size_t street;
    double t0, t1;
  };
  std::vector<Piece> pieces;
  for (double r = first_radius_;; r *= 2) {
    const double radius = std::min({r, wedge.radius, reach});
    pieces.clear();
    street_grid_.query(sector_bounds(wedge, radius), [&](std::size_t s) {
      const StreetSegment& street = streets_[s];
      double t0 = 0, t1 = 0;
      if (!clip_to_wedge(wedge, street.a, street.b, radius, t0, t1)) return;
      const Vec2 d = street.b - street.a;
      pieces.push_back(
          {distance_to_segment(wedge.apex, street.a + d * t0, street.a + d * t1), s, t0, t1});
    });
    // Nearest first: a near street is the likeliest to be seen and the cheapest to decide.
    std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) {
      return x.near < y.near || (x.near == y.near && x.street < y.street);
    });
    bool found = false;
    for (const Piece& piece : pieces) {
      const StreetSegment& street = streets_[piece.street];
      found = piece_visible(face, wedge, street.a, street.b, piece.t0, piece.t1);
      if (found) break;
    }
    if (found) return true;
    if (radius >= wedge.radius || radius >= reach) return false;
    if (blocked_beyond(face, wedge, radius)) return false;
  }
}

const std::vector<std::array<Vec2, 3>>& OrientedSearch::triangles(std::size_t occluder) {
  if (!triangulated_[occluder]) {
    triangulated_[occluder] = true;
    Triangulation t;
    if (triangulate(occluders_[occluder], t)) {
      for (const auto& tri : t.triangles) {
        triangles_[occluder].push_back(
            {t.vertices[tri[0]], t.vertices[tri[1]], t.vertices[tri[2]]});
      }
    }
  }
  return triangles_[occluder];
}

// Direction of v relative to the wedge axis, in radians in (-pi, pi].
double relative_angle(const Wedge& w, Vec2 v) {
  return std::atan2(cross(w.axis, v), dot(w.axis, v));
}

// The closed range [lo, hi] of directions (relative to the wedge axis) whose open interior the
// triangle hides beyond `radius`: every sight line strictly inside it crosses the triangle's
// interior within that distance. A triangle apart from the apex hides the range between its
// extreme vertices from its farthest vertex on; one with the apex on its boundary (a neighbour
// touching the wall) hides the range between its other vertices at once, one holding the apex
// every direction. False when there is no range to trust: too far, or wrapping round behind.
bool hidden_range(const std::array<Vec2, 3>& tri, const Wedge& wedge, double radius, double& lo,
                  double& hi) {
  const PointLocation where = locate(Polygon{{tri[0], tri[1], tri[2]}, {}}, wedge.apex);
  if (where == PointLocation::kInside) {
    lo = -std::numbers::pi;
    hi = std::numbers::pi;
    return true;
  }
  lo = 1e300;
  hi = -1e300;
  double far = 0;
  for (const Vec2 v : tri) {
    const double distance = length(v - wedge.apex);
    if (where == PointLocation::kBoundary && distance <= 1e-9) continue;  // the apex itself
    const double angle = relative_angle(wedge, v - wedge.apex);
    lo = std::min(lo, angle);
    hi = std::max(hi, angle);
    far = std::max(far, distance);
  }
  if (where == PointLocation::kBoundary) return hi - lo <= std::numbers::pi + 1e-12;
  return far <= radius && hi - lo < std::numbers::pi;
}

// Whether the occluders within `radius` hide every direction of the wedge but a finite number:
// then no street beyond `radius` is seen over a positive angle. The closed hidden ranges of their
// triangles must cover the wedge.
bool OrientedSearch::blocked_beyond(std::size_t face, const Wedge& wedge, double radius) {
  std::vector<std::pair<double, double>> ranges;
  occluder_grid_.query(sector_bounds(wedge, radius), [&](std::size_t o) {
    if (skip_ && skip_(face, o)) return;
    for (const std::array<Vec2, 3>& tri : triangles(o)) {
      double lo = 0, hi = 0;
      if (hidden_range(tri, wedge, radius, lo, hi)) ranges.emplace_back(lo, hi);
    }
  });
  std::sort(ranges.begin(), ranges.end());
  const double tolerance = relative_angle(wedge, wedge.left);
  double covered = -tolerance;
  for (const auto& [lo, hi] : ranges) {
    if (lo > covered) return false;
    covered = std::max(covered, hi);
    if (covered >= tolerance) return true;
  }
  return false;
}

// Whether some point of a + t (b - a), t in [t0, t1], is seen from the apex. Visibility along the
// piece changes only where a sight line passes an occluder vertex or the street crosses an
// occluder edge; one point strictly between consecutive events decides each stretch.
bool OrientedSearch::piece_visible(std::size_t face, const Wedge& wedge, Vec2 a, Vec2 b, double t0,
                                   double t1) {
  const Vec2 d = b - a;
  const Vec2 p0 = a + d * t0, p1 = a + d * t1;
  // A piece seen under no angle (a point, or along a sight line) does not count.
  const Vec2 e0 = p0 - wedge.apex, e1 = p1 - wedge.apex;
  if (std::abs(cross(e0, e1)) <= kParameterEpsilon * length(e0) * length(e1)) return false;
  Bounds3 view = segment_bounds(p0, p1);
  view.add({wedge.apex.x, wedge.apex.y, 0});
  std::vector<std::size_t> near;
  occluder_grid_.query(view, [&](std::size_t o) {
    if (!(skip_ && skip_(face, o))) near.push_back(o);
  });
  std::vector<double> events{t0, t1};
  for (const std::size_t o : near) {
    auto add_ring = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 w = ring[i] - wedge.apex;
        const double denom = cross(w, d);
        const Vec2 e = ring[(i + 1) % ring.size()] - ring[i];
        const double along = cross(d, e);
        for (const double t : {denom != 0 ? -cross(w, a - wedge.apex) / denom : t0,
                               along != 0 ? cross(ring[i] - a, e) / along : t0}) {
          if (t > t0 && t < t1) events.push_back(t);
        }
      }
    };
    add_ring(occluders_[o].outer);
    for (const Ring& hole : occluders_[o].holes) add_ring(hole);
  }
  std::sort(events.begin(), events.end());
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    const double lo = std::max(events[i], t0), hi = std::min(events[i + 1], t1);
    if (hi - lo <= kParameterEpsilon) continue;
    if (sight_clear(wedge.apex, a + d * ((lo + hi) / 2), near)) return true;
  }
  return false;
}

bool OrientedSearch::sight_clear(Vec2 from, Vec2 to, const std::vector<std::size_t>& near) const {
  const Bounds3 sight = segment_bounds(from, to);
  for (const std::size_t o : near) {
    if (detail::meets(occluder_grid_.box(o), sight) && crosses_interior(occluders_[o], from, to)) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<bool> is_oriented_to(std::span<const OrientedFace> faces,
                                 std::span<const StreetSegment> streets,
                                 std::span<const Polygon> occluders, double tolerance,
                                 double max_distance, const SkipPredicate& skip) {
  std::vector<bool> result(faces.size(), false);
  if (!(max_distance >= 0) || std::isnan(tolerance)) return result;
  const double radians = std::clamp(tolerance, 0.0, 90.0) * std::numbers::pi / 180;
  OrientedSearch search(streets, occluders, skip);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 n = faces[f].normal;
    const double horizontal = std::hypot(n.x, n.y);
    // Normals within 45 degrees of vertical (roofs, floors) never are (45 itself included).
    if (horizontal <= std::abs(n.z) || horizontal == 0) continue;
    const Vec2 axis{n.x / horizontal, n.y / horizontal};
    const Wedge wedge{faces[f].base, axis, rotated(axis, radians), rotated(axis, -radians),
                      max_distance};
    result[f] = search.oriented(f, wedge);
  }
  return result;
}

}  // namespace insula::kernel
