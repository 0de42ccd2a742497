// Adversarial inputs for the rectilinear straight skeleton (skeleton_rectilinear.h): many holes,
// near-degenerate and one-ulp widths, huge and tiny scales far from the origin, slivers, spirals,
// combs, staircases, crosses, nested courtyards, collinear vertices and the 1,024-vertex limit.
// For each input: whenever rectilinear_straight_skeleton returns a skeleton it must be CGAL's
// (general_straight_skeleton) face by face, and interior_straight_skeleton must always answer for
// a simple polygon CGAL handles. Declines (nullopt: CGAL takes over) are allowed; each test counts
// them and prints the count so a regression to "declines everything" shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "kernel/boolean2d.h"
#include "kernel/polygon.h"
#include "kernel/skeleton.h"
#include "kernel/skeleton_rectilinear.h"
#include "skeleton_checks.h"

namespace insula::kernel {
namespace {

using testing_skeleton::expect_matches;
using testing_skeleton::expect_valid;
using testing_skeleton::face_ring;

struct Tally {
  int compared = 0;  // the rectilinear builder answered and matched CGAL
  int declined = 0;  // it returned nullopt (CGAL took over)
  int skipped = 0;   // CGAL itself failed or the polygon is not simple: nothing to compare with
  std::vector<std::string> declined_names;
  void print(const char* what) const {
    std::printf("[ tally    ] %s: %d compared, %d declined, %d without reference\n", what, compared,
                declined, skipped);
    for (const std::string& name : declined_names) std::printf("[ declined ] %s\n", name.c_str());
  }
};

// Compares the rectilinear builder with CGAL on `polygon` (normalized orientation).
void check(const Polygon& polygon, const std::string& what, Tally& tally) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(is_rectilinear(polygon)) << what;
  if (!is_simple_polygon(polygon)) {
    ++tally.skipped;
    ADD_FAILURE() << what << ": the generator made a polygon is_simple_polygon rejects";
    return;
  }
  const auto ours = rectilinear_straight_skeleton(polygon);
  const auto reference = general_straight_skeleton(polygon);
  const auto chosen = interior_straight_skeleton(polygon);
  if (!reference.has_value()) {
    ++tally.skipped;
    // CGAL could not: the rectilinear builder may still answer, and then must be valid.
    if (ours.has_value()) expect_valid(polygon, *ours, what);
    return;
  }
  // A simple polygon CGAL handles always gets a skeleton, from whichever builder.
  ASSERT_TRUE(chosen.has_value()) << what;
  EXPECT_EQ(chosen->contour_count, reference->contour_count) << what;
  if (!ours.has_value()) {
    ++tally.declined;
    tally.declined_names.push_back(what);
    return;
  }
  expect_valid(polygon, *ours, what);
  expect_matches(polygon, *ours, *reference, what);
  ++tally.compared;
}

// A number as %g prints it (std::to_string writes 1e-9 as 0.000000).
std::string str(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// A clockwise rectangular hole.
Ring hole(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
}

Polygon transformed(Polygon p, double scale, Vec2 offset) {
  auto apply = [&](Ring& ring) {
    for (Vec2& v : ring) v = Vec2{v.x * scale + offset.x, v.y * scale + offset.y};
  };
  apply(p.outer);
  for (Ring& h : p.holes) apply(h);
  return p;
}

// The polygon mirrored across the diagonal (x <-> y), rings reversed to stay normalized: the
// same skeleton with horizontal and vertical swapped.
Polygon swapped(Polygon p) {
  auto apply = [](Ring& ring) {
    for (Vec2& v : ring) std::swap(v.x, v.y);
    std::reverse(ring.begin(), ring.end());
  };
  apply(p.outer);
  for (Ring& h : p.holes) apply(h);
  return p;
}

// The polygon's rings started at another vertex (a different contour numbering).
Polygon rotated_start(Polygon p, std::size_t k) {
  std::rotate(p.outer.begin(), p.outer.begin() + static_cast<std::ptrdiff_t>(k % p.outer.size()),
              p.outer.end());
  return p;
}

Polygon l_shape(double arm_x, double arm_y) {
  return {{{0, 0}, {12, 0}, {12, arm_y}, {arm_x, arm_y}, {arm_x, 12}, {0, 12}}, {}};
}

Polygon plus(double w, double arm) {
  const double a = arm, b = arm + w, c = 2 * arm + w;
  return {{{a, 0},
           {b, 0},
           {b, a},
           {c, a},
           {c, b},
           {b, b},
           {b, c},
           {a, c},
           {a, b},
           {0, b},
           {0, a},
           {a, a}},
          {}};
}

// A comb with `teeth` teeth hanging down; tooth i has width width(i) and depth depth(i).
template <class Width, class Depth>
Polygon comb(int teeth, Width width, Depth depth, double gap) {
  Polygon p;
  double x = 0;
  for (int i = 0; i < teeth; ++i) {
    // Each coordinate computed once, so that edges stay exactly axis-parallel.
    const double x1 = x + gap, x2 = x1 + width(i);
    p.outer.push_back({x, 0});
    p.outer.push_back({x1, 0});
    p.outer.push_back({x1, -depth(i)});
    p.outer.push_back({x2, -depth(i)});
    x = x2;
  }
  p.outer.push_back({x, 5});
  p.outer.push_back({0, 5});
  return p;
}

// A staircase of `steps` steps of the given treads and rises (counter-clockwise).
Polygon staircase(int steps, double tread, double rise) {
  Polygon p;
  p.outer.push_back({0, 0});
  const double side = steps * tread;
  p.outer.push_back({side, 0});
  for (int i = 0; i < steps; ++i) {
    p.outer.push_back({side - i * tread, (i + 1) * rise});
    p.outer.push_back({side - (i + 1) * tread, (i + 1) * rise});
  }
  return p;
}

TEST(RectilinearSkeletonAdversarial, StaircasesMatchCgal) {
  Tally tally;
  for (int steps : {1, 2, 3, 5, 8, 20, 60}) {
    check(staircase(steps, 1, 1), "square staircase " + std::to_string(steps), tally);
    check(staircase(steps, 2, 0.5), "flat staircase " + std::to_string(steps), tally);
    check(staircase(steps, 1, 1 + 1e-9), "almost square staircase " + std::to_string(steps), tally);
  }
  // The smallest decline found: rises 3e-10 longer than the treads, so the step events come
  // k * 3e-10 apart, around the merge tolerance (1e-10 of the size, 4e-10 here).
  check(staircase(4, 1, 1 + 3e-10), "staircase 4 rise 1 + 3e-10", tally);
  tally.print("staircases");
  EXPECT_GE(tally.compared, 15);
}

// On the 8 x 8 grid of unit holes, transposed, CGAL 5.5 read a node it had freed
// (MergeCoincidentNodes after MergeSplitNodes, heap-state dependent; docs/testing.md).
// skeleton.cc's SplitMergeGuard makes CGAL decline such input instead, so general_straight_skeleton
// may give nothing there (counted as "without reference") while the rectilinear builder answers;
// scripts/test_asan.sh runs this file under AddressSanitizer.
TEST(RectilinearSkeletonAdversarial, GridOfHolesMatchesCgal) {
  Tally tally;
  // Unit holes one unit apart (every hole's ridges meet its neighbours' at one time), then holes
  // nearly touching at their corners, then holes of alternating sizes.
  for (int n : {1, 2, 3, 4, 5, 6, 7, 8}) {
    Polygon p = rectangle(0, 0, 2.0 * n + 1, 2.0 * n + 1);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        p.holes.push_back(hole(2.0 * i + 1, 2.0 * j + 1, 2.0 * i + 2, 2.0 * j + 2));
    }
    check(p, "unit holes " + std::to_string(n), tally);
    check(swapped(p), "unit holes swapped " + std::to_string(n), tally);
  }
  for (double gap : {1e-3, 1e-6, 1e-9}) {
    // A checkerboard of holes whose corners are `gap` apart diagonally.
    const int n = 4;
    Polygon p = rectangle(-1, -1, n + 1, n + 1);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if ((i + j) % 2 != 0) continue;
        p.holes.push_back(hole(i + gap, j + gap, i + 1 - gap, j + 1 - gap));
      }
    }
    check(p, "checkerboard gap " + str(gap), tally);
  }
  {
    Polygon p = rectangle(0, 0, 40, 40);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const double s = 1 + 0.5 * ((i * 7 + j * 3) % 4);
        p.holes.push_back(hole(6.0 * i + 2, 6.0 * j + 2, 6.0 * i + 2 + s, 6.0 * j + 2 + 1.5 * s));
      }
    }
    check(p, "36 holes of four sizes", tally);
  }
  tally.print("grids of holes");
  EXPECT_GE(tally.compared, 8);
}

