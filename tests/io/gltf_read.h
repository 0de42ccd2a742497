// Reading a .glb back with tinygltf (an independent reader) in the glTF writer's tests. The test
// file includes <tiny_gltf.h> (with TINYGLTF_IMPLEMENTATION and its options) before this header:
// the library's implementation part has no include guard of its own.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace insula::io::testing {

// The model in `bytes`; a test failure when tinygltf reports an error or a warning.
inline tinygltf::Model load_glb(const std::string& bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error;
  std::string warning;
  const bool ok = loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()));
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(warning, "");
  return model;
}

// The values of a SCALAR or VEC3 accessor, components flattened.
template <typename T>
std::vector<T> read_accessor(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const tinygltf::BufferView& view =
      model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::size_t components = accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
  std::vector<T> values(accessor.count * components);
  std::memcpy(values.data(), data.data() + view.byteOffset + accessor.byteOffset,
              values.size() * sizeof(T));
  return values;
}

}  // namespace insula::io::testing

namespace insula::io::testing {

// The values of any accessor as doubles, components flattened, decoded from its component type
// (normalized integers mapped as glTF 2.0 §3.11 says) and read with its view's stride.
inline std::vector<double> read_values(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const tinygltf::BufferView& view =
      model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const int components =
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  const int size =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
  const std::size_t stride =
      view.byteStride != 0 ? view.byteStride : static_cast<std::size_t>(components * size);
  std::vector<double> values;
  for (std::size_t i = 0; i < accessor.count; ++i) {
    const unsigned char* element = data.data() + view.byteOffset + accessor.byteOffset + i * stride;
    for (int c = 0; c < components; ++c) {
      const unsigned char* at = element + c * size;
      double v = 0;
      switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
          float f;
          std::memcpy(&f, at, 4);
          v = f;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
          std::uint32_t u;
          std::memcpy(&u, at, 4);
          v = u;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t u;
          std::memcpy(&u, at, 2);
          v = accessor.normalized ? u / 65535.0 : u;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
          std::int16_t s;
          std::memcpy(&s, at, 2);
          v = accessor.normalized ? std::max(s / 32767.0, -1.0) : s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
          v = accessor.normalized ? *at / 255.0 : *at;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
          const auto s = static_cast<std::int8_t>(*at);
          v = accessor.normalized ? std::max(s / 127.0, -1.0) : s;
          break;
        }
        default:
          ADD_FAILURE() << "component type " << accessor.componentType;
      }
      values.push_back(v);
    }
  }
  return values;
}

using Matrix = std::array<double, 16>;  // column-major

inline Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
    }
  }
  return m;
}

// A node's own transform: its matrix, or translation * rotation * scale.
inline Matrix local_matrix(const tinygltf::Node& node) {
  Matrix m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (node.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m[i] = node.matrix[i];
    return m;
  }
  const std::vector<double> t =
      node.translation.empty() ? std::vector<double>{0, 0, 0} : node.translation;
  const std::vector<double> q =
      node.rotation.empty() ? std::vector<double>{0, 0, 0, 1} : node.rotation;
  const std::vector<double> s = node.scale.empty() ? std::vector<double>{1, 1, 1} : node.scale;
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)},
                          {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)},
                          {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)}};
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 3; ++k) m[4 * c + k] = r[c][k] * s[static_cast<std::size_t>(c)];
  }
  for (int k = 0; k < 3; ++k) m[12 + k] = t[static_cast<std::size_t>(k)];
  return m;
}

// One primitive as a viewer draws it: positions placed by its node's world matrix (glTF frame,
// meters), unit normals turned with it, the indices, and per vertex its feature id (or -1).
struct PlacedPrimitive {
  std::string node;
  std::string mesh;
  std::string material;
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<double, 3>> normals;
  std::vector<std::uint32_t> indices;
  std::vector<double> features;
  std::vector<std::array<double, 2>> uvs;  // TEXCOORD_0 when the primitive has it
};

