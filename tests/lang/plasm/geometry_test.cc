// The geometry stage (docs/plasm-language.md, "Geometry" and "Output"): exact results of small
// programs, measured on the polyhedra the evaluator gives and on the meshes they export.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "kernel/mesh.h"
#include "lang/plasm/output.h"
#include "lang/plasm/polyhedron.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

constexpr double kPi = std::numbers::pi;

// A checked program and its evaluator; values are asked for by DEF name.
class Checked {
 public:
  explicit Checked(const std::string& text) : source_("t.psm", text) {
    auto parsed = parse(source_);
    if (!parsed.ok()) {
      error_ = base::render(parsed.diagnostics().front());
      return;
    }
    program_.emplace(std::move(parsed.value()));
    const CheckResult checked = check(*program_, source_);
    if (!checked.diagnostics.empty()) {
      error_ = base::render(checked.diagnostics.front());
      return;
    }
    evaluator_ = std::make_unique<Evaluator>(*program_, source_);
  }

  ValuePtr value(const std::string& name) {
    if (!evaluator_) {
      ADD_FAILURE() << error_;
      return make_number(0);
    }
    auto v = evaluator_->value_of(name);
    if (!v.ok()) {
      ADD_FAILURE() << base::render(v.diagnostics().front());
      return make_number(0);
    }
    return v.value();
  }
  PolyPtr poly(const std::string& name) {
    const ValuePtr v = value(name);
    if (!v->is_polyhedron()) {
      ADD_FAILURE() << name << " is " << summary(*v);
      return make_leaf(3, {}, {});
    }
    return v->polyhedron();
  }
  std::string text(const std::string& name) { return summary(*value(name)); }
  double number(const std::string& name) {
    const ValuePtr v = value(name);
    if (!v->is_number()) {
      ADD_FAILURE() << name << " is " << summary(*v);
      return std::nan("");
    }
    return v->number();
  }

 private:
  base::Source source_;
  std::optional<Program> program_;
  std::unique_ptr<Evaluator> evaluator_;
  std::string error_;
};

// What a polyhedron exports: all parts' meshes together, welded, with their measures.
struct Exported {
  shape::Building building;
  MeshStats stats;
  kernel::Mesh mesh;
  kernel::MeshCheck check;
  double volume = 0;
  double area = 0;
  double smallest_face = 0;
  std::size_t used_vertices = 0;  // vertices some face uses
};

Exported exported(const PolyPtr& p) {
  Exported e;
  e.building = polyhedron_building(*p, "t", e.stats);
  kernel::Mesh all;
  for (const shape::Part& part : e.building.parts) all.append(part.mesh);
  e.mesh = kernel::weld(all);
  e.check = kernel::check(e.mesh);
  e.volume = kernel::volume(e.mesh);
  e.area = kernel::surface_area(e.mesh);
  std::vector<bool> used(e.mesh.vertex_count(), false);
  for (std::size_t f = 0; f < e.mesh.face_count(); ++f)
    for (std::uint32_t v : e.mesh.face(f)) used[v] = true;
  e.used_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  e.smallest_face = e.mesh.empty() ? 0 : 1e300;
  for (std::size_t f = 0; f < e.mesh.face_count(); ++f)
    e.smallest_face = std::min(e.smallest_face, kernel::face_area(e.mesh, f));
  return e;
}

// The total k-volume of a complex of 1D cells (each a segment).
double total_length(const PolyPtr& p) {
  const FlatComplex flat = flatten_cells(*p);
  double sum = 0;
  for (const Cell& cell : flat.cells) {
    double lo = 1e300;
    double hi = -1e300;
    for (std::uint32_t v : cell) {
      lo = std::min(lo, flat.point(v)[0]);
      hi = std::max(hi, flat.point(v)[0]);
    }
    sum += hi - lo;
  }
  return sum;
}

TEST(PlasmGeometry, QuoteCellsAndLength) {
  Checked r(
      "DEF qq = QUOTE:<1, -2, 3>; DEF lo = MIN:1:qq; DEF hi = MAX:1:qq;"
      "DEF extent = SIZE:1:qq; DEF one = Q:2.5;");
  const FlatComplex flat = flatten_cells(*r.poly("qq"));
  EXPECT_EQ(flat.dim, 1);
  EXPECT_EQ(flat.cells.size(), 2U);
  EXPECT_DOUBLE_EQ(total_length(r.poly("qq")), 4.0);
  EXPECT_EQ(r.number("lo"), 0.0);
  EXPECT_EQ(r.number("hi"), 6.0);
  EXPECT_EQ(r.number("extent"), 6.0);
  EXPECT_EQ(r.text("qq"), "<polyhedron 1D, 2 cells>");
  EXPECT_DOUBLE_EQ(total_length(r.poly("one")), 2.5);
}

