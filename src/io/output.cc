#include "io/output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "io/atomic_file.h"
#include "io/cityjson_writer.h"
#include "io/cityjsonseq_writer.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/png_renderer.h"
#include "io/svg_writer.h"
#include "io/tileset_writer.h"

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
  if (std::filesystem::path(path).filename() == "tileset.json") return "3dtiles";
  if (ends_with(path, ".city.jsonl")) return "cityjsonseq";
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
  if (format == "obj") return write_obj(scene, path, options.obj);
  if (format == "glb" || format == "gltf") return write_gltf(scene, path, options.gltf);
  if (format == "cityjson") return write_cityjson(scene, path, options.cityjson);
  if (format == "cityjsonseq") return write_cityjsonseq(scene, path, options.cityjson);
  if (format == "3dtiles") return write_tileset(scene, path, options.gltf, options.tiles);
  if (format == "svg") return write_svg(scene, path, options.svg);
  if (format == "png") return write_png(scene, path, options.render);
  return path + ": unknown output format";
}

std::vector<std::string> files_of_output(const std::string& path) {
  if (output_format_name(path) == "3dtiles") return {path, tiles_folder(path).string()};
  if (output_format_name(path) != "obj") return {path};
  return {path, std::filesystem::path(path).replace_extension(".mtl").string(),
          origin_sidecar_path(path).string()};
}

namespace {

std::string backup_of(const std::string& path) {
  return path + ".insula-backup";
}

}  // namespace

OutputTransaction::OutputTransaction(std::function<bool()> cancelled)
    : cancelled_(std::move(cancelled)) {}

OutputTransaction::~OutputTransaction() {
  if (!finished_) roll_back();
}

std::string OutputTransaction::cancelled_error() const {
  return cancelled_ && cancelled_() ? "interrupted" : "";
}

// Makes the files free for this transaction: an existing file that is not already ours is moved
// aside first, and only then the path counts as ours, so a rollback never removes a user's file.
std::string OutputTransaction::claim(const std::vector<std::string>& files) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const std::string& file : files) {
    if (std::string error = cancelled_error(); !error.empty()) return error;
    if (created_.contains(file)) continue;
    std::error_code error;
    if (std::filesystem::exists(file, error)) {
      std::filesystem::rename(file, backup_of(file), error);
      if (error) return file + ": cannot move the existing file aside: " + error.message();
      moved_.push_back(file);
    }
    created_.insert(file);
  }
  return {};
}

// A 3D Tiles output names its own folder (city/tileset.json): made here when missing, and then
// ours to remove on a rollback.
std::string OutputTransaction::make_folder(const std::filesystem::path& folder) {
  std::error_code error;
  if (folder.empty() || std::filesystem::is_directory(folder, error)) return {};
  if (!std::filesystem::create_directory(folder, error) || error) {
    return folder.string() + ": cannot create the folder: " + error.message();
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  created_.insert(folder.string());
  return {};
}

std::string OutputTransaction::claim_output(const std::string& path) {
  if (output_format_name(path) == "3dtiles") {
    if (std::string error = make_folder(std::filesystem::path(path).parent_path());
        !error.empty()) {
      return error;
    }
  }
  return claim(files_of_output(path));
}

std::string OutputTransaction::write_scene(const shape::Scene& scene, const std::string& path,
                                           const OutputOptions& options) {
  if (std::string error = claim_output(path); !error.empty()) return error;
  if (std::string error = io::write_scene(scene, path, options); !error.empty()) return error;
  return cancelled_error();
}

std::string OutputTransaction::write_text(const std::string& path, std::string_view content) {
  if (std::string error = claim({path}); !error.empty()) return error;
  if (std::string error = write_file_atomically(path, content); !error.empty()) return error;
  return cancelled_error();
}

std::string OutputTransaction::commit() {
  if (std::string error = cancelled_error(); !error.empty()) {
    roll_back();
    return error;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  // The commit point: from here on the new files stay, whatever arrives.
  finished_ = true;
  std::error_code ignored;
  for (const std::string& path : moved_) std::filesystem::remove_all(backup_of(path), ignored);
  moved_.clear();
  created_.clear();
  return {};
}

void OutputTransaction::roll_back() {
  const std::lock_guard<std::mutex> lock(mutex_);
  finished_ = true;
  std::error_code ignored;
  // remove_all: a 3D Tiles output's tiles folder; the set's order removes a folder before the
  // paths inside it, which are gone with it.
  for (const std::string& path : created_) std::filesystem::remove_all(path, ignored);
  for (const std::string& path : moved_) std::filesystem::rename(backup_of(path), path, ignored);
  moved_.clear();
  created_.clear();
}

std::string check_output_directories(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    std::filesystem::path directory = std::filesystem::path(path).parent_path();
    // A 3D Tiles folder (city/tileset.json) is made when missing; its parent must exist.
    if (output_format_name(path) == "3dtiles") directory = directory.parent_path();
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
