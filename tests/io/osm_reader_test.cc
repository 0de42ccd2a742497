// io::read_osm and io::stream_osm on the hand-made files of tests/data/osm (make_osm.sh: nodes
// placed in UTM 33N meters, so every area is known): ways, multipolygons with holes and with
// rings of several ways, building:part, tags, the same footprints from .osm.pbf (converted with
// osmium-tool here), and broken input naming the element.
#include "io/osm_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace insula::io {
namespace {

const std::filesystem::path kData = std::filesystem::path(INSULA_TEST_DATA) / "osm";

std::string headline(const base::Diagnostic& d) {
  const std::string text = base::render(d);
  return text.substr(0, text.find('\n'));
}

std::string first_headline(const base::Result<FootprintSet>& result) {
  return result.diagnostics().empty() ? "(none)" : headline(result.diagnostics().front());
}

std::string text_of(const PropertyRow& properties, const std::string& key) {
  const std::optional<shape::Value> value = properties.find(key);
  if (!value) return "(absent)";
  const std::string* s = std::get_if<std::string>(&*value);
  return s != nullptr ? *s : "(not a string)";
}

std::map<std::string, const Footprint*> by_id(const FootprintSet& set) {
  std::map<std::string, const Footprint*> out;
  for (const Footprint& f : set.footprints) out[f.id] = &f;
  return out;
}

// A scratch folder for converted files, removed with the test.
struct TempDir {
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("insula_osm_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::filesystem::path path;
};

std::filesystem::path to_pbf(const std::filesystem::path& osm, const TempDir& dir) {
  const std::filesystem::path pbf = dir.path / (osm.stem().string() + ".osm.pbf");
  const std::string command = "osmium cat -O -o '" + pbf.string() + "' '" + osm.string() + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return pbf;
}

TEST(OsmReader, WaysMultipolygonsAndPartsBecomeFootprintsWithTheirTags) {
  const auto result = read_osm((kData / "buildings.osm").string());
  ASSERT_TRUE(result.ok()) << first_headline(result);
  EXPECT_TRUE(result.diagnostics().empty()) << first_headline(result);
  EXPECT_EQ(result->crs, "EPSG:32633");
  EXPECT_EQ(result->source_crs, "OGC:CRS84");
  ASSERT_EQ(result->footprints.size(), 4u);  // the road is not a building
  const auto ids = by_id(result.value());
  ASSERT_EQ(ids.count("way/101"), 1u);
  ASSERT_EQ(ids.count("way/121"), 1u);
  ASSERT_EQ(ids.count("relation/201"), 1u);
  ASSERT_EQ(ids.count("relation/202"), 1u);
  // Areas of the UTM rectangles the nodes were made from (make_osm.sh), to 0.2 %: libosmium keeps
  // locations in 1e-7 degrees (up to 6 mm off per corner here).
  const Footprint& way = *ids.at("way/101");
  ASSERT_EQ(way.polygons.size(), 1u);
  EXPECT_NEAR(kernel::area(way.polygons[0]), 200.0, 0.4);
  EXPECT_NEAR(kernel::area(ids.at("way/121")->polygons[0]), 48.0, 0.1);
  const Footprint& courtyard = *ids.at("relation/201");
  ASSERT_EQ(courtyard.polygons.size(), 1u);
  ASSERT_EQ(courtyard.polygons[0].holes.size(), 1u);
  EXPECT_EQ(courtyard.polygons[0].outer.size(), 4u);
  EXPECT_NEAR(kernel::area(courtyard.polygons[0]), 800.0, 1.6);
  const Footprint& two_ways = *ids.at("relation/202");
  ASSERT_EQ(two_ways.polygons.size(), 1u);
  EXPECT_EQ(two_ways.polygons[0].outer.size(), 4u);
  EXPECT_NEAR(kernel::area(two_ways.polygons[0]), 200.0, 0.4);
  // Tags verbatim, as strings; the element's type and id beside them.
  EXPECT_EQ(text_of(way.properties, "building"), "yes");
  EXPECT_EQ(text_of(way.properties, "height"), "12");
  EXPECT_EQ(text_of(way.properties, "building:levels"), "4");
  EXPECT_EQ(text_of(way.properties, "roof:shape"), "gabled");
  EXPECT_EQ(text_of(way.properties, "name"), "Haus Eins");
  EXPECT_EQ(text_of(way.properties, "osm_type"), "way");
  EXPECT_EQ(text_of(way.properties, "osm_id"), "101");
  EXPECT_EQ(way.properties.size(), 8u);
  EXPECT_EQ(text_of(ids.at("way/121")->properties, "building:part"), "yes");
  EXPECT_EQ(text_of(ids.at("way/121")->properties, "min_height"), "5");
  EXPECT_EQ(text_of(courtyard.properties, "building"), "apartments");
  EXPECT_EQ(text_of(courtyard.properties, "type"), "(absent)");
  EXPECT_EQ(text_of(courtyard.properties, "osm_type"), "relation");
  EXPECT_EQ(text_of(courtyard.properties, "osm_id"), "201");
  // The UTM frame: the part lies 2 m inside the building's south-west corner.
  const kernel::Bounds2 outline = kernel::bounds(way.polygons[0]);
  const kernel::Bounds2 part = kernel::bounds(ids.at("way/121")->polygons[0]);
  EXPECT_NEAR(part.min.x - outline.min.x, 2.0, 0.01);
  EXPECT_NEAR(part.min.y - outline.min.y, 2.0, 0.01);
  EXPECT_NEAR(outline.min.x + result->origin.x, 390000.0, 0.01);
  EXPECT_NEAR(outline.min.y + result->origin.y, 5820000.0, 0.01);
}

TEST(OsmReader, PbfGivesTheSameFootprintsAsXml) {
  TempDir dir;
  const auto xml = read_osm((kData / "buildings.osm").string());
  const auto pbf = read_osm(to_pbf(kData / "buildings.osm", dir).string());
  ASSERT_TRUE(xml.ok());
  ASSERT_TRUE(pbf.ok()) << first_headline(pbf);
  ASSERT_EQ(pbf->footprints.size(), xml->footprints.size());
  EXPECT_EQ(pbf->origin, xml->origin);
  for (std::size_t i = 0; i < xml->footprints.size(); ++i) {
    const Footprint& a = xml->footprints[i];
    const Footprint& b = pbf->footprints[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.properties.map(), b.properties.map());
    ASSERT_EQ(a.polygons.size(), b.polygons.size());
    for (std::size_t p = 0; p < a.polygons.size(); ++p) {
      // Both store locations as 1e-7 degree integers: the same bits come out.
      EXPECT_EQ(a.polygons[p].outer, b.polygons[p].outer) << a.id;
      EXPECT_EQ(a.polygons[p].holes, b.polygons[p].holes) << a.id;
    }
  }
}

TEST(OsmReader, StreamDeliversLonLatBatches) {
  OsmStreamOptions options;
  options.batch_size = 3;
  std::vector<std::size_t> sizes;
  std::vector<OsmFeature> all;
  const auto stats =
      stream_osm((kData / "buildings.osm").string(), options, [&](std::vector<OsmFeature>& batch) {
        sizes.push_back(batch.size());
        for (OsmFeature& f : batch) all.push_back(std::move(f));
      });
  ASSERT_TRUE(stats.ok());
  EXPECT_EQ(stats->features, 4u);
  EXPECT_EQ(stats->ways, 2u);
  EXPECT_EQ(stats->relations, 2u);
  EXPECT_EQ(sizes, (std::vector<std::size_t>{3, 1}));
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0].element(), "way 101");
  EXPECT_TRUE(all[0].problem.empty());
  ASSERT_EQ(all[0].polygons.size(), 1u);
  // Longitude first, as node 1 of make_osm.sh gives it (to libosmium's 1e-7 degrees).
  const kernel::Ring& ring = all[0].polygons[0].outer;
  EXPECT_EQ(ring.size(), 4u);
  EXPECT_EQ(std::count_if(ring.begin(), ring.end(),
                          [](kernel::Vec2 v) {
                            return std::abs(v.x - 13.378811770) < 1e-7 &&
                                   std::abs(v.y - 52.518995312) < 1e-7;
                          }),
            1);
  // The ring starts at the way's first node and runs its way (nodes 1, 2, 3, 4), not where
  // libosmium's assembler starts it, so a CGA lot's first edge is the way's first edge.
  const double lon[] = {13.378811770, 13.379106403, 13.379103095, 13.378808461};
  const double lat[] = {52.518995312, 52.518999349, 52.519089214, 52.519085178};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    EXPECT_NEAR(ring[i].x, lon[i], 1e-7) << "corner " << i;
    EXPECT_NEAR(ring[i].y, lat[i], 1e-7) << "corner " << i;
  }
}

