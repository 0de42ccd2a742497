// Straight skeleton of rectilinear polygons by a kinetic wavefront with one global event step.
//
// Why this works (Aichholzer, Aurenhammer, Alberts, Gärtner 1995; Eppstein & Erickson 1999 for
// the orthogonal case): in a rectilinear polygon every wavefront edge stays on its contour edge's
// line moved inward at unit speed, and every wavefront vertex moves diagonally (or across its line,
// for a straight vertex). The region the wavefront bounds at time t is the polygon eroded by an
// axis-parallel square of half-side t, so at an event time T the wavefront after the event is the
// boundary of the (regularized) region the wavefront encloses at T. The step below computes it
// directly: it classifies the cells of the grid spanned by the vertex coordinates by winding
// number, traces the boundary of the inside cells and labels each new edge with the contour edge
// of the old wavefront edge it lies on. Edge collapses, splits, vertex events, zero-width slivers
// and several events at one point are all the same step, which is what makes the many
// simultaneous events of symmetric building outlines (where CGAL's filtered predicates fall back
// to exact arithmetic) cheap and exact: every coordinate is a contour coordinate plus or minus t.
// Old vertices that do not survive end at a skeleton node, new ones start at one, and slivers of
// zero width become ridge arcs between the faces of their two edges.
#include "kernel/skeleton_rectilinear.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

#include "kernel/skeleton_faces.h"

namespace insula::kernel {
namespace {

constexpr std::uint32_t kNone = 0xffffffffU;

// Above this many contour vertices the O(n^2)-per-event search and grid could take seconds on
// outlines with many separate events; CGAL takes them. (A 1,002-vertex comb takes ~5 ms,
// bench/roof_bench.cc.)
constexpr std::size_t kMaxVertices = 1024;

// A contour edge's supporting line moved inward at unit speed: its y (horizontal edge) or x
// (vertical edge) at time t is base + sign * t, sign being the inward normal's component.
struct Line {
  bool horizontal = false;
  double base = 0;
  double sign = 0;
  double at(double t) const { return base + sign * t; }
};

// A coordinate moving linearly: base + rate * t.
struct Motion {
  double base = 0;
  double rate = 0;
  double at(double t) const { return base + rate * t; }
};

// A wavefront vertex between the wavefront edges of contour edges `in` and `out`. A straight
// vertex (both edges on one line) keeps its coordinate along that line, `along`.
struct WaveVertex {
  std::uint32_t in = 0;
  std::uint32_t out = 0;
  double along = 0;
  std::uint32_t start = 0;  // the skeleton node where its trace began
};
using Cycle = std::vector<WaveVertex>;

// Sorted distinct coordinates of one axis; values closer than the tolerance are one grid line.
class Axis {
 public:
  Axis(std::vector<double> values, double tolerance) {
    std::sort(values.begin(), values.end());
    for (double v : values) {
      if (!lines_.empty() && v - last_.back() <= tolerance) {
        last_.back() = v;
      } else {
        lines_.push_back(v);
        last_.push_back(v);
      }
    }
  }
  std::uint32_t index(double v) const {
    return static_cast<std::uint32_t>(std::lower_bound(last_.begin(), last_.end(), v) -
                                      last_.begin());
  }
  std::uint32_t size() const { return static_cast<std::uint32_t>(lines_.size()); }
  double operator[](std::uint32_t i) const { return lines_[i]; }

