#include "io/obj_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <system_error>
#include <tuple>
#include <utility>

#include "io/atomic_file.h"
#include "io/json_stream.h"
#include "io/triangulated.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

// 1 µm: far below the 1 mm a survey needs, and 6 + 7 digits stay exact in a double for UTM.
constexpr int kCoordinateDecimals = 6;
// Room for a number from write_decimal().
constexpr std::size_t kDecimalRoom = 64;

// A scene point as the OBJ writes it: local or world, Z up or Y up (x, z, -y).
kernel::Vec3 written(kernel::Vec3 local, const shape::Scene& scene, const ObjOptions& options) {
  const kernel::Vec3 p = options.world ? local + scene.origin : local;
  if (options.up_axis() == 'y') return {p.x, p.z, -p.y};
  return p;
}

// `value` rounded to `decimals` decimals the slow, exact way: std::to_chars' correctly rounded
// fixed notation (ties to even on the exact binary value), trailing zeros trimmed; "0" past
// kDecimalRoom characters.
char* write_decimal_exactly(char* at, double value, int decimals) {
  std::array<char, kDecimalRoom> buffer;
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                          std::chars_format::fixed, decimals);
  if (error != std::errc()) {
    *at = '0';
    return at + 1;
  }
  std::string_view text(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
  if (text.find('.') != std::string_view::npos) {
    while (text.back() == '0') text.remove_suffix(1);
    if (text.back() == '.') text.remove_suffix(1);
  }
  if (text == "-0") text = "0";
  return std::copy(text.begin(), text.end(), at);
}

// The usual case in integers: value * 10^decimals rounded to the nearest integer, whose digits are
// then the text. The product carries a rounding error of at most |product| * 2^-53; where its
// fraction is further than twice that from one half, the nearest integer is the one to_chars
// rounds the exact value to. Closer to a tie (or too large for the integers) the exact path
// decides.
char* write_decimal(char* at, double value, int decimals) {
  static constexpr std::array<std::int64_t, 10> kPowers{
      1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};
  if (!std::isfinite(value)) {
    *at = '0';
    return at + 1;
  }
  const double scaled = decimals >= 0 && decimals < 10 ? value * kPowers[decimals] : 0;
  const double magnitude = std::abs(scaled);
  const double whole = std::floor(magnitude);
  const double fraction = magnitude - whole;
  if (decimals < 0 || decimals >= 10 || !(magnitude < 1e15) ||
      std::abs(fraction - 0.5) <= magnitude * 0x1p-52 + 0x1p-60) {
    return write_decimal_exactly(at, value, decimals);
  }
  auto units = static_cast<std::int64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  if (scaled < 0 && units != 0) *at++ = '-';
  const std::int64_t power = kPowers[decimals];
  at = std::to_chars(at, at + kDecimalRoom, units / power).ptr;
  if (std::int64_t rest = units % power; rest != 0) {
    *at++ = '.';
    int digits = decimals;
    while (rest % 10 == 0) {
      rest /= 10;
      --digits;
    }
    for (int d = digits - 1; d >= 0; --d) {
      at[d] = static_cast<char>('0' + rest % 10);
      rest /= 10;
    }
    at += digits;
  }
  return at;
}

// Where a vertex line lies in the text: two vertices are one point in the file when their lines
// are the same text.
struct VertexLine {
  std::size_t offset;
  std::size_t size;
};

// Lines are formed in a buffer and appended whole: appending piece by piece cost more than the
// formatting.
VertexLine append_vertex(std::string& out, kernel::Vec3 p) {
  std::array<char, 3 * kDecimalRoom + 8> line;
  char* at = line.data();
  *at++ = 'v';
  for (double c : {p.x, p.y, p.z}) {
    *at++ = ' ';
    at = write_decimal(at, c, kCoordinateDecimals);
  }
  *at++ = '\n';
  const VertexLine written_line{out.size(), static_cast<std::size_t>(at - line.data())};
  out.append(line.data(), at);
  return written_line;
}

// The corners of a face as the file shows them: a corner written at the same place as the corner
// before it (two vertices closer than the 1 um the text keeps, as a PLaSM column's capital has
// where its surface pinches) is left out, as the GLB writer contracts them. Fewer than three left:
// the face has no area in the file and is not written. Returns whether `kept` is the loop itself.
bool corners_as_written(const std::string& out, const kernel::Mesh& mesh,
                        std::span<const VertexLine> lines, std::span<const std::uint32_t> loop,
                        std::vector<std::uint32_t>& kept) {
  const auto same_place = [&](std::uint32_t a, std::uint32_t b) {
    // Points a few micrometres apart or more are written apart: the text is compared only for
    // the rare corners closer than that.
    constexpr double kApart = 4e-6;
    const kernel::Vec3 d = mesh.position(a) - mesh.position(b);
    if (std::abs(d.x) > kApart || std::abs(d.y) > kApart || std::abs(d.z) > kApart) return false;
    const VertexLine& x = lines[a];
    const VertexLine& y = lines[b];
    return a == b ||
           (x.size == y.size && out.compare(x.offset, x.size, out, y.offset, y.size) == 0);
  };
  bool all = true;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (same_place(loop[i], loop[(i + 1) % loop.size()])) all = false;
  }
  if (all) return true;
  kept.clear();
  for (std::uint32_t vertex : loop) {
    if (kept.empty() || !same_place(kept.back(), vertex)) kept.push_back(vertex);
  }
  while (kept.size() > 1 && same_place(kept.back(), kept.front())) kept.pop_back();
  return false;
}

