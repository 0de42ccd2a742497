#include "io/gltf_reader.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

// tinygltf's implementation is compiled here under a namespace of its own: glTF test files compile
// it too (the library has no separate object), and a test linking this reader as well would
// otherwise define every tinygltf function twice.
#define tinygltf insula_tinygltf
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE  // assets are read for their geometry: images stay undecoded
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE  // nor loaded (external buffers are)
#define TINYGLTF_NO_INCLUDE_JSON
#include <tiny_gltf.h>

namespace insula::io {

namespace fs = std::filesystem;

namespace {

using base::Diagnostic;
using base::Span;
using kernel::Vec3;
using json = nlohmann::json;

constexpr std::string_view kMeshopt = "EXT_meshopt_compression";
constexpr std::string_view kInstancing = "EXT_mesh_gpu_instancing";

// A failure of one step: its diagnostic code and message (the file is named by import_gltf).
struct Error {
  std::string code;
  std::string message;
};

Error unreadable(std::string why) {
  return {"AST001", "cannot read the asset: " + std::move(why)};
}

// ---- the container: a GLB's chunks, or a .gltf's text ----

std::uint32_t u32_at(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int b = 3; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>(bytes[at + b]);
  return v;
}

void append_u32(std::string& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out += static_cast<char>((v >> (8 * b)) & 0xFFU);
}

struct Container {
  bool binary = false;
  std::string text;  // the JSON chunk or the whole .gltf
  std::string bin;   // the BIN chunk (GLB only; may be empty)
};

constexpr std::uint32_t kJsonChunk = 0x4E4F534A;
constexpr std::uint32_t kBinChunk = 0x004E4942;

// Splits a GLB (glTF 2.0 §4.4) into its chunks, checking every length against the bytes there
// are: a truncated file is an error here, before tinygltf reads past its end.
std::optional<Container> split_glb(std::string_view bytes) {
  if (bytes.size() < 20 || u32_at(bytes, 4) != 2 || u32_at(bytes, 8) > bytes.size()) return {};
  bytes = bytes.substr(0, u32_at(bytes, 8));
  Container out{true, {}, {}};
  for (std::size_t at = 12; at + 8 <= bytes.size();) {
    const std::size_t length = u32_at(bytes, at);
    const std::uint32_t type = u32_at(bytes, at + 4);
    if (length > bytes.size() - at - 8) return {};
    const std::string_view data = bytes.substr(at + 8, length);
    if (at == 12 && type != kJsonChunk) return {};
    if (type == kJsonChunk && at == 12) out.text = data;
    if (type == kBinChunk && at != 12 && out.bin.empty()) out.bin = data;
    at += 8 + (length + 3) / 4 * 4;
  }
  if (out.text.empty()) return {};
  return out;
}

// The GLB again, with `text` as its JSON chunk.
std::string join_glb(const std::string& text, const std::string& bin) {
  std::string chunks;
  const auto chunk = [&chunks](const std::string& data, std::uint32_t type, char padding) {
    const std::size_t padded = (data.size() + 3) / 4 * 4;
    append_u32(chunks, static_cast<std::uint32_t>(padded));
    append_u32(chunks, type);
    chunks += data;
    chunks.append(padded - data.size(), padding);
  };
  chunk(text, kJsonChunk, ' ');
  if (!bin.empty()) chunk(bin, kBinChunk, '\0');
  std::string out = "glTF";
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(12 + chunks.size()));
  return out + chunks;
}

// ---- the JSON, before tinygltf reads it ----

// Extensions that change what the geometry is, which this reader applies, and extensions that
// change only looks (materials, textures, lights), which an asset's geometry can do without.
bool known_extension(std::string_view name) {
  if (name == "KHR_mesh_quantization" || name == kMeshopt || name == kInstancing) return true;
  for (std::string_view looks : {"KHR_materials_", "KHR_texture_", "EXT_texture_"}) {
    if (name.starts_with(looks)) return true;
  }
  return name == "KHR_lights_punctual";
}

std::optional<Error> check_required(const json& gltf) {
  const auto it = gltf.find("extensionsRequired");
  if (it == gltf.end() || !it->is_array()) return {};
  for (const json& name : *it) {
    if (!name.is_string() || known_extension(name.get<std::string>())) continue;
    return Error{"AST004", "the asset requires the glTF extension " + name.get<std::string>() +
                               ", which Insula does not read"};
  }
  return {};
}

// EXT_meshopt_compression's fallback buffer: flagged, and without data of its own.
bool is_fallback(const json& buffer) {
  if (!buffer.is_object() || buffer.contains("uri")) return false;
  const json::json_pointer flag("/extensions/EXT_meshopt_compression/fallback");
  return buffer.contains(flag) && buffer.at(flag) == true;
}

// tinygltf 2.7 cannot load EXT_meshopt_compression's fallback buffer, which has neither a uri nor
// data: in a GLB it copies the BIN chunk into it (or fails, when the fallback is the longer). Each
// one is handed to tinygltf as a 3-byte data URI instead, and its real length returned by index,
// to be re-created (and decoded into) after loading. Nullopt for a length that is none or too long.
std::optional<std::map<std::size_t, std::size_t>> stub_fallback_buffers(json& gltf) {
  // Bounds the allocation a malformed file can ask for.
  constexpr std::uint64_t kLongest = std::uint64_t{1} << 32;
  std::map<std::size_t, std::size_t> lengths;
  const auto buffers = gltf.find("buffers");
  if (buffers == gltf.end() || !buffers->is_array()) return lengths;
  for (std::size_t i = 0; i < buffers->size(); ++i) {
    json& buffer = (*buffers)[i];
    if (!is_fallback(buffer)) continue;
    const json length = buffer.value("byteLength", json{});
    if (!length.is_number_unsigned() || length.get<std::uint64_t>() > kLongest) return {};
    lengths[i] = length.get<std::size_t>();
    buffer["uri"] = "data:application/octet-stream;base64,AAAA";
    buffer["byteLength"] = 3;
  }
  return lengths;
}

// ---- EXT_meshopt_compression ----

// A member of an extension object: an unsigned number (or `otherwise` when absent; SIZE_MAX,
// which no check passes, when it is something else).
std::size_t size_field(const json& object, const char* key, std::size_t otherwise) {
  const auto it = object.find(key);
  if (it == object.end()) return otherwise;
  return it->is_number_unsigned() ? it->get<std::size_t>() : SIZE_MAX;
}

std::string string_field(const json& object, const char* key, std::string otherwise) {
  const auto it = object.find(key);
  if (it == object.end()) return otherwise;
  return it->is_string() ? it->get<std::string>() : std::string();
}

// Undoes an ATTRIBUTES view's filter in place (the extension's filters, each for its strides).
bool unfilter(const std::string& filter, unsigned char* data, std::size_t count,
              std::size_t stride) {
  if (filter == "NONE") return true;
  if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8)) {
    meshopt_decodeFilterOct(data, count, stride);
  } else if (filter == "QUATERNION" && stride == 8) {
    meshopt_decodeFilterQuat(data, count, stride);
  } else if (filter == "EXPONENTIAL" && stride % 4 == 0) {
    meshopt_decodeFilterExp(data, count, stride);
  } else {
    return false;
  }
  return true;
}

