// Walls with openings (wall.h, docs/kernel-walls.md). Stages: validate the outline and the
// openings, build the boundary rings (outline with door notches spliced in, one clockwise ring per
// hole), cut the region into u-monotone pieces with diagonals between existing vertices
// (MakeMonotone, de Berg et al., "Computational Geometry", 3rd ed., section 3.2), then emit front
// and back pieces and one side quad per boundary edge. Because every piece boundary and every quad
// use only ring vertices, the mesh has no T-junctions and is closed on shared indices.
#include "kernel/wall.h"

#include "kernel/polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <utility>

namespace insula::kernel {
namespace {

// Absolute tolerance in meters: distances at or below it count as touching.
constexpr double kEps = 1e-9;
constexpr int kMaxArchSegments = 1024;

// ---------------------------------------------------------------------------------------------
// Small planar predicates.

struct Box {
  Vec2 min{1e300, 1e300};
  Vec2 max{-1e300, -1e300};
  void add(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  bool overlaps(const Box& o, double pad) const {
    return min.x <= o.max.x + pad && o.min.x <= max.x + pad && min.y <= o.max.y + pad &&
           o.min.y <= max.y + pad;
  }
};

Box ring_box(const Ring& ring) {
  Box b;
  for (Vec2 p : ring) b.add(p);
  return b;
}

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

// inside_ring for an axis-parallel rectangle with bounding box `b`: the crossing test meets only
// its two vertical sides, each when b.min.y <= p.y < b.max.y, at x = b.min.x and x = b.max.x
// exactly (the interpolation adds a zero), so p is inside when also b.min.x <= p.x < b.max.x.
// The same verdicts without the loop (every placed wall's outline is such a rectangle).
bool inside_rectangle(const Box& b, Vec2 p) {
  return b.min.y <= p.y && p.y < b.max.y && b.min.x <= p.x && p.x < b.max.x;
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

struct Accepted {
  std::size_t index = 0;
  Opening opening;  // with the sill snapped onto the host edge for notches
  Ring ring;        // clockwise; for a notch the last edge (the sill) lies on the host edge
  Box box;
  int host = -1;  // outline edge a notch opens through, or -1 for a hole
};

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

// `rectangle` is the outline's box when the outline is an axis-parallel rectangle, else null.
std::optional<Finding> against_outline(const Ring& outline, const Box* rectangle, const Accepted& c,
                                       double margin) {
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
    const bool inside = rectangle ? inside_rectangle(*rectangle, a) : inside_ring(outline, a);
    if (!inside && ring_distance(outline, a) > kEps) {
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
  if (!c.box.overlaps(d.box, margin + kEps)) return std::nullopt;
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

// Greedy validation in input order against the outline and the earlier accepted openings.
// `spare` (optional) holds rings of an earlier wall whose storage the accepted openings take over.
std::vector<OpeningIssue> validate(const Ring& outline, const WallSpec& spec,
                                   std::vector<Accepted>& accepted,
                                   std::vector<Ring>* spare = nullptr) {
  std::vector<OpeningIssue> issues;
  if (spec.openings.empty()) return issues;  // most walls: nothing to validate
  const double margin = spec.min_margin;
  const Box outline_box = ring_box(outline);
  const Box* rectangle = axis_rectangle(outline) ? &outline_box : nullptr;
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
    c.box = ring_box(c.ring);
    std::optional<Finding> finding = against_outline(outline, rectangle, c, margin);
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

// ---------------------------------------------------------------------------------------------
// Boundary rings: every vertex starts one directed edge with the wall's material on its left.

// emit_into indexes its tag table by this order (top, bottom, end, jamb, sill, lintel).
enum class EdgeKind : std::uint8_t { kTop, kBottom, kEnd, kJamb, kSill, kLintel };

struct Boundary {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> prev;
  std::vector<EdgeKind> kind;         // of the edge leaving each vertex
  std::vector<std::int32_t> opening;  // opening of that edge, or -1 for the rim
  std::uint32_t ring_start = 0;

  // Empties every array, keeping its storage for the next wall (WallWorkspace).
  void clear() {
    points.clear();
    next.clear();
    prev.clear();
    kind.clear();
    opening.clear();
    ring_start = 0;
  }

  void add(Vec2 p, EdgeKind k, std::int32_t o) {
    points.push_back(p);
    kind.push_back(k);
    opening.push_back(o);
  }
  // Links the vertices added since the last close() into a ring.
  void close() {
    const auto n = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t i = ring_start; i < n; ++i) {
      next.push_back(i + 1 < n ? i + 1 : ring_start);
      prev.push_back(i > ring_start ? i - 1 : n - 1);
    }
    ring_start = n;
  }
};

EdgeKind rim_kind(Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  // The outward normal of a counter-clockwise edge is (d.y, -d.x) / |d|. Axis-parallel edges
  // (every edge of a rectangular wall) are settled without the root: |d| = |d.x| when d.y = 0.
  if (d.x == 0) return EdgeKind::kEnd;
  if (d.y != 0 && std::abs(d.x) <= 1e-9 * length(d)) return EdgeKind::kEnd;
  return d.x < 0 ? EdgeKind::kTop : EdgeKind::kBottom;
}

// Adds an opening's ring as edges: left jamb, lintel pieces, right jamb, then the sill (holes
// only).
void add_opening_edges(Boundary& out, const Accepted& c, bool notch) {
  const auto o = static_cast<std::int32_t>(c.index);
  const std::size_t m = c.ring.size();
  for (std::size_t i = 0; i < m; ++i) {
    EdgeKind k = EdgeKind::kLintel;
    if (i == 0 || i == m - 2) k = EdgeKind::kJamb;
    if (i == m - 1) {
      if (notch) break;  // the sill corner continues along the host edge
      k = EdgeKind::kSill;
    }
    out.add(c.ring[i], k, o);
  }
}

// `notches` is scratch storage (its contents are replaced).
void build_boundary(const Ring& outline, const std::vector<Accepted>& cut, Boundary& out,
                    std::vector<const Accepted*>& notches) {
  notches.clear();
  for (const Accepted& c : cut) {
    if (c.host >= 0) notches.push_back(&c);
  }
  std::sort(notches.begin(), notches.end(), [](const Accepted* a, const Accepted* b) {
    return a->host != b->host ? a->host < b->host : a->opening.u < b->opening.u;
  });
  std::size_t k = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const EdgeKind rim = rim_kind(outline[i], outline[(i + 1) % outline.size()]);
    out.add(outline[i], rim, -1);
    for (; k < notches.size() && notches[k]->host == static_cast<int>(i); ++k) {
      add_opening_edges(out, *notches[k], true);
      out.add(notches[k]->ring.back(), rim, -1);
    }
  }
  out.close();
  for (const Accepted& c : cut) {
    if (c.host >= 0) continue;
    add_opening_edges(out, c, false);
    out.close();
  }
}

// ---------------------------------------------------------------------------------------------
// Monotone partition (de Berg section 3.2). The book sweeps top to bottom; we sweep along +u by
// working in the rotated frame x = v, y = -u (a rotation, so orientation and "interior on the
// left" are preserved). Ties are broken as in the book: equal y, smaller x comes first.

enum class VertexType : std::uint8_t { kStart, kSplit, kEnd, kMerge, kRegular };

class MonotonePartition {
 public:
  // Diagonals (vertex pairs) splitting the region of `b` into y-monotone pieces; false on a guard
  // failure. The sweep's arrays keep their storage from one call to the next (WallWorkspace).
  bool run(const Boundary& b, std::vector<std::array<std::uint32_t, 2>>& diagonals) {
    b_ = &b;
    const std::size_t n = b.points.size();
    q_.resize(n);
    for (std::size_t i = 0; i < n; ++i) q_[i] = {b.points[i].y, -b.points[i].x};
    type_.resize(n);
    bool split_or_merge = false;
    for (std::uint32_t i = 0; i < n; ++i) {
      type_[i] = classify(i);
      split_or_merge |= type_[i] == VertexType::kSplit || type_[i] == VertexType::kMerge;
    }
    // Without split or merge vertices the region is monotone already (de Berg, Lemma 3.4) and the
    // sweep would add no diagonal (it adds them only at split vertices and at merge helpers): a
    // plain wall skips the sort and the sweep. (A door notch can still make a merge vertex through
    // the equal-y tie-break, so walls with doors usually do sweep.)
    if (!split_or_merge) return true;
    status_.clear();
    // Vertices from the top down: sorted with their coordinates at hand (the comparison below(c, a)
    // on copies; the same comparisons on the same sequence, so the same order).
    order_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) order_[i] = {q_[i], i};
    std::sort(order_.begin(), order_.end(), [](const Ordered& a, const Ordered& c) {
      return c.q.y < a.q.y || (c.q.y == a.q.y && c.q.x > a.q.x);
    });
    helper_.assign(n, 0);
    for (const Ordered& o : order_) {
      if (!handle(o.vertex, diagonals)) return false;
    }
    return true;
  }

 private:
  bool below(std::uint32_t a, std::uint32_t c) const {
    return q_[a].y < q_[c].y || (q_[a].y == q_[c].y && q_[a].x > q_[c].x);
  }

  VertexType classify(std::uint32_t v) const {
    const std::uint32_t p = b_->prev[v], n = b_->next[v];
    const bool convex = cross(q_[v] - q_[p], q_[n] - q_[v]) > 0;
    const bool p_below = below(p, v), n_below = below(n, v);
    if (p_below && n_below) return convex ? VertexType::kStart : VertexType::kSplit;
    if (!p_below && !n_below) return convex ? VertexType::kEnd : VertexType::kMerge;
    return VertexType::kRegular;
  }

  // x of edge e (from e to next(e), going down) at height y.
  double x_at(std::uint32_t e, double y) const {
    const Vec2 a = q_[e], c = q_[b_->next[e]];
    if (a.y == c.y) return std::max(a.x, c.x);
    return a.x + (c.x - a.x) * (y - a.y) / (c.y - a.y);
  }

  // The status edge directly left of v, or -1.
  std::int64_t left_of(std::uint32_t v) const {
    std::int64_t best = -1;
    double best_x = -1e300;
    for (std::uint32_t e : status_) {
      const double x = x_at(e, q_[v].y);
      if (x < q_[v].x && x > best_x) best = e, best_x = x;
    }
    return best;
  }

  void erase(std::uint32_t e) {
    auto it = std::find(status_.begin(), status_.end(), e);
    if (it != status_.end()) {
      *it = status_.back();
      status_.pop_back();
    }
  }

  // Connects v to the helper of e if that helper is a merge vertex.
  void fix_up(std::uint32_t v, std::uint32_t e, std::vector<std::array<std::uint32_t, 2>>& d) {
    if (type_[helper_[e]] == VertexType::kMerge) d.push_back({v, helper_[e]});
  }

  bool handle(std::uint32_t v, std::vector<std::array<std::uint32_t, 2>>& d) {
    const std::uint32_t in = b_->prev[v];  // e_{i-1}
    switch (type_[v]) {
      case VertexType::kStart:
        status_.push_back(v);
        helper_[v] = v;
        return true;
      case VertexType::kEnd:
        fix_up(v, in, d);
        erase(in);
        return true;
      case VertexType::kSplit: {
        const std::int64_t e = left_of(v);
        if (e < 0) return false;
        d.push_back({v, helper_[static_cast<std::uint32_t>(e)]});
        helper_[static_cast<std::uint32_t>(e)] = v;
        status_.push_back(v);
        helper_[v] = v;
        return true;
      }
      case VertexType::kMerge: {
        fix_up(v, in, d);
        erase(in);
        return connect_left(v, d);
      }
      case VertexType::kRegular:
        if (below(v, in)) {  // interior to the right: the chain runs downward
          fix_up(v, in, d);
          erase(in);
          status_.push_back(v);
          helper_[v] = v;
          return true;
        }
        return connect_left(v, d);
    }
    return false;
  }

  bool connect_left(std::uint32_t v, std::vector<std::array<std::uint32_t, 2>>& d) {
    const std::int64_t e = left_of(v);
    if (e < 0) return false;
    fix_up(v, static_cast<std::uint32_t>(e), d);
    helper_[static_cast<std::uint32_t>(e)] = v;
    return true;
  }

  struct Ordered {
    Vec2 q;  // q_[vertex]
    std::uint32_t vertex;
  };

  const Boundary* b_ = nullptr;
  std::vector<Vec2> q_;
  std::vector<Ordered> order_;
  std::vector<VertexType> type_;
  std::vector<std::uint32_t> helper_;
  std::vector<std::uint32_t> status_;
};

// ---------------------------------------------------------------------------------------------
// Faces of the subdivision: walk half-edges keeping the face on the left. At a vertex with
// diagonals the next half-edge is the first one clockwise from the way back.

class PieceWalker {
 public:
  // Appends each piece of `b` cut by `diagonals` as a vertex loop (offsets into `loops`); false if
  // a walk does not close into a simple loop. The arrays keep their storage between calls.
  bool run(const Boundary& b, const std::vector<std::array<std::uint32_t, 2>>& diagonals,
           std::vector<std::uint32_t>& loops, std::vector<std::uint32_t>& offsets) {
    b_ = &b;
    if (diagonals.empty()) {
      rings_as_pieces(loops, offsets);
      return true;
    }
    link(diagonals);
    std::vector<std::uint32_t>& stamp = fill_;  // free once the half-edges are linked
    stamp.assign(b.points.size(), 0);
    std::uint32_t piece = 0;
    const std::size_t half_edges = to_.size();  // read once: the loop's stores may alias it
    for (std::uint32_t h = 0; h < half_edges; ++h) {
      if (used_[h]) continue;
      ++piece;
      std::uint32_t cur = h;
      std::uint32_t from = from_of(h);
      for (std::size_t steps = 0;; ++steps) {
        if (steps > half_edges || stamp[from] == piece) return false;
        stamp[from] = piece;
        used_[cur] = 1;
        loops.push_back(from);
        const std::uint32_t at = to_[cur];
        cur = next_half_edge(from, at);
        from = at;
        if (cur == h) break;
        if (used_[cur]) return false;
      }
      offsets.push_back(static_cast<std::uint32_t>(loops.size()));
    }
    return true;
  }

 private:
  // Without diagonals every ring is a piece, listed from its first vertex along `next`: what the
  // walk below yields then, without linking half-edges.
  void rings_as_pieces(std::vector<std::uint32_t>& loops, std::vector<std::uint32_t>& offsets) {
    const auto n = static_cast<std::uint32_t>(b_->points.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      loops.push_back(i);
      if (b_->next[i] != i + 1) offsets.push_back(static_cast<std::uint32_t>(loops.size()));
    }
  }

  // Outgoing half-edges per vertex: its boundary edge, then its diagonals.
  void link(const std::vector<std::array<std::uint32_t, 2>>& diagonals) {
    const std::size_t n = b_->points.size();
    start_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] = 1;
    for (const auto& d : diagonals) ++start_[d[0] + 1], ++start_[d[1] + 1];
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
    to_.resize(start_[n]);
    used_.assign(start_[n], 0);
    fill_.assign(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) to_[fill_[i]++] = b_->next[i];
    for (const auto& d : diagonals) to_[fill_[d[0]]++] = d[1], to_[fill_[d[1]]++] = d[0];
  }

  std::uint32_t from_of(std::uint32_t h) const {
    return static_cast<std::uint32_t>(std::upper_bound(start_.begin(), start_.end(), h) -
                                      start_.begin() - 1);
  }

  std::uint32_t next_half_edge(std::uint32_t from, std::uint32_t at) const {
    const std::uint32_t first = start_[at], last = start_[at + 1];
    if (last - first == 1) return first;
    const Vec2 back = b_->points[from] - b_->points[at];
    // The least clockwise angle from `back` in (0, 2 pi], compared without computing angles: first
    // by half-turn (0 for (0, pi], 1 for (pi, 2 pi]), then within a half-turn by orientation.
    const auto half_turn = [back](Vec2 d) {
      const double c = cross(d, back);
      return c > 0 || (c == 0 && dot(d, back) < 0) ? 0 : 1;
    };
    std::uint32_t best = first;
    Vec2 best_d = b_->points[to_[first]] - b_->points[at];
    int best_half = half_turn(best_d);
    for (std::uint32_t h = first + 1; h < last; ++h) {
      const Vec2 d = b_->points[to_[h]] - b_->points[at];
      const int half = half_turn(d);
      if (half < best_half || (half == best_half && cross(d, best_d) < 0)) {
        best = h, best_d = d, best_half = half;
      }
    }
    return best;
  }

  const Boundary* b_ = nullptr;
  std::vector<std::uint32_t> start_;  // outgoing half-edges of vertex v: [start_[v], start_[v+1])
  std::vector<std::uint32_t> to_;
  std::vector<std::uint8_t> used_;
  std::vector<std::uint32_t> fill_;  // next free slot per vertex while linking; then walk stamps
};

// ---------------------------------------------------------------------------------------------
// The plain wall: an outline (x0, y0), (x1, y0), (x1, y1), (x0, y1) (counter-clockwise from the
// lower-left corner, as place_wall and the bldg builder make it) with rectangular openings that
// stand clear of the outline and whose u-ranges lie side by side, each beyond the margin of the
// next. Most walls of a building are such. For them the general stages have a known outcome,
// produced here directly (the same boundary, the same loops in the same order):
//  - validation accepts every opening (a gap beyond the margin, with slack for the rounding of the
//    general path's distances; boxes apart along u fail Box::overlaps exactly as there), so `cut`
//    is every opening in input order and opening i is boundary ring i + 1 (vertices 4 + 4i ..);
//  - the sweep (de Berg section 3.2, along +u) meets vertices 0 (start) and 3, then opening after
//    opening by u, each with its lower-left corner a as a split vertex (diagonal to the helper of
//    the bottom edge: vertex 3 for the first opening, the previous opening's upper-right corner c
//    after that) and c as a merge vertex, then vertex 1 (diagonal to the last c);
//  - the walk from half-edge 0 then closes piece 1 = 0, 1, then c, d, a of each opening from the
//    last to the first, then 3, and piece 2 = 1, 2, 3, then a, b, c of each opening from the first.
// A wall that differs in any way takes the general path; tests/kernel/wall_plain_test.cc builds
// random walls both ways (WallWorkspace::set_plain_shortcut) and compares them.

struct PlainOpening {
  double u0;
  double u1;
  std::uint32_t index;  // into WallSpec::openings
};

// The openings of a plain wall in `sorted`, ordered by u; false when the wall is not plain.
// `ccw` is the validated outline, counter-clockwise.
bool plain_wall(const Ring& ccw, const WallSpec& spec, std::vector<PlainOpening>& sorted) {
  sorted.clear();
  if (ccw.size() != 4) return false;
  const double x0 = ccw[0].x, y0 = ccw[0].y, x1 = ccw[2].x, y1 = ccw[2].y;
  if (!(ccw[1].x == x1 && ccw[1].y == y0 && ccw[3].x == x0 && ccw[3].y == y1 && x0 < x1 &&
        y0 < y1)) {
    return false;
  }
  // The general path's distances err by a few units in the last place of the coordinates; a gap
  // this much beyond `reach` is beyond the margin (and kEps) there too.
  const double reach = std::max(spec.min_margin, kEps);
  const double scale = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
  const double clear = reach + 1e-9 * (reach + scale);
  for (std::size_t i = 0; i < spec.openings.size(); ++i) {
    const Opening& o = spec.openings[i];
    if (o.arch_rise != 0 || !parameter_problem(o).empty()) return false;
    const double u1 = o.u + o.width;
    const double top = o.sill + o.height;  // fill_ring's top without an arch
    if (!(o.u - x0 > clear && x1 - u1 > clear && o.sill - y0 > clear && y1 - top > clear)) {
      return false;
    }
    sorted.push_back({o.u, u1, static_cast<std::uint32_t>(i)});
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const PlainOpening& a, const PlainOpening& b) { return a.u0 < b.u0; });
  // Box::overlaps' x test with against_opening's pad: false for neighbours, so for every pair.
  const double pad = spec.min_margin + kEps;
  for (std::size_t j = 1; j < sorted.size(); ++j) {
    if (!(sorted[j].u0 > sorted[j - 1].u1 + pad)) return false;
  }
  return true;
}

// build_boundary's rings for a plain wall: the outline's edges are bottom, end, top, end
// (rim_kind), each opening's left jamb, lintel, right jamb and sill (add_opening_edges). Written in
// place, every ring a run of four vertices; `prev` stays empty (only the sweep reads it).
void plain_boundary(const Ring& ccw, const WallSpec& spec, Boundary& b) {
  const std::size_t n = 4 + 4 * spec.openings.size();
  b.prev.clear();  // resized, not cleared: the arrays' old entries are overwritten, not zeroed
  b.points.resize(n);
  b.next.resize(n);
  b.kind.resize(n);
  b.opening.resize(n);
  b.ring_start = static_cast<std::uint32_t>(n);
  const auto ring = [&b](std::uint32_t first, std::array<Vec2, 4> corners,
                         std::array<EdgeKind, 4> kinds, std::int32_t opening) {
    for (std::uint32_t k = 0; k < 4; ++k) {
      b.points[first + k] = corners[k];
      b.next[first + k] = first + (k + 1) % 4;
      b.kind[first + k] = kinds[k];
      b.opening[first + k] = opening;
    }
  };
  ring(0, {ccw[0], ccw[1], ccw[2], ccw[3]},
       {EdgeKind::kBottom, EdgeKind::kEnd, EdgeKind::kTop, EdgeKind::kEnd}, -1);
  for (std::size_t i = 0; i < spec.openings.size(); ++i) {
    const Opening& o = spec.openings[i];
    const double u1 = o.u + o.width;
    const double top = o.sill + o.height;
    ring(static_cast<std::uint32_t>(4 + 4 * i),
         {Vec2{o.u, o.sill}, {o.u, top}, {u1, top}, {u1, o.sill}},
         {EdgeKind::kJamb, EdgeKind::kLintel, EdgeKind::kJamb, EdgeKind::kSill},
         static_cast<std::int32_t>(i));
  }
}

// The pieces' loops of a plain wall (see above), written in place: without openings one piece,
// the outline; else two pieces of 3 + 3k vertices for k openings.
void plain_loops(const std::vector<PlainOpening>& sorted, std::vector<std::uint32_t>& loops,
                 std::vector<std::uint32_t>& offsets) {
  if (sorted.empty()) {
    loops.assign({0, 1, 2, 3});
    offsets.assign({0, 4});
    return;
  }
  const auto piece = static_cast<std::uint32_t>(3 + 3 * sorted.size());
  loops.resize(2 * piece);
  offsets.assign({0, piece, 2 * piece});
  std::uint32_t* lower = loops.data();
  std::uint32_t* upper = lower + piece;
  *lower++ = 0, *lower++ = 1;
  *upper++ = 1, *upper++ = 2, *upper++ = 3;
  for (std::size_t j = 0; j < sorted.size(); ++j) {
    const std::uint32_t below = 4 + 4 * sorted[sorted.size() - 1 - j].index;  // right to left
    *lower++ = below + 2, *lower++ = below + 3, *lower++ = below;
    const std::uint32_t above = 4 + 4 * sorted[j].index;  // left to right
    *upper++ = above, *upper++ = above + 1, *upper++ = above + 2;
  }
  *lower = 3;
}

// ---------------------------------------------------------------------------------------------
// Mesh emission.

const FaceTag& tag_for(const WallFaceTags& tags, EdgeKind kind) {
  switch (kind) {
    case EdgeKind::kTop:
      return tags.top;
    case EdgeKind::kBottom:
      return tags.bottom;
    case EdgeKind::kEnd:
      return tags.end;
    case EdgeKind::kJamb:
      return tags.jamb;
    case EdgeKind::kSill:
      return tags.sill;
    case EdgeKind::kLintel:
      return tags.lintel;
  }
  return tags.end;
}

void emit(const Boundary& b, const std::vector<std::uint32_t>& loops,
          const std::vector<std::uint32_t>& offsets, const WallSpec& spec, const WallFrame& frame,
          WallResult& result) {
  const auto n = static_cast<std::uint32_t>(b.points.size());
  const std::size_t pieces = offsets.size() - 1;
  Mesh& mesh = result.mesh;
  mesh.reserve(2 * n, 2 * pieces + n, 2 * loops.size() + 4 * n);
  for (Vec2 p : b.points) mesh.add_vertex(frame.map(p.x, p.y, spec.thickness));
  for (Vec2 p : b.points) mesh.add_vertex(frame.map(p.x, p.y, 0));
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < pieces; ++f) {
    loop.assign(loops.begin() + offsets[f], loops.begin() + offsets[f + 1]);
    mesh.add_face(loop, spec.tags.front);
  }
  for (std::size_t f = 0; f < pieces; ++f) {
    loop.assign(loops.begin() + offsets[f], loops.begin() + offsets[f + 1]);
    std::reverse(loop.begin(), loop.end());
    for (std::uint32_t& v : loop) v += n;
    mesh.add_face(loop, spec.tags.back);
  }
  result.face_opening.assign(2 * pieces, -1);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = b.next[i];
    mesh.add_face({i, n + i, n + j, j}, tag_for(spec.tags, b.kind[i]));
    result.face_opening.push_back(b.opening[i]);
  }
  if (dot(cross(frame.u_axis, frame.v_axis), frame.normal) < 0) mesh.flip();
  result.front_pieces = pieces;
}

