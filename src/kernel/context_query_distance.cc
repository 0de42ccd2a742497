// The ground-plane distance query (seed 003, §4.5, Fig. 1: levels of detail by the distance to the
// main path): the least XY distance from each entity's footprint to the targets'.
#include <algorithm>
#include <cmath>

#include "kernel/context_query.h"
#include "kernel/context_query_grid.h"

namespace insula::kernel {

namespace {

struct Edge {
  Vec2 a;
  Vec2 b;
};

// Every edge of the footprint: polygon ring edges, segments, and points as zero-length edges.
std::vector<Edge> edges_of(const Footprint& f) {
  std::vector<Edge> edges;
  auto ring_edges = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
  };
  for (const Polygon& p : f.polygons) {
    ring_edges(p.outer);
    for (const Ring& hole : p.holes) ring_edges(hole);
  }
  for (const StreetSegment& s : f.segments) edges.push_back({s.a, s.b});
  for (const Vec2 p : f.points) edges.push_back({p, p});
  return edges;
}

Bounds3 footprint_bounds(const std::vector<Edge>& edges) {
  Bounds3 box;
  for (const Edge& e : edges) {
    box.add({e.a.x, e.a.y, 0});
    box.add({e.b.x, e.b.y, 0});
  }
  return box;
}

// Two segments that do not cross properly are nearest at an endpoint of one of them.
double edge_distance(const Edge& p, const Edge& q) {
  if (segments_cross_properly(p.a, p.b, q.a, q.b)) return 0;
  return std::min({distance_to_segment(p.a, q.a, q.b), distance_to_segment(p.b, q.a, q.b),
                   distance_to_segment(q.a, p.a, p.b), distance_to_segment(q.b, p.a, p.b)});
}

// One point of each part of the footprint: a part inside a polygon of the other footprint whose
// edges do not meet it has all its points inside, so its first one tells.
std::vector<Vec2> part_points(const Footprint& f) {
  std::vector<Vec2> points = f.points;
  for (const Polygon& p : f.polygons) {
    if (!p.outer.empty()) points.push_back(p.outer[0]);
  }
  for (const StreetSegment& s : f.segments) points.push_back(s.a);
  return points;
}

bool any_inside(const std::vector<Vec2>& points, const Footprint& f) {
  for (const Polygon& p : f.polygons) {
    for (const Vec2 q : points) {
      if (locate(p, q) != PointLocation::kOutside) return true;
    }
  }
  return false;
}

struct Prepared {
  std::vector<Edge> edges;
  std::vector<Vec2> parts;
  Bounds3 box;
};

Prepared prepare(const Footprint& f) {
  Prepared p{edges_of(f), part_points(f), {}};
  p.box = footprint_bounds(p.edges);
  return p;
}

// Lower bound of the distance between two footprints: the gap between their boxes.
double box_gap(const Bounds3& a, const Bounds3& b) {
  const double dx = std::max({0.0, a.min.x - b.max.x, b.min.x - a.max.x});
  const double dy = std::max({0.0, a.min.y - b.max.y, b.min.y - a.max.y});
  return std::hypot(dx, dy);
}

double footprint_distance(const Prepared& a, const Footprint& fa, const Prepared& b,
                          const Footprint& fb) {
  if (any_inside(a.parts, fb) || any_inside(b.parts, fa)) return 0;
  double best = 1e300;
  for (const Edge& p : a.edges) {
    for (const Edge& q : b.edges) best = std::min(best, edge_distance(p, q));
  }
  return best;
}

}  // namespace

std::vector<NearestTarget> nearest_targets(std::span<const Footprint> entities,
                                           std::span<const Footprint> targets,
                                           const SkipPredicate& skip) {
  std::vector<Prepared> prepared;
  std::vector<Bounds3> boxes;
  for (const Footprint& t : targets) {
    prepared.push_back(prepare(t));
    boxes.push_back(prepared.back().box);
  }
  detail::BoxGrid grid(std::move(boxes));
  const Bounds3 all = grid.bounds();
  const Vec3 extent = all.size();
  // The first search box reaches about one target spacing (at least 1 m) beyond the entity.
  const double per_side = std::sqrt(static_cast<double>(std::max<std::size_t>(targets.size(), 1)));
  const double step = std::max({extent.x / per_side, extent.y / per_side, 1.0});
  std::vector<NearestTarget> result(entities.size());
  for (std::size_t e = 0; e < entities.size(); ++e) {
    const Prepared entity = prepare(entities[e]);
    if (entity.edges.empty() || all.empty()) continue;
    NearestTarget& best = result[e];
    auto consider = [&](std::size_t t) {
      if (skip && skip(e, t)) return;
      const double gap = box_gap(entity.box, prepared[t].box);
      if (best.target >= 0 && gap > best.distance) return;
      const double d = footprint_distance(entity, entities[e], prepared[t], targets[t]);
      if (best.target < 0 || d < best.distance ||
          (d == best.distance && static_cast<int>(t) < best.target)) {
        best = {static_cast<int>(t), d};
      }
    };
    // Grow the search box until it holds a candidate or covers every target...
    const double reach = box_gap(entity.box, all) + std::max(extent.x, extent.y) + step;
    for (double r = step; best.target < 0; r *= 2) {
      grid.query(detail::grown(entity.box, r), consider);
      if (r >= reach) break;
    }
    // ...then look at every target whose box lies within the best distance.
    if (best.target >= 0) grid.query(detail::grown(entity.box, best.distance), consider);
  }
  return result;
}

}  // namespace insula::kernel
