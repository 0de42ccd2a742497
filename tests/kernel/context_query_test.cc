#include "kernel/context_query.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <vector>

namespace insula::kernel {
namespace {

// Runs f and prints how long it took: the scale tests report times without asserting them.
template <class F>
auto timed(const char* what, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  auto result = f();
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  std::cout << what << ": " << took.count() << " ms\n";
  return result;
}

// ---- k-means ----

TEST(KMeans, TwoObviousClustersConvergeInThreePasses) {
  // Centres start at the first two points, (0) and (1); pass 1 puts 1, 10 and 11 with the
  // second (mean 22/3), pass 2 moves 1 to the first, pass 3 changes nothing.
  const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {10, 0, 0}, {11, 0, 0}};
  const KMeansResult r = kmeans(points, 2, 100);
  EXPECT_EQ(r.cluster, (std::vector<int>{0, 0, 1, 1}));
  ASSERT_EQ(r.centers.size(), 2u);
  EXPECT_EQ(r.centers[0], (Vec3{0.5, 0, 0}));
  EXPECT_EQ(r.centers[1], (Vec3{10.5, 0, 0}));
  EXPECT_EQ(r.iterations, 3);
}

TEST(KMeans, StopsAtMaxIterationsWithCentersOfTheReturnedAssignment) {
  const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {10, 0, 0}, {11, 0, 0}};
  const KMeansResult r = kmeans(points, 2, 1);
  EXPECT_EQ(r.cluster, (std::vector<int>{0, 1, 1, 1}));
  EXPECT_EQ(r.centers[0], (Vec3{0, 0, 0}));
  EXPECT_DOUBLE_EQ(r.centers[1].x, 22.0 / 3);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(kmeans(points, 2, 0).iterations, 1);  // at least one pass
}

