// CityEngine's scope and footprint operations spelled in CGA (docs/operations-cityengine.md): one
// derivation per operation, asserting the terminals' scopes and areas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "derive_util.h"
#include "kernel/mesh.h"

namespace insula::lang::cga {
namespace {

using kernel::Vec3;
using testing::compile_text;
using testing::derive_all;
using testing::diagnostics_text;
using testing::rectangle_lot;
using testing::symbol_count;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

Lot polygon_lot(std::vector<kernel::Vec2> ring) {
  Lot lot;
  lot.id = "lot";
  lot.polygons.push_back({std::move(ring), {}});
  return lot;
}

// A w x d lot turned 30 degrees about world Z.
Lot turned_lot(double w, double d) {
  const double c = std::cos(std::numbers::pi / 6);
  const double s = std::sin(std::numbers::pi / 6);
  return polygon_lot({{0, 0}, {w * c, w * s}, {w * c - d * s, w * s + d * c}, {-d * s, d * c}});
}

// Derives `text` on `lot` and returns the single lot's result (failures fail the test).
LotResult derive_one(const std::string& text, const Lot& lot) {
  auto p = compile_text(text);
  if (!p) return {};
  auto r = derive_all(*p, {lot});
  EXPECT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  return std::move(r[0]);
}

// The area of a flat terminal: its outline's, or its scope's for a rectangle.
double flat_area(const LotResult& r, const Terminal& t) {
  const Geometry& g = r.geometry[t.geometry];
  if (g.kind == Geometry::Kind::kMesh && g.outline) return kernel::area(*g.outline);
  return t.scope.size.x * t.scope.size.y;
}

// No file is there: every file function fails as for a missing file.
struct NoFiles final : FileQueries {
  bool exists(const std::string&) const override { return false; }
  std::string search(const std::string&, std::string&) const override { return ""; }
  std::string random(const std::string&, double, std::string&) const override { return ""; }
  std::optional<double> asset_info(const std::string& name, const std::string&,
                                   std::string& error) const override {
    error = "asset '" + name + "' not found";
    return std::nullopt;
  }
  std::optional<double> image_info(const std::string& name, const std::string&,
                                   std::string& error) const override {
    error = "image '" + name + "' not found";
    return std::nullopt;
  }
  std::optional<std::string> read_text(const std::string& path, std::string& error) const override {
    error = "file '" + path + "' not found";
    return std::nullopt;
  }
};

TEST(CityEngineOps, AlignScopeToAxesTurnsTheMassToTheWorld) {
  const LotResult r = derive_one("Lot --> extrude(10) alignScopeToAxes() A\n", turned_lot(20, 5));
  ASSERT_EQ(r.terminals_store.size(), 1U);
  const shape::Scope& s = r.terminals_store[0].scope;
  expect_near(s.x, {1, 0, 0});
  expect_near(s.y, {0, 0, 1});
  EXPECT_NEAR(s.size.y, 10, 1e-9);
  const double c = std::cos(std::numbers::pi / 6);
  EXPECT_NEAR(s.size.x, 20 * c + 5 * 0.5, 1e-9);
  // One axis: y stays up and x keeps the lot's direction.
  const LotResult y = derive_one("Lot --> extrude(10) alignScopeToAxes(y) A\n", turned_lot(20, 5));
  expect_near(y.terminals_store[0].scope.x, {c, 0.5, 0});
  EXPECT_NEAR(y.terminals_store[0].scope.size.x, 20, 1e-9);
}

TEST(CityEngineOps, AlignScopeToGeometryTakesTheLongestEdge) {
  const LotResult r =
      derive_one("Lot --> alignScopeToGeometry(yUp, 0, \"longest\") A\n", rectangle_lot(2, 10));
  ASSERT_EQ(r.terminals_store.size(), 1U);
  expect_near(r.terminals_store[0].scope.size, {10, 2, 0}, 1e-9);
  EXPECT_NEAR(flat_area(r, r.terminals_store[0]), 20, 1e-9);
  // A face index the mass does not have is an error at derivation time.
  auto p = compile_text("Lot --> extrude(3) alignScopeToGeometry(yUp, 9) A\n");
  ASSERT_TRUE(p);
  const auto bad = derive_all(*p, {rectangle_lot(2, 10)});
  EXPECT_NE(diagnostics_text(bad[0]).find(
                "alignScopeToGeometry: face index 9 is out of range (the shape has 6 faces)"),
            std::string::npos)
      << diagnostics_text(bad[0]);
}

TEST(CityEngineOps, RotateScopeRefitsAroundTheUnmovedMass) {
  const LotResult r =
      derive_one("Lot --> extrude(10) rotateScope(0, 45, 0) A\n", rectangle_lot(10, 10));
  const shape::Scope& s = r.terminals_store[0].scope;
  EXPECT_NEAR(s.size.x, 10 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.size.y, 10, 1e-9);
  EXPECT_NEAR(s.volume(), 2000, 1e-6);
}

TEST(CityEngineOps, SetPivotMovesTheOriginToACorner) {
  const LotResult r = derive_one("Lot --> extrude(3) setPivot(xyz, 1) A\n", rectangle_lot(2, 4));
  const shape::Scope& s = r.terminals_store[0].scope;
  // The mass scope is 2 x 3 x 4; corner 1 is far along x, so x and z trade places.
  expect_near(s.size, {4, 3, 2}, 1e-9);
  // The mass's z points from the lot's back edge (y = 4) to its front: the origin is at y = 4.
  expect_near(s.origin, {2, 4, 0}, 1e-9);
}

TEST(CityEngineOps, MirrorKeepsTheScope) {
  const LotResult r = derive_one("Lot --> extrude(2) mirror(true, false, false) A\n",
                                 polygon_lot({{0, 0}, {4, 0}, {0, 2}}));
  const Terminal& t = r.terminals_store[0];
  expect_near(t.scope.size, {4, 2, 2}, 1e-9);
  const Geometry& g = r.geometry[t.geometry];
  ASSERT_TRUE(g.mesh);
  EXPECT_NEAR(kernel::volume(*g.mesh), 8, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*g.mesh));
}

TEST(CityEngineOps, TranslateAndRotateInTheWorldFrame) {
  const LotResult base = derive_one("Lot --> extrude(5) A\n", turned_lot(8, 4));
  const LotResult t =
      derive_one("Lot --> extrude(5) translate(rel, world, 0, 3, 0) A\n", turned_lot(8, 4));
  expect_near(t.terminals_store[0].scope.origin,
              base.terminals_store[0].scope.origin + Vec3{0, 0, 3}, 1e-9);
  const LotResult a =
      derive_one("Lot --> extrude(5) translate(abs, world, 1, 2, 3) A\n", rectangle_lot(8, 4));
  expect_near(a.terminals_store[0].scope.origin, {1, -3, 2}, 1e-9);
  const LotResult r =
      derive_one("Lot --> extrude(5) rotate(rel, world, 0, 90, 0) A\n", rectangle_lot(8, 4));
  expect_near(r.terminals_store[0].scope.x, {0, 1, 0});
  expect_near(r.terminals_store[0].scope.y, {0, 0, 1});
}

TEST(CityEngineOps, ShapeLUOSplitALotIntoBandAndRemainder) {
  const std::string rules = R"(
Lot --> shapeL(3, 2){ shape: A | remainder: B }
)";
  auto p = compile_text(rules);
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "A"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "B"), 1U);
  ASSERT_EQ(r[0].terminals_store.size(), 2U);
  EXPECT_NEAR(flat_area(r[0], r[0].terminals_store[0]), 40, 1e-9);
  EXPECT_NEAR(flat_area(r[0], r[0].terminals_store[1]), 40, 1e-9);

  const LotResult u =
      derive_one("Lot --> shapeU(3, 1, 2){ shape: A | remainder: B }\n", rectangle_lot(10, 8));
  ASSERT_EQ(u.terminals_store.size(), 2U);
  EXPECT_NEAR(flat_area(u, u.terminals_store[0]), 45, 1e-9);
  expect_near(u.terminals_store[1].scope.size, {7, 5, 0}, 1e-9);

  const LotResult o =
      derive_one("Lot --> shapeO(1, 1, 1, 1){ shape: A | remainder: NIL }\n", rectangle_lot(10, 8));
  ASSERT_EQ(o.terminals_store.size(), 1U);
  EXPECT_NEAR(flat_area(o, o.terminals_store[0]), 32, 1e-9);
}

