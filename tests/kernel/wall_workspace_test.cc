// build_wall with a reused WallWorkspace (wall.h): one workspace for a run of walls, failures in
// between, must give exactly what separate build_wall calls give, appended into one mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/wall.h"

namespace insula::kernel {
namespace {

Opening window(double u, double sill, double width, double height) {
  return {u, sill, width, height};
}

// A random star-shaped outline with random, often conflicting openings (doors on the base when
// the outline is a rectangle); every seventh wall is invalid and every fifth fails on a rejected
// opening, so the workspace is reused across every kind of result.
WallSpec random_wall(std::mt19937& rng, int trial) {
  std::uniform_real_distribution<double> unit(0, 1);
  WallSpec spec;
  spec.thickness = 0.1 + 0.3 * unit(rng);
  if (trial % 3 == 0) {
    const double length = 3 + 8 * unit(rng);
    spec.outline = {{0, 0}, {length, 0}, {length, 3}, {0, 3}};
  } else {
    const int n = 3 + static_cast<int>(unit(rng) * 12);
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * (i + 0.8 * unit(rng)) / n;
      const double radius = 4 + 4 * unit(rng);
      spec.outline.push_back({10 + radius * std::cos(angle), 8 + radius * std::sin(angle)});
    }
  }
  if (trial % 7 == 6) spec.outline.push_back(spec.outline.back());  // a repeated vertex
  spec.policy = trial % 5 == 4 ? OpeningPolicy::kFail : OpeningPolicy::kSkip;
  const int openings = static_cast<int>(unit(rng) * 12);
  for (int k = 0; k < openings; ++k) {
    Opening o = trial % 3 == 0 ? window(0.2 + 8 * unit(rng), unit(rng) < 0.3 ? 0 : 0.9,
                                        0.5 + unit(rng), 1 + unit(rng))
                               : window(2 + 16 * unit(rng), 1 + 14 * unit(rng),
                                        0.2 + 1.5 * unit(rng), 0.3 + 2 * unit(rng));
    if (unit(rng) < 0.4) {
      o.arch_rise = std::min(o.width / 2, o.height / 2) * unit(rng);
      o.arch_segments = 1 + static_cast<int>(unit(rng) * 10);
    }
    spec.openings.push_back(o);
  }
  return spec;
}

WallFrame random_frame(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const double angle = std::numbers::pi * unit(rng);
  WallFrame frame;
  frame.origin = {10 * unit(rng), 10 * unit(rng), 3 * unit(rng)};
  frame.u_axis = {std::cos(angle), std::sin(angle), 0};
  frame.v_axis = {0, 0, 1};
  frame.normal = cross(frame.u_axis, frame.v_axis);
  if (unit(rng) < 0) frame.normal = -frame.normal;  // left-handed now and then
  return frame;
}

TEST(WallWorkspace, ReusedWorkspaceMatchesSeparateWalls) {
  std::mt19937 rng(2024);
  WallWorkspace workspace;
  Mesh together;  // every wall through the one workspace
  Mesh separate;  // every wall built alone, then appended
  int ok = 0, invalid = 0, rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE(trial);
    const WallSpec spec = random_wall(rng, trial);
    const WallFrame frame = random_frame(rng);
    const WallResult alone = build_wall(spec, frame);
    const WallResult& reused = build_wall(spec, frame, together, workspace);
    ASSERT_EQ(reused.status, alone.status);
    EXPECT_EQ(reused.message, alone.message);
    EXPECT_EQ(reused.cut, alone.cut);
    EXPECT_EQ(reused.front_pieces, alone.front_pieces);
    ASSERT_EQ(reused.issues.size(), alone.issues.size());
    for (std::size_t i = 0; i < alone.issues.size(); ++i) {
      EXPECT_EQ(reused.issues[i].message, alone.issues[i].message);
      EXPECT_EQ(reused.issues[i].problem, alone.issues[i].problem);
    }
    EXPECT_TRUE(reused.mesh.empty());
    if (alone.ok()) {
      separate.append(alone.mesh);
      ++ok;
    } else {
      ++(alone.status == WallStatus::kInvalidWall ? invalid : rejected);
    }
  }
  // The run covered every outcome, with many walls built.
  EXPECT_GT(ok, 150);
  EXPECT_GT(invalid, 20);
  EXPECT_GT(rejected, 10);
  ASSERT_EQ(together.vertex_count(), separate.vertex_count());
  ASSERT_EQ(together.face_count(), separate.face_count());
  for (std::uint32_t v = 0; v < together.vertex_count(); ++v) {
    ASSERT_EQ(together.position(v), separate.position(v)) << v;
  }
  for (std::size_t f = 0; f < together.face_count(); ++f) {
    const auto a = together.face(f), b = separate.face(f);
    ASSERT_EQ(std::vector<std::uint32_t>(a.begin(), a.end()),
              std::vector<std::uint32_t>(b.begin(), b.end()))
        << f;
    EXPECT_EQ(together.tag(f).semantic, separate.tag(f).semantic);
  }
  EXPECT_TRUE(is_watertight(together));
}

