#include "lang/bldg/plan_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>

#include "kernel/boolean2d.h"
#include "kernel/planar.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;
using kernel::Ring;
using kernel::Vec2;

// Is b, between its neighbours a and c, not a corner? It is when an edge beside it is shorter
// than kLineTolerance, or when it lies between a and c within kLineTolerance of the line ac.
bool redundant(Vec2 a, Vec2 b, Vec2 c) {
  constexpr double kTol2 = kLineTolerance * kLineTolerance;
  const Vec2 ac = c - a;
  const Vec2 ab = b - a;
  const Vec2 bc = c - b;
  if (kernel::dot(ab, ab) < kTol2 || kernel::dot(bc, bc) < kTol2) return true;
  if (!(kernel::dot(ab, bc) > 0)) return false;
  const double len2 = kernel::dot(ac, ac);
  if (len2 < kTol2) return false;
  return std::abs(kernel::cross(ac, ab)) / std::sqrt(len2) < kLineTolerance;
}

// Erases the redundant vertex of lowest index, again and again, until none is left. After an
// erasure at i only the vertices beside it changed neighbours, so the scan resumes at i - 1 rather
// than at 0 (vertices 0 .. i - 2 were kept and keep their neighbours), except when the erased
// vertex was the first or the last, which changes vertex 0's neighbour: then it restarts at 0.
void simplify_ring(Ring& ring) {
  std::size_t i = 0;
  while (ring.size() >= 3 && i < ring.size()) {
    const std::size_t n = ring.size();
    if (!redundant(ring[i == 0 ? n - 1 : i - 1], ring[i], ring[i + 1 < n ? i + 1 : 0])) {
      ++i;
      continue;
    }
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
    i = (i == 0 || i == n - 1) ? 0 : i - 1;
  }
}

struct Interval {
  double s0;
  double s1;
  int other;
};

// Intervals of edge p->q (parameter in metres from p) covered by edges of `ring` running the
// opposite way on the same line. `u` is the edge's unit direction and `len` its length, computed
// once per edge by the caller (they were recomputed, with std::hypot, per ring).
void covered_by_ring(Vec2 p, Vec2 u, double len, const Ring& ring, int other,
                     std::vector<Interval>& out) {
  const std::size_t n = ring.size();
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2 a = ring[j];
    const Vec2 b = ring[j + 1 < n ? j + 1 : 0];
    if (kernel::dot(b - a, u) >= 0) continue;  // must run the other way
    const double sa = kernel::dot(a - p, u);
    const double sb = kernel::dot(b - p, u);
    const double lo = std::max(0.0, std::min(sa, sb));
    const double hi = std::min(len, std::max(sa, sb));
    if (hi - lo <= kLineTolerance) continue;
    // The other edge must lie on this one where they overlap (checked at the overlap's ends, not
    // at the other edge's far ends: two long edges a few micrometres off parallel still match).
    auto off_line = [&](double s) {
      const Vec2 q_on_other = a + (b - a) * ((s - sa) / (sb - sa));
      return std::abs(kernel::cross(u, q_on_other - p)) > kLineTolerance;
    };
    if (off_line(lo) || off_line(hi)) continue;
    out.push_back({lo, hi, other});
  }
}

// The polygons an edge is compared with: others[near[i]], whose boxes are boxes[near[i]]. With
// `shared_only` the caller keeps only the pieces that have a polygon on the other side, so edges
// no other polygon covers are skipped without listing their open pieces.
struct Neighbours {
  std::span<const Polygon* const> others;
  std::span<const kernel::Bounds2> boxes;
  std::span<const std::uint32_t> near;
  bool shared_only = false;
};

// False when the box's shadow on the edge's line (parameter from p along u) overlaps [0, len] by
// less than kLineTolerance minus a nanometre: then every edge of a ring inside the box gives an
// overlap covered_by_ring drops (hi - lo <= kLineTolerance; the nanometre covers the rounding of
// its projections, which differ from the box corner's by far less). Neighbours touching the edge
// only at a corner are skipped so.
bool overlaps_along(Vec2 p, Vec2 u, double len, const kernel::Bounds2& box) {
  const double x0 = (box.min.x - p.x) * u.x;
  const double x1 = (box.max.x - p.x) * u.x;
  const double y0 = (box.min.y - p.y) * u.y;
  const double y1 = (box.max.y - p.y) * u.y;
  const double lo = std::min(x0, x1) + std::min(y0, y1);
  const double hi = std::max(x0, x1) + std::max(y0, y1);
  return std::min(len, hi) - std::max(0.0, lo) > kLineTolerance - 1e-9;
}

