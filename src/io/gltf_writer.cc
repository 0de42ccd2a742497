#include "io/gltf_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "io/atomic_file.h"
#include "io/float32_weld.h"
#include "io/json_stream.h"
#include "io/png_renderer.h"
#include "io/triangulated.h"
#include "kernel/uv.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

constexpr std::uint32_t kArrayBuffer = 34962;
constexpr std::uint32_t kElementArrayBuffer = 34963;
constexpr std::uint32_t kFloat = 5126;
constexpr std::uint32_t kUnsignedInt = 5125;
constexpr std::uint32_t kTriangles = 4;
constexpr std::uint32_t kLinear = 9729;
constexpr std::uint32_t kLinearMipmapLinear = 9987;
constexpr std::uint32_t kClampToEdge = 33071;
constexpr std::uint32_t kRepeat = 10497;
constexpr std::string_view kLightsExtension = "KHR_lights_punctual";
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

std::size_t padded(std::size_t size) {
  return (size + 3) / 4 * 4;
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

std::string part_name(const shape::Part& part, std::size_t index) {
  return part.name.empty() ? "part" + std::to_string(index) : part.name;
}

// One primitive (the faces of one part showing one material): where its data sits in the buffer.
// Accessors come in threes: POSITION (with min/max), NORMAL, indices.
struct PrimitiveRecord {
  std::uint32_t material = 0;
  std::uint32_t vertex_count = 0;
  std::uint32_t index_count = 0;
  std::size_t position_offset = 0;  // bytes into the vertex view; normals follow the positions
  std::size_t index_offset = 0;     // bytes into the index view
  std::size_t uv_offset = 0;        // bytes into the texture coordinate view
  // TEXCOORD_0 (parts with a uv map, parts of solidGeometry with "uv_scale", textured materials)
  bool has_uv = false;
  std::uint32_t accessor = 0;  // first of its accessors (3, or 4 with texture coordinates)
  std::array<float, 3> min{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::max()};
  std::array<float, 3> max{std::numeric_limits<float>::lowest(),
                           std::numeric_limits<float>::lowest(),
                           std::numeric_limits<float>::lowest()};
};

// A glTF mesh: a run of primitives. Parts that are instances of one shared mesh (seed 001 §4.5)
// point at the same record and get a node each with their placement as the node's matrix.
struct MeshRecord {
  std::string name;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

// The texture size of a part in meters, or 0 for none (solid_geometry's attribute).
double uv_scale(const shape::Part& part) {
  auto it = part.attributes.find("uv_scale");
  if (it == part.attributes.end()) return 0;
  const auto* v = std::get_if<double>(&it->second);
  return v != nullptr && *v > 0 ? *v : 0;
}

// A material's image as PNG bytes, or empty when it has none (or a malformed one).
std::string png_of(const shape::Material& material) {
  const shape::Image* image = material.image.get();
  if (image == nullptr) return {};
  if (!image->encoded.empty()) return image->encoded;  // a file's bytes, embedded as they are
  if (image->width <= 0 || image->height <= 0 ||
      image->rgba.size() !=
          4 * static_cast<std::size_t>(image->width) * static_cast<std::size_t>(image->height)) {
    return {};
  }
  return encode_png(Image{image->width, image->height, image->rgba});
}

// Fills the binary buffer in one pass over the scene (vertex view: per primitive its positions
// then its normals; index view after it), then writes the JSON from compact records. Object keys
// are written in sorted order, so the text is the one nlohmann::json would print.
class Builder {
 public:
  explicit Builder(const shape::Scene& scene);

  // The glTF JSON; `buffer_uri` (when not empty) becomes the buffer's "uri".
  void write_json(JsonStream& json, std::string_view buffer_uri) const;
  // Appends the binary buffer (vertex, index and texture coordinate views, little-endian, then
  // the PNG images).
  void append_binary(std::string& out) const;
  std::size_t binary_size() const { return image_offset(images_.size()); }

 private:
  // Adds the part's primitives as a new glTF mesh (or finds its shared one); returns the mesh
  // index, or -1 when no face produced a triangle.
  std::int32_t add_part(const shape::Part& part, std::size_t index);
  std::uint32_t add_primitives(const kernel::Mesh& mesh, double uv, const shape::Part& part);
  void add_primitive(const kernel::Mesh& mesh, std::uint32_t material,
                     std::span<const std::pair<std::uint32_t, std::uint32_t>> faces);
  void add_face(const kernel::Mesh& mesh, std::size_t face, PrimitiveRecord& primitive);
  // Appends the corners `loop` (mesh vertex ids) and the triangles in triangles_ over them.
  void add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                   kernel::Vec3 newell, PrimitiveRecord& primitive);

  void add_images();
  // Bytes into the buffer where image `image` starts (each padded to 4 bytes after the UVs).
  std::size_t image_offset(std::size_t image) const;
  void fit_uvs(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop, kernel::Vec3 newell);

  void write_accessors(JsonStream& json) const;
  void write_meshes(JsonStream& json) const;
  void write_nodes(JsonStream& json) const;
  void write_materials(JsonStream& json) const;
  void write_lights(JsonStream& json) const;
  void write_light_node(JsonStream& json, std::size_t light) const;
  void write_images(JsonStream& json) const;
  void write_buffers(JsonStream& json, std::string_view buffer_uri) const;
  void write_scene(JsonStream& json) const;
  // The wrap modes of the samplers, in sampler order: clamped first when used, then repeat.
  std::vector<std::uint32_t> sampler_wraps() const {
    std::vector<std::uint32_t> wraps;
    if (std::count(image_repeats_.begin(), image_repeats_.end(), false) > 0) {
      wraps.push_back(kClampToEdge);
    }
    if (std::count(image_repeats_.begin(), image_repeats_.end(), true) > 0)
      wraps.push_back(kRepeat);
    return wraps;
  }

  const shape::Scene& scene_;
  MaterialTable materials_;
  std::vector<float> vertices_;         // the vertex view, as floats
  std::vector<std::uint32_t> indices_;  // the index view
  std::vector<PrimitiveRecord> primitives_;
  std::vector<float> uvs_;  // the texture coordinate view (empty: no such view)
  // Textures: one per distinct image of a material in the table, PNG-encoded; their bytes follow
  // the texture coordinates in the buffer, each in a view of its own.
  std::vector<std::int32_t> material_texture_;  // by table material; -1: untextured
  std::vector<std::string> images_;             // PNG (or a file's JPEG) bytes by texture
  std::vector<std::string> image_names_;
  std::vector<std::string> image_types_;  // MIME types
  std::vector<bool> image_repeats_;       // a file's image repeats over a uv map
  std::vector<MeshRecord> meshes_;
  std::vector<std::int32_t> part_mesh_;  // glTF mesh of each part (-1: none), parts in scene order
  std::map<const kernel::Mesh*, std::int32_t> shared_;  // instance meshes already added
  double uv_ = 0;                                       // texture size of the part being added
  const shape::Part* uv_part_ = nullptr;                // the part being added when it has a uv map
  bool fit_uv_ = false;  // the primitive being added shows an image: UVs fit each face

  // Scratch reused from face to face.
  FaceTriangulator triangulator_;
  std::vector<CornerTriangle> triangles_;
  std::vector<float> normals_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> faces_by_material_;
  Float32Weld weld_;                    // of the mesh being added
  std::vector<std::uint32_t> corners_;  // a welded face's corners (representative vertex ids)
  std::vector<kernel::Vec2> face_uvs_;  // a textured face's planar coordinates
};

Builder::Builder(const shape::Scene& scene) : scene_(scene), materials_(scene) {
  // Upper bounds (every face kept): 6 floats per corner, 3 indices per corner beyond two a face.
  std::size_t corners = 0;
  std::size_t triangles = 0;
  for (const shape::Building& building : scene_.buildings) {
    for (const shape::Part& part : building.parts) {
      const kernel::Mesh& mesh = part.instance_of ? *part.instance_of : part.mesh;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const std::size_t n = mesh.face(f).size();
        corners += n;
        triangles += n >= 3 ? n - 2 : 0;
      }
    }
  }
  vertices_.reserve(6 * corners);
  indices_.reserve(3 * triangles);
  add_images();
  for (const shape::Building& building : scene_.buildings) {
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      part_mesh_.push_back(add_part(building.parts[p], p));
    }
  }
  // No primitive, no buffer to hold the images.
  if (primitives_.empty()) images_.clear();
}

