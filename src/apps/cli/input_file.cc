#include "apps/cli/input_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace insula::cli {

std::optional<std::string> read_input_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return buffer.str();
}

}  // namespace insula::cli
