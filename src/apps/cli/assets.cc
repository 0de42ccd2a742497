#include "apps/cli/assets.h"

#include "apps/cli/asset_folders.h"
#include "apps/cli/warnings.h"

namespace insula::cli {

namespace fs = std::filesystem;

io::AssetLibrary folder_assets(const std::vector<std::string>& folders) {
  return io::AssetLibrary(
      [folders](std::string_view name, std::string& error) -> std::optional<fs::path> {
        const std::string key(name);
        fs::path relative(key);
        if (!relative.empty() && !relative.has_extension()) relative += ".obj";
        return find_in_folders(folders, relative, key, error);
      },
      io::AssetLibrary::Missing::kError);
}

void report_missing_assets(const std::vector<io::AssetLibrary::Failure>& failures,
                           const std::string& input, bool quiet, nlohmann::json& report) {
  for (const io::AssetLibrary::Failure& f : failures) {
    const std::string times = f.count == 1 ? "once" : std::to_string(f.count) + " times";
    const base::Diagnostic d =
        base::Diagnostic::warning("AST100", f.error + "; asked for " + times + ", inserted nothing",
                                  base::Span::whole(input));
    emit_warning(d.code, base::render(d), quiet);
    report["missing_assets"][f.name] = f.count;
  }
}

void report_missing_textures(const std::vector<io::TextureFailure>& failures,
                             const std::string& input, bool quiet, nlohmann::json& report) {
  for (const io::TextureFailure& f : failures) {
    const base::Diagnostic d = base::Diagnostic::warning(
        "AST101", "texture '" + f.name + "': " + f.error + "; its faces show their colour only",
        base::Span::whole(input));
    emit_warning(d.code, base::render(d), quiet);
    report["missing_textures"][f.name] = f.error;
  }
}

}  // namespace insula::cli