 private:
  std::vector<double> lines_;  // the first value of each group: the grid line's coordinate
  std::vector<double> last_;   // the last value of each group, for lookup
};

// An old wavefront edge lying on a grid line, over grid points [lo, hi].
struct LineEdge {
  std::uint32_t line, lo, hi, label;
  double sign;
};

// A unit segment of the new wavefront: from grid point `from` in direction `dir` (0 +x, 1 +y,
// 2 -x, 3 -y), on the old wavefront edge of contour edge `label`.
struct Unit {
  std::uint32_t from;
  int dir;
  std::uint32_t label;
};

class Builder {
 public:
  Builder(const Polygon& polygon, Skeleton& out) : out_(out) {
    Vec2 lo = polygon.outer[0], hi = lo;
    double largest = 0;
    auto add_ring = [&](const Ring& ring) {
      const auto first = static_cast<std::uint32_t>(out_.vertices.size());
      const auto m = static_cast<std::uint32_t>(ring.size());
      out_.ring_starts.push_back(first);
      for (std::uint32_t k = 0; k < m; ++k) {
        const Vec2 p = ring[k];
        out_.vertices.push_back({p, 0.0});
        lines_.push_back(line_of(p, ring[(k + 1) % m]));
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
      }
      Cycle cycle;
      for (std::uint32_t k = 0; k < m; ++k) {
        const std::uint32_t before = first + (k + m - 1) % m;
        const double along = lines_[first + k].horizontal ? ring[k].x : ring[k].y;
        cycle.push_back({before, first + k, along, first + k});
      }
      cycles_.push_back(std::move(cycle));
    };
    add_ring(polygon.outer);
    for (const Ring& hole : polygon.holes) add_ring(hole);
    out_.contour_count = static_cast<std::uint32_t>(out_.vertices.size());
    out_.ring_starts.push_back(out_.contour_count);
    // Coordinates are contour coordinates plus or minus a time, so they carry a few ulps of the
    // largest absolute coordinate; features below 1e-10 of the outline's size are merged.
    tolerance_ = 1e-10 * std::max({hi.x - lo.x, hi.y - lo.y, 1e-300}) + 1e-14 * largest;
    area_ = area(polygon);
  }

  // Regions of the wavefront (an outer cycle and its holes) never meet again once apart, so each
  // is advanced on its own: event search and grid stay the size of one region.
  bool run() {
    std::vector<std::vector<Cycle>> pending{std::move(cycles_)};
    std::vector<double> since{0.0};
    const std::size_t limit = 8 * out_.contour_count + 64;
    for (std::size_t steps = 0; !pending.empty(); ++steps) {
      std::vector<Cycle> cycles = std::move(pending.back());
      const double now = since.back();
      pending.pop_back();
      since.pop_back();
      const double t = next_event(cycles, now);
      if (steps == limit || !std::isfinite(t) || !advance(cycles, t)) return false;
      if (!split_regions(std::move(cycles), t, pending)) return false;
      since.resize(pending.size(), t);
    }
    return assemble_skeleton_faces(arcs_, out_) && faces_valid();
  }

 private:
  static Line line_of(Vec2 p, Vec2 q) {
    if (p.y == q.y) return {true, p.y, q.x > p.x ? 1.0 : -1.0};
    return {false, p.x, q.y > p.y ? -1.0 : 1.0};
  }

  Motion x_of(const WaveVertex& v) const {
    if (!lines_[v.in].horizontal) return {lines_[v.in].base, lines_[v.in].sign};
    if (!lines_[v.out].horizontal) return {lines_[v.out].base, lines_[v.out].sign};
    return {v.along, 0};
  }
  Motion y_of(const WaveVertex& v) const {
    if (lines_[v.in].horizontal) return {lines_[v.in].base, lines_[v.in].sign};
    if (lines_[v.out].horizontal) return {lines_[v.out].base, lines_[v.out].sign};
    return {v.along, 0};
  }
  // The vertex's coordinate along the line of `edge`, and across it.
  Motion along(const WaveVertex& v, const Line& edge) const {
    return edge.horizontal ? x_of(v) : y_of(v);
  }
  Motion across(const WaveVertex& v, const Line& edge) const {
    return edge.horizontal ? y_of(v) : x_of(v);
  }

  // The first time after `now` at which a wavefront edge collapses or a vertex reaches a
  // wavefront edge it is not part of (split and vertex events); infinity when none.
  double next_event(const std::vector<Cycle>& cycles, double now) const {
    const double after = now + tolerance_;
    double best = std::numeric_limits<double>::infinity();
    for (const Cycle& c : cycles) {
      for (std::size_t i = 0; i < c.size(); ++i) {
        const WaveVertex& a = c[i];
        const WaveVertex& b = c[(i + 1) % c.size()];
        const Line& edge = lines_[a.out];
        const Motion pa = along(a, edge), pb = along(b, edge);
        if (pa.rate != pb.rate) {
          const double t = (pb.base - pa.base) / (pa.rate - pb.rate);
          if (t > after && t < best) best = t;
        }
        for (const Cycle& d : cycles) {
          for (const WaveVertex& v : d) {
            if (&v == &a || &v == &b) continue;
            const Motion m = across(v, edge);
            if (m.rate == edge.sign) continue;  // moves with the edge: never meets it
            if (edge.sign * (m.at(now) - edge.at(now)) < -tolerance_) continue;  // behind it
            const double t = (edge.base - m.base) / (m.rate - edge.sign);
            if (!(t > after && t < best)) continue;
            const double s = along(v, edge).at(t);
            const double lo = std::min(pa.at(t), pb.at(t)), hi = std::max(pa.at(t), pb.at(t));
            if (s >= lo - tolerance_ && s <= hi + tolerance_) best = t;
          }
        }
      }
    }
    return best;
  }

