#include "apps/cli/view_options.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "apps/cli/validators.h"

namespace insula::cli {
namespace {

// Parses "WIDTHxHEIGHT" (pixels, 16..8192 each).
std::string parse_size(const std::string& text, io::RenderOptions& render) {
  int width = 0;
  int height = 0;
  char x = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 ||
      (x != 'x' && x != 'X') || width < 16 || height < 16 || width > 8192 || height > 8192) {
    return "expected WIDTHxHEIGHT in pixels, each 16 to 8192, e.g. 1600x1200";
  }
  render.width = width;
  render.height = height;
  return {};
}

}  // namespace

void add_view_options(CLI::App& command, io::OutputOptions& output) {
  io::RenderOptions& render = output.render;
  command
      .add_option_function<std::string>(
          "--image-size",
          [&render](const std::string& text) {
            const std::string error = parse_size(text, render);
            if (!error.empty()) throw CLI::ValidationError("--image-size", error);
          },
          "PNG size in pixels, WIDTHxHEIGHT (default 1024x768)")
      ->type_name("WxH");
  command
      .add_option("--azimuth", render.azimuth_deg,
                  "PNG view: direction the camera looks from, degrees counter-clockwise from east "
                  "(default 225, south-west)")
      ->check(finite_range(-360.0, 360.0));
  command
      .add_option("--elevation", render.elevation_deg,
                  "PNG view: camera elevation in degrees, 90 = plan (default 35)")
      ->check(finite_range(5.0, 90.0));
  command.add_flag("--cutaway", render.cutaway,
                   "PNG view: cut the buildings open to show interiors");
  command
      .add_option_function<double>(
          "--cut-height",
          [&render](double height) {
            render.cutaway = true;
            render.cut_height = height;
          },
          "PNG cutaway at this height in meters (local Z; footprints stand on 0); implies "
          "--cutaway")
      ->check(finite_range(-1000.0, 10000.0));
  command
      .add_option_function<std::string>(
          "--up", [&output](const std::string& axis) { output.obj.up = axis.front(); },
          "OBJ up axis: y (Blender, Maya, three.js, game engines; the default) or z (GIS; the "
          "default with --obj-world)")
      ->check(CLI::IsMember({"y", "z"}))
      ->type_name("y|z");
  command.add_flag("--obj-world", output.obj.world,
                   "OBJ in world coordinates (local + origin, the input's CRS), Z up unless --up "
                   "y; by default OBJ is local, with the origin in its header and .origin.json");
  command
      .add_option_function<std::string>(
          "--gltf-nodes",
          [&output](const std::string& layout) {
            output.gltf.nodes = layout == "element" ? io::GltfOptions::Nodes::kElement
                                : layout == "scene" ? io::GltfOptions::Nodes::kScene
                                                    : io::GltfOptions::Nodes::kBuilding;
          },
          "GLB/glTF nodes: building (one node and mesh per building, parts as feature ids with a "
          "property table; the default), element (a node per part, to edit parts) or scene (one "
          "node and mesh for all, each part a feature with its building's id: big scenes in "
          "viewers)")
      ->check(CLI::IsMember({"building", "element", "scene"}))
      ->type_name("building|element|scene");
  command
      .add_option_function<std::string>(
          "--gltf-colours",
          [&output](const std::string& colours) { output.gltf.by_class = colours == "class"; },
          "GLB/glTF colours: material (each face's own; the default) or class (each face's "
          "semantic class: walls, roofs, windows, doors...)")
      ->check(CLI::IsMember({"material", "class"}))
      ->type_name("material|class");
  command
      .add_option_function<std::string>(
          "--gltf-instancing",
          [&output](const std::string& form) {
            output.gltf.instancing = form == "gpu" ? io::GltfOptions::Instancing::kGpu
                                                   : io::GltfOptions::Instancing::kNodes;
          },
          "GLB/glTF repeated meshes: nodes (a node per instance over one shared mesh; the "
          "default, read everywhere) or gpu (EXT_mesh_gpu_instancing: three.js, Cesium, game "
          "engines; Blender 3.6+)")
      ->check(CLI::IsMember({"nodes", "gpu"}))
      ->type_name("nodes|gpu");
  command.add_flag_function(
      "--gltf-float", [&output](std::int64_t) { output.gltf.quantize = false; },
      "GLB/glTF positions and normals as floats (by default quantized with "
      "KHR_mesh_quantization, within 1 mm)");
  command.add_flag("--compress", output.gltf.compress,
                   "GLB/glTF buffers compressed with EXT_meshopt_compression (meshoptimizer; "
                   "three.js, Babylon.js, Cesium and gltfpack read it, Blender does not)");
  command
      .add_option("--tile-faces", output.tiles.tile_faces,
                  "3D Tiles: a tile splits into four while its buildings have more faces than "
                  "this (default 50000)")
      ->check(CLI::Range(std::size_t{100}, std::size_t{100000000}));
  command
      .add_option(
          "--tile-blocks", output.tiles.block_buildings,
          "3D Tiles: inner tiles over at most this many buildings show each as a block (its "
          "bounding box) for views from afar (default 0: inner tiles stay empty)")
      ->check(CLI::Range(std::size_t{0}, std::size_t{10000000}));
  command
      .add_option("--svg-scale", output.svg.pixels_per_meter,
                  "SVG picture scale in pixels per meter (default: fit 1000 pixels)")
      ->check(finite_range(0.01, 1000.0));
}

}  // namespace insula::cli