// Writes the wall's faces into `mesh` after whatever it already holds (vertex indices shifted by
// its vertex count). A left-handed frame gets every loop reversed as it is written, which is what
// Mesh::flip does afterwards to a wall built alone. The loops are written straight into the mesh's
// face slots (no loop vector per face, no size check per face).
void emit_into(const Boundary& b, const std::vector<std::uint32_t>& loops,
               const std::vector<std::uint32_t>& offsets, const WallSpec& spec,
               const WallFrame& frame, Mesh& mesh) {
  const auto n = static_cast<std::uint32_t>(b.points.size());
  const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
  const std::size_t pieces = offsets.size() - 1;
  const bool flip = dot(cross(frame.u_axis, frame.v_axis), frame.normal) < 0;
  // Front vertices, then back vertices: frame.map(u, v, thickness) and frame.map(u, v, 0), written
  // in one pass that evaluates their common part origin + u_axis u + v_axis v once (the same
  // sums in the same order as WallFrame::map, so the same bits).
  std::vector<Vec3>& positions = mesh.positions();
  positions.resize(base + 2 * std::size_t{n});
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 p = b.points[i];
    const Vec3 in_plane = frame.origin + frame.u_axis * p.x + frame.v_axis * p.y;
    positions[base + i] = in_plane + frame.normal * spec.thickness;
    positions[base + n + i] = in_plane + frame.normal * 0.0;
  }
  // Front pieces, back pieces (reversed, on the back vertices), then one quad per boundary edge.
  const Mesh::FaceSlots slots = mesh.add_face_slots(2 * pieces + n, 2 * loops.size() + 4 * n);
  std::uint32_t* out = slots.indices.data();
  std::size_t face = 0;
  const auto close_face = [&](const FaceTag& tag) {
    slots.ends[face] = slots.first_index + static_cast<std::uint32_t>(out - slots.indices.data());
    slots.tags[face++] = tag;
  };
  const auto write_pieces = [&](bool reversed, std::uint32_t shift, const FaceTag& tag) {
    for (std::size_t f = 0; f < pieces; ++f) {
      const std::uint32_t* first = loops.data() + offsets[f];
      const std::uint32_t* last = loops.data() + offsets[f + 1];
      if (reversed) {
        while (last != first) *out++ = *--last + shift;
      } else {
        while (first != last) *out++ = *first++ + shift;
      }
      close_face(tag);
    }
  };
  write_pieces(flip, base, spec.tags.front);
  write_pieces(!flip, base + n, spec.tags.back);
  // The side quads: (i, n + i, n + j, j) for the edge i -> j, its two ends swapped when flipped;
  // tags looked up by edge kind (tag_for's choice, in EdgeKind order).
  const std::array<const FaceTag*, 6> kind_tags{&spec.tags.top,  &spec.tags.bottom,
                                                &spec.tags.end,  &spec.tags.jamb,
                                                &spec.tags.sill, &spec.tags.lintel};
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = b.next[i];
    const std::uint32_t first = base + (flip ? j : i);
    const std::uint32_t second = base + (flip ? i : j);
    out[0] = first, out[1] = first + n, out[2] = second + n, out[3] = second;
    out += 4;
    close_face(*kind_tags[static_cast<std::size_t>(b.kind[i])]);
  }
}