// Appends the pieces of edge p->q (length len >= kLineTolerance, box edge_box) to `out`.
// `covered` is the caller's scratch, its storage reused from edge to edge.
void pieces_of_edge(Vec2 p, Vec2 q, double len, const kernel::Bounds2& edge_box,
                    const Neighbours& nb, std::vector<Interval>& covered,
                    std::vector<EdgePiece>& out) {
  covered.clear();
  const Vec2 u = (q - p) / len;
  for (const std::uint32_t k : nb.near) {
    if (!kernel::touches(edge_box, nb.boxes[k], kLineTolerance)) continue;
    if (!overlaps_along(p, u, len, nb.boxes[k])) continue;
    covered_by_ring(p, u, len, nb.others[k]->outer, static_cast<int>(k), covered);
    for (const Ring& hole : nb.others[k]->holes)
      covered_by_ring(p, u, len, hole, static_cast<int>(k), covered);
  }
  if (nb.shared_only && covered.empty()) return;  // one open piece, unwanted
  if (covered.size() > 1)
    std::sort(covered.begin(), covered.end(),
              [](const Interval& x, const Interval& y) { return x.s0 < y.s0; });
  double s = 0;
  const std::size_t start = out.size();  // pieces merge within this edge only
  auto push = [&](double s0, double s1, int other) {
    if (s1 - s0 <= kLineTolerance) return;
    if (out.size() > start && out.back().other == other &&
        edge_length(out.back().b - (p + u * s0)) < kLineTolerance) {
      out.back().b = s1 >= len - kLineTolerance ? q : p + u * s1;
      return;
    }
    out.push_back({s0 <= kLineTolerance ? p : p + u * s0,
                   s1 >= len - kLineTolerance ? q : p + u * s1, other});
  };
  for (const Interval& c : covered) {
    if (c.s1 <= s + kLineTolerance) continue;
    if (c.s0 > s) push(s, c.s0, -1);
    push(std::max(s, c.s0), c.s1, c.other);
    s = c.s1;
  }
  if (s < len) push(s, len, -1);
}

bool touches_any(const kernel::Bounds2& edge_box, const Neighbours& nb) {
  return std::any_of(nb.near.begin(), nb.near.end(), [&](std::uint32_t k) {
    return kernel::touches(edge_box, nb.boxes[k], kLineTolerance);
  });
}

// Appends the pieces of every edge of `cell` (outer ring, then holes) to `out`.
void append_pieces(const Polygon& cell, const Neighbours& nb, std::vector<EdgePiece>& out) {
  std::vector<Interval> covered;
  auto ring_pieces = [&](const Ring& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = ring[i];
      const Vec2 q = ring[i + 1 < n ? i + 1 : 0];
      kernel::Bounds2 edge_box;
      edge_box.min = {std::min(p.x, q.x), std::min(p.y, q.y)};
      edge_box.max = {std::max(p.x, q.x), std::max(p.y, q.y)};
      if (nb.shared_only && !touches_any(edge_box, nb)) continue;
      const double len = edge_length(q - p);
      if (len < kLineTolerance) continue;
      pieces_of_edge(p, q, len, edge_box, nb, covered, out);
    }
  };
  ring_pieces(cell.outer);
  for (const Ring& h : cell.holes) ring_pieces(h);
}

// The pieces of `cell`'s boundary shared with the single polygon `other` (index 0; open pieces
// may be left out); empty, and nothing allocated, when the boxes do not touch (most pairs callers
// ask about).
std::vector<EdgePiece> pieces_against(const Polygon& cell, const kernel::Bounds2& cell_box,
                                      const Polygon& other, const kernel::Bounds2& other_box) {
  std::vector<EdgePiece> pieces;
  if (!kernel::touches(cell_box, other_box, kLineTolerance)) return pieces;
  const Polygon* const others[1] = {&other};
  static constexpr std::uint32_t near[1] = {0};
  append_pieces(cell, Neighbours{others, {&other_box, 1}, near, true}, pieces);
  return pieces;
}

}  // namespace

double area_below(const std::vector<Polygon>& region, bool along_x, double t) {
  return along_x ? area_below_axis<true>(region, t) : area_below_axis<false>(region, t);
}

