#include "io/gltf_writer.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <variant>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "io/triangulated.h"

namespace insula::io {
namespace {

using nlohmann::json;

constexpr std::uint32_t kArrayBuffer = 34962;
constexpr std::uint32_t kElementArrayBuffer = 34963;
constexpr std::uint32_t kFloat = 5126;
constexpr std::uint32_t kUnsignedInt = 5125;
constexpr std::uint32_t kTriangles = 4;
constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

// Little-endian whatever the host (glTF 2.0, "Binary glTF Layout").
void append_u32(std::string& out, std::uint32_t value) {
  const char bytes[4] = {static_cast<char>(value & 0xFFU), static_cast<char>((value >> 8) & 0xFFU),
                         static_cast<char>((value >> 16) & 0xFFU),
                         static_cast<char>((value >> 24) & 0xFFU)};
  out.append(bytes, 4);
}

void append_f32(std::string& out, float value) {
  append_u32(out, std::bit_cast<std::uint32_t>(value));
}

// Z-up local meters to glTF's Y-up frame: (x, y, z) -> (x, z, -y), a rotation (keeps handedness).
std::array<float, 3> to_y_up(kernel::Vec3 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.z), static_cast<float>(-p.y)};
}

json value_json(const shape::Value& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  if (const auto* d = std::get_if<double>(&value)) return std::isfinite(*d) ? json(*d) : json();
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  return nullptr;
}

json attributes_json(const shape::AttributeMap& attributes) {
  json out = json::object();
  for (const auto& [name, value] : attributes) out[name] = value_json(value);
  return out;
}

std::string_view kind_name(shape::PartKind kind) {
  switch (kind) {
    case shape::PartKind::kBuildingPart:
      return "BuildingPart";
    case shape::PartKind::kStorey:
      return "Storey";
    case shape::PartKind::kRoom:
      return "Room";
    case shape::PartKind::kInstallation:
      return "Installation";
    case shape::PartKind::kOther:
      break;
  }
  return "Other";
}

// Colour channels rounded to 6 decimals so the JSON shows 0.86, not 0.8600000143051147.
double channel(float value) {
  return std::round(static_cast<double>(value) * 1e6) / 1e6;
}

// Accumulates the binary buffer and the JSON arrays that describe it.
class Builder {
 public:
  explicit Builder(const shape::Scene& scene) : scene_(scene), materials_(scene) {}

  json build();
  const std::string& binary() const { return binary_; }

 private:
  struct Primitive {
    std::string positions;  // float32 xyz, Y-up
    std::string normals;    // float32 xyz, Y-up
    std::string indices;    // uint32
    std::uint32_t vertex_count = 0;
    std::uint32_t index_count = 0;
    std::array<float, 3> min{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                             std::numeric_limits<float>::max()};
    std::array<float, 3> max{std::numeric_limits<float>::lowest(),
                             std::numeric_limits<float>::lowest(),
                             std::numeric_limits<float>::lowest()};
  };

  void add_face(const kernel::Mesh& mesh, std::size_t face, Primitive& primitive);
  json part_node(const shape::Part& part, std::size_t index);
  json add_primitive(const Primitive& primitive, std::uint32_t material);
  std::uint32_t add_accessor(json accessor) {
    accessors_.push_back(std::move(accessor));
    return static_cast<std::uint32_t>(accessors_.size() - 1);
  }
  json materials_json() const;
  json scene_extras() const;

  const shape::Scene& scene_;
  MaterialTable materials_;
  std::string vertex_bytes_;
  std::string index_bytes_;
  std::string binary_;
  json accessors_ = json::array();
  json meshes_ = json::array();
  json nodes_ = json::array();
  std::vector<CornerTriangle> scratch_;
};

void Builder::add_face(const kernel::Mesh& mesh, std::size_t face, Primitive& primitive) {
  scratch_.clear();
  if (!triangulate_face(mesh, face, scratch_)) return;
  const auto loop = mesh.face(face);
  const std::array<float, 3> normal = to_y_up(kernel::face_normal(mesh, face));
  const std::uint32_t base = primitive.vertex_count;
  for (std::uint32_t vertex : loop) {
    const std::array<float, 3> p = to_y_up(mesh.position(vertex));
    for (std::size_t k = 0; k < 3; ++k) {
      append_f32(primitive.positions, p[k]);
      append_f32(primitive.normals, normal[k]);
      primitive.min[k] = std::min(primitive.min[k], p[k]);
      primitive.max[k] = std::max(primitive.max[k], p[k]);
    }
  }
  primitive.vertex_count += static_cast<std::uint32_t>(loop.size());
  for (const CornerTriangle& triangle : scratch_) {
    for (std::uint32_t corner : triangle) append_u32(primitive.indices, base + corner);
  }
  primitive.index_count += static_cast<std::uint32_t>(3 * scratch_.size());
}

json Builder::add_primitive(const Primitive& primitive, std::uint32_t material) {
  const auto vec3_accessor = [&](const std::string& bytes) {
    json accessor = {{"bufferView", 0},
                     {"byteOffset", vertex_bytes_.size()},
                     {"componentType", kFloat},
                     {"count", primitive.vertex_count},
                     {"type", "VEC3"}};
    vertex_bytes_ += bytes;
    return accessor;
  };
  json position = vec3_accessor(primitive.positions);
  position["min"] = {primitive.min[0], primitive.min[1], primitive.min[2]};
  position["max"] = {primitive.max[0], primitive.max[1], primitive.max[2]};
  const std::uint32_t position_index = add_accessor(std::move(position));
  const std::uint32_t normal_index = add_accessor(vec3_accessor(primitive.normals));
  const std::uint32_t index_index = add_accessor({{"bufferView", 1},
                                                  {"byteOffset", index_bytes_.size()},
                                                  {"componentType", kUnsignedInt},
                                                  {"count", primitive.index_count},
                                                  {"type", "SCALAR"}});
  index_bytes_ += primitive.indices;
  return {{"attributes", {{"POSITION", position_index}, {"NORMAL", normal_index}}},
          {"indices", index_index},
          {"material", material},
          {"mode", kTriangles}};
}