// Decodes one view's compressed bytes (`ext`, the view's EXT_meshopt_compression object) into the
// view's own place in its (fallback) buffer, where accessors then read them as plain data. Every
// offset, length and stride is checked first: the codecs trust theirs.
std::optional<std::string> decode_view(const json& ext, const tinygltf::BufferView& view,
                                       tinygltf::Model& model) {
  const std::size_t source = size_field(ext, "buffer", SIZE_MAX);
  const std::size_t offset = size_field(ext, "byteOffset", 0);
  const std::size_t length = size_field(ext, "byteLength", SIZE_MAX);
  const std::size_t stride = size_field(ext, "byteStride", SIZE_MAX);
  const std::size_t count = size_field(ext, "count", SIZE_MAX);
  const std::string mode = string_field(ext, "mode", "");
  const std::string filter = string_field(ext, "filter", "NONE");
  if (source >= model.buffers.size() || view.buffer < 0 ||
      static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return "names no buffer";
  }
  const std::vector<unsigned char>& from = model.buffers[source].data;
  std::vector<unsigned char>& to = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (offset > from.size() || length > from.size() - offset) return "runs past its buffer";
  if (stride == 0 || stride > 256 || view.byteOffset > to.size() ||
      count > (to.size() - view.byteOffset) / stride) {
    return "does not fit its view's buffer";
  }
  const unsigned char* in = from.data() + offset;
  unsigned char* out = to.data() + view.byteOffset;
  int status = -1;
  if (mode == "ATTRIBUTES" && stride % 4 == 0) {
    status = meshopt_decodeVertexBuffer(out, count, stride, in, length);
    if (status == 0 && !unfilter(filter, out, count, stride)) return "has filter " + filter;
  } else if (mode == "TRIANGLES" && (stride == 2 || stride == 4) && count % 3 == 0) {
    status = meshopt_decodeIndexBuffer(out, count, stride, in, length);
  } else if (mode == "INDICES" && (stride == 2 || stride == 4)) {
    status = meshopt_decodeIndexSequence(out, count, stride, in, length);
  } else {
    return "has mode " + mode + " with stride " + std::to_string(stride);
  }
  if (status != 0) return "does not decode";
  return {};
}

