// The folder the studio works on (issue 15, "Security and robustness"): every path a request names
// is resolved inside it or refused (`..`, absolute paths, symbolic links leading out), and saving
// writes atomically (a temporary file beside the target, renamed over it).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace insula::studio {

class Workspace {
 public:
  // `root` must be an existing folder.
  explicit Workspace(const std::filesystem::path& root);

  const std::filesystem::path& root() const { return root_; }

  // The file `relative` names inside the folder, or nullopt (with `why`) when it would lead out
  // of it: empty, absolute, with `..`, or reaching outside through a symbolic link.
  std::optional<std::filesystem::path> resolve(const std::string& relative, std::string& why) const;

  struct Entry {
    std::string path;  // relative, '/'-separated
    std::uintmax_t bytes = 0;
  };
  // The files a user edits or builds (.cga .bldg .lua .psm .graph.json .geojson .osm ...), sorted,
  // leaving out hidden folders, node_modules and anything leading out of the folder.
  std::vector<Entry> files() const;

  // Writes `text` to `path` (resolved) atomically; empty string or the reason.
  static std::string save(const std::filesystem::path& path, const std::string& text);

 private:
  std::filesystem::path root_;  // canonical
};

// True for the extensions the studio lists.
bool is_studio_file(const std::filesystem::path& path);

}  // namespace insula::studio
