// io::read_geojson: accepted inputs, attributes, ids, origin shift and round trip, CRS, repair
// policy, and the bad-input catalog in tests/data/bad (one file per case, exact first line).
#include "io/geojson_reader.h"

#include "kernel/skeleton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace insula::io {
namespace {

using base::Diagnostic;
using base::Severity;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The first line of the rendering: `file:line:col: severity[CODE]: message`.
std::string headline(const Diagnostic& d) {
  const std::string text = base::render(d);
  return text.substr(0, text.find('\n'));
}

std::vector<std::string> headlines(const std::vector<Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diagnostics) out.push_back(headline(d));
  return out;
}

std::size_t count_code(const std::vector<Diagnostic>& diagnostics, const std::string& code) {
  return static_cast<std::size_t>(std::count_if(
      diagnostics.begin(), diagnostics.end(), [&](const Diagnostic& d) { return d.code == code; }));
}

std::string square(double x, double y, double w, double h) {
  std::ostringstream s;
  s.precision(17);
  const double xs[] = {x, x + w, x + w, x, x};
  const double ys[] = {y, y, y + h, y + h, y};
  s << '[';
  for (int i = 0; i < 5; ++i) s << (i ? ", [" : "[") << xs[i] << ", " << ys[i] << ']';
  s << ']';
  return s.str();
}

std::string feature(const std::string& id_member, const std::string& properties,
                    const std::string& geometry) {
  return R"({"type": "Feature", )" + id_member + R"("properties": )" + properties +
         R"(, "geometry": )" + geometry + "}";
}

std::string polygon(const std::string& rings) {
  return R"({"type": "Polygon", "coordinates": [)" + rings + "]}";
}

std::string collection(const std::vector<std::string>& features, const std::string& extra = "") {
  std::string out = R"({"type": "FeatureCollection", )" + extra + R"("features": [)";
  for (std::size_t i = 0; i < features.size(); ++i) out += (i ? ",\n" : "\n") + features[i];
  return out + "\n]}\n";
}

base::Result<FootprintSet> read(const std::string& text, const GeoJsonOptions& options = {}) {
  return read_geojson(text, "test.geojson", options);
}

// ---- Accepted input ---------------------------------------------------------------------------

TEST(GeoJsonReader, FeatureCollectionWithHoleGivesNormalizedPolygon) {
  // Outer ring clockwise and hole counter-clockwise (GeoJSON 2008 files do this): both flipped.
  const std::string text = collection({feature(
      R"("id": "courtyard", )", R"({"height": 12})",
      polygon("[[0, 0], [0, 20], [30, 20], [30, 0], [0, 0]], [[10, 5], [20, 5], [20, 15], [10, "
              "15], [10, 5]]"))});
  const auto result = read(text);
  ASSERT_TRUE(result.ok()) << headlines(result.diagnostics()).front();
  EXPECT_TRUE(result.diagnostics().empty());
  ASSERT_EQ(result->footprints.size(), 1u);
  const Footprint& f = result->footprints[0];
  EXPECT_EQ(f.id, "courtyard");
  ASSERT_EQ(f.polygons.size(), 1u);
  const kernel::Polygon& p = f.polygons[0];
  EXPECT_EQ(p.outer.size(), 4u);  // closing position dropped
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_GT(kernel::signed_area(p.outer), 0);
  EXPECT_LT(kernel::signed_area(p.holes[0]), 0);
  EXPECT_DOUBLE_EQ(kernel::area(p), 600.0 - 100.0);
  EXPECT_EQ(result->origin, (kernel::Vec3{0, 0, 0}));
  EXPECT_EQ(result->crs, "");
}

TEST(GeoJsonReader, MultiPolygonBecomesOneFootprintWithSeveralPolygons) {
  const std::string text = feature("", R"({"name": "twin"})",
                                   R"({"type": "MultiPolygon", "coordinates": [[)" +
                                       square(0, 0, 10, 10) + "], [" + square(20, 0, 5, 4) + "]]}");
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->footprints.size(), 1u);
  EXPECT_EQ(result->footprints[0].id, "twin");  // from properties.name
  ASSERT_EQ(result->footprints[0].polygons.size(), 2u);
  EXPECT_DOUBLE_EQ(kernel::area(result->footprints[0].polygons[0]), 100.0);
  EXPECT_DOUBLE_EQ(kernel::area(result->footprints[0].polygons[1]), 20.0);
}

TEST(GeoJsonReader, BareGeometriesAreFeatureZero) {
  const auto poly = read(polygon(square(0, 0, 3, 2)));
  ASSERT_TRUE(poly.ok());
  ASSERT_EQ(poly->footprints.size(), 1u);
  EXPECT_EQ(poly->footprints[0].id, "feature-0");
  EXPECT_TRUE(poly->footprints[0].properties.empty());
  const auto multi =
      read(R"({"type": "MultiPolygon", "coordinates": [[)" + square(0, 0, 3, 2) + "]]}");
  ASSERT_TRUE(multi.ok());
  EXPECT_DOUBLE_EQ(kernel::area(multi->footprints[0].polygons[0]), 6.0);
}

TEST(GeoJsonReader, PropertiesBecomeTypedAttributes) {
  const std::string text =
      feature(R"("id": 17, )",
              R"({"height": 9.5, "levels": 3, "big": 12345678901234, "listed": true, "name": "Hall",
          "note": null, "tags": {"a": [1, 2.5, "x"], "b": null}, "list": [true, false]})",
              polygon(square(0, 0, 10, 10)));
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  const Footprint& f = result->footprints.at(0);
  EXPECT_EQ(f.id, "17");  // numeric id as text
  const shape::AttributeMap a = f.properties.map();
  EXPECT_EQ(std::get<double>(a.at("height")), 9.5);
  EXPECT_EQ(std::get<double>(a.at("levels")), 3.0);
  EXPECT_EQ(std::get<double>(a.at("big")), 12345678901234.0);
  EXPECT_EQ(std::get<bool>(a.at("listed")), true);
  EXPECT_EQ(std::get<std::string>(a.at("name")), "Hall");
  EXPECT_TRUE(shape::is_null(a.at("note")));
  EXPECT_EQ(std::get<std::string>(a.at("tags")), R"({"a":[1,2.5,"x"],"b":null})");
  EXPECT_EQ(std::get<std::string>(a.at("list")), "[true,false]");
  EXPECT_EQ(a.size(), 8u);
}

TEST(GeoJsonReader, IdsComeFromIdMemberThenPropertiesThenIndex) {
  const std::string text = collection({
      feature(R"("id": "m", )", R"({"id": "ignored", "name": "ignored"})",
              polygon(square(0, 0, 1, 1))),
      feature("", R"({"id": 42, "name": "ignored"})", polygon(square(2, 0, 1, 1))),
      feature("", R"({"name": "Tower"})", polygon(square(4, 0, 1, 1))),
      feature("", "null", polygon(square(6, 0, 1, 1))),
  });
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  std::vector<std::string> ids;
  for (const Footprint& f : result->footprints) ids.push_back(f.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"m", "42", "Tower", "feature-3"}));
  EXPECT_EQ(result->footprints[3].feature_index, 3u);
}

// Integer ids keep every digit (through a double, 12345678901234567890 became ...7168 and its
// neighbour clashed with it); an empty id is said to be empty.
TEST(GeoJsonReader, IntegerIdsAreExactAndAnEmptyIdIsNamed) {
  const std::string text = collection({
      feature(R"("id": 12345678901234567890, )", "{}", polygon(square(0, 0, 1, 1))),
      feature(R"("id": 12345678901234567891, )", "{}", polygon(square(2, 0, 1, 1))),
      feature(R"("id": -9007199254740993, )", "{}", polygon(square(4, 0, 1, 1))),
      feature(R"("id": "", )", "{}", polygon(square(6, 0, 1, 1))),
  });
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  std::vector<std::string> ids;
  for (const Footprint& f : result->footprints) ids.push_back(f.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"12345678901234567890", "12345678901234567891",
                                           "-9007199254740993", "feature-3"}));
  const std::vector<std::string> lines = headlines(result.diagnostics());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("warning[GEO018]: feature 3: \"id\" is an empty string; ignored"),
            std::string::npos)
      << lines[0];
}

