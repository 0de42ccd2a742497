#include "apps/cli/input_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace insula::cli {

std::optional<std::string> read_input_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  // A regular file is read at its size in one call: streaming it through a string stream grew
  // and copied the buffer over and over (a tenth of reading a 13 MB lot file, issue 17).
  if (const auto size = std::filesystem::file_size(path, error);
      !error && std::filesystem::is_regular_file(path, error)) {
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size) return std::nullopt;
    return text;
  }
  std::ostringstream buffer;  // a pipe or device: its size is unknown
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return buffer.str();
}

std::string read_failure_reason(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return "Is a directory";
  // Opened again to learn errno: read_input_file's stream does not keep it.
  const int fd = ::open(path.c_str(), O_RDONLY);
  const int reason = errno;
  if (fd < 0) return std::strerror(reason);
  ::close(fd);
  return "read error";
}

std::optional<std::string> read_input_or_report(const std::string& path) {
  std::optional<std::string> text = read_input_file(path);
  if (!text) std::fprintf(stderr, "%s: error: %s\n", path.c_str(), read_failure(path).c_str());
  return text;
}

}  // namespace insula::cli
