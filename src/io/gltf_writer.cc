#include "io/gltf_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "io/gltf_buffers.h"
#include "io/gltf_mesh.h"
#include "io/gltf_metadata.h"
#include "io/gltf_placement.h"
#include "io/json_stream.h"
#include "io/png_renderer.h"
#include "io/triangulated.h"
#include "kernel/transform.h"

namespace insula::io {
namespace {

using gltf::Accessor;
using gltf::Affine;
using gltf::Buffers;
using gltf::Component;
using gltf::ViewKind;

constexpr std::uint32_t kLinear = 9729;
constexpr std::uint32_t kLinearMipmapLinear = 9987;
constexpr std::uint32_t kClampToEdge = 33071;
constexpr std::uint32_t kRepeat = 10497;
constexpr std::string_view kLightsExtension = "KHR_lights_punctual";
constexpr std::string_view kQuantizationExtension = "KHR_mesh_quantization";
constexpr std::string_view kInstancingExtension = "EXT_mesh_gpu_instancing";
constexpr std::string_view kMeshoptExtension = "EXT_meshopt_compression";
constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::size_t padded(std::size_t size) {
  return (size + 3) / 4 * 4;
}

// Colour channels rounded to 6 decimals so the JSON shows 0.86, not 0.8600000143051147.
double channel(float value) {
  return std::round(static_cast<double>(value) * 1e6) / 1e6;
}

std::string part_name(const shape::Part& part, std::size_t index) {
  return part.name.empty() ? "part" + std::to_string(index) : part.name;
}

std::string building_name(const shape::Building& building, std::size_t index) {
  return building.id.empty() ? "building" + std::to_string(index) : building.id;
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

struct MeshEntry {
  std::string name;
  gltf::MeshRecord record;
};

// The instances of one mesh in one building, placed by EXT_mesh_gpu_instancing.
struct InstanceGroup {
  std::uint32_t translation = 0;
  std::uint32_t rotation = 0;
  std::uint32_t scale = 0;
  std::optional<std::uint32_t> feature;
  std::uint32_t feature_count = 0;
};

// A node under a building's node: a part (element layout, or an instance placed by its node) or
// a group of GPU instances.
struct ChildNode {
  std::string name;
  const shape::Part* part = nullptr;  // its kind and attributes go to `extras`
  std::int32_t mesh = -1;
  std::optional<Affine> placement;
  std::optional<InstanceGroup> instances;
};

// A part that instances a shared mesh, and its row in the parts' table.
struct PlacedInstance {
  std::size_t part = 0;
  std::int32_t mesh = -1;
  std::uint32_t row = 0;
};

struct BuildingNode {
  std::int32_t mesh = -1;
  std::optional<Affine> placement;  // the dequantization of its mesh
  std::vector<ChildNode> children;
};

// Assembles the meshes building by building into the buffer views (io/gltf_mesh.h), then writes
// the JSON from compact records. Object keys are written in sorted order, so the text is the one
// nlohmann::json would print.
class Builder {
 public:
  Builder(const shape::Scene& scene, const GltfOptions& options);

  // The glTF JSON; `buffer_uri` (when not empty) becomes the buffer's "uri".
  void write_json(JsonStream& json, std::string_view buffer_uri) const;
  void append_binary(std::string& out) const { buffers_.append_binary(out); }
  void binary_pieces(std::vector<std::string_view>& pieces) const {
    buffers_.binary_pieces(pieces);
  }
  std::size_t binary_size() const { return buffers_.binary_size(); }
  // Room for the JSON text, so it does not move as it grows: about 400 bytes per primitive
  // (its accessors and the EXT_mesh_features block) and per node (name and extras).
  std::size_t json_size_estimate() const {
    std::size_t items = scene_.lights.size() + materials_.materials().size();
    for (const MeshEntry& mesh : meshes_) items += mesh.record.primitives.size();
    for (const BuildingNode& building : buildings_) items += 1 + building.children.size();
    return 400 * items + 4096;
  }

 private:
  void reserve_views();
  void add_images();
  BuildingNode by_building(const shape::Building& building, std::size_t index);
  BuildingNode by_element(const shape::Building& building);
  void reserve_assembler(const shape::Building& building);
  // The mesh a part instances (added the first time), or -1 when none of its faces has area.
  std::int32_t shared_mesh(const shape::Part& part, std::size_t index);
  // Writes what `assembler` holds as a new mesh; -1 when it holds no triangle.
  std::int32_t add_mesh(gltf::MeshAssembler& assembler, std::string name);
  gltf::MeshOptions mesh_options(bool with_features, bool quantize) const;
  InstanceGroup add_instance_group(const std::vector<gltf::Trs>& placed,
                                   const std::vector<float>& features);
  void add_instance_groups(const shape::Building& building,
                           const std::vector<PlacedInstance>& instances, const Affine& inside,
                           BuildingNode& node);

  void write_extensions(JsonStream& json) const;
  void write_meshes(JsonStream& json) const;
  void write_nodes(JsonStream& json) const;
  void write_child(JsonStream& json, const ChildNode& child) const;
  void write_materials(JsonStream& json) const;
  // The KHR_lights_punctual member of the root's extensions.
  void write_lights(JsonStream& json) const;
  void write_light_node(JsonStream& json, std::size_t light) const;
  void write_images(JsonStream& json) const;
  void write_textures(JsonStream& json) const;
  void write_scene(JsonStream& json) const;
  // The wrap modes of the samplers, in sampler order: clamped first when used, then repeat.
  std::vector<std::uint32_t> sampler_wraps() const;
  std::vector<std::string_view> extensions_used() const;
  std::vector<std::string_view> extensions_required() const;

  const shape::Scene& scene_;
  GltfOptions options_;
  MaterialTable materials_;
  Buffers buffers_;
  gltf::MeshViews views_;
  // With a property table (building nodes): each part that shows a triangle gets the next row, in
  // scene order; has_row_ says which did (a part whose faces all collapse where they are written
  // has no row, as it has no vertex to point at one).
  bool with_table_ = false;
  std::uint32_t next_row_ = 0;
  std::vector<bool> has_row_;
  std::optional<gltf::PartTable> table_;
  gltf::MeshOptions mesh_options_;
  // Textures: one per distinct image of a material in the table, PNG-encoded (or a file's bytes),
  // each in a view of its own.
  std::vector<std::int32_t> material_texture_;  // by table material; -1: untextured
  std::vector<std::string> images_;
  std::vector<std::string> image_names_;
  std::vector<std::string> image_types_;  // MIME types
  std::vector<bool> image_repeats_;       // a file's image repeats over a uv map
  std::vector<std::uint32_t> image_views_;
  std::optional<gltf::MeshAssembler> assembler_;  // a building's (or a part's) own faces
  // Shared meshes are assembled apart: the first instance may come amid a building's faces.
  std::optional<gltf::MeshAssembler> shared_assembler_;
  std::vector<MeshEntry> meshes_;
  std::map<const kernel::Mesh*, std::int32_t> shared_;  // instanced meshes already added
  std::vector<BuildingNode> buildings_;
  std::optional<std::uint32_t> instance_views_[4];  // translation, rotation, scale, feature
  bool quantized_ = false;                          // some attribute uses KHR_mesh_quantization
  bool gpu_instances_ = false;
};

Builder::Builder(const shape::Scene& scene, const GltfOptions& options)
    : scene_(scene),
      options_(options),
      materials_(scene, options.by_class),
      views_(gltf::MeshViews::create(buffers_)) {
  reserve_views();
  add_images();
  std::vector<bool> textured;
  for (std::int32_t texture : material_texture_) textured.push_back(texture >= 0);
  assembler_.emplace(materials_, textured);
  shared_assembler_.emplace(materials_, std::move(textured));
  mesh_options_.quantize = options_.quantize;
  mesh_options_.first_use_order = options_.compress;
  if (options_.nodes == GltfOptions::Nodes::kBuilding) {
    std::size_t parts = 0;
    for (const shape::Building& building : scene_.buildings) parts += building.parts.size();
    with_table_ = parts > 0;
    // Decided before any row is given: at most one a part.
    if (parts > 65535) mesh_options_.feature_component = Component::kFloat;
  }
  // A mesh per building, usually: room for its node, its record and about six accessors.
  buildings_.reserve(scene_.buildings.size());
  meshes_.reserve(scene_.buildings.size());
  buffers_.reserve_accessors(6 * scene_.buildings.size());
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    const shape::Building& building = scene_.buildings[b];
    buildings_.push_back(options_.nodes == GltfOptions::Nodes::kBuilding ? by_building(building, b)
                                                                         : by_element(building));
  }
  if (with_table_ && next_row_ > 0) table_.emplace(scene_, has_row_);
  if (meshes_.empty()) {
    // No primitive: no buffer, so no images and no table either.
    images_.clear();
    table_.reset();
  }
  for (const std::string& image : images_) {
    image_views_.push_back(buffers_.add_view(ViewKind::kBytes, 0));
    buffers_.data(image_views_.back()) += image;
  }
  if (table_) table_->write_data(buffers_);
  buffers_.finish(options_.compress);
}

// Room for every corner and triangle (an upper bound: merging only removes), so the views do
// not move as they grow.
void Builder::reserve_views() {
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
  buffers_.data(views_.quantized_positions).reserve(8 * corners);
  buffers_.data(views_.quantized_normals).reserve(4 * corners);
  if (options_.nodes == GltfOptions::Nodes::kBuilding) {
    buffers_.data(views_.features).reserve(4 * corners);
  }
  buffers_.data(views_.short_indices).reserve(6 * triangles);
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

std::int32_t Builder::add_mesh(gltf::MeshAssembler& assembler, std::string name) {
  if (assembler.empty()) {
    assembler.clear();
    return -1;
  }
  gltf::MeshRecord record = assembler.emit(buffers_, views_);
  quantized_ = quantized_ || assembler.options().quantize;  // byte normals at least
  meshes_.push_back({std::move(name), std::move(record)});
  return static_cast<std::int32_t>(meshes_.size() - 1);
}

// The options of a mesh with (or without) feature ids, quantized (or not).
gltf::MeshOptions Builder::mesh_options(bool with_features, bool quantize) const {
  gltf::MeshOptions options = mesh_options_;
  options.with_features = with_features;
  options.quantize = quantize;
  return options;
}

// Shared meshes keep float positions: their instances' placements stay plain node transforms.
std::int32_t Builder::shared_mesh(const shape::Part& part, std::size_t index) {
  if (auto it = shared_.find(part.instance_of.get()); it != shared_.end()) return it->second;
  shared_assembler_->start(mesh_options(false, false));
  shared_assembler_->add(*part.instance_of, part, 0, true);
  const std::int32_t mesh = add_mesh(*shared_assembler_, part_name(part, index));
  shared_[part.instance_of.get()] = mesh;
  return mesh;
}

Affine node_placement(const gltf::MeshRecord& record) {
  return gltf::dequantization(record.offset, record.scale);
}

// One mesh for all the building's own faces, each vertex carrying its part's row in the table;
// instances (without a uv map of their own) point at their shared mesh.
BuildingNode Builder::by_building(const shape::Building& building, std::size_t index) {
  BuildingNode node;
  std::vector<PlacedInstance> instances;
  assembler_->start(mesh_options(with_table_, options_.quantize));
  reserve_assembler(building);
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    bool shown = false;
    if (part.instance_of && !part.uv) {
      const std::int32_t mesh = shared_mesh(part, p);
      shown = mesh >= 0;
      if (shown) instances.push_back({p, mesh, next_row_});
    } else if (part.instance_of) {
      shown = assembler_->add(kernel::transformed(*part.instance_of, part.instance_transform), part,
                              next_row_, false);
    } else {
      shown = assembler_->add(part.mesh, part, next_row_, false);
    }
    if (with_table_) has_row_.push_back(shown);
    if (shown) ++next_row_;
  }
  node.mesh = add_mesh(*assembler_, building_name(building, index));
  Affine inside;  // the frame the building node's children live in
  if (node.mesh >= 0 && meshes_[node.mesh].record.quantized) {
    node.placement = node_placement(meshes_[node.mesh].record);
    inside = *node.placement;
  }
  add_instance_groups(building, instances, inside, node);
  return node;
}

// Room in the assembler for the building's own faces (a tile's building has thousands of parts).
void Builder::reserve_assembler(const shape::Building& building) {
  std::size_t vertices = 0;
  std::size_t corners = 0;
  std::size_t faces = 0;
  for (const shape::Part& part : building.parts) {
    if (part.instance_of && !part.uv) continue;  // in a shared mesh
    const kernel::Mesh& mesh = part.instance_of ? *part.instance_of : part.mesh;
    vertices += mesh.vertex_count();
    faces += mesh.face_count();
    if (mesh.face_count() > 0) {
      const auto last = mesh.face(mesh.face_count() - 1);
      corners += static_cast<std::size_t>(last.data() + last.size() - mesh.face(0).data());
    }
  }
  assembler_->reserve(vertices, corners, faces);
}

// Each instance as a node of its own, or with GPU instancing one node per mesh placing them all
// (an instance whose placement has a shear keeps a node of its own: TRS cannot hold it).
void Builder::add_instance_groups(const shape::Building& building,
                                  const std::vector<PlacedInstance>& instances,
                                  const Affine& inside, BuildingNode& node) {
  const auto placement = [&](const shape::Part& part) {
    return gltf::relative_to(gltf::y_up(part.instance_transform), inside.translation,
                             inside.columns[0][0]);
  };
  std::vector<std::int32_t> meshes;
  for (const PlacedInstance& instance : instances) {
    if (std::find(meshes.begin(), meshes.end(), instance.mesh) == meshes.end()) {
      meshes.push_back(instance.mesh);
    }
  }
  if (options_.instancing == GltfOptions::Instancing::kNodes) meshes.clear();
  for (std::int32_t mesh : meshes) {
    std::vector<gltf::Trs> placed;
    std::vector<float> features;
    for (const PlacedInstance& instance : instances) {
      if (instance.mesh != mesh) continue;
      if (auto trs = gltf::decompose(placement(building.parts[instance.part]))) {
        placed.push_back(*trs);
        features.push_back(static_cast<float>(instance.row));
      }
    }
    if (placed.empty()) continue;
    const InstanceGroup group = add_instance_group(placed, features);
    node.children.push_back({meshes_[mesh].name, nullptr, mesh, std::nullopt, group});
    gpu_instances_ = true;
  }
  for (const PlacedInstance& instance : instances) {
    const shape::Part& part = building.parts[instance.part];
    const bool grouped = std::find(meshes.begin(), meshes.end(), instance.mesh) != meshes.end() &&
                         gltf::decompose(placement(part)).has_value();
    if (!grouped) {
      node.children.push_back(
          {part_name(part, instance.part), &part, instance.mesh, placement(part), {}});
    }
  }
}

// The EXT_mesh_gpu_instancing accessors of one group: TRANSLATION, ROTATION, SCALE and, with
// the parts' table, each instance's row as _FEATURE_ID_0; one view per attribute for the asset.
InstanceGroup Builder::add_instance_group(const std::vector<gltf::Trs>& placed,
                                          const std::vector<float>& features) {
  constexpr std::array<std::uint32_t, 4> kStrides{12, 16, 12, 4};
  for (std::size_t k = 0; k < 4; ++k) {
    if (!instance_views_[k]) {
      instance_views_[k] = buffers_.add_view(ViewKind::kInstances, kStrides[k]);
    }
  }
  const auto add = [&](std::size_t k, std::string_view type, const std::vector<float>& values) {
    gltf::Bytes& data = buffers_.data(*instance_views_[k]);
    const std::size_t offset = data.size();
    for (float v : values) gltf::append_value(data, v);
    return buffers_.add_accessor(Accessor{*instance_views_[k], offset, Component::kFloat,
                                          placed.size(), type, false, std::nullopt, std::nullopt});
  };
  std::vector<float> t;
  std::vector<float> r;
  std::vector<float> s;
  for (const gltf::Trs& trs : placed) {
    for (double c : trs.translation) t.push_back(static_cast<float>(c));
    for (double c : trs.rotation) r.push_back(static_cast<float>(c));
    for (double c : trs.scale) s.push_back(static_cast<float>(c));
  }
  InstanceGroup group;
  group.translation = add(0, "VEC3", t);
  group.rotation = add(1, "VEC4", r);
  group.scale = add(2, "VEC3", s);
  if (with_table_) {
    group.feature = add(3, "SCALAR", features);
    group.feature_count = static_cast<std::uint32_t>(features.size());
  }
  return group;
}

// One node and mesh per part under the building's node; a part none of whose faces shows a
// triangle has none.
BuildingNode Builder::by_element(const shape::Building& building) {
  BuildingNode node;
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    ChildNode child{part_name(part, p), &part, -1, std::nullopt, std::nullopt};
    if (part.instance_of && !part.uv) {
      child.mesh = shared_mesh(part, p);
      child.placement = gltf::y_up(part.instance_transform);
    } else {
      const bool instance = part.instance_of != nullptr;
      assembler_->start(mesh_options(false, options_.quantize));
      assembler_->add(instance ? *part.instance_of : part.mesh, part, 0, instance);
      child.mesh = add_mesh(*assembler_, child.name);
      std::optional<Affine> dequantize;
      if (child.mesh >= 0 && meshes_[child.mesh].record.quantized) {
        dequantize = node_placement(meshes_[child.mesh].record);
      }
      if (instance) {
        child.placement = gltf::y_up(part.instance_transform);
        if (dequantize) child.placement = gltf::compose(*child.placement, *dequantize);
      } else {
        child.placement = dequantize;
      }
    }
    if (child.mesh >= 0) node.children.push_back(std::move(child));
  }
  return node;
}

void write_numbers(JsonStream& json, std::string_view key, std::span<const double> values) {
  json.key(key).begin_array();
  for (double v : values) json.number(v + 0.0);
  json.end_array();
}

// `extension`: EXT_mesh_features on a primitive, EXT_instance_features on an instancing node.
void write_feature_ids(JsonStream& json, std::string_view extension, std::uint32_t feature_count) {
  json.key(extension).begin_object().key("featureIds").begin_array();
  json.begin_object().key("attribute").integer(0).key("featureCount").integer(feature_count);
  json.key("propertyTable").integer(0).end_object().end_array().end_object();
}

void Builder::write_meshes(JsonStream& json) const {
  json.key("meshes").begin_array();
  for (const MeshEntry& mesh : meshes_) {
    const gltf::MeshRecord& record = mesh.record;
    json.begin_object().key("name").string(mesh.name);
    json.key("primitives").begin_array();
    for (const gltf::PrimitiveRecord& primitive : record.primitives) {
      json.begin_object().key("attributes").begin_object();
      json.key("NORMAL").integer(record.normal).key("POSITION").integer(record.position);
      if (record.uv) json.key("TEXCOORD_0").integer(*record.uv);
      if (record.feature) json.key("_FEATURE_ID_0").integer(*record.feature);
      json.end_object();
      if (record.feature) {
        json.key("extensions").begin_object();
        write_feature_ids(json, gltf::kFeaturesExtension, primitive.feature_count);
        json.end_object();
      }
      json.key("indices").integer(primitive.indices);
      json.key("material").integer(primitive.material).end_object();
    }
    json.end_array().end_object();
  }
  json.end_array();
}

void Builder::write_child(JsonStream& json, const ChildNode& child) const {
  json.begin_object();
  if (child.instances) {
    const InstanceGroup& group = *child.instances;
    json.key("extensions").begin_object();
    if (group.feature) {
      write_feature_ids(json, gltf::kInstanceFeaturesExtension, group.feature_count);
    }
    json.key(kInstancingExtension).begin_object().key("attributes").begin_object();
    json.key("ROTATION").integer(group.rotation).key("SCALE").integer(group.scale);
    json.key("TRANSLATION").integer(group.translation);
    if (group.feature) json.key("_FEATURE_ID_0").integer(*group.feature);
    json.end_object().end_object().end_object();
  }
  if (child.part != nullptr) {
    json.key("extras").attributes(child.part->attributes, "kind",
                                  gltf::kind_name(child.part->kind));
  }
  if (child.placement) write_numbers(json, "matrix", gltf::matrix(*child.placement));
  if (child.mesh >= 0) json.key("mesh").integer(child.mesh);
  json.key("name").string(child.name).end_object();
}

// Per building: its child nodes, then the building's node with them as children.
void Builder::write_nodes(JsonStream& json) const {
  json.key("nodes").begin_array();
  std::size_t node = 0;
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    const shape::Building& building = scene_.buildings[b];
    const BuildingNode& record = buildings_[b];
    for (const ChildNode& child : record.children) write_child(json, child);
    json.begin_object();
    if (!record.children.empty()) {
      json.key("children").begin_array();
      for (std::size_t c = 0; c < record.children.size(); ++c) json.integer(node + c);
      json.end_array();
    }
    if (!building.attributes.empty()) json.key("extras").attributes(building.attributes);
    if (record.mesh >= 0) json.key("mesh").integer(record.mesh);
    json.key("name").string(building_name(building, b));
    if (record.placement) {
      const double s = record.placement->columns[0][0];
      write_numbers(json, "scale", std::array<double, 3>{s, s, s});
      write_numbers(json, "translation", record.placement->translation);
    }
    json.end_object();
    node += record.children.size() + 1;
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
  json.key(kLightsExtension).begin_object().key("lights").begin_array();
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
  json.end_array().end_object();
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
  json.key("images").begin_array();
  for (std::size_t i = 0; i < images_.size(); ++i) {
    json.begin_object().key("bufferView").integer(buffers_.view_index(image_views_[i]));
    json.key("mimeType").string(image_types_[i]).key("name").string(image_names_[i]).end_object();
  }
  json.end_array();
}

std::vector<std::uint32_t> Builder::sampler_wraps() const {
  std::vector<std::uint32_t> wraps;
  if (std::count(image_repeats_.begin(), image_repeats_.end(), false) > 0) {
    wraps.push_back(kClampToEdge);
  }
  if (std::count(image_repeats_.begin(), image_repeats_.end(), true) > 0) wraps.push_back(kRepeat);
  return wraps;
}

// A procedural image shows once per face (clamped); a file's image repeats over a uv map. Only
// the samplers some texture uses are written.
void Builder::write_textures(JsonStream& json) const {
  const std::vector<std::uint32_t> wraps = sampler_wraps();
  json.key("textures").begin_array();
  for (std::size_t i = 0; i < images_.size(); ++i) {
    const std::uint32_t wrap = image_repeats_[i] ? kRepeat : kClampToEdge;
    const auto sampler = std::find(wraps.begin(), wraps.end(), wrap) - wraps.begin();
    json.begin_object().key("sampler").integer(sampler);
    json.key("source").integer(i).end_object();
  }
  json.end_array();
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
    for (const BuildingNode& building : buildings_) {
      node += building.children.size();
      json.integer(node++);
    }
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) json.integer(node++);
    json.end_array();
  }
  json.end_object().end_array();
}

