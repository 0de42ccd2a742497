#include "apps/cli/plasm_assets.h"

#include "apps/cli/asset_folders.h"
#include "apps/cli/input_file.h"
#include "lang/plasm/parts.h"

namespace insula::cli {

bool is_plasm_part(std::string_view name) {
  const std::string file = lang::plasm::split_part_name(name).first;
  return file.size() > 4 && file.compare(file.size() - 4, 4, ".psm") == 0;
}

std::shared_ptr<const kernel::Mesh> PlasmAssets::find(std::string_view name,
                                                      std::string& error) const {
  if (!is_plasm_part(name)) {
    if (next_ != nullptr) return next_->find(name, error);
    error = "asset '" + std::string(name) + "' not found";
    return nullptr;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  auto it = cache_.find(name);
  if (it == cache_.end()) it = cache_.emplace(std::string(name), load(std::string(name))).first;
  if (!it->second.mesh) error = it->second.error;
  return it->second.mesh;
}

PlasmAssets::Entry PlasmAssets::load(const std::string& name) const {
  const auto [file, expression] = lang::plasm::split_part_name(name);
  Entry entry;
  const std::optional<std::filesystem::path> path =
      find_in_folders(folders_, file, name, entry.error);
  if (!path) return entry;
  const std::optional<std::string> text = read_input_file(path->string());
  if (!text) {
    entry.error = "cannot read asset '" + file + "'";
    return entry;
  }
  const base::Source source(file, *text);
  entry.mesh = lang::plasm::part_mesh(source, expression, entry.error);
  if (!entry.mesh) entry.error = "asset '" + name + "': " + entry.error;
  return entry;
}

}  // namespace insula::cli