TEST(CityEngineOps, InnerRectangleOfAnLShapedLot) {
  const LotResult r =
      derive_one("Lot --> innerRectangle(scope){ shape: Court | remainder: Rest }\n",
                 polygon_lot({{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}));
  ASSERT_EQ(r.terminals_store.size(), 2U);
  expect_near(r.terminals_store[0].scope.size, {10, 5, 0}, 1e-9);
  EXPECT_NEAR(flat_area(r, r.terminals_store[1]), 20, 1e-9);
}

TEST(CityEngineOps, CleanupGeometryDropsCollinearVerticesAndKeepsTaggedEdges) {
  const Lot lot = polygon_lot({{0, 0}, {5, 0}, {10, 0}, {10, 6}, {0, 6}});
  const LotResult flat = derive_one("Lot --> cleanupGeometry(all, 0) A\n", lot);
  const Geometry& f = flat.geometry[flat.terminals_store[0].geometry];
  ASSERT_TRUE(f.mesh);
  EXPECT_EQ(f.mesh->vertex_count(), 4U);  // the collinear corner at (5, 0) is gone
  EXPECT_NEAR(kernel::surface_area(*f.mesh), 60, 1e-9);
  // The extruded lot's two front walls are separate faces (ids per lot edge): as CityEngine,
  // cleanup keeps the edge between them, and the solid stays closed.
  const LotResult mass = derive_one("Lot --> extrude(4) cleanupGeometry(all, 0.1) A\n", lot);
  const Geometry& g = mass.geometry[mass.terminals_store[0].geometry];
  ASSERT_TRUE(g.mesh);
  EXPECT_EQ(g.mesh->face_count(), 7U);
  EXPECT_TRUE(kernel::is_watertight(*g.mesh));
  EXPECT_NEAR(kernel::volume(*g.mesh), 240, 1e-9);
}

TEST(CityEngineOps, PrimitivesReplaceTheGeometry) {
  const LotResult r = derive_one(
      "Lot --> split(x){ 4: primitiveCube() A | 4: primitiveCylinder(8, 1, 2) B | 4: "
      "primitiveQuad(2, 2) C }\n",
      rectangle_lot(12, 4));
  ASSERT_EQ(r.terminals_store.size(), 3U);
  const Terminal& a = r.terminals_store[0];
  expect_near(a.scope.size, {4, 4, 4}, 1e-9);
  EXPECT_NEAR(kernel::volume(*r.geometry[a.geometry].mesh), 64, 1e-9);
  const Terminal& b = r.terminals_store[1];
  EXPECT_NEAR(kernel::volume(*r.geometry[b.geometry].mesh), 8 * std::sin(std::numbers::pi / 4),
              1e-9);
  const Terminal& c = r.terminals_store[2];
  expect_near(c.scope.size, {2, 2, 0}, 1e-9);
  expect_near(c.scope.origin, {9, 1, 0}, 1e-9);
}

TEST(CityEngineOps, InsertAlongUvOnALot) {
  // Four 3 m tiles of the unit cube along a 12 x 4 m lot, 2 m high along the lot's
  // CityEngine y (its normal).
  const LotResult r = derive_one(
      "version \"2023.0\"\n"
      "Lot --> setupProjection(0, scope.xz, 3, '1) projectUV(0)\n"
      "        insertAlongUV(0, \"builtin:cube\", 2) A\n",
      rectangle_lot(12, 4));
  ASSERT_EQ(r.terminals_store.size(), 1U);
  const Terminal& a = r.terminals_store[0];
  const kernel::Mesh world = shape::mesh_to_world(*r.geometry[a.geometry].mesh, a.scope);
  const kernel::Bounds3 b = world.bounds();
  expect_near(b.min, {0, 0, 0}, 1e-9);
  expect_near(b.max, {12, 4, 2}, 1e-9);
  EXPECT_NEAR(kernel::volume(world), 12 * 4 * 2, 1e-6);
}

TEST(CityEngineOps, SphereConeAndDiskPrimitives) {
  const LotResult r = derive_one(
      "version \"2023.0\"\n"
      "Lot --> split(x){ 4: primitiveSphere(12, 6) A | 4: primitiveCone(6) B | 4: "
      "primitiveDisk(8, 1) C }\n",
      rectangle_lot(12, 4));
  ASSERT_EQ(r.terminals_store.size(), 3U);
  const Terminal& a = r.terminals_store[0];
  expect_near(a.scope.size, {4, 4, 4}, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*r.geometry[a.geometry].mesh));
  const Terminal& b = r.terminals_store[1];
  EXPECT_EQ(r.geometry[b.geometry].mesh->face_count(), 7U);
  const Terminal& c = r.terminals_store[2];
  EXPECT_NEAR(flat_area(r, c), 2 * std::sqrt(2.0), 1e-9);  // an octagon of radius 1
}

