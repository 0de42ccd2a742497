// Validation of a wall and its openings (wall.h, wall_detail.h): the outline must be a simple
// polygon with usable thickness and margin, and each opening, in input order, have usable
// parameters and stand clear of the outline and of the openings accepted before it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "kernel/planar.h"
#include "kernel/polygon.h"
#include "kernel/wall.h"
#include "kernel/wall_detail.h"

namespace insula::kernel {
namespace wall_detail {
namespace {

constexpr int kMaxArchSegments = 1024;

// ---------------------------------------------------------------------------------------------
// Small planar predicates.

// The gap between the bounding boxes of segments ab and cd along the axis where it is largest
// (negative when the boxes overlap): a lower bound of the segments' distance, for skipping far
// pairs cheaply. Callers compare it with a positive tolerance.
inline double box_gap(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double gap_x =
      std::max(std::min(c.x, d.x) - std::max(a.x, b.x), std::min(a.x, b.x) - std::max(c.x, d.x));
  const double gap_y =
      std::max(std::min(c.y, d.y) - std::max(a.y, b.y), std::min(a.y, b.y) - std::max(c.y, d.y));
  return std::max(gap_x, gap_y);
}

// Squared distance between segments ab and cd that do not cross: the least of the endpoint-to-
// segment distances.
double squared_endpoint_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return std::min(
      std::min(squared_distance_to_segment(a, c, d), squared_distance_to_segment(b, c, d)),
      std::min(squared_distance_to_segment(c, a, b), squared_distance_to_segment(d, a, b)));
}

// Squared distance between segments ab and cd (0 when they cross). Squared so that the hot
// validation loops take no root per pair; callers compare with squared tolerances or take one
// root of the minimum.
double squared_segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_cross_properly(a, b, c, d)) return 0;
  return squared_endpoint_distance(a, b, c, d);
}

// Point p lies within `tolerance` of segment ab. Most outline vertices are far from the edges
// they are tested against along one axis already; that test is a few comparisons.
bool point_within(Vec2 p, Vec2 a, Vec2 b, double tolerance) {
  if (std::min(a.x, b.x) - p.x > tolerance || p.x - std::max(a.x, b.x) > tolerance ||
      std::min(a.y, b.y) - p.y > tolerance || p.y - std::max(a.y, b.y) > tolerance) {
    return false;
  }
  return squared_distance_to_segment(p, a, b) <= tolerance * tolerance;
}

// Segments ab and cd come within `tolerance` of each other.
bool segments_within(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double tolerance) {
  if (box_gap(a, b, c, d) > tolerance) return false;
  return squared_segment_distance(a, b, c, d) <= tolerance * tolerance;
}

// Crossing-number test; meaningful for points farther than kEps from the boundary.
bool inside_ring(const Ring& ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

double ring_distance(const Ring& ring, Vec2 p) {
  double d = 1e300;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    d = std::min(d, distance_to_segment(p, ring[i], ring[(i + 1) % ring.size()]));
  }
  return d;
}

// Strictly inside a convex clockwise ring (by more than kEps).
bool inside_convex_cw(const Ring& ring, Vec2 p) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i];
    const Vec2 e = ring[(i + 1) % ring.size()] - a;
    const double side = cross(e, p - a);
    if (side > 0 || side > -kEps * length(e)) return false;  // the root only near the edge
  }
  return true;
}

// Separating axis test for convex rings: interiors overlap by more than kEps on every edge normal.
bool convex_interiors_overlap(const Ring& a, const Ring& b) {
  for (const Ring* r : {&a, &b}) {
    for (std::size_t i = 0; i < r->size(); ++i) {
      const Vec2 axis = normalized(perp((*r)[(i + 1) % r->size()] - (*r)[i]));
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (Vec2 p : a) amin = std::min(amin, dot(p, axis)), amax = std::max(amax, dot(p, axis));
      for (Vec2 p : b) bmin = std::min(bmin, dot(p, axis)), bmax = std::max(bmax, dot(p, axis));
      if (amax <= bmin + kEps || bmax <= amin + kEps) return false;
    }
  }
  return true;
}