TEST(OsmReader, AClockwiseWayStartsAtItsFirstNodeAndRunsItsWay) {
  // Nodes 1, 4, 3, 2 of buildings.osm (clockwise), the second one mapped twice at one place.
  TempDir dir;
  const std::filesystem::path file = dir.path / "clockwise.osm";
  std::ofstream(file) << R"(<?xml version="1.0" encoding="UTF-8"?>
<osm version="0.6">
  <node id="1" version="1" lat="52.518995312" lon="13.378811770"/>
  <node id="2" version="1" lat="52.518999349" lon="13.379106403"/>
  <node id="3" version="1" lat="52.519089214" lon="13.379103095"/>
  <node id="4" version="1" lat="52.519085178" lon="13.378808461"/>
  <node id="9" version="1" lat="52.518995312" lon="13.378811770"/>
  <way id="1" version="1">
    <nd ref="1"/><nd ref="9"/><nd ref="4"/><nd ref="3"/><nd ref="2"/><nd ref="1"/>
    <tag k="building" v="yes"/>
  </way>
</osm>
)";
  OsmStreamOptions options;
  std::vector<OsmFeature> all;
  const auto stats = stream_osm(file.string(), options, [&](std::vector<OsmFeature>& batch) {
    for (OsmFeature& f : batch) all.push_back(std::move(f));
  });
  ASSERT_TRUE(stats.ok());
  ASSERT_EQ(all.size(), 1u);
  ASSERT_EQ(all[0].polygons.size(), 1u) << all[0].problem;
  const kernel::Ring& ring = all[0].polygons[0].outer;
  const double lon[] = {13.378811770, 13.378808461, 13.379103095, 13.379106403};
  const double lat[] = {52.518995312, 52.519085178, 52.519089214, 52.518999349};
  ASSERT_EQ(ring.size(), 4u);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    EXPECT_NEAR(ring[i].x, lon[i], 1e-7) << "corner " << i;
    EXPECT_NEAR(ring[i].y, lat[i], 1e-7) << "corner " << i;
  }
}