// "f v v v ..." or "f v/vt v/vt ...", one buffer at a time however long the face.
void append_face(std::string& out, std::span<const std::uint32_t> loop, std::size_t first_vertex,
                 std::optional<std::size_t> first_uv) {
  std::array<char, 256> line;
  constexpr std::size_t kCorner = 48;  // " 123/456" at most
  char* at = line.data();
  *at++ = 'f';
  for (std::uint32_t vertex : loop) {
    if (line.data() + line.size() - at < static_cast<std::ptrdiff_t>(kCorner)) {
      out.append(line.data(), at);
      at = line.data();
    }
    *at++ = ' ';
    at = std::to_chars(at, at + 20, first_vertex + vertex).ptr;
    if (first_uv) {
      *at++ = '/';
      at = std::to_chars(at, at + 20, *first_uv + vertex).ptr;
    }
  }
  *at++ = '\n';
  out.append(line.data(), at);
}

// A face of a part with the group it is written in: class, then material index.
struct GroupedFace {
  kernel::SemanticClass semantic;
  std::uint32_t material;
  std::size_t face;
};

// The faces of one part by group, in class then material order, in mesh order within a group.
void group_faces(const kernel::Mesh& mesh, const MaterialTable& materials,
                 std::vector<GroupedFace>& faces) {
  faces.clear();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const kernel::FaceTag& tag = mesh.tag(f);
    faces.push_back({tag.semantic, materials.index(tag), f});
  }
  // The face number last: a plain sort keeps mesh order within a group.
  std::sort(faces.begin(), faces.end(), [](const GroupedFace& a, const GroupedFace& b) {
    return std::tuple(a.semantic, a.material, a.face) < std::tuple(b.semantic, b.material, b.face);
  });
}

// Scratch of append_part(), kept from part to part.
struct PartScratch {
  std::vector<GroupedFace> faces;
  std::vector<VertexLine> lines;
  std::vector<std::uint32_t> corners;
};

// Writes a part's vertices (and texture coordinates, one per vertex, when it has a uv map) then its
// faces; `first_vertex` / `first_uv` are the 1-based OBJ indices of its vertex 0 / its first vt.
void append_part(std::string& out, const shape::Scene& scene, const ObjOptions& options,
                 const std::string& building_name, const shape::Part& part, std::size_t part_index,
                 const MaterialTable& materials, std::size_t first_vertex, std::size_t first_uv,
                 PartScratch& scratch) {
  scratch.lines.clear();
  for (const kernel::Vec3& p : part.mesh.positions()) {
    scratch.lines.push_back(append_vertex(out, written(p, scene, options)));
  }
  if (part.uv) {
    for (const kernel::Vec3& p : part.mesh.positions()) {
      const kernel::Vec2 t = part.uv->at(p);
      out += "vt ";
      append_decimal(out, t.x, kCoordinateDecimals);
      out += ' ';
      append_decimal(out, t.y, kCoordinateDecimals);
      out += '\n';
    }
  }
  const std::string part_name = safe_name(part.name, "part" + std::to_string(part_index));
  group_faces(part.mesh, materials, scratch.faces);
  const GroupedFace* group = nullptr;  // the group of the last face written
  for (const GroupedFace& face : scratch.faces) {
    std::span<const std::uint32_t> loop = part.mesh.face(face.face);
    if (!corners_as_written(out, part.mesh, scratch.lines, loop, scratch.corners)) {
      if (scratch.corners.size() < 3) continue;
      loop = scratch.corners;
    }
    if (group == nullptr || face.semantic != group->semantic || face.material != group->material) {
      out += "g " + building_name + "." + part_name + "." +
             std::string(kernel::semantic_name(face.semantic)) + "\n";
      out += "usemtl " + materials.materials()[face.material].name + "\n";
    }
    group = &face;
    append_face(out, loop, first_vertex, part.uv ? std::optional(first_uv) : std::nullopt);
  }
}

// About the size of the OBJ text, so that it is not reallocated (and copied) as it grows: a vertex
// line ("v 12.345678 9 -6.5") about 32 bytes, a face about 8 a corner, a part's group lines 96.
std::size_t text_size(const shape::Scene& scene) {
  std::size_t size = 1024;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      const kernel::Mesh& mesh = part.mesh;
      std::size_t corners = 0;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) corners += mesh.face(f).size();
      const std::size_t per_vertex = part.uv ? 56 : 32;
      size += per_vertex * mesh.vertex_count() + 8 * corners + 4 * mesh.face_count() + 96;
    }
  }
  return size;
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

void append_decimal(std::string& out, double value, int decimals) {
  std::array<char, kDecimalRoom> buffer;
  out.append(buffer.data(), write_decimal(buffer.data(), value, decimals));
}

std::string format_decimal(double value, int decimals) {
  std::string text;
  append_decimal(text, value, decimals);
  return text;
}

ObjText obj_text(const shape::Scene& input, std::string_view mtl_file_name,
                 const ObjOptions& options) {
  shape::Scene expanded;  // shared-mesh instances written as plain geometry
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  const MaterialTable materials(scene);
  ObjText text;
  text.obj.reserve(text_size(scene));
  append_header(text.obj, scene, options, mtl_file_name);
  text.origin_json = origin_json(scene, options);
  std::size_t next_vertex = 1;
  std::size_t next_uv = 1;
  PartScratch scratch;
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    const shape::Building& building = scene.buildings[b];
    const std::string building_name = safe_name(building.id, "building" + std::to_string(b));
    text.obj += "o " + building_name + "\n";
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      const shape::Part& part = building.parts[p];
      append_part(text.obj, scene, options, building_name, part, p, materials, next_vertex, next_uv,
                  scratch);
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
