#include "lang/bldg/plan_treemap.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

struct AreaFunction {
  const std::vector<Polygon>& region;
  bool along_x;
  TreemapStats& stats;
  // The region's only ring when it is one polygon without holes (most regions), else null:
  // area_below_axis's sum then has one term, (0 + twice) / 2, taken without its loops.
  const kernel::Ring* single = nullptr;
  double operator()(double t) const {
    ++stats.area_evaluations;
    if (single != nullptr) {
      const double twice = along_x ? detail::clipped_twice_area<true>(*single, t)
                                   : detail::clipped_twice_area<false>(*single, t);
      return (0.0 + twice) / 2;
    }
    return along_x ? area_below_axis<true>(region, t) : area_below_axis<false>(region, t);
  }
};

// An end of the bisection bracket: a width and its area's departure from the target.
struct Probe {
  double at;
  double f;
};

// Bisection of [lo, hi] for the width whose area is within `tolerance` of `target`: the plain
// loop
//     for (k = 0; k < 100 && hi - lo > width; ++k) {
//       mid = (lo + hi) / 2; fm = area(start + mid) - target;
//       if (|fm| <= tolerance) return mid;  (fm < 0 ? lo : hi) = mid;
//     }
//     return (lo + hi) / 2;
// with the same probes' outcomes but fewer area evaluations. After a probe lands on one side,
// the loop's next probes, for as long as they land on that side too, are known in advance (the
// moving end takes each in turn). The area below a line only grows as the line moves, so along
// such a run the probes landing on that side form a prefix, and only where it ends matters. A
// guess of that index (the area interpolated linearly between the bracket's ends, exact up to
// rounding where the region's width across the axis is constant, i.e. in rectangles) is checked
// with its neighbour, then galloping away from it and halving find the true end whatever the
// guess. Long runs are common: a rectangle's first guess (Eq. 2) is exact up to rounding, and the
// loop then walks from one Eq. 5 step back down to it, 20-25 halvings to the 1e-9 tolerance. The
// probes of a run are a tolerance apart or more in area, far above the area sum's rounding, so
// the prefix found is the loop's and the result the same bits. `lo` and `hi` carry the departures
// already evaluated at the bracket's ends (place_cut's last Eq. 5 steps).
template <typename Area>
double bisect(const Area& area, double start, Probe lo, Probe hi, double target, double tolerance,
              double width) {
  constexpr int kMaxProbes = 100;
  std::array<double, kMaxProbes> run;
  const auto departure = [&](double at) { return area(start + at) - target; };
  int k = 0;
  while (k < kMaxProbes && hi.at - lo.at > width) {
    const Probe mid{0.5 * (lo.at + hi.at), departure(0.5 * (lo.at + hi.at))};
    ++k;
    if (std::abs(mid.f) <= tolerance) return mid.at;
    const bool below = mid.f < 0;  // below: lo moves up to each probe; else hi moves down
    (below ? lo : hi) = mid;
    const Probe fixed = below ? hi : lo;
    const auto same_side = [&](double f) { return below ? f < -tolerance : f > tolerance; };
    // The loop's next probes while each lands on the same side, up to its iteration limits, and
    // the first whose interpolated departure does not. The run is listed only a few probes past
    // that guess: should it go on further, the loop's next round takes it up.
    constexpr std::size_t kPastGuess = 8;
    const double slope = (mid.f - fixed.f) / (mid.at - fixed.at);
    const auto room = static_cast<std::size_t>(kMaxProbes - k);  // the loop's iterations left
    std::size_t n = 0;
    std::size_t guess = kMaxProbes;
    // The moving end takes each probe in turn, the fixed one stays: one loop per direction, up to
    // the guess (tested at each probe), then one listing kPastGuess probes further.
    double l = lo.at;
    double h = hi.at;
    const auto list = [&](double& moving, const double& other, std::size_t limit, bool find) {
      while (n < limit && h - l > width) {
        const double m = 0.5 * (moving + other);
        run[n++] = m;
        moving = m;
        if (find && !same_side(fixed.f + slope * (m - fixed.at))) {
          guess = n - 1;
          return;
        }
      }
    };
    if (below) {
      list(l, h, room, true);
      if (guess != kMaxProbes) list(l, h, std::min(room, guess + kPastGuess), false);
    } else {
      list(h, l, room, true);
      if (guess != kMaxProbes) list(h, l, std::min(room, guess + kPastGuess), false);
    }
    if (n == 0) break;
    // run[0, a) land on the same side (the last at departure fa), run[b, n) do not (the first
    // at departure fb; b == n: none listed does not).
    std::size_t a = 0;
    std::size_t b = n;
    double fa = mid.f;
    double fb = 0;
    const auto probe = [&](std::size_t m) {
      const double f = departure(run[m]);
      if (same_side(f)) {
        a = m + 1;
        fa = f;
        return true;
      }
      b = m;
      fb = f;
      return false;
    };
    std::size_t step = 1;
    if (probe(std::min(guess, n - 1))) {
      while (a < b && probe(std::min(a + step, b) - 1)) step *= 2;
    } else {
      while (a < b && !probe(b - std::min(step, b - a))) step *= 2;
    }
    while (a < b) probe(a + (b - a) / 2);
    if (b > 0) (below ? lo : hi) = Probe{run[b - 1], fa};
    k += static_cast<int>(b);
    if (b == n) continue;  // the whole list landed on the same side: the loop goes on from there
    // run[b] is the loop's next probe, and lands within the tolerance or on the other side.
    ++k;
    if (std::abs(fb) <= tolerance) return run[b];
    (below ? hi : lo) = Probe{run[b], fb};
  }
  return 0.5 * (lo.at + hi.at);
}