std::string wall_problem(const WallSpec& spec, double outline_area) {
  if (!std::isfinite(spec.thickness) || spec.thickness <= 0)
    return "wall thickness must be positive and finite";
  if (!std::isfinite(spec.min_margin) || spec.min_margin < 0)
    return "minimum margin must be non-negative and finite";
  return outline_problem(spec.outline, outline_area);
}

// signed_area(ring), with four-vertex outlines (every placed wall's rectangle) summed in place:
// the same shoelace terms relative to the first vertex in the same order, so the same bits,
// without the moment terms signed_area's shared helper also accumulates.
double outline_signed_area(const Ring& ring) {
  if (ring.size() != 4) return signed_area(ring);
  double twice_area = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    twice_area += cross(ring[i] - ring[0], ring[(i + 1) % 4] - ring[0]);
  }
  return 0.5 * twice_area;
}

// The outline counter-clockwise: `ring` itself when it is (no copy), else its reverse, written
// into `scratch`.
const Ring& counter_clockwise(const Ring& ring, double area, Ring& scratch) {
  if (area >= 0) return ring;
  scratch.assign(ring.rbegin(), ring.rend());
  return scratch;
}

}  // namespace

// Everything one wall needs between validation and emission; reused from wall to wall.
struct WallWorkspace::Buffers {
  Ring outline;  // the spec's outline reversed, when it is clockwise
  std::vector<Accepted> cut;
  std::vector<Ring> spare_rings;  // the rings of `cut` between walls
  std::vector<const Accepted*> notches;
  Boundary boundary;
  MonotonePartition partition;
  PieceWalker walker;
  std::vector<std::array<std::uint32_t, 2>> diagonals;
  std::vector<std::uint32_t> loops;    // the pieces' vertex loops, one after the other
  std::vector<std::uint32_t> offsets;  // piece f is loops[offsets[f], offsets[f + 1])
  std::vector<PlainOpening> plain;     // a plain wall's openings by u
  bool plain_shortcut = true;          // WallWorkspace::set_plain_shortcut
  std::size_t plain_walls = 0;         // built through it
  WallResult result;                   // of the last appending build_wall
};