TEST(CityEngineOps, AlignScopeToGeometryBBoxTakesTheMinimumRectangle) {
  // A 5 x 20 lot turned by 30 degrees, its first edge the short one: xz puts x along the long
  // side, the normal (CityEngine's y) stays; zx puts CityEngine's z (Insula's -y) there instead.
  for (const auto& [axes, sx, sz] : {std::tuple{"xz", 20.0, 5.0}, std::tuple{"zx", 5.0, 20.0}}) {
    const LotResult r = derive_one(
        std::string("version \"2023.0\"\nLot --> ") + "alignScopeToGeometryBBox(" + axes + ") A\n",
        turned_lot(5, 20));
    ASSERT_EQ(r.terminals_store.size(), 1U);
    const shape::Scope& s = r.terminals_store[0].scope;
    EXPECT_NEAR(s.size.x, sx, 1e-9) << axes;
    EXPECT_NEAR(s.size.y, sz, 1e-9) << axes;
    expect_near(s.z, {0, 0, 1});  // still the lot's normal
  }
}

TEST(CityEngineOps, SetScopeTranslationMovesTheScope) {
  // ce.lib's static model rules place an asset with set(scope.tx, ...): the scope moves in the
  // object frame (x, up, -y of the lot) so that scope.t reads the value.
  auto p = compile_text(
      "version \"2023.0\"\nLot --> s(2, 3, 4) set(scope.tx, 5) set(scope.ty, 1)\n"
      "  set(scope.tz, scope.tz + 2) print(scope.tx) print(scope.ty) A.\n");
  ASSERT_TRUE(p);
  const std::vector<LotResult> r = derive_all(*p, {rectangle_lot(12, 4)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 2U);
  EXPECT_EQ(r[0].prints[0], "test.cga:3: print: 5");
  EXPECT_EQ(r[0].prints[1], "test.cga:3: print: 1");
  const Terminal& a = r[0].terminals_store[0];
  EXPECT_NEAR(a.scope.origin.x, 5, 1e-9);
  EXPECT_NEAR(a.scope.origin.z, 1, 1e-9);
  EXPECT_NEAR(a.scope.origin.y, -2, 1e-9);  // 2 m further along CityEngine's z (Insula's -y)
  EXPECT_NEAR(a.scope.size.x, 2, 1e-9);
}

TEST(CityEngineOps, CompSlopeSelectors) {
  auto p = compile_text(R"(
Lot --> extrude(4) comp(f){ horizontal: H | vertical: V }
H --> roofHip(30) comp(f){ aslant: S | nutant: N | horizontal: B }
)");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 6)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "H"), 2U);  // top and bottom
  EXPECT_EQ(symbol_count(*p, r[0], "V"), 4U);
  // Each hip roof's four slopes face up at 30 degrees: aslant.
  EXPECT_EQ(symbol_count(*p, r[0], "S"), 8U);
  EXPECT_EQ(symbol_count(*p, r[0], "N"), 0U);
}

TEST(CityEngineOps, SplitAreaInItsPositionalForm) {
  // CityEngine's keyed block (`splitArea(x){ 10: A | ~1: B }`) is the reader's; the registry's
  // positional form runs today.
  const LotResult r = derive_one("Lot --> splitArea(x, 10, ~1) A\n", rectangle_lot(10, 4));
  ASSERT_EQ(r.terminals_store.size(), 2U);
  EXPECT_NEAR(flat_area(r, r.terminals_store[0]), 10, 1e-9);
  EXPECT_NEAR(flat_area(r, r.terminals_store[1]), 30, 1e-9);
}

TEST(CityEngineOps, SplitAreaWithKeyedAreasAndRepeats) {
  // 200 m²: 50 m² first, then pieces of about 40 m² fitting the 150 m² left.
  const LotResult r =
      derive_one("version \"2019.0\"\nLot --> splitArea(x) { 50 : A | { ~40 : B }* }\n",
                 rectangle_lot(20, 10));
  ASSERT_GE(r.terminals_store.size(), 3U);
  EXPECT_NEAR(flat_area(r, r.terminals_store[0]), 50, 1e-6);
  double rest = 0;
  for (std::size_t i = 1; i < r.terminals_store.size(); ++i) {
    rest += flat_area(r, r.terminals_store[i]);
    EXPECT_NEAR(flat_area(r, r.terminals_store[i]), flat_area(r, r.terminals_store[1]), 1e-6);
  }
  EXPECT_NEAR(rest, 150, 1e-6);
}

TEST(CityEngineOps, NegativeScaleMirrorsBehindTheOrigin) {
  // s('1, '1, -2) on a 4 m mass: 2 m deep, on the negative side of the scope's z.
  const LotResult r =
      derive_one("version \"2019.0\"\nLot --> extrude(4) s('1, '1, -2) A\n", rectangle_lot(20, 10));
  ASSERT_EQ(r.terminals_store.size(), 1U);
  const Terminal& t = r.terminals_store[0];
  EXPECT_NEAR(t.scope.size.z, 2, 1e-9);
  const kernel::Mesh& mesh = *r.geometry[t.geometry].mesh;
  double lo = 1e9;
  double hi = -1e9;
  for (const Vec3& p : mesh.positions()) {
    const Vec3 w = t.scope.to_world(p);
    lo = std::min(lo, w.y);
    hi = std::max(hi, w.y);
  }
  // The mass's z runs south from y = 10: mirrored, the slab lies north of it, y in [10, 12].
  EXPECT_NEAR(lo, 10, 1e-9);
  EXPECT_NEAR(hi, 12, 1e-9);
  EXPECT_NEAR(std::fabs(kernel::volume(mesh)), 160, 1e-9);
}

TEST(CityEngineOps, SetbackByWorldDirection) {
  // A 3 m strip along the south edge only (a lot whose first edge runs east, so south is its
  // front), and what is left.
  const LotResult r =
      derive_one("version \"2019.0\"\nLot --> setback(3) { world.south : S | remainder : R }\n",
                 rectangle_lot(20, 10));
  ASSERT_EQ(r.terminals_store.size(), 2U);
  EXPECT_NEAR(flat_area(r, r.terminals_store[0]), 60, 1e-6);
  EXPECT_NEAR(flat_area(r, r.terminals_store[1]), 140, 1e-6);
}

TEST(CityEngineOps, SetbackStripsByDirectionDoNotOverlap) {
  // South then west on a 20 x 10 lot: the south strip takes the corner, the west strip the rest
  // of its edge, and the pieces add up to the lot (they overlapped by 2 x 2 m before).
  const LotResult r = derive_one(
      "version \"2019.0\"\nLot --> setback(2) { world.south : S | world.west : W | remainder : R "
      "}\n",
      rectangle_lot(20, 10));
  ASSERT_EQ(r.terminals_store.size(), 3U);
  EXPECT_NEAR(flat_area(r, r.terminals_store[0]), 40, 1e-6);
  EXPECT_NEAR(flat_area(r, r.terminals_store[1]), 2 * 8, 1e-6);
  EXPECT_NEAR(flat_area(r, r.terminals_store[2]), 18 * 8, 1e-6);
}

TEST(CityEngineOps, MissingFilesAndDivisionByZeroDoNotStopTheModel) {
  // assetInfo(a, tx) takes tx as a word; a missing asset is 0 with a warning, and CityEngine's
  // IEEE division makes 0 / 0 NaN (isnan) rather than an error.
  auto p = compile_text(
      "version \"2019.0\"\n"
      "Lot --> report(\"x\", assetInfo(\"tree.obj\", tx)) report(\"nan\", isnan(0 / scope.sy))\n"
      "  report(\"inf\", isinf(ln(scope.sy))) report(\"root\", isnan(sqrt(scope.sy - 1)))\n"
      "  extrude(3) A.\n");
  ASSERT_TRUE(p);
  NoFiles files;
  DeriveOptions options;
  options.files = &files;
  const auto r = derive_all(*p, {rectangle_lot(10, 10)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(r[0].reports.at("x").sum, 0);
  EXPECT_EQ(r[0].reports.at("nan").sum, 1);
  EXPECT_EQ(r[0].reports.at("inf").sum, 1);  // ln(0): IEEE math, as CityEngine's
  EXPECT_EQ(r[0].reports.at("root").sum, 1);
  EXPECT_EQ(symbol_count(*p, r[0], "A"), 1U);
  EXPECT_NE(diagnostics_text(r[0]).find("warning[CGA604]: 'tree.obj' not found: 0"),
            std::string::npos)
      << diagnostics_text(r[0]);
}

// Three images: a square, a wide and a tall one.
struct ImageFiles final : FileQueries {
  bool exists(const std::string&) const override { return true; }
  std::string search(const std::string&, std::string&) const override {
    return "a.png;b.png;c.png;";
  }
  std::string random(const std::string&, double, std::string&) const override { return ""; }
  std::optional<double> asset_info(const std::string&, const std::string&,
                                   std::string&) const override {
    return std::nullopt;
  }
  std::optional<double> image_info(const std::string& name, const std::string& key,
                                   std::string&) const override {
    const double w = name == "b.png" ? 200 : 100;
    const double h = name == "c.png" ? 200 : 100;
    return key == "sx" ? w : h;
  }
  std::optional<std::string> read_text(const std::string&, std::string&) const override {
    return std::nullopt;
  }
};

TEST(CityEngineOps, ImagesByRatio) {
  // A 20 x 10 lot: along x over z (CityEngine's lot axes) the wide image fits best, the tall
  // one worst.
  auto p = compile_text(
      "version \"2019.0\"\nLot --> print(imagesSortRatio(\"a.png;b.png;c.png\", xz)) "
      "print(imageBestRatio(\"*.png\", xz)) print(imageBestRatio(\"*.png\", zx)) X.\n");
  ASSERT_TRUE(p);
  ImageFiles files;
  DeriveOptions options;
  options.files = &files;
  const auto r = derive_all(*p, {rectangle_lot(20, 10)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 3U);
  EXPECT_EQ(r[0].prints[0], "test.cga:2: print: b.png;a.png;c.png;");
  EXPECT_EQ(r[0].prints[1], "test.cga:2: print: b.png");
  EXPECT_EQ(r[0].prints[2], "test.cga:2: print: c.png");
}

// Five assets of known bounding boxes (sx, sy, sz); "*.obj" finds them all, anything else none.
struct AssetFiles final : FileQueries {
  bool exists(const std::string&) const override { return true; }
  std::string search(const std::string& query, std::string&) const override {
    return query == "*.obj" ? "a.obj;b.obj;c.obj;d.obj;e.obj;" : "";
  }
  std::string random(const std::string&, double, std::string&) const override { return ""; }
  std::optional<double> asset_info(const std::string& name, const std::string& key,
                                   std::string&) const override {
    struct Box {
      const char* name;
      double x, y, z;
    };
    static constexpr Box kBoxes[] = {{"a.obj", 1, 1, 1},
                                     {"b.obj", 4, 1, 2},
                                     {"c.obj", 10, 3, 5},
                                     {"d.obj", 2, 2, 8},
                                     {"e.obj", 22, 3, 10}};
    for (const Box& b : kBoxes) {
      if (name != b.name) continue;
      if (key == "sx") return b.x;
      if (key == "sy") return b.y;
      if (key == "sz") return b.z;
      return 0.0;
    }
    return std::nullopt;  // not found
  }
  std::optional<double> image_info(const std::string&, const std::string&,
                                   std::string&) const override {
    return std::nullopt;
  }
  std::optional<std::string> read_text(const std::string&, std::string&) const override {
    return std::nullopt;
  }
};

LotResult derive_assets(const std::string& rules, std::uint64_t seed = 0,
                        const std::string& lot = "extrude(3) Mass") {
  auto p = compile_text("version \"2019.0\"\nLot --> " + lot + "\nMass --> " + rules + " X.\n");
  EXPECT_TRUE(p);
  if (!p) return {};
  AssetFiles files;
  DeriveOptions options;
  options.files = &files;
  options.seed = seed;
  std::vector<LotResult> results = derive_all(*p, {rectangle_lot(20, 10)}, options);
  return std::move(results[0]);
}

std::vector<std::string> printed(const LotResult& r) {
  std::vector<std::string> out;
  for (const std::string& line : r.prints) {
    const std::size_t at = line.find("print:") + 6;  // "print: " and the text, "print:" if none
    out.push_back(at < line.size() ? line.substr(at + 1) : std::string());
  }
  return out;
}

// The mass's scope is 20 x 3 x 10. Per axis the scaling an asset needs, ln(scope / asset): by
// size the largest (then the sum) ranks, by ratio the spread of those (max - min).
TEST(CityEngineOps, AssetsSortSizeAndRatio) {
  const LotResult r = derive_assets(
      "print(scope.sx) print(scope.sy) print(scope.sz) "
      "print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", xyz, 0)) "
      "print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", y, 0)) "
      "print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", xz, 0.1)) "
      "print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", xz, 0.05)) "
      "print(assetsSortSize(\"zz.obj;c.obj;a.obj;\", x, 0)) "
      "print(assetsSortRatio(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", xz)) "
      "print(assetsSortRatio(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", zx)) "
      "print(assetsSortRatio(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", \"xyz\")) "
      "print(assetsSortRatio([\"a.obj\", \"b.obj\", \"d.obj\"], xz))");
  ASSERT_TRUE(r.ok) << diagnostics_text(r);
  EXPECT_EQ(printed(r), (std::vector<std::string>{
                            "20", "3", "10", "e.obj;c.obj;b.obj;d.obj;a.obj;",
                            "c.obj;e.obj;d.obj;a.obj;b.obj;", "e.obj;", "", "c.obj;a.obj;",
                            "b.obj;c.obj;e.obj;a.obj;d.obj;", "b.obj;c.obj;e.obj;a.obj;d.obj;",
                            "e.obj;b.obj;c.obj;a.obj;d.obj;", "(3)[b.obj,a.obj,d.obj]"}));
}