double area_of(const std::vector<Polygon>& region) {
  double total = 0;
  for (const Polygon& p : region) total += kernel::area(p);
  return total;
}

kernel::Bounds2 bounds_of(const std::vector<Polygon>& region) {
  kernel::Bounds2 b;
  for (const Polygon& p : region) kernel::add(b, p.outer);
  return b;
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

Polygon oriented_rectangle(Vec2 from, Vec2 along, Vec2 inward, double length, double depth) {
  Polygon p{
      {from, from + along * length, from + along * length + inward * depth, from + inward * depth},
      {}};
  kernel::normalize(p);
  return p;
}

void simplify(Polygon& polygon) {
  simplify_ring(polygon.outer);
  for (Ring& h : polygon.holes) simplify_ring(h);
  std::erase_if(polygon.holes, [](const Ring& h) { return h.size() < 3; });
}

int wall_count(const Polygon& polygon) {
  Ring ring = polygon.outer;
  simplify_ring(ring);
  return static_cast<int>(ring.size());
}

std::vector<EdgePiece> boundary_pieces(const Polygon& cell,
                                       const std::vector<const Polygon*>& others) {
  std::vector<kernel::Bounds2> boxes(others.size());
  for (std::size_t k = 0; k < others.size(); ++k)
    if (others[k] != nullptr) boxes[k] = kernel::bounds(*others[k]);
  return boundary_pieces(cell, kernel::bounds(cell), others, boxes);
}

std::vector<EdgePiece> boundary_pieces(const Polygon& cell, const kernel::Bounds2& cell_box,
                                       const std::vector<const Polygon*>& others,
                                       const std::vector<kernel::Bounds2>& boxes) {
  // Only the polygons whose box touches the cell's can share an edge with it (indices kept).
  std::vector<std::uint32_t> near;
  for (std::size_t k = 0; k < others.size(); ++k) {
    if (others[k] == nullptr) continue;
    if (kernel::touches(cell_box, boxes[k], kLineTolerance))
      near.push_back(static_cast<std::uint32_t>(k));
  }
  std::vector<EdgePiece> out;
  out.reserve(cell.outer.size() + 4);
  append_pieces(cell, Neighbours{others, boxes, near}, out);
  return out;
}

std::vector<EdgePiece> boundary_pieces(const Polygon& cell,
                                       const std::vector<const Polygon*>& others,
                                       const std::vector<kernel::Bounds2>& boxes,
                                       std::span<const std::uint32_t> near) {
  std::vector<EdgePiece> out;
  out.reserve(cell.outer.size() + 4);
  append_pieces(cell, Neighbours{others, boxes, near}, out);
  return out;
}

std::vector<EdgePiece> shared_segments(const Polygon& cell, const Polygon& other) {
  std::vector<EdgePiece> out;
  for (const EdgePiece& piece :
       pieces_against(cell, kernel::bounds(cell), other, kernel::bounds(other)))
    if (piece.other == 0) out.push_back(piece);
  return out;
}

double shared_length(const Polygon& cell, const Polygon& other) {
  double total = 0;
  for (const EdgePiece& piece :
       pieces_against(cell, kernel::bounds(cell), other, kernel::bounds(other)))
    if (piece.other == 0) total += piece.length();
  return total;
}

double longest_shared_segment(const Polygon& cell, const kernel::Bounds2& cell_box,
                              const Polygon& other, const kernel::Bounds2& other_box) {
  double best = 0;
  for (const EdgePiece& piece : pieces_against(cell, cell_box, other, other_box))
    if (piece.other == 0) best = std::max(best, piece.length());
  return best;
}

bool covers(const std::vector<Polygon>& outer, const Polygon& inner) {
  const kernel::BooleanResult r = kernel::subtract({inner}, outer);
  return r.ok() && area_of(r.polygons) < 1e-9;
}

bool overlaps(const Polygon& a, const Polygon& b) {
  if (!kernel::touches(kernel::bounds(a), kernel::bounds(b), 0)) return false;
  const kernel::BooleanResult r = kernel::intersect({a}, {b});
  return r.ok() && area_of(r.polygons) > 1e-9;
}

NearLists touching_boxes(const std::vector<kernel::Bounds2>& boxes, double margin) {
  const std::size_t n = boxes.size();
  // Pairs (i, j) whose boxes touch, by a sweep along x: boxes sorted by their left side, each
  // compared only with those starting before its right side ends.
  std::vector<std::uint32_t> by_left(n);
  for (std::size_t i = 0; i < n; ++i) by_left[i] = static_cast<std::uint32_t>(i);
  std::sort(by_left.begin(), by_left.end(),
            [&](std::uint32_t a, std::uint32_t b) { return boxes[a].min.x < boxes[b].min.x; });
  std::vector<double> left(n);  // left sides in sweep order, contiguous for the inner loop
  for (std::size_t k = 0; k < n; ++k) left[k] = boxes[by_left[k]].min.x;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(4 *
                n);  // a cell of a plan touches a few others: one allocation, not a doubling run
  for (std::size_t k = 0; k < n; ++k) {
    const kernel::Bounds2& a = boxes[by_left[k]];
    const double reach = a.max.x + margin;
    // Boxes further right start past a's right side plus the margin: none of them touches a.
    for (std::size_t m = k + 1; m < n && left[m] <= reach; ++m) {
      if (!kernel::touches(a, boxes[by_left[m]], margin)) continue;
      pairs.push_back({by_left[k], by_left[m]});
    }
  }
  // Both directions of every pair into the rows (a counting pass, then a fill), each row sorted.
  NearLists lists;
  lists.start.assign(n + 1, 0);
  for (const auto& [i, j] : pairs) {
    ++lists.start[i + 1];
    ++lists.start[j + 1];
  }
  for (std::size_t i = 0; i < n; ++i) lists.start[i + 1] += lists.start[i];
  // The rows in pair order first, then read back polygon by polygon: polygon p, taken in
  // increasing order, goes to the rows of its partners, so every row comes out sorted (rows are
  // symmetric), with no comparison.
  std::vector<std::uint32_t> unsorted(lists.start[n]);
  std::vector<std::uint32_t> fill(lists.start.begin(), lists.start.end() - 1);
  for (const auto& [i, j] : pairs) {
    unsorted[fill[i]++] = j;
    unsorted[fill[j]++] = i;
  }
  lists.near.resize(lists.start[n]);
  std::copy(lists.start.begin(), lists.start.end() - 1, fill.begin());
  for (std::size_t p = 0; p < n; ++p)
    for (std::uint32_t k = lists.start[p]; k < lists.start[p + 1]; ++k)
      lists.near[fill[unsorted[k]]++] = static_cast<std::uint32_t>(p);
  return lists;
}

namespace {

// Moves `v` onto the first edge of `ring` it lies within `tolerance` of (strictly between the
// edge's ends, and not within `tolerance` of either end); true when it did.
bool snap_to_ring(Vec2& v, const Ring& ring, double tolerance) {
  const double tol2 = tolerance * tolerance;
  // An edge whose box is further than this from v cannot hold a foot within `tolerance` of v
  // (the foot lies in the edge's box up to rounding): skipped before the division below.
  const double reach = 1.5 * tolerance + 1e-9;
  auto dist2 = [](Vec2 a, Vec2 b) { return kernel::dot(a - b, a - b); };
  const std::size_t n = ring.size();
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 p = ring[e];
    const Vec2 q = ring[e + 1 < n ? e + 1 : 0];
    if (v.x < std::min(p.x, q.x) - reach || v.x > std::max(p.x, q.x) + reach ||
        v.y < std::min(p.y, q.y) - reach || v.y > std::max(p.y, q.y) + reach)
      continue;
    if (dist2(v, p) <= tol2 || dist2(v, q) <= tol2) continue;
    const Vec2 d = q - p;
    const double dd = kernel::dot(d, d);
    const double t = dd > 0 ? kernel::dot(v - p, d) / dd : -1;
    if (t <= 0 || t >= 1) continue;
    const Vec2 foot = p + d * t;
    if (dist2(v, foot) > tol2) continue;
    v = foot;
    return true;
  }
  return false;
}

}  // namespace

