// The steps every footprint reader ends with, shared by GeoJSON (io/geojson_reader.h) and
// OpenStreetMap (io/osm_reader.h) input: CRS choice and reprojection to ground meters, origin
// shift, repair (kernel::repair, touching rings, slivers), ids, and the capped, skip-aware
// diagnostics. A reader collects RawFootprints in world coordinates and calls finish_features();
// docs/geojson.md ("Coordinates, units and CRS", "Repair policy") gives the rules.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "io/property_table.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::io {

struct Footprint {
  // GeoJSON: the feature's "id" member, else properties.id, else properties.name, else
  // "feature-<index>". OSM: "way/123" or "relation/456". Unique within a FootprintSet: a repeated
  // id is renamed "<id>-2", "<id>-3"... with a warning.
  std::string id;
  // Local coordinates (world - origin) in meters, normalized (outer ring counter-clockwise, holes
  // clockwise, no closing vertex) and repaired. One entry per polygon of a MultiPolygon (or of an
  // OSM multipolygon, or per loop of a ring split where it touched itself), in input order.
  std::vector<kernel::Polygon> polygons;
  // What the input said before normalization, per polygon (same order and frame as `polygons`):
  // the outer ring's first edge as written (its first position and the next distinct one), and
  // whether that ring ran clockwise. Lets a front-end orient a lot by the file's first edge
  // without reading the input again.
  std::vector<std::array<kernel::Vec2, 2>> first_edges;
  std::vector<bool> outer_clockwise;
  // GeoJSON properties: numbers -> double, bool, string, null -> monostate; nested objects and
  // arrays as compact JSON strings. OSM: every tag verbatim as a string, plus "osm_type" and
  // "osm_id" (docs/osm.md). A row of one table shared by the set's footprints: properties.map()
  // makes the AttributeMap of one building when it is built.
  PropertyRow properties;
  // 0-based position in the input (the FeatureCollection; for OSM, the order footprints were
  // assembled in).
  std::size_t feature_index = 0;
};

struct FootprintSet {
  // world = local + origin. x and y are whole meters; z is always 0.
  kernel::Vec3 origin;
  // The CRS of the world coordinates ("EPSG:32633"): the input's CRS when it is in ground meters,
  // the --out-crs asked for, or the UTM zone geographic and non-metric input was reprojected to;
  // empty when nothing names one.
  std::string crs;
  // The CRS the input's coordinates were in when they were reprojected ("OGC:CRS84" for
  // longitude/latitude); empty when nothing was reprojected.
  std::string source_crs;
  std::vector<Footprint> footprints;
  // Features left out because they were invalid (FootprintOptions::skip_invalid).
  std::size_t skipped_invalid = 0;
  // The same, by the code of the error that skipped each ("GEO022": a self-crossing ring,
  // "GEO028": a sliver, ...; docs/geojson.md lists them).
  std::map<std::string, std::size_t> skipped_by_code;
  // Repairs made, by kind: "duplicate_vertex", "collinear_vertex", "spike", "dropped_hole",
  // "split_touching_ring", "separated_touching_rings" (docs/geojson.md, "Repair policy"). Each
  // kind is warned about once per read; the counts are complete.
  std::map<std::string, std::size_t> repairs;
  // Map areas left out (FootprintOptions::leave_out_non_buildings), and the tags that said so
  // ("landuse=forest"; each once, in order of first use).
  std::size_t non_buildings = 0;
  std::vector<std::string> non_building_tags;
  // Warnings past FootprintOptions::max_warnings, by code: not listed, counted here so a report
  // can count every warning. The diagnostics end with a note per code that gives the same count
  // (so a failed read, which has no FootprintSet, still says how many).
  std::map<std::string, std::size_t> unlisted_warnings;
};

