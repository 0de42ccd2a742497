// The shortcuts docs/PERFORMANCE.md ("PLaSM") describes give the geometry the general path gives:
// a difference against many disjoint operands in one boolean (and the one-by-one fallback when
// they overlap), the export's hull of a stored cell reused for every instance (mirrored ones
// turned outward), tetrahedra without a hull, and MAP memoised by its arguments; and STRUCT's
// narrow transformations, which the instance test met.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lang/plasm/output.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

struct Built {
  std::string error;
  double volume = 0;
  bool closed = true;
  std::size_t parts = 0;
  std::size_t solid_cells = 0;
};

Built build(const std::string& text) {
  Built out;
  const base::Source source("t.psm", text);
  const auto program = parse(source);
  if (!program.ok()) return {base::render(program.diagnostics().front())};
  const auto scene = program_scene(program.value(), source);
  if (!scene.ok()) return {base::render(scene.diagnostics().front())};
  out.solid_cells = scene.value().stats.solid_cells;
  for (const shape::Building& b : scene.value().scene.buildings) {
    for (const shape::Part& p : b.parts) {
      ++out.parts;
      out.volume += kernel::volume(p.mesh);
      out.closed = out.closed && kernel::check(p.mesh).closed;
    }
  }
  return out;
}

// bench/plasm/wall_windows.psm: one by one, the growing result failed the operand check
// ("first operand intersects itself") after minutes; against the windows side by side it is
// one boolean.
TEST(PlasmFastPaths, WallMinusHundredWindows) {
  const Built b = build(R"(
DEF wall = CUBOID:<45, 0.5, 30>;
DEF window (i, j::IsReal) = (T:<1, 2, 3>:<4.5*i - 3.75, -0.25, 3*j - 2.4> ~ CUBOID):<1.5, 1, 1.8>;
DEF places = CAT:(AA:(DISTR ~ [K:(1 .. 10), ID]):(1 .. 10));
DIFFERENCE:(wall AL AA:window:places);
)");
  ASSERT_EQ(b.error, "");
  EXPECT_NEAR(b.volume, 45 * 0.5 * 30 - 100 * 1.5 * 0.5 * 1.8, 1e-6);
  EXPECT_TRUE(b.closed);
}

// Overlapping (and touching) operands make no valid combined mesh: they go one by one.
TEST(PlasmFastPaths, OverlappingOperandsOneByOne) {
  const Built difference = build(
      "DIFFERENCE:<CUBOID:<4, 4, 4>, (T:<1, 2, 3>:<1, 1, -1> ~ CUBOID):<2, 2, 6>, "
      "(T:<1, 2, 3>:<2, 2, -1> ~ CUBOID):<1, 1, 6>, (T:<1, 2, 3>:<3, 1, -1> ~ CUBOID):<0.5, 2, "
      "6>>;");
  ASSERT_EQ(difference.error, "");
  // Holes through the cube: 2 x 2 (holding the 1 x 1), and 0.5 x 2 touching it.
  EXPECT_NEAR(difference.volume, 64 - 4 * (4 + 1), 1e-6);
  EXPECT_TRUE(difference.closed);
  const Built sum =
      build("UNION:<CUBOID:<2, 2, 2>, (T:1:1 ~ CUBOID):<2, 2, 2>, (T:1:5 ~ CUBOID):<1, 1, 1>>;");
  ASSERT_EQ(sum.error, "");
  EXPECT_NEAR(sum.volume, 12 + 1, 1e-6);
}

// A stored cell placed many times, some mirrored: every instance outward, the same volume.
TEST(PlasmFastPaths, InstancesAndMirrorsShareOneHull) {
  const std::string cell = "DEF p = JOIN:(TRUNCONE:<1, 0.5, 2>:12);\n";
  const Built one = build(cell + "p;");
  ASSERT_EQ(one.error, "");
  ASSERT_GT(one.volume, 0);
  const Built many = build(cell +
                           "STRUCT:<p, T:1:3, p, S:1:-1, p, T:2:3, R:<1, 2>:(PI/5), p, S:3:-1, "
                           "p, S:<1, 2>:<-1, 2>, p>;");
  ASSERT_EQ(many.error, "");
  EXPECT_EQ(many.solid_cells, 6U);
  EXPECT_TRUE(many.closed);
  // Four congruent copies, the last two scaled by |det| = 1 and 2: 5 + 2 = 7 volumes.
  EXPECT_NEAR(many.volume, 7 * one.volume, 1e-9 * many.volume);
}

// A transformation of fewer coordinates than the part it places leaves the others alone (the
// flattening applied it narrow, and these came out flat: no volume, or PSM420).
TEST(PlasmFastPaths, NarrowTransformationsInStruct) {
  for (const char* program :
       {"STRUCT:<T:1:3, CUBOID:<1, 1, 1>>;", "STRUCT:<T:<1, 2>:<3, 3>, CUBOID:<1, 1, 1>>;",
        "STRUCT:<R:<1, 2>:(PI/5), CUBOID:<1, 1, 1>>;"}) {
    const Built b = build(program);
    ASSERT_EQ(b.error, "") << program;
    EXPECT_NEAR(b.volume, 1, 1e-9) << program;
  }
}

// MAP's simplices are exported without a hull; mirrored by a coordinate map they stay outward.
TEST(PlasmFastPaths, MappedTetrahedra) {
  const Built straight = build("MAP:[S1, S2, S3]:(Q:<1, 1> * Q:<2> * Q:<1>);");
  const Built mirrored = build("MAP:[S2, S1, S3]:(Q:<1, 1> * Q:<2> * Q:<1>);");
  ASSERT_EQ(straight.error, "");
  ASSERT_EQ(mirrored.error, "");
  EXPECT_NEAR(straight.volume, 4, 1e-9);
  EXPECT_NEAR(mirrored.volume, 4, 1e-9);
  EXPECT_TRUE(straight.closed && mirrored.closed);
  EXPECT_EQ(straight.solid_cells, 12U);  // two boxes, six tetrahedra each
}

// The same coordinate functions on the same domain twice (Listing 6's ceiling and body): the
// memoised map is the same complex, so the dome sits at z = 0 exactly as before.
TEST(PlasmFastPaths, MemoisedMapKeepsTheProgramsValue) {
  const std::string text = R"(
DEF f = [S1, S2, S3 + 1];
DEF dom = Q:<1> * Q:<1> * Q:<1>;
DEF lifted = (T:3:(-:(MIN:3:(MAP:f:dom))) ~ MAP:f):dom;
)";
  EXPECT_EQ(testing::value_of(text, "lifted"), "<polyhedron 3D, 6 cells>");
  EXPECT_EQ(testing::value_of(text + "DEF low = MIN:3:lifted;", "low"), "0");
}

}  // namespace
}  // namespace insula::lang::plasm