TEST(KMeans, TieGoesToTheLowerCluster) {
  // (1,0,0) is as far from centre 0 at the origin as from centre 1 at (2,0,0).
  const std::vector<Vec3> points{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}};
  const KMeansResult first = kmeans(points, 2, 1);
  EXPECT_EQ(first.cluster, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(first.centers[0], (Vec3{0.5, 0, 0}));
  const KMeansResult r = kmeans(points, 2, 100);
  EXPECT_EQ(r.cluster, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(r.iterations, 2);
}

TEST(KMeans, EmptyClusterKeepsItsCentroid) {
  // Both centres start at the origin: every point ties and goes to cluster 0, cluster 1 is empty
  // and keeps the origin, which then wins the two origin points back.
  const std::vector<Vec3> points{{0, 0, 0}, {0, 0, 0}, {5, 0, 0}};
  const KMeansResult one = kmeans(points, 2, 1);
  EXPECT_EQ(one.cluster, (std::vector<int>{0, 0, 0}));
  EXPECT_DOUBLE_EQ(one.centers[0].x, 5.0 / 3);
  EXPECT_EQ(one.centers[1], (Vec3{0, 0, 0}));
  const KMeansResult r = kmeans(points, 2, 100);
  EXPECT_EQ(r.cluster, (std::vector<int>{1, 1, 0}));
  EXPECT_EQ(r.centers[0], (Vec3{5, 0, 0}));
  EXPECT_EQ(r.centers[1], (Vec3{0, 0, 0}));
  EXPECT_EQ(r.iterations, 3);
}

TEST(KMeans, MoreClustersThanPointsActsAsOneClusterPerPoint) {
  const std::vector<Vec3> points{{3, 1, 0}, {-2, 4, 1}};
  const KMeansResult r = kmeans(points, 5, 100);
  EXPECT_EQ(r.cluster, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.centers, points);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_TRUE(kmeans(points, 0, 100).centers.empty());
  EXPECT_TRUE(kmeans({}, 3, 100).cluster.empty());
}

// ---- ray cast ----

Mesh box(Vec3 origin, Vec3 size) {
  Mesh m;
  add_box(m, origin, {size.x, 0, 0}, {0, size.y, 0}, {0, 0, size.z}, {});
  return m;
}

std::vector<Mesh> stacked_boxes() {
  return {box({0, 0, 0}, {1, 1, 1}), box({0, 0, 2}, {1, 1, 1})};
}

TEST(RayCast, HitsTheNearestOfTwoStackedBoxes) {
  const std::vector<Ray> rays{{{0.5, 0.5, 10}, {0, 0, -1}, 1e9}, {{5, 5, 10}, {0, 0, -1}, 1e9}};
  const RayCastResult r = ray_cast(rays, stacked_boxes());
  EXPECT_EQ(r.hits[0].target, 1);
  EXPECT_EQ(r.hits[0].distance, 7);
  EXPECT_EQ(r.hits[0].position, (Vec3{0.5, 0.5, 3}));
  EXPECT_EQ(r.hits[1].target, -1);  // misses
  EXPECT_EQ(r.hits[1].distance, -1);
  EXPECT_EQ(r.target_hit, (std::vector<bool>{false, true}));
}

TEST(RayCast, SkipPredicateAndMaxDistance) {
  const auto skip_upper = [](std::size_t, std::size_t target) { return target == 1; };
  const std::vector<Ray> rays{{{0.5, 0.5, 10}, {0, 0, -2}, 9}, {{0.5, 0.5, 10}, {0, 0, -1}, 8.5}};
  const RayCastResult r = ray_cast(rays, stacked_boxes(), skip_upper);
  EXPECT_EQ(r.hits[0].target, 0);  // exactly at max_distance; direction normalised
  EXPECT_EQ(r.hits[0].distance, 9);
  EXPECT_EQ(r.hits[0].position, (Vec3{0.5, 0.5, 1}));
  EXPECT_EQ(r.hits[1].target, -1);  // the lower box is 9 away, beyond 8.5
  EXPECT_EQ(r.target_hit, (std::vector<bool>{true, false}));
}

TEST(RayCast, RayFromInsideHitsTheFarFaceAndTiesGoToTheLowerTarget) {
  const std::vector<Mesh> twins{box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1})};
  const std::vector<Ray> rays{{{0.5, 0.5, 0.5}, {1, 0, 0}, 1e9}};
  const RayCastResult r = ray_cast(rays, twins);
  EXPECT_EQ(r.hits[0].target, 0);
  EXPECT_EQ(r.hits[0].distance, 0.5);
  const RayCastResult skipped =
      ray_cast(rays, twins, [](std::size_t, std::size_t target) { return target == 0; });
  EXPECT_EQ(skipped.hits[0].target, 1);
}

TEST(RayCast, ConcaveFaceIsTestedAsAPolygon) {
  // An L-shaped floor: the notch at x, y in (1, 2) is not part of it.
  Mesh l;
  l.add_polygon(std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
                {});
  const std::vector<Ray> rays{{{1.5, 1.5, 1}, {0, 0, -1}, 1e9}, {{0.5, 1.5, 1}, {0, 0, -1}, 1e9}};
  const RayCastResult r = ray_cast(rays, std::vector<Mesh>{l});
  EXPECT_EQ(r.hits[0].target, -1);
  EXPECT_EQ(r.hits[1].target, 0);
  EXPECT_EQ(r.hits[1].distance, 1);
}