void Builder::add_images() {
  std::map<const shape::Image*, std::int32_t> seen;
  for (const shape::Material& material : materials_.materials()) {
    std::int32_t texture = -1;
    if (material.image != nullptr) {
      const auto [it, added] = seen.try_emplace(material.image.get(), -1);
      if (added) {
        if (std::string png = png_of(material); !png.empty()) {
          it->second = static_cast<std::int32_t>(images_.size());
          images_.push_back(std::move(png));
          image_names_.push_back(material.image->name);
          const bool file = !material.image->encoded.empty();
          image_types_.push_back(file ? material.image->mime_type : "image/png");
          image_repeats_.push_back(file);
        }
      }
      texture = it->second;
    }
    material_texture_.push_back(texture);
  }
}

std::int32_t Builder::add_part(const shape::Part& part, std::size_t index) {
  // Instances share a mesh, unless a uv map gives each its own texture coordinates.
  const bool shared = part.instance_of && !part.uv;
  if (shared) {
    if (auto it = shared_.find(part.instance_of.get()); it != shared_.end()) return it->second;
  }
  const auto first = static_cast<std::uint32_t>(primitives_.size());
  const std::uint32_t count =
      add_primitives(part.instance_of ? *part.instance_of : part.mesh, uv_scale(part), part);
  std::int32_t mesh = -1;
  if (count > 0) {
    mesh = static_cast<std::int32_t>(meshes_.size());
    meshes_.push_back({part_name(part, index), first, count});
  }
  if (shared) shared_[part.instance_of.get()] = mesh;
  return mesh;
}

