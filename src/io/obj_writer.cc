#include "io/obj_writer.h"

#include <charconv>
#include <cmath>
#include <map>
#include <system_error>
#include <utility>

#include "io/atomic_file.h"
#include "io/triangulated.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

// 1 µm: far below the 1 mm a survey needs, and 6 + 7 digits stay exact in a double for UTM.
constexpr int kCoordinateDecimals = 6;

void append_vertex(std::string& out, kernel::Vec3 world) {
  out += "v ";
  out += format_decimal(world.x, kCoordinateDecimals);
  out += ' ';
  out += format_decimal(world.y, kCoordinateDecimals);
  out += ' ';
  out += format_decimal(world.z, kCoordinateDecimals);
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

// Writes a part's vertices then its faces; `first_vertex` is the 1-based OBJ index of its vertex 0.
void append_part(std::string& out, const shape::Scene& scene, const std::string& building_name,
                 const shape::Part& part, std::size_t part_index, const MaterialTable& materials,
                 std::size_t first_vertex) {
  for (const kernel::Vec3& p : part.mesh.positions()) append_vertex(out, p + scene.origin);
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
      }
      out += '\n';
    }
  }
}

void append_header(std::string& out, const shape::Scene& scene, std::string_view mtl_file_name) {
  out += "# Insula OBJ export: meters, Z up, world coordinates (local + origin)\n";
  out += "# origin " + format_decimal(scene.origin.x, kCoordinateDecimals) + " " +
         format_decimal(scene.origin.y, kCoordinateDecimals) + " " +
         format_decimal(scene.origin.z, kCoordinateDecimals) + "\n";
  if (!scene.crs.empty()) out += "# crs " + safe_name(scene.crs, "") + "\n";
  out += "mtllib " + std::string(mtl_file_name) + "\n";
}

std::string mtl_text(const MaterialTable& materials) {
  std::string out = "# Insula MTL export: Kd is the material's linear RGB colour, d its alpha\n";
  for (const shape::Material& material : materials.materials()) {
    const auto channel = [&](std::size_t i) { return format_decimal(material.rgba[i], 6); };
    out += "\nnewmtl " + material.name + "\n";
    out += "Ka 0 0 0\n";
    out += "Kd " + channel(0) + " " + channel(1) + " " + channel(2) + "\n";
    out += "Ks 0 0 0\n";
    out += "d " + channel(3) + "\n";
    out += "illum 1\n";
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

ObjText obj_text(const shape::Scene& input, std::string_view mtl_file_name) {
  shape::Scene expanded;  // shared-mesh instances written as plain geometry
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  const MaterialTable materials(scene);
  ObjText text;
  append_header(text.obj, scene, mtl_file_name);
  std::size_t next_vertex = 1;
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    const shape::Building& building = scene.buildings[b];
    const std::string building_name = safe_name(building.id, "building" + std::to_string(b));
    text.obj += "o " + building_name + "\n";
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      const shape::Part& part = building.parts[p];
      append_part(text.obj, scene, building_name, part, p, materials, next_vertex);
      next_vertex += part.mesh.vertex_count();
    }
  }
  text.mtl = mtl_text(materials);
  return text;
}

std::string write_obj(const shape::Scene& scene, const std::filesystem::path& obj_path) {
  std::filesystem::path mtl_path = obj_path;
  mtl_path.replace_extension(".mtl");
  // The real file name, even with blanks: Blender and assimp read mtllib to the end of the line.
  const ObjText text = obj_text(scene, mtl_path.filename().string());
  if (std::string error = write_file_atomically(mtl_path, text.mtl); !error.empty()) return error;
  if (std::string error = write_file_atomically(obj_path, text.obj); !error.empty()) {
    std::error_code ignored;
    std::filesystem::remove(mtl_path, ignored);
    return error;
  }
  return {};
}

}  // namespace insula::io