// The end coordinate of rectangle i: starts at `start` with width w0 (Eq. 2), scaled by +-step
// until area_below crosses `target` (Eqs. 4-5), then bisected within the last step.
double place_cut(const AreaFunction& area, double start, double w0, double extent, double step,
                 double target, double tolerance, double end) {
  const double delta = step * extent;
  double w = std::clamp(w0, 0.0, end - start);
  double f = area(start + w) - target;
  Probe lo{w, f};
  Probe hi{w, f};
  if (f < 0) {
    // w stops growing at end - start, and start + (end - start) may round below end: without
    // the width test the loop would then repeat that last step forever (a region whose area up
    // to `end` stays below the target, e.g. two pieces side by side).
    while (f < 0 && start + w < end && w < end - start) {  // grow: Sx = (width + step) / width
      lo = {w, f};
      w = std::min(w + delta, end - start);
      f = area(start + w) - target;
      ++area.stats.scaling_steps;
    }
    hi = {w, f};
  } else {
    while (f > 0 && w > 0) {  // shrink: Sx = (width - step) / width
      hi = {w, f};
      w = std::max(w - delta, 0.0);
      f = area(start + w) - target;
      ++area.stats.scaling_steps;
    }
    lo = {w, f};
  }
  if (std::abs(f) <= tolerance) return start + w;
  return start + bisect(area, start, lo, hi, target, tolerance, 1e-12 * std::max(1.0, extent));
}

bool convex(const kernel::Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return true;
  // Consecutive triples (a, b, c), wrapping around, without a division per vertex.
  kernel::Vec2 a = ring[n - 2];
  kernel::Vec2 b = ring[n - 1];
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::Vec2 c = ring[i];
    if (kernel::cross(b - a, c - b) < -1e-12) return false;
    a = b;
    b = c;
  }
  return true;
}

// Sutherland-Hodgman against sign x (coord - t) <= 0: exact for a convex ring (the cut lies
// exactly on the line, with no boolean grid), which is most cells. Writes into `out` (cleared).
void clip(const kernel::Ring& ring, bool along_x, double t, double sign, kernel::Ring& out) {
  out.clear();
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::Vec2 p = ring[i];
    const kernel::Vec2 q = ring[i + 1 < n ? i + 1 : 0];
    const double cp = sign * ((along_x ? p.x : p.y) - t);
    const double cq = sign * ((along_x ? q.x : q.y) - t);
    if (cp <= 0) out.push_back(p);
    if ((cp < 0 && cq > 0) || (cp > 0 && cq < 0)) {
      kernel::Vec2 x = p + (q - p) * (cp / (cp - cq));
      (along_x ? x.x : x.y) = t;
      out.push_back(x);
    }
  }
}

// On a concave or holed region, a cut passing within kSnap (1 m) of a vertex strictly inside the
// region's extent (a reflex corner, a courtyard's edge) would leave a sliver of room beside it:
// the cut moves onto the vertex. The cell's area then departs from its target by at most kSnap
// times the region's width (docs/bldg-floorplan.md). Convex regions have no such vertex.
constexpr double kSnap = 1.0;