TEST(WallWorkspace, ResultIsResetBetweenWalls) {
  WallWorkspace workspace;
  Mesh mesh;
  WallSpec bad;
  bad.outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  bad.openings = {window(1, 1, 1, 1), window(2, 1, 1, 1)};  // touching: rejected under kFail
  const WallResult& first = build_wall(bad, {}, mesh, workspace);
  EXPECT_EQ(first.status, WallStatus::kRejectedOpening);
  EXPECT_EQ(first.message, "opening 1 touches opening 0");
  EXPECT_EQ(mesh.face_count(), 0U);
  WallSpec good = bad;
  good.openings.pop_back();
  const WallResult& second = build_wall(good, {}, mesh, workspace);
  EXPECT_TRUE(second.ok());
  EXPECT_TRUE(second.message.empty());
  EXPECT_TRUE(second.issues.empty());
  EXPECT_EQ(second.cut, std::vector<std::size_t>{0});
  EXPECT_EQ(second.front_pieces, 2U);
  // 2 front + 2 back pieces, 4 rim quads and 4 reveal quads.
  EXPECT_EQ(mesh.face_count(), 12U);
  EXPECT_NEAR(volume(mesh), (12 - 1) * 0.3, 1e-12);
  WallWorkspace moved = std::move(workspace);
  good.thickness = 0;
  EXPECT_EQ(build_wall(good, {}, mesh, moved).message,
            "wall thickness must be positive and finite");
  EXPECT_EQ(mesh.face_count(), 12U);
}

// Axis-parallel rectangles (place_wall's outlines) take a shorter validation path; its verdicts
// must be those of the general tests.
TEST(WallWorkspace, RectangleOutlinesAreValidatedLikeAnyOutline) {
  const auto message = [](Ring outline) {
    WallSpec spec;
    spec.outline = std::move(outline);
    return build_wall(spec).message;
  };
  EXPECT_EQ(message({{0, 0}, {4, 0}, {4, 3}, {0, 3}}), "");
  EXPECT_EQ(message({{0, 0}, {0, 3}, {4, 3}, {4, 0}}), "");  // clockwise, y side first
  EXPECT_EQ(message({{0, 0}, {1e-10, 0}, {1e-10, 3}, {0, 3}}),
            "wall outline vertex 1 repeats the previous vertex");
  EXPECT_EQ(message({{0, 0}, {2e-5, 0}, {2e-5, 2e-5}, {0, 2e-5}}), "wall outline has zero area");
  EXPECT_EQ(message({{0, 0}, {INFINITY, 0}, {INFINITY, 3}, {0, 3}}),
            "wall outline has a non-finite coordinate");
  EXPECT_EQ(message({{0, 0}, {4, 0}, {4, 3}, {0, 3.5}}), "");  // not a rectangle: general path
}

TEST(SquaredDistanceToSegment, SquareOfTheDistance) {
  const Vec2 a{1, 1}, b{4, 5};
  for (const Vec2 p : {Vec2{0, 0}, Vec2{5, 7}, Vec2{3, 1}, Vec2{2.5, 3}, Vec2{-2, 9}}) {
    const double d = distance_to_segment(p, a, b);
    EXPECT_NEAR(squared_distance_to_segment(p, a, b), d * d, 1e-12);
  }
  EXPECT_EQ(squared_distance_to_segment({3, 1}, a, a), 4.0);    // zero-length segment: to a
  EXPECT_EQ(squared_distance_to_segment({0, -2}, a, b), 10.0);  // beyond a: to a
  EXPECT_EQ(squared_distance_to_segment({4, 1}, {0, 0}, {8, 0}), 1.0);
}

}  // namespace
}  // namespace insula::kernel
