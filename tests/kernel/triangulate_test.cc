#include "kernel/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

namespace insula::kernel {
namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}

// Ring with every edge subdivided into `k` collinear pieces.
Ring subdivide(const Ring& ring, int k) {
  Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    for (int j = 0; j < k; ++j) out.push_back(a + (b - a) * (double(j) / k));
  }
  return out;
}

Ring star(int points, double r_in, double r_out, Vec2 c = {}) {
  Ring out;
  for (int i = 0; i < 2 * points; ++i) {
    const double t = std::numbers::pi * i / points;
    const double r = i % 2 ? r_in : r_out;
    out.push_back(c + Vec2{r * std::cos(t), r * std::sin(t)});
  }
  return out;
}

// Checks the contract of a successful triangulation: valid indices, counter-clockwise
// non-degenerate triangles, total area equal to the polygon's area. With `conforming`, also that
// the triangles form a proper triangulation of the rings: each ring edge (in normalised
// orientation) is used once by one triangle and every other edge is shared by two triangles in
// opposite directions, which rules out overlaps, gaps and T-junctions.
void expect_valid(const Polygon& polygon, const Triangulation& t, bool conforming = true) {
  ASSERT_EQ(t.status, TriangulationStatus::kOk);
  double total = 0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& tri : t.triangles) {
    for (std::uint32_t i : tri) ASSERT_LT(i, t.vertices.size());
    const Vec2 a = t.vertices[tri[0]], b = t.vertices[tri[1]], c = t.vertices[tri[2]];
    const double twice = cross(b - a, c - a);
    EXPECT_GT(twice, 0) << "triangle " << tri[0] << " " << tri[1] << " " << tri[2];
    total += 0.5 * twice;
    for (int k = 0; k < 3; ++k) ++edges[{tri[k], tri[(k + 1) % 3]}];
  }
  EXPECT_NEAR(total, area(polygon), 1e-9 * std::max(1.0, area(polygon)));
  if (!conforming) return;
  Polygon n = polygon;
  normalize(n);
  // Map normalised ring edges back to vertex indices (outer first, then holes, as documented).
  std::uint32_t base = 0;
  auto ring_edges = [&](const Ring& original, const Ring& normal) {
    const bool flipped =
        normal.front() != original.front() || signed_area(normal) * signed_area(original) < 0;
    const auto m = std::uint32_t(original.size());
    for (std::uint32_t i = 0; i < m; ++i) {
      const std::uint32_t u = base + i, v = base + (i + 1) % m;
      const auto key = flipped ? std::pair{v, u} : std::pair{u, v};
      EXPECT_EQ(edges[key], 1) << "ring edge " << key.first << "-" << key.second;
      edges.erase(key);
    }
    base += m;
  };
  ring_edges(polygon.outer, n.outer);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) ring_edges(polygon.holes[h], n.holes[h]);
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
    const auto it = edges.find({edge.second, edge.first});
    EXPECT_TRUE(it != edges.end() && it->second == 1)
        << "interior edge " << edge.first << "-" << edge.second << " is not shared";
  }
}

Triangulation run(const Polygon& p) {
  Triangulation t;
  EXPECT_TRUE(triangulate(p, t)) << to_string(t.status);
  return t;
}

TEST(Triangulate, SquareGivesTwoTriangles) {
  const Polygon p{rect(0, 0, 1, 1), {}};
  const Triangulation t = run(p);
  EXPECT_EQ(t.triangles.size(), 2U);
  EXPECT_EQ(t.vertices.size(), 4U);
  expect_valid(p, t);
}

TEST(Triangulate, ClockwiseOuterKeepsVertexOrderAndGivesCcwTriangles) {
  const Polygon p{reversed(rect(0, 0, 2, 1)), {}};
  const Triangulation t = run(p);
  EXPECT_EQ(t.vertices, p.outer);
  expect_valid(p, t);
}

