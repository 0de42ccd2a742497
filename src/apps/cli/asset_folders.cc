#include "apps/cli/asset_folders.h"

#include <algorithm>

namespace insula::cli {

namespace fs = std::filesystem;

std::optional<fs::path> find_in_folders(const std::vector<std::string>& folders,
                                        const fs::path& relative, const std::string& name,
                                        std::string& error) {
  if (relative.empty() || relative.is_absolute() || relative.has_root_name()) {
    error = "asset '" + name + "': only names inside the asset folders are allowed";
    return std::nullopt;
  }
  for (const fs::path& part : relative) {
    if (part == "..") {
      error = "asset '" + name + "': '..' is not allowed in asset names";
      return std::nullopt;
    }
  }
  for (const std::string& folder : folders) {
    std::error_code ec;
    const fs::path root = fs::canonical(folder, ec);
    if (ec) continue;
    const fs::path candidate = fs::weakly_canonical(root / relative, ec);
    if (ec || !fs::is_regular_file(candidate, ec)) continue;
    const auto [end, unused] =
        std::mismatch(root.begin(), root.end(), candidate.begin(), candidate.end());
    (void)unused;
    if (end != root.end()) {
      error = "asset '" + name + "' leads outside its asset folder";
      return std::nullopt;
    }
    return candidate;
  }
  error = "asset '" + name + "' not found in the asset folders";
  return std::nullopt;
}

}  // namespace insula::cli
