#include "io/cityjson_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <deque>
#include <vector>

#include "io/atomic_file.h"
#include "io/cityjson_objects.h"
#include "io/json_stream.h"
#include "shape/alike_parts.h"

namespace insula::io {
namespace {

using cityjson::Quantised;

// Writes the CityJSON text directly (no document tree): the city objects first
// (io/cityjson_objects.h), then the members in sorted order with the objects sorted by id, so the
// text is the one nlohmann::json would print for the same document. One vertex list for the whole
// file, quantised from the scene's local minimum corner.
class Writer {
 public:
  Writer(const shape::Scene& scene, const cityjson::SceneSize& size,
         const CityJsonOptions& options);
  void write(std::string& out);

 private:
  void write_metadata(JsonStream& json) const;

  const shape::Scene& scene_;
  CityJsonOptions options_;
  kernel::Vec3 min_{};  // local minimum corner of every finite vertex
  cityjson::CityObjects objects_;
  // Buildings with their alike parts merged (options_), kept for the attributes objects_ points at.
  std::deque<shape::Building> merged_;
};

Writer::Writer(const shape::Scene& scene, const cityjson::SceneSize& size,
               const CityJsonOptions& options)
    : scene_(scene), options_(options), min_(size.minimum), objects_(min_) {
  objects_.pool().reserve(size.vertices);
  // About 4 corners a face (quads, triangles and a few larger faces); more only cost a copy.
  objects_.reserve_rings(size.faces, 4 * size.faces);
  objects_.reserve_ids(size.objects);
}

void Writer::write_metadata(JsonStream& json) const {
  json.begin_object();
  const cityjson::VertexPool& pool = objects_.pool();
  if (!pool.vertices().empty()) {
    const kernel::Vec3 t = scene_.origin + min_;
    const std::array<double, 3> translate{t.x, t.y, t.z};
    json.key("geographicalExtent").begin_array();
    for (const Quantised* corner : {&pool.low(), &pool.high()}) {
      for (std::size_t k = 0; k < 3; ++k) {
        json.number(translate[k] + static_cast<double>((*corner)[k]) * cityjson::kScale);
      }
    }
    json.end_array();
  }
  const std::string reference_system = cityjson_reference_system(scene_.crs);
  if (!reference_system.empty()) json.key("referenceSystem").string(reference_system);
  json.end_object();
}

void Writer::write(std::string& out) {
  const std::vector<shape::Building>& buildings = scene_.buildings;
  for (std::size_t b = 0; b < buildings.size(); ++b) {
    cityjson::CityObjects::prefetch_ahead(buildings, b);
    if (options_.merge_alike_parts && shape::has_alike_parts(buildings[b])) {
      shape::Building& merged = merged_.emplace_back(shape::merge_alike_parts(buildings[b]));
      objects_.add_building(merged, b);
      // The objects keep pointers to the attributes alone: the geometry is theirs now.
      for (shape::Part& part : merged.parts) part.mesh = kernel::Mesh();
      merged.plans.clear();
    } else {
      objects_.add_building(buildings[b], b);
    }
  }
  // The objects, then about 20 bytes per vertex ("[123456,234567,3456],").
  out.reserve(out.size() + objects_.text_size_estimate() + 24 * objects_.pool().vertices().size() +
              512);
  JsonStream json(out);
  json.begin_object().key("CityObjects");
  objects_.write_objects(json);
  json.key("metadata");
  write_metadata(json);
  json.key("transform");
  cityjson::write_transform(json, scene_.origin + min_);
  json.key("type").string("CityJSON").key("version").string("2.0");
  json.key("vertices");
  objects_.write_vertices(json);
  json.end_object();
}

}  // namespace

std::string cityjson_reference_system(const std::string& crs) {
  static constexpr std::string_view kPrefix = "https://www.opengis.net/def/crs/";
  if (crs.starts_with(kPrefix) || crs.starts_with("http://www.opengis.net/def/crs/")) return crs;
  std::string upper = crs;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  std::string_view rest = upper;
  if (!rest.starts_with("EPSG:")) return {};
  rest.remove_prefix(5);
  if (rest.starts_with(':')) rest.remove_prefix(1);
  if (rest.empty() || rest.size() > 9 ||
      !std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return {};
  }
  return std::string(kPrefix) + "EPSG/0/" + std::string(rest);
}

// Shared-mesh instances are placed part by part as they are measured and added, with no copy of
// the scene (shape::expand_instances()) nor a pass to look for them.
std::string cityjson_text(const shape::Scene& scene, const CityJsonOptions& options) {
  Writer writer(scene, cityjson::measure(scene), options);
  std::string out;
  writer.write(out);
  out += '\n';
  return out;
}

std::string write_cityjson(const shape::Scene& scene, const std::filesystem::path& path,
                           const CityJsonOptions& options) {
  return write_file_atomically(path, cityjson_text(scene, options));
}

}  // namespace insula::io
