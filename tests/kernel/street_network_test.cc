#include "kernel/street_network.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <utility>

#include "kernel/boolean2d.h"

namespace insula::kernel {
namespace {

using Edges = std::vector<std::array<std::uint32_t, 2>>;

StreetNetwork polyline(std::vector<Vec3> points, bool closed = false) {
  StreetNetwork network{std::move(points), {}};
  const auto n = static_cast<std::uint32_t>(network.vertices.size());
  for (std::uint32_t k = 0; k + 1 < n; ++k) network.edges.push_back({k, k + 1});
  if (closed && n > 2) network.edges.push_back({n - 1, 0});
  return network;
}

StreetNetwork merged(std::vector<StreetNetwork> networks, double tolerance = 1e-3) {
  return merge_networks(networks, tolerance);
}

double total_area(const std::vector<Polygon>& polygons) {
  double sum = 0;
  for (const Polygon& p : polygons) sum += area(p);
  return sum;
}

// Roads and blocks tile the area inside the roads' outer boundary: nothing overlaps, nothing is
// left between them (for networks whose every enclosure is a face).
void expect_tiling(const StreetSurfaces& s) {
  const BooleanResult all = unite(s.roads, s.blocks);
  ASSERT_TRUE(all.ok());
  const double sum = total_area(s.roads) + total_area(s.blocks);
  EXPECT_NEAR(total_area(all.polygons), sum, 1e-6 * sum);
  for (const Polygon& p : all.polygons) EXPECT_TRUE(p.holes.empty());
}

void expect_valid(const std::vector<Polygon>& polygons) {
  for (const Polygon& p : polygons) {
    EXPECT_GT(signed_area(p.outer), 0);
    EXPECT_TRUE(repair(p, 1e-9).ok);
  }
}

// Segments ab and cd meet at a point interior to both (orientation tests alone misjudge nearly
// collinear segments that do not meet).
bool really_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (!segments_cross_properly(a, b, c, d)) return false;
  const double denominator = cross(b - a, d - c);
  const double t = cross(c - a, d - c) / denominator, u = cross(c - a, b - a) / denominator;
  return t > 0 && t < 1 && u > 0 && u < 1;
}

// What merge_networks promises, checked pair by pair.
void expect_planar(const StreetNetwork& m, double tolerance) {
  const auto& v = m.vertices;
  int near_vertices = 0, on_edge = 0, crossings = 0, repeats = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      near_vertices += length(drop(v[i]) - drop(v[j])) <= tolerance;
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (std::size_t i = 0; i < m.edges.size(); ++i) {
    const auto [a, b] = m.edges[i];
    repeats += a == b || !seen.insert(std::minmax(a, b)).second;
    for (std::uint32_t k = 0; k < v.size(); ++k)
      on_edge +=
          k != a && k != b && distance_to_segment(drop(v[k]), drop(v[a]), drop(v[b])) <= tolerance;
    for (std::size_t j = i + 1; j < m.edges.size(); ++j) {
      const auto [c, d] = m.edges[j];
      crossings += really_cross(drop(v[a]), drop(v[b]), drop(v[c]), drop(v[d]));
    }
  }
  EXPECT_EQ(near_vertices, 0);
  EXPECT_EQ(on_edge, 0);
  EXPECT_EQ(crossings, 0);
  EXPECT_EQ(repeats, 0);
}

TEST(StreetNetwork, GridBlocksInOrderStartingAtTheirAnchor) {
  const StreetSurfaces s = street_surfaces(grid_network(3, 3, 50, 50), 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 4U);
  const Vec2 anchors[] = {{5, 5}, {55, 5}, {5, 55}, {55, 55}};
  for (std::size_t k = 0; k < 4; ++k) {
    const Ring& ring = s.blocks[k].outer;
    EXPECT_NEAR(area(s.blocks[k]), 1600, 1e-6);
    ASSERT_EQ(ring.size(), 4U);
    EXPECT_EQ(ring[0], anchors[k]) << k;
    // Counter-clockwise from the anchor: the first edge runs along +x.
    EXPECT_EQ(ring[1], (anchors[k] + Vec2{40, 0})) << k;
    EXPECT_TRUE(s.blocks[k].holes.empty());
  }
  ASSERT_EQ(s.roads.size(), 1U);
  EXPECT_EQ(s.roads[0].holes.size(), 4U);
  EXPECT_NEAR(area(s.roads[0]), 110.0 * 110.0 - 4 * 1600, 1e-6);
  const Bounds2 box = bounds(s.roads[0]);
  EXPECT_EQ(box.min, (Vec2{-5, -5}));
  EXPECT_EQ(box.max, (Vec2{105, 105}));
  EXPECT_EQ(s.z, 0);
  expect_tiling(s);
  expect_valid(s.blocks);
}

TEST(StreetNetwork, GeoreferencedGridKeepsItsPrecision) {
  // UTM-sized coordinates: the same blocks, shifted.
  const Vec3 origin{512345.25, 5412345.5, 120};
  const StreetSurfaces s = street_surfaces(grid_network(3, 3, 50, 50, origin), 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 4U);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(area(s.blocks[k]), 1600, 1e-4);
  EXPECT_NEAR(s.blocks[1].outer[0].x, origin.x + 55, 1e-6);
  EXPECT_NEAR(s.blocks[1].outer[0].y, origin.y + 5, 1e-6);
  EXPECT_EQ(s.z, 120);
}

TEST(StreetNetwork, RightAngleBendIsMitred) {
  const StreetSurfaces s = road_buffer(polyline({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}}), 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.roads.size(), 1U);
  // 110 x 10 along x, 10 x 100 up; the outer corner is the miter point (105, -5).
  EXPECT_NEAR(area(s.roads[0]), 110.0 * 10.0 + 10.0 * 100.0, 1e-6);
  EXPECT_EQ(s.roads[0].outer.size(), 6U);
  const Bounds2 box = bounds(s.roads[0]);
  EXPECT_EQ(box.min, (Vec2{-5, -5}));
  EXPECT_EQ(box.max, (Vec2{105, 105}));
}

