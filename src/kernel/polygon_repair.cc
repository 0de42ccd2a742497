// Validation and repair of polygons with holes (polygon.h). What is repaired and what is only
// reported is listed in docs/kernel-polygons.md; in short, the repairs never change the region a
// reasonable reader sees: repeated and collinear vertices and zero-width spikes are removed,
// orientation is fixed, degenerate holes (no area) are dropped. Crossings, self-touching rings and
// misplaced holes are reported, never guessed at.
//
// Edge-pair tests use a uniform grid over all edges (each pair is tested at most once thanks to a
// per-edge stamp), so a 10k-vertex ring is checked in a few milliseconds rather than the 50M pair
// tests of the naive O(n^2) loop.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "base/union_find.h"
#include "kernel/polygon.h"

namespace insula::kernel {
namespace {

// Past this many intersection findings the rest are summarised in one issue: a random 10k-vertex
// ring has millions of crossings, and nobody reads more than a few.
constexpr std::size_t kMaxFindings = 100;

std::string format_number(double v) {
  if (std::abs(v) < 1e6) v = std::round(v * 1e9) / 1e9;  // hide floating noise in messages
  if (v == 0) v = 0;                                     // no "-0"
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return std::string(buffer.data(), result.ptr);
}

std::string format_point(Vec2 p) {
  // Appended piecewise: GCC 12 gives a false -Wrestrict on the chained operator+ form.
  std::string text = "(";
  text.append(format_number(p.x)).append(", ").append(format_number(p.y)).append(")");
  return text;
}

std::string ring_name(int ring) {
  return ring == 0 ? "outer ring" : "hole " + std::to_string(ring);
}

// A ring after clean-up, with the index each kept vertex had in the caller's ring.
struct CleanRing {
  int id = 0;
  Ring points;
  std::vector<int> source;
  bool usable = false;     // finite and at least 3 vertices
  bool zero_area = false;  // mean width below the tolerance
};

PolygonIssue make_issue(PolygonIssueKind kind, int ring, int vertex, bool repaired,
                        std::string message) {
  return PolygonIssue{kind, ring, vertex, repaired, std::move(message)};
}

// ---- Stage 1: per-ring clean-up ---------------------------------------------------------------

bool report_non_finite(const Ring& ring, int id, std::vector<PolygonIssue>& issues) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (std::isfinite(ring[i].x) && std::isfinite(ring[i].y)) continue;
    issues.push_back(make_issue(PolygonIssueKind::kNonFinite, id, int(i), false,
                                ring_name(id) + ": vertex " + std::to_string(i) +
                                    " has a non-finite coordinate " + format_point(ring[i])));
    return true;
  }
  return false;
}

// Removes repeated vertices, collinear vertices and spike tips with a work list over a circular
// doubly linked list, so chains of spikes (a zero-width appendage walked out and back) unwind
// completely in O(n).
class RingCleaner {
 public:
  RingCleaner(const Ring& ring, int id, double tolerance, std::vector<PolygonIssue>& issues)
      : ring_(ring), id_(id), tolerance_(tolerance), issues_(issues) {}

  CleanRing run() {
    std::size_t n = ring_.size();
    while (n > 1 && ring_[n - 1] == ring_[0]) --n;  // a closing vertex is notation, not an issue
    alive_count_ = n;
    prev_.resize(n);
    next_.resize(n);
    alive_.assign(n, true);
    for (std::size_t i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
      work_.push_back(n - 1 - i);  // popped in ascending order
    }
    while (!work_.empty() && alive_count_ > 2) {
      const std::size_t v = work_.back();
      work_.pop_back();
      if (alive_[v]) visit(v);
    }
    return collect(n);
  }