// One primitive per material, materials in index order, faces in mesh order within each.
std::uint32_t Builder::add_primitives(const kernel::Mesh& mesh, double uv,
                                      const shape::Part& part) {
  uv_ = uv;
  uv_part_ = part.uv ? &part : nullptr;
  weld_.run(mesh);
  faces_by_material_.clear();
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    faces_by_material_.emplace_back(materials_.index(mesh.tag(f)), f);
  }
  std::sort(faces_by_material_.begin(), faces_by_material_.end());
  const std::size_t first = primitives_.size();
  const std::span<const std::pair<std::uint32_t, std::uint32_t>> all(faces_by_material_);
  for (std::size_t begin = 0; begin < all.size();) {
    std::size_t end = begin;
    while (end < all.size() && all[end].first == all[begin].first) ++end;
    add_primitive(mesh, all[begin].first, all.subspan(begin, end - begin));
    begin = end;
  }
  return static_cast<std::uint32_t>(primitives_.size() - first);
}

void Builder::add_primitive(const kernel::Mesh& mesh, std::uint32_t material,
                            std::span<const std::pair<std::uint32_t, std::uint32_t>> faces) {
  PrimitiveRecord primitive;
  primitive.material = material;
  primitive.position_offset = 4 * vertices_.size();
  primitive.index_offset = 4 * indices_.size();
  primitive.uv_offset = 4 * uvs_.size();
  fit_uv_ = material_texture_[material] >= 0;
  primitive.has_uv = uv_part_ != nullptr || uv_ > 0 || fit_uv_;
  primitive.accessor =
      primitives_.empty() ? 0 : primitives_.back().accessor + (primitives_.back().has_uv ? 4 : 3);
  normals_.clear();
  for (const auto& entry : faces) add_face(mesh, entry.second, primitive);
  if (primitive.index_count == 0) return;  // every face degenerate: no primitive
  vertices_.insert(vertices_.end(), normals_.begin(), normals_.end());
  primitives_.push_back(primitive);
}