TEST(RayCast, TenThousandRaysAgainstTenThousandBoxesUseTheHierarchy) {
  // Unit boxes every 2 m; each ray starts at its own box's centre (skipped) and looks along +x,
  // so it hits the next box of its row 1.5 m away, except in the last column.
  constexpr int kSide = 100;
  std::vector<Mesh> boxes;
  std::vector<Ray> rays;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      boxes.push_back(box({2.0 * i, 2.0 * j, 0}, {1, 1, 1}));
      rays.push_back({{2.0 * i + 0.5, 2.0 * j + 0.5, 0.5}, {1, 0, 0}, 1e9});
    }
  }
  const auto own = [](std::size_t ray, std::size_t target) { return ray == target; };
  const RayCastResult r =
      timed("10,000 rays x 10,000 boxes", [&] { return ray_cast(rays, boxes, own); });
  std::cout << r.face_tests << " face tests\n";
  std::size_t hits = 0, targets_hit = 0;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      const RayHit& hit = r.hits[j * kSide + i];
      if (i + 1 < kSide) {
        ASSERT_EQ(hit.target, j * kSide + i + 1) << i << "," << j;
        ASSERT_EQ(hit.distance, 1.5);
        ASSERT_EQ(hit.position, (Vec3{2.0 * i + 2, 2.0 * j + 0.5, 0.5}));
        ++hits;
      } else {
        ASSERT_EQ(hit.target, -1);
      }
      ASSERT_EQ(r.target_hit[j * kSide + i], i > 0);
      targets_hit += r.target_hit[j * kSide + i] ? 1 : 0;
    }
  }
  EXPECT_EQ(hits, 9900u);
  EXPECT_EQ(targets_hit, 9900u);
  // Brute force would make 10,000 x 60,000 face tests; the hierarchy needs a few dozen per ray.
  EXPECT_LT(r.face_tests, 20u * rays.size());
}

TEST(RayCast, DegenerateRaysAndFacesHitNothing) {
  Mesh sliver;  // a face of zero area has no plane
  sliver.add_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {});
  const std::vector<Mesh> targets{sliver, box({0, 0, 0}, {1, 1, 1})};
  const std::vector<Ray> rays{{{0.5, 0.5, 5}, {0, 0, 0}, 1e9},
                              {{0.5, 0.5, 5}, {0, 0, -1}, std::nan("")},
                              {{0.5, 0.5, 5}, {0, 0, -1}, -1},
                              {{0.5, -1, 0.5}, {1, 0, 0}, 1e9}};  // parallel to the box's sides
  const RayCastResult r = ray_cast(rays, targets);
  for (const RayHit& hit : r.hits) EXPECT_EQ(hit.target, -1);
  EXPECT_TRUE(ray_cast(rays, std::vector<Mesh>{}).hits[3].target == -1);
}

// ---- occlusion ----

// A 10 x 10 wall in the plane y = 0 facing -y.
FlatShape wall() {
  return {{{{0, 0, 0}, {10, 0, 0}, {10, 0, 10}, {0, 0, 10}}}, {0, -1, 0}};
}

BoxEdges aabb(Vec3 min, Vec3 max) {
  return {min, {max.x - min.x, 0, 0}, {0, max.y - min.y, 0}, {0, 0, max.z - min.z}};
}

double occlusion_of_wall(const std::vector<BoxEdges>& boxes, double distance = 10) {
  return occlusion(std::vector<FlatShape>{wall()}, boxes, distance)[0];
}

TEST(Occlusion, BoxOverTheLeftHalfInFrontCoversHalf) {
  EXPECT_NEAR(occlusion_of_wall({aabb({0, -3, 0}, {5, -1, 10})}), 0.5, 1e-12);
  // Reaching past the wall's edges changes nothing.
  EXPECT_NEAR(occlusion_of_wall({aabb({-4, -3, -2}, {5, -1, 20})}), 0.5, 1e-12);
}

TEST(Occlusion, BoxesBehindOrBeyondTheDistanceDoNotOcclude) {
  EXPECT_EQ(occlusion_of_wall({aabb({0, 1, 0}, {5, 3, 10})}), 0);      // behind
  EXPECT_EQ(occlusion_of_wall({aabb({0, 0, 0}, {5, 2, 10})}), 0);      // touching from behind
  EXPECT_EQ(occlusion_of_wall({aabb({0, -15, 0}, {5, -12, 10})}), 0);  // beyond 10 m
  EXPECT_EQ(occlusion_of_wall({aabb({0, -15, 0}, {5, -12, 10})}, 0), 0);
  // Only part of the box lies in the slab: still the full projection.
  EXPECT_NEAR(occlusion_of_wall({aabb({0, -12, 0}, {5, -8, 10})}), 0.5, 1e-12);
  EXPECT_NEAR(occlusion_of_wall({aabb({0, -1, 0}, {5, 1, 10})}), 0.5, 1e-12);  // straddles
}