// On the flat lot (scope 20 x 0 x 10) y does not count, as i() keeps an asset's size where the
// scope's is 0.
TEST(CityEngineOps, AssetsOnAFlatScope) {
  const LotResult r = derive_assets(
      "print(scope.sy) print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", y, 0)) "
      "print(assetsSortSize(\"a.obj;b.obj;c.obj;d.obj;e.obj;\", xyz, 0)) "
      "print(assetsSortRatio(\"d.obj;c.obj;b.obj;\", xyz))",
      0, "Mass");
  ASSERT_TRUE(r.ok) << diagnostics_text(r);
  EXPECT_EQ(printed(r),
            (std::vector<std::string>{"0", "a.obj;b.obj;c.obj;d.obj;e.obj;",
                                      "e.obj;c.obj;b.obj;d.obj;a.obj;", "c.obj;b.obj;d.obj;"}));
}

TEST(CityEngineOps, AssetBestApproxAndFit) {
  const LotResult r = derive_assets(
      "print(assetBestSize(\"*.obj\", \"xyz\")) print(assetBestSize(\"*.obj\", y)) "
      "print(assetBestRatio(\"*.obj\", \"xz\")) print(assetBestRatio(\"*.obj\", \"xyz\")) "
      "print(assetApproxRatio(\"*.obj\", \"xz\", 1)) print(assetApproxSize(\"*.obj\", \"xyz\", 0)) "
      "print(assetBestSize(\"*.png\", \"xyz\")) print(assetFitSize(\"*.obj\", \"xz\", 0.01))");
  ASSERT_TRUE(r.ok) << diagnostics_text(r);
  EXPECT_EQ(printed(r), (std::vector<std::string>{"e.obj", "c.obj", "b.obj", "e.obj", "b.obj",
                                                  "e.obj", "", ""}));

  // One of the n best, from the shape's generator: the same seed the same picks.
  std::string many;
  for (int i = 0; i < 12; ++i) {
    many += "print(assetApproxRatio(\"*.obj\", \"xz\", 2)) ";
    many += "print(assetApproxSize(\"*.obj\", \"xyz\", 3)) ";
    many += "print(assetFitSize(\"*.obj\", \"xz\", 1)) ";
  }
  const LotResult first = derive_assets(many, 7);
  ASSERT_TRUE(first.ok) << diagnostics_text(first);
  const std::vector<std::string> picks = printed(first);
  ASSERT_EQ(picks.size(), 36U);
  std::set<std::string> ratio2, size3, fit;
  for (std::size_t i = 0; i < picks.size(); i += 3) {
    ratio2.insert(picks[i]);
    size3.insert(picks[i + 1]);
    fit.insert(picks[i + 2]);
  }
  EXPECT_EQ(ratio2, (std::set<std::string>{"b.obj", "c.obj"}));
  EXPECT_EQ(size3, (std::set<std::string>{"e.obj", "c.obj", "b.obj"}));
  EXPECT_EQ(fit, (std::set<std::string>{"c.obj", "e.obj"}));  // scalings within [0, 2]
  EXPECT_EQ(printed(derive_assets(many, 7)), picks);
  EXPECT_NE(printed(derive_assets(many, 8)), picks);
}