 private:
  void visit(std::size_t v) {
    const std::size_t q = next_[v];
    const Vec2 a = ring_[prev_[v]], b = ring_[v], c = ring_[q];
    if (length(c - b) <= tolerance_) {
      report(PolygonIssueKind::kDuplicateVertex, q,
             "vertex " + std::to_string(q) + " repeats vertex " + std::to_string(v) + " (removed)");
      remove(q);
      work_.push_back(v);
      return;
    }
    const double base = length(c - a);
    if (base <= tolerance_) {
      report(PolygonIssueKind::kSelfIntersection, v,
             "vertex " + std::to_string(v) + " is the tip of a zero-width spike (removed)");
      remove(v);
      return;
    }
    if (std::abs(cross(c - a, b - a)) / base > tolerance_) return;
    const double t = dot(b - a, c - a) / (base * base);
    if (t >= 0 && t <= 1) {
      report(PolygonIssueKind::kCollinearVertex, v,
             "vertex " + std::to_string(v) + " lies on the line through its neighbours (removed)");
    } else {
      report(PolygonIssueKind::kSelfIntersection, v,
             "vertex " + std::to_string(v) + " is the tip of a zero-width spike (removed)");
    }
    remove(v);
  }

  void remove(std::size_t v) {
    alive_[v] = false;
    --alive_count_;
    next_[prev_[v]] = next_[v];
    prev_[next_[v]] = prev_[v];
    work_.push_back(next_[v]);
    work_.push_back(prev_[v]);
  }

  void report(PolygonIssueKind kind, std::size_t vertex, const std::string& text) {
    issues_.push_back(make_issue(kind, id_, int(vertex), true, ring_name(id_) + ": " + text));
  }

  CleanRing collect(std::size_t n) const {
    CleanRing out;
    out.id = id_;
    for (std::size_t i = 0; i < n; ++i) {
      if (!alive_[i]) continue;
      out.points.push_back(ring_[i]);
      out.source.push_back(int(i));
    }
    return out;
  }

  const Ring& ring_;
  int id_;
  double tolerance_;
  std::vector<PolygonIssue>& issues_;
  std::vector<std::size_t> prev_, next_, work_;
  std::vector<bool> alive_;
  std::size_t alive_count_ = 0;
};

void check_size_and_area(CleanRing& ring, double tolerance, std::vector<PolygonIssue>& issues) {
  if (ring.points.size() < 3) {
    const bool hole = ring.id > 0;
    issues.push_back(make_issue(PolygonIssueKind::kTooFewVertices, ring.id, -1, hole,
                                ring_name(ring.id) + ": " + std::to_string(ring.points.size()) +
                                    " distinct vertices, at least 3 needed" +
                                    (hole ? " (hole dropped)" : "")));
    return;
  }
  double length_sum = 0;
  for (std::size_t i = 0; i < ring.points.size(); ++i)
    length_sum += length(ring.points[(i + 1) % ring.points.size()] - ring.points[i]);
  // A ring whose mean width (2A / perimeter) is below the tolerance encloses nothing. It is still
  // checked for crossings: a bow-tie has zero signed area, and "crossing" is the better report.
  ring.zero_area = std::abs(signed_area(ring.points)) <= 0.5 * tolerance * length_sum;
  ring.usable = true;
}

// Called after the crossing checks, so only zero-area rings that do not cross themselves are
// reported as such; those are then left out of the result (a hole) or fail it (the outer ring).
void report_zero_area(std::vector<CleanRing>& rings, std::vector<PolygonIssue>& issues) {
  for (CleanRing& ring : rings) {
    if (!ring.zero_area) continue;
    const bool crosses = std::any_of(issues.begin(), issues.end(), [&](const PolygonIssue& i) {
      return i.ring == ring.id && i.kind == PolygonIssueKind::kSelfIntersection && !i.repaired;
    });
    if (crosses) continue;
    const bool hole = ring.id > 0;
    issues.push_back(
        make_issue(PolygonIssueKind::kZeroArea, ring.id, -1, hole,
                   ring_name(ring.id) + ": zero area" + (hole ? " (hole dropped)" : "")));
    ring.usable = false;
  }
}

