#include "io/gltf_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/read_file.h"
#include "io/gltf_load.h"

namespace insula::io {

namespace fs = std::filesystem;

namespace {

using base::Diagnostic;
using base::Span;
using kernel::Vec3;

using gltf_load::Error;
using gltf_load::kInstancing;
using gltf_load::unreadable;

// ---- accessors ----

std::uint32_t little_endian(const unsigned char* at, int bytes) {
  std::uint32_t v = 0;
  for (int b = bytes - 1; b >= 0; --b) v = (v << 8) | at[b];
  return v;
}

// One component, normalized integers mapped to [0, 1] or [-1, 1] (glTF 2.0 §3.11).
double component(const unsigned char* at, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto v = static_cast<std::int8_t>(at[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? at[0] / 255.0 : at[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const auto v = static_cast<std::int16_t>(little_endian(at, 2));
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const std::uint32_t v = little_endian(at, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return little_endian(at, 4);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return std::bit_cast<float>(little_endian(at, 4));
    default:
      return 0;
  }
}

// Appends `count` elements of `components` components of `type` read from bufferView `index`,
// `offset` bytes in and its byteStride apart (or packed). False when they run past the view or
// its buffer.
bool read_view(const tinygltf::Model& model, int index, std::size_t offset, std::size_t count,
               std::size_t components, int type, bool normalized, std::vector<double>& out) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.bufferViews.size()) return false;
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return false;
  }
  const std::vector<unsigned char>& data =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(type));
  if (size <= 0 || view.byteOffset > data.size()) return false;
  if (count == 0) return true;
  const std::size_t element = components * static_cast<std::size_t>(size);
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : element;
  // Overflow-proof bounds: the view's end within its buffer, then the elements within the view.
  const std::size_t end =
      view.byteOffset + std::min(data.size() - view.byteOffset, view.byteLength);
  if (offset > end - view.byteOffset) return false;
  const std::size_t start = view.byteOffset + offset;
  if (element > end - start || count - 1 > (end - start - element) / stride) return false;
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned char* at = data.data() + start + i * stride;
    for (std::size_t c = 0; c < components; ++c)
      out.push_back(component(at + c * size, type, normalized));
  }
  return true;
}

struct Values {
  std::size_t components = 0;  // per element: 1 SCALAR, 3 VEC3, ...
  std::vector<double> data;    // components flattened
};

// Sparse accessors (glTF 2.0 §3.6.2.3): replaces the elements the sparse indices name.
bool apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& a, Values& values) {
  const auto count = static_cast<std::size_t>(std::max(a.sparse.count, 0));
  std::vector<double> at;
  std::vector<double> replacements;
  if (!read_view(model, a.sparse.indices.bufferView,
                 static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0)), count, 1,
                 a.sparse.indices.componentType, false, at) ||
      !read_view(model, a.sparse.values.bufferView,
                 static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0)), count,
                 values.components, a.componentType, a.normalized, replacements)) {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (at[i] >= static_cast<double>(a.count)) return false;
    std::copy_n(replacements.begin() + static_cast<std::ptrdiff_t>(i * values.components),
                values.components,
                values.data.begin() + static_cast<std::ptrdiff_t>(at[i]) *
                                          static_cast<std::ptrdiff_t>(values.components));
  }
  return true;
}

// Accessor `index` decoded from any component type, read with its view's stride. Nullopt when it
// does not exist or names data outside its view or buffer.
std::optional<Values> read_accessor(const tinygltf::Model& model, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return {};
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  if (components <= 0) return {};
  Values out{static_cast<std::size_t>(components), {}};
  if (a.bufferView >= 0) {
    if (!read_view(model, a.bufferView, a.byteOffset, a.count, out.components, a.componentType,
                   a.normalized, out.data)) {
      return {};
    }
  } else {
    // No view: zeros, for sparse substitutions (bounded: nothing in the file backs them).
    if (a.count > (std::size_t{1} << 24)) return {};
    out.data.assign(a.count * out.components, 0.0);
  }
  if (a.sparse.isSparse && !apply_sparse(model, a, out)) return {};
  return out;
}

// ---- placing ----

using Matrix = std::array<double, 16>;  // column-major, as glTF's node.matrix
constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
    }
  }
  return m;
}

// translation * rotation (quaternion x, y, z, w; normalized, as quantized ones are only nearly
// unit) * scale.
Matrix trs(std::array<double, 3> t, std::array<double, 4> q, std::array<double, 3> s) {
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (norm > 0) {
    for (double& c : q) c /= norm;
  }
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)},
                          {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)},
                          {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)}};
  Matrix m = kIdentity;
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 3; ++k) m[4 * c + k] = r[c][k] * s[static_cast<std::size_t>(c)];
  }
  for (int k = 0; k < 3; ++k) m[12 + k] = t[static_cast<std::size_t>(k)];
  return m;
}