// A wrong axes selector is an error at the call: the derivation stops (the CLI exits 1).
TEST(CityEngineOps, AssetAxesAreChecked) {
  for (const char* call :
       {"assetsSortSize(\"a.obj;\", xw, 0)", "assetBestSize(\"*.obj\", \"xx\")",
        "assetBestRatio(\"*.obj\", \"x\")", "assetApproxRatio(\"*.obj\", \"xyzx\", 2)",
        "assetsSortRatio(\"a.obj;\", \"\")"}) {
    const LotResult r = derive_assets(std::string("print(") + call + ")");
    EXPECT_FALSE(r.ok) << call;
    const std::string text = diagnostics_text(r);
    EXPECT_NE(text.find("test.cga:3:"), std::string::npos) << text;
    EXPECT_NE(text.find("error[CGA603]: the axes of an asset "), std::string::npos) << text;
  }
}

TEST(CityEngineOps, ConvexifyAndTrim) {
  auto p = compile_text("Lot --> convexify() extrude(3) trim() A\n");
  ASSERT_TRUE(p);
  const auto r =
      derive_all(*p, {polygon_lot({{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}})});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "A"), 2U);
  double volume = 0;
  for (std::size_t i = 0; i < r[0].terminals_store.size(); ++i) {
    const Geometry& g = r[0].geometry[r[0].terminals_store[i].geometry];
    ASSERT_TRUE(g.mesh);
    EXPECT_TRUE(kernel::is_watertight(*g.mesh));
    volume += kernel::volume(*g.mesh);
  }
  EXPECT_NEAR(volume, 210, 1e-9);
  EXPECT_NE(diagnostics_text(r[0]).find(
                "trim: trim planes are not made in Insula: trim() leaves the shape unchanged"),
            std::string::npos)
      << diagnostics_text(r[0]);
}