WallWorkspace::WallWorkspace() : buffers_(std::make_unique<Buffers>()) {}
WallWorkspace::~WallWorkspace() = default;
WallWorkspace::WallWorkspace(WallWorkspace&&) noexcept = default;
WallWorkspace& WallWorkspace::operator=(WallWorkspace&&) noexcept = default;
void WallWorkspace::set_plain_shortcut(bool enabled) {
  buffers_->plain_shortcut = enabled;
}
std::size_t WallWorkspace::plain_walls() const {
  return buffers_->plain_walls;
}

namespace {

// The stages both forms of build_wall share: validation, boundary rings, monotone partition and
// piece loops, left in `w` (boundary, loops, offsets). On failure `result` says why and nothing is
// left to emit. `result` is reset first, so a workspace's result can be reused.
bool partition_wall(const WallSpec& spec, WallWorkspace::Buffers& w, WallResult& result) {
  result.status = WallStatus::kOk;
  result.message.clear();
  result.issues.clear();
  result.cut.clear();
  result.face_opening.clear();
  result.front_pieces = 0;
  const double area = outline_signed_area(spec.outline);
  if (std::string why = wall_problem(spec, area); !why.empty()) {
    result.status = WallStatus::kInvalidWall;
    result.message = std::move(why);
    return false;
  }
  const Ring& ccw = counter_clockwise(spec.outline, area, w.outline);
  for (Accepted& c : w.cut) w.spare_rings.push_back(std::move(c.ring));
  w.cut.clear();
  if (w.plain_shortcut && plain_wall(ccw, spec, w.plain)) {
    plain_boundary(ccw, spec, w.boundary);
    plain_loops(w.plain, w.loops, w.offsets);
    for (std::size_t i = 0; i < spec.openings.size(); ++i) result.cut.push_back(i);
    result.front_pieces = w.offsets.size() - 1;
    ++w.plain_walls;
    return true;
  }
  result.issues = validate(ccw, spec, w.cut, &w.spare_rings);
  if (!result.issues.empty() && spec.policy == OpeningPolicy::kFail) {
    result.status = WallStatus::kRejectedOpening;
    result.message = result.issues.front().message;
    return false;
  }
  w.boundary.clear();
  build_boundary(ccw, w.cut, w.boundary, w.notches);
  w.diagonals.clear();
  w.loops.clear();
  w.offsets.assign(1, 0);
  if (!w.partition.run(w.boundary, w.diagonals) ||
      !w.walker.run(w.boundary, w.diagonals, w.loops, w.offsets)) {
    result.status = WallStatus::kDecompositionFailed;
    result.message = "the planar partition of the wall failed";
    result.issues.clear();
    return false;
  }
  for (const Accepted& c : w.cut) result.cut.push_back(c.index);
  result.front_pieces = w.offsets.size() - 1;
  return true;
}

}  // namespace

