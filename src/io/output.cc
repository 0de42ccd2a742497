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

void remove_outputs(const std::vector<std::string>& paths) {
  std::error_code ignored;
  for (const std::string& path : paths) {
    std::filesystem::remove(path, ignored);
    if (output_format_name(path) == "obj") {
      std::filesystem::remove(std::filesystem::path(path).replace_extension(".mtl"), ignored);
    }
  }
}

}  // namespace insula::io