// CityEngine's scatter (docs/operations-cityengine.md, "scatter"): point shapes fed to the block,
// the enum words checked as the registry's choices.
TEST(CityEngineOps, ScatterFeedsPointShapesToItsBlock) {
  const std::string head = "version \"2023.0\"\n";
  const LotResult r = derive_one(head +
                                     "Lot --> scatter(surface, 20, uniform) { Tree }\n"
                                     "Tree --> i(\"cube\")\n",
                                 rectangle_lot(20, 10));
  ASSERT_EQ(r.terminals_store.size(), 20U);
  for (std::size_t k = 0; k < r.terminals_store.size(); ++k) {
    const Terminal& t = r.terminals_store[k];
    EXPECT_TRUE(r.geometry[t.geometry].mesh);  // the inserted cube
    EXPECT_NEAR(t.scope.origin.z, 0, 1e-9);
    EXPECT_GE(t.scope.origin.x, -1e-9);
    EXPECT_LE(t.scope.origin.x, 20 + 1e-9);
    EXPECT_GE(t.scope.origin.y, -1e-9);
    EXPECT_LE(t.scope.origin.y, 10 + 1e-9);
    expect_near(t.scope.y, {0, 0, 1});  // on a surface: y the normal, so the cube stands up
    expect_near(t.scope.size, {1, 1, 1});
  }
  // gaussian with CityEngine's mean and relative deviation: clustered on the left side.
  const LotResult g = derive_one(
      head + "Lot --> scatter(surface, 30, gaussian, left, '0.1) { P }\n", rectangle_lot(20, 10));
  ASSERT_EQ(g.terminals_store.size(), 30U);
  double mean_x = 0;
  for (std::size_t k = 0; k < 30; ++k) mean_x += g.terminals_store[k].scope.origin.x / 30;
  EXPECT_LT(mean_x, 4);
  // volume in an extruded lot, scope on the lot.
  const LotResult v = derive_one(head + "Lot --> extrude(6) scatter(volume, 25, uniform) { P }\n",
                                 rectangle_lot(20, 10));
  ASSERT_EQ(v.terminals_store.size(), 25U);
  for (std::size_t k = 0; k < v.terminals_store.size(); ++k) {
    const Terminal& t = v.terminals_store[k];
    EXPECT_GT(t.scope.origin.z, 0);
    EXPECT_LT(t.scope.origin.z, 6);
  }
  const LotResult s =
      derive_one(head + "Lot --> scatter(scope, 5, uniform) { P }\n", rectangle_lot(20, 10));
  EXPECT_EQ(s.terminals_store.size(), 5U);
  const LotResult none =
      derive_one(head + "Lot --> scatter(surface, 0, uniform) { P }\n", rectangle_lot(20, 10));
  EXPECT_EQ(none.terminals_store.size(), 0U);
}

