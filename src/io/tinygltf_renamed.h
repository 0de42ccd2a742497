// tinygltf as io's glTF reader uses it, under a namespace of its own (insula_tinygltf): the glTF
// test files compile tinygltf's implementation too (the library has no separate object), and a
// test linking the reader as well would otherwise define every tinygltf function twice. Exactly
// one file (io/gltf_load.cc) defines TINYGLTF_IMPLEMENTATION before including this.
#pragma once

#include <nlohmann/json.hpp>

#define tinygltf insula_tinygltf
#define TINYGLTF_NO_STB_IMAGE  // assets are read for their geometry: images stay undecoded
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE  // nor loaded (external buffers are)
#define TINYGLTF_NO_INCLUDE_JSON
#include <tiny_gltf.h>