template <std::size_t N>
std::array<double, N> array_or(const std::vector<double>& v, std::array<double, N> otherwise) {
  if (v.size() == N) std::copy(v.begin(), v.end(), otherwise.begin());
  return otherwise;
}

Matrix local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return array_or<16>(node.matrix, kIdentity);
  return trs(array_or<3>(node.translation, {0, 0, 0}), array_or<4>(node.rotation, {0, 0, 0, 1}),
             array_or<3>(node.scale, {1, 1, 1}));
}

Vec3 apply(const Matrix& m, const double* p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
          m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

double determinant(const Matrix& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}

// Where a node's mesh goes: the node's world matrix, or with EXT_mesh_gpu_instancing that matrix
// times each instance's TRS (the extension applies the instance transform first). Nullopt when
// the instance attributes are unreadable or of different counts.
std::optional<std::vector<Matrix>> places(const tinygltf::Model& model, const tinygltf::Node& node,
                                          const Matrix& world) {
  const auto ext = node.extensions.find(std::string(kInstancing));
  if (ext == node.extensions.end()) return std::vector<Matrix>{world};
  // (tinygltf's Value::Get asserts an object.)
  if (!ext->second.IsObject() || !ext->second.Get("attributes").IsObject()) return {};
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  std::array<std::optional<Values>, 3> trs_values;  // TRANSLATION, ROTATION, SCALE
  const std::array<const char*, 3> names{"TRANSLATION", "ROTATION", "SCALE"};
  const std::array<std::size_t, 3> components{3, 4, 3};
  std::optional<std::size_t> count;
  for (std::size_t k = 0; k < 3; ++k) {
    const tinygltf::Value& index = attributes.Get(names[k]);
    if (!index.IsInt()) continue;  // absent: that part of every instance is the identity
    trs_values[k] = read_accessor(model, index.Get<int>());
    if (!trs_values[k] || trs_values[k]->components != components[k]) return {};
    const std::size_t n = trs_values[k]->data.size() / components[k];
    if (count && *count != n) return {};
    count = n;
  }
  if (!count) return std::vector<Matrix>{world};
  const auto element = [&](std::size_t k, std::size_t i, auto otherwise) {
    if (!trs_values[k]) return otherwise;
    std::copy_n(trs_values[k]->data.begin() + static_cast<std::ptrdiff_t>(i * components[k]),
                components[k], otherwise.begin());
    return otherwise;
  };
  std::vector<Matrix> out;
  for (std::size_t i = 0; i < *count; ++i) {
    out.push_back(multiply(world, trs(element(0, i, std::array<double, 3>{0, 0, 0}),
                                      element(1, i, std::array<double, 4>{0, 0, 0, 1}),
                                      element(2, i, std::array<double, 3>{1, 1, 1}))));
  }
  return out;
}

// ---- the mesh ----

// A primitive's triangle corners: its index list, or without one its vertices in order.
std::optional<std::vector<std::uint32_t>> corners(const tinygltf::Model& model,
                                                  const tinygltf::Primitive& p,
                                                  std::size_t vertices) {
  std::vector<std::uint32_t> out;
  if (p.indices < 0) {
    for (std::size_t v = 0; v < vertices; ++v) out.push_back(static_cast<std::uint32_t>(v));
  } else {
    const std::optional<Values> indices = read_accessor(model, p.indices);
    if (!indices || indices->components != 1) return {};
    for (double i : indices->data) {
      if (i >= static_cast<double>(vertices)) return {};
      out.push_back(static_cast<std::uint32_t>(i));
    }
  }
  out.resize(out.size() / 3 * 3);
  return out;
}

kernel::MaterialId material_tag(const tinygltf::Model& model, int material) {
  const bool known = material >= 0 && static_cast<std::size_t>(material) < model.materials.size() &&
                     material < std::numeric_limits<kernel::MaterialId>::max();
  return known ? static_cast<kernel::MaterialId>(material + 1) : 0;
}

// Appends a triangle primitive's faces at each of `at`; points and lines add nothing.
std::optional<Error> add_primitive(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                   const std::vector<Matrix>& at, kernel::Mesh& out,
                                   std::uint32_t& face_id) {
  const auto position = p.attributes.find("POSITION");
  if (p.mode != TINYGLTF_MODE_TRIANGLES || position == p.attributes.end()) return {};
  const std::optional<Values> points = read_accessor(model, position->second);
  if (!points || points->components != 3) {
    return unreadable("POSITION accessor " + std::to_string(position->second) +
                      " is no VEC3 inside its buffer");
  }
  const std::size_t n = points->data.size() / 3;
  const auto loops = corners(model, p, n);
  if (!loops) {
    return unreadable("index accessor " + std::to_string(p.indices) +
                      " is unreadable or names a vertex that does not exist");
  }
  kernel::FaceTag tag;
  tag.material = material_tag(model, p.material);
  for (const Matrix& m : at) {
    const auto base = static_cast<std::uint32_t>(out.vertex_count());
    for (std::size_t v = 0; v < n; ++v) out.add_vertex(apply(m, &points->data[3 * v]));
    // A mirroring transform turns the triangles clockwise (glTF 2.0 §3.7.4): swapping two corners
    // keeps them facing out.
    const bool mirrored = determinant(m) < 0;
    for (std::size_t c = 0; c < loops->size(); c += 3) {
      const std::uint32_t a = base + (*loops)[c];
      const std::uint32_t b = base + (*loops)[c + (mirrored ? 2 : 1)];
      const std::uint32_t d = base + (*loops)[c + (mirrored ? 1 : 2)];
      tag.face_id = face_id++;
      out.add_face({a, b, d}, tag);
    }
  }
  return {};
}

// Appends the triangles of node `index` and its descendants, placed by the transforms down to it.
std::optional<Error> add_node(const tinygltf::Model& model, int index, const Matrix& parent,
                              std::size_t depth, kernel::Mesh& out, std::uint32_t& face_id) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) {
    return unreadable("node " + std::to_string(index) + " does not exist");
  }
  // No path down a tree is longer than its node count: a longer one runs round a cycle.
  if (depth > model.nodes.size()) return unreadable("its nodes form a cycle");
  const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
  const Matrix world = multiply(parent, local_matrix(node));
  if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < model.meshes.size()) {
    const auto at = places(model, node, world);
    if (!at) {
      return unreadable("the EXT_mesh_gpu_instancing attributes of node " + std::to_string(index) +
                        " are unreadable");
    }
    for (const tinygltf::Primitive& p :
         model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
      if (auto error = add_primitive(model, p, *at, out, face_id)) return error;
    }
  }
  for (int child : node.children) {
    if (auto error = add_node(model, child, world, depth + 1, out, face_id)) return error;
  }
  return {};
}