void fix_orientation(CleanRing& ring, std::vector<PolygonIssue>& issues) {
  const bool hole = ring.id > 0;
  const double a = signed_area(ring.points);
  if (hole ? a <= 0 : a >= 0) return;
  std::reverse(ring.points.begin(), ring.points.end());
  std::reverse(ring.source.begin(), ring.source.end());
  issues.push_back(
      make_issue(PolygonIssueKind::kWrongOrientation, ring.id, -1, true,
                 ring_name(ring.id) + (hole ? ": counter-clockwise, reversed to clockwise"
                                            : ": clockwise, reversed to counter-clockwise")));
}

// ---- Stage 2: edge intersections --------------------------------------------------------------

struct Edge {
  Vec2 a, b;
  int ring;       // index into the CleanRing list
  int index;      // position of `a` in the clean ring
  int ring_size;  // number of vertices of the clean ring
  double length;  // |b - a|, > 0 after clean-up
};

enum class FindingKind { kCross, kTouchEdge, kTouchVertex };

struct Finding {
  FindingKind kind;
  int ring_s, edge_s;  // for touches, edge_s's start vertex is the touching vertex
  int ring_t, edge_t;  // for kTouchVertex, edge_t's start vertex is the vertex touched
  Vec2 point;
};

bool adjacent(const Edge& s, const Edge& t) {
  if (s.ring != t.ring) return false;
  const int n = s.ring_size;
  return (s.index + 1) % n == t.index || (t.index + 1) % n == s.index;
}

// Signed distance of p from the line through s (positive on the left).
double side(const Edge& s, Vec2 p) {
  return cross(s.b - s.a, p - s.a) / s.length;
}

// Classifies one edge pair; at most one crossing or up to two touches are appended. A touch is
// attributed to the start vertex of an edge, so a vertex shared by two edges is reported once.
void classify(const Edge& s, const Edge& t, double tol, std::vector<Finding>& out) {
  // Most pairs of a dense ring end here: one edge lies strictly on one side of the other's line.
  const double d1 = side(s, t.a), d2 = side(s, t.b);
  if ((d1 > tol && d2 > tol) || (d1 < -tol && d2 < -tol)) return;
  const double d3 = side(t, s.a), d4 = side(t, s.b);
  if ((d3 > tol && d4 > tol) || (d3 < -tol && d4 < -tol)) return;
  const bool straddle_s = (d1 > tol && d2 < -tol) || (d1 < -tol && d2 > tol);
  const bool straddle_t = (d3 > tol && d4 < -tol) || (d3 < -tol && d4 > tol);
  if (straddle_s && straddle_t) {
    out.push_back({FindingKind::kCross, s.ring, s.index, t.ring, t.index,
                   t.a + (t.b - t.a) * (d1 / (d1 - d2))});
    return;
  }
  const bool s_on_t = distance_to_segment(s.a, t.a, t.b) <= tol && length(s.a - t.b) > tol;
  if (s_on_t) {
    const bool vertex = length(s.a - t.a) <= tol;
    out.push_back({vertex ? FindingKind::kTouchVertex : FindingKind::kTouchEdge, s.ring, s.index,
                   t.ring, t.index, s.a});
  }
  const bool t_on_s = distance_to_segment(t.a, s.a, s.b) <= tol && length(t.a - s.b) > tol &&
                      length(t.a - s.a) > tol;
  if (t_on_s) out.push_back({FindingKind::kTouchEdge, t.ring, t.index, s.ring, s.index, t.a});
}

bool boxes_overlap(const Edge& s, const Edge& t, double tol) {
  return std::min(s.a.x, s.b.x) <= std::max(t.a.x, t.b.x) + tol &&
         std::min(t.a.x, t.b.x) <= std::max(s.a.x, s.b.x) + tol &&
         std::min(s.a.y, s.b.y) <= std::max(t.a.y, t.b.y) + tol &&
         std::min(t.a.y, t.b.y) <= std::max(s.a.y, s.b.y) + tol;
}

