#include "kernel/wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

namespace insula::kernel {
namespace {

Ring rectangle(double length, double height) {
  return {{0, 0}, {length, 0}, {length, height}, {0, height}};
}

Opening window(double u, double sill, double width, double height) {
  Opening o;
  o.u = u;
  o.sill = sill;
  o.width = width;
  o.height = height;
  return o;
}

Opening arched(double u, double sill, double width, double height, double rise, int segments) {
  Opening o = window(u, sill, width, height);
  o.arch_rise = rise;
  o.arch_segments = segments;
  return o;
}

WallSpec wall(Ring outline, std::vector<Opening> openings, double thickness = 0.3) {
  WallSpec spec;
  spec.outline = std::move(outline);
  spec.openings = std::move(openings);
  spec.thickness = thickness;
  return spec;
}

std::map<SemanticClass, int> count_classes(const Mesh& mesh) {
  std::map<SemanticClass, int> counts;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) ++counts[mesh.tag(f).semantic];
  return counts;
}

// A vertex lying strictly inside an edge of a face it does not belong to is a T-junction.
int t_junctions(const Mesh& mesh) {
  int found = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec3 a = mesh.position(loop[i]);
      const Vec3 b = mesh.position(loop[(i + 1) % loop.size()]);
      const Vec3 ab = b - a;
      for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
        if (v == loop[i] || v == loop[(i + 1) % loop.size()]) continue;
        const Vec3 ap = mesh.position(v) - a;
        const double t = dot(ap, ab) / dot(ab, ab);
        if (t <= 1e-9 || t >= 1 - 1e-9) continue;
        if (length(ap - ab * t) < 1e-9) ++found;
      }
    }
  }
  return found;
}

// Closed and oriented on shared vertices (no welding), positive volume, no T-junctions, and the
// Euler characteristic of a solid with `genus` handles.
void expect_solid(const WallResult& r, int genus) {
  ASSERT_TRUE(r.ok()) << r.message;
  const MeshCheck c = check(r.mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.oriented);
  EXPECT_EQ(c.boundary_edges, 0U);
  EXPECT_EQ(c.non_manifold_edges, 0U);
  EXPECT_EQ(c.components, 1U);
  EXPECT_EQ(c.euler_characteristic, 2 - 2 * genus);
  EXPECT_GT(volume(r.mesh), 0);
  EXPECT_EQ(t_junctions(r.mesh), 0);
  EXPECT_EQ(r.face_opening.size(), r.mesh.face_count());
}

TEST(Wall, PlainSlabIsABox) {
  const WallResult r = build_wall(wall(rectangle(4, 3), {}, 0.25));
  expect_solid(r, 0);
  EXPECT_NEAR(volume(r.mesh), 4 * 3 * 0.25, 1e-12);
  EXPECT_EQ(r.mesh.face_count(), 6U);
  EXPECT_EQ(r.front_pieces, 1U);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kWallSurface], 1);
  EXPECT_EQ(counts[SemanticClass::kInteriorWallSurface], 1);
  EXPECT_EQ(counts[SemanticClass::kClosureSurface], 4);
}

TEST(Wall, RectangularWindowHasTwoJambsOneSillOneLintel) {
  const WallResult r = build_wall(wall(rectangle(5, 3), {window(1.5, 0.9, 1.2, 1.4)}));
  expect_solid(r, 1);
  EXPECT_NEAR(volume(r.mesh), (5 * 3 - 1.2 * 1.4) * 0.3, 1e-12);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kJamb], 2);
  EXPECT_EQ(counts[SemanticClass::kSill], 1);
  EXPECT_EQ(counts[SemanticClass::kLintel], 1);
  EXPECT_EQ(r.cut, std::vector<std::size_t>{0});
  EXPECT_TRUE(r.issues.empty());
}