// --id-attr: a register's id column names the building wherever the feature has it.
TEST(GeoJsonReader, IdPropertyNamesTheBuildingsThatHaveIt) {
  const std::string text = collection({
      feature(R"("id": "m", )", R"({"identificatiebagpnd": "0503100000017303"})",
              polygon(square(0, 0, 1, 1))),
      feature("", R"({"identificatiebagpnd": 503100000018603})", polygon(square(2, 0, 1, 1))),
      feature("", R"({"identificatiebagpnd": null, "name": "Tower"})", polygon(square(4, 0, 1, 1))),
      feature("", R"({"identificatiebagpnd": ""})", polygon(square(6, 0, 1, 1))),
  });
  GeoJsonOptions options;
  options.id_property = "identificatiebagpnd";
  const auto result = read(text, options);
  ASSERT_TRUE(result.ok());
  std::vector<std::string> ids;
  for (const Footprint& f : result->footprints) ids.push_back(f.id);
  EXPECT_EQ(
      ids, (std::vector<std::string>{"0503100000017303", "503100000018603", "Tower", "feature-3"}));
}

TEST(GeoJsonReader, DuplicateIdsAreRenamedInFileOrderAvoidingLaterIds) {
  const std::string text = collection({
      feature(R"("id": "b7", )", "{}", polygon(square(0, 0, 1, 1))),
      feature(R"("id": "b7", )", "{}", polygon(square(2, 0, 1, 1))),
      feature(R"("id": "b7-2", )", "{}", polygon(square(4, 0, 1, 1))),
      feature(R"("id": "b7", )", "{}", polygon(square(6, 0, 1, 1))),
  });
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  std::vector<std::string> ids;
  for (const Footprint& f : result->footprints) ids.push_back(f.id);
  // "b7-2" is taken by feature 2 itself, so feature 1 becomes "b7-3" and feature 3 "b7-4".
  EXPECT_EQ(ids, (std::vector<std::string>{"b7", "b7-3", "b7-2", "b7-4"}));
  EXPECT_EQ(count_code(result.diagnostics(), "GEO019"), 2u);
  EXPECT_EQ(headline(result.diagnostics()[0]),
            R"(test.geojson:3:27: warning[GEO019]: feature 1 (id "b7"): id "b7" is already used )"
            R"(by feature 0; renamed to "b7-3")");
}

TEST(GeoJsonReader, NonPolygonFeaturesAreSkippedWithWarningsAndIndicesKept) {
  const std::string text = collection({
      feature(R"("id": "road", )", "{}",
              R"({"type": "LineString", "coordinates": [[0, 0], [5, 5]]})"),
      feature(R"("id": "hall", )", "{}", polygon(square(0, 0, 8, 6))),
      feature("", "{}", "null"),
  });
  const auto result = read(text);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->footprints.size(), 1u);
  EXPECT_EQ(result->footprints[0].id, "hall");
  EXPECT_EQ(result->footprints[0].feature_index, 1u);
  EXPECT_EQ(headlines(result.diagnostics()),
            (std::vector<std::string>{
                "test.geojson:2:74: warning[GEO017]: feature 0 (id \"road\"): geometry type "
                "LineString is not a polygon; skipped",
                "test.geojson:4:51: warning[GEO017]: feature 2: geometry is null; skipped"}));
}

// A GeometryCollection's Polygons and MultiPolygons are one MultiPolygon's polygons, numbered
// across its members; other members are left out with a warning.
TEST(GeoJsonReader, GeometryCollectionPolygonsAreReadAsAMultiPolygon) {
  const std::string members = R"({"type": "GeometryCollection", "geometries": [)" +
                              polygon(square(0, 0, 8, 6)) +
                              R"(, {"type": "Point", "coordinates": [1, 1]},
{"type": "MultiPolygon", "coordinates": [[)" +
                              square(20, 0, 5, 5) + "], [" + square(30, 0, 5, 5) + "]]}]}";
  const auto result = read(collection({feature(R"("id": "gc", )", "{}", members)}));
  ASSERT_TRUE(result.ok()) << headline(result.diagnostics().front());
  ASSERT_EQ(result->footprints.size(), 1u);
  ASSERT_EQ(result->footprints[0].polygons.size(), 3u);
  EXPECT_DOUBLE_EQ(kernel::area(result->footprints[0].polygons[2]), 25.0);
  EXPECT_EQ(headlines(result.diagnostics()),
            (std::vector<std::string>{"test.geojson:2:198: warning[GEO017]: feature 0 (id \"gc\"): "
                                      "GeometryCollection member 1 is a Point; left out"}));
  // A bad ring in a member is reported where it is, as "polygon K" across the members.
  const std::string bad =
      R"({"type": "GeometryCollection", "geometries": [)" + polygon(square(0, 0, 8, 6)) + R"(,
{"type": "Polygon", "coordinates": [[[20, 0], [30, 10], [30, 0], [20, 10], [20, 0]]]}]})";
  const auto bow_tie = read(collection({feature("", "{}", bad)}));
  ASSERT_FALSE(bow_tie.ok());
  EXPECT_EQ(headline(bow_tie.diagnostics().front()).substr(0, 69),
            "test.geojson:3:38: error[GEO022]: feature 0: polygon 1: outer ring: e");
  // Only points: the feature is skipped, as a Point feature is.
  const auto points =
      read(collection({feature("", "{}",
                               R"({"type": "GeometryCollection", "geometries": [{"type": "Point",)"
                               R"( "coordinates": [1, 1]}]})"),
                       feature("", "{}", polygon(square(0, 0, 8, 6)))}));
  ASSERT_TRUE(points.ok());
  EXPECT_EQ(points->footprints.size(), 1u);
  EXPECT_EQ(count_code(points.diagnostics(), "GEO017"), 2u);
}

TEST(GeoJsonReader, LocatesProblemsInMinifiedText) {
  // Everything on one line: the column alone must find the offending coordinate.
  const std::string text =
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":)"
      R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}},{"type":"Feature","id":"x",)"
      R"("properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,true],[1,1],[0,0]]]}}]})";
  const auto result = read(text);
  ASSERT_FALSE(result.ok());
  const std::size_t column = text.find("true") + 1;
  EXPECT_EQ(headline(result.diagnostics().at(0)),
            "test.geojson:1:" + std::to_string(column) +
                R"(: error[GEO012]: feature 1 (id "x"): polygon ring 0 position 1 coordinate 1 is )"
                "a boolean; expected a number");
}

// ---- Origin shift and round trip --------------------------------------------------------------