// The transposed 8 x 8 grid again and again, each time with the heap moved a little: CGAL 5.5
// breaks ties between simultaneous events by handle address, so whether a split-node merge would
// free a node still in use depends on the heap (docs/testing.md). In a sanitized run the guard
// declined run 19 of 50 (gdb: the throw at skeleton.cc's on_cleanup_started); in release builds
// none of 200. Every run must either decline or give a valid skeleton, with no sanitizer report
// on the way; the product answers this outline with the rectilinear builder either way.
TEST(RectilinearSkeletonAdversarial, GridOfHolesInManyHeapStates) {
  Polygon grid = rectangle(0, 0, 17, 17);
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j)
      grid.holes.push_back(hole(2.0 * i + 1, 2.0 * j + 1, 2.0 * i + 2, 2.0 * j + 2));
  }
  grid = swapped(grid);
  int declined = 0;
  std::vector<std::vector<double>> ballast;
  for (int run = 0; run < 20; ++run) {
    ballast.emplace_back(static_cast<std::size_t>(run % 7 + 1) * 13);  // moves later allocations
    const auto reference = general_straight_skeleton(grid);
    if (!reference.has_value()) {
      ++declined;
      continue;
    }
    expect_valid(grid, *reference, "unit holes swapped 8, run " + std::to_string(run));
  }
  std::printf("[ tally    ] transposed 8 x 8 grid: CGAL declined %d of 20 runs\n", declined);
  const auto chosen = interior_straight_skeleton(grid);
  ASSERT_TRUE(chosen.has_value());
  expect_valid(grid, *chosen, "unit holes swapped 8, chosen");
}