TEST(Occlusion, OverlappingBoxesAreNotCountedTwice) {
  // Each covers 6 x 5 = 30 of the 100 m^2; together x in [0, 10], z in [0, 5].
  EXPECT_NEAR(occlusion_of_wall({aabb({0, -3, 0}, {6, -1, 5}), aabb({4, -5, 0}, {10, -2, 5})}), 0.5,
              1e-12);
}

TEST(Occlusion, OrientedAndFlatBoxes) {
  // A box turned 45 degrees about the wall normal projects to a diamond of 8 m^2.
  const BoxEdges turned{{5, -1, 1}, {2, 0, 2}, {0, -2, 0}, {-2, 0, 2}};
  EXPECT_NEAR(occlusion_of_wall({turned}), 0.08, 1e-12);
  // A flat occluder (a facade scope of zero depth) parallel to the wall, 2 m in front.
  const BoxEdges flat{{0, -2, 0}, {5, 0, 0}, {0, 0, 0}, {0, 0, 10}};
  EXPECT_NEAR(occlusion_of_wall({flat}), 0.5, 1e-12);
}

TEST(Occlusion, SkipPredicateAndSeveralShapes) {
  const std::vector<BoxEdges> boxes{aabb({0, -3, 0}, {5, -1, 10}), aabb({5, -3, 0}, {10, -1, 10})};
  const FlatShape roof{{{{0, -3, 12}, {10, -3, 12}, {10, 0, 12}, {0, 0, 12}}}, {0, 0, 1}};
  const std::vector<FlatShape> shapes{wall(), roof};
  const std::vector<double> all = occlusion(shapes, boxes, 10);
  EXPECT_NEAR(all[0], 1, 1e-12);
  EXPECT_EQ(all[1], 0);  // the boxes lie below the roof
  const auto skip = [](std::size_t shape, std::size_t box) { return shape == 0 && box == 1; };
  EXPECT_NEAR(occlusion(shapes, boxes, 10, skip)[0], 0.5, 1e-12);
}

TEST(Occlusion, SouthFacesOfTenThousandBoxes) {
  // Unit boxes every 2 m: each south face has the box of the row before 1 m in front of it,
  // covering it exactly, except in the first row.
  constexpr int kSide = 100;
  std::vector<FlatShape> faces;
  std::vector<BoxEdges> boxes;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      const double x = 2.0 * i, y = 2.0 * j;
      boxes.push_back(aabb({x, y, 0}, {x + 1, y + 1, 1}));
      faces.push_back({{{{x, y, 0}, {x + 1, y, 0}, {x + 1, y, 1}, {x, y, 1}}}, {0, -1, 0}});
    }
  }
  const auto own = [](std::size_t face, std::size_t box) { return face == box; };
  const std::vector<double> r =
      timed("10,000 faces x 10,000 boxes", [&] { return occlusion(faces, boxes, 1.5, own); });
  for (int k = 0; k < kSide * kSide; ++k) ASSERT_NEAR(r[k], k < kSide ? 0 : 1, 1e-12) << k;
}

TEST(Occlusion, DegenerateShapesAndDistances) {
  const std::vector<BoxEdges> boxes{aabb({0, -3, 0}, {5, -1, 10})};
  const std::vector<FlatShape> shapes{
      {}, {{{{0, 0, 0}, {10, 0, 0}, {20, 0, 0}}}, {0, -1, 0}}, {wall().loops, {0, 0, 0}}};
  for (const double occluded : occlusion(shapes, boxes, 10)) EXPECT_EQ(occluded, 0);
  EXPECT_EQ(occlusion(std::vector<FlatShape>{wall()}, boxes, std::nan(""))[0], 0);
  EXPECT_EQ(occlusion(std::vector<FlatShape>{wall()}, boxes, -1)[0], 0);
}

