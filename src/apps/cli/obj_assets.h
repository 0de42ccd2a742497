// OBJ assets named by CGA's I(), Pshape() and i() and by graphs' shape.insert, read from the
// program's folder once each (thread-safe: lots derive in parallel).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "shape/operation.h"

namespace insula::cli {

class ObjAssets : public shape::AssetProvider {
 public:
  explicit ObjAssets(std::filesystem::path dir) : dir_(std::move(dir)) {}

  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto it = cache_.find(std::string(name));
    if (it == cache_.end()) it = cache_.emplace(std::string(name), load(name)).first;
    if (!it->second.mesh) error = it->second.error;
    return it->second.mesh;
  }

 private:
  struct Entry {
    std::shared_ptr<const kernel::Mesh> mesh;
    std::string error;
  };
  Entry load(std::string_view name) const;

  std::filesystem::path dir_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, Entry> cache_;
};

}  // namespace insula::cli
