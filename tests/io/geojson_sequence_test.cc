// io::read_geojson of a GeoJSON text sequence (RFC 8142 GeoJSONSeq, newline-delimited GeoJSON as
// Microsoft's building footprints ship it): one Feature per line, read as a FeatureCollection of
// the same features is, with diagnostics on the line of the feature.
#include "io/geojson_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace insula::io {
namespace {

std::string headline(const base::Diagnostic& d) {
  const std::string text = base::render(d);
  return text.substr(0, text.find('\n'));
}

// A 10 m square at (x, 0) in lon/lat-free meters, as one line.
std::string feature_line(int x, const std::string& properties = R"({"height": -1.0})") {
  const std::string a = std::to_string(x);
  const std::string b = std::to_string(x + 10);
  return R"({"type":"Feature","properties":)" + properties +
         R"(,"geometry":{"type":"Polygon","coordinates":[[[)" + a + ",0],[" + b + ",0],[" + b +
         ",10],[" + a + ",10],[" + a + ",0]]]}}";
}

base::Result<FootprintSet> read_sequence(const std::string& text,
                                         const std::string& name = "msft.geojsonl") {
  return read_geojson(text, name);
}

TEST(GeoJsonSequence, NamesBySuffix) {
  EXPECT_TRUE(is_geojson_sequence_path("Liechtenstein.geojsonl"));
  EXPECT_TRUE(is_geojson_sequence_path("dir/a.GEOJSONS"));
  EXPECT_TRUE(is_geojson_sequence_path("a.geojsonseq"));
  EXPECT_TRUE(is_geojson_sequence_path("a.ndjson"));
  EXPECT_FALSE(is_geojson_sequence_path("a.geojson"));
  EXPECT_FALSE(is_geojson_sequence_path("a.json"));
  EXPECT_FALSE(is_geojson_sequence_path("l"));
}

// The same features as a sequence and as a FeatureCollection give the same footprints.
TEST(GeoJsonSequence, ReadsLikeAFeatureCollection) {
  std::string lines;
  std::string collection = R"({"type":"FeatureCollection","features":[)";
  for (int i = 0; i < 600; ++i) {  // more than one chunk of 256 features
    lines += feature_line(20 * i) + "\n";
    if (i > 0) collection += ',';
    collection += feature_line(20 * i);
  }
  collection += "]}";
  const auto sequence = read_sequence(lines);
  const auto document = read_geojson(collection, "msft.geojson");
  ASSERT_TRUE(sequence.ok()) << base::render(sequence.diagnostics().front());
  ASSERT_TRUE(document.ok());
  ASSERT_EQ(sequence->footprints.size(), 600u);
  ASSERT_EQ(document->footprints.size(), 600u);
  for (std::size_t i = 0; i < 600; ++i) {
    EXPECT_EQ(sequence->footprints[i].id, document->footprints[i].id);
    EXPECT_EQ(sequence->footprints[i].polygons[0].outer, document->footprints[i].polygons[0].outer);
    EXPECT_EQ(sequence->footprints[i].properties.map(), document->footprints[i].properties.map());
  }
  EXPECT_EQ(sequence->origin.x, document->origin.x);
}

// RFC 8142's record separator, blank lines, CRLF line ends and a byte order mark are skipped;
// GeoJsonOptions::sequence reads any name as a sequence.
TEST(GeoJsonSequence, RecordSeparatorsAndBlankLines) {
  const std::string text = "\xEF\xBB\xBF\x1E" + feature_line(0) + "\r\n\r\n\n  \n\x1E" +
                           feature_line(20) + "\n\x1E" + feature_line(40);
  GeoJsonOptions options;
  options.sequence = true;
  const auto set = read_geojson(text, "stdin", options);
  ASSERT_TRUE(set.ok()) << base::render(set.diagnostics().front());
  ASSERT_EQ(set->footprints.size(), 3u);
  EXPECT_EQ(set->footprints[2].id, "feature-2");
  // Without the option or the name, the text is not one JSON document.
  EXPECT_FALSE(read_geojson(text, "stdin").ok());
}

TEST(GeoJsonSequence, ALineThatIsNotAFeatureIsAnErrorNamingTheLine) {
  const auto array = read_sequence(feature_line(0) + "\n\n[1, 2]\n" + feature_line(20) + "\n");
  ASSERT_FALSE(array.ok());
  EXPECT_EQ(headline(array.diagnostics().front()),
            "msft.geojsonl:3:1: error[GEO015]: feature 1: line 3 of the GeoJSON sequence is an "
            "array; expected a Feature object");
  const auto collection =
      read_sequence(feature_line(0) + "\n" + R"({"type":"FeatureCollection","features":[]})");
  ASSERT_FALSE(collection.ok());
  EXPECT_EQ(headline(collection.diagnostics().front()),
            "msft.geojsonl:2:9: error[GEO015]: feature 1: line 2 of the GeoJSON sequence: "
            "\"type\" is \"FeatureCollection\"; expected \"Feature\"");
}

// A syntax error, two values on one line and a feature split over two lines are GEO001 on
// their line, in any chunk.
TEST(GeoJsonSequence, SyntaxErrorsNameTheirLine) {
  std::string lines;
  for (int i = 0; i < 300; ++i) lines += feature_line(20 * i) + "\n";
  const auto broken = read_sequence(lines + R"({"type":"Feature",})" + "\n");
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.diagnostics().size(), 1u);
  EXPECT_EQ(headline(broken.diagnostics().front()).substr(0, 37),
            "msft.geojsonl:301:19: error[GEO001]: ");
  const auto two = read_sequence(feature_line(0) + " " + feature_line(20) + "\n");
  ASSERT_FALSE(two.ok());
  EXPECT_EQ(two.diagnostics().front().span.line, 1u);
  EXPECT_EQ(two.diagnostics().front().code, "GEO001");
  const std::string split = feature_line(0);
  const auto wrapped =
      read_sequence(feature_line(40) + "\n" + split.substr(0, 30) + "\n" + split.substr(30) + "\n");
  ASSERT_FALSE(wrapped.ok());
  EXPECT_EQ(wrapped.diagnostics().front().span.line, 2u);
  const std::string rendered = base::render(wrapped.diagnostics().front());
  EXPECT_NE(rendered.find("one whole Feature on each line"), std::string::npos) << rendered;
}

// A bad feature's diagnostics point into its own line, as they point into a collection.
TEST(GeoJsonSequence, FeatureErrorsPointIntoTheirLine) {
  const std::string bow_tie =
      R"({"type":"Feature","id":"x","properties":{},"geometry":{"type":"Polygon",)"
      R"("coordinates":[[[0,0],[10,10],[10,0],[0,10],[0,0]]]}})";
  const auto set = read_sequence(feature_line(100) + "\n\n" + bow_tie + "\n");
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.diagnostics().front().code, "GEO022");
  EXPECT_EQ(set.diagnostics().front().span.line, 3u);
  GeoJsonOptions keep_going;
  keep_going.skip_invalid = true;
  const auto kept =
      read_geojson(feature_line(100) + "\n\n" + bow_tie + "\n", "a.ndjson", keep_going);
  ASSERT_TRUE(kept.ok());
  EXPECT_EQ(kept->footprints.size(), 1u);
  EXPECT_EQ(kept->skipped_invalid, 1u);
}

TEST(GeoJsonSequence, BlankFileIsEmpty) {
  const auto set = read_sequence("\n\x1E\n  \r\n");
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.diagnostics().front().code, "GEO002");
}

}  // namespace
}  // namespace insula::io
