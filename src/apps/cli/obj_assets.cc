#include "apps/cli/obj_assets.h"

#include "apps/cli/input_file.h"
#include "io/obj_reader.h"

namespace insula::cli {

ObjAssets::Entry ObjAssets::load(std::string_view name) const {
  const std::filesystem::path path = dir_ / std::string(name);
  const std::optional<std::string> text = read_input_file(path.string());
  if (!text) return {nullptr, "asset '" + std::string(name) + "' not found in " + dir_.string()};
  base::Result<kernel::Mesh> mesh = io::read_obj(*text, path.string());
  if (!mesh.ok()) {
    const std::string why =
        mesh.diagnostics().empty() ? "unreadable" : base::render(mesh.diagnostics().front());
    return {nullptr, "asset '" + std::string(name) + "': " + why};
  }
  return {std::make_shared<kernel::Mesh>(std::move(mesh.value())), {}};
}

}  // namespace insula::cli