std::string meters(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

bool finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// ---------------------------------------------------------------------------------------------
// Outline validation. `ccw` is the outline turned counter-clockwise.

// Four vertices forming a rectangle with sides parallel to the axes, each longer than kEps.
bool axis_rectangle(const Ring& r) {
  if (r.size() != 4) return false;
  const bool x_first = r[0].y == r[1].y && r[1].x == r[2].x && r[2].y == r[3].y && r[3].x == r[0].x;
  const bool y_first = r[0].x == r[1].x && r[1].y == r[2].y && r[2].x == r[3].x && r[3].y == r[0].y;
  if (!x_first && !y_first) return false;
  const double along_x = std::abs(x_first ? r[1].x - r[0].x : r[2].x - r[1].x);
  const double along_y = std::abs(x_first ? r[2].y - r[1].y : r[1].y - r[0].y);
  return along_x > kEps && along_y > kEps;
}

// `area` is signed_area(ring), computed once by the caller (who also orients the ring by it).
std::string outline_problem(const Ring& ring, double area) {
  const std::size_t n = ring.size();
  if (n < 3) return "wall outline needs at least 3 vertices";
  for (Vec2 p : ring) {
    if (!finite(p)) return "wall outline has a non-finite coordinate";
  }
  if (axis_rectangle(ring)) {
    // Sides longer than kEps: no repeated vertex, no adjacent edges folding back, opposite edges a
    // side length apart. Only the area is left to test (the common case: place_wall's outline).
    return std::abs(2 * area) <= kEps ? "wall outline has zero area" : std::string{};
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 step = ring[i] - ring[(i + n - 1) % n];
    if (dot(step, step) <= kEps * kEps) {
      return "wall outline vertex " + std::to_string(i) + " repeats the previous vertex";
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    // Adjacent edges may only meet at their shared vertex: no spike folding back.
    if (n > 3 && (point_within(c, a, b, kEps) || point_within(a, b, c, kEps)))
      return "wall outline edges " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
             " overlap";
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_within(a, b, ring[j], ring[(j + 1) % n], kEps)) {
        return "wall outline edges " + std::to_string(i) + " and " + std::to_string(j) +
               " touch or cross";
      }
    }
  }
  if (std::abs(2 * area) <= kEps) return "wall outline has zero area";
  return {};
}

// ---------------------------------------------------------------------------------------------
// Opening geometry.

// Appends the arch points strictly between the springing points, left to right.
void append_arch(const Opening& o, Ring& ring) {
  const double half = o.width / 2;
  const double rise = std::min(o.arch_rise, half);
  // Circle through both springing points and the apex: R = (half^2 + rise^2) / (2 rise).
  const double radius = (half * half + rise * rise) / (2 * rise);
  const double spring = o.sill + o.height - rise;
  const Vec2 center{o.u + half, spring + rise - radius};
  const double theta0 = std::atan2(radius - rise, half);  // angle of the right springing point
  const double sweep = std::numbers::pi - 2 * theta0;
  for (int k = 1; k < o.arch_segments; ++k) {
    const double theta = std::numbers::pi - theta0 - sweep * k / o.arch_segments;
    ring.push_back(center + Vec2{std::cos(theta), std::sin(theta)} * radius);
  }
}

// The opening's ring (see opening_ring) written into `ring`, whose storage is reused.
void fill_ring(const Opening& o, Ring& ring) {
  const double u1 = o.u + o.width;
  const double top = o.sill + o.height - (o.arch_rise > 0 ? o.arch_rise : 0);
  ring.assign({{o.u, o.sill}, {o.u, top}});
  if (o.arch_rise > 0) append_arch(o, ring);
  ring.push_back({u1, top});
  ring.push_back({u1, o.sill});
}

Ring make_ring(const Opening& o) {
  Ring ring;
  fill_ring(o, ring);
  return ring;
}

// ---------------------------------------------------------------------------------------------
// Opening validation.

