// Reading a .glb back with tinygltf (an independent reader) in the glTF writer's tests. The test
// file includes <tiny_gltf.h> (with TINYGLTF_IMPLEMENTATION and its options) before this header:
// the library's implementation part has no include guard of its own.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

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
