#include "io/asset_search.h"

#include <algorithm>
#include <system_error>

namespace insula::io {

namespace fs = std::filesystem;

namespace {

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

fs::path absolute_normal(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p.empty() ? fs::path(".") : p, ec);
  if (ec) a = p;
  a = a.lexically_normal();
  // "dir/" normalises to "dir/" with an empty last component; parent_path() needs it gone.
  if (!a.has_filename() && a.has_parent_path() && a != a.root_path()) a = a.parent_path();
  return a;
}

// CityEngine's project layout: assets/ and rules/ beside each other, and Eclipse's .project file.
bool is_project(const fs::path& folder) {
  return is_dir(folder / "assets") || is_dir(folder / "rules") || is_file(folder / ".project");
}

std::optional<fs::path> find_project(fs::path folder) {
  while (true) {
    if (is_project(folder)) return folder;
    if (!folder.has_relative_path()) return std::nullopt;  // reached the root
    folder = folder.parent_path();
  }
}

// `relative` inside `base`, or nullopt when it is not (lexically) inside.
std::optional<fs::path> inside(const fs::path& file, const fs::path& base) {
  const auto [b, f] = std::mismatch(base.begin(), base.end(), file.begin(), file.end());
  if (b != base.end()) return std::nullopt;
  fs::path rest;
  for (auto it = f; it != file.end(); ++it) rest /= *it;
  return rest;
}

}  // namespace

std::string generic_asset_name(std::string_view name) {
  std::string out(name);
  std::replace(out.begin(), out.end(), '\\', '/');
  return out;
}

AssetSearch::AssetSearch(const fs::path& rule_file, const fs::path& workspace) {
  folder_ = absolute_normal(rule_file).parent_path();
  project_ = find_project(folder_);
  if (!workspace.empty()) {
    workspace_ = absolute_normal(workspace);
  } else {
    workspace_ = project_ ? project_->parent_path() : folder_.parent_path();
  }
}

std::vector<fs::path> AssetSearch::candidates(std::string_view name) const {
  const std::string generic = generic_asset_name(name);
  std::vector<fs::path> out;
  if (generic.empty()) return out;
  auto add = [&](const fs::path& p) {
    const fs::path n = p.lexically_normal();
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  };
  if (generic.front() == '/') {
    // A workspace path. Its project may also be the rule file's own project outside the
    // workspace (--workspace elsewhere): "/<project name>/..." then means that project.
    const fs::path rest = fs::path(generic).relative_path();
    add(workspace_ / rest);
    if (project_ && !rest.empty() && *rest.begin() == project_->filename()) {
      fs::path tail;
      for (auto it = std::next(rest.begin()); it != rest.end(); ++it) tail /= *it;
      add(*project_ / tail);
    }
    return out;
  }
  const fs::path relative(generic);
  add(folder_ / relative);
  if (project_) {
    add(*project_ / "assets" / relative);
    add(*project_ / "rules" / relative);
    add(*project_ / relative);
  }
  return out;
}

std::optional<fs::path> AssetSearch::resolve(std::string_view name) const {
  for (const fs::path& candidate : candidates(name)) {
    if (is_file(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string AssetSearch::workspace_name(const fs::path& file) const {
  const fs::path f = absolute_normal(file);
  if (auto rest = inside(f, workspace_); rest && !rest->empty()) {
    std::string name(1, '/');  // appended: GCC 12 reports a false -Wrestrict on "/" + string
    name += rest->generic_string();
    return name;
  }
  if (project_) {
    if (auto rest = inside(f, *project_); rest && !rest->empty()) return rest->generic_string();
  }
  return f.generic_string();
}

}  // namespace insula::io