std::vector<std::string_view> Builder::extensions_required() const {
  std::vector<std::string_view> required;
  // Without these a reader would place, decode or find nothing right.
  if (gpu_instances_) required.push_back(kInstancingExtension);
  if (buffers_.compressed()) required.push_back(kMeshoptExtension);
  if (quantized_) required.push_back(kQuantizationExtension);
  return required;
}

std::vector<std::string_view> Builder::extensions_used() const {
  std::vector<std::string_view> used = extensions_required();
  if (table_) {
    used.push_back(gltf::kFeaturesExtension);
    used.push_back(gltf::kMetadataExtension);
    if (gpu_instances_) used.push_back(gltf::kInstanceFeaturesExtension);
  }
  if (!scene_.lights.empty()) used.push_back(kLightsExtension);
  std::sort(used.begin(), used.end());
  return used;
}

// The root's "extensions": the parts' property table and the lights.
void Builder::write_extensions(JsonStream& json) const {
  if (!table_ && scene_.lights.empty()) return;
  json.key("extensions").begin_object();
  if (table_) table_->write_json(json, buffers_);
  if (!scene_.lights.empty()) write_lights(json);
  json.end_object();
}

// Root members in sorted order; the buffer and everything describing it only when some face
// produced triangles.
void Builder::write_json(JsonStream& json, std::string_view buffer_uri) const {
  const bool has_meshes = !meshes_.empty();
  json.begin_object();
  buffers_.write_accessors(json);
  json.key("asset").begin_object().key("generator").string("Insula");
  json.key("version").string("2.0").end_object();
  if (!buffers_.empty()) buffers_.write_views(json, buffer_uri);
  write_extensions(json);
  const auto write_list = [&json](std::string_view key,
                                  const std::vector<std::string_view>& names) {
    if (names.empty()) return;
    json.key(key).begin_array();
    for (std::string_view name : names) json.string(name);
    json.end_array();
  };
  std::vector<std::string_view> required = extensions_required();
  std::sort(required.begin(), required.end());
  write_list("extensionsRequired", required);
  write_list("extensionsUsed", extensions_used());
  const bool has_images = !images_.empty();
  if (has_images) write_images(json);
  if (has_meshes) {
    write_materials(json);
    write_meshes(json);
  }
  if (!scene_.buildings.empty() || !scene_.lights.empty()) write_nodes(json);
  if (has_images) {
    json.key("samplers").begin_array();
    for (std::uint32_t wrap : sampler_wraps()) {
      json.begin_object().key("magFilter").integer(kLinear);
      json.key("minFilter").integer(kLinearMipmapLinear).key("wrapS").integer(wrap);
      json.key("wrapT").integer(wrap).end_object();
    }
    json.end_array();
  }
  write_scene(json);
  if (has_images) write_textures(json);
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
  gltf::append_value(out, static_cast<std::uint32_t>(padded(size)));
  gltf::append_value(out, type);
}