TEST(GeoJsonReader, UtmCoordinatesShiftToWholeMeterOriginAndRoundTrip) {
  // ETRS89 / UTM 32N values with sub-millimetre digits.
  const std::vector<kernel::Vec2> world = {{500123.456789, 5400987.654321},
                                           {500163.456789, 5400987.654321},
                                           {500163.456789, 5401017.654321},
                                           {500123.456789, 5401017.654321}};
  std::string ring = "[";
  for (std::size_t i = 0; i <= world.size(); ++i) {
    std::ostringstream s;
    s.precision(17);
    s << (i ? ", [" : "[") << world[i % world.size()].x << ", " << world[i % world.size()].y << "]";
    ring += s.str();
  }
  ring += "]";
  const auto result = read(collection({feature("", "{}", polygon(ring))},
                                      R"("crs": {"type": "name", "properties": {"name": )"
                                      R"("urn:ogc:def:crs:EPSG::25832"}}, )"));
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result.diagnostics().empty());
  EXPECT_EQ(result->crs, "EPSG:25832");
  // Centre (500143.456789, 5401002.654321) rounded down.
  EXPECT_EQ(result->origin, (kernel::Vec3{500143, 5401002, 0}));
  const kernel::Ring& local = result->footprints[0].polygons[0].outer;
  ASSERT_EQ(local.size(), 4u);
  for (const kernel::Vec2& v : local) {
    EXPECT_LT(std::abs(v.x), 25.0);
    EXPECT_LT(std::abs(v.y), 20.0);
    const kernel::Vec2 back{v.x + result->origin.x, v.y + result->origin.y};
    const auto match = std::find_if(world.begin(), world.end(), [&](kernel::Vec2 w) {
      return std::abs(back.x - w.x) <= 1e-9 * std::abs(w.x) &&
             std::abs(back.y - w.y) <= 1e-9 * std::abs(w.y);
    });
    ASSERT_NE(match, world.end()) << back.x << ", " << back.y;
    // Sterbenz: world - origin is exact here, so the round trip is bit-exact.
    EXPECT_EQ(back, *match);
  }
}

TEST(GeoJsonReader, SmallCoordinatesKeepZeroOriginAndGivenOriginIsUsed) {
  const std::string text = polygon(square(9000, -9000, 10, 10));
  const auto near = read(text);
  ASSERT_TRUE(near.ok());
  EXPECT_EQ(near->origin, (kernel::Vec3{0, 0, 0}));
  EXPECT_EQ(near->footprints[0].polygons[0].outer[0], (kernel::Vec2{9000, -9000}));

  GeoJsonOptions options;
  options.origin = kernel::Vec2{9000, -9010};
  const auto shifted = read(text, options);
  ASSERT_TRUE(shifted.ok());
  EXPECT_EQ(shifted->origin, (kernel::Vec3{9000, -9010, 0}));
  EXPECT_EQ(shifted->footprints[0].polygons[0].outer[0], (kernel::Vec2{0, 10}));
}

// ---- CRS ----------------------------------------------------------------------------------------

// The first line of the failure to read a square at UTM-like coordinates under `crs_member`.
std::string crs_of_failure(const std::string& crs_member) {
  const auto result = read(collection({feature("", "{}", polygon(square(500000, 5400000, 10, 10)))},
                                      R"("crs": )" + crs_member + ", "));
  return result.ok() ? "ok" : headlines(result.diagnostics()).front();
}

std::string crs_of(const std::string& crs_member, std::vector<std::string>* warnings = nullptr) {
  const auto result = read(collection({feature("", "{}", polygon(square(500000, 5400000, 10, 10)))},
                                      R"("crs": )" + crs_member + ", "));
  EXPECT_TRUE(result.ok());
  if (warnings != nullptr) *warnings = headlines(result.diagnostics());
  return result.ok() ? result->crs : "?";
}

TEST(GeoJsonReader, CrsNamesAreReducedToEpsgCodes) {
  EXPECT_EQ(crs_of(R"({"type": "name", "properties": {"name": "EPSG:25833"}})"), "EPSG:25833");
  EXPECT_EQ(crs_of(R"({"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG:6.6:32631"}})"),
            "EPSG:32631");
  EXPECT_EQ(crs_of(R"({"type": "name", "properties": {"name": )"
                   R"("http://www.opengis.net/def/crs/EPSG/0/2056"}})"),
            "EPSG:2056");
  EXPECT_EQ(crs_of(R"({"type": "EPSG", "properties": {"code": 27700}})"), "EPSG:27700");
  EXPECT_EQ(crs_of("null"), "");
  std::vector<std::string> warnings;
  EXPECT_EQ(crs_of(R"({"type": "name", "properties": {"name": "local grid"}})", &warnings), "");
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          R"(test.geojson:1:38: warning[GEO007]: crs "local grid" names no EPSG )"
                          "code; ignored"}));
}

// What the reader takes the coordinates to be in, and what it builds in (docs/geojson.md).
struct CrsOutcome {
  std::string crs;
  std::string source_crs;
  kernel::Vec2 first;  // world coordinates of the first footprint's first vertex
};

CrsOutcome outcome(const base::Result<FootprintSet>& result) {
  if (!result.ok()) return {"failed: " + headlines(result.diagnostics()).front(), "", {}};
  const kernel::Vec2 local = result->footprints[0].polygons[0].outer[0];
  return {
      result->crs, result->source_crs, {local.x + result->origin.x, local.y + result->origin.y}};
}

TEST(GeoJsonReader, LonLatWithoutCrsMemberIsReprojectedToItsUtmZone) {
  // RFC 7946: no "crs" member means WGS 84 longitude/latitude. Berlin lies in UTM zone 33N.
  const std::string lonlat = polygon(square(13.40495, 52.52001, 0.0003, 0.00018));
  const CrsOutcome berlin = outcome(read(lonlat));
  EXPECT_EQ(berlin.crs, "EPSG:32633");
  EXPECT_EQ(berlin.source_crs, "OGC:CRS84");
  // echo 13.40495 52.52001 | cs2cs OGC:CRS84 EPSG:32633 (the square's first vertex).
  EXPECT_NEAR(berlin.first.x, 391775.892, 1e-3);
  EXPECT_NEAR(berlin.first.y, 5820073.346, 1e-3);
  // Southern hemisphere and west of Greenwich: zone 23S (Rio de Janeiro).
  EXPECT_EQ(outcome(read(polygon(square(-43.2, -22.9, 0.0002, 0.0002)))).crs, "EPSG:32723");
  // Fiji, on both sides of the antimeridian: the box's centre (0 degrees) is on the far side of
  // the Earth; the zone is the one of the data's own middle, 60S (it was 31S).
  const std::string fiji =
      collection({feature("", "{}", polygon(square(179.9996, -16.5, 0.0001, 0.0001))),
                  feature("", "{}", polygon(square(-179.9999, -16.5, 0.0001, 0.0001)))});
  EXPECT_EQ(outcome(read(fiji)).crs, "EPSG:32760");
  // A map export's forest beside its buildings spans kilometres (0.2 degrees here): the buildings
  // still make it longitude/latitude (one such polygon made the whole file meters, every
  // building a sliver of 0 m2).
  const std::string with_forest =
      collection({feature("", "{}", polygon(square(9.52, 47.16, 0.0003, 0.0002))),
                  feature("", "{}", polygon(square(9.4, 47.0, 0.2, 0.2))),
                  feature("", "{}", polygon(square(9.53, 47.17, 0.0002, 0.0002)))});
  EXPECT_EQ(outcome(read(with_forest)).crs, "EPSG:32632");
  // Map areas do not vote (with or without leave_out_non_buildings): three large polygons of a
  // forest outnumbered two buildings, and the file was read as meters.
  const std::string forest = R"({"type": "MultiPolygon", "coordinates": [[)" +
                             square(9.4, 47.0, 0.1, 0.1) + "], [" + square(9.6, 47.0, 0.1, 0.1) +
                             "], [" + square(9.4, 47.2, 0.1, 0.1) + "]]}";
  const std::string outvoted = collection(
      {feature("", R"({"building": "yes"})", polygon(square(9.52, 47.14, 2e-4, 1e-4))),
       feature("", R"({"landuse": "forest"})", forest),
       feature("", R"({"building": "yes"})", polygon(square(9.521, 47.14, 2e-4, 1e-4)))});
  EXPECT_EQ(outcome(read(outvoted)).crs, "EPSG:32632");
  // Mostly large: meters near (0, 0), as hand-made files are; the one small square is a 4 cm
  // sliver, not 4 km of degrees.
  const std::string local_meters =
      collection({feature("", "{}", polygon(square(0, 0, 10, 8))),
                  feature("", "{}", polygon(square(20, 0, 0.04, 0.04))),
                  feature("", "{}", polygon(square(40, 0, 12, 9)))});
  const std::string sliver = outcome(read(local_meters)).crs;
  EXPECT_NE(sliver.find("a sliver (area 0.002 m2"), std::string::npos) << sliver;
  const std::string meters = collection({feature("", "{}", polygon(square(0, 0, 10, 8))),
                                         feature("", "{}", polygon(square(40, 0, 12, 9)))});
  EXPECT_EQ(outcome(read(meters)).crs, "");
  // --crs names another projected CRS to build in: ETRS89 / UTM 33N.
  GeoJsonOptions options;
  options.crs = "EPSG:25833";
  const CrsOutcome etrs = outcome(read(lonlat, options));
  EXPECT_EQ(etrs.crs, "EPSG:25833");
  EXPECT_NEAR(etrs.first.x, berlin.first.x, 2.0);  // ETRS89 and WGS 84 differ by under a metre
}