TEST(StreetNetwork, RoadBufferIsTheRoadsAlone) {
  const StreetNetwork grid = grid_network(3, 3, 50, 50);
  const StreetSurfaces buffer = road_buffer(grid, 10);
  ASSERT_TRUE(buffer.ok());
  EXPECT_TRUE(buffer.blocks.empty());
  ASSERT_EQ(buffer.roads.size(), 1U);
  EXPECT_NEAR(area(buffer.roads[0]), 5700, 1e-6);
}

TEST(StreetNetwork, GridNetworkOrder) {
  const StreetNetwork grid = grid_network(3, 2, 10, 20, {1, 2, 3});
  ASSERT_EQ(grid.vertices.size(), 6U);
  EXPECT_EQ(grid.vertices[4], (Vec3{11, 22, 3}));
  EXPECT_EQ(grid.edges, (Edges{{0, 1}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {4, 5}}));
  EXPECT_TRUE(grid_network(0, 5, 1, 1).vertices.empty());
  const StreetNetwork one = grid_network(1, 1, 1, 1);
  EXPECT_EQ(one.vertices.size(), 1U);
  EXPECT_TRUE(one.edges.empty());
}

TEST(StreetNetwork, CrossingSegmentsShareOneNewVertex) {
  const StreetNetwork m =
      merged({polyline({{0, 0, 0}, {10, 10, 4}}), polyline({{0, 10, 0}, {10, 0, 0}})});
  ASSERT_EQ(m.vertices.size(), 5U);
  // The crossing comes after the input vertices; its z is interpolated along the first edge.
  EXPECT_EQ(m.vertices[4], (Vec3{5, 5, 2}));
  EXPECT_EQ(m.edges, (Edges{{0, 4}, {4, 1}, {2, 4}, {4, 3}}));
}

TEST(StreetNetwork, TJunctionSplitsTheThroughRoad) {
  const StreetNetwork m =
      merged({polyline({{0, 0, 0}, {10, 0, 0}}), polyline({{5, 5, 0}, {5, 0.0004, 0}})});
  ASSERT_EQ(m.vertices.size(), 4U);
  EXPECT_EQ(m.edges, (Edges{{0, 3}, {3, 1}, {2, 3}}));
  // The through road bends to the stem's end, which lies within the tolerance.
  EXPECT_EQ(m.vertices[3], (Vec3{5, 0.0004, 0}));
  // Beyond the tolerance the stem stays apart.
  const StreetNetwork apart =
      merged({polyline({{0, 0, 0}, {10, 0, 0}}), polyline({{5, 5, 0}, {5, 0.002, 0}})});
  EXPECT_EQ(apart.edges.size(), 2U);
}