TEST(RectilinearSkeletonAdversarial, NearDegenerateWidthsMatchCgal) {
  Tally tally;
  for (double eps : {1e-9, 1e-10, 1e-11, 1e-12}) {
    check(l_shape(5, 5 + eps), "L arms differing by " + str(eps), tally);
    check(plus(4 + eps, 4), "plus " + str(eps), tally);
    check(rectangle(0, 0, 10, 10 + eps), "square + eps " + str(eps), tally);
    // A U whose inner notch is eps narrower than the arms.
    check(
        {{{0, 0}, {14, 0}, {14, 10}, {10, 10}, {10, 4 + eps}, {4, 4 + eps}, {4, 10}, {0, 10}}, {}},
        "U " + str(eps), tally);
  }
  // Widths one ulp apart.
  const double four = 4.0, up = std::nextafter(four, 8.0), down = std::nextafter(four, 0.0);
  check(rectangle(0, 0, 8, std::nextafter(8.0, 9.0)), "square + 1 ulp", tally);
  check(l_shape(up, four), "L + 1 ulp", tally);
  check(l_shape(down, up), "L -1/+1 ulp", tally);
  check(plus(up, 4), "plus + 1 ulp", tally);
  check(comb(
            40, [&](int i) { return i % 2 == 0 ? four : up; }, [](int) { return 3.0; }, 2.0),
        "comb of teeth one ulp apart", tally);
  check(comb(
            40, [](int i) { return 2.0 + 1e-11 * i; }, [](int) { return 3.0; }, 2.0),
        "comb of teeth 1e-11 apart", tally);
  // Two reflex corners 1e-9..1e-12 out of line.
  for (double eps : {1e-9, 1e-12}) {
    check({{{0, 0}, {20, 0}, {20, 4}, {14, 4}, {14, 10}, {6, 10}, {6, 4 + eps}, {0, 4 + eps}}, {}},
          "inverted T reflex out of line " + str(eps), tally);
  }
  tally.print("near-degenerate widths");
  EXPECT_GE(tally.compared, 10);
}

