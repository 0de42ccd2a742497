// A streaming JSON text writer for the big exports (glTF, CityJSON): values are appended to one
// std::string as they come, with no document tree, so writing costs about as much as the bytes
// it produces. The text is byte for byte what nlohmann::json::dump() (compact) or dump(indent)
// (pretty) prints for the same document: doubles in nlohmann's shortest round-trip form ("3.0",
// "0.001", "1e-07", non-finite as null), strings escaped the same way (\" \\ \b \f \n \r \t,
// other control characters as \u00xx, UTF-8 kept as is), "{}" and "[]" for empty containers.
// The caller writes object keys in the order nlohmann would (sorted bytewise) when it wants the
// same bytes; the stream does not sort. Bytes that are not valid UTF-8 become U+FFFD.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "shape/value.h"

namespace insula::io {

class JsonStream {
 public:
  // Appends to `out` (not cleared). `indent` < 0 writes compact text; >= 0 writes one member or
  // element per line, nested `indent` spaces per level, like nlohmann's dump(indent).
  explicit JsonStream(std::string& out, int indent = -1) : out_(out), indent_(indent) {}

  JsonStream& begin_object() { return open('{'); }
  JsonStream& end_object() { return close('}'); }
  JsonStream& begin_array() { return open('['); }
  JsonStream& end_array() { return close(']'); }

  // The next member's key; must be followed by exactly one value (or container).
  JsonStream& key(std::string_view name);
  // A key spelled in the source, the usual case: in compact text, written with copies whose size
  // the compiler knows (keys are a third of the work of a glTF's JSON).
  template <std::size_t N>
  JsonStream& key(const char (&name)[N]) {
    constexpr std::size_t kSize = N - 1;
    // Folded away for a literal; a char array that is not one (a NUL inside) is read up to it.
    if (indent_ >= 0 || !plain(name, kSize)) return key(std::string_view(name));
    std::array<char, kSize + 4> buffer;
    char* at = separator(buffer.data());
    *at++ = '"';
    std::memcpy(at, name, kSize);
    at += kSize;
    *at++ = '"';
    *at++ = ':';
    out_.append(buffer.data(), static_cast<std::size_t>(at - buffer.data()));
    after_key_ = true;
    return *this;
  }

  JsonStream& string(std::string_view text);
  // Non-finite values are written as null, as nlohmann does.
  JsonStream& number(double value);
  template <std::integral T>
  requires(!std::same_as<T, bool>) JsonStream& integer(T value) {
    append_integer(value);
    return *this;
  }
  JsonStream& boolean(bool value);
  JsonStream& null();
  // A shape::Value: bool, number (null when not finite), string, or null when unset.
  JsonStream& value(const shape::Value& value);
  // Text that is already one complete JSON value, written in this stream's layout (compact).
  JsonStream& raw(std::string_view json);

  // An object of `attributes` (sorted by name, as std::map keeps them). When `extra_name` is not
  // empty and not an attribute name, the member extra_name: extra_text (a string) is added in
  // its sorted place.
  JsonStream& attributes(const shape::AttributeMap& attributes, std::string_view extra_name = {},
                         std::string_view extra_text = {});

 private:
  JsonStream& open(char bracket);
  JsonStream& close(char bracket);
  void before_value();
  char* separator(char* at);
  // No character of `text` needs escaping (nor is a NUL).
  static constexpr bool plain(const char* text, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
      const auto c = static_cast<unsigned char>(text[i]);
      if (c < 0x20U || c == '"' || c == '\\' || c >= 0x80U) return false;
    }
    return true;
  }
  // Appends `text` quoted, then `after`, in one go when the text is compact and short and needs
  // no escaping; false (nothing written) otherwise.
  bool append_short(std::string_view text, std::string_view after);
  void newline(std::size_t depth);
  // The value with its separator before it.
  void append_integer(std::int64_t value);
  void append_integer(std::uint64_t value);
  template <std::integral T>
  void append_integer(T value) {
    if constexpr (std::is_signed_v<T>) {
      append_integer(static_cast<std::int64_t>(value));
    } else {
      append_integer(static_cast<std::uint64_t>(value));
    }
  }

  std::string& out_;
  int indent_;
  std::vector<std::uint32_t> counts_;  // values written so far in each open container
  bool after_key_ = false;
};

// `text` escaped as a JSON string body (no quotes), appended to `out`; see JsonStream.
void append_json_escaped(std::string& out, std::string_view text);

}  // namespace insula::io