// Flat shading: the face's corners become vertices of their own, all carrying the face normal.
// Where float32 merges vertices (weld_, float32_weld.h) the face's triangles and corners come from
// the weld, over the merged vertices.
void Builder::add_face(const kernel::Mesh& mesh, std::size_t face, PrimitiveRecord& primitive) {
  const kernel::Vec3 newell = kernel::face_normal(mesh, face);
  triangles_.clear();
  if (!weld_.active()) {
    if (!triangulator_.triangulate(mesh, face, newell, triangles_)) return;
    add_corners(mesh, mesh.face(face), newell, primitive);
    return;
  }
  corners_.clear();
  for (const auto& triangle : weld_.triangles(face)) {
    CornerTriangle t{};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto it = std::find(corners_.begin(), corners_.end(), triangle[k]);
      t[k] = static_cast<std::uint32_t>(it - corners_.begin());
      if (it == corners_.end()) corners_.push_back(triangle[k]);
    }
    triangles_.push_back(t);
  }
  add_corners(mesh, corners_, newell, primitive);
}

void Builder::add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                          kernel::Vec3 newell, PrimitiveRecord& primitive) {
  const std::array<float, 3> normal = to_y_up(newell);
  const std::uint32_t base = primitive.vertex_count;
  if (uv_part_ != nullptr) {
    // The part's map is over world positions; an instance's mesh is placed first. glTF's v runs
    // down the image, CityEngine's up.
    for (std::uint32_t vertex : loop) {
      const kernel::Vec3 p = mesh.position(vertex);
      const kernel::Vec2 t = uv_part_->uv->at(
          uv_part_->instance_of ? kernel::apply_point(uv_part_->instance_transform, p) : p);
      uvs_.push_back(static_cast<float>(t.x));
      uvs_.push_back(static_cast<float>(1 - t.y));
    }
  } else if (fit_uv_) {
    fit_uvs(mesh, loop, newell);
  }
  for (std::uint32_t vertex : loop) {
    if (uv_ > 0 && !fit_uv_ && uv_part_ == nullptr) {
      const kernel::Vec2 t = kernel::planar_uv(mesh.position(vertex), newell, uv_);
      uvs_.push_back(static_cast<float>(t.x));
      uvs_.push_back(static_cast<float>(t.y));
    }
    const Float3 p = to_y_up(mesh.position(weld_.representative(vertex)));
    for (std::size_t k = 0; k < 3; ++k) {
      vertices_.push_back(p[k]);
      normals_.push_back(normal[k]);
      primitive.min[k] = std::min(primitive.min[k], p[k]);
      primitive.max[k] = std::max(primitive.max[k], p[k]);
    }
  }
  primitive.vertex_count += static_cast<std::uint32_t>(loop.size());
  for (const CornerTriangle& triangle : triangles_) {
    for (std::uint32_t corner : triangle) indices_.push_back(base + corner);
  }
  primitive.index_count += static_cast<std::uint32_t>(3 * triangles_.size());
}