TEST(RectilinearSkeletonAdversarial, ScalesAndOffsetsMatchCgal) {
  Tally tally;
  const std::vector<Polygon> shapes = {
      l_shape(5, 5),
      l_shape(4, 7),
      plus(4, 4),
      staircase(6, 1, 1),
      {{{0, 0}, {20, 0}, {20, 14}, {0, 14}}, {hole(6, 4, 15, 9)}},
      comb(
          12, [](int i) { return 1.0 + 0.25 * (i % 3); }, [](int i) { return 2.0 + 0.5 * (i % 2); },
          1.0),
  };
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    for (double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
      for (Vec2 offset : {Vec2{0, 0}, Vec2{1e7, -1e7}, Vec2{-3.3e6, 5.1e6}}) {
        // Below ~1e-8 of the offset the input coordinates themselves are rounded away.
        if (offset.x != 0 && scale < 1e-3) continue;
        check(transformed(shapes[k], scale, offset),
              "shape " + std::to_string(k) + " scale " + str(scale) + " offset " + str(offset.x),
              tally);
      }
    }
  }
  tally.print("scales and offsets");
  EXPECT_GE(tally.compared, 40);
}

// Tiny outlines far from the origin: features of a few hundred ulps of their coordinates. The
// builder merges coordinates within 1e-14 of the largest coordinate; what it returns must still be
// CGAL's skeleton.
TEST(RectilinearSkeletonAdversarial, TinyOutlinesFarAwayMatchCgal) {
  Tally tally;
  for (double scale : {1e-6, 1e-7, 2e-8}) {
    for (const Polygon& shape : {l_shape(5, 5), l_shape(4, 7), plus(4, 4), staircase(4, 1, 1)}) {
      check(transformed(shape, scale, {1e7, 1e7}), "tiny at 1e7, scale " + str(scale), tally);
    }
  }
  tally.print("tiny far away");
}

TEST(RectilinearSkeletonAdversarial, SliversAndThinShapesMatchCgal) {
  Tally tally;
  check(rectangle(0, 0, 1000, 1e-3), "1000 x 1e-3", tally);
  check(rectangle(0, 0, 1e-3, 1e6), "1e-3 x 1e6", tally);
  check(l_shape(1e-4, 1e-4), "thin L", tally);
  check(comb(
            50, [](int) { return 1e-3; }, [](int i) { return 100.0 + i; }, 1e-3),
        "comb of needles", tally);
  // A thin frame: a huge courtyard in a thin ring.
  check({rectangle(0, 0, 100, 100).outer, {hole(1e-3, 1e-3, 100 - 1e-3, 100 - 1e-3)}}, "thin frame",
        tally);
  check({rectangle(0, 0, 100, 100).outer, {hole(1e-3, 2e-3, 100 - 3e-3, 100 - 4e-3)}},
        "thin uneven frame", tally);
  tally.print("slivers");
  EXPECT_GE(tally.compared, 4);
}

// A square spiral corridor of width `w` (walls between turns also `w` wide), made as a union.
Polygon spiral(int turns, double w) {
  std::vector<Polygon> parts;
  double x0 = 0, y0 = 0, x1 = (4 * turns + 1) * w, y1 = x1;
  // Walk inward: bottom, right, top, left, each shrinking by 2w every full turn.
  for (int t = 0; t < turns; ++t) {
    parts.push_back(rectangle(x0, y0, x1, y0 + w));
    parts.push_back(rectangle(x1 - w, y0, x1, y1));
    parts.push_back(rectangle(x0 + 2 * w, y1 - w, x1, y1));
    parts.push_back(rectangle(x0 + 2 * w, y0 + 2 * w, x0 + 3 * w, y1));
    x0 += 2 * w;
    y0 += 2 * w;
    x1 -= 2 * w;
    y1 -= 2 * w;
  }
  auto u = union_all(parts);
  return u.empty() ? Polygon{} : u[0];
}

TEST(RectilinearSkeletonAdversarial, SpiralsMatchCgal) {
  Tally tally;
  for (int turns : {1, 2, 4, 8}) {
    for (double w : {1.0, 0.3, 1e-3}) {
      const Polygon p = spiral(turns, w);
      ASSERT_TRUE(is_rectilinear(p));
      check(p, "spiral " + std::to_string(turns) + " w " + str(w), tally);
    }
  }
  tally.print("spirals");
  EXPECT_GE(tally.compared, 8);
}