Ring opening_ring(const Opening& opening) {
  if (!parameter_problem(opening).empty()) return {};
  return make_ring(opening);
}

double opening_area(const Opening& opening) {
  const Ring ring = opening_ring(opening);
  return ring.empty() ? 0 : std::abs(signed_area(ring));
}

std::vector<OpeningIssue> check_openings(const WallSpec& spec, std::vector<std::size_t>* accepted) {
  if (accepted) accepted->clear();
  const double area = outline_signed_area(spec.outline);
  if (!wall_problem(spec, area).empty()) return {};
  std::vector<Accepted> cut;
  Ring scratch;
  const Ring& outline = counter_clockwise(spec.outline, area, scratch);
  std::vector<OpeningIssue> issues = validate(outline, spec, cut);
  if (accepted) {
    for (const Accepted& c : cut) accepted->push_back(c.index);
  }
  return issues;
}

WallResult build_wall(const WallSpec& spec, const WallFrame& frame) {
  WallWorkspace workspace;
  WallWorkspace::Buffers& w = workspace.buffers();
  WallResult result;
  if (partition_wall(spec, w, result)) emit(w.boundary, w.loops, w.offsets, spec, frame, result);
  return result;
}

WallResult build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out) {
  WallWorkspace workspace;
  build_wall(spec, frame, out, workspace);
  return std::move(workspace.buffers().result);
}

