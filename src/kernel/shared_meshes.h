// Meshes kept by content, so that meshes alike in every vertex and face become one shared mesh
// (equal CGA i() results placed as instances of one mesh, issue 21).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "kernel/mesh.h"

namespace insula::kernel {

class SharedMeshes {
 public:
  // The first mesh given that is alike `mesh` (kernel::same_content), or `mesh` itself.
  std::shared_ptr<const Mesh> share(std::shared_ptr<const Mesh> mesh) {
    std::vector<std::shared_ptr<const Mesh>>& alike = by_hash_[content_hash(*mesh)];
    for (const auto& known : alike) {
      if (same_content(*known, *mesh)) return known;
    }
    alike.push_back(mesh);
    return mesh;
  }

 private:
  std::map<std::uint64_t, std::vector<std::shared_ptr<const Mesh>>> by_hash_;
};

}  // namespace insula::kernel