TEST(Triangulate, LUHAndComb) {
  const Polygon l{{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, {}};
  const Polygon u{{{0, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 1}, {2, 1}, {2, 4}, {0, 4}}, {}};
  const Polygon h{{{0, 0},
                   {1, 0},
                   {1, 1},
                   {2, 1},
                   {2, 0},
                   {3, 0},
                   {3, 3},
                   {2, 3},
                   {2, 2},
                   {1, 2},
                   {1, 3},
                   {0, 3}},
                  {}};
  Ring comb{{0, 0}, {20, 0}, {20, 1}};
  for (int i = 9; i >= 0; --i) {
    comb.push_back({2.0 * i + 1.5, 1});
    comb.push_back({2.0 * i + 1.5, 5});
    comb.push_back({2.0 * i + 0.5, 5});
    comb.push_back({2.0 * i + 0.5, 1});
  }
  comb.push_back({0, 1});
  for (const Polygon& p : {l, u, h, Polygon{comb, {}}}) {
    const Triangulation t = run(p);
    EXPECT_EQ(t.triangles.size(), p.outer.size() - 2);
    expect_valid(p, t);
  }
}

TEST(Triangulate, SquareWithHoleUsesEveryVertex) {
  const Polygon p{rect(0, 0, 4, 4), {rect(1, 1, 3, 3)}};
  const Triangulation t = run(p);
  EXPECT_EQ(t.vertices.size(), 8U);
  EXPECT_EQ(t.triangles.size(), 8U);  // n + 2h - 2
  expect_valid(p, t);
}

TEST(Triangulate, TwentyHoles) {
  Polygon p{rect(0, 0, 50, 40), {}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = 2 + 10.0 * i, y = 2 + 10.0 * j;
      // Alternate orientations and shapes: squares and small stars.
      if ((i + j) % 2)
        p.holes.push_back(rect(x, y, x + 5, y + 6));
      else
        p.holes.push_back(reversed(star(5, 1.5, 3, {x + 3, y + 3})));
    }
  const Triangulation t = run(p);
  std::size_t n = p.outer.size();
  for (const Ring& h : p.holes) n += h.size();
  EXPECT_EQ(t.triangles.size(), n + 2 * p.holes.size() - 2);
  expect_valid(p, t);
}

TEST(Triangulate, CollinearHeavyRingsKeepEveryVertex) {
  const Polygon p{subdivide(rect(0, 0, 10, 6), 7), {subdivide(rect(2, 2, 8, 4), 5)}};
  const Triangulation t = run(p);
  expect_valid(p, t);  // conforming: no collinear vertex was skipped (no T-junction)
  const Polygon l{subdivide({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 4), {}};
  expect_valid(l, run(l));
  // A triangle with 30 vertices on its base.
  Ring fan{{0, 5}};
  for (int i = 30; i >= 0; --i) fan.push_back({double(i) / 3.0 - 5, -1});
  std::reverse(fan.begin(), fan.end());
  const Polygon f{fan, {}};
  expect_valid(f, run(f));
}

TEST(Triangulate, ThousandVertexStar) {
  const Polygon p{star(500, 3, 10), {}};
  const Triangulation t = run(p);
  EXPECT_EQ(t.triangles.size(), 998U);
  expect_valid(p, t);
}

TEST(Triangulate, StarWithHolesAndUtmOffset) {
  const Vec2 utm{500000, 5000000};
  Polygon p{star(64, 40, 50, utm), {}};
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * std::numbers::pi * i / 6;
    p.holes.push_back(star(8, 2, 4, utm + Vec2{25 * std::cos(a), 25 * std::sin(a)}));
  }
  expect_valid(p, run(p));
}

TEST(Triangulate, HoleTouchingOuterAtAVertex) {
  // OGC-valid: the hole's vertex (0, 2) is also a vertex of the outer ring.
  const Polygon p{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 2}}, {{{0, 2}, {2, 3}, {2, 1}}}};
  expect_valid(p, run(p), false);
}

