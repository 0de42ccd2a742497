#include "kernel/inner_rectangle.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace insula::kernel {

namespace {

struct Segment {
  Vec2 a;
  Vec2 b;
};

std::vector<Segment> segments_of(const Polygon& polygon) {
  std::vector<Segment> out;
  const auto add = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      out.push_back({ring[i], ring[(i + 1) % ring.size()]});
  };
  add(polygon.outer);
  for (const Ring& hole : polygon.holes) add(hole);
  return out;
}

// Whether segment ab passes through the open rectangle (lo, hi) (Liang-Barsky clipping; touching
// the rectangle's border does not count).
bool crosses_interior(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi, double eps) {
  lo = lo + Vec2{eps, eps};
  hi = hi - Vec2{eps, eps};
  if (lo.x >= hi.x || lo.y >= hi.y) return false;
  double t0 = 0;
  double t1 = 1;
  const Vec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] <= 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 >= t1) return false;
  }
  return true;
}

// The rectangle lies in the polygon: no boundary passes through its interior, no vertex (a hole
// inside it) lies strictly inside, and its centre is inside.
bool rectangle_inside(const Polygon& polygon, const std::vector<Segment>& segments, Vec2 lo,
                      Vec2 hi, double eps) {
  for (const Segment& s : segments) {
    // Cheap rejection first: a segment beside the rectangle touches nothing.
    if (std::max(s.a.x, s.b.x) <= lo.x || std::min(s.a.x, s.b.x) >= hi.x ||
        std::max(s.a.y, s.b.y) <= lo.y || std::min(s.a.y, s.b.y) >= hi.y) {
      continue;
    }
    if (crosses_interior(s.a, s.b, lo, hi, eps)) return false;
    if (s.a.x > lo.x + eps && s.a.x < hi.x - eps && s.a.y > lo.y + eps && s.a.y < hi.y - eps) {
      return false;
    }
  }
  return locate(polygon, (lo + hi) * 0.5, 0) == PointLocation::kInside;
}

std::vector<double> grid_lines(const Polygon& polygon, double lo, double hi, int steps, bool x,
                               double eps) {
  std::vector<double> v;
  const auto add = [&](const Ring& ring) {
    for (Vec2 p : ring) v.push_back(x ? p.x : p.y);
  };
  add(polygon.outer);
  for (const Ring& hole : polygon.holes) add(hole);
  for (int k = 0; k <= steps; ++k) v.push_back(lo + (hi - lo) * k / steps);
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double c : v) {
    if (out.empty() || c - out.back() > eps) out.push_back(c);
  }
  return out;
}

}  // namespace