TEST(OsmReader, BrokenElementsAreNamedAndSkippedWithKeepGoing) {
  struct Case {
    const char* file;
    const char* code;
    const char* headline;
    const char* cause;  // the note that says what usually causes it, if any
  };
  const Case cases[] = {
      {"missing_node.osm", "OSM003",
       "missing_node.osm: error[OSM003]: way 102: node 999 has no location (not in the file, or "
       "beyond +-180 x +-90)",
       "an extract cut at a border with osmium extract's 'simple' strategy (or a bounding-box "
       "download) leaves out the nodes outside it; its default, 'complete_ways', keeps every way "
       "whole"},
      {"unclosed_multipolygon.osm", "OSM004",
       "unclosed_multipolygon.osm: error[OSM004]: relation 203: no polygon could be assembled: a "
       "ring is not closed: it ends at node 24 of way 115 (13.3802783, 52.5191952)",
       nullptr},
      {"open_way.osm", "OSM002",
       "open_way.osm: error[OSM002]: way 104: is not closed: it starts at node 21 and ends at "
       "node 23",
       nullptr},
  };
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(kData);  // short names in the messages
  for (const Case& c : cases) {
    const auto strict = read_osm(c.file);
    EXPECT_FALSE(strict.ok()) << c.file;
    EXPECT_EQ(first_headline(strict), c.headline);
    OsmOptions options;
    options.skip_invalid = true;
    options.skip_invalid_flag = "--keep-going";
    const auto lenient = read_osm(c.file, options);
    ASSERT_TRUE(lenient.ok()) << first_headline(lenient);
    ASSERT_EQ(lenient->footprints.size(), 1u) << c.file;
    EXPECT_EQ(lenient->footprints[0].id, "way/101");
    EXPECT_EQ(lenient->skipped_invalid, 1u);
    EXPECT_EQ(lenient->skipped_by_code.at(c.code), 1u);
    ASSERT_EQ(lenient.diagnostics().size(), 1u);
    EXPECT_EQ(lenient.diagnostics()[0].severity, base::Severity::kWarning);
    std::vector<std::string> notes;
    if (c.cause != nullptr) notes.emplace_back(c.cause);
    notes.emplace_back("feature skipped (--keep-going)");
    EXPECT_EQ(lenient.diagnostics()[0].notes, notes);
  }
  std::filesystem::current_path(here);
}