std::optional<Error> decode_meshopt(const json& gltf, tinygltf::Model& model) {
  const auto views = gltf.find("bufferViews");
  if (views == gltf.end() || !views->is_array()) return {};
  const json::json_pointer ext_path("/extensions/" + std::string(kMeshopt));
  for (std::size_t i = 0; i < model.bufferViews.size() && i < views->size(); ++i) {
    const json& view = (*views)[i];
    if (!view.contains(ext_path) || !view.at(ext_path).is_object()) continue;
    if (auto why = decode_view(view.at(ext_path), model.bufferViews[i], model)) {
      return unreadable("the EXT_meshopt_compression data of bufferView " + std::to_string(i) +
                        " " + *why);
    }
  }
  return {};
}

// ---- loading ----

// Images are not decoded (TINYGLTF_NO_STB_IMAGE); tinygltf still wants a loader to hand them to.
bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                          const unsigned char*, int, void*) {
  return true;
}

// tinygltf's error text on one line.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text.empty() ? "tinygltf cannot parse it" : text;
}

// `model` from the container's JSON (already checked and stubbed) with tinygltf.
std::optional<Error> parse(const fs::path& path, const Container& container, const json& gltf,
                           tinygltf::Model& model) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_undecoded, nullptr);
  std::string error;
  std::string warning;
  const std::string text = gltf.dump(-1, ' ', false, json::error_handler_t::replace);
  const std::string base = path.parent_path().string();
  bool ok = false;
  try {  // tinygltf reads malformed files with checked accesses that throw
    if (container.binary) {
      const std::string glb = join_glb(text, container.bin);
      ok = loader.LoadBinaryFromMemory(&model, &error, &warning,
                                       reinterpret_cast<const unsigned char*>(glb.data()),
                                       static_cast<unsigned>(glb.size()), base);
    } else {
      ok = loader.LoadASCIIFromString(&model, &error, &warning, text.data(),
                                      static_cast<unsigned>(text.size()), base);
    }
  } catch (const std::exception& e) {
    return unreadable(e.what());
  }
  if (!ok) return unreadable(one_line(error));
  return {};
}

// The glTF in `bytes` (a GLB or a .gltf's text) as a tinygltf model with every
// EXT_meshopt_compression view decoded.
std::optional<Error> load(const fs::path& path, const std::string& bytes, tinygltf::Model& model) {
  const std::optional<Container> container =
      bytes.starts_with("glTF") ? split_glb(bytes) : Container{false, bytes, {}};
  if (!container) return unreadable("the GLB is truncated or no glTF 2.0 binary");
  json gltf = json::parse(container->text, nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object()) return unreadable("its JSON does not parse");
  if (auto error = check_required(gltf)) return error;
  const auto fallbacks = stub_fallback_buffers(gltf);
  if (!fallbacks) return unreadable("an EXT_meshopt_compression fallback buffer has no length");
  if (auto error = parse(path, *container, gltf, model)) return error;
  for (const auto& [index, length] : *fallbacks) model.buffers[index].data.assign(length, 0);
  return decode_meshopt(gltf, model);
}

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

std::optional<std::string> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(bytes).str();
}

base::Result<ImportedAsset> fail(const fs::path& path, Error error) {
  return base::Result<ImportedAsset>::failure({Diagnostic::error(
      std::move(error.code), std::move(error.message), Span::whole(path.string()))});
}

}  // namespace

base::Result<ImportedAsset> import_gltf(const fs::path& path) {
  const std::optional<std::string> bytes = read_bytes(path);
  if (!bytes) return fail(path, {"AST001", "cannot read the file"});
  tinygltf::Model model;
  if (auto error = load(path, *bytes, model)) return fail(path, std::move(*error));
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