// A uniform grid of edge ids in CSR form; about one cell per edge.
class EdgeGrid {
 public:
  EdgeGrid(const std::vector<Edge>& edges, double tol) : edges_(edges), tol_(tol) {
    Bounds2 box;
    for (const Edge& e : edges) {
      box.add(e.a);
      box.add(e.b);
    }
    origin_ = box.min;
    const double w = std::max(box.max.x - box.min.x, tol), h = std::max(box.max.y - box.min.y, tol);
    const double n = double(std::max<std::size_t>(edges.size(), 1));
    cell_ = std::sqrt(w * h / n);
    cell_ = std::max({cell_, w / 2048.0, h / 2048.0});
    nx_ = std::clamp(int(std::ceil(w / cell_)), 1, 2048);
    ny_ = std::clamp(int(std::ceil(h / cell_)), 1, 2048);
    start_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
    for_each_cell_pass(true);
    for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    items_.resize(start_.back());
    fill_ = std::vector<std::uint32_t>(start_.begin(), start_.end() - 1);
    for_each_cell_pass(false);
  }

  // Calls visit(i, j) once for every pair i < j of edges whose cells are shared.
  template <typename Visit>
  void pairs(Visit&& visit) const {
    std::vector<std::uint32_t> stamp(edges_.size(), UINT32_MAX);
    for (std::uint32_t i = 0; i < edges_.size(); ++i) {
      const auto [x0, y0, x1, y1] = cell_range(edges_[i]);
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const std::size_t c = std::size_t(y) * std::size_t(nx_) + std::size_t(x);
          for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
            const std::uint32_t j = items_[k];
            if (j <= i || stamp[j] == i) continue;
            stamp[j] = i;
            if (!visit(i, j)) return;
          }
        }
      }
    }
  }

 private:
  std::tuple<int, int, int, int> cell_range(const Edge& e) const {
    auto cx = [&](double v) { return std::clamp(int((v - origin_.x) / cell_), 0, nx_ - 1); };
    auto cy = [&](double v) { return std::clamp(int((v - origin_.y) / cell_), 0, ny_ - 1); };
    return {cx(std::min(e.a.x, e.b.x) - tol_), cy(std::min(e.a.y, e.b.y) - tol_),
            cx(std::max(e.a.x, e.b.x) + tol_), cy(std::max(e.a.y, e.b.y) + tol_)};
  }

  void for_each_cell_pass(bool count) {
    for (std::uint32_t i = 0; i < edges_.size(); ++i) {
      const auto [x0, y0, x1, y1] = cell_range(edges_[i]);
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const std::size_t c = std::size_t(y) * std::size_t(nx_) + std::size_t(x);
          if (count)
            ++start_[c + 1];
          else
            items_[fill_[c]++] = i;
        }
      }
    }
  }

  const std::vector<Edge>& edges_;
  double tol_;
  Vec2 origin_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, items_, fill_;
};

std::vector<Finding> find_intersections(const std::vector<CleanRing>& rings, double tol,
                                        bool& truncated) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (!rings[r].usable) continue;
    const Ring& p = rings[r].points;
    for (std::size_t i = 0; i < p.size(); ++i)
      edges.push_back({p[i], p[(i + 1) % p.size()], int(r), int(i), int(p.size()),
                       kernel::length(p[(i + 1) % p.size()] - p[i])});
  }
  std::vector<Finding> findings;
  truncated = false;
  if (edges.empty()) return findings;
  const EdgeGrid grid(edges, tol);
  grid.pairs([&](std::uint32_t i, std::uint32_t j) {
    const Edge& s = edges[i];
    const Edge& t = edges[j];
    if (adjacent(s, t) || !boxes_overlap(s, t, tol)) return true;
    classify(s, t, tol, findings);
    if (findings.size() < kMaxFindings) return true;
    truncated = true;
    return false;
  });
  std::sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
    return std::tie(a.ring_s, a.edge_s, a.ring_t, a.edge_t) <
           std::tie(b.ring_s, b.edge_s, b.ring_t, b.edge_t);
  });
  return findings;
}