  // The global event step at `time` (see the file comment).
  bool advance(std::vector<Cycle>& cycles, double time);
  // Groups the cycles into regions (a counter-clockwise cycle and the clockwise ones inside it)
  // appended to `regions`; false if a clockwise cycle lies in none.
  bool split_regions(std::vector<Cycle> cycles, double time,
                     std::vector<std::vector<Cycle>>& regions) const;
  bool faces_valid() const;

  Skeleton& out_;
  std::vector<Line> lines_;  // per contour edge
  std::vector<Cycle> cycles_;
  std::vector<SkeletonArc> arcs_;
  double tolerance_ = 0;
  double area_ = 0;
};

// State of one event step: the grid spanned by the wavefront's vertices at the event time.
class EventGrid {
 public:
  EventGrid(std::vector<double> xs, std::vector<double> ys, double tolerance)
      : x_(std::move(xs), tolerance), y_(std::move(ys), tolerance) {
    nx_ = x_.size();
    ny_ = y_.size();
    winding_.assign(static_cast<std::size_t>(nx_) * (ny_ > 0 ? ny_ - 1 : 0), 0);
    node_.assign(static_cast<std::size_t>(nx_) * ny_, kNone);
  }
  const Axis& x() const { return x_; }
  const Axis& y() const { return y_; }
  std::uint32_t point(std::uint32_t ix, std::uint32_t iy) const { return iy * nx_ + ix; }
  std::uint32_t px(std::uint32_t p) const { return p % nx_; }
  std::uint32_t py(std::uint32_t p) const { return p / nx_; }
  std::uint32_t nx() const { return nx_; }
  std::uint32_t ny() const { return ny_; }

  // A vertical wavefront edge from row iy0 to row iy1 on grid column ix. Cells right of a
  // downward edge gain +1: with outer rings counter-clockwise and holes clockwise the winding
  // number is 1 inside the wavefront and 0 outside.
  void add_vertical(std::uint32_t ix, std::uint32_t iy0, std::uint32_t iy1) {
    const int delta = iy1 < iy0 ? 1 : -1;
    for (std::uint32_t row = std::min(iy0, iy1); row < std::max(iy0, iy1); ++row) {
      winding_[static_cast<std::size_t>(row) * nx_ + ix] += delta;
    }
  }
  // Turns the per-column deltas into winding numbers; false when some cell is neither inside
  // (1) nor outside (0), i.e. the wavefront overlapped itself.
  bool accumulate() {
    for (std::uint32_t row = 0; row + 1 < ny_; ++row) {
      int sum = 0;
      for (std::uint32_t ix = 0; ix < nx_; ++ix) {
        sum += winding_[static_cast<std::size_t>(row) * nx_ + ix];
        winding_[static_cast<std::size_t>(row) * nx_ + ix] = sum;
        if (sum != 0 && sum != 1) return false;
      }
    }
    return true;
  }
  // Whether the cell right of column ix and above row iy is inside (false outside the grid).
  bool inside(std::int64_t ix, std::int64_t iy) const {
    if (ix < 0 || iy < 0 || ix + 1 >= nx_ || iy + 1 >= ny_) return false;
    return winding_[static_cast<std::size_t>(iy) * nx_ + static_cast<std::size_t>(ix)] == 1;
  }
  std::uint32_t& node(std::uint32_t p) { return node_[p]; }

