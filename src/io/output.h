// Chooses the writer for an output path by its extension (design.md, "Outputs").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/png_renderer.h"
#include "io/svg_writer.h"
#include "shape/scene.h"

namespace insula::io {

// .obj, .glb, .gltf, .city.json, .svg, .png (case-insensitive).
bool is_supported_output(const std::string& path);
// "obj", "glb", "gltf", "cityjson", "svg", "png"; empty when unsupported.
std::string output_format_name(const std::string& path);
// Options of the formats that have any (the others ignore them).
struct OutputOptions {
  RenderOptions render;
  SvgOptions svg;
};

// Writes the scene in the path's format, atomically. Empty string on success, else the reason.
std::string write_scene(const shape::Scene& scene, const std::string& path,
                        const OutputOptions& options = {});
// The files a path's writer creates: the path itself, and for OBJ its .mtl beside it.
std::vector<std::string> files_of_output(const std::string& path);

// Writes several outputs as one transaction: files that already exist are first moved aside, and
// when any write fails, everything this call wrote is removed and the moved files are put back, so
// a failed run neither leaves partial output nor loses the user's earlier files. `on_written` is
// called after each output with its index (for timings). Empty string on success.
std::string write_outputs(const shape::Scene& scene, const std::vector<std::string>& paths,
                          const OutputOptions& options,
                          const std::function<void(std::size_t)>& on_written = {});
// Checks before any work that every output's directory exists; empty string when it does.
std::string check_output_directories(const std::vector<std::string>& paths);

}  // namespace insula::io