TEST(GeoJsonReader, LonLatBuildingIsNoLongerANeedle) {
  // Issue 12: this 20 x 20 m building in degrees was read as meters, a 0.0003 x 0.00018 m
  // footprint the builders stretched into a needle, with only a warning.
  const std::filesystem::path file =
      std::filesystem::path(INSULA_TEST_DATA) / "geo" / "lonlat_degrees.geojson";
  const auto result = read_geojson(read_text(file), "lonlat_degrees.geojson");
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result.diagnostics().empty());
  ASSERT_EQ(result->footprints.size(), 1u);
  // The area of the corners cs2cs OGC:CRS84 EPSG:32633 gives.
  EXPECT_NEAR(kernel::area(result->footprints[0].polygons[0]), 407.674, 0.01);
}

TEST(GeoJsonReader, CrsOptionStatesTheCrsOfMetersAndReprojectsNamedCrs) {
  // Meters in no named CRS are taken to be in --crs: nothing moves.
  GeoJsonOptions options;
  options.crs = "EPSG:25832";
  const std::string meters = polygon(square(500010.25, 5400020.5, 20, 15));
  const CrsOutcome stated = outcome(read(meters, options));
  EXPECT_EQ(stated.crs, "EPSG:25832");
  EXPECT_EQ(stated.source_crs, "");
  EXPECT_EQ(stated.first, (kernel::Vec2{500010.25, 5400020.5}));
  // Small local meters are not mistaken for degrees (a 20 m square is not 20 degrees wide).
  EXPECT_EQ(outcome(read(polygon(square(0, 0, 20, 15)))).crs, "");
  // A file that names its CRS is reprojected to --crs: UTM 32N to UTM 33N.
  const std::string named =
      collection({feature("", "{}", polygon(square(700000, 5800000, 10, 10)))},
                 R"("crs": {"type": "name", "properties": {"name": )"
                 R"("EPSG:25832"}}, )");
  options.crs = "EPSG:25833";
  const CrsOutcome moved = outcome(read(named, options));
  EXPECT_EQ(moved.crs, "EPSG:25833");
  EXPECT_EQ(moved.source_crs, "EPSG:25832");
  EXPECT_GT(std::abs(moved.first.x - 700000), 1000);
  // --crs EPSG:4326 states that the file's numbers are degrees: these are not.
  options.crs = "EPSG:4326";
  EXPECT_EQ(outcome(read(meters, options)).crs,
            "failed: test.geojson:1:38: error[GEO008]: feature 0: polygon ring 0 position 0 "
            "(500010.25, 5400020.5) is not a longitude/latitude, but crs EPSG:4326 is geographic "
            "(degrees)");
  // OGC CRS84 named in the file, with coordinates that are not degrees.
  EXPECT_EQ(crs_of_failure(R"({"type": "name", "properties": {"name": )"
                           R"("urn:ogc:def:crs:OGC:1.3:CRS84"}})"),
            "test.geojson:2:88: error[GEO008]: feature 0: polygon ring 0 position 0 (500000, "
            "5400000) is not a longitude/latitude, but crs OGC:CRS84 is geographic (degrees)");
}

TEST(GeoJsonReader, LonLatBlockGivesTheSameBuildingsAsItsUtmVersion) {
  // The acceptance case of issue 12 item 3: an OSM-like block (block_lonlat.geojson) and the
  // same block reprojected by PROJ's cs2cs (make_block_utm.sh).
  const std::filesystem::path folder = std::filesystem::path(INSULA_TEST_DATA) / "geo";
  const auto lonlat = read_geojson(read_text(folder / "block_lonlat.geojson"), "block_lonlat");
  const auto utm = read_geojson(read_text(folder / "block_utm.geojson"), "block_utm");
  ASSERT_TRUE(lonlat.ok()) << headlines(lonlat.diagnostics()).front();
  ASSERT_TRUE(utm.ok());
  EXPECT_TRUE(lonlat.diagnostics().empty()) << headlines(lonlat.diagnostics()).front();
  EXPECT_EQ(lonlat->crs, "EPSG:32633");
  EXPECT_EQ(utm->crs, "EPSG:32633");
  ASSERT_EQ(lonlat->footprints.size(), 9u);
  ASSERT_EQ(utm->footprints.size(), 9u);
  double total = 0;
  for (std::size_t i = 0; i < 9; ++i) {
    const Footprint& a = lonlat->footprints[i];
    const Footprint& b = utm->footprints[i];
    SCOPED_TRACE(a.id);
    EXPECT_EQ(a.id, b.id);
    ASSERT_EQ(a.polygons.size(), b.polygons.size());
    for (std::size_t p = 0; p < a.polygons.size(); ++p) {
      const double area = kernel::area(a.polygons[p]);
      EXPECT_NEAR(area, kernel::area(b.polygons[p]), 0.005 * area);
      EXPECT_EQ(a.polygons[p].holes.size(), b.polygons[p].holes.size());
      const kernel::Vec2 ca = kernel::centroid(a.polygons[p]);
      const kernel::Vec2 cb = kernel::centroid(b.polygons[p]);
      EXPECT_NEAR(ca.x + lonlat->origin.x, cb.x + utm->origin.x, 0.01);
      EXPECT_NEAR(ca.y + lonlat->origin.y, cb.y + utm->origin.y, 0.01);
      total += area;
    }
  }
  // The block was drawn in UTM 33N meters (an 80 x 60 m block, 3,172 m2 of footprints) and
  // written in degrees of 7 decimals, as OSM does (about 1 cm).
  EXPECT_NEAR(total, 3172, 1.0);
}

// ---- Policies ----------------------------------------------------------------------------------