TEST(PlasmGeometry, Intervals) {
  Checked r("DEF i = INTERVALS:10:5;");
  const FlatComplex flat = flatten_cells(*r.poly("i"));
  ASSERT_EQ(flat.cells.size(), 5U);
  EXPECT_DOUBLE_EQ(total_length(r.poly("i")), 10.0);
  for (const Cell& cell : flat.cells)
    EXPECT_DOUBLE_EQ(std::abs(flat.point(cell[1])[0] - flat.point(cell[0])[0]), 2.0);
}

TEST(PlasmGeometry, CuboidAndSimplexVolumes) {
  Checked r("DEF box = CUBOID:<2, 3, 4>; DEF s = SIMPLEX:3; DEF tri = SIMPLEX:2;");
  const Exported box = exported(r.poly("box"));
  EXPECT_DOUBLE_EQ(box.volume, 24.0);
  EXPECT_DOUBLE_EQ(box.area, 2 * (6 + 12 + 8.0));
  EXPECT_TRUE(box.check.closed);
  EXPECT_EQ(box.mesh.face_count(), 6U);
  EXPECT_EQ(box.mesh.vertex_count(), 8U);
  EXPECT_EQ(box.stats.solid_cells, 1U);
  const Exported s = exported(r.poly("s"));
  EXPECT_NEAR(s.volume, 1.0 / 6, 1e-12);
  EXPECT_TRUE(s.check.closed);
  EXPECT_EQ(s.mesh.face_count(), 4U);
  const Exported tri = exported(r.poly("tri"));
  EXPECT_NEAR(tri.area, 0.5, 1e-12);
  EXPECT_EQ(tri.stats.surface_cells, 1U);
}

// A product of QUOTEs is a conforming grid: it exports as one closed shell, the faces between
// cells removed.
TEST(PlasmGeometry, ProductGridIsOneClosedShell) {
  Checked r(
      "DEF g = QUOTE:<2, 2> * QUOTE:<1, 1, 1> * QUOTE:<1, 1, 1, 1>;"
      "DEF gap = QUOTE:<1, -1, 1> * QUOTE:<1> * QUOTE:<1>;");
  const PolyPtr g = r.poly("g");
  EXPECT_EQ(g->dim, 3);
  EXPECT_EQ(cell_count(*g), 24U);
  const Exported e = exported(g);
  EXPECT_DOUBLE_EQ(e.volume, 48.0);
  EXPECT_DOUBLE_EQ(e.area, 2 * (4 * 3 + 3 * 4 + 4 * 4.0));
  // 2 x 3 x 4 cells: 2 (2*3 + 3*4 + 2*4) = 52 boundary faces; 3 * 4 * 5 = 60 lattice points,
  // minus the 2 * 1 * 3 = 6 strictly inside.
  EXPECT_EQ(e.mesh.face_count(), 52U);
  EXPECT_EQ(e.used_vertices, 54U);
  EXPECT_TRUE(e.check.closed);
  EXPECT_TRUE(e.check.oriented);
  EXPECT_EQ(e.check.components, 1U);
  EXPECT_EQ(e.check.euler_characteristic, 2);
  // A gap keeps two shells.
  const Exported gap = exported(r.poly("gap"));
  EXPECT_EQ(gap.check.components, 2U);
  EXPECT_DOUBLE_EQ(gap.volume, 2.0);
}

