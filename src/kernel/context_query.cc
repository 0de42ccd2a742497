// k-means clustering (seed 003, §4.4, Fig. 7) and the occlusion query (seed 003, §6.1). The ray
// cast is in context_query_ray.cc, the ground-plane queries in context_query_ground.cc.
#include "kernel/context_query.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/boolean2d.h"
#include "kernel/context_query_grid.h"
#include "kernel/convex_hull.h"

namespace insula::kernel {

namespace {

double squared_distance(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return dot(d, d);
}

// The nearest center's index; a tie keeps the lower index (strict comparison).
int nearest_center(Vec3 p, const std::vector<Vec3>& centers) {
  int best = 0;
  double best_d = squared_distance(p, centers[0]);
  for (std::size_t c = 1; c < centers.size(); ++c) {
    const double d = squared_distance(p, centers[c]);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(c);
    }
  }
  return best;
}

// Moves each center to the mean of its points, summed in point order; empty clusters keep theirs.
void update_centers(std::span<const Vec3> points, const std::vector<int>& cluster,
                    std::vector<Vec3>& centers) {
  std::vector<Vec3> sums(centers.size());
  std::vector<std::size_t> counts(centers.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    sums[cluster[i]] += points[i];
    ++counts[cluster[i]];
  }
  for (std::size_t c = 0; c < centers.size(); ++c) {
    if (counts[c] > 0) centers[c] = sums[c] / static_cast<double>(counts[c]);
  }
}

}  // namespace

KMeansResult kmeans(std::span<const Vec3> points, int k, int max_iterations) {
  KMeansResult result;
  if (k < 1 || points.empty()) return result;
  const std::size_t count = std::min(static_cast<std::size_t>(k), points.size());
  result.centers.assign(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(count));
  result.cluster.assign(points.size(), -1);
  const int passes = std::max(max_iterations, 1);
  for (int pass = 1; pass <= passes; ++pass) {
    bool changed = false;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int c = nearest_center(points[i], result.centers);
      changed |= c != result.cluster[i];
      result.cluster[i] = c;
    }
    result.iterations = pass;
    if (!changed) break;
    update_centers(points, result.cluster, result.centers);
  }
  return result;
}

namespace {

// An orthonormal frame of a plane: 2D coordinates along u and v, height along n.
struct PlaneFrame {
  Vec3 origin;
  Vec3 u;
  Vec3 v;
  Vec3 n;
  Vec2 to_2d(Vec3 p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
  double height(Vec3 p) const { return dot(p - origin, n); }
};

PlaneFrame plane_frame(Vec3 origin, Vec3 normal) {
  const Vec3 n = normalized(normal);
  // The world axis least aligned with n keeps the cross product well conditioned.
  const Vec3 helper = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                          ? Vec3{1, 0, 0}
                          : (std::abs(n.y) <= std::abs(n.z) ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  const Vec3 u = normalized(cross(helper, n));
  return {origin, u, cross(n, u), n};
}

std::array<Vec3, 8> corners(const BoxEdges& box) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) {
    c[i] = box.origin + box.u * (i & 1) + box.v * ((i >> 1) & 1) + box.w * ((i >> 2) & 1);
  }
  return c;
}

Bounds3 box_bounds(const BoxEdges& box) {
  Bounds3 b;
  for (const Vec3 c : corners(box)) b.add(c);
  return b;
}

constexpr double kTouch = 1e-9;  // metres: a box no thicker than this in front only touches

// The projection onto the frame's plane of the part of `box` with 0 < height <= distance: the
// convex hull of the box corners inside that slab and of the box edges' crossings of its two
// planes (the vertices of a convex polytope cut by planes). Empty when that part is empty or
// projects to no area.
Ring slab_shadow(const BoxEdges& box, const PlaneFrame& frame, double distance) {
  const std::array<Vec3, 8> c = corners(box);
  std::array<double, 8> h;
  double low = 1e300, high = -1e300;
  for (int i = 0; i < 8; ++i) {
    h[i] = frame.height(c[i]);
    low = std::min(low, h[i]);
    high = std::max(high, h[i]);
  }
  if (high <= kTouch || low > distance) return {};
  const double lo = std::max(low, 0.0), hi = std::min(high, distance);
  std::vector<Vec2> points;
  for (int i = 0; i < 8; ++i) {
    if (h[i] >= lo && h[i] <= hi) points.push_back(frame.to_2d(c[i]));
  }
  for (int i = 0; i < 8; ++i) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      const int j = i | bit;
      if (j == i) continue;
      for (const double level : {lo, hi}) {
        if ((h[i] - level) * (h[j] - level) < 0) {
          const double t = (level - h[i]) / (h[j] - h[i]);
          points.push_back(frame.to_2d(c[i] + (c[j] - c[i]) * t));
        }
      }
    }
  }
  Hull2Result hull = convex_hull_2d(points);
  return hull.ok() ? std::move(hull.ring) : Ring{};
}

double total_area(const std::vector<Polygon>& polygons) {
  double sum = 0;
  for (const Polygon& p : polygons) sum += area(p);
  return sum;
}

double shape_occlusion(const FlatShape& shape, std::size_t index, detail::BoxGrid& grid,
                       std::span<const BoxEdges> occluders, double distance,
                       const SkipPredicate& skip) {
  if (shape.loops.empty() || shape.loops[0].empty() || length(shape.normal) == 0) return 0;
  const PlaneFrame frame = plane_frame(shape.loops[0][0], shape.normal);
  std::vector<Polygon> region;
  Bounds3 slab;
  for (const std::vector<Vec3>& loop : shape.loops) {
    Polygon p;
    for (const Vec3 q : loop) {
      p.outer.push_back(frame.to_2d(q));
      slab.add(q);
      slab.add(q + frame.n * distance);
    }
    region.push_back(std::move(p));
  }
  const double shape_area = total_area(union_all(region));
  if (shape_area <= 0) return 0;
  std::vector<Polygon> shadows;
  grid.query(slab, [&](std::size_t o) {
    if (skip && skip(index, o)) return;
    Ring ring = slab_shadow(occluders[o], frame, distance);
    if (!ring.empty()) shadows.push_back({std::move(ring), {}});
  });
  if (shadows.empty()) return 0;
  const BooleanResult covered = intersect(region, shadows);
  return std::clamp(total_area(covered.polygons) / shape_area, 0.0, 1.0);
}

}  // namespace

std::vector<double> occlusion(std::span<const FlatShape> shapes,
                              std::span<const BoxEdges> occluders, double distance,
                              const SkipPredicate& skip) {
  std::vector<Bounds3> boxes;
  boxes.reserve(occluders.size());
  for (const BoxEdges& box : occluders) boxes.push_back(box_bounds(box));
  detail::BoxGrid grid(std::move(boxes));
  std::vector<double> result(shapes.size(), 0);
  if (!(distance > 0)) return result;  // no slab in front (also NaN)
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    result[s] = shape_occlusion(shapes[s], s, grid, occluders, distance, skip);
  }
  return result;
}

}  // namespace insula::kernel
