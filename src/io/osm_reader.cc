// OpenStreetMap footprints through libosmium: pass 1 reads relations only and keeps building
// multipolygons; pass 2 reads nodes and ways, stores node locations (flex_mem index), assembles
// each closed building way as it comes and each multipolygon when its last member way has been
// read, and hands the results to the consumer in batches. read_osm() then runs the finishing
// steps every footprint reader shares (io/footprint_finish.h). docs/osm.md has the details.
#include "io/osm_reader.h"

// GCC 12 warns falsely inside libosmium's area builder (a strlen it cannot see is guarded).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#include <osmium/area/assembler.hpp>
#include <osmium/area/problem_reporter.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/io/error.hpp>
#include <osmium/relations/manager_util.hpp>
#include <osmium/relations/relations_manager.hpp>
#include <osmium/visitor.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <map>
#include <optional>

namespace insula::io {

std::string OsmFeature::element() const {
  return (relation ? "relation " : "way ") + std::to_string(id);
}

namespace {

bool is_building(const osmium::TagList& tags) {
  return tags.has_key("building") || tags.has_key("building:part");
}

std::string location_text(const osmium::Location& location) {
  if (!location.valid()) return "(no location)";
  return "(" + number_text(location.lon()) + ", " + number_text(location.lat()) + ")";
}

// Keeps the first problem libosmium's assembler reports for the object being assembled: the
// reason given when no area comes out.
class FirstProblem : public osmium::area::ProblemReporter {
 public:
  void clear() {
    code_.clear();
    message_.clear();
  }
  const std::string& code() const { return code_; }
  const std::string& message() const { return message_; }

  void report_duplicate_node(osmium::object_id_type node_id1, osmium::object_id_type node_id2,
                             osmium::Location location) override {
    note("OSM004", "nodes " + std::to_string(node_id1) + " and " + std::to_string(node_id2) +
                       " lie at the same place " + location_text(location));
  }
  void report_intersection(osmium::object_id_type way1_id, osmium::Location way1_seg_start,
                           osmium::Location way1_seg_end, osmium::object_id_type way2_id,
                           osmium::Location way2_seg_start, osmium::Location way2_seg_end,
                           osmium::Location intersection) override {
    (void)way1_seg_start;
    (void)way1_seg_end;
    (void)way2_seg_start;
    (void)way2_seg_end;
    note("OSM004", way1_id == way2_id
                       ? "way " + std::to_string(way1_id) + " crosses itself at " +
                             location_text(intersection)
                       : "ways " + std::to_string(way1_id) + " and " + std::to_string(way2_id) +
                             " cross at " + location_text(intersection));
  }
  void report_duplicate_segment(const osmium::NodeRef& nr1, const osmium::NodeRef& nr2) override {
    note("OSM004", "the segment from node " + std::to_string(nr1.ref()) + " to node " +
                       std::to_string(nr2.ref()) + " is used twice");
  }
  void report_overlapping_segment(const osmium::NodeRef& nr1, const osmium::NodeRef& nr2) override {
    note("OSM004", "segments at nodes " + std::to_string(nr1.ref()) + " and " +
                       std::to_string(nr2.ref()) + " overlap");
  }
  void report_ring_not_closed(const osmium::NodeRef& nr, const osmium::Way* way) override {
    note("OSM004", "a ring is not closed: it ends at node " + std::to_string(nr.ref()) +
                       (way != nullptr ? " of way " + std::to_string(way->id()) : std::string()) +
                       " " + location_text(nr.location()));
  }
  void report_invalid_location(osmium::object_id_type way_id,
                               osmium::object_id_type node_id) override {
    note("OSM003", "node " + std::to_string(node_id) + " of way " + std::to_string(way_id) +
                       " has no location (not in the file, or beyond +-180 x +-90)");
  }