// CityEngine's envelope (docs/operations-cityengine.md, "envelope"): `world.up` is the registry's
// enum choice; the 4-argument form slopes every side, Esri's Candler form gives side pairs.
TEST(CityEngineOps, EnvelopeErectsASlopedVolumeOverTheLot) {
  const std::string head = "version \"2023.0\"\n";
  const LotResult r =
      derive_one(head + "Lot --> envelope(world.up, 10, 6, 45) Mass\n", rectangle_lot(20, 10));
  ASSERT_EQ(r.terminals_store.size(), 1U);
  const Terminal& t = r.terminals_store[0];
  const kernel::Mesh& m = *r.geometry[t.geometry].mesh;
  EXPECT_TRUE(kernel::is_watertight(m));
  // 6 * 200 + the slopes up to the flat top at 10 (tests/shape/envelope_test.cc).
  EXPECT_NEAR(kernel::volume(m), 1200 + 1216.0 / 3, 1e-4);
  EXPECT_NEAR(t.scope.size.y, 10, 1e-9);
  const LotResult candler =
      derive_one(head + "Lot --> envelope(world.up, 0.6, 0.45, 45, 0.45, 45, 0.45, 45) Mass\n",
                 rectangle_lot(20, 10));
  ASSERT_EQ(candler.terminals_store.size(), 1U);
  const kernel::Mesh& c = *candler.geometry[candler.terminals_store[0].geometry].mesh;
  EXPECT_TRUE(kernel::is_watertight(c));
  EXPECT_NEAR(kernel::volume(c), 0.45 * 200 + 200 * 0.15 - 30 * 0.0225 + 4 * 0.003375 / 3, 1e-4);
}

