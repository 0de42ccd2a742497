// Where a rule file's asset, texture and import names are found, as CityEngine finds them
// (docs/assets.md, "Search order"). A CityEngine project is a folder holding `assets/` and
// `rules/` (or CityEngine's `.project` file); the workspace holds the projects, and a name that
// starts with '/' is a workspace path ("/MyProject/assets/door.obj", "/ESRI.lib/rules/x.cga"),
// looked for in the workspace and then in an unpacked rule package's `.ws/` folder.
// Reads the file system only: no caching, safe to share between threads.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace insula::io {

class AssetSearch {
 public:
  // `rule_file`: the file whose names are resolved (it need not exist). `workspace`: the folder
  // '/'-names start from; empty means the parent of the project folder (or of the rule file's
  // folder when it is in no project). Both are made absolute.
  explicit AssetSearch(const std::filesystem::path& rule_file,
                       const std::filesystem::path& workspace = {});

  // The existing regular file `name` denotes, trying candidates() in order, then the same places
  // ignoring letter case (rule files written on Windows, whose file names ignore it); nullopt
  // when none exists or the name is empty. Backslashes count as '/', for the same reason.
  std::optional<std::filesystem::path> resolve(std::string_view name) const;
  // Every place resolve() tries for `name`, in order, existing or not (for "looked in" messages).
  std::vector<std::filesystem::path> candidates(std::string_view name) const;

  const std::filesystem::path& folder() const { return folder_; }  // the rule file's folder
  // The nearest folder, from the rule file's folder up, that holds assets/, rules/ or .project.
  const std::optional<std::filesystem::path>& project() const { return project_; }
  const std::filesystem::path& workspace() const { return workspace_; }

  // The name CityEngine gives `file` (an absolute path): "/Project/assets/x.obj" for a file under
  // the workspace, else its path relative to the project folder, else `file` itself. resolve()
  // finds the file again from that name.
  std::string workspace_name(const std::filesystem::path& file) const;

 private:
  // (base, relative) per candidate: the case-insensitive pass matches only below the base.
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> places(
      std::string_view name) const;

  std::filesystem::path folder_;
  std::optional<std::filesystem::path> project_;
  std::filesystem::path workspace_;
  // A rule package's (.rpk) copy of the workspace files it uses: `.ws/` next to its `rules/`.
  std::optional<std::filesystem::path> package_workspace_;
};

// `name` with backslashes turned into '/'.
std::string generic_asset_name(std::string_view name);

}  // namespace insula::io