// The bottom outline edge (running +u at the sill's height) that contains the opening's width.
int find_host(const Ring& outline, const Opening& o) {
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    if (std::abs(a.y - b.y) <= kEps && b.x > a.x && std::abs(o.sill - a.y) <= kEps &&
        a.x < o.u - kEps && o.u + o.width < b.x - kEps) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

struct Finding {
  OpeningProblem problem;
  double distance = 0;
};

// Distance-based verdict shared by the outline and the opening-opening checks.
std::optional<OpeningProblem> closeness(double distance, double margin, OpeningProblem touches,
                                        OpeningProblem near) {
  if (distance <= kEps) return touches;
  if (distance < margin) return near;
  return std::nullopt;
}

std::optional<Finding> against_outline(const Ring& outline, const Accepted& c, double margin) {
  const std::size_t n = outline.size();
  const std::size_t m = c.ring.size();
  // A notch's sill edge (last) and its two bottom corners lie on the host edge by construction.
  const std::size_t edges = c.host >= 0 ? m - 1 : m;
  for (Vec2 p : outline) {
    if (inside_convex_cw(c.ring, p)) return Finding{OpeningProblem::kOutsideOutline};
  }
  // Edge pairs whose boxes lie farther apart than `reach` can neither cross nor decide the verdict
  // (closeness() looks at distances up to kEps and the margin): they are skipped.
  const double reach = std::max(margin, kEps);
  for (std::size_t i = 0; i < edges; ++i) {
    // A notch's first corner sits on the host edge; its last corner ends edge `edges - 1`.
    const Vec2 a = c.ring[i];
    if (c.host >= 0 && i == 0) continue;
    if (!inside_ring(outline, a) && ring_distance(outline, a) > kEps) {
      return Finding{OpeningProblem::kOutsideOutline};
    }
  }
  double squared = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n; ++j) {
    if (static_cast<int>(j) == c.host) continue;
    const Vec2 p = outline[j], q = outline[(j + 1) % n];
    // The opening's box holds every edge's box: an outline edge beyond `reach` of it is beyond
    // `reach` of each opening edge, and all of them would be skipped below.
    if (box_gap(c.box.min, c.box.max, p, q) > reach) continue;
    for (std::size_t i = 0; i < edges; ++i) {
      const Vec2 a = c.ring[i], b = c.ring[(i + 1) % m];
      if (box_gap(a, b, p, q) > reach) continue;
      if (segments_cross_properly(a, b, p, q)) return Finding{OpeningProblem::kOutsideOutline};
      squared = std::min(squared, squared_endpoint_distance(a, b, p, q));
    }
  }
  const double distance = std::sqrt(squared);
  const auto verdict =
      closeness(distance, margin, OpeningProblem::kTouchesOutline, OpeningProblem::kNearOutline);
  if (!verdict) return std::nullopt;
  return Finding{*verdict, distance};
}

std::optional<Finding> against_opening(const Accepted& c, const Accepted& d, double margin) {
  if (!touches(c.box, d.box, margin + kEps)) return std::nullopt;
  if (convex_interiors_overlap(c.ring, d.ring)) return Finding{OpeningProblem::kOverlapsOpening};
  const double reach = std::max(margin, kEps);  // farther pairs cannot decide (as above)
  double squared = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c.ring.size(); ++i) {
    const Vec2 a = c.ring[i], b = c.ring[(i + 1) % c.ring.size()];
    for (std::size_t j = 0; j < d.ring.size(); ++j) {
      const Vec2 p = d.ring[j], q = d.ring[(j + 1) % d.ring.size()];
      if (box_gap(a, b, p, q) > reach) continue;
      squared = std::min(squared, squared_segment_distance(a, b, p, q));
    }
  }
  const double distance = std::sqrt(squared);
  const auto verdict =
      closeness(distance, margin, OpeningProblem::kTouchesOpening, OpeningProblem::kNearOpening);
  if (!verdict) return std::nullopt;
  return Finding{*verdict, distance};
}

std::string describe(std::size_t index, const Finding& f, std::optional<std::size_t> other,
                     double margin) {
  const std::string self = "opening " + std::to_string(index);
  const std::string them = other ? "opening " + std::to_string(*other) : "the wall outline";
  switch (f.problem) {
    case OpeningProblem::kOutsideOutline:
      return self + " extends outside the wall outline";
    case OpeningProblem::kOverlapsOpening:
      return self + " overlaps " + them;
    case OpeningProblem::kTouchesOutline:
    case OpeningProblem::kTouchesOpening:
      return self + " touches " + them;
    case OpeningProblem::kNearOutline:
    case OpeningProblem::kNearOpening:
      return self + " is " + meters(f.distance) + " m from " + them + ", less than the margin " +
             meters(margin) + " m";
    case OpeningProblem::kBadParameters:
      break;
  }
  return self;
}

}  // namespace

