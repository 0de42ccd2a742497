// CityJSONSeq writer (`.city.jsonl`, CityJSON 2.0 "Text sequences"; docs/formats.md,
// "CityJSONSeq"): line 1 is a "CityJSON" object with the transform and the metadata and no city
// objects or vertices; every other line is one "CityJSONFeature" per building: the "Building" and
// its parts as io/cityjson_writer.h writes them, with the line's own integer vertices (indices
// local to the line) under the first line's transform. Compact JSON, each line ending in "\n".
// The transform is fixed before any building is seen, so a streaming pipeline can write a line per
// building as it comes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>

#include "io/cityjson_writer.h"
#include "kernel/vec.h"
#include "shape/scene.h"

namespace insula::io {

namespace cityjson {
class CityObjects;
}

class CityJsonSeqWriter {
 public:
  // `origin` and `crs` as in shape::Scene. The transform's scale is 0.001 (1 mm) and its translate
  // `translate` (world coordinates), by default `origin`.
  CityJsonSeqWriter(kernel::Vec3 origin, std::string crs,
                    std::optional<kernel::Vec3> translate = std::nullopt);
  ~CityJsonSeqWriter();
  CityJsonSeqWriter(const CityJsonSeqWriter&) = delete;
  CityJsonSeqWriter& operator=(const CityJsonSeqWriter&) = delete;

  // The first line (with its "\n").
  std::string header_line() const;
  // The line of one building of a scene with the constructor's origin (local coordinates; a part
  // that instances a shared mesh is expanded), with its "\n". Ids stay unique across the lines of
  // one writer: an unnamed building is "building<n>" (n = the lines written before), a repeated
  // id gets a "-2", "-3", ... suffix.
  std::string feature_line(const shape::Building& building);
  // The ids of the buildings other writers put on other lines of the same file (a tile job writes
  // each tile's lines apart): part ids avoid them.
  void avoid(std::shared_ptr<const std::unordered_set<std::string>> building_ids);

 private:
  kernel::Vec3 origin_;
  std::string crs_;
  kernel::Vec3 translate_;
  std::unique_ptr<cityjson::CityObjects> objects_;
  std::size_t features_ = 0;
};

// The whole scene as CityJSONSeq text: the header, then one line per building in scene order. The
// translate is the scene's origin plus its local minimum corner, as in cityjson_text(), so both
// files hold the same vertex coordinates.
std::string cityjsonseq_text(const shape::Scene& scene, const CityJsonOptions& options = {});

// Writes `path` atomically. Returns an empty string on success, else a message naming the file.
std::string write_cityjsonseq(const shape::Scene& scene, const std::filesystem::path& path,
                              const CityJsonOptions& options = {});

}  // namespace insula::io
