// Reading an input file whole, for the verbs that parse one.
#pragma once

#include <optional>
#include <string>

namespace insula::cli {

// The file's bytes, or nullopt when it cannot be opened or read (a directory included).
std::optional<std::string> read_input_file(const std::string& path);

}  // namespace insula::cli