std::string parameter_problem(const Opening& o) {
  if (!std::isfinite(o.u) || !std::isfinite(o.sill) || !std::isfinite(o.width) ||
      !std::isfinite(o.height) || !std::isfinite(o.arch_rise)) {
    return "position and size must be finite";
  }
  if (o.width <= kEps || o.height <= kEps) return "width and height must be positive";
  if (o.arch_rise < 0 || o.arch_rise > o.width / 2 * (1 + 1e-12) || o.arch_rise >= o.height - kEps)
    return "arch rise must be in [0, width / 2] and below the height";
  if (o.arch_rise > 0 && (o.arch_segments < 1 || o.arch_segments > kMaxArchSegments))
    return "arch segments must be in [1, 1024]";
  return {};
}

std::string wall_problem(const WallSpec& spec, double outline_area) {
  if (!std::isfinite(spec.thickness) || spec.thickness <= 0)
    return "wall thickness must be positive and finite";
  if (!std::isfinite(spec.min_margin) || spec.min_margin < 0)
    return "minimum margin must be non-negative and finite";
  return outline_problem(spec.outline, outline_area);
}

const Ring& counter_clockwise(const Ring& ring, double area, Ring& scratch) {
  if (area >= 0) return ring;
  scratch.assign(ring.rbegin(), ring.rend());
  return scratch;
}

std::vector<OpeningIssue> validate(const Ring& outline, const WallSpec& spec,
                                   std::vector<Accepted>& accepted, std::vector<Ring>* spare) {
  std::vector<OpeningIssue> issues;
  if (spec.openings.empty()) return issues;  // most walls: nothing to validate
  const double margin = spec.min_margin;
  for (std::size_t i = 0; i < spec.openings.size(); ++i) {
    Accepted c;
    c.index = i;
    c.opening = spec.openings[i];
    if (std::string why = parameter_problem(c.opening); !why.empty()) {
      issues.push_back({i, OpeningProblem::kBadParameters, std::nullopt,
                        "opening " + std::to_string(i) + ": " + why});
      continue;
    }
    c.host = find_host(outline, c.opening);
    if (c.host >= 0) c.opening.sill = outline[static_cast<std::size_t>(c.host)].y;
    if (spare != nullptr && !spare->empty()) {
      c.ring = std::move(spare->back());
      spare->pop_back();
    }
    fill_ring(c.opening, c.ring);
    c.box = bounds(c.ring);
    std::optional<Finding> finding = against_outline(outline, c, margin);
    std::optional<std::size_t> other;
    for (std::size_t k = 0; !finding && k < accepted.size(); ++k) {
      finding = against_opening(c, accepted[k], margin);
      if (finding) other = accepted[k].index;
    }
    if (finding) {
      issues.push_back({i, finding->problem, other, describe(i, *finding, other, margin)});
    } else {
      accepted.push_back(std::move(c));
    }
  }
  return issues;
}

}  // namespace wall_detail

Ring opening_ring(const Opening& opening) {
  if (!wall_detail::parameter_problem(opening).empty()) return {};
  return wall_detail::make_ring(opening);
}

double opening_area(const Opening& opening) {
  const Ring ring = opening_ring(opening);
  return ring.empty() ? 0 : std::abs(signed_area(ring));
}

std::vector<OpeningIssue> check_openings(const WallSpec& spec, std::vector<std::size_t>* accepted) {
  if (accepted) accepted->clear();
  const double area = signed_area(spec.outline);
  if (!wall_detail::wall_problem(spec, area).empty()) return {};
  std::vector<wall_detail::Accepted> cut;
  Ring scratch;
  const Ring& outline = wall_detail::counter_clockwise(spec.outline, area, scratch);
  std::vector<OpeningIssue> issues = wall_detail::validate(outline, spec, cut);
  if (accepted) {
    for (const wall_detail::Accepted& c : cut) accepted->push_back(c.index);
  }
  return issues;
}

}  // namespace insula::kernel