json Builder::part_node(const shape::Part& part, std::size_t index) {
  const std::string name = part.name.empty() ? "part" + std::to_string(index) : part.name;
  json extras = attributes_json(part.attributes);
  if (!extras.contains("kind")) extras["kind"] = kind_name(part.kind);
  json node = json::object();
  node["name"] = name;
  node["extras"] = std::move(extras);
  std::map<std::uint32_t, Primitive> by_material;
  for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
    add_face(part.mesh, f, by_material[materials_.index(part.mesh.tag(f))]);
  }
  json primitives = json::array();
  for (const auto& [material, primitive] : by_material) {
    if (primitive.index_count > 0) primitives.push_back(add_primitive(primitive, material));
  }
  if (!primitives.empty()) {
    json mesh = json::object();
    mesh["name"] = name;
    mesh["primitives"] = std::move(primitives);
    meshes_.push_back(std::move(mesh));
    node["mesh"] = meshes_.size() - 1;
  }
  return node;
}

json Builder::materials_json() const {
  json out = json::array();
  for (const shape::Material& material : materials_.materials()) {
    const auto& c = material.rgba;
    json entry = {
        {"name", material.name},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {channel(c[0]), channel(c[1]), channel(c[2]), channel(c[3])}},
          {"metallicFactor", 0.0},
          {"roughnessFactor", 0.9}}}};
    if (c[3] < 1.0F) entry["alphaMode"] = "BLEND";
    out.push_back(std::move(entry));
  }
  return out;
}

json Builder::scene_extras() const {
  json extras = {{"origin", {scene_.origin.x, scene_.origin.y, scene_.origin.z}},
                 {"units", "m"},
                 {"world_from_gltf", "(x, y, z) = (X + origin[0], -Z + origin[1], Y + origin[2])"}};
  if (!scene_.crs.empty()) extras["crs"] = scene_.crs;
  return extras;
}

json Builder::build() {
  json roots = json::array();
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    const shape::Building& building = scene_.buildings[b];
    json children = json::array();
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      nodes_.push_back(part_node(building.parts[p], p));
      children.push_back(nodes_.size() - 1);
    }
    json node = {{"name", building.id.empty() ? "building" + std::to_string(b) : building.id}};
    if (!children.empty()) node["children"] = std::move(children);
    if (!building.attributes.empty()) node["extras"] = attributes_json(building.attributes);
    nodes_.push_back(std::move(node));
    roots.push_back(nodes_.size() - 1);
  }
  json scene = {{"name", "Insula"}, {"extras", scene_extras()}};
  if (!roots.empty()) scene["nodes"] = std::move(roots);
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "Insula"}}}, {"scene", 0}};
  gltf["scenes"] = json::array();
  gltf["scenes"].push_back(std::move(scene));
  if (!nodes_.empty()) gltf["nodes"] = std::move(nodes_);
  if (!meshes_.empty()) {
    gltf["meshes"] = std::move(meshes_);
    gltf["accessors"] = std::move(accessors_);
    gltf["materials"] = materials_json();
    gltf["bufferViews"] = {{{"buffer", 0},
                            {"byteLength", vertex_bytes_.size()},
                            {"byteStride", 12},
                            {"target", kArrayBuffer}},
                           {{"buffer", 0},
                            {"byteOffset", vertex_bytes_.size()},
                            {"byteLength", index_bytes_.size()},
                            {"target", kElementArrayBuffer}}};
    binary_.reserve(vertex_bytes_.size() + index_bytes_.size());
    binary_.append(vertex_bytes_).append(index_bytes_);
    gltf["buffers"] = {{{"byteLength", binary_.size()}}};
  }
  return gltf;
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t group = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    if (n > 1) group |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (n > 2) group |= static_cast<unsigned char>(bytes[i + 2]);
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 0x3FU] : '=';
    }
  }
  return out;
}

std::size_t padded(std::size_t size) {
  return (size + 3) / 4 * 4;
}

void append_chunk(std::string& out, const std::string& data, char pad, std::uint32_t type) {
  append_u32(out, static_cast<std::uint32_t>(padded(data.size())));
  append_u32(out, type);
  out += data;
  out.append(padded(data.size()) - data.size(), pad);
}

bool has_gltf_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".gltf";
}

}  // namespace

std::string glb_bytes(const shape::Scene& scene) {
  Builder builder(scene);
  const json gltf = builder.build();
  const std::string text = gltf.dump();
  const std::string& binary = builder.binary();
  const std::size_t total =
      12 + 8 + padded(text.size()) + (binary.empty() ? 0 : 8 + padded(binary.size()));
  std::string out;
  out.reserve(total);
  append_u32(out, kGlbMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_chunk(out, text, ' ', kChunkJson);
  if (!binary.empty()) append_chunk(out, binary, '\0', kChunkBin);
  return out;
}

std::string gltf_text(const shape::Scene& scene) {
  Builder builder(scene);
  json gltf = builder.build();
  if (gltf.contains("buffers")) {
    gltf["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(builder.binary());
  }
  return gltf.dump(1) + "\n";
}

std::string write_gltf(const shape::Scene& scene, const std::filesystem::path& path) {
  return write_file_atomically(path,
                               has_gltf_extension(path) ? gltf_text(scene) : glb_bytes(scene));
}

}  // namespace insula::io
