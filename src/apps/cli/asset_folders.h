// Asset names resolved inside asset folders (docs/lua-api.md, "Sandbox"): a name is a relative
// path; absolute names, ".." and symbolic links leading out of a folder are refused. Shared by
// the OBJ assets of Lua programs and the PLaSM parts of CGA grammars and Lua programs.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace insula::cli {

// The file `relative` names in the first folder that has it, or nullopt with `error` set.
std::optional<std::filesystem::path> find_in_folders(const std::vector<std::string>& folders,
                                                     const std::filesystem::path& relative,
                                                     const std::string& name, std::string& error);

}  // namespace insula::cli