TEST(OsmReader, TruncatedDamagedAndMissingFilesFailWithOneError) {
  TempDir dir;
  const std::filesystem::path pbf = to_pbf(kData / "buildings.osm", dir);
  std::string bytes;
  {
    std::ifstream in(pbf, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 200u);
  const std::filesystem::path cut = dir.path / "cut.osm.pbf";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const auto truncated = read_osm(cut.string());
  EXPECT_FALSE(truncated.ok());
  ASSERT_EQ(truncated.diagnostics().size(), 1u);
  EXPECT_EQ(headline(truncated.diagnostics()[0]),
            cut.string() +
                ": error[OSM001]: not a valid .osm.pbf file (truncated or damaged?): PBF error: "
                "unexpected EOF");

  const std::filesystem::path xml = dir.path / "cut.osm";
  std::string text;
  {
    std::ifstream in(kData / "buildings.osm", std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string cut_text = text.substr(0, text.find("<way id=\"111\""));
  std::ofstream(xml, std::ios::binary) << cut_text;
  const auto cut_xml = read_osm(xml.string());
  EXPECT_FALSE(cut_xml.ok());
  ASSERT_EQ(cut_xml.diagnostics().size(), 1u);
  EXPECT_EQ(cut_xml.diagnostics()[0].code, "OSM001");
  EXPECT_EQ(cut_xml.diagnostics()[0].message, "not valid OSM XML: no element found");
  // expat points at the end of the cut text.
  EXPECT_EQ(cut_xml.diagnostics()[0].span.line,
            1 + std::count(cut_text.begin(), cut_text.end(), '\n'));

  const auto missing = read_osm((dir.path / "none.osm.pbf").string());
  EXPECT_FALSE(missing.ok());
  EXPECT_EQ(missing.diagnostics().at(0).code, "OSM001");
}

TEST(OsmReader, RecognizesOsmFileNames) {
  EXPECT_TRUE(is_osm_path("city.osm"));
  EXPECT_TRUE(is_osm_path("a/b/Country-latest.OSM.PBF"));
  EXPECT_TRUE(is_osm_path("x.osm.bz2"));
  EXPECT_FALSE(is_osm_path("city.geojson"));
  EXPECT_FALSE(is_osm_path("osm"));
}

}  // namespace
}  // namespace insula::io
