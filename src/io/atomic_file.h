// Writes an output file so that a failed run leaves nothing behind: the content goes to a
// temporary file beside the target, which is renamed over it only when complete (design.md,
// "Diagnostics": no partial output file).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace insula::io {

// Writes `content` to `path` atomically. Returns an empty string on success, else a message
// naming the path and the reason.
std::string write_file_atomically(const std::filesystem::path& path, std::string_view content);
// The same for content given as pieces, written one after the other.
std::string write_file_atomically(const std::filesystem::path& path,
                                  std::span<const std::string_view> pieces);

}  // namespace insula::io