void weld(const std::vector<Polygon*>& cells, double tolerance) {
  std::size_t vertices = 0;
  for (const Polygon* c : cells) {
    vertices += c->outer.size();
    for (const Ring& h : c->holes) vertices += h.size();
  }
  std::vector<Vec2*> points;
  points.reserve(vertices);
  for (Polygon* c : cells) {
    for (Vec2& v : c->outer) points.push_back(&v);
    for (Ring& h : c->holes)
      for (Vec2& v : h) points.push_back(&v);
  }
  // Vertex clusters: sorted by x (then index), each point takes the first earlier representative
  // in reach. The keys are sorted with the points' indices, not through the pointers.
  std::vector<Vec2> original(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) original[i] = *points[i];
  std::vector<std::pair<double, std::size_t>> by_x(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) by_x[i] = {original[i].x, i};
  std::sort(by_x.begin(), by_x.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  });
  const double tol2 = tolerance * tolerance;
  auto dist2 = [](Vec2 a, Vec2 b) { return kernel::dot(a - b, a - b); };
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const std::size_t i = by_x[k].second;
    for (std::size_t m = k; m-- > 0;) {
      const std::size_t j = by_x[m].second;
      if (original[i].x - original[j].x > tolerance) break;
      if (dist2(original[i], original[j]) <= tol2) {
        *points[i] = *points[j];
        break;
      }
    }
  }
  // T-junctions: a vertex on another cell's edge goes exactly onto that edge. Cells are visited
  // in order and each vertex tries the touching cells in index order (the first edge wins).
  std::vector<kernel::Bounds2> boxes;
  boxes.reserve(cells.size());
  for (const Polygon* c : cells) boxes.push_back(kernel::bounds(*c));
  const NearLists lists = touching_boxes(boxes, tolerance);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    auto snap_ring = [&](Ring& ring) {
      for (Vec2& v : ring) {
        kernel::Bounds2 pb;
        pb.min = v;
        pb.max = v;
        for (std::uint32_t k = lists.start[i]; k < lists.start[i + 1]; ++k) {
          const std::size_t j = lists.near[k];
          if (!kernel::touches(pb, boxes[j], tolerance)) continue;
          if (snap_to_ring(v, cells[j]->outer, tolerance)) break;
          bool done = false;
          for (const Ring& h : cells[j]->holes) done = done || snap_to_ring(v, h, tolerance);
          if (done) break;
        }
      }
    };
    snap_ring(cells[i]->outer);
    for (Ring& h : cells[i]->holes) snap_ring(h);
  }
  for (Polygon* c : cells) simplify(*c);
}