// Keeps only the vertices `p`'s triangles use (primitives of a mesh share their attributes), in
// order of first use, and renumbers the indices.
inline void compact(PlacedPrimitive& p) {
  std::vector<std::int64_t> renumbered(p.positions.size(), -1);
  PlacedPrimitive out{p.node, p.mesh, p.material, {}, {}, {}, {}, {}};
  for (std::uint32_t i : p.indices) {
    if (renumbered[i] < 0) {
      renumbered[i] = static_cast<std::int64_t>(out.positions.size());
      out.positions.push_back(p.positions[i]);
      out.normals.push_back(p.normals[i]);
      out.features.push_back(p.features[i]);
      if (!p.uvs.empty()) out.uvs.push_back(p.uvs[i]);
    }
    out.indices.push_back(static_cast<std::uint32_t>(renumbered[i]));
  }
  p = std::move(out);
}

// TRS as a matrix (glTF 2.0 §3.5.3).
inline Matrix trs_matrix(const std::vector<double>& t, const std::vector<double>& q,
                         const std::vector<double>& s) {
  tinygltf::Node node;
  node.translation = t;
  node.rotation = q;
  node.scale = s;
  return local_matrix(node);
}

// The primitives of mesh `mesh` placed by `world`, appended to `out`; `feature` (>= 0) replaces
// the vertices' feature ids (a GPU instance's own).
inline void place_mesh(const tinygltf::Model& model, const std::string& node_name, int mesh_index,
                       const Matrix& world, double feature, std::vector<PlacedPrimitive>& out) {
  const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(mesh_index)];
  for (const tinygltf::Primitive& primitive : mesh.primitives) {
    PlacedPrimitive placed{node_name,
                           mesh.name,
                           primitive.material >= 0
                               ? model.materials[static_cast<std::size_t>(primitive.material)].name
                               : "",
                           {},
                           {},
                           {},
                           {},
                           {}};
    const std::vector<double> p = read_values(model, primitive.attributes.at("POSITION"));
    const std::vector<double> n = read_values(model, primitive.attributes.at("NORMAL"));
    for (std::size_t i = 0; i + 2 < p.size(); i += 3) {
      std::array<double, 3> a{};
      std::array<double, 3> b{};
      for (int r = 0; r < 3; ++r) {
        a[r] = world[12 + r];
        for (int k = 0; k < 3; ++k) {
          a[r] += world[4 * k + r] * p[i + k];
          b[r] += world[4 * k + r] * n[i + k];
        }
      }
      const double length = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
      for (double& c : b) c /= length;
      placed.positions.push_back(a);
      placed.normals.push_back(b);
    }
    for (double i : read_values(model, primitive.indices))
      placed.indices.push_back(static_cast<std::uint32_t>(i));
    if (feature >= 0) {
      placed.features.assign(placed.positions.size(), feature);
    } else if (primitive.attributes.contains("_FEATURE_ID_0")) {
      placed.features = read_values(model, primitive.attributes.at("_FEATURE_ID_0"));
    } else {
      placed.features.assign(placed.positions.size(), -1);
    }
    if (primitive.attributes.contains("TEXCOORD_0")) {
      const std::vector<double> st = read_values(model, primitive.attributes.at("TEXCOORD_0"));
      for (std::size_t i = 0; i + 1 < st.size(); i += 2) placed.uvs.push_back({st[i], st[i + 1]});
    }
    compact(placed);
    out.push_back(std::move(placed));
  }
}

