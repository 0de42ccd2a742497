#include "io/asset_import.h"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

#include "base/read_file.h"
#include "io/gltf_reader.h"
#include "io/obj_reader.h"

namespace insula::io {

namespace fs = std::filesystem;

namespace {

using base::Diagnostic;
using base::Span;
using kernel::Vec3;

base::Result<ImportedAsset> fail(const fs::path& path, std::string code, std::string message) {
  return base::Result<ImportedAsset>::failure(
      {Diagnostic::error(std::move(code), std::move(message), Span::whole(path.string()))});
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The rest of a line after its keyword, when the line starts with `keyword` and a blank.
std::optional<std::string_view> after(std::string_view line, std::string_view keyword) {
  line = trim(line);
  if (line.size() <= keyword.size() || line.substr(0, keyword.size()) != keyword) return {};
  if (!std::isspace(static_cast<unsigned char>(line[keyword.size()]))) return {};
  return trim(line.substr(keyword.size()));
}

template <typename Fn>
void for_each_line(std::string_view text, Fn&& fn) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    fn(text.substr(start, end - start));
    start = end + 1;
  }
}

// Diffuse colours by material name from an MTL file: Kd, and d (or Tr = 1 - d) for opacity.
void read_mtl(const fs::path& path, std::map<std::string, std::array<float, 4>>& colours) {
  const std::optional<std::string> text = base::read_file(path);
  if (!text) return;
  std::array<float, 4>* current = nullptr;
  for_each_line(*text, [&](std::string_view line) {
    if (auto name = after(line, "newmtl")) {
      current = &colours[std::string(*name)];
      *current = AssetMaterial{}.rgba;
      return;
    }
    if (current == nullptr) return;
    std::istringstream in{std::string(trim(line))};
    std::string key;
    in >> key;
    float a = 0, b = 0, c = 0;
    if (key == "Kd" && (in >> a >> b >> c)) {
      (*current)[0] = a;
      (*current)[1] = b;
      (*current)[2] = c;
    } else if (key == "d" && (in >> a)) {
      (*current)[3] = a;
    } else if (key == "Tr" && (in >> a)) {
      (*current)[3] = 1.0F - a;
    }
  });
}

base::Result<ImportedAsset> import_obj(const fs::path& path) {
  const std::optional<std::string> text = base::read_file(path);
  if (!text) return fail(path, "AST001", "cannot read the file");
  base::Result<ObjModel> model = parse_obj(*text, path.string());
  if (!model.ok()) return base::Result<ImportedAsset>::failure(std::move(model.diagnostics()));
  std::map<std::string, std::array<float, 4>> colours;
  for_each_line(*text, [&](std::string_view line) {
    const auto names = after(line, "mtllib");
    if (!names) return;
    // One name with blanks (Blender writes those) or several names separated by blanks.
    const fs::path whole = path.parent_path() / std::string(*names);
    if (std::error_code ec; fs::is_regular_file(whole, ec)) return read_mtl(whole, colours);
    std::istringstream in{std::string(*names)};
    for (std::string name; in >> name;) read_mtl(path.parent_path() / name, colours);
  });
  ImportedAsset out;
  out.mesh = kernel::weld(model->mesh, 0);
  for (const std::string& name : model->materials) {
    const auto it = colours.find(name);
    out.materials.push_back({name, it != colours.end() ? it->second : AssetMaterial{}.rgba});
  }
  return {std::move(out), std::move(model.diagnostics())};
}

// The scene's metadata value `key` as a number (FBX stores ints, floats and doubles).
std::optional<double> metadata_number(const aiScene& scene, const char* key) {
  if (scene.mMetaData == nullptr) return std::nullopt;
  if (int i = 0; scene.mMetaData->Get(key, i)) return i;
  if (float f = 0; scene.mMetaData->Get(key, f)) return f;
  if (double d = 0; scene.mMetaData->Get(key, d)) return d;
  return std::nullopt;
}

AssetMaterial material_of(const aiMaterial& m) {
  AssetMaterial out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  aiColor4D c;
  if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
      m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
    out.rgba = {c.r, c.g, c.b, c.a};
  }
  if (float opacity = 1; m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1) {
    out.rgba[3] = opacity;
  }
  return out;
}

// Appends the triangles of every mesh under `node`, placed by the node transforms down to it.
void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
              const aiMatrix4x4& to_asset, kernel::Mesh& out, std::uint32_t& face_id) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  const aiMatrix4x4 place = to_asset * transform;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const auto base = static_cast<std::uint32_t>(out.vertex_count());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = place * mesh.mVertices[v];
      out.add_vertex({p.x, p.y, p.z});
    }
    kernel::FaceTag tag;
    const bool known = mesh.mMaterialIndex < scene.mNumMaterials &&
                       mesh.mMaterialIndex < std::numeric_limits<kernel::MaterialId>::max();
    tag.material = known ? static_cast<kernel::MaterialId>(mesh.mMaterialIndex + 1) : 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      tag.face_id = face_id++;
      out.add_face({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]},
                   tag);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    add_node(scene, *node.mChildren[c], transform, to_asset, out, face_id);
  }
}

// FBX: centimeters per unit and the up axis from the file's global settings; Assimp applies
// neither. (DAE's up_axis Assimp applies itself.)
aiMatrix4x4 fbx_to_asset_space(const aiScene& scene) {
  aiMatrix4x4 m;
  if (const auto unit = metadata_number(scene, "UnitScaleFactor"); unit && *unit > 0) {
    aiMatrix4x4::Scaling(aiVector3D(static_cast<float>(*unit / 100.0)), m);
  }
  const auto up = metadata_number(scene, "UpAxis");
  if (up && *up == 2) {
    const double sign = metadata_number(scene, "UpAxisSign").value_or(1) < 0 ? -1.0 : 1.0;
    aiMatrix4x4 z_to_y;
    aiMatrix4x4::RotationX(static_cast<float>(-sign * std::numbers::pi / 2), z_to_y);
    m = z_to_y * m;
  }
  return m;
}

base::Result<ImportedAsset> import_assimp(const fs::path& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_FindDegenerates);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    const std::string why = importer.GetErrorString();
    return fail(path, "AST001", "cannot read the asset" + (why.empty() ? "" : ": " + why));
  }
  const aiMatrix4x4 to_asset =
      lower(path.extension().string()) == ".fbx" ? fbx_to_asset_space(*scene) : aiMatrix4x4();
  kernel::Mesh mesh;
  std::uint32_t face_id = 0;
  add_node(*scene, *scene->mRootNode, aiMatrix4x4(), to_asset, mesh, face_id);
  for (const Vec3& p : mesh.positions()) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return fail(path, "AST002", "the asset has a vertex that is not a finite number");
    }
  }
  ImportedAsset out;
  out.mesh = kernel::weld(mesh, 0);
  if (out.mesh.empty()) return fail(path, "AST003", "the asset has no faces");
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
    out.materials.push_back(material_of(*scene->mMaterials[m]));
  }
  return out;
}

}  // namespace

base::Result<ImportedAsset> import_asset(const fs::path& path) {
  if (std::error_code ec; !fs::is_regular_file(path, ec)) {
    return fail(path, "AST001", "cannot read the file");
  }
  const std::string extension = lower(path.extension().string());
  if (extension == ".obj") return import_obj(path);
  // Not Assimp: Assimp 5.2 ignores KHR_mesh_quantization and EXT_meshopt_compression, which
  // Insula's own glTF output uses.
  if (extension == ".glb" || extension == ".gltf") return import_gltf(path);
  return import_assimp(path);
}

}  // namespace insula::io