TEST(Wall, RevealNormalsPointIntoTheOpening) {
  const WallResult r = build_wall(wall(rectangle(5, 3), {window(1.5, 0.9, 1.2, 1.4)}));
  ASSERT_TRUE(r.ok());
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    const Vec3 n = face_normal(r.mesh, f);
    const Vec3 c = r.mesh.position(r.mesh.face(f)[0]);
    switch (r.mesh.tag(f).semantic) {
      case SemanticClass::kWallSurface:
        EXPECT_NEAR(n.z, 1, 1e-12);
        break;
      case SemanticClass::kInteriorWallSurface:
        EXPECT_NEAR(n.z, -1, 1e-12);
        break;
      case SemanticClass::kSill:
        EXPECT_NEAR(n.y, 1, 1e-12);
        break;
      case SemanticClass::kLintel:
        EXPECT_NEAR(n.y, -1, 1e-12);
        break;
      case SemanticClass::kJamb:
        EXPECT_NEAR(n.x, c.x < 2 ? 1 : -1, 1e-12);
        EXPECT_EQ(r.face_opening[f], 0);
        break;
      default:
        EXPECT_EQ(r.face_opening[f], -1);
        break;
    }
  }
}

TEST(Wall, TenWindowsInTwoRows) {
  std::vector<Opening> openings;
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < 5; ++i)
      openings.push_back(window(0.8 + 2.0 * i, 1.0 + 3.0 * row, 1.0, 1.5));
  }
  const WallResult r = build_wall(wall(rectangle(10.6, 6), openings));
  expect_solid(r, 10);
  EXPECT_NEAR(volume(r.mesh), (10.6 * 6 - 10 * 1.5) * 0.3, 1e-9);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kJamb], 20);
  EXPECT_EQ(counts[SemanticClass::kSill], 10);
  EXPECT_EQ(counts[SemanticClass::kLintel], 10);
}

TEST(Wall, DoorNotchesTheBottomEdge) {
  const WallResult r =
      build_wall(wall(rectangle(4, 3), {window(1.0, 0, 1.0, 2.1), window(2.6, 1.0, 0.8, 1.2)}));
  expect_solid(r, 1);  // the door adds no handle, the window does
  EXPECT_NEAR(volume(r.mesh), (12 - 2.1 - 0.96) * 0.3, 1e-12);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kJamb], 4);
  EXPECT_EQ(counts[SemanticClass::kSill], 1);
  EXPECT_EQ(counts[SemanticClass::kLintel], 2);
  // The bottom rim is split by the notch: two bottom pieces, the top and two ends.
  EXPECT_EQ(counts[SemanticClass::kClosureSurface], 5);
  int bottoms = 0;
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    if (face_normal(r.mesh, f).y < -0.5) ++bottoms;
  }
  EXPECT_EQ(bottoms, 4);  // two rim pieces and both lintels
}

TEST(Wall, DoorAtTheWallBaseOfAGableOutline) {
  WallSpec spec = wall({{0, 0}, {6, 0}, {6, 3}, {3, 5}, {0, 3}}, {window(2.5, 0, 1, 2.2)});
  spec.tags.top = {SemanticClass::kRoofSurface};
  spec.tags.end = {SemanticClass::kWallSurface, 0, 7};
  const WallResult r = build_wall(spec);
  expect_solid(r, 0);
  EXPECT_NEAR(volume(r.mesh), (18 + 6 - 2.2) * 0.3, 1e-12);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kRoofSurface], 2);     // both slopes
  EXPECT_EQ(counts[SemanticClass::kClosureSurface], 2);  // the bottom, split by the door
  EXPECT_EQ(counts[SemanticClass::kSill], 0);
}

TEST(Wall, GableWithAWindowInTheGable) {
  const WallResult r = build_wall(wall({{0, 0}, {6, 0}, {6, 3}, {3, 5}, {0, 3}},
                                       {window(2.6, 3.1, 0.8, 0.9), window(1, 1, 1, 1.2)}));
  expect_solid(r, 2);
  EXPECT_NEAR(volume(r.mesh), (24 - 0.72 - 1.2) * 0.3, 1e-12);
}