TEST(GeoJsonReader, WebMercatorGivesTheSameBuildingsAsLonLat) {
  // Issue 19 item 3: Web Mercator meters are not ground meters (x 1.64 at 52.5 degrees): the
  // block in EPSG:3857 (make_block_utm.sh) is reprojected to UTM like its lon/lat original.
  const std::filesystem::path folder = std::filesystem::path(INSULA_TEST_DATA) / "geo";
  const auto lonlat = read_geojson(read_text(folder / "block_lonlat.geojson"), "block_lonlat");
  const std::string mercator_text = read_text(folder / "block_3857.geojson");
  const auto mercator = read_geojson(mercator_text, "block_3857");
  ASSERT_TRUE(lonlat.ok());
  ASSERT_TRUE(mercator.ok()) << headlines(mercator.diagnostics()).front();
  EXPECT_EQ(mercator->crs, "EPSG:32633");
  EXPECT_EQ(mercator->source_crs, "EPSG:3857");
  // The same file without its "crs" member, stated with --crs; and an unofficial alias.
  std::string bare = mercator_text;
  const std::size_t crs_at = bare.find("\"crs\"");
  bare.erase(crs_at, bare.find("\"generator\"") - crs_at);
  GeoJsonOptions stated;
  stated.crs = "EPSG:900913";
  const auto bare_read = read_geojson(bare, "bare", stated);
  ASSERT_TRUE(bare_read.ok()) << headlines(bare_read.diagnostics()).front();
  EXPECT_EQ(bare_read->crs, "EPSG:32633");
  EXPECT_EQ(bare_read->source_crs, "EPSG:3857");
  for (const auto* other : {&mercator.value(), &bare_read.value()}) {
    ASSERT_EQ(other->footprints.size(), lonlat->footprints.size());
    for (std::size_t i = 0; i < other->footprints.size(); ++i) {
      const Footprint& a = lonlat->footprints[i];
      const Footprint& b = other->footprints[i];
      EXPECT_EQ(a.id, b.id);
      double area_a = 0, area_b = 0;
      for (const kernel::Polygon& p : a.polygons) area_a += kernel::area(p);
      for (const kernel::Polygon& p : b.polygons) area_b += kernel::area(p);
      EXPECT_NEAR(area_b / area_a, 1.0, 0.005) << a.id;
    }
  }
  // A --crs that cannot be built in says nothing about a file that names its CRS: ignored, said.
  GeoJsonOptions ignored;
  ignored.crs = "EPSG:4326";
  const auto named = read_geojson(mercator_text, "block_3857", ignored);
  ASSERT_TRUE(named.ok());
  EXPECT_EQ(named->source_crs, "EPSG:3857");
  EXPECT_EQ(headlines(named.diagnostics()),
            std::vector<std::string>{"block_3857:3:9: warning[GEO007]: GeoJsonOptions::crs "
                                     "EPSG:4326 ignored: the input names its CRS (EPSG:3857)"});
  // --out-crs builds in another CRS in ground meters; Web Mercator is refused as one.
  GeoJsonOptions out;
  out.out_crs = "EPSG:25833";
  const auto etrs = read_geojson(mercator_text, "block_3857", out);
  ASSERT_TRUE(etrs.ok());
  EXPECT_EQ(etrs->crs, "EPSG:25833");
  out.out_crs = "EPSG:3857";
  const auto refused = read_geojson(mercator_text, "block_3857", out);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(headlines(refused.diagnostics()).front(),
            "block_3857: error[GEO007]: GeoJsonOptions::out_crs: EPSG:3857 (WGS 84 / "
            "Pseudo-Mercator) is a Mercator projection, whose meters grow with latitude (1 / "
            "cos(latitude)); name a projected CRS in ground meters");
}

TEST(GeoJsonReader, ProjectedFeetAreReprojectedToUtm) {
  // NAD83 / New York Long Island in US survey feet: a 100 ft square near Manhattan.
  const std::string feet =
      collection({feature("", "{}", polygon(square(988000, 200000, 100, 100)))},
                 R"("crs": {"type": "name", "properties": {"name": "EPSG:2263"}}, )");
  const auto result = read(feet);
  ASSERT_TRUE(result.ok()) << headlines(result.diagnostics()).front();
  EXPECT_EQ(result->crs, "EPSG:32618");
  EXPECT_EQ(result->source_crs, "EPSG:2263");
  constexpr double kFoot = 1200.0 / 3937.0;
  EXPECT_NEAR(kernel::area(result->footprints[0].polygons[0]), 100 * 100 * kFoot * kFoot, 2.0);
}

TEST(GeoJsonReader, FootprintsKeepTheFirstEdgeAndOrientationAsWritten) {
  // Clockwise outer ring starting at (10, 0): normalization reverses it, the file's order stays.
  const auto result = read(collection({
      feature("", "{}", polygon("[[10, 0], [0, 0], [0, 8], [10, 8], [10, 0]]")),
      feature("", "{}", polygon("[[0, 0], [0, 0], [12, 0], [12, 6], [0, 6], [0, 0]]")),
  }));
  ASSERT_TRUE(result.ok());
  const Footprint& cw = result->footprints[0];
  ASSERT_EQ(cw.first_edges.size(), 1u);
  EXPECT_EQ(cw.first_edges[0][0], (kernel::Vec2{10, 0}));
  EXPECT_EQ(cw.first_edges[0][1], (kernel::Vec2{0, 0}));
  EXPECT_EQ(cw.outer_clockwise, std::vector<bool>{true});
  EXPECT_EQ(cw.polygons[0].outer[0], (kernel::Vec2{10, 8}));
  EXPECT_EQ(cw.polygons[0].outer[1], (kernel::Vec2{0, 8}));
  // A repeated first position does not make a zero-length first edge.
  const Footprint& ccw = result->footprints[1];
  EXPECT_EQ(ccw.first_edges[0][1], (kernel::Vec2{12, 0}));
  EXPECT_EQ(ccw.outer_clockwise, std::vector<bool>{false});
}

TEST(GeoJsonReader, TouchingRingsAreRepairedCountedAndWarnedOncePerKind) {
  // Issue 19 item 5: rings meeting at one point are unambiguous and repaired. A hole touching the
  // outer ring and two holes touching: the touching hole vertex moves 1 cm into its hole. A ring
  // through one point twice: cut there, into two polygons (a figure eight) or a polygon and a
  // hole (a courtyard pinched off at (10, 0)), which then touches and is separated the same way.
  const std::string text = collection({
      feature(R"("id": "ok", )", "{}", polygon(square(30, 0, 10, 10))),
      feature(R"("id": "pinched", )", "{}",
              polygon(square(0, 0, 20, 20) + ", [[0, 0], [5, 5], [5, 10], [2, 8], [0, 0]]")),
      feature(
          R"("id": "holes", )", "{}",
          polygon(square(50, 0, 20, 10) + ", " + square(52, 2, 4, 4) + ", " + square(56, 6, 4, 2))),
      feature(R"("id": "eight", )", "{}",
              polygon("[[100, 0], [110, 0], [110, 10], [120, 10], [120, 20], [110, 20], "
                      "[110, 10], [100, 10], [100, 0]]")),
      feature(R"("id": "loop", )", "{}",
              polygon("[[200, 0], [210, 0], [208, 5], [212, 5], [210, 0], [220, 0], [220, 20], "
                      "[200, 20], [200, 0]]")),
      feature(R"("id": "triangle", )", "{}", polygon("[[300, 0], [310, 0], [300, 10], [300, 0]]")),
  });
  const auto result = read(text);
  ASSERT_TRUE(result.ok()) << headlines(result.diagnostics()).front();
  std::map<std::string, const Footprint*> ids;
  for (const Footprint& f : result->footprints) ids[f.id] = &f;
  ASSERT_EQ(ids.size(), 6u);
  const double hole = 22.5;  // the pinched hole's shoelace area
  ASSERT_EQ(ids["pinched"]->polygons.size(), 1u);
  ASSERT_EQ(ids["pinched"]->polygons[0].holes.size(), 1u);
  EXPECT_NEAR(kernel::area(ids["pinched"]->polygons[0]), 400 - hole, 0.1);
  EXPECT_TRUE(kernel::is_simple_polygon(ids["pinched"]->polygons[0]));
  EXPECT_NEAR(kernel::area(ids["holes"]->polygons[0]), 200 - 16 - 8, 0.1);
  EXPECT_TRUE(kernel::is_simple_polygon(ids["holes"]->polygons[0]));
  ASSERT_EQ(ids["eight"]->polygons.size(), 2u);
  EXPECT_EQ(kernel::area(ids["eight"]->polygons[0]) + kernel::area(ids["eight"]->polygons[1]),
            200.0);
  ASSERT_EQ(ids["loop"]->polygons.size(), 1u);
  ASSERT_EQ(ids["loop"]->polygons[0].holes.size(), 1u);
  EXPECT_NEAR(kernel::area(ids["loop"]->polygons[0]), 400 - 10, 0.1);
  EXPECT_TRUE(kernel::is_simple_polygon(ids["loop"]->polygons[0]));
  EXPECT_EQ(kernel::area(ids["triangle"]->polygons[0]), 50.0);
  EXPECT_EQ(result->repairs, (std::map<std::string, std::size_t>{{"collinear_vertex", 1},
                                                                 {"separated_touching_rings", 3},
                                                                 {"split_touching_ring", 2}}));
  // One warning per kind, however many repairs.
  EXPECT_EQ(headlines(result.diagnostics()),
            (std::vector<std::string>{
                "test.geojson:3:151: warning[GEO027]: feature 1 (id \"pinched\"): polygon: rings "
                "touch at (0, 0); separated them by moving the touching vertex 0.01 m",
                "test.geojson:5:123: warning[GEO027]: feature 3 (id \"eight\"): polygon: a ring "
                "passes twice through (110, 10); split there into 2 polygons",
                "test.geojson:6:102: warning[GEO026]: feature 4 (id \"loop\"): polygon: outer "
                "ring: vertex 0 lies on the line through its neighbours (removed)"}));
}