TEST(RectilinearSkeletonAdversarial, CombsMatchCgal) {
  Tally tally;
  for (int teeth : {1, 2, 7, 31, 100}) {
    check(comb(
              teeth, [](int) { return 2.0; }, [](int) { return 3.0; }, 2.0),
          "equal comb " + std::to_string(teeth), tally);
    check(comb(
              teeth, [](int i) { return 2.0 + 1e-6 * i; }, [](int) { return 3.0; }, 2.0),
          "slightly widening comb " + std::to_string(teeth), tally);
    check(comb(
              teeth, [](int i) { return 2.0 + 0.5 * (i % 2); },
              [](int i) { return 1.0 + 0.75 * (i % 5); }, 1.5),
          "mixed comb " + std::to_string(teeth), tally);
    // Gaps equal to the teeth: the notches' reflex vertices meet the teeth ridges at one time.
    check(comb(
              teeth, [](int) { return 1.0; }, [](int) { return 4.0; }, 1.0),
          "fine comb " + std::to_string(teeth), tally);
    check(swapped(comb(
              teeth, [](int) { return 1.0; }, [](int) { return 4.0; }, 1.0)),
          "fine comb swapped " + std::to_string(teeth), tally);
  }
  tally.print("combs");
  EXPECT_GE(tally.compared, 20);
}

TEST(RectilinearSkeletonAdversarial, CrossesAndNestedCourtyardsMatchCgal) {
  Tally tally;
  for (double arm : {1.0, 4.0, 4.0 + 1e-9, 10.0}) {
    check(plus(4, arm), "plus arm " + str(arm), tally);
    Polygon p = plus(4, arm);
    // A hole in the middle of the cross, centred and off-centre.
    p.holes.push_back(hole(arm + 1, arm + 1, arm + 3, arm + 3));
    check(p, "plus with centred hole, arm " + str(arm), tally);
    p.holes[0] = hole(arm + 0.5, arm + 1, arm + 3, arm + 3.25);
    check(p, "plus with off-centre hole, arm " + str(arm), tally);
  }
  // A double cross (#).
  check(union_all({rectangle(2, 0, 4, 12), rectangle(8, 0, 10, 12), rectangle(0, 2, 12, 4),
                   rectangle(0, 8, 12, 10)})[0],
        "#", tally);
  // Nested courtyards: rings of equal width around a centre, each its own polygon; and square
  // frames whose hole is at the same distance from every side (every event at one time).
  for (double width : {1.0, 2.5}) {
    for (int k = 1; k <= 4; ++k) {
      const double o = 3 * width * k;
      check({rectangle(-o, -o, o, o).outer, {hole(-o + width, -o + width, o - width, o - width)}},
            "frame " + std::to_string(k) + " width " + str(width), tally);
      check({rectangle(-o, -o, o, o + width).outer,
             {hole(-o + width, -o + width, o - width, o - width)}},
            "frame with a wider top " + std::to_string(k), tally);
    }
  }
  // An L-shaped courtyard in an L-shaped building, and a plus-shaped courtyard in a square.
  check({l_shape(5, 5).outer, {{{1, 1}, {1, 11}, {4, 11}, {4, 4}, {11, 4}, {11, 1}}}}, "L in L",
        tally);
  {
    Polygon inner = plus(2, 2);
    for (Vec2& v : inner.outer) v = v + Vec2{3, 3};
    std::reverse(inner.outer.begin(), inner.outer.end());
    check({rectangle(0, 0, 12, 12).outer, {inner.outer}}, "plus courtyard", tally);
  }
  tally.print("crosses and courtyards");
  EXPECT_GE(tally.compared, 25);
}

TEST(RectilinearSkeletonAdversarial, CollinearVerticesMatchCgal) {
  Tally tally;
  // (255 per side, 1,020 vertices, is RectangleWithMaximumCollinearVertices below.)
  for (int per_side : {1, 2, 10, 100}) {
    Polygon p;
    auto side = [&](Vec2 a, Vec2 b) {
      for (int i = 0; i < per_side; ++i) p.outer.push_back(a + (b - a) * (double(i) / per_side));
    };
    side({0, 0}, {20, 0});
    side({20, 0}, {20, 8});
    side({20, 8}, {0, 8});
    side({0, 8}, {0, 0});
    check(p, "rectangle with " + std::to_string(per_side) + " vertices per side", tally);
    check(rotated_start(p, 7), "the same started elsewhere", tally);
  }
  // Collinear vertices exactly where a ridge or valley lands.
  check({{{0, 0}, {6, 0}, {12, 0}, {12, 6}, {12, 12}, {6, 12}, {0, 12}, {0, 6}}, {}},
        "square with midpoints", tally);
  check({{{0, 0}, {14, 0}, {14, 6}, {10, 6}, {6, 6}, {6, 12}, {3, 12}, {0, 12}, {0, 6}}, {}},
        "L with collinear vertices at the reflex corner line", tally);
  tally.print("collinear vertices");
  EXPECT_GE(tally.compared, 10);
}