// A stepped (non-convex) outline: its reflex corner and an opening edge share the same u.
TEST(Wall, SteppedOutlineWithAlignedCorners) {
  const Ring outline = {{0, 0}, {8, 0}, {8, 3}, {5, 3}, {5, 5}, {0, 5}};
  const std::vector<Opening> openings = {window(1, 1, 1, 1), window(5.5, 1, 1, 1.5),
                                         window(2, 3.3, 1, 1), window(3.8, 1, 1.2, 1),
                                         window(0.5, 2.5, 1, 1)};
  const WallResult r = build_wall(wall(outline, openings));
  expect_solid(r, 5);
  EXPECT_NEAR(volume(r.mesh), (8 * 3 + 5 * 2 - 1 - 1.5 - 1 - 1.2 - 1) * 0.3, 1e-12);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kClosureSurface], 6);
}

TEST(Wall, ClockwiseOutlineIsAccepted) {
  const WallResult r =
      build_wall(wall({{0, 3}, {5, 3}, {5, 0}, {0, 0}}, {window(1.5, 0.9, 1.2, 1.4)}));
  expect_solid(r, 1);
  EXPECT_NEAR(volume(r.mesh), (15 - 1.68) * 0.3, 1e-12);
}

TEST(Wall, SemicircularArchWithSixteenSegments) {
  const double w = 1.2, h = 2.4, rise = 0.6;
  const Opening o = arched(1.4, 0.8, w, h, rise, 16);
  const WallResult r = build_wall(wall(rectangle(4, 4), {o}));
  expect_solid(r, 1);
  const double exact_opening = w * (h - rise) + std::numbers::pi * rise * rise / 2;
  EXPECT_NEAR(volume(r.mesh), (16 - opening_area(o)) * 0.3, 1e-12);
  EXPECT_NEAR(opening_area(o), exact_opening, 0.01 * exact_opening);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kJamb], 2);
  EXPECT_EQ(counts[SemanticClass::kSill], 1);
  EXPECT_EQ(counts[SemanticClass::kLintel], 16);
  EXPECT_EQ(opening_ring(o).size(), 4U + 15U);
}

TEST(Wall, SegmentalArchAreaConverges) {
  const double w = 2.0, h = 2.5, rise = 0.4;
  const double radius = (1.0 + rise * rise) / (2 * rise);
  const double angle = 2 * std::asin(1.0 / radius);
  const double exact = w * (h - rise) + radius * radius / 2 * (angle - std::sin(angle));
  for (int n : {4, 16, 64}) {
    const Opening o = arched(1, 0.5, w, h, rise, n);
    const WallResult r = build_wall(wall(rectangle(4, 4), {o}));
    expect_solid(r, 1);
    EXPECT_NEAR(volume(r.mesh), (16 - opening_area(o)) * 0.3, 1e-12);
    EXPECT_NEAR(opening_area(o), exact, 2.0 / (n * n));
  }
  // The apex is at the full height.
  const Ring ring = opening_ring(arched(1, 0.5, w, h, rise, 16));
  EXPECT_NEAR(ring[1 + 8].y, 0.5 + h, 1e-12);
  EXPECT_NEAR(ring[1 + 8].x, 2, 1e-12);
}

TEST(Wall, ArchedDoorNotch) {
  const WallResult r = build_wall(wall(rectangle(4, 3), {arched(1.4, 0, 1.2, 2.4, 0.6, 8)}));
  expect_solid(r, 0);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kLintel], 8);
  EXPECT_EQ(counts[SemanticClass::kSill], 0);
}

TEST(Wall, HundredOpeningsInALongWall) {
  std::vector<Opening> openings;
  for (int i = 0; i < 50; ++i) {
    openings.push_back(window(0.5 + 2.0 * i, 0.9, 1.0, 1.4));
    openings.push_back(arched(0.5 + 2.0 * i, 3.5, 1.0, 1.6, 0.5, 6));
  }
  const WallResult r = build_wall(wall(rectangle(100.2, 6), openings));
  expect_solid(r, 100);
  double removed = 0;
  for (const Opening& o : openings) removed += opening_area(o);
  EXPECT_NEAR(volume(r.mesh), (100.2 * 6 - removed) * 0.3, 1e-9);
  auto counts = count_classes(r.mesh);
  EXPECT_EQ(counts[SemanticClass::kJamb], 200);
  EXPECT_EQ(counts[SemanticClass::kSill], 100);
  EXPECT_EQ(counts[SemanticClass::kLintel], 50 + 50 * 6);
}