TEST(GeoJsonReader, CrossingsSliversAndUnsplittableTouchesAreSkippedWithTheirReason) {
  const std::string text = collection({
      feature(R"("id": "ok", )", "{}", polygon(square(30, 0, 10, 10))),
      // Edges crossing: a bow-tie.
      feature(R"("id": "bowtie", )", "{}", polygon("[[0, 0], [10, 10], [10, 0], [0, 10], [0, 0]]")),
      // Two passes through (10, 10) that cross there: no single reading.
      feature(R"("id": "crossing", )", "{}",
              polygon("[[0, 0], [10, 10], [20, 20], [20, 0], [10, 10], [0, 20], [0, 0]]")),
      // 10 m x 0.2 m: width 2 * area / perimeter = 0.196 m.
      feature(R"("id": "thin", )", "{}", polygon(square(60, 0, 10, 0.2))),
      // 0.04 m2.
      feature(R"("id": "tiny", )", "{}", polygon(square(80, 0, 0.2, 0.2))),
  });
  const auto strict = read(text);
  EXPECT_FALSE(strict.ok());
  GeoJsonOptions options;
  options.skip_invalid = true;
  options.skip_invalid_flag = "--keep-going";
  const auto skipped = read(text, options);
  ASSERT_TRUE(skipped.ok());
  ASSERT_EQ(skipped->footprints.size(), 1u);
  EXPECT_EQ(skipped->footprints[0].id, "ok");
  EXPECT_EQ(skipped->skipped_invalid, 4u);
  EXPECT_EQ(skipped->skipped_by_code,
            (std::map<std::string, std::size_t>{{"GEO022", 2}, {"GEO028", 2}}));
  const std::vector<std::string> lines = headlines(skipped.diagnostics());
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0],
            "test.geojson:3:104: warning[GEO022]: feature 1 (id \"bowtie\"): polygon: outer ring: "
            "edges 0-1 and 2-3 cross at (5, 5)");
  EXPECT_EQ(lines[1].substr(0, lines[1].find("polygon:")),
            "test.geojson:4:106: warning[GEO022]: feature 2 (id \"crossing\"): ");
  EXPECT_EQ(lines[2],
            "test.geojson:5:101: warning[GEO028]: feature 3 (id \"thin\"): polygon: a sliver "
            "(area 2 m2, width about 0.196 m = 2 * area / perimeter; footprints need at least 1 "
            "m2 and 0.5 m)");
  EXPECT_EQ(lines[3].substr(0, lines[3].find(" (area")),
            "test.geojson:6:101: warning[GEO028]: feature 4 (id \"tiny\"): polygon: a sliver");
  for (const base::Diagnostic& d : skipped.diagnostics()) {
    EXPECT_EQ(d.notes.back(), "feature skipped (--keep-going)");
  }
}

// A sliver among a MultiPolygon's polygons (a 0.7 m2 scrap beside a register's building) is left
// out with a warning; the feature keeps its other polygons. Only slivers: the feature fails.
TEST(GeoJsonReader, ASliverPartOfAMultiPolygonIsLeftOut) {
  const auto multi = [](const std::string& polygons) {
    return R"({"type": "MultiPolygon", "coordinates": [)" + polygons + "]}";
  };
  const std::string text = collection({
      feature(R"("id": "house", )", "{}",
              multi("[" + square(0, 0, 6, 5) + "], [" + square(10, 0, 10, 0.1) + "]")),
      feature(R"("id": "scraps", )", "{}",
              multi("[" + square(30, 0, 10, 0.1) + "], [" + square(50, 0, 0.2, 0.2) + "]")),
  });
  const auto strict = read(text);
  EXPECT_FALSE(strict.ok());  // "scraps" has nothing but slivers
  GeoJsonOptions options;
  options.skip_invalid = true;
  options.skip_invalid_flag = "--keep-going";
  const auto kept = read(text, options);
  ASSERT_TRUE(kept.ok());
  ASSERT_EQ(kept->footprints.size(), 1u);
  EXPECT_EQ(kept->footprints[0].id, "house");
  ASSERT_EQ(kept->footprints[0].polygons.size(), 1u);
  EXPECT_NEAR(kernel::area(kept->footprints[0].polygons[0]), 30, 1e-9);
  const std::vector<std::string> lines = headlines(kept.diagnostics());
  ASSERT_GE(lines.size(), 1u);
  EXPECT_NE(lines[0].find("warning[GEO028]: feature 0 (id \"house\"): polygon 1: a sliver"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("left out, the feature keeps its other polygons"), std::string::npos);
  EXPECT_EQ(kept->skipped_by_code.at("GEO028"), 1u);  // "scraps"
}

// FootprintOptions::leave_out_non_buildings: a map export's areas that are not buildings are left
// out before their geometry is checked (a self-crossing meadow, a tree row thinner than a
// footprint), counted with their tags; without the option (`check`) every feature is checked.
TEST(GeoJsonReader, MapAreasAreLeftOutBeforeTheirGeometryIsChecked) {
  const std::string bow_tie = "[[-50, -50], [150, 150], [150, -50], [-50, 150], [-50, -50]]";
  const std::string text = collection({
      feature(R"("id": "house", )", R"({"building": "house"})", polygon(square(0, 0, 12, 9))),
      feature(R"("id": "meadow", )", R"({"landuse": "meadow"})", polygon(bow_tie)),
      feature(R"("id": "trees", )", R"({"natural": "tree_row"})", polygon(square(70, 0, 3, 0.2))),
      feature(R"("id": "garage", )", R"({"amenity": "parking", "height": 9})",
              polygon(square(20, 0, 10, 10))),
      feature(R"("id": "verge", )", R"({"landuse": "grass"})",
              polygon("[[80, 0], [90, 0], [80, 0]]")),
  });
  EXPECT_FALSE(read(text).ok());
  GeoJsonOptions options;
  options.leave_out_non_buildings = true;
  const auto left = read(text, options);
  ASSERT_TRUE(left.ok()) << headlines(left.diagnostics()).front();
  ASSERT_EQ(left->footprints.size(), 2u);
  EXPECT_EQ(left->footprints[0].id, "house");
  EXPECT_EQ(left->footprints[1].id, "garage");  // a height says structure
  EXPECT_EQ(left->non_buildings, 3u);
  EXPECT_EQ(left->non_building_tags,
            (std::vector<std::string>{"landuse=meadow", "natural=tree_row", "landuse=grass"}));
  EXPECT_EQ(left->skipped_invalid, 0u);
  EXPECT_TRUE(left.diagnostics().empty()) << headlines(left.diagnostics()).front();
  // No building tag anywhere (a register's `landuse` column): nothing is a map area.
  const std::string text_register =
      collection({feature("", R"({"landuse": "R1"})", polygon(square(0, 0, 12, 9)))});
  const auto kept = read(text_register, options);
  ASSERT_TRUE(kept.ok());
  EXPECT_EQ(kept->footprints.size(), 1u);
  EXPECT_EQ(kept->non_buildings, 0u);
  // There, an error found while reading (a ring of 3 positions) is held until the file is read,
  // then reported as without the option.
  const std::string short_register =
      collection({feature("", R"({"landuse": "R1"})", polygon(square(0, 0, 12, 9))),
                  feature(R"("id": "short", )", R"({"landuse": "R2"})",
                          polygon("[[20, 0], [30, 0], [20, 0]]"))});
  const auto plain = read(short_register);
  const auto held = read(short_register, options);
  EXPECT_FALSE(held.ok());
  EXPECT_EQ(headlines(held.diagnostics()), headlines(plain.diagnostics()));
  options.skip_invalid = true;
  const auto skipped = read(short_register, options);
  ASSERT_TRUE(skipped.ok());
  EXPECT_EQ(skipped->skipped_invalid, 1u);
  EXPECT_EQ(skipped->skipped_by_code.at("GEO010"), 1u);
}

TEST(GeoJsonReader, ALongRingIsRead) {
  // 1,232 vertices on a circle of radius 20 m.
  std::ostringstream ring;
  ring.precision(17);
  constexpr int kN = 1232;
  ring << "[";
  for (int i = 0; i <= kN; ++i) {
    const double a = 2 * M_PI * (i % kN) / kN;
    ring << (i ? ", [" : "[") << 20 * std::cos(a) << ", " << 20 * std::sin(a) << "]";
  }
  ring << "]";
  const auto result = read(polygon(ring.str()));
  ASSERT_TRUE(result.ok()) << headlines(result.diagnostics()).front();
  ASSERT_EQ(result->footprints.size(), 1u);
  EXPECT_EQ(result->footprints[0].polygons[0].outer.size(), std::size_t{kN});
  EXPECT_NEAR(kernel::area(result->footprints[0].polygons[0]), M_PI * 400, 0.1);
}

TEST(GeoJsonReader, WithoutSkippingTheFirstFeatureErrorSuggestsTheFlag) {
  const std::string text = collection({
      feature(R"("id": "short", )", "{}", polygon("[[0, 0], [1, 0], [0, 0]]")),
      feature(R"("id": "shorter", )", "{}", polygon("[[0, 0], [1, 0]]")),
  });
  GeoJsonOptions options;
  options.skip_invalid_flag = "--keep-going";
  const auto result = read(text, options);
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 2u);
  EXPECT_EQ(result.diagnostics()[0].notes,
            std::vector<std::string>{"--keep-going skips invalid features, each with a warning"});
  EXPECT_TRUE(result.diagnostics()[1].notes.empty());
}

