// The export model every writer consumes: buildings made of named parts, each a mesh in local
// coordinates (meters, Z up) with tagged faces. `origin` is the offset that takes local coordinates
// back to the input's coordinate reference system (world = local + origin), so far-from-origin
// inputs such as UTM keep full precision in double arithmetic (design.md, "Coordinates and units").
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/transform.h"
#include "kernel/vec.h"
#include "shape/plan.h"
#include "shape/uv_map.h"
#include "shape/value.h"

namespace insula::shape {

// An RGBA image, 8 bits per channel, rows top to bottom (a procedural texture, seed 003 §5.1; or
// an image file a grammar's texture() names, decoded).
struct Image {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  // For an image read from a file: its bytes as found and their type ("image/png",
  // "image/jpeg"), which writers embed or copy as they are. Such an image repeats over the uv
  // map of the faces showing it; one without (a procedural image) shows once per face.
  std::string encoded{};
  std::string mime_type{};
};

struct Material {
  std::string name;
  std::array<float, 4> rgba{0.8F, 0.8F, 0.8F, 1.0F};  // linear RGB + alpha
  // A base colour texture (glTF writes it as an image; other writers keep the colour).
  std::shared_ptr<const Image> image{};
  // The image file a grammar names (CityEngine's material.colormap), as written; io's
  // load_textures finds it and sets `image`. Empty: none.
  std::string texture{};
};

// A punctual light (glTF KHR_lights_punctual), in local coordinates like the parts.
struct Light {
  std::string name;
  std::string kind = "point";  // point, spot
  kernel::Vec3 position;
  kernel::Vec3 direction{0, 0, -1};  // spot lights
  std::array<float, 3> color{1.0F, 1.0F, 1.0F};
  double intensity = 1;  // candela
  double range = 0;      // 0: unlimited
};

// A CityGML-like object type for a part.
// kFurniture: movable things placed in rooms (seed 001 §4.5; CityJSON BuildingFurniture).
enum class PartKind { kBuildingPart, kStorey, kRoom, kInstallation, kFurniture, kOther };
// The labels a front-end gives what it places (seed 001 §4.5): collect() makes such parts
// kFurniture (in rooms) or kInstallation (on facades: balconies).
inline constexpr std::string_view kFurnitureLabel = "furniture";
inline constexpr std::string_view kInstallationLabel = "installation";

struct Part {
  std::string name;
  PartKind kind = PartKind::kBuildingPart;
  AttributeMap attributes;
  kernel::Mesh mesh;
  // An instance of a shared mesh (seed 001 §4.5: repeated decorations are shared, not copied): when
  // set, the part's geometry is `instance_of` placed by `instance_transform` (mesh stays empty).
  // glTF writes one mesh and a node per instance; the other writers expand it.
  // (`{}` on members added later lets older aggregate initialisers omit them without warnings.)
  std::shared_ptr<const kernel::Mesh> instance_of{};
  kernel::Transform instance_transform{};
  // Texture coordinates (uv set 0, CityEngine's projectUV; shape/uv_map.h) of a point of the
  // mesh: writers evaluate it per vertex. Empty: none (writers may make their own).
  std::optional<UvMap> uv{};
  // Attributes the part takes from elsewhere where it has none of its own, shared rather than
  // copied: a 3D Tiles tile merges many buildings into one and points each part at its
  // building's attributes (io/tileset_writer.cc). Read by the glTF property table.
  std::shared_ptr<const AttributeMap> inherited{};
};

struct Building {
  std::string id;  // unique within the scene
  AttributeMap attributes;
  std::vector<Part> parts;
  std::vector<StoreyPlan> plans{};  // floor plans (traversable buildings); empty for masses
};

// Moves the building by `offset` (meters, the local frame): every part's mesh, or its placement
// when it is an instance (the shared mesh stays shared), its uv map (texture coordinates stay on
// the surface they were made for) and the floor plans. Attributes are left as they are. A front-end
// that builds at a frame of its own (a lot at its own origin) moves the result back with it.
void translate(Building& building, kernel::Vec3 offset);

struct Scene {
  kernel::Vec3 origin;              // world = local + origin
  std::string crs;                  // e.g. "EPSG:32633"; empty when unknown
  std::vector<Material> materials;  // indexed by kernel::MaterialId; index 0 = "default"
  std::vector<Building> buildings;
  std::vector<Light> lights{};

  Scene();
  // The material a face shows: its own, or the default colour of its semantic class.
  Material material_for(const kernel::FaceTag& tag) const;
};

// Default colours per semantic class (walls light plaster, roofs terracotta, ...).
Material default_material(kernel::SemanticClass semantic);

}  // namespace insula::shape