const WallResult& build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out,
                             WallWorkspace& workspace) {
  WallWorkspace::Buffers& w = workspace.buffers();
  if (partition_wall(spec, w, w.result)) {
    emit_into(w.boundary, w.loops, w.offsets, spec, frame, out);
  }
  return w.result;
}

namespace {

// place_wall's frame, and the wall's length; nullopt as documented there.
std::optional<std::pair<WallFrame, double>> frame_and_length(Vec3 base_start, Vec3 base_end,
                                                             double height, double thickness,
                                                             WallAlignment alignment) {
  const bool inputs_finite = std::isfinite(base_start.x) && std::isfinite(base_start.y) &&
                             std::isfinite(base_start.z) && std::isfinite(base_end.x) &&
                             std::isfinite(base_end.y) && std::isfinite(base_end.z) &&
                             std::isfinite(height) && std::isfinite(thickness);
  if (!inputs_finite || height <= 0 || thickness <= 0) return std::nullopt;
  const Vec3 run{base_end.x - base_start.x, base_end.y - base_start.y, 0};
  const double len = length(run);
  if (len <= kEps) return std::nullopt;
  WallFrame frame;
  frame.u_axis = run / len;
  frame.v_axis = {0, 0, 1};
  frame.normal = cross(frame.u_axis, frame.v_axis);
  const double shift = alignment == WallAlignment::kInside   ? thickness
                       : alignment == WallAlignment::kCenter ? thickness / 2
                                                             : 0;
  frame.origin = base_start - frame.normal * shift;
  return std::pair{frame, len};
}

}  // namespace

std::optional<WallPlacement> place_wall(Vec3 base_start, Vec3 base_end, double height,
                                        double thickness, WallAlignment alignment) {
  const auto placed = frame_and_length(base_start, base_end, height, thickness, alignment);
  if (!placed) return std::nullopt;
  WallPlacement w;
  w.frame = placed->first;
  const double len = placed->second;
  w.outline = {{0, 0}, {len, 0}, {len, height}, {0, height}};
  w.length = len;
  w.height = height;
  w.thickness = thickness;
  return w;
}

std::optional<WallFrame> place_wall_frame(Vec3 base_start, Vec3 base_end, double height,
                                          double thickness, WallAlignment alignment) {
  const auto placed = frame_and_length(base_start, base_end, height, thickness, alignment);
  if (!placed) return std::nullopt;
  return placed->first;
}

}  // namespace insula::kernel
