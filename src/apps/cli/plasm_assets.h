// PLaSM parts as assets (issue 13): `FILE.psm#EXPRESSION` names, found in the asset folders,
// evaluated by lang/plasm (parts.h) once per name; every other name goes to `next`.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "shape/operation.h"

namespace insula::cli {

class PlasmAssets : public shape::AssetProvider {
 public:
  PlasmAssets(std::vector<std::string> folders, const shape::AssetProvider* next)
      : folders_(std::move(folders)), next_(next) {}

  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override;

 private:
  struct Entry {
    std::shared_ptr<const kernel::Mesh> mesh;
    std::string error;
  };
  Entry load(const std::string& name) const;

  std::vector<std::string> folders_;
  const shape::AssetProvider* next_;
  mutable std::mutex mutex_;  // CGA derives lots on several threads
  mutable std::map<std::string, Entry, std::less<>> cache_;
};

// True when an asset name is a PLaSM part (its file part ends in .psm).
bool is_plasm_part(std::string_view name);

}  // namespace insula::cli