// STRUCT: a transformation applies to everything after it, cumulatively.
TEST(PlasmGeometry, StructPlacementIsCumulative) {
  Checked r(
      "DEF c = CUBOID:<1, 1, 1>;"
      "DEF row = STRUCT:<c, T:1:2, c, T:1:2, c>;"
      "DEF lo = MIN:<1, 2, 3>:row; DEF hi = MAX:<1, 2, 3>:row;"
      "DEF turned = STRUCT:<T:1:10, R:<1, 2>:(PI/2), c>;"
      "DEF tlo = MIN:<1, 2>:turned; DEF thi = MAX:<1, 2>:turned;"
      "DEF scaled = STRUCT:<S:<1, 3>:<2, 3>, T:1:1, c>;"
      "DEF slo = MIN:<1, 3>:scaled; DEF shi = MAX:<1, 3>:scaled;");
  EXPECT_EQ(r.text("lo"), "<0, 0, 0>");
  EXPECT_EQ(r.text("hi"), "<5, 1, 1>");
  const Exported row = exported(r.poly("row"));
  EXPECT_NEAR(row.volume, 3.0, 1e-12);
  EXPECT_EQ(row.check.components, 3U);
  // T then R: the rotation about the origin acts first on the cube, then the translation.
  EXPECT_NEAR(r.value("tlo")->sequence()[0]->number(), 9.0, 1e-12);
  EXPECT_NEAR(r.value("thi")->sequence()[0]->number(), 10.0, 1e-12);
  EXPECT_NEAR(r.value("tlo")->sequence()[1]->number(), 0.0, 1e-12);
  EXPECT_NEAR(r.value("thi")->sequence()[1]->number(), 1.0, 1e-12);
  // S then T: the translation by 1 is scaled by 2.
  EXPECT_EQ(r.text("slo"), "<2, 0>");
  EXPECT_EQ(r.text("shi"), "<4, 3>");
}

// A mirror turns cells inside out; the export keeps solids outward.
TEST(PlasmGeometry, MirrorKeepsSolidsOutward) {
  Checked r(
      "DEF c = T:<1, 2, 3>:<1, 2, 3>:(CUBOID:<1, 2, 3>);"
      "DEF m = S:1:-1:c;"
      "DEF holed = CUBOID:<3, 3, 1> - T:<1, 2>:<1, 1>:(CUBOID:<1, 1, 1>);"
      "DEF mh = S:2:-1:holed;"
      "DEF ball = SPHERE:1:<12, 24>; DEF mball = S:3:-1:ball;");
  const Exported m = exported(r.poly("m"));
  EXPECT_NEAR(m.volume, 6.0, 1e-12);
  EXPECT_TRUE(m.check.closed);
  EXPECT_NEAR(m.mesh.bounds().min.x, -2.0, 1e-12);
  const Exported mh = exported(r.poly("mh"));
  EXPECT_NEAR(mh.volume, 8.0, 1e-9);
  EXPECT_TRUE(mh.check.closed);
  // A closed surface from MAP faces out, mirrored or not.
  const Exported ball = exported(r.poly("ball"));
  const Exported mball = exported(r.poly("mball"));
  EXPECT_GT(ball.volume, 4.0);
  EXPECT_NEAR(mball.volume, ball.volume, 1e-9);
}

TEST(PlasmGeometry, EmbedAddsCoordinates) {
  Checked r(
      "DEF sq = CUBOID:<2, 3>; DEF e = EMBED:1:sq; DEF lifted = T:3:5:e;"
      "DEF e2 = EMBED:2:sq;");
  EXPECT_EQ(r.poly("sq")->dim, 2);
  EXPECT_EQ(r.poly("e")->dim, 3);
  EXPECT_EQ(r.poly("e2")->dim, 4);
  const Exported lifted = exported(r.poly("lifted"));
  EXPECT_DOUBLE_EQ(lifted.area, 6.0);
  EXPECT_EQ(lifted.stats.surface_cells, 1U);
  EXPECT_DOUBLE_EQ(lifted.mesh.bounds().min.z, 5.0);
  // In 4D nothing is drawn: the cell is counted as skipped.
  const Exported e2 = exported(r.poly("e2"));
  EXPECT_TRUE(e2.mesh.empty());
  EXPECT_EQ(e2.stats.skipped_cells, 1U);
}

TEST(PlasmGeometry, MeasuresWithAnIndexSequence) {
  Checked r(
      "DEF b = T:<1, 2, 3>:<-1, 2, 10>:(CUBOID:<2, 4, 6>);"
      "DEF sizes = SIZE:<1, 2, 3>:b; DEF lo = MIN:<3, 1>:b; DEF hi = MAX:<2>:b;"
      "DEF mid = MED:<1, 2, 3>:b; DEF one = SIZE:2:b;");
  EXPECT_EQ(r.text("sizes"), "<2, 4, 6>");
  EXPECT_EQ(r.text("lo"), "<10, -1>");
  EXPECT_EQ(r.text("hi"), "<6>");
  EXPECT_EQ(r.text("mid"), "<0, 4, 13>");
  EXPECT_EQ(r.text("one"), "4");
}

