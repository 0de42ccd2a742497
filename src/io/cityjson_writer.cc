#include "io/cityjson_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <vector>

#include "io/atomic_file.h"
#include "io/cityjson_objects.h"
#include "io/json_stream.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

using cityjson::Quantised;

// Writes the CityJSON text directly (no document tree): the city objects first
// (io/cityjson_objects.h), then the members in sorted order with the objects sorted by id, so the
// text is the one nlohmann::json would print for the same document. One vertex list for the whole
// file, quantised from the scene's local minimum corner.
class Writer {
 public:
  explicit Writer(const shape::Scene& scene);
  void write(std::string& out);

 private:
  void write_metadata(JsonStream& json) const;

  const shape::Scene& scene_;
  kernel::Vec3 min_{};  // local minimum corner of every finite vertex
  cityjson::CityObjects objects_;
};

Writer::Writer(const shape::Scene& scene)
    : scene_(scene), min_(cityjson::local_minimum(scene)), objects_(min_) {
  std::size_t vertices = 0;
  std::size_t corners = 0;
  std::size_t parts = 0;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      vertices += part.mesh.vertex_count();
      for (std::size_t f = 0; f < part.mesh.face_count(); ++f) corners += part.mesh.face(f).size();
    }
    parts += building.parts.size() + 1;
  }
  objects_.pool().reserve(vertices);
  // About 12 bytes a corner ("123456,", brackets and a semantic value) and 160 an object.
  objects_.reserve_text(12 * corners + 160 * parts);
}

void Writer::write_metadata(JsonStream& json) const {
  json.begin_object();
  const std::vector<Quantised>& vertices = objects_.pool().vertices();
  if (!vertices.empty()) {
    Quantised lo = vertices.front();
    Quantised hi = lo;
    for (const Quantised& q : vertices) {
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    }
    const kernel::Vec3 t = scene_.origin + min_;
    const std::array<double, 3> translate{t.x, t.y, t.z};
    json.key("geographicalExtent").begin_array();
    for (const Quantised* corner : {&lo, &hi}) {
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
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    objects_.add_building(scene_.buildings[b], b);
  }
  // The objects, then about 20 bytes per vertex ("[123456,234567,3456],").
  out.reserve(out.size() + objects_.text_size() + 24 * objects_.pool().vertices().size() + 512);
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

std::string cityjson_text(const shape::Scene& input) {
  shape::Scene expanded;  // shared-mesh instances written as plain geometry
  Writer writer(shape::expand_instances(input, expanded));
  std::string out;
  writer.write(out);
  out += '\n';
  return out;
}

std::string write_cityjson(const shape::Scene& scene, const std::filesystem::path& path) {
  return write_file_atomically(path, cityjson_text(scene));
}

}  // namespace insula::io
