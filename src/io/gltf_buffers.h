// The binary side of a glTF asset (glTF 2.0 §3.6, "Binary Data Storage"): buffer views that grow as
// the writer appends data of one layout to each (all quantized positions of the scene in one view,
// all normals in another, ...), the accessors over them, and the buffer that holds them. Few views
// keep the JSON small and let EXT_meshopt_compression work on long runs of alike data: with
// `compress`, every vertex and index view is encoded with meshoptimizer (modes ATTRIBUTES and
// TRIANGLES) into the GLB's buffer, and the views point at an uncompressed fallback buffer that
// has no data (the extension is then required). Views start at multiples of 8 bytes (the
// alignment EXT_structural_metadata asks of its tables, more than glTF's 4).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/json_stream.h"

namespace insula::io::gltf {

enum class Component : std::uint32_t {
  kByte = 5120,
  kUnsignedByte = 5121,
  kShort = 5122,
  kUnsignedShort = 5123,
  kUnsignedInt = 5125,
  kFloat = 5126,
};

// What a view holds, which decides its target and how --compress encodes it.
enum class ViewKind {
  kVertices,   // vertex attributes, `stride` bytes each (ARRAY_BUFFER, meshopt ATTRIBUTES)
  kIndices,    // triangle lists of `stride`-byte indices (ELEMENT_ARRAY_BUFFER, meshopt TRIANGLES)
  kInstances,  // per-instance attributes (no target, meshopt ATTRIBUTES)
  kColumn,     // a property table column: compressed as 4-byte groups (meshopt ATTRIBUTES)
  kBytes,      // anything else, images: stored as they are
};

// A view's bytes: grows as std::string does, and also without writing the bytes it adds
// (extend()), for data the writer fills in place right after: a tile's vertex attributes, which a
// std::string zeroed first at about the cost of writing them.
class Bytes {
 public:
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  char* data() { return data_.get(); }
  const char* data() const { return data_.get(); }
  std::string_view view() const { return {data_.get(), size_}; }
  char& operator[](std::size_t i) { return data_[i]; }
  void reserve(std::size_t capacity) {
    if (capacity > capacity_) reallocate(capacity);
  }
  // `count` more bytes at the end, not written: the caller writes every one of them.
  char* extend(std::size_t count) {
    if (count > capacity_ - size_) reallocate(std::max(size_ + count, 2 * capacity_));
    char* at = data_.get() + size_;
    size_ += count;
    return at;
  }
  void append(const char* bytes, std::size_t count) {
    if (count > 0) std::memcpy(extend(count), bytes, count);
  }
  void append(std::size_t count, char c) {
    if (count > 0) std::memset(extend(count), c, count);
  }
  void push_back(char c) { *extend(1) = c; }
  Bytes& operator+=(std::string_view bytes) {
    append(bytes.data(), bytes.size());
    return *this;
  }

 private:
  void reallocate(std::size_t capacity) {
    auto data = std::make_unique_for_overwrite<char[]>(capacity);
    if (size_ > 0) std::memcpy(data.get(), data_.get(), size_);
    data_ = std::move(data);
    capacity_ = capacity;
  }

  std::unique_ptr<char[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

struct Accessor {
  std::uint32_t view = 0;
  std::size_t offset = 0;  // bytes into the view
  Component component = Component::kFloat;
  std::size_t count = 0;
  std::string_view type = "SCALAR";  // SCALAR, VEC2, VEC3, VEC4
  bool normalized = false;
  // Written for POSITION accessors (required there), in the accessor's own units.
  std::optional<std::array<double, 3>> min{};
  std::optional<std::array<double, 3>> max{};
};

class Buffers {
 public:
  // A new, empty view; its index is the one accessors and images name. Views left empty are not
  // written (indices are renumbered at writing).
  std::uint32_t add_view(ViewKind kind, std::uint32_t stride);
  // The bytes of `view` so far, to append to (little-endian values). The reference stays valid
  // when more views are added.
  Bytes& data(std::uint32_t view) { return views_[view].bytes; }
  std::uint32_t add_accessor(const Accessor& accessor);
  void reserve_accessors(std::size_t count) { accessors_.reserve(count); }
  void set_bounds(std::uint32_t accessor,
                  const std::pair<std::array<double, 3>, std::array<double, 3>>& min_max) {
    accessors_[accessor].min = min_max.first;
    accessors_[accessor].max = min_max.second;
  }
  bool empty() const;

  // Lays the views out in the buffer; with `compress`, encodes the vertex and index views with
  // meshoptimizer. Call once, after the last append and before writing.
  void finish(bool compress);
  bool compressed() const { return compress_; }
  // The glTF index of a view (views left empty are skipped).
  std::uint32_t view_index(std::uint32_t view) const { return views_[view].index; }

  // "accessors" (when any).
  void write_accessors(JsonStream& json) const;
  // "bufferViews" and "buffers"; `uri` (when not empty) becomes the first buffer's "uri".
  void write_views(JsonStream& json, std::string_view uri) const;
  // The bytes of the first buffer (the GLB's BIN chunk), unpadded, and their count.
  void append_binary(std::string& out) const;
  // The same bytes as the pieces they are laid out from, appended to `pieces`: each view's bytes
  // and the zeros before it (the one layout append_binary() copies, for writing the pieces to a
  // file in turn). They point into the views: valid while these Buffers are.
  void binary_pieces(std::vector<std::string_view>& pieces) const;
  std::size_t binary_size() const { return binary_size_; }

 private:
  struct View {
    ViewKind kind;
    std::uint32_t stride;
    Bytes bytes;
    std::uint32_t index = 0;         // glTF index once finished
    std::size_t offset = 0;          // into the buffer the view's bufferView names
    std::string encoded{};           // meshopt-encoded bytes (compressed views only)
    std::size_t encoded_offset = 0;  // into the first buffer
  };
  bool is_compressed(const View& view) const;

  std::deque<View> views_;  // a deque: data() references survive add_view()
  std::vector<Accessor> accessors_;
  bool compress_ = false;
  std::size_t binary_size_ = 0;    // the first buffer
  std::size_t fallback_size_ = 0;  // the uncompressed fallback buffer (compressed output only)
};

// Appends `value`'s bytes little-endian, whatever the host (glTF 2.0 §3.6.2.1), to a std::string
// or Bytes.
template <typename Out, typename T>
void append_value(Out& out, T value) {
  static_assert(std::is_arithmetic_v<T>);
  using Bits = std::conditional_t<
      sizeof(T) == 1, std::uint8_t,
      std::conditional_t<sizeof(T) == 2, std::uint16_t,
                         std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  const auto bits = std::bit_cast<Bits>(value);
  char bytes[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bytes[i] = static_cast<char>((bits >> (8 * i)) & 0xFFU);
  out.append(bytes, sizeof(T));
}

// Stores `value`'s bytes little-endian at `at` and moves `at` past them: for filling a buffer
// sized beforehand, where appending value by value would cost more than the values.
template <typename T>
void put_value(char*& at, T value) {
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(at, &value, sizeof(T));
  } else {
    std::string bytes;
    append_value(bytes, value);
    std::memcpy(at, bytes.data(), sizeof(T));
  }
  at += sizeof(T);
}

// Pads `out` (a std::string or Bytes) with zero bytes to a multiple of `alignment`.
template <typename Out>
void pad(Out& out, std::size_t alignment) {
  out.append((alignment - out.size() % alignment) % alignment, '\0');
}

}  // namespace insula::io::gltf