 private:
  void note(const char* code, std::string message) {
    if (!code_.empty()) return;
    code_ = code;
    message_ = std::move(message);
  }
  std::string code_;
  std::string message_;
};

using LocationIndex =
    osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
using LocationHandler = osmium::handler::NodeLocationsForWays<LocationIndex>;

// Building multipolygons from pass 1, their member ways in pass 2, closed building ways as they
// come. RelationsManager keeps the relations and, until a relation is complete, its member ways.
class BuildingCollector
    : public osmium::relations::RelationsManager<BuildingCollector, false, true, false> {
 public:
  BuildingCollector(const OsmStreamOptions& options,
                    const std::function<void(std::vector<OsmFeature>&)>& consume)
      : options_(options), consume_(consume) {
    config_.problem_reporter = &problem_;
    config_.create_empty_areas = false;
  }

  bool new_relation(const osmium::Relation& relation) const {
    const char* type = relation.tags().get_value_by_key("type");
    if (type == nullptr || std::strcmp(type, "multipolygon") != 0) return false;
    if (!is_building(relation.tags())) return false;
    return std::any_of(
        relation.members().cbegin(), relation.members().cend(),
        [](const osmium::RelationMember& m) { return m.type() == osmium::item_type::way; });
  }

  void complete_relation(const osmium::Relation& relation) {
    std::vector<const osmium::Way*> ways;
    for (const osmium::RelationMember& member : relation.members()) {
      if (member.ref() != 0) ways.push_back(this->get_member_way(member.ref()));
    }
    OsmFeature& feature = begin(true, relation.id(), relation.tags());
    if (!missing_location(feature, ways)) {
      problem_.clear();
      osmium::area::Assembler assembler{config_};
      assemble(feature, assembler(relation, ways, scratch_));
    }
    finish_one();
  }

  // Ways outside every building multipolygon: an open one tagged as a building is a broken
  // outline (inside a multipolygon it is one piece of a ring).
  void way_not_in_any_relation(const osmium::Way& way) {
    if (!is_building(way.tags()) || way.tags().has_tag("area", "no") || way.is_closed()) return;
    OsmFeature& feature = begin(false, way.id(), way.tags());
    feature.code = "OSM002";
    feature.problem = way.nodes().empty()
                          ? std::string("has no nodes")
                          : "is not closed: it starts at node " +
                                std::to_string(way.nodes().front().ref()) + " and ends at node " +
                                std::to_string(way.nodes().back().ref());
    finish_one();
  }

  void after_way(const osmium::Way& way) {
    if (!is_building(way.tags()) || way.tags().has_tag("area", "no") || !way.is_closed()) return;
    OsmFeature& feature = begin(false, way.id(), way.tags());
    const std::vector<const osmium::Way*> ways{&way};
    if (way.nodes().size() < 4) {
      feature.code = "OSM002";
      const std::size_t n = way.nodes().size();
      feature.problem = "has " + std::to_string(n) + (n == 1 ? " node" : " nodes") +
                        "; a closed outline needs at least 4 (3 corners and the first again)";
    } else if (!missing_location(feature, ways)) {
      problem_.clear();
      osmium::area::Assembler assembler{config_};
      assemble(feature, assembler(way, scratch_));
      if (feature.polygons.size() == 1 && feature.polygons[0].holes.empty()) {
        follow_way(way, feature.polygons[0].outer);
      }
    }
    finish_one();
  }

  // Multipolygons whose member ways never came (cut off by the extract's border).
  void report_incomplete() {
    this->for_each_incomplete_relation([&](const osmium::relations::RelationHandle& handle) {
      OsmFeature& feature = begin(true, handle->id(), handle->tags());
      feature.code = "OSM005";
      std::string missing;
      std::size_t count = 0;
      for (const osmium::RelationMember& member : handle->members()) {
        if (member.ref() == 0 || this->get_member_way(member.ref()) != nullptr) continue;
        if (count++ == 0) missing = std::to_string(member.ref());
      }
      feature.problem = "member way " + missing +
                        (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") +
                        " is not in the file";
      finish_one();
    });
  }

  void flush_batch() {
    if (batch_.empty()) return;
    consume_(batch_);
    batch_.clear();
  }

  OsmStreamStats stats;

 private:
  OsmFeature& begin(bool relation, osmium::object_id_type id, const osmium::TagList& tags) {
    OsmFeature& feature = batch_.emplace_back();
    feature.relation = relation;
    feature.id = id;
    for (const osmium::Tag& tag : tags) {
      if (relation && std::strcmp(tag.key(), "type") == 0) continue;
      feature.tags.emplace_back(tag.key(), tag.value());
    }
    return feature;
  }

  void finish_one() {
    const OsmFeature& feature = batch_.back();
    ++stats.features;
    ++(feature.relation ? stats.relations : stats.ways);
    if (batch_.size() >= options_.batch_size) flush_batch();
  }

  // The assembler would stop at the first node without a location anyway; naming it here says
  // which node of which way.
  static bool missing_location(OsmFeature& feature, const std::vector<const osmium::Way*>& ways) {
    for (const osmium::Way* way : ways) {
      for (const osmium::NodeRef& node : way->nodes()) {
        if (node.location().valid()) continue;
        feature.code = "OSM003";
        feature.problem = "node " + std::to_string(node.ref()) +
                          (feature.relation ? " of way " + std::to_string(way->id()) : "") +
                          " has no location (not in the file, or beyond +-180 x +-90)";
        return true;
      }
    }
    return false;
  }

  void assemble(OsmFeature& feature, bool ok) {
    bool any = false;
    if (ok) {
      for (const osmium::Area& area : scratch_.select<osmium::Area>()) {
        for (const osmium::OuterRing& outer : area.outer_rings()) {
          kernel::Polygon& polygon = feature.polygons.emplace_back();
          add_ring(outer, polygon.outer);
          for (const osmium::InnerRing& inner : area.inner_rings(outer)) {
            add_ring(inner, polygon.holes.emplace_back());
          }
          any = true;
        }
      }
    }
    scratch_.clear();
    if (any) return;
    feature.polygons.clear();
    feature.code = problem_.code().empty() ? "OSM004" : problem_.code();
    feature.problem = problem_.message().empty()
                          ? std::string("no polygon could be assembled")
                          : "no polygon could be assembled: " + problem_.message();
  }

  // The assembler starts a ring at a node of its own choosing; a closed way's ring starts at the
  // way's first node and runs its way instead, as GeoJSON exports of the way write it, so a CGA
  // lot's first edge (its scope x axis, docs/cga-derivation.md) is the same from either file.
  static void follow_way(const osmium::Way& way, kernel::Ring& ring) {
    const auto at = [](const osmium::NodeRef& node) {
      return kernel::Vec2{node.location().lon(), node.location().lat()};
    };
    const auto first = std::find(ring.begin(), ring.end(), at(way.nodes()[0]));
    if (first == ring.end()) return;  // the assembler dropped that node (a spike)
    std::rotate(ring.begin(), first, ring.end());
    // The way's direction by its signed area: its second node may repeat the first or be a
    // spike's tip the assembler dropped.
    kernel::Ring nodes;
    nodes.reserve(way.nodes().size());
    for (const osmium::NodeRef& node : way.nodes()) nodes.push_back(at(node));
    if ((kernel::signed_area(nodes) < 0) != (kernel::signed_area(ring) < 0)) {
      std::reverse(ring.begin() + 1, ring.end());
    }
  }

  template <typename TRing>
  static void add_ring(const TRing& ring, kernel::Ring& out) {
    for (const osmium::NodeRef& node : ring) {
      out.push_back({node.location().lon(), node.location().lat()});
    }
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  }

  const OsmStreamOptions& options_;
  const std::function<void(std::vector<OsmFeature>&)>& consume_;
  osmium::area::AssemblerConfig config_;
  FirstProblem problem_;
  osmium::memory::Buffer scratch_{4096, osmium::memory::Buffer::auto_grow::yes};
  std::vector<OsmFeature> batch_;
};

bool ends_with(const std::string& text, const char* suffix) {
  const std::size_t n = std::strlen(suffix);
  return text.size() >= n && text.compare(text.size() - n, n, suffix) == 0;
}

}  // namespace

bool is_osm_path(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* suffix : {".osm", ".pbf", ".osm.bz2", ".osm.gz", ".osc", ".opl"}) {
    if (ends_with(lower, suffix)) return true;
  }
  return false;
}

base::Result<OsmStreamStats> stream_osm(
    const std::string& path, const OsmStreamOptions& options,
    const std::function<void(std::vector<OsmFeature>&)>& consume) {
  const auto fail = [&](base::Span span, std::string message) {
    std::vector<base::Diagnostic> out{base::Diagnostic::error("OSM001", std::move(message), span)};
    return base::Result<OsmStreamStats>::failure(std::move(out));
  };
  try {
    const osmium::io::File file{path};
    BuildingCollector collector(options, consume);
    osmium::relations::read_relations(file, collector);
    LocationIndex index;
    LocationHandler locations{index};
    locations.ignore_errors();  // a missing node becomes an invalid location, named per feature
    osmium::io::Reader reader{file, osmium::osm_entity_bits::node | osmium::osm_entity_bits::way,
                              osmium::io::read_meta::no};
    osmium::apply(reader, locations, collector.handler());
    reader.close();
    collector.report_incomplete();
    collector.flush_batch();
    return base::Result<OsmStreamStats>(collector.stats, {});
  } catch (const osmium::xml_error& e) {
    return fail(e.line > 0 ? base::Span::at(path, static_cast<std::uint32_t>(e.line),
                                            static_cast<std::uint32_t>(e.column + 1))
                           : base::Span::whole(path),
                "not valid OSM XML: " + e.error_string);
  } catch (const osmium::pbf_error& e) {
    return fail(base::Span::whole(path),
                std::string("not a valid .osm.pbf file (truncated or damaged?): ") + e.what());
  } catch (const std::exception& e) {
    return fail(base::Span::whole(path),
                std::string("cannot read OpenStreetMap data: ") + e.what());
  }
}

namespace {

class OsmBuilder : public FootprintBuilder {
 public:
  OsmBuilder(const std::string& path, const OsmOptions& options)
      : FootprintBuilder(path, options, "OsmOptions"), path_(path), osm_options_(options) {
    empty_note_ =
        "the file has no closed way or multipolygon relation tagged building or "
        "building:part";
  }