 private:
  Axis x_, y_;
  std::uint32_t nx_ = 0, ny_ = 0;
  std::vector<int> winding_;         // per cell: row * nx + column (the last column unused)
  std::vector<std::uint32_t> node_;  // per grid point: the node made in this step, or kNone
};

// The old wavefront edge on `line` facing `sign` that covers [lo, lo + 1], or kNone.
std::uint32_t label_of(const std::vector<LineEdge>& edges, std::uint32_t line, std::uint32_t lo,
                       double sign) {
  for (const LineEdge& e : edges) {
    if (e.line == line && e.sign == sign && e.lo <= lo && lo + 1 <= e.hi) return e.label;
  }
  return kNone;
}

bool Builder::advance(std::vector<Cycle>& cycles, double time) {
  // 1. Where every vertex is at `time`, snapped to the grid of distinct coordinates.
  std::vector<double> xs, ys;
  for (const Cycle& c : cycles) {
    for (const WaveVertex& v : c) {
      xs.push_back(x_of(v).at(time));
      ys.push_back(y_of(v).at(time));
    }
  }
  EventGrid grid(xs, ys, tolerance_);
  struct Old {
    std::uint32_t point, in, out, start;
    bool survives;
  };
  std::vector<Old> old;
  std::vector<LineEdge> horizontal, vertical;
  for (const Cycle& c : cycles) {
    const std::size_t first = old.size();
    for (const WaveVertex& v : c) {
      const std::uint32_t p =
          grid.point(grid.x().index(x_of(v).at(time)), grid.y().index(y_of(v).at(time)));
      old.push_back({p, v.in, v.out, v.start, false});
    }
    // 2. The old wavefront's edges on their grid lines, and the winding numbers they give.
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::uint32_t a = old[first + i].point;
      const std::uint32_t b = old[first + (i + 1) % c.size()].point;
      const Line& edge = lines_[c[i].out];
      if (edge.horizontal) {
        if (grid.py(a) != grid.py(b)) return false;
        const std::uint32_t lo = std::min(grid.px(a), grid.px(b));
        const std::uint32_t hi = std::max(grid.px(a), grid.px(b));
        if (lo < hi) horizontal.push_back({grid.py(a), lo, hi, c[i].out, edge.sign});
      } else {
        if (grid.px(a) != grid.px(b)) return false;
        const std::uint32_t lo = std::min(grid.py(a), grid.py(b));
        const std::uint32_t hi = std::max(grid.py(a), grid.py(b));
        if (lo < hi) vertical.push_back({grid.px(a), lo, hi, c[i].out, edge.sign});
        grid.add_vertical(grid.px(a), grid.py(a), grid.py(b));
      }
    }
  }
  if (!grid.accumulate()) return false;

  // 3. The boundary of the inside cells as unit segments, inside on their left.
  std::vector<Unit> units;
  for (std::uint32_t iy = 0; iy < grid.ny(); ++iy) {
    for (std::uint32_t ix = 0; ix + 1 < grid.nx(); ++ix) {
      const bool above = grid.inside(ix, iy), below = grid.inside(ix, std::int64_t{iy} - 1);
      if (above == below) continue;
      const std::uint32_t label = label_of(horizontal, iy, ix, above ? 1.0 : -1.0);
      if (label == kNone) return false;
      units.push_back(above ? Unit{grid.point(ix, iy), 0, label}
                            : Unit{grid.point(ix + 1, iy), 2, label});
    }
  }
  for (std::uint32_t ix = 0; ix < grid.nx(); ++ix) {
    for (std::uint32_t iy = 0; iy + 1 < grid.ny(); ++iy) {
      const bool right = grid.inside(ix, iy), left = grid.inside(std::int64_t{ix} - 1, iy);
      if (right == left) continue;
      const std::uint32_t label = label_of(vertical, ix, iy, right ? 1.0 : -1.0);
      if (label == kNone) return false;
      units.push_back(right ? Unit{grid.point(ix, iy + 1), 3, label}
                            : Unit{grid.point(ix, iy), 1, label});
    }
  }

