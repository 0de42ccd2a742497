// The treemap's cut search (plan_treemap.cc, seed 000 §3.2 Eqs. 3-5): cell areas meet their
// targets within the search's tolerance whatever route the bisection takes, and a region whose
// area up to its far side stays below a target ends the search instead of looping.
#include "lang/bldg/plan_treemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lang/bldg/plan_geometry.h"

namespace insula::lang::bldg {
namespace {

using kernel::Polygon;
using kernel::Vec2;

// A convex polygon through n points of the ellipse centred at (cx, cy) with radii (rx, ry).
Polygon ellipse_polygon(double cx, double cy, double rx, double ry, int n, double phase) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * M_PI * i / n;
    p.outer.push_back({cx + rx * std::cos(a), cy + ry * std::sin(a)});
  }
  return p;
}

TEST(PlanTreemapSearch, CellAreasMeetTheirTargetsOnRectanglesAndConvexRegions) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int it = 0; it < 400; ++it) {
    const double w = 1 + 30 * u(rng);
    const double h = 1 + 30 * u(rng);
    const double x0 = 100 * (u(rng) - 0.5);
    const double y0 = 100 * (u(rng) - 0.5);
    const Polygon region = it % 2 == 0 ? plan::rectangle(x0, y0, x0 + w, y0 + h)
                                       : ellipse_polygon(x0, y0, w, h, 3 + it % 10, u(rng));
    std::vector<double> weights;
    for (int k = 0; k < 2 + it % 5; ++k) weights.push_back(0.1 + 3 * u(rng));
    double total_weight = 0;
    for (double x : weights) total_weight += x;
    const bool along_x = it % 3 != 0;
    const auto cells = plan::split_region({region}, weights, along_x, 0.01);
    ASSERT_EQ(cells.size(), weights.size());
    const double total = plan::area_of({region});
    // Every cut lands within 1e-9 of the region's area of its cumulative target (the cells
    // themselves are simplified, which moves their areas by far less than the 1e-7 allowed).
    double cumulative = 0;
    double reached = 0;
    for (std::size_t i = 0; i + 1 < weights.size(); ++i) {
      cumulative += weights[i] / total_weight;
      reached += plan::area_of(cells[i]);
      EXPECT_NEAR(reached, total * cumulative, 1e-7 * total) << "case " << it << " cut " << i;
    }
    reached += plan::area_of(cells.back());
    EXPECT_NEAR(reached, total, 1e-7 * total) << "case " << it;
  }
}

TEST(PlanTreemapSearch, RegionShortOfTheTargetEndsTheSearch) {
  // A rectangle and a clockwise triangle beside it (found by a random search): the area up to
  // the region's far side stays below the first cut's target, and start + (end - start) rounds
  // below end, which once made the Eq. 5 growth repeat its last step forever.
  const Polygon a{{{-3.2038821082759017, 47.636439875402559},
                   {-1.8063521161524501, 47.636439875402559},
                   {-1.8063521161524501, 64.872094341906447},
                   {-3.2038821082759017, 64.872094341906447}},
                  {}};
  const Polygon b{{{0.19364788384754994, 47.636439875402559},
                   {-0.40882212402899842, 48.636439875402559},
                   {-0.40882212402899842, 64.872094341906447}},
                  {}};
  const auto cells =
      plan::split_region({a, b}, {1.926892230248477, 0.083919050460558267}, true, 0.01);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_FALSE(cells[0].empty());
}

}  // namespace
}  // namespace insula::lang::bldg