  base::Result<FootprintSet> run() {
    declared_crs_ = "OGC:CRS84";  // OpenStreetMap is WGS 84 longitude/latitude
    base::Result<OsmStreamStats> streamed =
        stream_osm(path_, osm_options_.stream, [&](std::vector<OsmFeature>& batch) {
          for (OsmFeature& feature : batch) add(feature);
        });
    if (!streamed.ok()) {
      for (const base::Diagnostic& d : streamed.diagnostics()) {
        report(d.severity, d.code.c_str(), d.message, {kNoIndex, d.span}, d.notes);
      }
      return result();
    }
    finish_features(whole_input());
    return result();
  }

 private:
  Location locate(std::size_t feature, const FootprintPlace&) override {
    return {feature, base::Span::whole(name_)};
  }
  // "way 123" for the id "way/123" (OsmFeature::element()).
  std::string feature_name(std::size_t index) const override {
    std::string name = features_[index].id;
    name[name.find('/')] = ' ';
    return name;
  }
  std::string fallback_id(std::size_t index) const override { return features_[index].id; }

  void add(OsmFeature& feature) {
    const std::size_t index = features_.size();
    RawFootprint& raw = add_raw();
    raw.id = (feature.relation ? "relation/" : "way/") + std::to_string(feature.id);
    raw.multi = feature.polygons.size() > 1;
    raw.polygons = std::move(feature.polygons);
    for (const auto& [key, value] : feature.tags) properties_.set_text(index, key, value);
    properties_.set_text(index, "osm_type", feature.relation ? "relation" : "way");
    properties_.set_text(index, "osm_id", std::to_string(feature.id));
    if (!feature.problem.empty()) {
      std::vector<std::string> notes;
      if (feature.code == "OSM003" && !explained_cut_) {
        // Most often the building crosses the border of an extract cut with a simple strategy.
        notes.push_back(
            "an extract cut at a border with osmium extract's 'simple' strategy (or a bounding-box "
            "download) leaves out the nodes outside it; its default, 'complete_ways', keeps every "
            "way whole");
        explained_cut_ = true;
      }
      feature_issue(index, true, feature.code.c_str(), feature.problem,
                    {index, base::Span::whole(name_)}, std::move(notes));
    }
  }

  std::string path_;
  const OsmOptions& osm_options_;
  bool explained_cut_ = false;  // the first OSM003 says what usually causes it
};

}  // namespace

base::Result<FootprintSet> read_osm(const std::string& path, const OsmOptions& options) {
  return OsmBuilder(path, options).run();
}

}  // namespace insula::io