// The default scene's root nodes; in a file without scenes, every node that is no node's child.
std::vector<int> roots(const tinygltf::Model& model) {
  if (!model.scenes.empty()) {
    const bool valid = model.defaultScene >= 0 &&
                       static_cast<std::size_t>(model.defaultScene) < model.scenes.size();
    return model.scenes[valid ? static_cast<std::size_t>(model.defaultScene) : 0].nodes;
  }
  std::vector<bool> child(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes) {
    for (int c : node.children) {
      if (c >= 0 && static_cast<std::size_t>(c) < child.size())
        child[static_cast<std::size_t>(c)] = true;
    }
  }
  std::vector<int> out;
  for (std::size_t i = 0; i < child.size(); ++i) {
    if (!child[i]) out.push_back(static_cast<int>(i));
  }
  return out;
}

AssetMaterial material_of(const tinygltf::Material& m) {
  AssetMaterial out;
  out.name = m.name;
  const std::vector<double>& rgba = m.pbrMetallicRoughness.baseColorFactor;
  if (rgba.size() == 4) {
    for (std::size_t i = 0; i < 4; ++i) out.rgba[i] = static_cast<float>(rgba[i]);
  }
  return out;
}

base::Result<ImportedAsset> fail(const fs::path& path, Error error) {
  return base::Result<ImportedAsset>::failure({Diagnostic::error(
      std::move(error.code), std::move(error.message), Span::whole(path.string()))});
}

}  // namespace

base::Result<ImportedAsset> import_gltf(const fs::path& path) {
  const std::optional<std::string> bytes = base::read_file(path);
  if (!bytes) return fail(path, {"AST001", "cannot read the file"});
  tinygltf::Model model;
  if (auto error = gltf_load::load(path, *bytes, model)) return fail(path, std::move(*error));
  kernel::Mesh mesh;
  std::uint32_t face_id = 0;
  for (int root : roots(model)) {
    if (auto error = add_node(model, root, kIdentity, 0, mesh, face_id)) {
      return fail(path, std::move(*error));
    }
  }
  for (const Vec3& p : mesh.positions()) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return fail(path, {"AST002", "the asset has a vertex that is not a finite number"});
    }
  }
  ImportedAsset out;
  out.mesh = kernel::weld(mesh, 0);
  if (out.mesh.empty()) return fail(path, {"AST003", "the asset has no faces"});
  for (const tinygltf::Material& m : model.materials) out.materials.push_back(material_of(m));
  return out;
}

}  // namespace insula::io