// ---- Stage 3: findings to issues --------------------------------------------------------------

class FindingReporter {
 public:
  FindingReporter(const std::vector<CleanRing>& rings, double tol,
                  std::vector<PolygonIssue>& issues)
      : rings_(rings), tol_(tol), issues_(issues) {}

  void report(const std::vector<Finding>& findings) {
    for (const Finding& f : findings) {
      if (f.ring_s == f.ring_t)
        self(f);
      else
        between(f);
    }
    for (const auto& [pair, points] : touches_) {
      if (points.size() < 2) continue;
      const auto [lo, hi] = pair;
      issues_.push_back(make_issue(PolygonIssueKind::kRingsIntersect, rings_[hi].id, -1, false,
                                   ring_name(rings_[hi].id) + " touches " +
                                       ring_name(rings_[lo].id) + " at " + format_point(points[0]) +
                                       " and " + format_point(points[1]) +
                                       ", which splits the polygon's interior"));
    }
    report_touch_loops();
  }

  // Pairs (lower, higher) of clean-ring indices whose edges cross.
  std::vector<std::pair<int, int>> crossing_pairs;

 private:
  // Rings touching once each can still split the interior when the touches close a loop (outer
  // touches hole 1, hole 1 touches hole 2, hole 2 touches the outer). In the graph of rings and
  // distinct touch points such a loop is a cycle (union-find); rings meeting at one common point
  // share a point node and form none.
  void report_touch_loops() {
    std::vector<Vec2> points;
    base::UnionFind loops(rings_.size());
    auto point_node = [&](Vec2 p) {
      for (std::size_t i = 0; i < points.size(); ++i)
        if (length(points[i] - p) <= tol_) return int(rings_.size() + i);
      points.push_back(p);
      return int(loops.add());
    };
    std::vector<std::pair<int, int>> linked;  // (ring, point node) edges already in the graph
    for (const auto& [pair, touch] : touches_) {
      if (touch.size() != 1) continue;
      const int pt = point_node(touch[0]);
      for (int ring : {pair.first, pair.second}) {
        if (std::find(linked.begin(), linked.end(), std::pair{ring, pt}) != linked.end()) continue;
        linked.emplace_back(ring, pt);
        if (loops.unite(std::uint32_t(ring), std::uint32_t(pt))) continue;
        const auto [lo, hi] = pair;
        issues_.push_back(make_issue(
            PolygonIssueKind::kRingsIntersect, rings_[hi].id, -1, false,
            ring_name(rings_[hi].id) + " touches " + ring_name(rings_[lo].id) + " at " +
                format_point(touch[0]) +
                ", closing a loop of touching rings that splits the polygon's interior"));
        return;
      }
    }
  }

  int vertex(int ring, int index) const { return rings_[ring].source[index]; }
  std::string edge(int ring, int index) const {
    const int n = int(rings_[ring].source.size());
    return std::to_string(vertex(ring, index)) + "-" +
           std::to_string(vertex(ring, (index + 1) % n));
  }

  void self(const Finding& f) {
    const int id = rings_[f.ring_s].id;
    std::string text;
    switch (f.kind) {
      case FindingKind::kCross:
        text =
            "edges " + edge(f.ring_s, f.edge_s) + " and " + edge(f.ring_t, f.edge_t) + " cross at ";
        break;
      case FindingKind::kTouchEdge:
        text = "vertex " + std::to_string(vertex(f.ring_s, f.edge_s)) + " touches edge " +
               edge(f.ring_t, f.edge_t) + " at ";
        break;
      case FindingKind::kTouchVertex:
        text = "vertices " + std::to_string(vertex(f.ring_s, f.edge_s)) + " and " +
               std::to_string(vertex(f.ring_t, f.edge_t)) + " coincide at ";
        break;
    }
    issues_.push_back(make_issue(PolygonIssueKind::kSelfIntersection, id,
                                 vertex(f.ring_s, f.edge_s), false,
                                 ring_name(id) + ": " + text + format_point(f.point)));
  }

