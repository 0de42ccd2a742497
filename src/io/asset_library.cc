#include "io/asset_library.h"

namespace insula::io {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(std::string_view name) {
  std::string out(1, '\'');
  out.append(name);
  out.push_back('\'');
  return out;
}

}  // namespace

AssetLibrary::AssetLibrary(Resolver resolve, Missing missing)
    : resolve_(std::move(resolve)), missing_(missing) {}

AssetLibrary::AssetLibrary(const AssetSearch& search, Missing missing)
    : AssetLibrary(
          [&search](std::string_view name, std::string& error) -> std::optional<fs::path> {
            if (auto path = search.resolve(name)) return path;
            std::string places;
            for (const fs::path& p : search.candidates(name)) {
              if (!places.empty()) places += ", ";
              places += p.string();
            }
            error = "asset " + in_quotes(name) + " not found" +
                    (places.empty() ? std::string() : " (looked in " + places + ")");
            return std::nullopt;
          },
          missing) {}

AssetLibrary::Entry AssetLibrary::load(const std::string& name) const {
  Entry out;
  const std::optional<fs::path> path = resolve_(name, out.error);
  if (!path) {
    if (out.error.empty()) out.error = "asset " + in_quotes(name) + " not found";
    return out;
  }
  base::Result<ImportedAsset> imported = import_asset(*path);
  if (!imported.ok()) {
    const std::string why = imported.diagnostics().empty()
                                ? "unreadable"
                                : base::render(imported.diagnostics().front());
    out.error = "asset " + in_quotes(name) + ": " + why;
    return out;
  }
  auto asset = std::make_shared<ImportedAsset>(std::move(imported.value()));
  auto mesh = std::make_shared<kernel::Mesh>(asset->mesh);
  for (std::size_t f = 0; f < mesh->face_count(); ++f) mesh->tag(f).material = 0;
  out.asset = std::move(asset);
  out.mesh = std::move(mesh);
  return out;
}

const AssetLibrary::Entry& AssetLibrary::entry(std::string_view name) const {
  std::shared_future<Entry> future;
  std::promise<Entry> promise;
  bool first = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto it = cache_.find(name);
    if (it == cache_.end()) {
      it = cache_.emplace(std::string(name), promise.get_future().share()).first;
      first = true;
    }
    future = it->second;
  }
  // Imported outside the lock, so other assets load meanwhile; the map keeps the shared state.
  if (first) promise.set_value(load(std::string(name)));
  const Entry& e = future.get();
  if (!e.asset) {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++failed_[std::string(name)];
  }
  return e;
}

std::shared_ptr<const ImportedAsset> AssetLibrary::asset(std::string_view name,
                                                         std::string& error) const {
  const Entry& e = entry(name);
  if (!e.asset) error = e.error;
  return e.asset;
}

std::shared_ptr<const kernel::Mesh> AssetLibrary::find(std::string_view name,
                                                       std::string& error) const {
  const Entry& e = entry(name);
  if (e.mesh) return e.mesh;
  if (missing_ == Missing::kNothing) {
    static const auto kEmpty = std::make_shared<const kernel::Mesh>();
    return kEmpty;
  }
  error = e.error;
  return nullptr;
}

std::vector<AssetLibrary::Failure> AssetLibrary::failures() const {
  std::vector<Failure> out;
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [name, count] : failed_) {
    out.push_back({name, cache_.find(name)->second.get().error, count});
  }
  return out;
}

}  // namespace insula::io
