#include "kernel/party_walls.h"

#include <algorithm>
#include <cmath>

#include "kernel/box_pairs.h"

namespace insula::kernel {
namespace {

constexpr double kPi = 3.14159265358979323846;

Bounds2 region_bounds(const std::vector<Polygon>& region) {
  Bounds2 box;
  for (const Polygon& polygon : region) {
    for (Vec2 p : polygon.outer) box.add(p);
  }
  return box;
}

// Calls visit(a, b) for every edge of every ring of `region`.
template <typename Visit>
void for_each_edge(const std::vector<Polygon>& region, Visit&& visit) {
  const auto ring_edges = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) visit(ring[i], ring[(i + 1) % ring.size()]);
  };
  for (const Polygon& polygon : region) {
    ring_edges(polygon.outer);
    for (const Ring& hole : polygon.holes) ring_edges(hole);
  }
}

// The party walls of `region` (index `self`) along `other` (index `neighbour`).
void walls_along(const std::vector<Polygon>& region, std::size_t self,
                 const std::vector<Polygon>& other, std::size_t neighbour,
                 const PartyWallTolerance& tolerance, std::vector<PartyWall>& walls) {
  for_each_edge(region, [&](Vec2 a, Vec2 b) {
    for_each_edge(other, [&](Vec2 c, Vec2 d) {
      const auto stretch = shared_stretch(a, b, c, d, tolerance);
      if (!stretch) return;
      const Vec2 unit = (b - a) / length(b - a);
      walls.push_back({self, neighbour, a + unit * stretch->first, a + unit * stretch->second});
    });
  });
}

}  // namespace

std::optional<std::pair<double, double>> shared_stretch(Vec2 a, Vec2 b, Vec2 c, Vec2 d,
                                                        const PartyWallTolerance& tolerance) {
  const double edge = length(b - a);
  const double other = length(d - c);
  if (!(edge >= tolerance.min_length && other >= tolerance.min_length)) return std::nullopt;
  const Vec2 u = (b - a) / edge;
  // Parallel or opposite: two footprints' rings run either way along a shared wall.
  const double sine = std::abs(cross(u, (d - c) / other));
  if (sine > std::sin(tolerance.angle_deg * kPi / 180)) return std::nullopt;
  const double tc = dot(c - a, u);
  const double td = dot(d - a, u);
  const double from = std::max(0.0, std::min(tc, td));
  const double to = std::min(edge, std::max(tc, td));
  if (to - from < tolerance.min_length) return std::nullopt;
  // Both ends of the overlap lie within the distance of the other edge's line.
  const auto off_line = [&](double t) {
    const Vec2 p = a + u * t;
    return std::abs(cross((d - c) / other, p - c));
  };
  if (off_line(from) > tolerance.distance || off_line(to) > tolerance.distance) return std::nullopt;
  return std::pair{from, to};
}

std::vector<PartyWall> find_party_walls(const std::vector<std::vector<Polygon>>& regions,
                                        const PartyWallTolerance& tolerance) {
  std::vector<Bounds2> boxes;
  boxes.reserve(regions.size());
  for (const std::vector<Polygon>& region : regions) boxes.push_back(region_bounds(region));
  std::vector<PartyWall> walls;
  for_each_box_pair(boxes, tolerance.distance, [&](std::size_t i, std::size_t j) {
    walls_along(regions[i], i, regions[j], j, tolerance, walls);
    walls_along(regions[j], j, regions[i], i, tolerance, walls);
  });
  std::stable_sort(walls.begin(), walls.end(), [](const PartyWall& x, const PartyWall& y) {
    return x.footprint != y.footprint ? x.footprint < y.footprint : x.neighbour < y.neighbour;
  });
  return walls;
}

bool on_party_wall(Vec2 a, Vec2 b, std::span<const PartyWall> walls,
                   const PartyWallTolerance& tolerance) {
  return std::any_of(walls.begin(), walls.end(), [&](const PartyWall& wall) {
    return shared_stretch(a, b, wall.a, wall.b, tolerance).has_value();
  });
}

}  // namespace insula::kernel