  void between(const Finding& f) {
    const int lo = std::min(f.ring_s, f.ring_t), hi = std::max(f.ring_s, f.ring_t);
    if (f.kind != FindingKind::kCross) {
      // One touching point between two rings is allowed (OGC); two or more are reported above.
      std::vector<Vec2>& points = touches_[{lo, hi}];
      const bool known = std::any_of(points.begin(), points.end(),
                                     [&](Vec2 p) { return length(p - f.point) <= tol_; });
      if (!known) points.push_back(f.point);
      return;
    }
    crossing_pairs.emplace_back(lo, hi);
    const int hole = rings_[f.ring_s].id > rings_[f.ring_t].id ? f.ring_s : f.ring_t;
    const int other = hole == f.ring_s ? f.ring_t : f.ring_s;
    const int hole_edge = hole == f.ring_s ? f.edge_s : f.edge_t;
    const int other_edge = hole == f.ring_s ? f.edge_t : f.edge_s;
    const std::string hn = ring_name(rings_[hole].id), on = ring_name(rings_[other].id);
    issues_.push_back(make_issue(
        PolygonIssueKind::kRingsIntersect, rings_[hole].id, vertex(hole, hole_edge), false,
        hn + " crosses " + on + ": edge " + edge(hole, hole_edge) + " of " + hn + " and edge " +
            edge(other, other_edge) + " of " + on + " cross at " + format_point(f.point)));
  }

  const std::vector<CleanRing>& rings_;
  double tol_;
  std::vector<PolygonIssue>& issues_;
  std::map<std::pair<int, int>, std::vector<Vec2>> touches_;
};

// ---- Stage 4: hole placement ------------------------------------------------------------------

// Where `inner` lies relative to `outer`, judged at its first vertex or edge midpoint that is not
// on `outer`'s boundary; kBoundary when every sample is on it (the rings coincide).
PointLocation ring_in_ring(const Ring& inner, const Ring& outer, double tol) {
  const Polygon container{outer, {}};
  for (const Vec2& p : inner) {
    const PointLocation where = locate(container, p, tol);
    if (where != PointLocation::kBoundary) return where;
  }
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Vec2 mid = (inner[i] + inner[(i + 1) % inner.size()]) * 0.5;
    const PointLocation where = locate(container, mid, tol);
    if (where != PointLocation::kBoundary) return where;
  }
  return PointLocation::kBoundary;
}

bool bounds_overlap(const Ring& a, const Ring& b) {
  Bounds2 ba, bb;
  for (Vec2 p : a) ba.add(p);
  for (Vec2 p : b) bb.add(p);
  return ba.min.x <= bb.max.x && bb.min.x <= ba.max.x && ba.min.y <= bb.max.y &&
         bb.min.y <= ba.max.y;
}

