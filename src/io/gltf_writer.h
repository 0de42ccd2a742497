// glTF 2.0 writer (docs/formats.md, "glTF"): binary .glb or .gltf JSON with an embedded buffer.
// By default one node per building (name = id, attributes in `extras`) holding one mesh with a
// primitive per material; every vertex carries its part's feature id (EXT_mesh_features) into a
// property table of the parts (EXT_structural_metadata, io/gltf_metadata.h). With
// GltfOptions::Nodes::kElement, the building node has one child node per part instead (name, kind
// and attributes in `extras`, a mesh each). Parts that instance a shared mesh (seed 001 §4.5) keep
// it shared: one mesh, a node per instance, or with Instancing::kGpu one node per building and mesh
// placing every instance (EXT_mesh_gpu_instancing). glTF is Y-up: a local Z-up point (x, y, z) is
// stored as (x, z, -y). Positions stay local (the scene origin that takes them back to the input
// CRS is kept as doubles in the scene's `extras`: "origin", "crs") and are quantized
// (KHR_mesh_quantization) to 1/1024 m where a mesh's extent allows (io/gltf_mesh.h); `compress`
// adds EXT_meshopt_compression (io/gltf_buffers.h). Faces are triangulated with
// kernel::triangulate (concave faces stay right) and shaded flat; vertices the written precision
// cannot tell apart are written as one, and faces contracted over them, so closed shells stay
// closed (io/float32_weld.h). Scene lights become KHR_lights_punctual lights with a node each;
// material images become embedded textures, their faces getting TEXCOORD_0. Output is
// deterministic.
#pragma once

#include <filesystem>
#include <string>

#include "shape/scene.h"

namespace insula::io {

struct GltfOptions {
  // kScene: one node and one mesh for the whole scene, every part a feature that carries its
  // building's id and attributes (the layout of a 3D Tiles tile; few draw calls for big scenes).
  enum class Nodes { kBuilding, kElement, kScene };
  enum class Instancing { kNodes, kGpu };
  Nodes nodes = Nodes::kBuilding;
  Instancing instancing = Instancing::kNodes;
  bool quantize = true;   // KHR_mesh_quantization where the error stays under 1 mm
  bool by_class = false;  // materials by semantic class (MaterialTable), not the faces' own
  bool compress = false;  // EXT_meshopt_compression
};

// The bytes of a .glb file for `scene` (12-byte header, JSON chunk, BIN chunk when non-empty).
std::string glb_bytes(const shape::Scene& scene, const GltfOptions& options = {});

// The text of a .gltf file for `scene`, its buffer embedded as a base64 data URI.
std::string gltf_text(const shape::Scene& scene, const GltfOptions& options = {});

// Writes `path` atomically: .gltf (any case) as JSON text, anything else as binary .glb. Returns an
// empty string on success, else a message naming the file.
std::string write_gltf(const shape::Scene& scene, const std::filesystem::path& path,
                       const GltfOptions& options = {});

}  // namespace insula::io
