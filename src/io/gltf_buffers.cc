#include "io/gltf_buffers.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>

namespace insula::io::gltf {
namespace {

constexpr std::uint32_t kArrayBuffer = 34962;
constexpr std::uint32_t kElementArrayBuffer = 34963;
constexpr std::string_view kMeshopt = "EXT_meshopt_compression";
constexpr std::size_t kViewAlignment = 8;

std::size_t aligned(std::size_t offset) {
  return (offset + kViewAlignment - 1) / kViewAlignment * kViewAlignment;
}

// The view's indices (2 or 4 bytes each) widened to what meshopt's index codec takes.
std::vector<unsigned int> read_indices(std::string_view bytes, std::uint32_t stride) {
  std::vector<unsigned int> indices(bytes.size() / stride);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    unsigned int value = 0;
    for (std::uint32_t b = 0; b < stride; ++b) value |= unsigned{data[stride * i + b]} << (8 * b);
    indices[i] = value;
  }
  return indices;
}

// EXT_meshopt_compression: vertex data with the attribute codec, triangle lists with the index
// codec (its version 1, which every decoder of the extension reads).
std::string encode(std::string_view bytes, ViewKind kind, std::uint32_t stride) {
  std::string out;
  if (kind == ViewKind::kIndices) {
    const std::vector<unsigned int> indices = read_indices(bytes, stride);
    const unsigned int vertices =
        indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
    out.resize(meshopt_encodeIndexBufferBound(indices.size(), vertices));
    meshopt_encodeIndexVersion(1);
    out.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                         indices.data(), indices.size()));
    return out;
  }
  if (kind == ViewKind::kColumn) stride = 4;
  const std::size_t count = bytes.size() / stride;
  out.resize(meshopt_encodeVertexBufferBound(count, stride));
  meshopt_encodeVertexVersion(0);
  out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                        bytes.data(), count, stride));
  return out;
}

}  // namespace

std::uint32_t Buffers::add_view(ViewKind kind, std::uint32_t stride) {
  views_.push_back(View{kind, stride, {}});
  return static_cast<std::uint32_t>(views_.size() - 1);
}

std::uint32_t Buffers::add_accessor(const Accessor& accessor) {
  accessors_.push_back(accessor);
  return static_cast<std::uint32_t>(accessors_.size() - 1);
}

bool Buffers::empty() const {
  return std::all_of(views_.begin(), views_.end(), [](const View& v) { return v.bytes.empty(); });
}

// The meshopt codecs take vertices of a multiple of 4 bytes up to 256 and whole triangles.
bool Buffers::is_compressed(const View& view) const {
  if (!compress_ || view.bytes.empty()) return false;
  switch (view.kind) {
    case ViewKind::kVertices:
    case ViewKind::kInstances:
      return view.stride % 4 == 0 && view.stride <= 256;
    case ViewKind::kIndices:
      return (view.stride == 2 || view.stride == 4) && view.bytes.size() % (3 * view.stride) == 0;
    case ViewKind::kColumn:
      return view.bytes.size() % 4 == 0;
    case ViewKind::kBytes:
      break;
  }
  return false;
}

void Buffers::finish(bool compress) {
  compress_ = compress;
  std::uint32_t index = 0;
  std::size_t first = 0;     // bytes in the first buffer
  std::size_t fallback = 0;  // bytes in the fallback buffer
  bool any_compressed = false;
  for (View& view : views_) {
    if (view.bytes.empty()) continue;
    // A column is compressed in 4-byte groups: pad it (readers use the table's row count).
    if (compress && view.kind == ViewKind::kColumn) pad(view.bytes, 4);
    view.index = index++;
    if (is_compressed(view)) {
      any_compressed = true;
      view.encoded = encode(view.bytes.view(), view.kind, view.stride);
      view.encoded_offset = aligned(first);
      first = view.encoded_offset + view.encoded.size();
      view.offset = aligned(fallback);
      fallback = view.offset + view.bytes.size();
    } else {
      view.offset = aligned(first);
      first = view.offset + view.bytes.size();
    }
  }
  compress_ = any_compressed;
  binary_size_ = first;
  fallback_size_ = fallback;
}

