#include "io/cityjsonseq_writer.h"

#include <utility>

#include "io/atomic_file.h"
#include "io/cityjson_objects.h"
#include "io/cityjson_writer.h"
#include "io/json_stream.h"
#include "shape/alike_parts.h"
#include "shape/part_mesh.h"

namespace insula::io {

CityJsonSeqWriter::CityJsonSeqWriter(kernel::Vec3 origin, std::string crs,
                                     std::optional<kernel::Vec3> translate)
    : origin_(origin),
      crs_(std::move(crs)),
      translate_(translate.value_or(origin)),
      objects_(std::make_unique<cityjson::CityObjects>(translate_ - origin_)) {}

CityJsonSeqWriter::~CityJsonSeqWriter() = default;

// Members in sorted order, as nlohmann::json would print them.
std::string CityJsonSeqWriter::header_line() const {
  std::string out;
  JsonStream json(out);
  json.begin_object().key("CityObjects").begin_object().end_object();
  json.key("metadata").begin_object();
  const std::string reference_system = cityjson_reference_system(crs_);
  if (!reference_system.empty()) json.key("referenceSystem").string(reference_system);
  json.end_object().key("transform");
  cityjson::write_transform(json, translate_);
  json.key("type").string("CityJSON").key("version").string("2.0");
  json.key("vertices").begin_array().end_array().end_object();
  out += '\n';
  return out;
}

std::string CityJsonSeqWriter::feature_line(const shape::Building& building) {
  objects_->clear();
  const std::string id = objects_->add_building(building, features_++);
  std::string out;
  JsonStream json(out);
  json.begin_object().key("CityObjects");
  objects_->write_objects(json);
  json.key("id").string(id).key("type").string("CityJSONFeature").key("vertices");
  objects_->write_vertices(json);
  json.end_object();
  out += '\n';
  return out;
}

void CityJsonSeqWriter::avoid(std::shared_ptr<const std::unordered_set<std::string>> building_ids) {
  objects_->avoid(std::move(building_ids));
}

std::string cityjsonseq_text(const shape::Scene& input, const CityJsonOptions& options) {
  shape::Scene expanded;  // instances expanded once, so local_minimum() sees them too
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  CityJsonSeqWriter writer(scene.origin, scene.crs, scene.origin + cityjson::local_minimum(scene));
  std::string out = writer.header_line();
  for (const shape::Building& building : scene.buildings) {
    out += writer.feature_line(options.merge_alike_parts && shape::has_alike_parts(building)
                                   ? shape::merge_alike_parts(building)
                                   : building);
  }
  return out;
}

std::string write_cityjsonseq(const shape::Scene& scene, const std::filesystem::path& path,
                              const CityJsonOptions& options) {
  return write_file_atomically(path, cityjsonseq_text(scene, options));
}

}  // namespace insula::io
