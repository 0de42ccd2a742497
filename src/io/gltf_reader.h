// glTF 2.0 assets (.glb, and .gltf with embedded or external buffers) read into a kernel::Mesh for
// io/asset_import.h with tinygltf. Besides plain glTF it reads what io's own glTF writer uses and
// Assimp 5.2 does not: KHR_mesh_quantization (integer and normalized attributes of any component
// type), EXT_meshopt_compression (decoded with meshoptimizer, filters included) and
// EXT_mesh_gpu_instancing (every instance placed), so Insula reads its own output back. The
// default scene's node tree is walked with node matrices or TRS; triangle primitives are kept (an
// index list or none), other modes skipped. Positions stay as glTF stores them (y up, meters), and
// identical positions are joined. A face's material is its primitive's material index + 1, the
// materials keeping their name and pbrMetallicRoughness.baseColorFactor.
#pragma once

#include <filesystem>

#include "base/diagnostic.h"
#include "io/asset_import.h"

namespace insula::io {

// Reads the glTF asset at `path`. Fails with diagnostics naming the file: AST001 the file cannot be
// read, is no glTF or holds data out of its bounds; AST002 a vertex is not a finite number; AST003
// no faces; AST004 the file requires an extension this reader does not know (named).
base::Result<ImportedAsset> import_gltf(const std::filesystem::path& path);

}  // namespace insula::io
