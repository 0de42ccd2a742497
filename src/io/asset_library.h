// The asset provider of every front-end (docs/assets.md): names resolved by a resolver
// (AssetSearch for CGA and graphs, the sandboxed asset folders for Lua), files read by
// import_asset once per name and shared. Thread-safe: lots derive in parallel, and different
// assets import concurrently while a second request for the same name waits for the first.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/asset_import.h"
#include "io/asset_search.h"
#include "shape/operation.h"

namespace insula::io {

class AssetLibrary : public shape::AssetProvider {
 public:
  // The file a name denotes, or nullopt with `error` saying why (e.g. where it looked).
  using Resolver =
      std::function<std::optional<std::filesystem::path>(std::string_view, std::string& error)>;
  // What find() gives for an asset that cannot be had. kError: null and the reason, so the
  // operation fails (Lua's componentFromFile). kNothing: an empty mesh, so an insert inserts
  // nothing, as CityEngine does; the failure is kept for failures() to report once per name.
  enum class Missing { kError, kNothing };

  AssetLibrary(Resolver resolve, Missing missing);
  // Names resolved as CityEngine resolves them (`search` must outlive the library).
  AssetLibrary(const AssetSearch& search, Missing missing);

  // The asset's mesh without its material ids (the scene's material table does not know them;
  // semantic classes stay), per shape::AssetProvider.
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override;
  // The asset with its materials, or null with `error` set (whatever `missing` says).
  std::shared_ptr<const ImportedAsset> asset(std::string_view name, std::string& error) const;

  struct Failure {
    std::string name;
    std::string error;      // "asset 'x.obj' not found (looked in ...)" or the import's reason
    std::size_t count = 0;  // requests that met it
  };
  // Every name that could not be had, sorted by name.
  std::vector<Failure> failures() const;

 private:
  struct Entry {
    std::shared_ptr<const ImportedAsset> asset;
    std::shared_ptr<const kernel::Mesh> mesh;  // asset->mesh with material ids 0
    std::string error;
  };
  const Entry& entry(std::string_view name) const;
  Entry load(const std::string& name) const;

  Resolver resolve_;
  Missing missing_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::shared_future<Entry>, std::less<>> cache_;
  mutable std::map<std::string, std::size_t, std::less<>> failed_;  // name -> requests
};

}  // namespace insula::io