TEST(StreetNetwork, WeldingKeepsTheFirstVertexWithinTolerance) {
  const StreetNetwork a = polyline({{0, 0, 1}, {10, 0, 1}});
  const StreetNetwork b = polyline({{10.0007, 0.0003, 5}, {10, 10, 5}});
  const StreetNetwork m = merged({a, b});
  ASSERT_EQ(m.vertices.size(), 3U);
  EXPECT_EQ(m.vertices[1], (Vec3{10, 0, 1}));
  EXPECT_EQ(m.edges, (Edges{{0, 1}, {1, 2}}));
  // Tolerance 0 (and a NaN tolerance, which acts as 0) welds only equal points.
  EXPECT_EQ(merged({a, b}, 0).vertices.size(), 4U);
  EXPECT_EQ(merged({a, b}, std::nan("")).vertices.size(), 4U);
  EXPECT_EQ(merged({a, polyline({{10, 0, 9}, {10, 10, 9}})}, 0).vertices.size(), 3U);
}

TEST(StreetNetwork, OverlapsAndRepeatsBecomeSharedPieces) {
  const StreetNetwork m =
      merged({polyline({{0, 0, 0}, {10, 0, 0}}), polyline({{15, 0, 0}, {5, 0, 0}}),
              polyline({{10, 0, 0}, {0, 0, 0}})});
  // 0--5--10--15: three pieces, each once, whatever the input direction.
  EXPECT_EQ(m.vertices.size(), 4U);
  EXPECT_EQ(m.edges, (Edges{{0, 3}, {3, 1}, {2, 1}}));
}

TEST(StreetNetwork, MergeIsAFixedPoint) {
  // A star of five long lines crossing near one point, plus a loop over them.
  std::vector<StreetNetwork> parts;
  for (int k = 0; k < 5; ++k) {
    const double a = k * 0.6283185307179586 + 0.1;
    parts.push_back(polyline({{-50 * std::cos(a), -50 * std::sin(a), 0},
                              {50 * std::cos(a) + 0.0001 * k, 50 * std::sin(a), 0}}));
  }
  parts.push_back(polyline({{-30, -30, 0}, {30, -30, 0}, {30, 30, 0}, {-30, 30, 0}}, true));
  const StreetNetwork once = merge_networks(parts, 1e-3);
  const StreetNetwork twice = merge_networks({&once, 1}, 1e-3);
  EXPECT_EQ(once.vertices, twice.vertices);
  EXPECT_EQ(once.edges, twice.edges);
  expect_planar(once, 1e-3);
  // The five lines meet in one welded vertex and cross the square ten times: 10 + 1 + 4 + 10
  // vertices; 10 spokes, 10 outer pieces, 10 + 4 square pieces.
  EXPECT_EQ(once.vertices.size(), 25U);
  EXPECT_EQ(once.edges.size(), 34U);
  const StreetSurfaces s = street_surfaces(once, 2);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.blocks.size(), 10U);
  expect_tiling(s);
  expect_valid(s.blocks);
}