double snap_to_corner(const std::vector<Polygon>& region, bool simple, bool along_x,
                      double previous, double t, double lo, double hi) {
  double best = t;
  double best_d = kSnap;
  auto consider = [&](const kernel::Ring& ring) {
    for (kernel::Vec2 v : ring) {
      const double c = along_x ? v.x : v.y;
      if (c <= lo + kSnap || c >= hi - kSnap || c <= previous + kSnap) continue;
      const double d = std::abs(c - t);
      if (d > 1e-9 && d < best_d) {
        best_d = d;
        best = c;
      }
    }
  };
  if (simple) return t;
  for (const Polygon& p : region) {
    consider(p.outer);
    for (const kernel::Ring& h : p.holes) consider(h);
  }
  return best;
}

}  // namespace

std::vector<std::vector<Polygon>> split_region(const std::vector<Polygon>& region,
                                               const std::vector<double>& weights, bool along_x,
                                               double step, TreemapStats* stats) {
  TreemapStats local;
  TreemapStats& s = stats != nullptr ? *stats : local;
  std::vector<std::vector<Polygon>> cells(weights.size());
  if (weights.empty()) return cells;
  if (weights.size() == 1) {
    cells[0] = region;
    return cells;
  }
  if (!(step > 0 && step <= 0.5)) step = 0.01;
  const kernel::Bounds2 box = bounds_of(region);
  const double lo = along_x ? box.min.x : box.min.y;
  const double hi = along_x ? box.max.x : box.max.y;
  const double extent = hi - lo;
  const double total_area = area_of(region);
  double total_weight = 0;
  for (double w : weights) total_weight += w;
  const AreaFunction area{
      region, along_x, s,
      region.size() == 1 && region[0].holes.empty() ? &region[0].outer : nullptr};
  // One convex ring (most regions): cuts need no corner snapping and cells are clipped directly.
  const bool fast = region.size() == 1 && region[0].holes.empty() && convex(region[0].outer);
  // Cut coordinates: cuts[i] ends child i; the first starts at the minimum rectangle (Eq. 1).
  thread_local std::vector<double> cuts;  // scratch reused from call to call
  cuts.assign(weights.size() + 1, 0.0);
  cuts[0] = lo;
  cuts.back() = hi;
  double cumulative = 0;
  for (std::size_t i = 0; i + 1 < weights.size(); ++i) {
    const double relative = weights[i] / total_weight;
    cumulative += relative;
    cuts[i + 1] = place_cut(area, cuts[i], extent * relative, extent, step, total_area * cumulative,
                            1e-9 * total_area, hi);
    cuts[i + 1] = snap_to_corner(region, fast, along_x, cuts[i], cuts[i + 1], lo, hi);
  }
  // Eq. 3: each auxiliary rectangle (reaching past the region across the axis, and past the
  // minimum rectangle at both ends of the row) intersected with the region.
  const double pad = 1 + 0.01 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (fast) {
      thread_local kernel::Ring after_start;  // scratch rings reused from cell to cell
      thread_local kernel::Ring before_end;
      const kernel::Ring* ring = &region[0].outer;
      if (i > 0) {
        clip(*ring, along_x, cuts[i], -1, after_start);
        ring = &after_start;
      }
      if (i + 1 < weights.size()) {
        clip(*ring, along_x, cuts[i + 1], 1, before_end);
        ring = &before_end;
      }
      Polygon p{*ring, {}};
      simplify(p);
      if (p.outer.size() >= 3 && kernel::area(p) > 1e-9) cells[i].push_back(std::move(p));
      continue;
    }
    const double a = i == 0 ? lo - pad : cuts[i];
    const double b = i + 1 == weights.size() ? hi + pad : cuts[i + 1];
    if (b - a <= 0) continue;
    const Polygon rect = along_x ? rectangle(a, box.min.y - pad, b, box.max.y + pad)
                                 : rectangle(box.min.x - pad, a, box.max.x + pad, b);
    kernel::BooleanResult r = kernel::intersect(region, {rect});
    if (!r.ok()) continue;
    for (Polygon& p : r.polygons) {
      simplify(p);
      if (p.outer.size() >= 3 && kernel::area(p) > 1e-9) cells[i].push_back(std::move(p));
    }
  }
  return cells;
}

}  // namespace insula::lang::bldg::plan
