// The asset providers the front-ends share (docs/assets.md): CGA grammars and graphs find assets
// as CityEngine does (io::AssetSearch, --workspace), Lua programs only in their sandboxed asset
// folders; both import through io::AssetLibrary.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/asset_library.h"
#include "io/textures.h"

namespace insula::cli {

// Lua's assets: a name is a relative path inside the asset folders (".obj" added when it has no
// extension; asset_folders.h refuses the rest); a missing asset is an error.
io::AssetLibrary folder_assets(const std::vector<std::string>& folders);

// One warning (AST100) per asset name that could not be had, with how many inserts it left
// empty, and report["missing_assets"] = {name: requests} when there are any.
void report_missing_assets(const std::vector<io::AssetLibrary::Failure>& failures,
                           const std::string& input, bool quiet, nlohmann::json& report);

// One warning (AST101) per texture that could not be had (its faces keep their colour), and
// report["missing_textures"] = {name: reason} when there are any.
void report_missing_textures(const std::vector<io::TextureFailure>& failures,
                             const std::string& input, bool quiet, nlohmann::json& report);

}  // namespace insula::cli