TEST(StreetNetwork, RandomSegmentsMergeIntoAPlanarGraph) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(0, 100);
    std::vector<StreetNetwork> parts;
    for (int k = 0; k < 40; ++k) {
      const Vec3 a{coordinate(random), coordinate(random), 0};
      // Some segments end on an earlier one's end or middle, some repeat part of one.
      Vec3 b{coordinate(random), coordinate(random), 0};
      if (k % 5 == 1) b = parts.back().vertices[0];
      if (k % 5 == 2) b = (parts.back().vertices[0] + parts.back().vertices[1]) * 0.5;
      parts.push_back(polyline({a, b}));
    }
    const StreetNetwork m = merge_networks(parts, 1e-3);
    SCOPED_TRACE(seed);
    EXPECT_GT(m.edges.size(), 100U);
    expect_planar(m, 1e-3);
    const StreetNetwork again = merge_networks({&m, 1}, 1e-3);
    EXPECT_EQ(again.vertices, m.vertices);
    EXPECT_EQ(again.edges, m.edges);
    const StreetSurfaces s = street_surfaces(m, 1);
    ASSERT_TRUE(s.ok());
    expect_valid(s.roads);
    EXPECT_FALSE(s.blocks.empty());
    // Deterministic: the same input gives the same rings in the same order.
    const StreetSurfaces repeat = street_surfaces(m, 1);
    ASSERT_EQ(repeat.blocks.size(), s.blocks.size());
    for (std::size_t k = 0; k < s.blocks.size(); ++k)
      EXPECT_EQ(repeat.blocks[k].outer, s.blocks[k].outer);
    const BooleanResult all = unite(s.roads, s.blocks);
    ASSERT_TRUE(all.ok());
    const double sum = total_area(s.roads) + total_area(s.blocks);
    EXPECT_NEAR(total_area(all.polygons), sum, 1e-6 * sum);
    expect_valid(s.blocks);
  }
}

TEST(StreetNetwork, DeadEndInsideABlockIsCutOut) {
  // A square of side 100 with a street from the middle of its bottom side 40 m into the block.
  StreetNetwork net = polyline({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true);
  net.vertices.push_back({50, 0, 0});
  net.vertices.push_back({50, 40, 0});
  net.edges.push_back({4, 5});
  const StreetSurfaces s = street_surfaces(net, 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 1U);
  // 90 x 90 minus the spike's buffer, 10 wide, from the road edge at y=5 to 5 m past its end.
  EXPECT_NEAR(area(s.blocks[0]), 90.0 * 90.0 - 10.0 * 40.0, 1e-6);
  EXPECT_EQ(s.blocks[0].outer.size(), 8U);
  EXPECT_EQ(s.blocks[0].outer[0], (Vec2{5, 5}));
  EXPECT_EQ(s.blocks[0].outer[1], (Vec2{45, 5}));
  ASSERT_EQ(s.roads.size(), 1U);
  EXPECT_NEAR(area(s.roads[0]), 110.0 * 110.0 - 7700, 1e-6);
  expect_tiling(s);
  expect_valid(s.blocks);
}

TEST(StreetNetwork, DeadEndsOutsideEndSquare) {
  // One street: a 10 x 100 rectangle grown by half a width at both ends.
  const StreetSurfaces s = street_surfaces(polyline({{0, 0, 0}, {100, 0, 0}}), 10);
  ASSERT_TRUE(s.ok());
  EXPECT_TRUE(s.blocks.empty());
  ASSERT_EQ(s.roads.size(), 1U);
  EXPECT_NEAR(area(s.roads[0]), 110.0 * 10.0, 1e-6);
  EXPECT_EQ(bounds(s.roads[0]).min, (Vec2{-5, -5}));
  // An open U whose ends nearly meet encloses no face: no block, though the roads close it.
  const StreetSurfaces u =
      street_surfaces(polyline({{0, 0, 0}, {0, -50, 0}, {50, -50, 0}, {50, 0, 0}, {4, 0, 0}}), 10);
  ASSERT_TRUE(u.ok());
  EXPECT_TRUE(u.blocks.empty());
  ASSERT_EQ(u.roads.size(), 1U);
  EXPECT_EQ(u.roads[0].holes.size(), 1U);
}

TEST(StreetNetwork, TriangleWithDiagonal) {
  // The diagonal ends on the hypotenuse (a T-junction street_surfaces merges itself) and cuts
  // the triangle into two right isosceles triangles of area 2500.
  StreetNetwork net = polyline({{0, 0, 0}, {100, 0, 0}, {0, 100, 0}}, true);
  net.vertices.push_back({50, 50, 0});
  net.edges.push_back({0, 3});
  const double width = 10;
  const StreetSurfaces s = street_surfaces(net, width);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 2U);
  // A triangle inset by d is similar to it, scaled by (1 - d/r) about its incentre.
  const double r = 50 * (std::sqrt(2.0) - 1);
  const double expected = 2500 * std::pow(1 - width / 2 / r, 2);
  EXPECT_NEAR(area(s.blocks[0]), expected, 1e-4);
  EXPECT_NEAR(area(s.blocks[1]), expected, 1e-4);
  // Order by anchor: the lower triangle first; each ring starts at its anchor.
  EXPECT_NEAR(s.blocks[0].outer[0].y, 5, 1e-6);
  EXPECT_GT(s.blocks[1].outer[0].y, 5);
  for (const Polygon& block : s.blocks)
    for (const Vec2 p : block.outer) EXPECT_GE(p.y, block.outer[0].y - 1e-6);
  // The roads' outer boundary is the triangle offset with the kernel's miter rule (squared at the
  // 45-degree corners, mitred at the right angle).
  ASSERT_EQ(s.roads.size(), 1U);
  const Polygon triangle{{{0, 0}, {100, 0}, {0, 100}}, {}};
  const BooleanResult grown = offset({triangle}, width / 2, JoinType::kMiter, kStreetMiterLimit);
  ASSERT_TRUE(grown.ok());
  EXPECT_NEAR(std::abs(signed_area(s.roads[0].outer)), area(grown.polygons[0]), 1e-4);
  expect_tiling(s);
  expect_valid(s.blocks);
}

