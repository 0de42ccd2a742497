// Chooses the writer for an output path by its extension (design.md, "Outputs").
#pragma once

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
// Removes files this run wrote (and an OBJ's .mtl), so a failed run leaves nothing behind.
void remove_outputs(const std::vector<std::string>& paths);

}  // namespace insula::io