TEST(Triangulate, HoleTouchingOuterInsideAnEdge) {
  const Polygon p{rect(0, 0, 4, 4), {{{0, 2}, {2, 3}, {2, 1}}}};
  expect_valid(p, run(p), false);
}

TEST(Triangulate, TwoHolesTouchingEachOther) {
  const Polygon p{rect(0, 0, 6, 4), {{{1, 1}, {1, 3}, {3, 2}}, {{3, 2}, {5, 3}, {5, 1}}}};
  expect_valid(p, run(p), false);
}

TEST(Triangulate, RepeatedClosingVertexIsKeptButUnused) {
  Ring r = rect(0, 0, 3, 2);
  r.push_back(r.front());
  const Polygon p{r, {}};
  const Triangulation t = run(p);
  EXPECT_EQ(t.vertices.size(), 5U);
  for (const auto& tri : t.triangles)
    for (std::uint32_t i : tri) EXPECT_NE(i, 4U);
  expect_valid(p, t, false);
}

TEST(Triangulate, DegenerateInputReturnsStatus) {
  Triangulation t;
  EXPECT_FALSE(triangulate(Polygon{}, t));
  EXPECT_EQ(t.status, TriangulationStatus::kTooFewVertices);
  EXPECT_FALSE(triangulate(Polygon{{{0, 0}, {1, 1}, {0, 0}}, {}}, t));
  EXPECT_EQ(t.status, TriangulationStatus::kTooFewVertices);
  EXPECT_FALSE(triangulate(Polygon{{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}}, t));
  EXPECT_EQ(t.status, TriangulationStatus::kZeroArea);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(triangulate(Polygon{{{0, 0}, {1, 0}, {nan, 1}}, {}}, t));
  EXPECT_EQ(t.status, TriangulationStatus::kNonFinite);
  EXPECT_TRUE(t.triangles.empty());
  // A degenerate hole is ignored.
  const Polygon with_flat_hole{rect(0, 0, 4, 4), {{{1, 1}, {2, 2}, {3, 3}}}};
  expect_valid(with_flat_hole, run(with_flat_hole), false);
}

TEST(Triangulate, InvalidInputFailsWithoutCrashing) {
  Triangulation t;
  // A bow-tie: no triangulation covers "its area" (zero signed area).
  EXPECT_FALSE(triangulate(Polygon{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}, t));
  // A hole outside the outer ring.
  EXPECT_FALSE(triangulate(Polygon{rect(0, 0, 1, 1), {rect(2, 2, 3, 3)}}, t));
  EXPECT_EQ(t.status, TriangulationStatus::kFailed);
  // Random self-intersecting rings: any outcome but a crash or a hang, and true only when valid.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 10);
  for (int k = 0; k < 200; ++k) {
    Polygon p;
    const int n = 3 + k % 40;
    for (int i = 0; i < n; ++i) p.outer.push_back({std::round(u(rng)), std::round(u(rng))});
    if (k % 3 == 0) p.holes.push_back(rect(4, 4, 5, 5));
    if (triangulate(p, t)) expect_valid(p, t, false);
  }
}

// Corpus of hard polygons (tests/data/polygons/*.txt): one ring per line as "x y x y ...", the
// first line is the outer ring, the rest are holes; lines starting with '#' are comments.
Polygon read_polygon(const std::filesystem::path& path) {
  std::ifstream in(path);
  Polygon p;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Ring ring;
    double x = 0, y = 0;
    while (s >> x >> y) ring.push_back({x, y});
    if (first)
      p.outer = ring;
    else
      p.holes.push_back(ring);
    first = false;
  }
  return p;
}

TEST(Triangulate, HardPolygonCorpus) {
  const std::filesystem::path dir = std::filesystem::path(INSULA_TEST_DATA) / "polygons";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const Polygon p = read_polygon(entry.path());
    ASSERT_GE(p.outer.size(), 3U);
    Triangulation t;
    ASSERT_TRUE(triangulate(p, t)) << to_string(t.status);
    expect_valid(p, t, false);
    ++count;
  }
  EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace insula::kernel
