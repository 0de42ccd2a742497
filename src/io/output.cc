#include "io/output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "io/cityjson_writer.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/png_renderer.h"
#include "io/svg_writer.h"

namespace insula::io {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

}  // namespace

std::string output_format_name(const std::string& path) {
  if (ends_with(path, ".city.json")) return "cityjson";
  for (const char* format : {"obj", "glb", "gltf", "svg", "png"}) {
    if (ends_with(path, std::string(".") + format)) return format;
  }
  return {};
}

bool is_supported_output(const std::string& path) {
  return !output_format_name(path).empty();
}

std::string write_scene(const shape::Scene& scene, const std::string& path,
                        const OutputOptions& options) {
  const std::string format = output_format_name(path);
  if (format == "obj") return write_obj(scene, path);
  if (format == "glb" || format == "gltf") return write_gltf(scene, path);
  if (format == "cityjson") return write_cityjson(scene, path);
  if (format == "svg") return write_svg(scene, path, options.svg);
  if (format == "png") return write_png(scene, path, options.render);
  return path + ": unknown output format";
}

std::vector<std::string> files_of_output(const std::string& path) {
  if (output_format_name(path) != "obj") return {path};
  return {path, std::filesystem::path(path).replace_extension(".mtl").string()};
}

namespace {

// Existing files moved aside while outputs are written, restored if the transaction fails.
class Backup {
 public:
  std::string move_aside(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return {};
    const std::string aside = path + ".insula-backup";
    std::filesystem::rename(path, aside, error);
    if (error) return path + ": cannot move the existing file aside: " + error.message();
    moved_.push_back(path);
    return {};
  }
  void restore() {
    std::error_code ignored;
    for (const std::string& path : moved_)
      std::filesystem::rename(path + ".insula-backup", path, ignored);
    moved_.clear();
  }
  void discard() {
    std::error_code ignored;
    for (const std::string& path : moved_)
      std::filesystem::remove(path + ".insula-backup", ignored);
    moved_.clear();
  }

 private:
  std::vector<std::string> moved_;
};

}  // namespace

std::string write_outputs(const shape::Scene& scene, const std::vector<std::string>& paths,
                          const OutputOptions& options,
                          const std::function<void(std::size_t)>& on_written) {
  Backup backup;
  std::vector<std::string> written;
  std::string error;
  for (std::size_t i = 0; i < paths.size() && error.empty(); ++i) {
    for (const std::string& file : files_of_output(paths[i])) {
      if (error.empty()) error = backup.move_aside(file);
    }
    if (error.empty()) error = write_scene(scene, paths[i], options);
    if (error.empty()) {
      written.push_back(paths[i]);
      if (on_written) on_written(i);
    }
  }
  if (error.empty()) {
    backup.discard();
    return {};
  }
  std::error_code ignored;
  for (const std::string& path : written) {
    for (const std::string& file : files_of_output(path)) std::filesystem::remove(file, ignored);
  }
  backup.restore();
  return error;
}

std::string check_output_directories(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    std::filesystem::path directory = std::filesystem::path(path).parent_path();
    if (directory.empty()) directory = ".";
    std::error_code error;
    if (!std::filesystem::is_directory(directory, error)) {
      return path + ": directory '" + directory.string() + "' does not exist";
    }
    if (std::filesystem::is_directory(path, error)) return path + ": is a directory";
  }
  return {};
}

}  // namespace insula::io
