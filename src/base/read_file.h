// A whole file's bytes, as they are (binary).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace insula::base {

// The bytes of `path`, or nothing when it cannot be opened or read.
std::optional<std::string> read_file(const std::filesystem::path& path);

}  // namespace insula::base