TEST(StreetNetwork, NestedNetworkMakesAHole) {
  const StreetNetwork big = polyline({{0, 0, 0}, {200, 0, 0}, {200, 200, 0}, {0, 200, 0}}, true);
  const StreetNetwork small =
      polyline({{80, 80, 0}, {120, 80, 0}, {120, 120, 0}, {80, 120, 0}}, true);
  const StreetSurfaces s = street_surfaces(merged({big, small}), 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 2U);
  EXPECT_EQ(s.blocks[0].outer[0], (Vec2{5, 5}));
  ASSERT_EQ(s.blocks[0].holes.size(), 1U);
  EXPECT_NEAR(area(s.blocks[0]), 190.0 * 190.0 - 50.0 * 50.0, 1e-6);
  EXPECT_EQ(s.blocks[1].outer[0], (Vec2{85, 85}));
  EXPECT_NEAR(area(s.blocks[1]), 30.0 * 30.0, 1e-6);
  EXPECT_EQ(s.roads.size(), 2U);
  expect_tiling(s);
}

TEST(StreetNetwork, NarrowFaceVanishesAndWideOneSplits) {
  // A 6 m wide face disappears under 10 m roads.
  const StreetSurfaces narrow =
      street_surfaces(polyline({{0, 0, 0}, {100, 0, 0}, {100, 6, 0}, {0, 6, 0}}, true), 10);
  ASSERT_TRUE(narrow.ok());
  EXPECT_TRUE(narrow.blocks.empty());
  // A dumbbell face, two 40 x 40 rooms joined by a 4 m corridor: the inset keeps the rooms only.
  const StreetNetwork dumbbell = polyline({{0, 0, 0},
                                           {40, 0, 0},
                                           {40, 18, 0},
                                           {80, 18, 0},
                                           {80, 0, 0},
                                           {120, 0, 0},
                                           {120, 40, 0},
                                           {80, 40, 0},
                                           {80, 22, 0},
                                           {40, 22, 0},
                                           {40, 40, 0},
                                           {0, 40, 0}},
                                          true);
  const StreetSurfaces s = street_surfaces(dumbbell, 10);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 2U);
  EXPECT_EQ(s.blocks[0].outer[0], (Vec2{5, 5}));
  EXPECT_EQ(s.blocks[1].outer[0], (Vec2{85, 5}));
  EXPECT_NEAR(area(s.blocks[0]), 30.0 * 30.0, 1e-6);
  EXPECT_NEAR(area(s.blocks[1]), 30.0 * 30.0, 1e-6);
  expect_tiling(s);
}

TEST(StreetNetwork, SurfacesLieAtTheLowestUsedZ) {
  StreetNetwork net = polyline({{0, 0, 3}, {10, 0, 7}});
  net.vertices.push_back({5, 5, -100});  // isolated: not part of any street
  const StreetSurfaces s = street_surfaces(net, 2);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.z, 3);
}