TEST(PlasmGeometry, AlignAndPlacements) {
  Checked r(
      "DEF p = CUBOID:<1, 1, 1>; DEF q = CUBOID:<2, 2, 2>;"
      "DEF on = p TOP q; DEF under = p BOTTOM q; DEF before = p LEFT q; DEF after = p RIGHT q;"
      "DEF al = ALIGN:<<1, MAX, MIN>, <2, MED, MED>>:<p, q>;"
      "DEF f (x) = <MIN:<1, 2, 3>:x, MAX:<1, 2, 3>:x>;"
      "DEF t = f:on; DEF b = f:under; DEF l = f:before; DEF rt = f:after; DEF a = f:al;");
  EXPECT_EQ(r.text("t"), "<<-0.5, -0.5, 0>, <1.5, 1.5, 3>>");
  EXPECT_EQ(r.text("b"), "<<-0.5, -0.5, -2>, <1.5, 1.5, 1>>");
  EXPECT_EQ(r.text("l"), "<<-2, 0, 0>, <1, 2, 2>>");
  EXPECT_EQ(r.text("rt"), "<<0, 0, 0>, <3, 2, 2>>");
  EXPECT_EQ(r.text("a"), "<<0, -0.5, 0>, <3, 1.5, 2>>");
  EXPECT_NEAR(exported(r.poly("on")).volume, 9.0, 1e-12);
}

TEST(PlasmGeometry, JoinIsTheConvexHull) {
  Checked r(
      "DEF apex = MKPOL:<<<1, 1, 3>>, <<1>>, <<1>>>;"
      "DEF pyramid = JOIN:<CUBOID:<2, 2>, apex>;"
      "DEF tesseract = JOIN:(CUBOID:<1, 1, 1, 1>);"
      "DEF square = JOIN:(QUOTE:<1, 1> * QUOTE:<1, 1>);");
  const Exported pyramid = exported(r.poly("pyramid"));
  EXPECT_NEAR(pyramid.volume, 4.0, 1e-12);
  EXPECT_EQ(pyramid.mesh.face_count(), 5U);
  EXPECT_EQ(pyramid.mesh.vertex_count(), 5U);
  EXPECT_TRUE(pyramid.check.closed);
  const FlatComplex t = flatten_cells(*r.poly("tesseract"));
  EXPECT_EQ(t.dim, 4);
  ASSERT_EQ(t.cells.size(), 1U);
  EXPECT_EQ(t.cells[0].size(), 16U);
  // The grid's centre and edge midpoints are no vertices of the hull.
  const FlatComplex sq = flatten_cells(*r.poly("square"));
  ASSERT_EQ(sq.cells.size(), 1U);
  EXPECT_EQ(sq.cells[0].size(), 4U);
}

TEST(PlasmGeometry, SkeletonCountsFaces) {
  Checked r(
      "DEF c = CUBOID:<1, 1, 1>; DEF k0 = SKELETON:0:c; DEF k1 = SKELETON:1:c;"
      "DEF k2 = SKELETON:2:c; DEF two = SKELETON:2:(QUOTE:<1, 1> * QUOTE:<1> * QUOTE:<1>);");
  EXPECT_EQ(cell_count(*r.poly("k0")), 8U);
  EXPECT_EQ(cell_count(*r.poly("k1")), 12U);
  EXPECT_EQ(cell_count(*r.poly("k2")), 6U);
  // Two cubes share a square: 11 faces, each once.
  EXPECT_EQ(cell_count(*r.poly("two")), 11U);
  const Exported k2 = exported(r.poly("k2"));
  EXPECT_DOUBLE_EQ(k2.area, 6.0);
  EXPECT_EQ(k2.stats.surface_cells, 6U);
  const Exported k1 = exported(r.poly("k1"));
  EXPECT_TRUE(k1.mesh.empty());
  EXPECT_EQ(k1.stats.skipped_cells, 12U);
}

