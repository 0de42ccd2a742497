#include "io/obj_writer.h"

#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <system_error>
#include <utility>

#include "io/atomic_file.h"
#include "io/json_stream.h"
#include "io/triangulated.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

// 1 µm: far below the 1 mm a survey needs, and 6 + 7 digits stay exact in a double for UTM.
constexpr int kCoordinateDecimals = 6;

// A scene point as the OBJ writes it: local or world, Z up or Y up (x, z, -y).
kernel::Vec3 written(kernel::Vec3 local, const shape::Scene& scene, const ObjOptions& options) {
  const kernel::Vec3 p = options.world ? local + scene.origin : local;
  if (options.up_axis() == 'y') return {p.x, p.z, -p.y};
  return p;
}

void append_vertex(std::string& out, kernel::Vec3 p) {
  out += "v ";
  out += format_decimal(p.x, kCoordinateDecimals);
  out += ' ';
  out += format_decimal(p.y, kCoordinateDecimals);
  out += ' ';
  out += format_decimal(p.z, kCoordinateDecimals);
  out += '\n';
}

// Faces of one part grouped by (class, material index), in class then material order.
using FaceGroups =
    std::map<std::pair<kernel::SemanticClass, std::uint32_t>, std::vector<std::size_t>>;

FaceGroups group_faces(const kernel::Mesh& mesh, const MaterialTable& materials) {
  FaceGroups groups;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const kernel::FaceTag& tag = mesh.tag(f);
    groups[{tag.semantic, materials.index(tag)}].push_back(f);
  }
  return groups;
}

// Writes a part's vertices (and texture coordinates, one per vertex, when it has a uv map) then its
// faces; `first_vertex` / `first_uv` are the 1-based OBJ indices of its vertex 0 / its first vt.
void append_part(std::string& out, const shape::Scene& scene, const ObjOptions& options,
                 const std::string& building_name, const shape::Part& part, std::size_t part_index,
                 const MaterialTable& materials, std::size_t first_vertex, std::size_t first_uv) {
  for (const kernel::Vec3& p : part.mesh.positions()) {
    append_vertex(out, written(p, scene, options));
  }
  if (part.uv) {
    for (const kernel::Vec3& p : part.mesh.positions()) {
      const kernel::Vec2 t = part.uv->at(p);
      out += "vt " + format_decimal(t.x, kCoordinateDecimals) + " " +
             format_decimal(t.y, kCoordinateDecimals) + "\n";
    }
  }
  const std::string part_name = safe_name(part.name, "part" + std::to_string(part_index));
  for (const auto& [key, faces] : group_faces(part.mesh, materials)) {
    out += "g " + building_name + "." + part_name + "." +
           std::string(kernel::semantic_name(key.first)) + "\n";
    out += "usemtl " + materials.materials()[key.second].name + "\n";
    for (std::size_t f : faces) {
      out += 'f';
      for (std::uint32_t vertex : part.mesh.face(f)) {
        out += ' ';
        out += std::to_string(first_vertex + vertex);
        if (part.uv) out += '/' + std::to_string(first_uv + vertex);
      }
      out += '\n';
    }
  }
}

// How a written point goes back to the world (the scene's CRS), for the header and the sidecar.
std::string to_world_text(const ObjOptions& options) {
  if (options.world) {
    return options.up_axis() == 'y' ? "world = (x, -z, y)" : "world = (x, y, z)";
  }
  return options.up_axis() == 'y' ? "world = (x, -z, y) + origin" : "world = (x, y, z) + origin";
}

std::string origin_text(const shape::Scene& scene) {
  return format_decimal(scene.origin.x, kCoordinateDecimals) + " " +
         format_decimal(scene.origin.y, kCoordinateDecimals) + " " +
         format_decimal(scene.origin.z, kCoordinateDecimals);
}

void append_header(std::string& out, const shape::Scene& scene, const ObjOptions& options,
                   std::string_view mtl_file_name) {
  out += std::string("# Insula OBJ export: meters, ") + (options.up_axis() == 'y' ? "Y" : "Z") +
         " up, " + (options.world ? "world" : "local") + " coordinates; " + to_world_text(options) +
         "\n";
  out += "# origin " + origin_text(scene) + "\n";
  if (!scene.crs.empty()) out += "# crs " + safe_name(scene.crs, "") + "\n";
  out += "mtllib " + std::string(mtl_file_name) + "\n";
}

