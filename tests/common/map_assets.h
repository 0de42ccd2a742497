// Assets by name for tests of operations that insert them, as the app's file-backed provider
// would serve them; a missing name fails as a missing file would.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "kernel/mesh.h"
#include "shape/operation.h"

namespace insula::testing {

class MapAssets : public shape::AssetProvider {
 public:
  std::map<std::string, std::shared_ptr<const kernel::Mesh>, std::less<>> meshes;
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    auto it = meshes.find(name);
    if (it != meshes.end()) return it->second;
    error = "cannot open '" + std::string(name) + ".obj'";
    return nullptr;
  }
};

}  // namespace insula::testing