TEST(PlasmGeometry, OffsetOfASegment) {
  Checked r(
      "DEF seg = MKPOL:<<<0, 0, 0>, <2, 0, 0>>, <<1, 2>>, <<1>>>;"
      "DEF diag = MKPOL:<<<0, 0, 0>, <1, 1, 0>>, <<1, 2>>, <<1>>>;"
      "DEF a = OFFSET:<1, 1, 1>:seg; DEF b = OFFSET:<1, 1, 1>:diag;");
  const Exported a = exported(r.poly("a"));
  EXPECT_NEAR(a.volume, 3.0, 1e-12);
  EXPECT_EQ(a.mesh.vertex_count(), 8U);
  // The Minkowski sum of the diagonal and the unit square is a hexagon of area 3, times 1.
  const Exported b = exported(r.poly("b"));
  EXPECT_NEAR(b.volume, 3.0, 1e-12);
  EXPECT_EQ(b.mesh.vertex_count(), 12U);
  EXPECT_TRUE(b.check.closed);
}

TEST(PlasmGeometry, SplitCells) {
  Checked r(
      "DEF parts = SPLITCELLS:(QUOTE:<1, 1, 1> * QUOTE:<1, 1>);"
      "DEF n = LEN:parts; DEF far = MAX:<1, 2>:(LAST:parts);");
  EXPECT_EQ(r.number("n"), 6.0);
  EXPECT_EQ(r.text("far"), "<3, 2>");
}

TEST(PlasmGeometry, CircleAreaApproachesPiRSquared) {
  double previous = 1;
  for (int n : {8, 16, 64, 256}) {
    Checked r("DEF c = CIRCLE:2:<" + std::to_string(n) + ", 4>;");
    const Exported e = exported(r.poly("c"));
    const double error = std::abs(e.area - kPi * 4) / (kPi * 4);
    EXPECT_LT(error, previous) << n;
    previous = error;
    if (n >= 64) {
      EXPECT_LT(error, 0.01) << n;
    }
    // The centre's collapsed triangles are not exported.
    EXPECT_GT(e.smallest_face, 1e-6) << n;
    EXPECT_EQ(e.stats.skipped_cells, 0U);
  }
}

TEST(PlasmGeometry, SphereAndTorusAreas) {
  Checked r(
      "DEF s = SPHERE:2:<24, 48>; DEF t = TORUS:<0.5, 2>:<24, 48>;"
      "DEF cone = TRUNCONE:<1, 0, 2>:<48, 1>;");
  const Exported s = exported(r.poly("s"));
  EXPECT_NEAR(s.area, 4 * kPi * 4, 4 * kPi * 4 * 0.01);
  EXPECT_GT(s.smallest_face, 1e-9);
  EXPECT_TRUE(s.check.closed);
  EXPECT_NEAR(s.volume, 4.0 / 3 * kPi * 8, 4.0 / 3 * kPi * 8 * 0.02);
  // TORUS:<r1, r2>: a tube of radius r1 around a circle of radius r2.
  const Exported t = exported(r.poly("t"));
  EXPECT_NEAR(t.area, 4 * kPi * kPi * 0.5 * 2, 4 * kPi * kPi * 0.01);
  EXPECT_NEAR(t.mesh.bounds().max.x, 2.5, 1e-9);
  EXPECT_NEAR(t.mesh.bounds().max.z, 0.5, 0.01);
  EXPECT_TRUE(t.check.closed);
  EXPECT_EQ(t.check.euler_characteristic, 0);
  EXPECT_NEAR(t.volume, 2 * kPi * kPi * 2 * 0.25, 2 * kPi * kPi * 2 * 0.25 * 0.02);
  // The cone's side: the apex's collapsed triangles are dropped.
  const Exported cone = exported(r.poly("cone"));
  EXPECT_NEAR(cone.area, kPi * std::sqrt(5.0), kPi * std::sqrt(5.0) * 0.01);
  EXPECT_GT(cone.smallest_face, 1e-9);
}