TEST(Wall, TouchingOpeningsAreRejectedWithTheReason) {
  const WallResult r = build_wall(wall(rectangle(6, 3), {window(1, 1, 1, 1), window(2, 1, 1, 1)}));
  EXPECT_EQ(r.status, WallStatus::kRejectedOpening);
  EXPECT_EQ(r.message, "opening 1 touches opening 0");
  ASSERT_EQ(r.issues.size(), 1U);
  EXPECT_EQ(r.issues[0].opening, 1U);
  EXPECT_EQ(r.issues[0].problem, OpeningProblem::kTouchesOpening);
  EXPECT_EQ(r.issues[0].other, std::optional<std::size_t>(0));
  EXPECT_TRUE(r.mesh.empty());
}

TEST(Wall, RejectionMessages) {
  const Ring outline = rectangle(6, 3);
  const auto message = [&](std::vector<Opening> openings) {
    const WallResult r = build_wall(wall(outline, std::move(openings)));
    return r.message;
  };
  EXPECT_EQ(message({window(1, 1, 2, 1), window(2, 1.5, 2, 1)}), "opening 1 overlaps opening 0");
  EXPECT_EQ(message({window(1, 1, 1, 1), window(1, 1, 1, 1)}), "opening 1 overlaps opening 0");
  EXPECT_EQ(message({window(1, 1, 1, 1), window(2.02, 1, 1, 1)}),
            "opening 1 is 0.02 m from opening 0, less than the margin 0.05 m");
  EXPECT_EQ(message({window(0, 1, 1, 1)}), "opening 0 touches the wall outline");
  EXPECT_EQ(message({window(1, 1, 1, 2)}), "opening 0 touches the wall outline");
  EXPECT_EQ(message({window(5.5, 1, 1, 1)}), "opening 0 extends outside the wall outline");
  EXPECT_EQ(message({window(10, 1, 1, 1)}), "opening 0 extends outside the wall outline");
  EXPECT_EQ(message({window(1, 1, 1, 1.99)}),
            "opening 0 is 0.01 m from the wall outline, less than the margin 0.05 m");
  EXPECT_EQ(message({window(0.02, 0, 1, 2)}),
            "opening 0 is 0.02 m from the wall outline, less than the margin 0.05 m");
  EXPECT_EQ(message({window(0, 0, 1, 2)}), "opening 0 touches the wall outline");
  EXPECT_EQ(message({window(1, 1, -1, 1)}), "opening 0: width and height must be positive");
  EXPECT_EQ(message({window(1, NAN, 1, 1)}), "opening 0: position and size must be finite");
  EXPECT_EQ(message({arched(1, 1, 1, 1, 0.6, 8)}),
            "opening 0: arch rise must be in [0, width / 2] and below the height");
  EXPECT_EQ(message({arched(1, 1, 1, 1, 0.5, 0)}), "opening 0: arch segments must be in [1, 1024]");
}

TEST(Wall, SkipPolicyBuildsWithoutTheRejected) {
  WallSpec spec = wall(rectangle(8, 3), {window(1, 1, 1, 1), window(1.5, 1.5, 1, 1),
                                         window(4, 1, 1, 1), window(7.5, 1, 1, 1)});
  spec.policy = OpeningPolicy::kSkip;
  const WallResult r = build_wall(spec);
  expect_solid(r, 2);
  EXPECT_EQ(r.cut, (std::vector<std::size_t>{0, 2}));
  ASSERT_EQ(r.issues.size(), 2U);
  EXPECT_EQ(r.issues[0].message, "opening 1 overlaps opening 0");
  EXPECT_EQ(r.issues[1].message, "opening 3 extends outside the wall outline");
  EXPECT_NEAR(volume(r.mesh), (24 - 2) * 0.3, 1e-12);
  std::vector<std::size_t> accepted;
  EXPECT_EQ(check_openings(spec, &accepted).size(), 2U);
  EXPECT_EQ(accepted, (std::vector<std::size_t>{0, 2}));
}

