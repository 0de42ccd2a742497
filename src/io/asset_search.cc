#include "io/asset_search.h"

#include <algorithm>
#include <cctype>
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

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// `relative` under `base` with every component matched ignoring ASCII letter case where no
// entry has its exact spelling (the alphabetically first of several that differ only in case).
std::optional<fs::path> find_ignoring_case(const fs::path& base, const fs::path& relative) {
  fs::path at = base;
  for (const fs::path& part : relative) {
    if (part == ".") continue;
    if (part == "..") {
      at = at.parent_path();
      continue;
    }
    std::error_code ec;
    if (fs::exists(at / part, ec)) {
      at /= part;
      continue;
    }
    const std::string want = lower(part.string());
    std::optional<fs::path> match;
    for (fs::directory_iterator it(at, ec), end; !ec && it != end; it.increment(ec)) {
      if (lower(it->path().filename().string()) != want) continue;
      if (!match || it->path() < *match) match = it->path();
    }
    if (!match) return std::nullopt;
    at = *match;
  }
  if (!is_file(at)) return std::nullopt;
  return at.lexically_normal();
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
  // An unpacked .rpk keeps the workspace files its rules name in `.ws/` at its root.
  std::error_code ec;
  for (fs::path at = folder_; !at.empty(); at = at.parent_path()) {
    if (fs::is_directory(at / ".ws", ec)) {
      package_workspace_ = at / ".ws";
      break;
    }
    if (at == at.parent_path()) break;
  }
}

std::vector<std::pair<fs::path, fs::path>> AssetSearch::places(std::string_view name) const {
  const std::string generic = generic_asset_name(name);
  std::vector<std::pair<fs::path, fs::path>> out;
  if (generic.empty()) return out;
  auto add = [&](const fs::path& base, const fs::path& relative) {
    const fs::path n = (base / relative).lexically_normal();
    const bool seen = std::any_of(out.begin(), out.end(), [&](const auto& p) {
      return (p.first / p.second).lexically_normal() == n;
    });
    if (!seen) out.emplace_back(base, relative);
  };
  if (generic.front() == '/') {
    // A workspace path. Its project may also be the rule file's own project outside the
    // workspace (--workspace elsewhere): "/<project name>/..." then means that project.
    const fs::path rest = fs::path(generic).relative_path();
    add(workspace_, rest);
    if (project_ && !rest.empty() && *rest.begin() == project_->filename()) {
      fs::path tail;
      for (auto it = std::next(rest.begin()); it != rest.end(); ++it) tail /= *it;
      add(*project_, tail);
    }
    if (package_workspace_) add(*package_workspace_, rest);
    return out;
  }
  const fs::path relative(generic);
  add(folder_, relative);
  if (project_) {
    add(*project_ / "assets", relative);
    add(*project_ / "rules", relative);
    add(*project_, relative);
  }
  return out;
}

std::vector<fs::path> AssetSearch::candidates(std::string_view name) const {
  std::vector<fs::path> out;
  for (const auto& [base, relative] : places(name))
    out.push_back((base / relative).lexically_normal());
  return out;
}

std::optional<fs::path> AssetSearch::resolve(std::string_view name) const {
  const auto tried = places(name);
  for (const auto& [base, relative] : tried) {
    const fs::path candidate = (base / relative).lexically_normal();
    if (is_file(candidate)) return candidate;
  }
  for (const auto& [base, relative] : tried) {
    if (auto found = find_ignoring_case(base, relative)) return found;
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