// A solid half-sphere shell: at the pole cos(PI/2) is 6e-17, not 0, so the simplices there
// collapse only up to rounding; they are dropped all the same, none drawn as a flat face.
TEST(PlasmGeometry, CollapsedSimplicesAtAPoleAreDropped) {
  Checked r(
      "DEF shell = MAP:<S3 * COS~S1 * COS~S2, S3 * COS~S1 * SIN~S2, S3 * SIN~S1>:"
      "(INTERVALS:(PI/2):6 * INTERVALS:(2*PI):8 * (T:1:4.5 ~ QUOTE):<0.5>);");
  const Exported e = exported(r.poly("shell"));
  EXPECT_EQ(e.stats.surface_cells, 0U);
  EXPECT_EQ(e.stats.skipped_cells, 0U);
  EXPECT_TRUE(e.check.closed);
  EXPECT_EQ(e.check.non_manifold_edges, 0U);
  EXPECT_GT(e.smallest_face, 1e-9);
  // Below the hemispherical shell's 2/3 pi (5^3 - 4.5^3): an inscribed polyhedron.
  const double shell = 2.0 / 3 * kPi * (125 - 91.125);
  EXPECT_LT(e.volume, shell);
  EXPECT_GT(e.volume, 0.85 * shell);
}

TEST(PlasmGeometry, MapKeepsOrientationUnderAMirror) {
  Checked r(
      "DEF dom = QUOTE:<1, 1> * QUOTE:<1, 1>;"
      "DEF up = MAP:<S1, S2, K:0>:dom; DEF swapped = MAP:<S2, S1, K:0>:dom;"
      "DEF solid = MAP:<K:0 - S1, S2, S3>:(CUBOID:<1, 2, 3>);");
  // A surface's side follows the domain's orientation: the swapped map faces -z.
  const Exported up = exported(r.poly("up"));
  const Exported swapped = exported(r.poly("swapped"));
  EXPECT_DOUBLE_EQ(up.area, 4.0);
  EXPECT_DOUBLE_EQ(swapped.area, 4.0);
  ASSERT_FALSE(up.mesh.empty());
  ASSERT_FALSE(swapped.mesh.empty());
  EXPECT_GT(kernel::face_normal(up.mesh, 0).z, 0.99);
  EXPECT_LT(kernel::face_normal(swapped.mesh, 0).z, -0.99);
  const Exported solid = exported(r.poly("solid"));
  EXPECT_NEAR(solid.volume, 6.0, 1e-12);
  EXPECT_TRUE(solid.check.closed);
}

TEST(PlasmGeometry, BezierPointValues) {
  Checked r(
      "DEF b = BEZIER:S1:<<0, 0>, <1, 2>, <2, 0>>;"
      "DEF mid = [S1:b, S2:b]:<0.5>; DEF quarter = [S1:b, S2:b]:<0.25>;"
      "DEF ArchSurface (rr,w::isreal) = Bezier:S2:<Circle0, Circle1>"
      " WHERE Circle0 = <K:rr * cos ~ S1, K:rr * sin ~ S1>,"
      " Circle1 = <K:(rr - w) * cos ~ S1, K:(rr - w) * sin ~ S1> END;"
      "DEF arch = ArchSurface:<2, 0.5>;"
      "DEF at = [S1:arch, S2:arch]:<PI/3, 0.5>;"
      "DEF curve = MAP:b:(INTERVALS:1:8);");
  EXPECT_EQ(r.text("mid"), "<1, 1>");
  EXPECT_EQ(r.text("quarter"), "<0.5, 0.75>");
  const Sequence& at = r.value("at")->sequence();
  ASSERT_EQ(at.size(), 2U);
  EXPECT_NEAR(at[0]->number(), 1.75 * std::cos(kPi / 3), 1e-12);
  EXPECT_NEAR(at[1]->number(), 1.75 * std::sin(kPi / 3), 1e-12);
  const PolyPtr curve = r.poly("curve");
  EXPECT_EQ(curve->dim, 2);
  EXPECT_EQ(cell_count(*curve), 8U);
}

TEST(PlasmGeometry, DifferenceWithAThroughHole) {
  Checked r(
      "DEF holed = CUBOID:<3, 3, 3> - T:<1, 2>:<1, 1>:(CUBOID:<1, 1, 3>);"
      "DEF same = DIFFERENCE:<CUBOID:<3, 3, 3>, T:<1, 2>:<1, 1>:(CUBOID:<1, 1, 3>)>;");
  for (const char* name : {"holed", "same"}) {
    const Exported e = exported(r.poly(name));
    EXPECT_NEAR(e.volume, 24.0, 1e-9) << name;
    EXPECT_NEAR(e.area, 6 * 9 - 2 + 4 * 3, 1e-9) << name;
    EXPECT_TRUE(e.check.closed) << name;
    EXPECT_TRUE(e.check.oriented) << name;
    EXPECT_EQ(e.check.non_manifold_edges, 0U) << name;
    EXPECT_EQ(e.check.components, 1U) << name;
    EXPECT_EQ(e.check.euler_characteristic, 0) << name;  // genus 1
  }
}

