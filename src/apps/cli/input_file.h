// Reading an input file whole, for the verbs that parse one.
#pragma once

#include <optional>
#include <string>

namespace insula::cli {

// The file's bytes, or nullopt when it cannot be opened or read (a directory included).
std::optional<std::string> read_input_file(const std::string& path);
// Why `path` could not be read, in the system's words ("No such file or directory", "Permission
// denied", "Is a directory").
std::string read_failure_reason(const std::string& path);
inline std::string read_failure(const std::string& path) {
  return "cannot read file: " + read_failure_reason(path);
}
// read_input_file, printing `PATH: error: cannot read file: <reason>` to stderr when it fails.
std::optional<std::string> read_input_or_report(const std::string& path);

}  // namespace insula::cli