TEST(StreetNetwork, DegenerateInput) {
  const StreetNetwork empty;
  EXPECT_TRUE(merged({}).vertices.empty());
  EXPECT_TRUE(merged({empty}).vertices.empty());
  const StreetSurfaces none = street_surfaces(empty, 10);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none.roads.empty());
  EXPECT_TRUE(none.blocks.empty());
  EXPECT_EQ(none.z, 0);

  // A single vertex is kept by merge but makes no surface.
  const StreetNetwork point{{{1, 2, 3}}, {}};
  EXPECT_EQ(merged({point}).vertices.size(), 1U);
  EXPECT_TRUE(street_surfaces(point, 10).roads.empty());

  // Zero-length edges, out-of-range indices and NaN vertices are dropped.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const StreetNetwork bad{{{0, 0, 0}, {0, 0, 0}, {nan, 1, 0}, {10, 0, 0}, {20, 0, 0}},
                          {{0, 0}, {0, 1}, {1, 2}, {2, 3}, {3, 9}, {1, 3}, {3, 4}}};
  const StreetNetwork m = merged({bad});
  EXPECT_EQ(m.vertices, (std::vector<Vec3>{{0, 0, 0}, {10, 0, 0}, {20, 0, 0}}));
  EXPECT_EQ(m.edges, (Edges{{0, 1}, {1, 2}}));
  const StreetSurfaces s = street_surfaces(bad, 2);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.roads.size(), 1U);
  EXPECT_NEAR(area(s.roads[0]), 22.0 * 2.0, 1e-6);

  for (const double width : {0.0, -1.0, nan, std::numeric_limits<double>::infinity()}) {
    const StreetSurfaces w = street_surfaces(grid_network(2, 2, 10, 10), width);
    EXPECT_EQ(w.status, StreetStatus::kBadWidth);
    EXPECT_TRUE(w.roads.empty());
    EXPECT_EQ(road_buffer(grid_network(2, 2, 10, 10), width).status, StreetStatus::kBadWidth);
  }
  EXPECT_EQ(to_string(StreetStatus::kBadWidth),
            "the street width must be a finite number greater than 0");

  // Beyond the booleans' range: a status, no surfaces.
  const StreetSurfaces far = street_surfaces(polyline({{0, 0, 0}, {1e13, 0, 0}}), 10);
  EXPECT_EQ(far.status, StreetStatus::kBooleanFailed);
  EXPECT_TRUE(far.roads.empty());
  // Extents that overflow a double: no crash, the edges kept as given.
  const StreetNetwork huge = polyline({{-1e308, -1e308, 0}, {1e308, 1e308, 0}, {1e308, -1e308, 0}});
  EXPECT_EQ(merged({huge}).edges.size(), 2U);
  EXPECT_EQ(street_surfaces(huge, 10).status, StreetStatus::kBooleanFailed);
}

TEST(StreetNetwork, DecomposeGivesEdgesAndVertices) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const StreetNetwork net{{{0, 0, 0}, {1, 0, 0}, {nan, 0, 0}, {1, 1, 2}},
                          {{0, 1}, {1, 2}, {3, 1}, {0, 7}}};
  const StreetParts parts = decompose(net);
  ASSERT_EQ(parts.edges.size(), 2U);
  EXPECT_EQ(parts.edges[1].vertices, (std::vector<Vec3>{{1, 1, 2}, {1, 0, 0}}));
  EXPECT_EQ(parts.edges[1].edges, (Edges{{0, 1}}));
  EXPECT_EQ(parts.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 2}}));
}

TEST(StreetNetwork, LargeGrid) {
  const auto start = std::chrono::steady_clock::now();
  const StreetSurfaces s = street_surfaces(grid_network(21, 21, 50, 50), 10);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("21 x 21 grid: %.3f s\n", seconds);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.blocks.size(), 400U);
  for (std::size_t k = 0; k < s.blocks.size(); ++k) {
    EXPECT_NEAR(area(s.blocks[k]), 1600, 1e-6);
    // Row by row, left to right.
    EXPECT_EQ(s.blocks[k].outer[0],
              (Vec2{5.0 + 50.0 * double(k % 20), 5.0 + 50.0 * double(k / 20)}));
  }
  ASSERT_EQ(s.roads.size(), 1U);
  EXPECT_NEAR(area(s.roads[0]), 1010.0 * 1010.0 - 400 * 1600, 1e-4);
}

}  // namespace
}  // namespace insula::kernel