// The size limit: 1,024 contour vertices exactly are the builder's, 1,025 CGAL's.
TEST(RectilinearSkeletonAdversarial, ExactlyTheVertexLimit) {
  Polygon p = comb(
      255, [](int i) { return 2.0 + 0.25 * (i % 3); }, [](int) { return 3.0; }, 2.0);
  ASSERT_EQ(p.outer.size(), 1022U);
  // Two collinear vertices on the top edge bring it to 1,024.
  const Vec2 top_right = p.outer[p.outer.size() - 2];
  p.outer.insert(p.outer.end() - 1, {top_right.x * 0.5, 5});
  p.outer.insert(p.outer.end() - 1, {top_right.x * 0.25, 5});
  ASSERT_EQ(p.outer.size(), 1024U);
  Tally tally;
  check(p, "1,024-vertex comb", tally);
  EXPECT_TRUE(rectilinear_straight_skeleton(p).has_value());
  p.outer.insert(p.outer.end() - 1, {top_right.x * 0.125, 5});
  EXPECT_FALSE(rectilinear_straight_skeleton(p).has_value());
  EXPECT_TRUE(interior_straight_skeleton(p).has_value());
  tally.print("1,024 vertices");
}

// Random unions of many small rectangles on a fine grid: many holes and near-touching corners.
TEST(RectilinearSkeletonAdversarial, DenseRandomUnionsMatchCgal) {
  Tally tally;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> cell(0, 24);
    std::uniform_int_distribution<int> size(1, 4);
    std::vector<Polygon> rects;
    for (int i = 0; i < 40; ++i) {
      const double x = cell(rng), y = cell(rng);
      rects.push_back(rectangle(x, y, x + size(rng), y + size(rng)));
    }
    for (const Polygon& p : union_all(rects)) {
      if (!is_rectilinear(p) || !is_simple_polygon(p)) continue;
      check(p, "dense union seed " + std::to_string(seed), tally);
    }
  }
  tally.print("dense random unions");
  EXPECT_GE(tally.compared, 60);
}

// Unions of random rectangles on an integer grid whose distinct coordinates are then moved by
// -8..7 times eps (one shift per coordinate value, so edges stay axis-parallel and the topology
// stays the same): events that were simultaneous become eps apart, around the builder's merge
// tolerance (1e-10 of the outline's size) when eps is 1e-10..1e-9.
TEST(RectilinearSkeletonAdversarial, PerturbedGridUnionsMatchCgal) {
  for (double eps : {1e-13, 1e-10, 1e-9, 1e-6}) {
    Tally tally;
    for (std::uint32_t seed = 1; seed <= 100; ++seed) {
      std::mt19937 rng(seed);
      std::uniform_int_distribution<int> cell(0, 12), size(1, 4);
      std::vector<Polygon> rects;
      const int n = 3 + static_cast<int>(seed % 10);
      for (int i = 0; i < n; ++i) {
        const double x = cell(rng), y = cell(rng);
        rects.push_back(rectangle(x, y, x + size(rng), y + size(rng)));
      }
      auto shift = [&](double v) {
        const auto h = static_cast<std::uint32_t>(std::lround(v) * 2654435761U + seed * 97U);
        return v + eps * (static_cast<int>(h >> 28) - 8);
      };
      for (Polygon p : union_all(rects)) {
        auto apply = [&](Ring& ring) {
          for (Vec2& v : ring) v = Vec2{shift(v.x), shift(v.y)};
        };
        apply(p.outer);
        for (Ring& h : p.holes) apply(h);
        if (!is_simple_polygon(p)) continue;
        check(p, "perturbed union seed " + std::to_string(seed) + " eps " + str(eps), tally);
      }
    }
    tally.declined_names.clear();  // only the count: dozens at eps = 1e-9
    tally.print(("perturbed unions, eps " + str(eps)).c_str());
    EXPECT_GE(tally.compared, 350);
  }
}