void check_hole_placement(const std::vector<CleanRing>& rings,
                          const std::vector<std::pair<int, int>>& crossing_pairs, double tol,
                          std::vector<PolygonIssue>& issues) {
  auto crossed = [&](int a, int b) {
    return std::find(crossing_pairs.begin(), crossing_pairs.end(), std::pair{a, b}) !=
           crossing_pairs.end();
  };
  const bool outer_ok = rings[0].usable;
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (!rings[h].usable || !outer_ok || crossed(0, int(h))) continue;
    const PointLocation where = ring_in_ring(rings[h].points, rings[0].points, tol);
    const std::string name = ring_name(rings[h].id);
    if (where == PointLocation::kOutside)
      issues.push_back(make_issue(PolygonIssueKind::kHoleOutside, rings[h].id, -1, false,
                                  name + " lies outside the outer ring"));
    else if (where == PointLocation::kBoundary)
      issues.push_back(make_issue(PolygonIssueKind::kRingsIntersect, rings[h].id, -1, false,
                                  name + " coincides with the outer ring"));
  }
  for (std::size_t i = 1; i < rings.size(); ++i) {
    for (std::size_t j = i + 1; j < rings.size(); ++j) {
      if (!rings[i].usable || !rings[j].usable || crossed(int(i), int(j))) continue;
      if (!bounds_overlap(rings[i].points, rings[j].points)) continue;
      const std::string ni = ring_name(rings[i].id), nj = ring_name(rings[j].id);
      const PointLocation j_in_i = ring_in_ring(rings[j].points, rings[i].points, tol);
      if (j_in_i == PointLocation::kBoundary)
        issues.push_back(make_issue(PolygonIssueKind::kRingsIntersect, rings[j].id, -1, false,
                                    nj + " coincides with " + ni));
      else if (j_in_i == PointLocation::kInside)
        issues.push_back(make_issue(PolygonIssueKind::kHoleOutside, rings[j].id, -1, false,
                                    nj + " lies inside " + ni));
      else if (ring_in_ring(rings[i].points, rings[j].points, tol) == PointLocation::kInside)
        issues.push_back(make_issue(PolygonIssueKind::kHoleOutside, rings[i].id, -1, false,
                                    ni + " lies inside " + nj));
    }
  }
}

}  // namespace

RepairResult repair(const Polygon& polygon, double tolerance) {
  RepairResult result;
  std::vector<PolygonIssue>& issues = result.issues;
  std::vector<CleanRing> rings;
  for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
    const Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
    const int id = int(r);
    if (report_non_finite(ring, id, issues)) {
      rings.push_back(CleanRing{id, {}, {}, false});
      continue;
    }
    rings.push_back(RingCleaner(ring, id, tolerance, issues).run());
    check_size_and_area(rings.back(), tolerance, issues);
    if (rings.back().usable && !rings.back().zero_area) fix_orientation(rings.back(), issues);
  }
  bool truncated = false;
  const std::vector<Finding> findings = find_intersections(rings, tolerance, truncated);
  FindingReporter reporter(rings, tolerance, issues);
  reporter.report(findings);
  if (truncated)
    issues.push_back(make_issue(
        PolygonIssueKind::kSelfIntersection, 0, -1, false,
        "more intersections not listed (stopped after " + std::to_string(kMaxFindings) + ")"));
  report_zero_area(rings, issues);
  check_hole_placement(rings, reporter.crossing_pairs, tolerance, issues);

  result.ok =
      std::all_of(issues.begin(), issues.end(), [](const PolygonIssue& i) { return i.repaired; });
  result.polygon.outer = rings[0].points;
  for (std::size_t r = 1; r < rings.size(); ++r)
    if (rings[r].usable) result.polygon.holes.push_back(rings[r].points);
  return result;
}

std::vector<PolygonIssue> validate(const Polygon& polygon, double tolerance) {
  return repair(polygon, tolerance).issues;
}

}  // namespace insula::kernel

namespace insula::kernel {
namespace {

Ring without_consecutive_repeats(const Ring& ring) {
  Ring out;
  for (const Vec2 v : ring) {
    if (out.empty() || out.back() != v) out.push_back(v);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// Cuts `ring` at a repeated point into loops, recursively; `points` collects the cut points.
void cut_loops(const Ring& ring, std::vector<Ring>& loops, std::vector<Vec2>& points) {
  const std::size_t n = ring.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(ring[a].x, ring[a].y, a) < std::tie(ring[b].x, ring[b].y, b);
  });
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const std::size_t i = order[k], j = order[k + 1];
    if (ring[i] != ring[j]) continue;
    Ring a(ring.begin() + long(i), ring.begin() + long(j));
    Ring b(ring.begin() + long(j), ring.end());
    b.insert(b.end(), ring.begin(), ring.begin() + long(i));
    if (a.size() < 3 || b.size() < 3 || signed_area(a) == 0 || signed_area(b) == 0) continue;
    points.push_back(ring[i]);
    cut_loops(a, loops, points);
    cut_loops(b, loops, points);
    return;
  }
  loops.push_back(ring);
}

}  // namespace