bool has_gltf_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".gltf";
}

// The scene as one building whose parts are its buildings' parts as features (Nodes::kScene).
shape::Scene merged(const shape::Scene& scene) {
  shape::Scene out;
  out.origin = scene.origin;
  out.crs = scene.crs;
  out.materials = scene.materials;
  out.lights = scene.lights;
  shape::Building& all = out.buildings.emplace_back();
  all.id = "scene";
  for (const shape::Building& building : scene.buildings) {
    const auto attributes = gltf::building_feature_attributes(building);
    for (const shape::Part& part : building.parts) {
      gltf::make_feature(all.parts.emplace_back(part), attributes);
    }
  }
  return out;
}

// The builder of `scene` as `options` lay it out.
struct LaidOut {
  LaidOut(const shape::Scene& scene, const GltfOptions& options)
      : merged_scene(options.nodes == GltfOptions::Nodes::kScene ? merged(scene) : shape::Scene()),
        builder(options.nodes == GltfOptions::Nodes::kScene ? merged_scene : scene,
                building_layout(options)) {}
  static GltfOptions building_layout(GltfOptions options) {
    if (options.nodes == GltfOptions::Nodes::kScene) options.nodes = GltfOptions::Nodes::kBuilding;
    return options;
  }
  shape::Scene merged_scene;
  Builder builder;
};