// lead: a rectangle with 255 collinear vertices per side (1,020 vertices, one simultaneous event
// at t = 4) takes ~1.2 s in Release in rectilinear_straight_skeleton (CGAL ~1.7 s), over the 1 s
// budget per case; it matches CGAL. Skipped to keep this file's runtime down; remove the skip when
// the step is cheaper (O(edges^2 x grid) in the sliver ridge loop and the per-unit label search).
TEST(RectilinearSkeletonAdversarial, RectangleWithMaximumCollinearVertices) {
  GTEST_SKIP() << "lead: 1,020 collinear vertices take ~1.2 s (over 1 s)";
  Polygon p;
  auto side = [&](Vec2 a, Vec2 b) {
    for (int i = 0; i < 255; ++i) p.outer.push_back(a + (b - a) * (double(i) / 255));
  };
  side({0, 0}, {20, 0});
  side({20, 0}, {20, 8});
  side({20, 8}, {0, 8});
  side({0, 8}, {0, 0});
  Tally tally;
  check(p, "rectangle with 1,020 collinear vertices", tally);
  EXPECT_EQ(tally.compared, 1);
}

// lead: outlines near the 1,024-vertex limit with hundreds of separate events are slow in the
// rectilinear builder (Release, loaded 2-core machine): a comb of 255 teeth of distinct widths
// and depths (1,022 vertices) ~1.2 s (CGAL ~0.9 s, so CGAL would be the faster choice), a square
// with 254 rectangular holes of distinct sizes (1,020 vertices) ~1.9 s (CGAL ~8 s). Both give
// valid skeletons; the comb matches CGAL. Skipped for the runtime budget; each is over 1 s.
TEST(RectilinearSkeletonAdversarial, ManySeparateEventsNearTheLimit) {
  GTEST_SKIP() << "lead: 255 distinct teeth ~1.2 s, 254 distinct holes ~1.9 s (over 1 s)";
  Tally tally;
  check(comb(
            255, [](int i) { return 1.0 + 0.003 * ((i * 53) % 101); },
            [](int i) { return 2.0 + 0.01 * ((i * 29) % 97); }, 1.0),
        "comb of 255 distinct teeth", tally);
  EXPECT_EQ(tally.compared, 1);
  Polygon p = rectangle(0, 0, 200, 200);
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 16 && p.holes.size() < 254; ++j) {
      const double x = 12.0 * i + 2, y = 12.0 * j + 2;
      const double w = 3 + 0.01 * ((i * 31 + j * 17) % 200),
                   h = 3 + 0.013 * ((i * 7 + j * 43) % 150);
      p.holes.push_back(hole(x, y, x + w, y + h));
    }
  }
  ASSERT_TRUE(is_simple_polygon(p));
  const auto s = rectilinear_straight_skeleton(p);  // CGAL takes ~8 s here: validity only
  ASSERT_TRUE(s.has_value());
  expect_valid(p, *s, "254 distinct holes");
}

// Features far below the merge tolerance (1e-10 of the size): notches and cracks of 1e-6..1e-14,
// holes 1e-6..1e-14 from the outer ring or from each other. Every hole closer than ~1e-9 is
// declined today (its first event comes within the tolerance of t = 0, which next_event skips, and
// the wavefronts then overlap); CGAL answers all of them.
TEST(RectilinearSkeletonAdversarial, NearlyTouchingFeaturesMatchCgal) {
  Tally tally;
  int hole_declines = 0;
  for (double e : {1e-6, 1e-9, 1e-10, 1e-12, 1e-14}) {
    check({{{0, 0}, {4, 0}, {4, e}, {6, e}, {6, 0}, {10, 0}, {10, 10}, {0, 10}}, {}},
          "notch depth " + str(e), tally);
    check({{{0, 0}, {5, 0}, {5, 6}, {5 + e, 6}, {5 + e, 0}, {10, 0}, {10, 10}, {0, 10}}, {}},
          "crack width " + str(e), tally);
    check({{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 5 + e}, {0, 5 + e}}, {}}, "step " + str(e),
          tally);
    const int before = tally.declined;
    const Ring outer = rectangle(0, 0, 10, 10).outer;
    check({outer, {hole(1, e, 6, 5)}}, "hole gap " + str(e), tally);
    check({outer, {hole(e, e, 6, 5)}}, "hole corner gap " + str(e), tally);
    check({outer, {hole(1, 1, 5, 5), hole(5 + e, 1, 9, 5)}}, "two holes gap " + str(e), tally);
    check({outer, {hole(1, 1, 5, 5), hole(5 + e, 5 + e, 9, 9)}}, "diagonal holes gap " + str(e),
          tally);
    hole_declines += tally.declined - before;
  }
  tally.print("nearly touching features");
  EXPECT_EQ(tally.compared + tally.declined, 35);
  std::printf("[ tally    ] %d of 20 nearly touching holes declined\n", hole_declines);
}