// A wall with windows through it (right prisms along y: the 2D sections' boolean, extruded) and
// with a blind niche (not through: the 3D boolean) give the same kind of solid.
TEST(PlasmGeometry, WallsWithWindowsAndNiches) {
  Checked r(
      "DEF window (i::IsNum) = T:<1, 2, 3>:<2 * i - 1.5, -1, 1>:(CUBOID:<1, 3, 1.5>);"
      "DEF wall = DIFFERENCE:(CUBOID:<12, 0.5, 4> AL AA:window:(1 .. 5));"
      "DEF niche = CUBOID:<12, 0.5, 4> - T:<1, 2, 3>:<1, 0.2, 1>:(CUBOID:<1, 1, 1.5>);");
  const Exported wall = exported(r.poly("wall"));
  EXPECT_NEAR(wall.volume, 12 * 0.5 * 4 - 5 * 1 * 0.5 * 1.5, 1e-9);
  EXPECT_TRUE(wall.check.closed);
  EXPECT_EQ(wall.check.non_manifold_edges, 0U);
  EXPECT_EQ(wall.check.euler_characteristic, 2 - 2 * 5);  // genus 5
  const Exported niche = exported(r.poly("niche"));
  EXPECT_NEAR(niche.volume, 12 * 0.5 * 4 - 1 * 0.3 * 1.5, 1e-9);
  EXPECT_TRUE(niche.check.closed);
  EXPECT_EQ(niche.check.euler_characteristic, 2);
}

TEST(PlasmGeometry, UnionIntersectionXor) {
  Checked r(
      "DEF a = CUBOID:<2, 2, 2>; DEF b = T:<1, 2, 3>:<1, 1, 1>:a;"
      "DEF touching = CUBOID:<1, 1, 1> + T:1:1:(CUBOID:<1, 1, 1>);"
      "DEF coplanar = UNION:<CUBOID:<2, 2, 1>, T:1:1:(CUBOID:<2, 2, 1>)>;"
      "DEF common = INTERSECTION:<a, b>; DEF both = UNION:<a, b>;"
      "DEF either = XOR:<CUBOID:<2, 1, 1>, T:1:1:(CUBOID:<2, 1, 1>)>;"
      "DEF cavity = XOR:<CUBOID:<3, 3, 3>, T:<1, 2, 3>:<1, 1, 1>:(CUBOID:<1, 1, 1>)>;"
      "DEF grid = QUOTE:<1, 1> * QUOTE:<1> * QUOTE:<1> - T:<1, 2, 3>:<0.5, 0.5, 0.5>:a;");
  const Exported touching = exported(r.poly("touching"));
  EXPECT_NEAR(touching.volume, 2.0, 1e-12);
  EXPECT_EQ(touching.check.components, 1U);
  EXPECT_TRUE(touching.check.closed);
  EXPECT_EQ(touching.check.euler_characteristic, 2);
  EXPECT_NEAR(touching.area, 10.0, 1e-12);
  const Exported coplanar = exported(r.poly("coplanar"));
  EXPECT_NEAR(coplanar.volume, 6.0, 1e-12);
  EXPECT_NEAR(coplanar.area, 2 * 6 + 2 * 3 + 2 * 2, 1e-12);
  EXPECT_TRUE(coplanar.check.closed);
  EXPECT_NEAR(exported(r.poly("common")).volume, 1.0, 1e-12);
  EXPECT_NEAR(exported(r.poly("both")).volume, 15.0, 1e-12);
  EXPECT_NEAR(exported(r.poly("either")).volume, 2.0, 1e-12);
  EXPECT_EQ(exported(r.poly("either")).check.components, 2U);
  const Exported cavity = exported(r.poly("cavity"));
  EXPECT_NEAR(cavity.volume, 26.0, 1e-12);
  EXPECT_EQ(cavity.check.components, 2U);
  EXPECT_TRUE(cavity.check.closed);
  // A complex of several cells is one operand.
  const Exported grid = exported(r.poly("grid"));
  EXPECT_NEAR(grid.volume, 2.0 - 1.5 * 0.5 * 0.5, 1e-12);
  EXPECT_TRUE(grid.check.closed);
}