// ---- is oriented to ----

// A wall whose bottom edge midpoint is the origin, facing -y.
constexpr OrientedFace kSouthFace{{0, 0}, {0, -1, 0}};
const std::vector<StreetSegment> kStreetInFront{{{-10, -20}, {10, -20}}};

bool oriented(const OrientedFace& face, const std::vector<StreetSegment>& streets,
              const std::vector<Polygon>& occluders = {}, double tolerance = 45,
              double max_distance = 1e9, const SkipPredicate& skip = {}) {
  return is_oriented_to(std::vector<OrientedFace>{face}, streets, occluders, tolerance,
                        max_distance, skip)[0];
}

Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

TEST(IsOrientedTo, StreetInFrontOrBehind) {
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront));
  EXPECT_FALSE(oriented(kSouthFace, {{{-10, 20}, {10, 20}}}));
  // A street running along the far side, out of a 10 degree cone but inside a 30 degree one.
  const std::vector<StreetSegment> off{{{5, -10}, {5, -25}}};  // 26.6 to 11.3 degrees off
  EXPECT_FALSE(oriented(kSouthFace, off, {}, 10));
  EXPECT_TRUE(oriented(kSouthFace, off, {}, 30));
}

TEST(IsOrientedTo, StreetAtFiftyDegreesNeedsThatTolerance) {
  // A 2 m street across the sight line 50 degrees off the normal, 20 m away: it spans 47.1 to
  // 52.9 degrees.
  constexpr double kRad = 50 * 3.14159265358979323846 / 180;
  const Vec2 dir{std::sin(kRad), -std::cos(kRad)};
  const std::vector<StreetSegment> street{{dir * 20 - perp(dir), dir * 20 + perp(dir)}};
  EXPECT_FALSE(oriented(kSouthFace, street, {}, 45));
  EXPECT_TRUE(oriented(kSouthFace, street, {}, 48));
  EXPECT_TRUE(oriented(kSouthFace, {{{5, -0.5}, {10, -0.5}}}, {}, 90));  // along the wall
  EXPECT_FALSE(oriented(kSouthFace, {{{5, -0.5}, {10, -0.5}}}, {}, 80));
}

TEST(IsOrientedTo, StreetsSeenUnderNoAngleDoNotCount) {
  // Tolerance 0 admits one sight line.
  EXPECT_FALSE(oriented(kSouthFace, {{{-1, -20}, {10, -20}}}, {}, 0));
  EXPECT_TRUE(oriented(kSouthFace, {{{-1, -20}, {10, -20}}}, {}, 1));
  // A street lying on a sight line, or meeting the cone in one point.
  EXPECT_FALSE(oriented(kSouthFace, {{{0, -5}, {0, -30}}}));
  EXPECT_FALSE(oriented(kSouthFace, {{{20, -20}, {30, -20}}}));
  EXPECT_TRUE(oriented(kSouthFace, {{{19, -20}, {30, -20}}}));
}

