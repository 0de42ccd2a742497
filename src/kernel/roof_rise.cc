#include "kernel/roof_rise.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/skeleton.h"

namespace insula::kernel {
namespace {

// The footprint's extent perpendicular to its longest outer edge: how far a shed rising across
// that edge climbs (the kernel's default shed edge, roof.h).
double extent_across_longest_edge(const Ring& ring) {
  std::size_t longest = 0;
  double longest_length = -1;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double edge = length(ring[(i + 1) % ring.size()] - ring[i]);
    if (edge > longest_length) {
      longest_length = edge;
      longest = i;
    }
  }
  if (longest_length <= 0) return 0;
  const Vec2 a = ring[longest];
  const Vec2 direction = (ring[(longest + 1) % ring.size()] - a) / longest_length;
  const Vec2 inward = perp(direction);  // outer rings are counter-clockwise
  // From the corner farthest behind the edge's line (a footprint that is not convex may reach
  // behind it; roof.cc's plan_shed starts the slope there) to the farthest in front.
  double low = 0;
  double high = 0;
  for (const Vec2& p : ring) {
    low = std::min(low, dot(p - a, inward));
    high = std::max(high, dot(p - a, inward));
  }
  return high - low;
}

}  // namespace

double roof_rise(const Polygon& footprint, RoofType type, double pitch_deg) {
  if (type == RoofType::kFlat || footprint.outer.size() < 3) return 0;
  const double slope = std::tan(pitch_deg * std::numbers::pi / 180.0);
  Polygon ring_ordered = footprint;
  normalize(ring_ordered);
  if (type == RoofType::kShed) return extent_across_longest_edge(ring_ordered.outer) * slope;
  const std::optional<Skeleton> skeleton = interior_straight_skeleton(ring_ordered);
  return skeleton ? skeleton->max_time() * slope : 0;
}

}  // namespace insula::kernel
