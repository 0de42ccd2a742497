#define TINYGLTF_IMPLEMENTATION
#include "io/gltf_load.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insula::io::gltf_load {

namespace fs = std::filesystem;

Error unreadable(std::string why) {
  return {"AST001", "cannot read the asset: " + std::move(why)};
}

namespace {

using json = nlohmann::json;

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
}  // namespace

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

}  // namespace insula::io::gltf_load