  // 4. Trace the new cycles. Where two inside cells touch only at a corner, turning left keeps
  // them apart: their corners move away from each other.
  std::vector<std::uint32_t> outgoing(static_cast<std::size_t>(grid.nx()) * grid.ny() * 2, kNone);
  for (std::uint32_t u = 0; u < units.size(); ++u) {
    std::uint32_t* slot = &outgoing[static_cast<std::size_t>(units[u].from) * 2];
    if (slot[0] != kNone) ++slot;
    if (*slot != kNone) return false;
    *slot = u;
  }
  auto end_of = [&](const Unit& u) {
    const std::uint32_t ix = grid.px(u.from), iy = grid.py(u.from);
    switch (u.dir) {
      case 0:
        return grid.point(ix + 1, iy);
      case 1:
        return grid.point(ix, iy + 1);
      case 2:
        return grid.point(ix - 1, iy);
      default:
        return grid.point(ix, iy - 1);
    }
  };
  std::vector<bool> traced(units.size(), false);
  std::vector<Cycle> next;
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::size_t, std::size_t>>
      fresh;  // point, in, out, cycle, index of each new vertex
  for (std::uint32_t first = 0; first < units.size(); ++first) {
    if (traced[first]) continue;
    std::vector<std::uint32_t> loop;
    std::uint32_t u = first;
    while (!traced[u]) {
      traced[u] = true;
      loop.push_back(u);
      const std::uint32_t* slot = &outgoing[static_cast<std::size_t>(end_of(units[u])) * 2];
      std::uint32_t pick = slot[0];
      if (slot[1] != kNone && units[slot[1]].dir == (units[u].dir + 1) % 4) pick = slot[1];
      if (pick == kNone) return false;
      u = pick;
    }
    if (u != first) return false;
    Cycle cycle;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Unit& before = units[loop[(k + loop.size() - 1) % loop.size()]];
      const Unit& here = units[loop[k]];
      if (before.dir == here.dir && before.label == here.label) continue;
      const double along =
          here.dir % 2 == 0 ? grid.x()[grid.px(here.from)] : grid.y()[grid.py(here.from)];
      fresh.emplace_back(here.from, before.label, here.label, next.size(), cycle.size());
      cycle.push_back({before.label, here.label, along, kNone});
    }
    if (cycle.size() < 4) return false;
    next.push_back(std::move(cycle));
  }

  // 5. Vertices found again (same place, same edges) continue their trace; the others end here,
  // and the new ones start here.
  auto node_at = [&](std::uint32_t p) {
    std::uint32_t& id = grid.node(p);
    if (id == kNone) {
      id = static_cast<std::uint32_t>(out_.vertices.size());
      out_.vertices.push_back({{grid.x()[grid.px(p)], grid.y()[grid.py(p)]}, time});
    }
    return id;
  };
  std::sort(old.begin(), old.end(), [](const Old& a, const Old& b) {
    return std::tie(a.point, a.in, a.out) < std::tie(b.point, b.in, b.out);
  });
  for (const auto& [point, in, out, cycle, index] : fresh) {
    const Old key{point, in, out, 0, false};
    auto it = std::lower_bound(old.begin(), old.end(), key, [](const Old& a, const Old& b) {
      return std::tie(a.point, a.in, a.out) < std::tie(b.point, b.in, b.out);
    });
    if (it != old.end() && it->point == point && it->in == in && it->out == out && !it->survives) {
      it->survives = true;
      next[cycle][index].start = it->start;
    } else {
      next[cycle][index].start = node_at(point);
    }
  }
  for (const Old& o : old) {
    if (o.survives) continue;
    const std::uint32_t end = node_at(o.point);
    if (end != o.start) arcs_.push_back({o.start, end, o.in, o.out});
  }

  // 6. Zero-width slivers: two old edges facing each other on one line with nothing inside on
  // either side vanish at once; they leave a ridge between their faces, cut at this step's nodes.
  auto ridges = [&](const std::vector<LineEdge>& edges, bool along_x) {
    for (const LineEdge& a : edges) {
      if (a.sign < 0) continue;
      for (const LineEdge& b : edges) {
        if (b.sign > 0 || b.line != a.line) continue;
        const std::uint32_t lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
        std::uint32_t from = lo;
        for (std::uint32_t s = lo + 1; s <= hi; ++s) {
          const std::uint32_t p = along_x ? grid.point(s, a.line) : grid.point(a.line, s);
          if (s < hi && grid.node(p) == kNone) continue;
          const std::uint32_t q = along_x ? grid.point(from, a.line) : grid.point(a.line, from);
          // Along +x the face of the edge facing down (b) is above, on the left; along +y the
          // face of the edge facing +x (a) is on the left.
          if (along_x) {
            arcs_.push_back({node_at(q), node_at(p), b.label, a.label});
          } else {
            arcs_.push_back({node_at(q), node_at(p), a.label, b.label});
          }
          from = s;
        }
      }
    }
  };
  ridges(horizontal, true);
  ridges(vertical, false);
  cycles = std::move(next);
  return true;
}