TEST(CityEngineOps, ScatterRepeatsWithTheSeed) {
  auto p = compile_text("version \"2023.0\"\nLot --> scatter(surface, 10, uniform) { P }\n");
  ASSERT_TRUE(p);
  const auto origins = [&](std::uint64_t seed) {
    DeriveOptions options;
    options.seed = seed;
    const auto r = derive_all(*p, {rectangle_lot(20, 10)}, options);
    std::vector<double> out;
    for (std::size_t k = 0; k < r[0].terminals_store.size(); ++k) {
      out.push_back(r[0].terminals_store[k].scope.origin.x);
    }
    return out;
  };
  EXPECT_EQ(origins(1), origins(1));
  EXPECT_NE(origins(1), origins(2));
  EXPECT_EQ(origins(1).size(), 10U);
}

TEST(CityEngineOps, ScatterChecksItsWords) {
  const base::Source source("bad.cga",
                            "version \"2023.0\"\nLot --> scatter(surfac, 3, uniform) { P }\n");
  base::Result<Grammar> grammar = parse(source);
  ASSERT_TRUE(grammar.ok());
  const auto program = compile(grammar.value(), source, {});
  ASSERT_FALSE(program.ok());
  EXPECT_NE(
      base::render(program.diagnostics().front()).find("must be one of surface, volume, scope"),
      std::string::npos)
      << base::render(program.diagnostics().front());
}

}  // namespace
}  // namespace insula::lang::cga
