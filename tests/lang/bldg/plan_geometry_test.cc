// Ring simplification of the floor-plan engine (plan_geometry.h): simplify and wall_count give
// what the plain rule gives (erase the redundant vertex of lowest index, again and again, until
// none is left; redundant: an edge beside it shorter than kLineTolerance, or it lies between its
// neighbours within kLineTolerance of the line joining them), on rings full of repeated and
// nearly collinear vertices.
#include "lang/bldg/plan_geometry.h"
#include "kernel/planar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace insula::lang::bldg {
namespace {

using kernel::Polygon;
using kernel::Ring;
using kernel::Vec2;

bool plain_redundant(Vec2 a, Vec2 b, Vec2 c) {
  const double tol = plan::kLineTolerance;
  const Vec2 ac = c - a;
  const Vec2 ab = b - a;
  const Vec2 bc = c - b;
  if (kernel::dot(ab, ab) < tol * tol || kernel::dot(bc, bc) < tol * tol) return true;
  if (!(kernel::dot(ab, bc) > 0)) return false;
  const double len2 = kernel::dot(ac, ac);
  if (len2 < tol * tol) return false;
  return std::abs(kernel::cross(ac, ab)) / std::sqrt(len2) < tol;
}

Ring plain_simplify(Ring ring) {
  for (bool erased = true; erased && ring.size() >= 3;) {
    erased = false;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (plain_redundant(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n])) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        erased = true;
        break;
      }
    }
  }
  return ring;
}

// A rectangle-like ring with extra vertices on its edges (exactly on, a few micrometres off, or
// off by more than the tolerance), repeated vertices and tiny steps.
Ring noisy_ring(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double w = 1 + 20 * u(rng);
  const double h = 1 + 20 * u(rng);
  const Vec2 corners[] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  const double offs[] = {0, 2e-6, -4e-6, 9e-6, 2e-5, 1e-3};
  Ring ring;
  for (int k = 0; k < 4; ++k) {
    const Vec2 a = corners[k];
    const Vec2 b = corners[(k + 1) % 4];
    const Vec2 n = kernel::perp(kernel::normalized(b - a));
    ring.push_back(a);
    const int extra = static_cast<int>(u(rng) * 4);
    for (int e = 0; e < extra; ++e) {
      const double t = (e + u(rng)) / (extra + 1);
      const Vec2 p = a + (b - a) * t + n * offs[static_cast<int>(u(rng) * 6)];
      ring.push_back(p);
      if (u(rng) < 0.2) ring.push_back(p);                  // repeated
      if (u(rng) < 0.1) ring.push_back(p + Vec2{3e-6, 0});  // a tiny step
    }
  }
  // Start anywhere on the ring: the first and last vertices' special cases are taken too.
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(u(rng) * ring.size()),
              ring.end());
  return ring;
}

TEST(PlanGeometry, SimplifyAndWallCountFollowThePlainRule) {
  std::mt19937_64 rng(5);
  int changed = 0;
  int unchanged = 0;
  for (int it = 0; it < 20000; ++it) {
    const Ring ring = noisy_ring(rng);
    const Ring expected = plain_simplify(ring);
    Polygon p{ring, {}};
    plan::simplify(p);
    ASSERT_EQ(p.outer.size(), expected.size()) << "ring " << it;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(p.outer[k].x, expected[k].x);
      EXPECT_EQ(p.outer[k].y, expected[k].y);
    }
    EXPECT_EQ(plan::wall_count(Polygon{ring, {}}), static_cast<int>(expected.size()));
    (expected.size() == ring.size() ? unchanged : changed) += 1;
  }
  // Both kinds of rings occur.
  EXPECT_GT(changed, 1000);
  EXPECT_GT(unchanged, 200);
}

TEST(PlanGeometry, ASquareKeepsFourWallsAndItsCollinearVertexGoes) {
  const Polygon square{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}};
  EXPECT_EQ(plan::wall_count(square), 4);
  Polygon with_mid{{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {}};
  EXPECT_EQ(plan::wall_count(with_mid), 4);
  plan::simplify(with_mid);
  EXPECT_EQ(with_mid.outer, square.outer);
}

// touching_boxes' rows hold, in increasing order, exactly the other boxes kernel::touches finds.
TEST(PlanGeometry, TouchingBoxesListEveryTouchingBoxInIncreasingOrder) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  int pairs = 0;
  for (int it = 0; it < 200; ++it) {
    std::vector<kernel::Bounds2> boxes(1 + it % 60);
    for (kernel::Bounds2& b : boxes) {
      // On a coarse grid, so that many boxes share sides exactly or nearly.
      const double x = std::round(20 * u(rng)) + (u(rng) < 0.3 ? 1e-6 : 0);
      const double y = std::round(20 * u(rng));
      b.min = {x, y};
      b.max = {x + 1 + std::round(4 * u(rng)), y + 1 + std::round(4 * u(rng))};
    }
    const plan::NearLists lists = plan::touching_boxes(boxes, plan::kLineTolerance);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      std::vector<std::uint32_t> expected;
      for (std::size_t j = 0; j < boxes.size(); ++j)
        if (j != i && kernel::touches(boxes[i], boxes[j], plan::kLineTolerance))
          expected.push_back(static_cast<std::uint32_t>(j));
      const auto row = lists.of(i);
      EXPECT_EQ(std::vector<std::uint32_t>(row.begin(), row.end()), expected);
      pairs += static_cast<int>(expected.size());
    }
  }
  EXPECT_GT(pairs, 10000);
}

}  // namespace
}  // namespace insula::lang::bldg
