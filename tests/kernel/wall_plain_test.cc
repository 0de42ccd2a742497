// The plain-wall shortcut of build_wall (kernel/wall_plain.cc): rectangular outlines with
// rectangular openings side by side get their boundary and pieces without validation and sweep.
// They must be what the general path gives (the same boundary vertices, edge kinds and openings,
// the same pieces in the same order, every opening cut), also for walls just outside its reach
// (openings at the margin, stacked, arched, doors on the base), which it must leave alone.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/wall.h"
#include "kernel/wall_detail.h"

namespace insula::kernel {
namespace {

Opening rectangle(double u, double sill, double width, double height) {
  return {u, sill, width, height};
}

// A rectangle outline (now and then listed from another corner or clockwise, or far from the
// origin) with rectangular openings in a row, many of them placed at the margin from the outline
// or a neighbour, give or take a few units in the last place, some stacked, arched, on the base or
// overlapping.
WallSpec random_wall(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  WallSpec spec;
  const double far = unit(rng) < 0.2 ? 1e4 : 20;
  const double x0 = unit(rng) < 0.5 ? 0 : far * (2 * unit(rng) - 1);
  const double y0 = unit(rng) < 0.5 ? 0 : -5 + 10 * unit(rng);
  const double length = 1 + 12 * unit(rng);
  const double height = 2.5 + 2 * unit(rng);
  spec.outline = {{x0, y0}, {x0 + length, y0}, {x0 + length, y0 + height}, {x0, y0 + height}};
  if (unit(rng) < 0.1)
    std::rotate(spec.outline.begin(), spec.outline.begin() + 1, spec.outline.end());
  if (unit(rng) < 0.1) std::reverse(spec.outline.begin(), spec.outline.end());
  spec.thickness = 0.1 + 0.3 * unit(rng);
  const double margins[] = {0.0, 0.05, 0.2};
  spec.min_margin = margins[static_cast<int>(unit(rng) * 3)];
  spec.policy = unit(rng) < 0.2 ? OpeningPolicy::kFail : OpeningPolicy::kSkip;
  const int count = static_cast<int>(unit(rng) * 6);
  // At the margin, or off it by a few units in the last place of the coordinates.
  const auto near = [&] { return unit(rng) < 0.5 ? 0 : (2 * unit(rng) - 1) * 1e-15 * far; };
  double u = x0 + spec.min_margin + (unit(rng) < 0.2 ? near() : 0.5 * unit(rng));
  for (int k = 0; k < count; ++k) {
    const double width = 0.3 + 1.2 * unit(rng);
    const double sill = unit(rng) < 0.15  ? y0
                        : unit(rng) < 0.2 ? y0 + spec.min_margin + near()
                                          : y0 + spec.min_margin + 1.5 * unit(rng);
    double top = sill + 0.5 + 2 * unit(rng);
    if (unit(rng) < 0.15) top = y0 + height - spec.min_margin + near();
    Opening o = rectangle(u, sill, width, top - sill);
    if (unit(rng) < 0.1) o.arch_rise = width / 4;
    spec.openings.push_back(o);
    const double r = unit(rng);
    u += r < 0.15  ? 0  // stacked or overlapping
         : r < 0.3 ? width + spec.min_margin + near()
                   : width + spec.min_margin + 0.8 * unit(rng);
  }
  std::shuffle(spec.openings.begin(), spec.openings.end(), rng);
  return spec;
}

// What one path gives for a wall: the boundary rings and the pieces.
struct Pieces {
  bool ok = false;
  std::vector<std::size_t> cut;
  wall_detail::Boundary boundary;
  std::vector<std::uint32_t> loops;
  std::vector<std::uint32_t> offsets{0};
};

// Validation, boundary rings and the monotone partition.
Pieces general_path(const WallSpec& spec, const Ring& ccw) {
  Pieces p;
  std::vector<wall_detail::Accepted> cut;
  const auto issues = wall_detail::validate(ccw, spec, cut);
  if (!issues.empty()) return p;
  std::vector<const wall_detail::Accepted*> notches;
  wall_detail::build_boundary(ccw, cut, p.boundary, notches);
  const wall_detail::PartitionScratchPtr scratch = wall_detail::make_partition_scratch();
  p.ok = wall_detail::partition(p.boundary, *scratch, p.loops, p.offsets);
  for (const wall_detail::Accepted& c : cut) p.cut.push_back(c.index);
  return p;
}

// The shortcut, for a plain wall.
std::optional<Pieces> plain_path(const WallSpec& spec) {
  Ring scratch;
  const Ring& ccw =
      wall_detail::counter_clockwise(spec.outline, signed_area(spec.outline), scratch);
  std::vector<wall_detail::PlainOpening> sorted;
  if (!wall_detail::plain_wall(ccw, spec, sorted)) return std::nullopt;
  Pieces p;
  p.ok = true;
  wall_detail::plain_boundary(ccw, spec, p.boundary);
  wall_detail::plain_loops(sorted, p.loops, p.offsets);
  for (std::size_t i = 0; i < spec.openings.size(); ++i) p.cut.push_back(i);
  return p;
}

TEST(WallPlain, ShortcutMatchesTheGeneralPath) {
  constexpr int kTrials = 3000;
  std::mt19937 rng(77);
  int plain = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    SCOPED_TRACE(trial);
    const WallSpec spec = random_wall(rng);
    const std::optional<Pieces> fast = plain_path(spec);
    if (!fast) continue;
    ++plain;
    Ring scratch;
    const Pieces general = general_path(
        spec, wall_detail::counter_clockwise(spec.outline, signed_area(spec.outline), scratch));
    ASSERT_TRUE(general.ok);
    EXPECT_EQ(fast->cut, general.cut);
    EXPECT_EQ(fast->boundary.points, general.boundary.points);
    EXPECT_EQ(fast->boundary.next, general.boundary.next);
    EXPECT_EQ(fast->boundary.kind, general.boundary.kind);
    EXPECT_EQ(fast->boundary.opening, general.boundary.opening);
    EXPECT_EQ(fast->loops, general.loops);
    EXPECT_EQ(fast->offsets, general.offsets);
  }
  // About a fifth of these walls is plain (300,000 walls were compared once with this generator,
  // all identical).
  EXPECT_GT(plain, 500) << plain;
  EXPECT_LT(plain, 1000) << plain;
}

// The pieces of a plain wall with three windows given out of order (input order 1, 2, 0 by u):
// the lower piece runs along the bottom and under the windows from right to left, the upper one
// from the right end over the windows from left to right.
TEST(WallPlain, PiecesOfThreeWindows) {
  WallSpec spec;
  spec.outline = {{0, 0}, {10, 0}, {10, 3}, {0, 3}};
  spec.openings = {rectangle(7, 1, 1, 1), rectangle(1, 1, 1, 1), rectangle(4, 0.5, 1, 2)};
  WallWorkspace workspace;
  Mesh mesh;
  const WallResult& r = build_wall(spec, {}, mesh, workspace);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(plain_path(spec).has_value());
  EXPECT_EQ(r.cut, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(r.front_pieces, 2U);
  // Opening i's corners are vertices 4 + 4i (lower left), +1 (upper left), +2, +3 (lower right).
  const auto face = [&](std::size_t f) {
    const auto loop = mesh.face(f);
    return std::vector<std::uint32_t>(loop.begin(), loop.end());
  };
  EXPECT_EQ(face(0), (std::vector<std::uint32_t>{0, 1, 6, 7, 4, 14, 15, 12, 10, 11, 8, 3}));
  EXPECT_EQ(face(1), (std::vector<std::uint32_t>{1, 2, 3, 8, 9, 10, 12, 13, 14, 4, 5, 6}));
  // 2 + 2 pieces, 4 rim quads, 12 reveal quads; a closed solid of the wall minus its openings.
  EXPECT_EQ(mesh.face_count(), 20U);
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_NEAR(volume(mesh), (30 - 1 - 1 - 2) * 0.3, 1e-12);
}

// Openings the shortcut leaves to the general path: stacked, arched, on the base, at the margin.
TEST(WallPlain, OtherWallsTakeTheGeneralPath) {
  const auto plain = [](std::vector<Opening> openings, double margin = 0.05) {
    WallSpec spec;
    spec.outline = {{0, 0}, {6, 0}, {6, 3}, {0, 3}};
    spec.openings = std::move(openings);
    spec.min_margin = margin;
    EXPECT_TRUE(build_wall(spec).ok());
    return plain_path(spec).has_value();
  };
  EXPECT_TRUE(plain({}));
  EXPECT_TRUE(plain({rectangle(1, 1, 1, 1), rectangle(3, 1, 1, 1)}));
  EXPECT_FALSE(plain({rectangle(1, 0.2, 1, 1), rectangle(1, 1.6, 1, 1)}));  // stacked
  Opening arch = rectangle(1, 1, 1, 1.5);
  arch.arch_rise = 0.5;
  EXPECT_FALSE(plain({arch}));
  EXPECT_FALSE(plain({rectangle(1, 0, 1, 2)}));         // a door notch in the base
  EXPECT_FALSE(plain({rectangle(0.3, 1, 1, 1)}, 0.3));  // at the margin from the end
  EXPECT_TRUE(plain({rectangle(0.31, 1, 1, 1)}, 0.3));
}

}  // namespace
}  // namespace insula::kernel