// The sidecar: what a GIS user needs to put the model back in place.
std::string origin_json(const shape::Scene& scene, const ObjOptions& options) {
  std::string out = "{\n  \"origin\": [" + format_decimal(scene.origin.x, kCoordinateDecimals) +
                    ", " + format_decimal(scene.origin.y, kCoordinateDecimals) + ", " +
                    format_decimal(scene.origin.z, kCoordinateDecimals) + "],\n";
  out += "  \"crs\": ";
  if (scene.crs.empty()) {
    out += "null";
  } else {
    out += '"';
    append_json_escaped(out, scene.crs);
    out += '"';
  }
  out += ",\n";
  out += "  \"units\": \"m\",\n";
  out += std::string("  \"up\": \"") + options.up_axis() + "\",\n";
  out += std::string("  \"coordinates\": \"") + (options.world ? "world" : "local") + "\",\n";
  out += "  \"toWorld\": \"" + to_world_text(options) + "\"\n}\n";
  return out;
}

// The file name each image read from a file gets beside the OBJ: its own, made unique.
std::map<const shape::Image*, std::string> texture_files(const MaterialTable& materials) {
  std::map<const shape::Image*, std::string> files;
  std::set<std::string> taken;
  for (const shape::Material& material : materials.materials()) {
    const shape::Image* image = material.image.get();
    if (image == nullptr || image->encoded.empty() || files.contains(image)) continue;
    std::string name = safe_name(image->name, "texture");
    for (int k = 2; taken.contains(name); ++k) {
      name = std::to_string(k) + "_" + safe_name(image->name, "texture");
    }
    taken.insert(name);
    files[image] = name;
  }
  return files;
}

std::string mtl_text(const MaterialTable& materials,
                     const std::map<const shape::Image*, std::string>& textures) {
  std::string out = "# Insula MTL export: Kd is the material's linear RGB colour, d its alpha\n";
  for (const shape::Material& material : materials.materials()) {
    const auto channel = [&](std::size_t i) { return format_decimal(material.rgba[i], 6); };
    out += "\nnewmtl " + material.name + "\n";
    out += "Ka 0 0 0\n";
    out += "Kd " + channel(0) + " " + channel(1) + " " + channel(2) + "\n";
    out += "Ks 0 0 0\n";
    out += "d " + channel(3) + "\n";
    out += "illum 1\n";
    if (auto it = textures.find(material.image.get()); it != textures.end()) {
      out += "map_Kd " + it->second + "\n";
    }
  }
  return out;
}

}  // namespace

std::string format_decimal(double value, int decimals) {
  if (!std::isfinite(value)) return "0";
  char buffer[64];
  const auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (error != std::errc()) return "0";
  std::string text(buffer, end);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

ObjText obj_text(const shape::Scene& input, std::string_view mtl_file_name,
                 const ObjOptions& options) {
  shape::Scene expanded;  // shared-mesh instances written as plain geometry
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  const MaterialTable materials(scene);
  ObjText text;
  append_header(text.obj, scene, options, mtl_file_name);
  text.origin_json = origin_json(scene, options);
  std::size_t next_vertex = 1;
  std::size_t next_uv = 1;
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    const shape::Building& building = scene.buildings[b];
    const std::string building_name = safe_name(building.id, "building" + std::to_string(b));
    text.obj += "o " + building_name + "\n";
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      const shape::Part& part = building.parts[p];
      append_part(text.obj, scene, options, building_name, part, p, materials, next_vertex,
                  next_uv);
      next_vertex += part.mesh.vertex_count();
      if (part.uv) next_uv += part.mesh.vertex_count();
    }
  }
  const std::map<const shape::Image*, std::string> files = texture_files(materials);
  text.mtl = mtl_text(materials, files);
  for (const auto& [image, name] : files) text.textures.emplace_back(name, image->encoded);
  return text;
}

std::filesystem::path origin_sidecar_path(const std::filesystem::path& obj_path) {
  std::filesystem::path sidecar = obj_path;
  sidecar.replace_extension(".origin.json");
  return sidecar;
}

std::string write_obj(const shape::Scene& scene, const std::filesystem::path& obj_path,
                      const ObjOptions& options) {
  std::filesystem::path mtl_path = obj_path;
  mtl_path.replace_extension(".mtl");
  // The real file name, even with blanks: Blender and assimp read mtllib to the end of the line.
  const ObjText text = obj_text(scene, mtl_path.filename().string(), options);
  std::vector<std::filesystem::path> written;
  const auto write = [&](const std::filesystem::path& path, const std::string& bytes) {
    std::string error = write_file_atomically(path, bytes);
    if (error.empty()) {
      written.push_back(path);
    } else {
      std::error_code ignored;
      for (const auto& p : written) std::filesystem::remove(p, ignored);
    }
    return error;
  };
  for (const auto& [name, bytes] : text.textures) {
    if (std::string error = write(obj_path.parent_path() / name, bytes); !error.empty()) {
      return error;
    }
  }
  if (std::string error = write(mtl_path, text.mtl); !error.empty()) return error;
  if (std::string error = write(origin_sidecar_path(obj_path), text.origin_json); !error.empty()) {
    return error;
  }
  return write(obj_path, text.obj);
}

}  // namespace insula::io