TouchSplit split_touching_rings(const Polygon& polygon) {
  TouchSplit result;
  result.polygons.push_back(polygon);
  const Ring outer = without_consecutive_repeats(polygon.outer);
  const double sign = signed_area(outer) < 0 ? -1 : 1;
  std::vector<Ring> outer_loops;
  std::vector<Vec2> points;
  cut_loops(outer, outer_loops, points);
  std::vector<Ring> pieces;
  std::vector<Ring> holes;
  for (Ring& loop : outer_loops) (signed_area(loop) * sign > 0 ? pieces : holes).push_back(loop);
  for (const Ring& hole : polygon.holes) {
    const Ring clean = without_consecutive_repeats(hole);
    std::vector<Ring> loops;
    const std::size_t before = points.size();
    cut_loops(clean, loops, points);
    if (points.size() == before) {
      holes.push_back(hole);  // untouched: repair() judges it as written
      continue;
    }
    const double hole_sign = signed_area(clean) < 0 ? -1 : 1;
    for (Ring& loop : loops) {
      if (signed_area(loop) * hole_sign < 0) return result;  // an island in a hole
      holes.push_back(std::move(loop));
    }
  }
  if (points.empty()) return result;
  // Same-winding loops nested in each other overlap: no single reading.
  constexpr double kTol = 0;
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    for (std::size_t b = 0; b < pieces.size(); ++b) {
      if (a != b && ring_in_ring(pieces[a], pieces[b], kTol) == PointLocation::kInside) {
        return result;
      }
    }
  }
  std::vector<Polygon> out(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) out[i].outer = pieces[i];
  for (Ring& hole : holes) {
    std::size_t home = pieces.size();
    for (std::size_t i = 0; i < pieces.size() && home == pieces.size(); ++i) {
      if (ring_in_ring(hole, pieces[i], kTol) == PointLocation::kInside) home = i;
    }
    if (home == pieces.size()) return result;  // a reversed loop outside: the ring crosses over
    out[home].holes.push_back(std::move(hole));
  }
  result.polygons = std::move(out);
  result.points = std::move(points);
  return result;
}

std::vector<Vec2> separate_touching_rings(Polygon& polygon, double distance) {
  std::vector<Vec2> moved;
  const std::size_t rings = polygon.holes.size() + 1;
  auto ring_at = [&](std::size_t r) -> Ring& {
    return r == 0 ? polygon.outer : polygon.holes[r - 1];
  };
  auto on_other_ring = [&](std::size_t r, Vec2 p) {
    for (std::size_t o = 0; o < rings; ++o) {
      if (o == r) continue;
      const Ring& other = ring_at(o);
      for (std::size_t i = 0; i < other.size(); ++i) {
        if (distance_to_segment(p, other[i], other[(i + 1) % other.size()]) == 0) return true;
      }
    }
    return false;
  };
  // Holes first: a hole shrinking by `distance` changes the building least. Then outer vertices
  // still on a hole (a reflex corner of the outline touching a hole's edge).
  for (std::size_t pass = 0; pass < 2; ++pass) {
    for (std::size_t r = pass == 0 ? 1 : 0; r < (pass == 0 ? rings : 1); ++r) {
      Ring& ring = ring_at(r);
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        if (!on_other_ring(r, ring[i])) continue;
        // The empty side is on the right of every edge (outer counter-clockwise, holes
        // clockwise): move along the bisector of the two right-hand normals.
        const Vec2 in = normalized(ring[i] - ring[(i + n - 1) % n]);
        const Vec2 out = normalized(ring[(i + 1) % n] - ring[i]);
        Vec2 direction = Vec2{in.y, -in.x} + Vec2{out.y, -out.x};
        if (length(direction) < 1e-9) direction = Vec2{in.y, -in.x};
        moved.push_back(ring[i]);
        ring[i] += normalized(direction) * distance;
      }
    }
  }
  return moved;
}

}  // namespace insula::kernel
