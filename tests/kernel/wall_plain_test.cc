// The plain-wall shortcut of build_wall (wall.cc, WallWorkspace::set_plain_shortcut): rectangular
// outlines with rectangular openings side by side get their pieces without the sweep. Walls built
// with and without it must be identical (mesh bits, face order, tags, every result field), also
// for walls just outside its reach (openings at the margin, stacked, arched, doors on the base).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/wall.h"

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

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.face_count(), b.face_count());
  for (std::uint32_t v = 0; v < a.vertex_count(); ++v) ASSERT_EQ(a.position(v), b.position(v));
  for (std::size_t f = 0; f < a.face_count(); ++f) {
    const auto fa = a.face(f), fb = b.face(f);
    ASSERT_EQ(std::vector<std::uint32_t>(fa.begin(), fa.end()),
              std::vector<std::uint32_t>(fb.begin(), fb.end()))
        << f;
    ASSERT_EQ(a.tag(f).semantic, b.tag(f).semantic) << f;
    ASSERT_EQ(a.tag(f).face_id, b.tag(f).face_id) << f;
  }
}

TEST(WallPlain, ShortcutMatchesTheGeneralPath) {
  constexpr int kTrials = 3000;
  std::mt19937 rng(77);
  WallWorkspace fast;
  WallWorkspace general;
  general.set_plain_shortcut(false);
  Mesh fast_mesh, general_mesh;
  int ok = 0, with_issues = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    SCOPED_TRACE(trial);
    const WallSpec spec = random_wall(rng);
    WallFrame frame;
    frame.origin = {1.5 * trial, -0.25 * trial, 3};
    if (trial % 4 == 1) frame.normal = {0, 0, -1};  // left-handed now and then
    const WallResult& a = build_wall(spec, frame, fast_mesh, fast);
    const WallResult& b = build_wall(spec, frame, general_mesh, general);
    ASSERT_EQ(a.status, b.status);
    EXPECT_EQ(a.message, b.message);
    EXPECT_EQ(a.cut, b.cut);
    EXPECT_EQ(a.front_pieces, b.front_pieces);
    ASSERT_EQ(a.issues.size(), b.issues.size());
    for (std::size_t i = 0; i < a.issues.size(); ++i) {
      EXPECT_EQ(a.issues[i].opening, b.issues[i].opening);
      EXPECT_EQ(a.issues[i].problem, b.issues[i].problem);
      EXPECT_EQ(a.issues[i].other, b.issues[i].other);
      EXPECT_EQ(a.issues[i].message, b.issues[i].message);
    }
    ok += a.ok();
    with_issues += !a.issues.empty();
  }
  expect_same_mesh(fast_mesh, general_mesh);
  EXPECT_TRUE(is_watertight(fast_mesh));
  // Both paths were exercised (about a fifth of these walls is plain; 300,000 walls were compared
  // once with this generator, all identical).
  EXPECT_EQ(general.plain_walls(), 0U);
  EXPECT_GT(fast.plain_walls(), 500U) << fast.plain_walls();
  EXPECT_LT(fast.plain_walls(), 1000U);
  EXPECT_GT(ok, 2000) << ok;
  EXPECT_GT(with_issues, 500) << with_issues;
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
  EXPECT_EQ(workspace.plain_walls(), 1U);
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
    WallWorkspace workspace;
    Mesh mesh;
    EXPECT_TRUE(build_wall(spec, {}, mesh, workspace).ok());
    return workspace.plain_walls() == 1;
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
