// Wavefront OBJ + MTL writer (docs/formats.md, "OBJ"). One `o` object per building; inside it one
// `g` group per part and face class/material (`g <building>.<part>.<Class>`), each with `usemtl`.
// Faces stay n-gons in their mesh orientation (counter-clockwise seen from outside). By default
// vertices are in the scene's local coordinates, Y up (x, z, -y of Insula's Z-up frame: a
// rotation, so faces keep their winding), as Blender, Maya, three.js and game engines read OBJ,
// and near the origin, so a float32 reader keeps millimetres; the origin and CRS that take them
// back to the world are in the header comment and in a sidecar `<stem>.origin.json`. `world`
// writes world coordinates (local + Scene::origin), Z up by default, for GIS users. Coordinates
// have 6 decimals (1 µm, trailing zeros trimmed). A part with a uv map (Part::uv) gets one `vt`
// per vertex and faces `f v/vt`; a material showing an image read from a file gets `map_Kd` with
// the image copied beside the OBJ. Output is deterministic.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shape/scene.h"

namespace insula::io {

struct ObjOptions {
  bool world = false;  // world coordinates (local + origin) instead of local ones
  char up = 0;         // 'y' or 'z'; 0: Y up for local coordinates, Z up for world ones
  char up_axis() const { return up != 0 ? up : world ? 'z' : 'y'; }
};

struct ObjText {
  std::string obj;
  std::string mtl;
  // Image files the MTL's map_Kd names (textures read from files, copied beside the OBJ so the
  // folder opens textured anywhere): (file name, bytes).
  std::vector<std::pair<std::string, std::string>> textures;
  std::string origin_json;  // the sidecar: origin, CRS, up axis and the way back to the world
};

// The OBJ and MTL texts of `scene`; the OBJ refers to the MTL as `mtl_file_name`.
ObjText obj_text(const shape::Scene& scene, std::string_view mtl_file_name,
                 const ObjOptions& options = {});

// The sidecar's path for an OBJ: `<stem>.origin.json` beside it.
std::filesystem::path origin_sidecar_path(const std::filesystem::path& obj_path);

// Writes `obj_path`, the .mtl and the origin sidecar beside it (same stem) and the texture images,
// atomically: on failure none of the files is left. Returns an empty string on success, else a
// message naming the file.
std::string write_obj(const shape::Scene& scene, const std::filesystem::path& obj_path,
                      const ObjOptions& options = {});

// `value` in fixed notation with at most `decimals` decimals, trailing zeros (and a trailing point)
// removed, "-0" written as "0". Locale independent. Shared by the text writers.
std::string format_decimal(double value, int decimals);
// format_decimal(value, decimals) appended to `out`.
void append_decimal(std::string& out, double value, int decimals);

}  // namespace insula::io
