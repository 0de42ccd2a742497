#include "io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace insula::io {

std::string write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  return write_file_atomically(path, std::span<const std::string_view>(&content, 1));
}

std::string write_file_atomically(const std::filesystem::path& path,
                                  std::span<const std::string_view> pieces) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return path.string() + ": cannot write: " + std::strerror(errno);
    for (const std::string_view piece : pieces) {
      out.write(piece.data(), static_cast<std::streamsize>(piece.size()));
    }
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return path.string() + ": write failed: " + std::strerror(errno);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return path.string() + ": cannot rename temporary file: " + error.message();
  }
  return {};
}

}  // namespace insula::io