// What every footprint reader accepts (GeoJsonOptions and OsmOptions extend it).
struct FootprintOptions {
  // When set, local = world - origin for this origin (z ignored): lets several files share one
  // local frame. When unset, see shift_threshold.
  std::optional<kernel::Vec2> origin;
  // Data whose bounding box lies within +-shift_threshold meters of (0, 0) keeps origin (0, 0, 0);
  // otherwise the origin is the bounding-box centre rounded down to whole meters.
  double shift_threshold = 1e4;
  // Tolerance in meters handed to kernel::repair() (duplicate / collinear vertices).
  double repair_tolerance = 1e-7;
  // Slivers: a polygon with less area (m2) or a smaller width estimate 2 * area / perimeter (m)
  // is an error (GEO028). 0 turns the test off.
  double min_area = 1.0;
  double min_width = 0.5;
  // How far a hole's vertex that touches another ring is moved into its hole (GEO027 repair).
  double touch_separation = 0.01;
  // false: any invalid feature makes the whole read fail (exit code 1 for the CLI).
  // true: invalid features are dropped, each with one warning giving its first error.
  bool skip_invalid = false;
  // How a user asks for skip_invalid ("--keep-going"): named in the note of skipped features
  // and, when skip_invalid is off, suggested under the first feature error.
  std::string skip_invalid_flag;
  // Leave out a map export's areas that are not buildings (io/map_areas.h: landuse=forest,
  // natural=water, ...) before their geometry is checked, in a file where some feature is tagged
  // building or building:part: a forest's self-crossing ring, or one of 3 positions, then fails
  // nothing and decides nothing (degrees or meters, origin). Builders ask for it; `check` reads
  // every feature.
  bool leave_out_non_buildings = false;
  // The input's CRS when it names none ("--crs"), or, for input that names its own CRS or is
  // longitude/latitude, the CRS to build in when it is a projected CRS in ground meters (the
  // older meaning, kept). docs/geojson.md gives the whole rule.
  std::string crs;
  // The CRS to build in ("--out-crs", "EPSG:N", projected, in ground meters).
  std::string out_crs;
  // The property that names each building ("--id-attr": a register's identificatiebagpnd,
  // cleabs, bin, OBJECTID), used wherever a feature has it (a number or non-empty text); empty:
  // the GeoJSON id member, properties.id or name, the OSM element.
  std::string id_property;
  // Stop after this many errors; further warnings past max_warnings are counted, not listed.
  std::size_t max_errors = 50;
  std::size_t max_warnings = 100;
};

// A footprint as a reader found it, before CRS, origin, repair and ids. Its name in messages and
// its fallback id come from the reader (FootprintBuilder::feature_name...) when needed.
struct RawFootprint {
  std::string id;  // empty: FootprintBuilder::fallback_id()
  // World coordinates in the input's CRS, no closing vertex, as written.
  std::vector<kernel::Polygon> polygons;
  bool multi = false;  // a MultiPolygon: messages say "polygon K" rather than "polygon"
  bool failed = false;
};

constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

// Where in a raw footprint a message points; kNoIndex fields are absent.
struct FootprintPlace {
  std::size_t polygon = kNoIndex;
  std::size_t ring = kNoIndex;  // 0: the outer ring, k: hole k
  std::size_t position = kNoIndex;
  bool id = false;  // the id rather than the geometry
};

// "1.5", "17", "1e+300": shortest text that reads back as `v`.
std::string number_text(double v);
// `text` in double quotes, cut after 40 bytes.
std::string quote_text(std::string_view text);

// The shared diagnostics and finishing steps. A reader derives from it, fills `features_` (and
// `declared_crs_` when the input names its CRS), reports its own problems through report() and
// feature_issue(), then calls finish_features() and result().
class FootprintBuilder {
 public:
  FootprintBuilder(std::string source_name, const FootprintOptions& options,
                   std::string options_name);
  virtual ~FootprintBuilder() = default;
  FootprintBuilder(const FootprintBuilder&) = delete;
  FootprintBuilder& operator=(const FootprintBuilder&) = delete;