// The GLB of `builder` (12-byte header, JSON chunk, BIN chunk when non-empty): everything up to
// the BIN chunk's data is appended to `head` (empty, with room reserved by the caller); the
// chunk's data follow as `binary`'s pieces, which point into the builder's views. The JSON is
// written in place after room for the two headers, which are filled in once its size is known
// (the JSON is most of the bytes of a GLB of buildings: copying it cost more than writing it).
void lay_out_glb(const Builder& builder, std::string& head, std::vector<std::string_view>& binary) {
  constexpr std::size_t kHeaders = 12 + 8;
  const std::size_t size = builder.binary_size();
  head.resize(kHeaders);
  JsonStream json(head);
  builder.write_json(json, {});
  const std::size_t text = head.size() - kHeaders;
  head.append(padded(text) - text, ' ');
  const std::size_t total = head.size() + (size == 0 ? 0 : 8 + padded(size));
  std::string headers;
  gltf::append_value(headers, kGlbMagic);
  gltf::append_value(headers, std::uint32_t{2});
  gltf::append_value(headers, static_cast<std::uint32_t>(total));
  append_chunk_header(headers, text, kChunkJson);
  head.replace(0, kHeaders, headers);
  if (size > 0) {
    append_chunk_header(head, size, kChunkBin);
    builder.binary_pieces(binary);
    static constexpr char kZeros[4] = {};
    if (padded(size) > size) binary.emplace_back(kZeros, padded(size) - size);
  }
}