std::optional<Rect2> largest_inner_rectangle(const Polygon& polygon, int steps) {
  if (polygon.outer.size() < 3 || !(area(polygon) > 0)) return std::nullopt;
  const Bounds2 b = bounds(polygon);
  const double extent = std::max(b.max.x - b.min.x, b.max.y - b.min.y);
  const double eps = extent * 1e-9;
  steps = std::max(steps, 1);
  const std::vector<double> xs = grid_lines(polygon, b.min.x, b.max.x, steps, true, eps);
  const std::vector<double> ys = grid_lines(polygon, b.min.y, b.max.y, steps, false, eps);
  const std::size_t nx = xs.size() - 1;
  const std::size_t ny = ys.size() - 1;
  if (nx == 0 || ny == 0) return std::nullopt;
  // Free cells: no boundary through them (each segment marks the cells of its bounding box it
  // crosses), centre inside.
  std::vector<char> blocked(nx * ny, 0);
  const std::vector<Segment> segments = segments_of(polygon);
  for (const Segment& s : segments) {
    const auto first = [](const std::vector<double>& g, double v) {
      const auto it = std::upper_bound(g.begin(), g.end(), v);
      return static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - g.begin() - 1, 0));
    };
    const std::size_t i0 = first(xs, std::min(s.a.x, s.b.x));
    const std::size_t i1 = std::min(first(xs, std::max(s.a.x, s.b.x)), nx - 1);
    const std::size_t j0 = first(ys, std::min(s.a.y, s.b.y));
    const std::size_t j1 = std::min(first(ys, std::max(s.a.y, s.b.y)), ny - 1);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        if (!blocked[j * nx + i] &&
            crosses_interior(s.a, s.b, {xs[i], ys[j]}, {xs[i + 1], ys[j + 1]}, eps)) {
          blocked[j * nx + i] = 1;
        }
      }
    }
  }
  std::vector<double> height(nx, 0);
  Rect2 best{};
  double best_area = 0;
  std::vector<std::size_t> stack;
  std::vector<double> crossings;
  for (std::size_t j = 0; j < ny; ++j) {
    // Cell centres of this row inside by the even-odd rule (holes included): the boundary
    // crossings of the row's centre line left of the centre.
    const double yc = (ys[j] + ys[j + 1]) / 2;
    crossings.clear();
    for (const Segment& s : segments) {
      if ((s.a.y > yc) != (s.b.y > yc)) {
        crossings.push_back(s.a.x + (yc - s.a.y) / (s.b.y - s.a.y) * (s.b.x - s.a.x));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 0; i < nx; ++i) {
      const double xc = (xs[i] + xs[i + 1]) / 2;
      const auto left =
          std::lower_bound(crossings.begin(), crossings.end(), xc) - crossings.begin();
      const bool free = !blocked[j * nx + i] && left % 2 == 1;
      height[i] = free ? height[i] + (ys[j + 1] - ys[j]) : 0;
    }
    // Largest rectangle under the histogram of column heights (columns of unequal widths).
    stack.clear();
    for (std::size_t i = 0; i <= nx; ++i) {
      const double h = i < nx ? height[i] : 0;
      while (!stack.empty() && height[stack.back()] >= h) {
        const double top = height[stack.back()];
        stack.pop_back();
        const double left = stack.empty() ? xs[0] : xs[stack.back() + 1];
        const double a = top * (xs[i] - left);
        if (a > best_area) {
          best_area = a;
          best = {{left, ys[j + 1] - top}, {xs[i], ys[j + 1]}};
        }
      }
      stack.push_back(i);
    }
  }
  if (best_area <= 0) return std::nullopt;
  // Grow sides to the boundary, then slide corners along slanted edges: shrink one side a little
  // and grow a perpendicular one while the area improves (a pattern search, halving the step).
  const auto fits = [&](const Rect2& r) {
    return r.max.x > r.min.x && r.max.y > r.min.y &&
           rectangle_inside(polygon, segments, r.min, r.max, 0);
  };
  const auto moved = [](Rect2 r, int side, double by) {
    if (side == 0) r.min.x -= by;
    if (side == 1) r.max.x += by;
    if (side == 2) r.min.y -= by;
    if (side == 3) r.max.y += by;
    return r;
  };
  // Grows every side as far as it fits, side `last` after the others.
  const auto grown = [&](Rect2 r, int last) {
    for (int k = 1; k <= 4; ++k) {
      const int side = (last + k) % 4;
      double lo = 0;
      double hi = extent;
      for (int it = 0; it < 44; ++it) {
        const double mid = (lo + hi) / 2;
        (fits(moved(r, side, mid)) ? lo : hi) = mid;
      }
      r = moved(r, side, lo);
    }
    return r;
  };
  // The grid's rectangle touches the boundary up to rounding: start strictly inside it.
  if (!fits(best)) best = {best.min + Vec2{eps, eps}, best.max - Vec2{eps, eps}};
  best = grown(best, 3);
  for (double delta = extent / steps; delta > extent * 1e-7; delta /= 2) {
    for (int round = 0; round < 16; ++round) {
      bool improved = false;
      for (int side = 0; side < 4; ++side) {
        const Rect2 candidate = grown(moved(best, side, -delta), side);
        if (candidate.area() > best.area() * (1 + 1e-12)) {
          best = candidate;
          improved = true;
        }
      }
      if (!improved) break;
    }
  }
  return best;
}

}  // namespace insula::kernel