// A textured face shows its image once: the face's planar coordinates (kernel::planar_uv, u to the
// right and v up seen from outside) scaled to its extent, v flipped because glTF's (0, 0) is the
// image's top-left corner. So text reads the right way round on walls, roofs and floors.
void Builder::fit_uvs(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                      kernel::Vec3 newell) {
  kernel::Vec2 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  kernel::Vec2 high{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  face_uvs_.clear();
  for (std::uint32_t vertex : loop) {
    const kernel::Vec2 t = kernel::planar_uv(mesh.position(vertex), newell, 1);
    low = {std::min(low.x, t.x), std::min(low.y, t.y)};
    high = {std::max(high.x, t.x), std::max(high.y, t.y)};
    face_uvs_.push_back(t);
  }
  const auto unit = [](double v, double from, double to) {
    return to > from ? (v - from) / (to - from) : 0.0;
  };
  for (const kernel::Vec2 t : face_uvs_) {
    uvs_.push_back(static_cast<float>(unit(t.x, low.x, high.x)));
    uvs_.push_back(static_cast<float>(1 - unit(t.y, low.y, high.y)));
  }
}

// Little-endian whatever the host (glTF 2.0, "Binary glTF Layout").
template <typename T>
void append_little_endian(std::string& out, const std::vector<T>& values) {
  static_assert(sizeof(T) == 4);
  if constexpr (std::endian::native == std::endian::little) {
    out.append(reinterpret_cast<const char*>(values.data()), 4 * values.size());
  } else {
    for (T value : values) append_u32(out, std::bit_cast<std::uint32_t>(value));
  }
}

std::size_t Builder::image_offset(std::size_t image) const {
  std::size_t offset = 4 * (vertices_.size() + indices_.size() + uvs_.size());
  for (std::size_t i = 0; i < image; ++i) offset += padded(images_[i].size());
  return offset;
}

void Builder::append_binary(std::string& out) const {
  append_little_endian(out, vertices_);
  append_little_endian(out, indices_);
  append_little_endian(out, uvs_);
  for (const std::string& png : images_) {
    out += png;
    out.append(padded(png.size()) - png.size(), '\0');
  }
}

void write_vec3(JsonStream& json, const std::array<float, 3>& v) {
  json.begin_array();
  for (float c : v) json.number(static_cast<double>(c));
  json.end_array();
}

// An instance's placement (local Z-up) as a glTF node matrix (Y-up, column-major): C T C^-1 with
// C: (x, y, z) -> (x, z, -y).
void write_matrix(JsonStream& json, const kernel::Transform& t) {
  const auto c = [](kernel::Vec3 v) { return std::array<double, 3>{v.x, v.z, -v.y}; };
  const std::array<std::array<double, 3>, 4> columns = {c(t.x), c(t.z), c(-t.y), c(t.t)};
  json.key("matrix").begin_array();
  for (std::size_t k = 0; k < 4; ++k) {
    for (double v : columns[k]) json.number(v);
    json.number(k == 3 ? 1.0 : 0.0);
  }
  json.end_array();
}

void Builder::write_accessors(JsonStream& json) const {
  json.key("accessors").begin_array();
  for (const PrimitiveRecord& p : primitives_) {
    json.begin_object().key("bufferView").integer(0).key("byteOffset").integer(p.position_offset);
    json.key("componentType").integer(kFloat).key("count").integer(p.vertex_count);
    json.key("max");
    write_vec3(json, p.max);
    json.key("min");
    write_vec3(json, p.min);
    json.key("type").string("VEC3").end_object();
    json.begin_object().key("bufferView").integer(0).key("byteOffset");
    json.integer(p.position_offset + 12 * std::size_t{p.vertex_count});
    json.key("componentType").integer(kFloat).key("count").integer(p.vertex_count);
    json.key("type").string("VEC3").end_object();
    json.begin_object().key("bufferView").integer(1).key("byteOffset").integer(p.index_offset);
    json.key("componentType").integer(kUnsignedInt).key("count").integer(p.index_count);
    json.key("type").string("SCALAR").end_object();
    if (!p.has_uv) continue;
    json.begin_object().key("bufferView").integer(2).key("byteOffset").integer(p.uv_offset);
    json.key("componentType").integer(kFloat).key("count").integer(p.vertex_count);
    json.key("type").string("VEC2").end_object();
  }
  json.end_array();
}

void Builder::write_meshes(JsonStream& json) const {
  json.key("meshes").begin_array();
  for (const MeshRecord& mesh : meshes_) {
    json.begin_object().key("name").string(mesh.name);
    json.key("primitives").begin_array();
    for (std::uint32_t primitive = mesh.first; primitive < mesh.first + mesh.count; ++primitive) {
      const PrimitiveRecord& record = primitives_[primitive];
      const std::uint32_t accessor = record.accessor;
      json.begin_object().key("attributes").begin_object();
      json.key("NORMAL").integer(accessor + 1).key("POSITION").integer(accessor);
      if (record.has_uv) json.key("TEXCOORD_0").integer(accessor + 3);
      json.end_object();
      json.key("indices").integer(accessor + 2);
      json.key("material").integer(record.material);
      json.key("mode").integer(kTriangles).end_object();
    }
    json.end_array().end_object();
  }
  json.end_array();
}

// Per building: one node per part, then the building's node with those parts as children.
void Builder::write_nodes(JsonStream& json) const {
  json.key("nodes").begin_array();
  std::size_t part_index = 0;
  std::size_t node = 0;
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    const shape::Building& building = scene_.buildings[b];
    for (std::size_t p = 0; p < building.parts.size(); ++p) {
      const shape::Part& part = building.parts[p];
      json.begin_object().key("extras").attributes(part.attributes, "kind", kind_name(part.kind));
      if (part.instance_of) write_matrix(json, part.instance_transform);
      if (const std::int32_t mesh = part_mesh_[part_index++]; mesh >= 0)
        json.key("mesh").integer(mesh);
      json.key("name").string(part_name(part, p)).end_object();
    }
    json.begin_object();
    if (!building.parts.empty()) {
      json.key("children").begin_array();
      for (std::size_t p = 0; p < building.parts.size(); ++p) json.integer(node + p);
      json.end_array();
    }
    if (!building.attributes.empty()) json.key("extras").attributes(building.attributes);
    json.key("name");
    json.string(building.id.empty() ? "building" + std::to_string(b) : building.id);
    json.end_object();
    node += building.parts.size() + 1;
  }
  for (std::size_t i = 0; i < scene_.lights.size(); ++i) write_light_node(json, i);
  json.end_array();
}

