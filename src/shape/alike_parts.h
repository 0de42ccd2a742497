// Parts alike in everything but their geometry, merged into one part (their meshes appended).
// A CGA building is hundreds of terminals of a dozen kinds (160 `Plaster` walls); a part per
// terminal is noise to a GIS user and costs memory per terminal, so the formats that name parts
// (CityJSON, 3D Tiles) take one part per kind. Shared by the front-ends that make such parts (CGA,
// graphs) and by the writers that merge a scene made part by part (docs/formats.md, CityJSON).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "shape/scene.h"

namespace insula::shape {

// The index of one building's parts by (name, kind, attributes, texture mapping). It holds no
// reference to the parts, so it stays valid while the building moves (a vector of buildings grows).
class AlikeParts {
 public:
  // The index in `parts` of the part with this name, kind, attributes and uv map, appended (with
  // no geometry) when there is none yet.
  std::size_t index(std::vector<Part>& parts, std::string_view name, PartKind kind,
                    const AttributeMap& attributes, const std::optional<UvMap>& uv);
  // `part` appended to `parts`, or its mesh appended to the alike part's. An instance of a shared
  // mesh stays a part of its own (writers place it on the GPU).
  void add(std::vector<Part>& parts, Part&& part);

 private:
  using Key = std::tuple<std::string, PartKind, AttributeMap, std::string>;
  std::map<Key, std::size_t> index_;
};

// Whether two of the building's parts (not instances) are alike.
bool has_alike_parts(const Building& building);
// The building with its alike parts merged, in the order of each kind's first part.
Building merge_alike_parts(const Building& building);

}  // namespace insula::shape