 protected:
  // Where a diagnostic points: `order` sorts diagnostics (GeoJSON: the byte offset; kNoIndex:
  // last), `span` is rendered.
  struct Location {
    std::size_t order = kNoIndex;
    base::Span span;
  };
  virtual Location locate(std::size_t feature, const FootprintPlace& place) = 0;
  // How messages name feature `index`: its name in other features' messages ("feature 3",
  // "way 123"), its label at the start of its own ("feature 3 (id \"b12\")"); and the id it gets
  // when it has none ("feature-3"). Made when needed rather than stored: a city has a million
  // features.
  virtual std::string feature_name(std::size_t index) const = 0;
  virtual std::string feature_label(std::size_t index) const { return feature_name(index); }
  virtual std::string fallback_id(std::size_t index) const = 0;
  Location whole_input() const { return {kNoIndex, base::Span::whole(name_)}; }

  void report(base::Severity severity, const char* code, std::string message, const Location& where,
              std::vector<std::string> notes = {});
  // A problem with feature `index`. An error fails the feature; under skip_invalid it becomes one
  // warning per feature (its first error) and the feature is skipped.
  void feature_issue(std::size_t index, bool is_error, const char* code, const std::string& message,
                     const Location& where, std::vector<std::string> notes = {});

  // A new raw footprint at the end of features_, with its empty row in properties_.
  RawFootprint& add_raw();
  // CRS -> origin -> repair -> ids, into result_. `crs_at` is where the input names its CRS.
  void finish_features(const Location& crs_at);
  base::Result<FootprintSet> result();

  std::string name_;
  const FootprintOptions& options_;
  std::string options_name_;  // "GeoJsonOptions": names options in messages
  std::vector<RawFootprint> features_;
  PropertyTable properties_;  // row k: the properties of features_[k]
  std::string declared_crs_;  // the input's CRS: "EPSG:N" or "OGC:CRS84"; empty: none named
  std::string empty_note_;    // GEO006's note when the input has no features at all
  FootprintSet result_;
  std::size_t errors_ = 0;
  bool stopped_ = false;

 private:
  struct Pending {
    std::size_t order;
    base::Diagnostic diagnostic;
  };
  // A feature error held while reading (FootprintOptions::leave_out_non_buildings) because the
  // feature may be a map area: whether it is depends on the whole file (map_export()).
  struct HeldIssue {
    std::size_t index;
    std::string code;
    std::string message;
    Location where;
    std::vector<std::string> notes;
  };
  bool hold_issue(std::size_t index, const char* code, const std::string& message,
                  const Location& where, std::vector<std::string>& notes);
  bool map_export(const std::shared_ptr<const PropertyTable>& properties) const;
  void release_held(const std::shared_ptr<const PropertyTable>& properties, bool map_export);
  void find_map_areas(const std::shared_ptr<const PropertyTable>& properties);
  void leave_out_map_area(std::size_t index, std::string tag);
  bool looks_like_degrees() const;
  std::optional<bool> degrees_vote(bool map_areas) const;
  kernel::Bounds2 valid_bounds() const;
  double centre_longitude(const kernel::Bounds2& box) const;
  void resolve_crs(const Location& crs_at);
  void to_geographic_range();
  void reproject_all(const std::string& from, const std::string& to, const Location& crs_at);
  void choose_origin();
  void repair(std::size_t index, Footprint& footprint);
  void repair_piece(std::size_t index, std::size_t p, kernel::Polygon piece, Footprint& footprint);
  void note_repair(std::size_t index, std::size_t p, const char* kind, const char* code,
                   const std::string& message, const FootprintPlace& place, std::size_t count);
  void reject_touching_rings(std::size_t index, std::size_t p, const kernel::Polygon& repaired);
  bool ids_distinct() const;
  void assign_ids_renaming();
  void assign_ids();
  std::string polygon_label(std::size_t index, std::size_t p) const;
  std::vector<std::string> local_note() const;
  std::string nothing_left_note() const;

  std::vector<Pending> pending_;
  // Per feature, whether it is a map area that is not a building (io/map_areas.h); empty when
  // no feature is tagged building or building:part.
  std::vector<bool> map_areas_;
  std::vector<HeldIssue> held_;
  bool holding_ = true;                           // until finish_features()
  std::set<std::string, std::less<>> area_tags_;  // FootprintSet::non_building_tags, as a set
  std::size_t warnings_ = 0;
  bool hinted_skip_ = false;
  std::map<std::string, bool, std::less<>> warned_repair_;
};

}  // namespace insula::io