TEST(GeoJsonReader, SkipInvalidDropsBadFeaturesAsWarnings) {
  const std::string text = collection({
      feature(R"("id": "good", )", "{}", polygon(square(0, 0, 5, 5))),
      feature(R"("id": "bowtie", )", "{}", polygon("[[0, 0], [10, 10], [10, 0], [0, 10], [0, 0]]")),
      feature(R"("id": "short", )", "{}", polygon("[[0, 0], [1, 0], [0, 0]]")),
  });
  EXPECT_FALSE(read(text).ok());
  GeoJsonOptions options;
  options.skip_invalid = true;
  const auto result = read(text, options);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->footprints.size(), 1u);
  EXPECT_EQ(result->footprints[0].id, "good");
  EXPECT_FALSE(base::has_errors(result.diagnostics()));
  EXPECT_EQ(result->skipped_invalid, 2u);
  EXPECT_EQ(count_code(result.diagnostics(), "GEO022"), 1u);
  EXPECT_EQ(count_code(result.diagnostics(), "GEO010"), 1u);
  for (const Diagnostic& d : result.diagnostics()) {
    ASSERT_EQ(d.notes.size(), 1u) << headline(d);
    EXPECT_EQ(d.notes[0], "feature skipped (GeoJsonOptions::skip_invalid)");
  }
}

TEST(GeoJsonReader, ErrorsAreCappedAndWarningsCounted) {
  std::vector<std::string> bad;
  for (int i = 0; i < 30; ++i)
    bad.push_back(feature("", "{}", polygon("[[0, 0], [1, 0], [0, 0]]")));
  GeoJsonOptions options;
  options.max_errors = 5;
  const auto failed = read(collection(bad), options);
  ASSERT_FALSE(failed.ok());
  ASSERT_EQ(failed.diagnostics().size(), 5u);
  EXPECT_EQ(failed.diagnostics().back().notes.back(),
            "too many errors (GeoJsonOptions::max_errors = 5); stopped reading");

  std::vector<std::string> open;
  for (int i = 0; i < 30; ++i) {
    open.push_back(feature("", "{}", polygon("[[0, 0], [1, 0], [1, 1], [0, 1]]")));
  }
  options.max_warnings = 10;
  const auto warned = read(collection(open), options);
  ASSERT_TRUE(warned.ok());
  EXPECT_EQ(warned->footprints.size(), 30u);
  ASSERT_EQ(warned.diagnostics().size(), 11u);
  // The warnings past the 10 listed are counted by code, in the set and in a closing note that a
  // failed read (no set) keeps.
  EXPECT_EQ(headline(warned.diagnostics().back()),
            "test.geojson: note[GEO011]: 20 more warnings of this code not listed");
  EXPECT_EQ(warned->unlisted_warnings, (std::map<std::string, std::size_t>{{"GEO011", 20}}));
  open.push_back(feature("", "{}", polygon("[[0, 0], [1, 0]]")));
  const auto warned_and_failed = read(collection(open), options);
  ASSERT_FALSE(warned_and_failed.ok());
  EXPECT_EQ(headline(warned_and_failed.diagnostics().back()),
            "test.geojson: note[GEO011]: 20 more warnings of this code not listed");
}

TEST(GeoJsonReader, DepthLimitIsAnOption) {
  const std::string multi =
      R"({"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", )"
      R"("coordinates": [[)" +
      square(0, 0, 1, 1) + "]]}}";
  GeoJsonOptions options;
  options.max_depth = 6;  // Feature, geometry, coordinates, polygon, ring, position
  EXPECT_TRUE(read(multi, options).ok());
  options.max_depth = 5;
  const auto result = read(multi, options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.diagnostics()[0].code, "GEO003");
}

TEST(GeoJsonReader, CoordinateLimitIsAnOption) {
  GeoJsonOptions options;
  options.max_abs_coordinate = 1000;
  const auto result = read(polygon(square(995, 0, 10, 10)), options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(headline(result.diagnostics()[0]),
            "test.geojson:1:49: error[GEO013]: feature 0: polygon ring 0 position 1 coordinate "
            "1005 is beyond +-1000 m (GeoJsonOptions::max_abs_coordinate)");
}

TEST(GeoJsonReader, ParseErrorGivesLineAndColumn) {
  const auto result = read("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0] [1, 0]]]}");
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 1u);
  EXPECT_EQ(headline(result.diagnostics()[0]),
            "test.geojson:2:26: error[GEO001]: syntax error while parsing array - unexpected "
            "'['; expected ']'");
}

// ---- The bad-input catalog ---------------------------------------------------------------------

struct CatalogCase {
  const char* file;
  bool ok;            // true: read succeeds with warnings only
  const char* first;  // the first error line (or, when ok, the first warning line)
};