TEST(IsOrientedTo, BlockedByAnOccluderUnlessSkippedOrSeenThroughAGap) {
  const Polygon block = rect(-15, -12, 15, -8);
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {block}));
  const auto skip_it = [](std::size_t, std::size_t) { return true; };
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront, {block}, 45, 1e9, skip_it));
  // Blocking only the left part leaves the street's right part visible.
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront, {rect(-15, -12, 3, -8)}));
  // Two thin blocks 0.2 m apart: sight lines through the gap reach x in (5.86, 6.14) of the
  // street, though no sight line to the street's middle or ends gets through.
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront,
                       {rect(-15, -10.1, 2.9, -9.9), rect(3.1, -10.1, 15, -9.9)}));
  // Closed gap: the blocks touch, so only the sight line along their shared edge passes.
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {rect(-15, -12, 3, -8), rect(3, -12, 15, -8)}));
  // A block touching sight lines only along its edge does not hide what lies beside it.
  EXPECT_TRUE(oriented(kSouthFace, {{{-1, -20}, {0, -20}}}, {rect(0, -12, 5, -8)}, 10));
  // A street through a footprint is seen up to the footprint.
  EXPECT_TRUE(oriented(kSouthFace, {{{0.2, -5}, {0, -20}}}, {rect(-15, -12, 15, -8)}));
}

TEST(IsOrientedTo, PartyWallFacingATouchingNeighbourSeesNothing) {
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {rect(-5, -10, 5, 0)}));
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {rect(0, -10, 5, 0), rect(-5, -10, 0, 0)}));
  // A neighbour touching only beside the wall's cone hides nothing.
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront, {rect(0.5, -10, 5, 0)}, 2));
}

TEST(IsOrientedTo, TenThousandTouchingFootprints) {
  // A solid 100 x 100 block of touching unit footprints, a street 0.5 m east of it: only the
  // east walls of the last column see it; the others face their neighbours.
  constexpr int kSide = 100;
  std::vector<Polygon> footprints;
  std::vector<OrientedFace> faces;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      footprints.push_back(rect(i, j, i + 1, j + 1));
      faces.push_back({{i + 1.0, j + 0.5}, {1, 0, 0}});
    }
  }
  const std::vector<StreetSegment> street{{{kSide + 0.5, -10}, {kSide + 0.5, kSide + 10}}};
  const auto own = [](std::size_t face, std::size_t footprint) { return footprint == face; };
  const std::vector<bool> r = timed("10,000 party walls", [&] {
    return is_oriented_to(faces, street, footprints, 45, 1e9, own);
  });
  for (int k = 0; k < kSide * kSide; ++k) ASSERT_EQ(r[k], k % kSide == kSide - 1) << k;
}

TEST(IsOrientedTo, RoofsAndFloorsNeverAre) {
  EXPECT_FALSE(oriented({{0, 0}, {0, -0.5, 0.9}}, kStreetInFront));
  EXPECT_FALSE(oriented({{0, 0}, {0, -1, 1}}, kStreetInFront));  // exactly 45 degrees
  EXPECT_FALSE(oriented({{0, 0}, {0, 0, -1}}, kStreetInFront));
  EXPECT_TRUE(oriented({{0, 0}, {0, -1, 0.9}}, kStreetInFront));
}

TEST(IsOrientedTo, MaxDistance) {
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {}, 45, 15));
  EXPECT_FALSE(oriented(kSouthFace, kStreetInFront, {}, 45, 20));  // touches it in one point
  EXPECT_TRUE(oriented(kSouthFace, kStreetInFront, {}, 45, 21));
  EXPECT_FALSE(oriented(kSouthFace, {}, {}, 45));
}

TEST(IsOrientedTo, TwentyThousandWallsOfAGridOfBlocks) {
  // 100 x 100 unit footprints every 2 m, a street 0.5 m south of each row. Every south wall sees
  // its street; within 20 degrees an east wall sees only the next footprint of its row, except in
  // the last column.
  constexpr int kSide = 100;
  std::vector<Polygon> footprints;
  std::vector<OrientedFace> faces;
  std::vector<StreetSegment> streets;
  for (int j = 0; j <= kSide; ++j) streets.push_back({{-1, 2.0 * j - 0.5}, {210, 2.0 * j - 0.5}});
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      footprints.push_back(rect(2.0 * i, 2.0 * j, 2.0 * i + 1, 2.0 * j + 1));
      faces.push_back({{2.0 * i + 0.5, 2.0 * j}, {0, -1, 0}});
      faces.push_back({{2.0 * i + 1, 2.0 * j + 0.5}, {1, 0, 0}});
    }
  }
  const auto own = [](std::size_t face, std::size_t footprint) { return footprint == face / 2; };
  const std::vector<bool> r = timed("20,000 walls, 10,000 footprints, 101 streets", [&] {
    return is_oriented_to(faces, streets, footprints, 20, 1e9, own);
  });
  for (int k = 0; k < kSide * kSide; ++k) {
    ASSERT_TRUE(r[2 * k]) << k;
    ASSERT_EQ(r[2 * k + 1], k % kSide == kSide - 1) << k;
  }
}