TEST(Wall, ZeroMarginStillRejectsTouching) {
  WallSpec spec = wall(rectangle(6, 3), {window(1, 1, 1, 1), window(2.001, 1, 1, 1)});
  spec.min_margin = 0;
  expect_solid(build_wall(spec), 2);
  spec.openings[1].u = 2;
  EXPECT_EQ(build_wall(spec).message, "opening 1 touches opening 0");
}

TEST(Wall, InvalidWalls) {
  EXPECT_EQ(build_wall(wall(rectangle(4, 3), {}, 0)).message,
            "wall thickness must be positive and finite");
  EXPECT_EQ(build_wall(wall({{0, 0}, {1, 0}}, {})).message,
            "wall outline needs at least 3 vertices");
  EXPECT_EQ(build_wall(wall({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {})).message,
            "wall outline edges 0 and 2 touch or cross");
  EXPECT_EQ(build_wall(wall({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, {})).message,
            "wall outline vertex 2 repeats the previous vertex");
  EXPECT_EQ(build_wall(wall({{0, 0}, {1, 0}, {2, 0}}, {})).message, "wall outline has zero area");
  WallSpec spec = wall(rectangle(4, 3), {});
  spec.min_margin = -1;
  EXPECT_EQ(build_wall(spec).status, WallStatus::kInvalidWall);
}

TEST(Wall, FrameMapsAndKeepsOrientation) {
  const auto placement = place_wall({10, 5, 2}, {10, 9, 2}, 3, 0.4);  // running +Y
  ASSERT_TRUE(placement);
  EXPECT_NEAR(placement->length, 4, 1e-12);
  EXPECT_NEAR(placement->frame.normal.x, 1, 1e-12);  // right of +Y is +X (outside a CCW footprint)
  WallSpec spec = wall(placement->outline, {window(1, 1, 1, 1)}, placement->thickness);
  const WallResult r = build_wall(spec, placement->frame);
  expect_solid(r, 1);
  EXPECT_NEAR(volume(r.mesh), (12 - 1) * 0.4, 1e-12);
  const Bounds3 b = r.mesh.bounds();
  // Inside alignment: the front face lies on the segment (x = 10), the wall extends to x = 9.6.
  EXPECT_NEAR(b.min.x, 9.6, 1e-12);
  EXPECT_NEAR(b.max.x, 10, 1e-12);
  EXPECT_NEAR(b.min.z, 2, 1e-12);
  EXPECT_NEAR(b.max.z, 5, 1e-12);
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    if (r.mesh.tag(f).semantic == SemanticClass::kWallSurface) {
      EXPECT_NEAR(face_normal(r.mesh, f).x, 1, 1e-12);
    }
  }
  const auto centered = place_wall({0, 0, 0}, {4, 0, 1}, 3, 0.4, WallAlignment::kCenter);
  ASSERT_TRUE(centered);
  EXPECT_NEAR(centered->frame.origin.y, 0.2, 1e-12);  // normal is -Y for a segment along +X
  EXPECT_FALSE(place_wall({1, 1, 0}, {1, 1, 5}, 3, 0.4));
  EXPECT_FALSE(place_wall({0, 0, 0}, {1, 0, 0}, 0, 0.4));
}

TEST(Wall, LeftHandedFrameStillOutward) {
  WallFrame frame;
  frame.normal = {0, 0, -1};
  const WallResult r = build_wall(wall(rectangle(5, 3), {window(1, 1, 1, 1)}), frame);
  expect_solid(r, 1);
  EXPECT_NEAR(volume(r.mesh), 14 * 0.3, 1e-12);
}

// Random rows of windows, arches and doors on random walls: always a closed solid of the right
// volume and genus.
TEST(Wall, RandomFacadesAreClosedSolids) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const int columns = 1 + static_cast<int>(unit(rng) * 8);
    const int rows = 1 + static_cast<int>(unit(rng) * 3);
    const double bay = 1.5 + unit(rng);
    const double storey = 2.5 + unit(rng);
    std::vector<Opening> openings;
    int doors = 0;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        if (unit(rng) < 0.2) continue;
        const double width = 0.3 + unit(rng) * (bay - 0.6);
        const double u = 0.2 + c * bay + unit(rng) * (bay - 0.2 - width - 0.1);
        const bool door = r == 0 && unit(rng) < 0.3;
        const double sill = door ? 0 : r * storey + 0.3 + unit(rng) * 0.5;
        const double height = 0.5 + unit(rng) * (storey - 1.4);
        Opening o = window(u, sill, width, height);
        if (unit(rng) < 0.4) {
          o.arch_rise = std::min(width / 2, height / 2) * unit(rng);
          o.arch_segments = 1 + static_cast<int>(unit(rng) * 12);
        }
        doors += door ? 1 : 0;
        openings.push_back(o);
      }
    }
    const double length = 0.3 + columns * bay;
    const double height = rows * storey + 0.2;
    Ring outline = rectangle(length, height);
    if (trial % 2 == 1) outline.insert(outline.begin() + 3, {length / 2, height + 2});  // gable
    const WallSpec spec = wall(outline, openings);
    const WallResult result = build_wall(spec);
    SCOPED_TRACE(trial);
    ASSERT_TRUE(result.ok()) << result.message;
    expect_solid(result, static_cast<int>(openings.size()) - doors);
    double removed = 0;
    for (const Opening& o : openings) removed += opening_area(o);
    const double outline_area = length * height + (trial % 2 == 1 ? length : 0);
    EXPECT_NEAR(volume(result.mesh), (outline_area - removed) * 0.3, 1e-9);
  }
}

}  // namespace
}  // namespace insula::kernel