const CatalogCase kCatalog[] = {
    {"deep_nesting.geojson", false,
     "deep_nesting.geojson:1:65: error[GEO003]: arrays and objects nest deeper than 64 levels "
     "(GeoJsonOptions::max_depth)"},
    {"deep_nesting_closed.geojson", false,
     "deep_nesting_closed.geojson:1:103: error[GEO003]: arrays and objects nest deeper than 64 "
     "levels (GeoJsonOptions::max_depth)"},
    {"duplicate_ids.geojson", true,
     "duplicate_ids.geojson:40:13: warning[GEO019]: feature 1 (id \"b7\"): id \"b7\" is already "
     "used by feature 0; renamed to \"b7-2\""},
    {"duplicate_vertices.geojson", true,
     "duplicate_vertices.geojson:22:13: warning[GEO025]: feature 0 (id \"dv\"): polygon: outer "
     "ring: vertex 2 repeats vertex 1 (removed) (and 1 more like it)"},
    {"empty.geojson", false,
     "empty.geojson: error[GEO002]: file is empty; expected a GeoJSON object"},
    {"empty_collection.geojson", false,
     "empty_collection.geojson: error[GEO006]: no polygon features"},
    {"empty_polygon.geojson", false, "empty_polygon.geojson: error[GEO006]: no polygon features"},
    {"feature_wrong_type.geojson", false,
     "feature_wrong_type.geojson:39:15: error[GEO015]: feature 1: \"type\" is \"Featur\"; expected "
     "\"Feature\""},
    {"features_not_array.geojson", false,
     "features_not_array.geojson:3:15: error[GEO005]: \"features\" is an object; expected an "
     "array"},
    {"geographic_crs.geojson", false,
     "geographic_crs.geojson:20:13: error[GEO008]: feature 0 (id \"u\"): polygon ring 0 position 0 "
     "(500010.25, 5400020.5) is not a longitude/latitude, but crs EPSG:4326 is geographic "
     "(degrees)"},
    {"hole_crosses_shell.geojson", false,
     "hole_crosses_shell.geojson:40:13: error[GEO023]: feature 0 (id \"hx\"): polygon: hole 1 "
     "crosses outer ring: edge 1-0 of hole 1 and edge 1-2 of outer ring cross at (10, 2)"},
    {"hole_touches_shell.geojson", true,
     "hole_touches_shell.geojson:36:13: warning[GEO027]: feature 0 (id \"pinched\"): polygon: "
     "rings touch at (0, 0); separated them by moving the touching vertex 0.01 m"},
    {"hole_outside.geojson", false,
     "hole_outside.geojson:35:11: error[GEO024]: feature 0 (id \"h\"): polygon: hole 1 lies "
     "outside the outer ring"},
    {"huge_coordinates.geojson", false,
     "huge_coordinates.geojson:19:15: error[GEO013]: feature 0 (id \"far\"): polygon ring 0 "
     "position 1 coordinate 1e+300 is beyond +-100000000 m (GeoJsonOptions::max_abs_coordinate)"},
    {"infinity_literal.geojson", false,
     "infinity_literal.geojson:2:74: error[GEO001]: NaN and Infinity are not valid JSON numbers"},
    {"invalid_utf8.geojson", false,
     "invalid_utf8.geojson:1:32: error[GEO001]: syntax error while parsing value - invalid string: "
     "ill-formed UTF-8 byte; last read: '\"caf\\xe9\"'"},
    {"missing_coordinates.geojson", false,
     "missing_coordinates.geojson:44:19: error[GEO014]: feature 1 (id \"nc\"): Polygon has no "
     "\"coordinates\""},
    {"nan_literal.geojson", false,
     "nan_literal.geojson:5:64: error[GEO001]: NaN and Infinity are not valid JSON numbers"},
    {"number_overflow.geojson", false,
     "number_overflow.geojson:2:28: error[GEO001]: number overflow parsing '1e400'"},
    {"position_too_short.geojson", false,
     "position_too_short.geojson:18:13: error[GEO014]: feature 0 (id \"p\"): polygon ring 0 "
     "position 1 is an array of 1; expected [x, y] or [x, y, z]"},
    {"self_intersection.geojson", false,
     "self_intersection.geojson:48:13: error[GEO022]: feature 1 (id \"bowtie\"): polygon: outer "
     "ring: edges 0-1 and 2-3 cross at (5, 5)"},
    {"string_numbers.geojson", false,
     "string_numbers.geojson:53:15: error[GEO012]: feature 1 (id \"s1\"): polygon ring 0 position "
     "1 coordinate 0 is a string (\"10.0\"); expected a number"},
    {"too_few_points.geojson", false,
     "too_few_points.geojson:47:11: error[GEO010]: feature 1 (id \"b12\"): polygon ring 0 has 3 "
     "positions; a closed ring needs at least 4"},
    {"top_level_array.geojson", false,
     "top_level_array.geojson:1:1: error[GEO004]: the top-level value is an array; expected a "
     "FeatureCollection, a Feature, a Polygon or a MultiPolygon"},
    {"top_level_topology.geojson", false,
     "top_level_topology.geojson:2:11: error[GEO004]: the top-level type is \"Topology\"; expected "
     "a FeatureCollection, a Feature, a Polygon or a MultiPolygon"},
    {"trailing_comma.geojson", false,
     "trailing_comma.geojson:6:3: error[GEO001]: trailing comma before ']' is not allowed in JSON"},
    {"truncated.geojson", false,
     "truncated.geojson:42:14: error[GEO001]: syntax error while parsing object key - invalid "
     "string: missing closing quote; last read: '\"heig'; expected string literal"},
    {"unclosed_ring.geojson", true,
     "unclosed_ring.geojson:13:11: warning[GEO011]: feature 0 (id \"open\"): polygon ring 0 is not "
     "closed (its last position differs from the first); closed it"},
    {"unknown_geometry_type.geojson", false,
     "unknown_geometry_type.geojson:45:17: error[GEO016]: feature 1 (id \"typo\"): geometry type "
     "\"Polygn\" is not a GeoJSON geometry type"},
    {"unterminated_string.geojson", false,
     "unterminated_string.geojson:1:74: error[GEO001]: syntax error while parsing value - invalid "
     "string: missing closing quote; last read: '\"abc'"},
    {"utm_bowtie.geojson", false,
     "utm_bowtie.geojson:54:13: error[GEO022]: feature 1 (id \"u2\"): polygon: outer ring: edges "
     "0-1 and 2-3 cross at (-10, -12)"},
    {"whitespace_only.geojson", false,
     "whitespace_only.geojson: error[GEO002]: file is empty; expected a GeoJSON object"},
    {"wrong_geometry_type.geojson", false,
     "wrong_geometry_type.geojson: error[GEO006]: no polygon features"},
    {"z_coordinates.geojson", true,
     "z_coordinates.geojson:17:15: warning[GEO009]: feature 0 (id \"z\"): polygon ring 0 position "
     "0 has 3 numbers; only x and y are used (footprints lie at z = 0; reported once)"},
    {"zero_area.geojson", false,
     "zero_area.geojson:13:11: error[GEO021]: feature 0 (id \"flat\"): polygon: outer ring: zero "
     "area (its positions lie on one line)"},
};

TEST(GeoJsonCatalog, EveryFileGivesItsExactFirstLine) {
  const std::filesystem::path folder = std::filesystem::path(INSULA_TEST_DATA) / "bad";
  std::set<std::string> listed;
  for (const CatalogCase& c : kCatalog) {
    SCOPED_TRACE(c.file);
    listed.insert(c.file);
    const std::string text = read_text(folder / c.file);
    const auto result = read_geojson(text, c.file);
    ASSERT_EQ(result.ok(), c.ok);
    const auto& diagnostics = result.diagnostics();
    ASSERT_FALSE(diagnostics.empty());
    const auto first =
        std::find_if(diagnostics.begin(), diagnostics.end(),
                     [&](const Diagnostic& d) { return c.ok || d.severity == Severity::kError; });
    ASSERT_NE(first, diagnostics.end());
    EXPECT_EQ(headline(*first), c.first);
    EXPECT_EQ(base::has_errors(diagnostics), !c.ok);
  }
  // Every file in the folder has a row, so a new case cannot go untested.
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".geojson") {
      EXPECT_EQ(listed.count(entry.path().filename().string()), 1u) << entry.path();
    }
  }
}

}  // namespace
}  // namespace insula::io