void Builder::write_materials(JsonStream& json) const {
  json.key("materials").begin_array();
  for (std::size_t m = 0; m < materials_.materials().size(); ++m) {
    const shape::Material& material = materials_.materials()[m];
    const auto& c = material.rgba;
    json.begin_object();
    if (c[3] < 1.0F) json.key("alphaMode").string("BLEND");
    json.key("name").string(material.name);
    json.key("pbrMetallicRoughness").begin_object().key("baseColorFactor").begin_array();
    for (float channel_value : c) json.number(channel(channel_value));
    json.end_array();
    if (material_texture_[m] >= 0) {
      json.key("baseColorTexture").begin_object().key("index").integer(material_texture_[m]);
      json.end_object();
    }
    json.key("metallicFactor").number(0.0).key("roughnessFactor").number(0.9);
    json.end_object().end_object();
  }
  json.end_array();
}

std::string light_name(const shape::Light& light, std::size_t index) {
  return light.name.empty() ? "light" + std::to_string(index) : light.name;
}

// The rotation taking glTF's light direction, -Z, to `direction` (local Z-up), as a unit
// quaternion (x, y, z, w): half-way vector construction, 180 degrees about +Y when opposite.
std::array<double, 4> spot_rotation(kernel::Vec3 direction) {
  kernel::Vec3 d = kernel::normalized(kernel::Vec3{direction.x, direction.z, -direction.y});
  if (!std::isfinite(d.x + d.y + d.z) || kernel::length(d) == 0) d = {0, -1, 0};
  // (0, 0, -1) x d and 1 + (0, 0, -1) . d
  const std::array<double, 4> q = {d.y, -d.x, 0, 1 - d.z};
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[3] * q[3]);
  if (n < 1e-12) return {0, 1, 0, 0};
  return {q[0] / n, q[1] / n, 0, q[3] / n};
}