// Whether p lies inside a rectilinear ring: crossings of the horizontal ray to the right with the
// ring's vertical edges, half-open in y.
bool ring_contains(const Ring& ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a.x != b.x || a.x <= p.x) continue;
    if ((a.y <= p.y) != (b.y <= p.y)) inside = !inside;
  }
  return inside;
}

bool Builder::split_regions(std::vector<Cycle> cycles, double time,
                            std::vector<std::vector<Cycle>>& regions) const {
  std::vector<Ring> rings(cycles.size());
  std::vector<double> areas(cycles.size());
  std::vector<std::size_t> outers;  // cycle ids of the counter-clockwise cycles
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    for (const WaveVertex& v : cycles[c]) rings[c].push_back({x_of(v).at(time), y_of(v).at(time)});
    areas[c] = signed_area(rings[c]);
    if (areas[c] > 0) outers.push_back(c);
  }
  if (outers.size() <= 1) {
    if (!cycles.empty()) regions.push_back(std::move(cycles));
    return true;
  }
  std::vector<std::size_t> region_of(cycles.size(), 0);
  for (std::size_t r = 0; r < outers.size(); ++r) region_of[outers[r]] = r;
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    if (areas[c] > 0) continue;
    // The midpoint of a hole's first edge lies strictly inside the hole's outer cycle, which is
    // the smallest counter-clockwise cycle around it (regions can nest in courtyards).
    const Vec2 probe = (rings[c][0] + rings[c][1]) / 2;
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < outers.size(); ++r) {
      if (areas[outers[r]] < smallest && ring_contains(rings[outers[r]], probe)) {
        smallest = areas[outers[r]];
        region_of[c] = r;
      }
    }
    if (!std::isfinite(smallest)) return false;
  }
  const std::size_t first = regions.size();
  regions.resize(first + outers.size());
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    regions[first + region_of[c]].push_back(std::move(cycles[c]));
  }
  return true;
}

// The faces tile the polygon and every face vertex lies at its time above the face's edge line.
bool Builder::faces_valid() const {
  double total = 0;
  Ring ring;
  for (std::uint32_t e = 0; e < out_.contour_count; ++e) {
    ring.clear();
    const Line& edge = lines_[e];
    for (std::uint32_t v : out_.face(e)) {
      const SkeletonVertex& s = out_.vertices[v];
      ring.push_back(s.position);
      const double distance =
          edge.sign * ((edge.horizontal ? s.position.y : s.position.x) - edge.base);
      if (!(s.time >= 0) || std::abs(distance - s.time) > 16 * tolerance_) return false;
    }
    const double a = signed_area(ring);
    if (!(a > 0)) return false;
    total += a;
  }
  return std::abs(total - area_) <= 1e-9 * area_;
}

}  // namespace

bool is_rectilinear(const Polygon& polygon) {
  auto ring_ok = [](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = ring[i], q = ring[(i + 1) % ring.size()];
      if (p.x != q.x && p.y != q.y) return false;
    }
    return ring.size() >= 4;
  };
  if (!ring_ok(polygon.outer)) return false;
  return std::all_of(polygon.holes.begin(), polygon.holes.end(), ring_ok);
}

std::optional<Skeleton> rectilinear_straight_skeleton(const Polygon& polygon) {
  std::size_t count = polygon.outer.size();
  for (const Ring& hole : polygon.holes) count += hole.size();
  if (count > kMaxVertices || !is_rectilinear(polygon)) return std::nullopt;
  Skeleton out;
  if (!Builder(polygon, out).run()) return std::nullopt;
  return out;
}

}  // namespace insula::kernel