bool convex_overlap(const Polygon& a, const Polygon& b) {
  auto separated = [](const Ring& p, const Ring& q) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 e = p[(i + 1) % n] - p[i];
      const Vec2 axis{-e.y, e.x};
      const double len = kernel::length(axis);
      if (len <= 0) continue;
      double pmin = 1e300, pmax = -1e300, qmin = 1e300, qmax = -1e300;
      for (Vec2 v : p) {
        const double d = kernel::dot(v, axis) / len;
        pmin = std::min(pmin, d);
        pmax = std::max(pmax, d);
      }
      for (Vec2 v : q) {
        const double d = kernel::dot(v, axis) / len;
        qmin = std::min(qmin, d);
        qmax = std::max(qmax, d);
      }
      if (pmax <= qmin + 1e-9 || qmax <= pmin + 1e-9) return true;
    }
    return false;
  };
  return !separated(a.outer, b.outer) && !separated(b.outer, a.outer);
}

bool convex_inside(const Polygon& region, const Ring& inner) {
  for (Vec2 v : inner)
    if (kernel::locate(region, v, 1e-7) == kernel::PointLocation::kOutside) return false;
  const double sign = kernel::signed_area(inner) >= 0 ? 1 : -1;
  auto strictly_inside = [&](Vec2 p) {
    const std::size_t n = inner.size();
    for (std::size_t i = 0; i < n; ++i)
      if (sign * kernel::cross(inner[(i + 1) % n] - inner[i], p - inner[i]) <= 1e-9) return false;
    return true;
  };
  auto ring_ok = [&](const Ring& r) {
    const std::size_t n = r.size();
    const std::size_t m = inner.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (strictly_inside(r[i])) return false;
      for (std::size_t j = 0; j < m; ++j)
        if (kernel::segments_cross_properly(r[i], r[(i + 1) % n], inner[j], inner[(j + 1) % m]))
          return false;
    }
    return true;
  };
  if (!ring_ok(region.outer)) return false;
  return std::all_of(region.holes.begin(), region.holes.end(), ring_ok);
}

int largest(const std::vector<Polygon>& polygons) {
  int best = -1;
  double best_area = -1;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const double a = kernel::area(polygons[i]);
    if (a > best_area) {
      best_area = a;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace insula::lang::bldg::plan