// KHR_lights_punctual: intensity in candela, range only when limited (the extension forbids 0),
// spot cones at the extension's defaults written out.
void Builder::write_lights(JsonStream& json) const {
  json.key("extensions").begin_object().key(kLightsExtension).begin_object();
  json.key("lights").begin_array();
  for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
    const shape::Light& light = scene_.lights[i];
    json.begin_object().key("color").begin_array();
    for (float c : light.color) json.number(channel(c));
    json.end_array().key("intensity").number(light.intensity);
    json.key("name").string(light_name(light, i));
    if (light.range > 0) json.key("range").number(light.range);
    const bool spot = light.kind == "spot";
    if (spot) {
      json.key("spot").begin_object().key("innerConeAngle").number(0.0);
      json.key("outerConeAngle").number(std::numbers::pi / 4).end_object();
    }
    json.key("type").string(spot ? "spot" : "point").end_object();
  }
  json.end_array().end_object().end_object();
  json.key("extensionsUsed").begin_array().string(kLightsExtension).end_array();
}

// A light's node: placed like the vertices, (x, y, z) -> (x, z, -y), but in doubles (a node's
// translation is not float32-bound).
void Builder::write_light_node(JsonStream& json, std::size_t index) const {
  const shape::Light& light = scene_.lights[index];
  json.begin_object().key("extensions").begin_object().key(kLightsExtension).begin_object();
  json.key("light").integer(index).end_object().end_object();
  json.key("name").string(light_name(light, index));
  if (light.kind == "spot") {
    json.key("rotation").begin_array();
    for (double c : spot_rotation(light.direction)) json.number(c + 0.0);
    json.end_array();
  }
  const kernel::Vec3 p = light.position;
  json.key("translation").begin_array();
  json.number(p.x + 0.0).number(p.z + 0.0).number(-p.y + 0.0).end_array().end_object();
}

// One image per texture, stored in the buffer (a file's bytes with their MIME type, a procedural
// image as PNG).
void Builder::write_images(JsonStream& json) const {
  const std::size_t first_view = 2 + (uvs_.empty() ? 0 : 1);
  json.key("images").begin_array();
  for (std::size_t i = 0; i < images_.size(); ++i) {
    json.begin_object().key("bufferView").integer(first_view + i);
    json.key("mimeType").string(image_types_[i]).key("name").string(image_names_[i]).end_object();
  }
  json.end_array();
}

void Builder::write_buffers(JsonStream& json, std::string_view buffer_uri) const {
  const std::size_t vertex_bytes = 4 * vertices_.size();
  json.key("bufferViews").begin_array();
  json.begin_object().key("buffer").integer(0).key("byteLength").integer(vertex_bytes);
  json.key("byteStride").integer(12).key("target").integer(kArrayBuffer).end_object();
  json.begin_object().key("buffer").integer(0).key("byteLength").integer(4 * indices_.size());
  json.key("byteOffset").integer(vertex_bytes);
  json.key("target").integer(kElementArrayBuffer).end_object();
  if (!uvs_.empty()) {
    json.begin_object().key("buffer").integer(0).key("byteLength").integer(4 * uvs_.size());
    json.key("byteOffset").integer(vertex_bytes + 4 * indices_.size());
    json.key("byteStride").integer(8).key("target").integer(kArrayBuffer).end_object();
  }
  for (std::size_t i = 0; i < images_.size(); ++i) {
    json.begin_object().key("buffer").integer(0).key("byteLength").integer(images_[i].size());
    json.key("byteOffset").integer(image_offset(i)).end_object();
  }
  json.end_array();
  json.key("buffers").begin_array().begin_object().key("byteLength").integer(binary_size());
  if (!buffer_uri.empty()) json.key("uri").string(buffer_uri);
  json.end_object().end_array();
}

void Builder::write_scene(JsonStream& json) const {
  json.key("scene").integer(0).key("scenes").begin_array().begin_object();
  json.key("extras").begin_object();
  if (!scene_.crs.empty()) json.key("crs").string(scene_.crs);
  json.key("origin").begin_array();
  json.number(scene_.origin.x).number(scene_.origin.y).number(scene_.origin.z).end_array();
  json.key("units").string("m");
  json.key("world_from_gltf").string("(x, y, z) = (X + origin[0], -Z + origin[1], Y + origin[2])");
  json.end_object().key("name").string("Insula");
  if (!scene_.buildings.empty() || !scene_.lights.empty()) {
    json.key("nodes").begin_array();
    std::size_t node = 0;
    for (const shape::Building& building : scene_.buildings) {
      node += building.parts.size();
      json.integer(node++);
    }
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) json.integer(node++);
    json.end_array();
  }
  json.end_object().end_array();
}