namespace insula::kernel {
namespace {

// Random star-shaped outlines with random, often conflicting openings: the skip policy keeps the
// valid ones and the result is always a closed solid whose genus is the number of openings cut.
TEST(Wall, RandomOutlinesWithSkippedOpenings) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t total_cut = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Ring outline;
    const int n = 3 + static_cast<int>(unit(rng) * 14);
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * (i + 0.8 * unit(rng)) / n;
      const double radius = 4 + 4 * unit(rng);
      outline.push_back({10 + radius * std::cos(angle), 8 + radius * std::sin(angle)});
    }
    WallSpec spec = wall(outline, {});
    spec.policy = OpeningPolicy::kSkip;
    for (int k = 0; k < 40; ++k) {
      Opening o = window(2 + 16 * unit(rng), 1 + 14 * unit(rng), 0.2 + 1.5 * unit(rng),
                         0.3 + 2 * unit(rng));
      if (unit(rng) < 0.5) {
        o.arch_rise = std::min(o.width / 2, o.height / 2) * unit(rng);
        o.arch_segments = 1 + static_cast<int>(unit(rng) * 10);
      }
      spec.openings.push_back(o);
    }
    const WallResult r = build_wall(spec);
    SCOPED_TRACE(trial);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.cut.size() + r.issues.size(), spec.openings.size());
    expect_solid(r, static_cast<int>(r.cut.size()));
    double area = 0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
      area += cross(outline[i], outline[(i + 1) % outline.size()]) / 2;
    }
    for (std::size_t i : r.cut) area -= opening_area(spec.openings[i]);
    EXPECT_NEAR(volume(r.mesh), area * 0.3, 1e-9);
    total_cut += r.cut.size();
  }
  EXPECT_GT(total_cut, 200U * 5);  // the property is exercised on many holes, not on empty walls
}

}  // namespace
}  // namespace insula::kernel