// Solids of booleans that touch inside one part are marked (non_manifold_edges), not merged; a
// part of one solid, or of solids apart, is not.
TEST(PlasmGeometry, TouchingSolidsInOnePartAreMarked) {
  const std::string text =
      "DEF hole = T:<1, 2>:<0.25, 0.25>:(CUBOID:<0.5, 0.5, 1>);\n"
      "STRUCT:<CUBOID:<1, 1, 1> - hole, T:1:1:(CUBOID:<1, 1, 1> - hole)>;\n"
      "STRUCT:<CUBOID:<1, 1, 1> - hole, T:1:3:(CUBOID:<1, 1, 1> - hole)>;\n";
  const base::Source source("touch.psm", text);
  auto program = parse(source);
  ASSERT_TRUE(program.ok());
  auto out = program_scene(program.value(), source);
  ASSERT_TRUE(out.ok()) << base::render(out.diagnostics().front());
  ASSERT_EQ(out->scene.buildings.size(), 2U);
  EXPECT_EQ(out->stats.non_manifold_parts, 1U);
  const auto& touching = out->scene.buildings[0].parts;
  ASSERT_EQ(touching.size(), 1U);
  ASSERT_TRUE(touching[0].attributes.count("non_manifold_edges"));
  EXPECT_EQ(out->scene.buildings[1].parts[0].attributes.count("non_manifold_edges"), 0U);
}

// Labels: each instance of a top-level DEF below the expression is a part named after it, with
// the path of names above it.
TEST(PlasmGeometry, PartsAreNamedAfterTopLevelDefs) {
  const std::string text =
      "DEF col = CUBOID:<1, 1, 3>;"
      "DEF beam = T:3:3:(CUBOID:<5, 1, 1>);"
      "DEF row = STRUCT:<col, T:1:2, col, T:1:2, col, beam>;"
      "row;";
  const base::Source source("labels.psm", text);
  auto program = parse(source);
  ASSERT_TRUE(program.ok());
  auto out = program_scene(program.value(), source);
  ASSERT_TRUE(out.ok()) << base::render(out.diagnostics().front());
  ASSERT_EQ(out->scene.buildings.size(), 1U);
  const shape::Building& b = out->scene.buildings[0];
  EXPECT_EQ(b.id, "labels-line1");
  int columns = 0;
  int beams = 0;
  for (const shape::Part& part : b.parts) {
    const auto path = part.attributes.find("plasm_path");
    ASSERT_NE(path, part.attributes.end()) << part.name;
    if (part.name == "col") {
      ++columns;
      EXPECT_EQ(shape::to_string(path->second), "row/col");
      EXPECT_NEAR(kernel::volume(part.mesh), 3.0, 1e-12);
    } else if (part.name == "beam") {
      ++beams;
      EXPECT_EQ(shape::to_string(path->second), "row/beam");
    } else {
      ADD_FAILURE() << "unexpected part " << part.name;
    }
  }
  EXPECT_EQ(columns, 3);
  EXPECT_EQ(beams, 1);
}

TEST(PlasmGeometry, PorticoHasTenColumns) {
  const std::filesystem::path file = testing::examples_dir() / "portico.psm";
  const base::Source source(file.filename().string(), testing::read_file(file));
  auto program = parse(source);
  ASSERT_TRUE(program.ok());
  auto out = program_scene(program.value(), source);
  ASSERT_TRUE(out.ok()) << base::render(out.diagnostics().front());
  ASSERT_EQ(out->scene.buildings.size(), 1U);
  std::map<std::string, int> parts;
  for (const shape::Part& part : out->scene.buildings[0].parts) {
    ++parts[part.name];
    if (part.name == "columna") {
      // The WHERE locals above it are on its path.
      EXPECT_EQ(shape::to_string(part.attributes.at("plasm_path")), "Portico/bay/column/columna");
    }
    EXPECT_TRUE(kernel::is_watertight(part.mesh) || part.name == "Arch") << part.name;
  }
  EXPECT_EQ(parts["columna"], 10);
  EXPECT_EQ(parts["Arch"], 5);
  EXPECT_EQ(parts.size(), 2U);
}

}  // namespace
}  // namespace insula::lang::plasm