// Root members in sorted order; the buffer and everything describing it only when some face
// produced triangles.
void Builder::write_json(JsonStream& json, std::string_view buffer_uri) const {
  const bool has_meshes = !primitives_.empty();
  json.begin_object();
  if (has_meshes) write_accessors(json);
  json.key("asset").begin_object().key("generator").string("Insula");
  json.key("version").string("2.0").end_object();
  const bool has_images = !images_.empty();
  if (has_meshes) write_buffers(json, buffer_uri);
  if (!scene_.lights.empty()) write_lights(json);
  if (has_images) write_images(json);
  if (has_meshes) {
    write_materials(json);
    write_meshes(json);
  }
  if (!scene_.buildings.empty() || !scene_.lights.empty()) write_nodes(json);
  if (has_images) {
    // A procedural image shows once per face (clamped); a file's image repeats over a uv map.
    // Only the samplers some texture uses are written.
    json.key("samplers").begin_array();
    for (std::uint32_t wrap : sampler_wraps()) {
      json.begin_object().key("magFilter").integer(kLinear);
      json.key("minFilter").integer(kLinearMipmapLinear).key("wrapS").integer(wrap);
      json.key("wrapT").integer(wrap).end_object();
    }
    json.end_array();
  }
  write_scene(json);
  if (has_images) {
    json.key("textures").begin_array();
    for (std::size_t i = 0; i < images_.size(); ++i) {
      const std::vector<std::uint32_t> wraps = sampler_wraps();
      const std::uint32_t wrap = image_repeats_[i] ? kRepeat : kClampToEdge;
      const auto sampler = std::find(wraps.begin(), wraps.end(), wrap) - wraps.begin();
      json.begin_object().key("sampler").integer(sampler);
      json.key("source").integer(i).end_object();
    }
    json.end_array();
  }
  json.end_object();
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

// A chunk's length (padded to 4 bytes) and type; the caller appends the data and the padding.
void append_chunk_header(std::string& out, std::size_t size, std::uint32_t type) {
  append_u32(out, static_cast<std::uint32_t>(padded(size)));
  append_u32(out, type);
}

bool has_gltf_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".gltf";
}

}  // namespace

std::string glb_bytes(const shape::Scene& scene) {
  const Builder builder(scene);
  std::string text;
  JsonStream json(text);
  builder.write_json(json, {});
  const std::size_t binary = builder.binary_size();
  const std::size_t total = 12 + 8 + padded(text.size()) + (binary == 0 ? 0 : 8 + padded(binary));
  std::string out;
  out.reserve(total);
  append_u32(out, kGlbMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_chunk_header(out, text.size(), kChunkJson);
  out += text;
  out.append(padded(text.size()) - text.size(), ' ');
  if (binary > 0) {
    append_chunk_header(out, binary, kChunkBin);
    builder.append_binary(out);
    out.append(padded(binary) - binary, '\0');
  }
  return out;
}

std::string gltf_text(const shape::Scene& scene) {
  const Builder builder(scene);
  std::string uri;
  if (builder.binary_size() > 0) {
    std::string binary;
    binary.reserve(builder.binary_size());
    builder.append_binary(binary);
    uri = "data:application/octet-stream;base64," + base64(binary);
  }
  std::string text;
  JsonStream json(text, 1);
  builder.write_json(json, uri);
  text += '\n';
  return text;
}

std::string write_gltf(const shape::Scene& scene, const std::filesystem::path& path) {
  return write_file_atomically(path,
                               has_gltf_extension(path) ? gltf_text(scene) : glb_bytes(scene));
}

}  // namespace insula::io
