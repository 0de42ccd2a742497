#include "lang/bldg/plan_treemap.h"

#include <algorithm>
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/planar.h"
#include "lang/bldg/plan_geometry.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

struct AreaFunction {
  const std::vector<Polygon>& region;
  bool along_x;
  TreemapStats& stats;
  double operator()(double t) const {
    ++stats.area_evaluations;
    return area_below(region, along_x, t);
  }
};

// Bisection of the widths [lo, hi] from `start` (the area below `target` at lo, above it at hi)
// for a width whose area is within `tolerance` of the target, or the middle of a bracket
// narrower than `width`.
double bisect(const AreaFunction& area, double start, double lo, double hi, double target,
              double tolerance, double width) {
  for (int k = 0; k < 100 && hi - lo > width; ++k) {
    const double mid = 0.5 * (lo + hi);
    const double f = area(start + mid) - target;
    if (std::abs(f) <= tolerance) return mid;
    (f < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The end coordinate of rectangle i: starts at `start` with width w0 (Eq. 2), scaled by +-step
// until area_below crosses `target` (Eqs. 4-5), then bisected within the last step.
double place_cut(const AreaFunction& area, double start, double w0, double extent, double step,
                 double target, double tolerance, double end) {
  const double delta = step * extent;
  double w = std::clamp(w0, 0.0, end - start);
  double f = area(start + w) - target;
  double lo = w;
  double hi = w;
  if (f < 0) {
    // w stops growing at end - start, and start + (end - start) may round below end: without
    // the width test the loop would then repeat that last step forever (a region whose area up
    // to `end` stays below the target, e.g. two pieces side by side).
    while (f < 0 && start + w < end && w < end - start) {  // grow: Sx = (width + step) / width
      lo = w;
      w = std::min(w + delta, end - start);
      f = area(start + w) - target;
      ++area.stats.scaling_steps;
    }
    hi = w;
  } else {
    while (f > 0 && w > 0) {  // shrink: Sx = (width - step) / width
      hi = w;
      w = std::max(w - delta, 0.0);
      f = area(start + w) - target;
      ++area.stats.scaling_steps;
    }
    lo = w;
  }
  if (std::abs(f) <= tolerance) return start + w;
  return start + bisect(area, start, lo, hi, target, tolerance, 1e-12 * std::max(1.0, extent));
}

// The part of `ring` where sign x (coord - t) <= 0: exact for a convex ring (the cut lies exactly
// on the line, with no boolean grid), which is most cells.
void clip(const kernel::Ring& ring, bool along_x, double t, double sign, kernel::Ring& out) {
  const kernel::Vec2 normal = along_x ? kernel::Vec2{-sign, 0} : kernel::Vec2{0, -sign};
  kernel::clip(ring, {{t, t}, normal}, out);
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
  const AreaFunction area{region, along_x, s};
  // One convex ring (most regions): cuts need no corner snapping and cells are clipped directly.
  const bool fast = region.size() == 1 && region[0].holes.empty() &&
                    kernel::is_convex(region[0].outer, kernel::Winding::kCounterClockwise, 1e-12);
  // Cut coordinates: cuts[i] ends child i; the first starts at the minimum rectangle (Eq. 1).
  std::vector<double> cuts(weights.size() + 1, 0.0);
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
  kernel::Ring after_start;  // the convex path's cuts, their storage reused from cell to cell
  kernel::Ring before_end;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (fast) {
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
