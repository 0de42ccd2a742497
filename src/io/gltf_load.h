// Loading a glTF asset (.glb bytes, or a .gltf's text with its external buffers) into a tinygltf
// model for io/gltf_reader.h: the GLB container split and checked, required extensions checked,
// EXT_meshopt_compression's data-less fallback buffers stubbed before tinygltf reads the JSON and
// their views decoded with meshoptimizer afterwards (filters included).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "io/tinygltf_renamed.h"

namespace insula::io::gltf_load {

inline constexpr std::string_view kMeshopt = "EXT_meshopt_compression";
inline constexpr std::string_view kInstancing = "EXT_mesh_gpu_instancing";

// A failure of one step: its diagnostic code and message (the file is named by import_gltf).
struct Error {
  std::string code;
  std::string message;
};

// AST001 "cannot read the asset: <why>".
Error unreadable(std::string why);

// The glTF in `bytes` (a GLB or a .gltf's text; `path` for external buffers) as a tinygltf model
// with every EXT_meshopt_compression view decoded; an error when it cannot be read or requires an
// extension the reader does not know (AST004).
std::optional<Error> load(const std::filesystem::path& path, const std::string& bytes,
                          tinygltf::Model& model);

}  // namespace insula::io::gltf_load