void Buffers::write_accessors(JsonStream& json) const {
  if (accessors_.empty()) return;
  const auto vec3 = [&json](const std::array<double, 3>& v) {
    json.begin_array();
    for (double c : v) json.number(c);
    json.end_array();
  };
  json.key("accessors").begin_array();
  for (const Accessor& a : accessors_) {
    json.begin_object().key("bufferView").integer(views_[a.view].index);
    if (a.offset != 0) json.key("byteOffset").integer(a.offset);
    json.key("componentType").integer(static_cast<std::uint32_t>(a.component));
    json.key("count").integer(a.count);
    if (a.max) {
      json.key("max");
      vec3(*a.max);
    }
    if (a.min) {
      json.key("min");
      vec3(*a.min);
    }
    if (a.normalized) json.key("normalized").boolean(true);
    json.key("type").string(a.type).end_object();
  }
  json.end_array();
}

void Buffers::write_views(JsonStream& json, std::string_view uri) const {
  json.key("bufferViews").begin_array();
  for (const View& view : views_) {
    if (view.bytes.empty()) continue;
    const bool compressed = is_compressed(view);
    json.begin_object().key("buffer").integer(compressed ? 1 : 0);
    json.key("byteLength").integer(view.bytes.size());
    if (view.offset != 0) json.key("byteOffset").integer(view.offset);
    if (view.kind == ViewKind::kVertices) json.key("byteStride").integer(view.stride);
    if (compressed) {
      json.key("extensions").begin_object().key(kMeshopt).begin_object();
      json.key("buffer").integer(0).key("byteLength").integer(view.encoded.size());
      if (view.encoded_offset != 0) json.key("byteOffset").integer(view.encoded_offset);
      const std::uint32_t stride = view.kind == ViewKind::kColumn ? 4 : view.stride;
      json.key("byteStride").integer(stride);
      json.key("count").integer(view.bytes.size() / stride);
      json.key("mode").string(view.kind == ViewKind::kIndices ? "TRIANGLES" : "ATTRIBUTES");
      json.end_object().end_object();
    }
    if (view.kind == ViewKind::kVertices) json.key("target").integer(kArrayBuffer);
    if (view.kind == ViewKind::kIndices) json.key("target").integer(kElementArrayBuffer);
    json.end_object();
  }
  json.end_array();
  json.key("buffers").begin_array().begin_object().key("byteLength").integer(binary_size_);
  if (!uri.empty()) json.key("uri").string(uri);
  json.end_object();
  if (compress_) {
    json.begin_object().key("byteLength").integer(fallback_size_);
    json.key("extensions").begin_object().key(kMeshopt).begin_object();
    json.key("fallback").boolean(true).end_object().end_object().end_object();
  }
  json.end_array();
}

void Buffers::append_binary(std::string& out) const {
  std::vector<std::string_view> pieces;
  binary_pieces(pieces);
  for (const std::string_view piece : pieces) out += piece;
}

void Buffers::binary_pieces(std::vector<std::string_view>& pieces) const {
  static constexpr char kZeros[kViewAlignment] = {};
  std::size_t at = 0;
  for (const View& view : views_) {
    if (view.bytes.empty()) continue;
    const bool compressed = is_compressed(view);
    const std::size_t offset = compressed ? view.encoded_offset : view.offset;
    if (offset > at) pieces.emplace_back(kZeros, offset - at);  // under kViewAlignment
    const std::string_view bytes = compressed ? std::string_view(view.encoded) : view.bytes.view();
    pieces.push_back(bytes);
    at = offset + bytes.size();
  }
}

}  // namespace insula::io::gltf