// Coordinates of ~1e154 and more (finite, so is_simple_polygon accepts them) killed the process
// with SIGFPE inside CGAL (GMP's mpq_set_d on an overflowed value in Compare_ss_event_angles_2),
// rectilinear or not; fixed in 37fd6a1 (skeletons decline coordinates beyond 1e100). Up to 1e100
// the builders must answer, beyond it nullopt, never a crash.
TEST(RectilinearSkeletonAdversarial, HugeCoordinatesDoNotCrash) {
  for (double scale : {1e50, 1e98, 1e150, 1e154, 1e200, 1e300}) {
    for (const Polygon& shape : {l_shape(5, 5), plus(4, 4), staircase(5, 1, 1)}) {
      const Polygon p = transformed(shape, scale, {0, 0});
      ASSERT_TRUE(is_simple_polygon(p));
      const auto s = interior_straight_skeleton(p);
      const auto reference = general_straight_skeleton(p);
      EXPECT_EQ(s.has_value(), scale < 1e100) << scale;
      EXPECT_EQ(reference.has_value(), scale < 1e100) << scale;
      if (s.has_value()) {
        EXPECT_EQ(s->face_count(), shape.outer.size());
      }
    }
  }
}

// Found by perturbing grid unions by 5e-9 (2 of 2,581 outlines): a square of side 4 + 1e-8 with
// a bump of height 2 + 5e-9 on its right side. The bump's two reflex corners meet at
// t = 1 + 2.5e-9 and the square's right side then runs on the two collinear short edges, so the
// last node is the square's centre at t = (4 + 1e-8) / 2. The rectilinear builder gives exactly
// that; CGAL gives 2 + 2.5e-9 (off by 2.5e-9, above the 1e-9 relative tolerance; its face
// areas still agree within 1e-7 of the polygon's). The reference is the hand-derived value.
TEST(RectilinearSkeletonAdversarial, SquareWithBumpHasItsCentreAtHalfTheSide) {
  const Polygon p{{{13.999999995, 7.9999999800000001},
                   {15, 7.9999999800000001},
                   {15, 9.9999999850000005},
                   {13.999999995, 9.9999999850000005},
                   {13.999999995, 10.999999985000001},
                   {9.9999999850000005, 10.999999985000001},
                   {9.9999999850000005, 6.9999999749999997},
                   {13.999999995, 6.9999999749999997}},
                  {}};
  ASSERT_TRUE(is_simple_polygon(p));
  const double side_x = 13.999999995 - 9.9999999850000005;
  const double side_y = 10.999999985000001 - 6.9999999749999997;
  ASSERT_NEAR(side_x, side_y, 1e-14);  // a square up to two ulps
  const auto ours = rectilinear_straight_skeleton(p);
  ASSERT_TRUE(ours.has_value());
  expect_valid(p, *ours, "square with bump");
  EXPECT_NEAR(ours->max_time(), side_x / 2, 1e-14);
  // The left, top and bottom faces (faces 5, 4, 6) meet at the centre: each is a quarter of the
  // square.
  for (std::uint32_t e : {4U, 5U, 6U}) {
    EXPECT_NEAR(signed_area(face_ring(*ours, e)), side_x * side_x / 4, 1e-12) << e;
  }
  const auto reference = general_straight_skeleton(p);
  ASSERT_TRUE(reference.has_value());
  std::printf("[ cgal     ] max time %.17g, exact %.17g\n", reference->max_time(), side_x / 2);
}

}  // namespace
}  // namespace insula::kernel
