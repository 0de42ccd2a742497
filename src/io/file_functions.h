// CGA's file functions as CityEngine defines them (docs/assets.md, "File functions"), for the
// CGA front-end to call: fileExists, fileSearch, fileRandom, assetInfo and imageInfo. Names are
// found by an AssetSearch; fileSearch lists the workspace's projects once (cached) and answers
// each distinct query once. Thread-safe: lots derive in parallel.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/asset_library.h"
#include "io/asset_search.h"

namespace insula::io {

struct ImageSize {
  int width = 0;
  int height = 0;
};
// The pixel size of an image file from its header: PNG, JPEG, BMP and TIFF (the formats
// CityEngine's textures come in); nullopt for other or broken files.
std::optional<ImageSize> read_image_size(const std::filesystem::path& path);

class FileFunctions {
 public:
  // `search` and `assets` must outlive this object; `assets` should resolve through `search`.
  FileFunctions(const AssetSearch& search, const AssetLibrary& assets)
      : search_(search), assets_(assets) {}

  // fileExists(path): true when `path` resolves (the asset search order) to a regular file.
  bool file_exists(std::string_view path) const;

  // fileSearch(query): every matching file of the workspace as an alphabetically sorted string
  // list, each entry a workspace path ("/Project/assets/a.obj") ended by ';'; "" when none match.
  // A query is terms separated by blanks, all of which must match (AND): a glob ('*' any
  // characters, '/' included; '?' one character) or, after a leading '$', a regular expression
  // (ECMAScript), matched against the whole of a file's path relative to the current project's
  // assets/ folder, relative to the project folder, and ('/'-prefixed when the query is) relative
  // to the workspace; or Name=, Ext=, Project=, Path= with a glob on the file name, extension
  // (no dot), project name or workspace path. Sets `error` (and returns "") for an invalid
  // regular expression.
  std::string file_search(std::string_view query, std::string& error) const;

  // fileRandom(query): the entry of file_search(query) at floor(random * count), `random` in
  // [0, 1) (the shape's random number); "" when nothing matches.
  std::string file_random(std::string_view query, double random, std::string& error) const;

  // assetInfo(path, attribute): the bounding box of the imported asset (asset space, y up):
  // "sx" "sy" "sz" its size, "tx" "ty" "tz" its lowest corner. nullopt with `error` when the
  // asset cannot be had or the attribute is none of those.
  std::optional<double> asset_info(std::string_view path, std::string_view attribute,
                                   std::string& error) const;

  // imageInfo(path, attribute): "sx" the width, "sy" the height, in pixels. nullopt with `error`
  // when the image is not found or unreadable or the attribute is neither.
  std::optional<double> image_info(std::string_view path, std::string_view attribute,
                                   std::string& error) const;

  // The bytes of a text file (readStringTable, readFloatTable), read once per resolved file.
  // nullopt with `error` when the file is not found or unreadable.
  std::optional<std::string> read_text(std::string_view path, std::string& error) const;

 private:
  struct Listed {
    std::filesystem::path path;
    std::string name;        // workspace_name(path): what fileSearch returns
    std::string project;     // the project folder's name
    std::string in_assets;   // path relative to the current project's assets/ ("" if outside)
    std::string in_project;  // relative to the current project (or the rule folder) ("" if outside)
    std::string in_workspace;  // relative to the workspace ("" if outside)
  };
  const std::vector<Listed>& listing() const;

  const AssetSearch& search_;
  const AssetLibrary& assets_;
  mutable std::mutex mutex_;
  mutable std::once_flag listed_;
  mutable std::vector<Listed> files_;
  mutable std::map<std::string, bool, std::less<>> exists_;
  mutable std::map<std::string, std::string, std::less<>> searches_;
  mutable std::map<std::filesystem::path, std::optional<ImageSize>> images_;
  mutable std::map<std::filesystem::path, std::optional<std::string>> texts_;
};

}  // namespace insula::io