// Every primitive of the default scene (or under its root node `only_root` when >= 0), node by
// node (depth first); EXT_mesh_gpu_instancing nodes place their mesh once per instance.
inline std::vector<PlacedPrimitive> placed_primitives(const tinygltf::Model& model,
                                                      int only_root = -1) {
  std::vector<PlacedPrimitive> out;
  const auto visit = [&](const auto& self, int index, const Matrix& parent) -> void {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    const Matrix world = multiply(parent, local_matrix(node));
    const auto instancing = node.extensions.find("EXT_mesh_gpu_instancing");
    if (node.mesh >= 0 && instancing != node.extensions.end()) {
      const tinygltf::Value& attributes = instancing->second.Get("attributes");
      const auto column = [&](const char* name) {
        return read_values(model, attributes.Get(name).GetNumberAsInt());
      };
      const std::vector<double> t = column("TRANSLATION");
      const std::vector<double> q = column("ROTATION");
      const std::vector<double> s = column("SCALE");
      std::vector<double> features(t.size() / 3, -1);
      if (attributes.Has("_FEATURE_ID_0")) features = column("_FEATURE_ID_0");
      for (std::size_t i = 0; i < t.size() / 3; ++i) {
        const Matrix placement = trs_matrix({t.begin() + 3 * i, t.begin() + 3 * i + 3},
                                            {q.begin() + 4 * i, q.begin() + 4 * i + 4},
                                            {s.begin() + 3 * i, s.begin() + 3 * i + 3});
        place_mesh(model, node.name, node.mesh, multiply(world, placement), features[i], out);
      }
    } else if (node.mesh >= 0) {
      place_mesh(model, node.name, node.mesh, world, -1, out);
    }
    for (int child : node.children) self(self, child, world);
  };
  const Matrix identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (model.scenes.empty()) return out;
  for (int root : model.scenes[0].nodes) {
    if (only_root < 0 || root == only_root) visit(visit, root, identity);
  }
  return out;
}

// The JSON chunk of a .glb.
inline nlohmann::json json_of(const std::string& glb) {
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.substr(20, length));
}

// The texts of a STRING or ENUM column of the parts' table, row by row.
inline std::vector<std::string> table_column(const tinygltf::Model& model,
                                             const nlohmann::json& json, const std::string& id) {
  const nlohmann::json& metadata = json["extensions"]["EXT_structural_metadata"];
  const nlohmann::json& table = metadata["propertyTables"][0];
  const std::size_t rows = table["count"];
  const auto bytes = [&](const char* key) {
    const tinygltf::BufferView& v =
        model.bufferViews[table["properties"][id][key].get<std::size_t>()];
    return model.buffers[0].data.data() + v.byteOffset;
  };
  std::vector<std::string> texts;
  const nlohmann::json& property = metadata["schema"]["classes"]["part"]["properties"][id];
  if (property["type"] == "STRING") {
    const unsigned char* values = bytes("values");
    const unsigned char* offsets = bytes("stringOffsets");
    for (std::size_t row = 0; row < rows; ++row) {
      std::uint32_t from = 0;
      std::uint32_t to = 0;
      std::memcpy(&from, offsets + 4 * row, 4);
      std::memcpy(&to, offsets + 4 * row + 4, 4);
      texts.emplace_back(reinterpret_cast<const char*>(values) + from, to - from);
    }
    return texts;
  }
  if (property["type"] == "SCALAR") {  // FLOAT64, as %g writes it; "" where it is noData
    const unsigned char* values = bytes("values");
    for (std::size_t row = 0; row < rows; ++row) {
      double value = 0;
      std::memcpy(&value, values + 8 * row, 8);
      char text[32];
      std::snprintf(text, sizeof text, "%g", value);
      texts.emplace_back(
          property.contains("noData") && value == property["noData"].get<double>() ? "" : text);
    }
    return texts;
  }
  const nlohmann::json& enumeration = metadata["schema"]["enums"][id];
  const bool wide = enumeration["valueType"] == "UINT16";
  const unsigned char* codes = bytes("values");
  for (std::size_t row = 0; row < rows; ++row) {
    std::uint16_t code = codes[row];
    if (wide) std::memcpy(&code, codes + 2 * row, 2);
    for (const nlohmann::json& value : enumeration["values"]) {
      if (value["value"] == code) texts.push_back(value["name"]);
    }
  }
  return texts;
}

}  // namespace insula::io::testing