// ---- distance ----

Footprint square(double x, double y, double side = 1) {
  return {{rect(x, y, x + side, y + side)}, {}, {}};
}

TEST(NearestTargets, DistanceBetweenSquares) {
  const std::vector<Footprint> targets{square(3, 3), square(3, 0), square(-5, 0)};
  const std::vector<NearestTarget> r =
      nearest_targets(std::vector<Footprint>{square(0, 0)}, targets);
  EXPECT_EQ(r[0].target, 1);
  EXPECT_EQ(r[0].distance, 2);
  const auto skip_one = [](std::size_t, std::size_t t) { return t == 1; };
  const std::vector<NearestTarget> s =
      nearest_targets(std::vector<Footprint>{square(0, 0)}, targets, skip_one);
  EXPECT_EQ(s[0].target, 0);
  EXPECT_DOUBLE_EQ(s[0].distance, std::sqrt(8.0));
  const auto skip_all = [](std::size_t, std::size_t) { return true; };
  const NearestTarget none =
      nearest_targets(std::vector<Footprint>{square(0, 0)}, targets, skip_all)[0];
  EXPECT_EQ(none.target, -1);
  EXPECT_EQ(none.distance, -1);
}

TEST(NearestTargets, OverlapInsideHolesPointsAndSegments) {
  Polygon ring = rect(0, 0, 10, 10);
  ring.holes.push_back({{3, 3}, {3, 7}, {7, 7}, {7, 3}});
  const std::vector<Footprint> targets{{{ring}, {}, {}}};
  const std::vector<Footprint> entities{
      square(1, 1),                      // inside the region
      square(4, 4, 1),                   // inside the hole, 1 m from its edges
      square(9.5, 4),                    // overlapping the outer edge
      {{}, {{12, 5}}, {}},               // a point 2 m east
      {{}, {}, {{{-3, -3}, {-1, -1}}}},  // a segment towards the corner
      {{}, {}, {}},                      // no geometry
  };
  const std::vector<NearestTarget> r = nearest_targets(entities, targets);
  EXPECT_EQ(r[0].distance, 0);
  EXPECT_EQ(r[1].distance, 1);
  EXPECT_EQ(r[2].distance, 0);
  EXPECT_EQ(r[3].distance, 2);
  EXPECT_DOUBLE_EQ(r[4].distance, std::sqrt(2.0));
  EXPECT_EQ(r[5].target, -1);
  EXPECT_EQ(r[0].target, 0);
}

TEST(NearestTargets, GridOfTenThousandSquaresTiesGoToTheLowerIndex) {
  // Points halfway between two neighbouring unit squares of a row are 0.5 m from both.
  constexpr int kSide = 100;
  std::vector<Footprint> targets, points;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      targets.push_back(square(2.0 * i, 2.0 * j));
      points.push_back({{}, {{2.0 * i + 1.5, 2.0 * j + 0.5}}, {}});
    }
  }
  const std::vector<NearestTarget> r =
      timed("10,000 points x 10,000 squares", [&] { return nearest_targets(points, targets); });
  for (int k = 0; k < kSide * kSide; ++k) {
    ASSERT_EQ(r[k].target, k) << k;
    ASSERT_EQ(r[k].distance, 0.5);
  }
}

}  // namespace
}  // namespace insula::kernel