// Room for the GLB's head: headers, JSON and the BIN chunk's header.
std::size_t head_estimate(const Builder& builder) {
  return 12 + 8 + builder.json_size_estimate() + 8;
}

}  // namespace

std::string glb_bytes(const shape::Scene& scene, const GltfOptions& options) {
  const LaidOut laid_out(scene, options);
  const Builder& builder = laid_out.builder;
  std::string out;
  out.reserve(head_estimate(builder) + padded(builder.binary_size()));
  std::vector<std::string_view> binary;
  lay_out_glb(builder, out, binary);
  for (const std::string_view piece : binary) out += piece;
  return out;
}

std::string gltf_text(const shape::Scene& scene, const GltfOptions& options) {
  const LaidOut laid_out(scene, options);
  const Builder& builder = laid_out.builder;
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

// A .glb is written from its pieces in turn, without joining them into one string first (a copy of
// every byte of a tile).
std::string write_gltf(const shape::Scene& scene, const std::filesystem::path& path,
                       const GltfOptions& options) {
  if (has_gltf_extension(path)) return write_file_atomically(path, gltf_text(scene, options));
  const LaidOut laid_out(scene, options);
  std::string head;
  head.reserve(head_estimate(laid_out.builder));
  std::vector<std::string_view> pieces(1);
  lay_out_glb(laid_out.builder, head, pieces);
  pieces.front() = head;
  return write_file_atomically(path, pieces);
}

}  // namespace insula::io
