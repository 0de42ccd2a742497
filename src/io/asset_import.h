// Asset files (meshes a grammar inserts) read into a kernel::Mesh (docs/assets.md, "Formats").
// OBJ goes through io's own reader (n-gon faces, semantic classes from group names, positioned
// diagnostics) plus the diffuse colours of its MTL files; GLB/glTF through io/gltf_reader.h
// (tinygltf, with the quantization, meshopt compression and GPU instancing extensions Insula's own
// glTF output uses); FBX, DAE and every other format Assimp reads go through Assimp. All but OBJ
// come triangulated. Either way the mesh is in asset space, which is CGA's scope space: y up, as
// OBJ and glTF store it. DAE files that declare Z_UP and FBX files whose UpAxis is z are turned y
// up (x, y, z) -> (x, z, -y); FBX lengths become meters by the file's UnitScaleFactor (centimeters
// per unit). Identical positions are joined.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/mesh.h"

namespace insula::io {

struct AssetMaterial {
  std::string name;
  std::array<float, 4> rgba{0.8F, 0.8F, 0.8F, 1.0F};  // the diffuse (base) colour and opacity
};

struct ImportedAsset {
  // A face's FaceTag::material is its material's index in `materials` + 1 (0: none).
  kernel::Mesh mesh;
  std::vector<AssetMaterial> materials;
};

// Reads the asset at `path`. Fails (diagnostics naming the file, codes AST001..) when the file
// cannot be read, is in no format Assimp knows, requires a glTF extension not read, or holds no
// face.
base::Result<ImportedAsset> import_asset(const std::filesystem::path& path);

}  // namespace insula::io
