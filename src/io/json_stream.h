// A streaming JSON text writer for the big exports (glTF, CityJSON): values are appended to one
// std::string as they come (see below), with no document tree, so writing costs about as much as
// the bytes it produces. The text is byte for byte what nlohmann::json::dump() (compact) or
// dump(indent) (pretty) prints for the same document: doubles in nlohmann's shortest round-trip
// form ("3.0", "0.001", "1e-07", non-finite as null), strings escaped the same way (\" \\ \b \f \n
// \r \t, other control characters as \u00xx, UTF-8 kept as is), "{}" and "[]" for empty containers.
// The caller writes object keys in the order nlohmann would (sorted bytewise) when it wants the
// same bytes; the stream does not sort. Bytes that are not valid UTF-8 become U+FFFD.
#pragma once

#include <array>
#include <charconv>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shape/value.h"

namespace insula::io {

// The text gathers in a buffer inside the stream and reaches `out` in large appends: when the
// outermost value is complete, when the buffer fills, on flush() and at destruction. Appending
// token by token to the string cost more than forming the tokens.
class JsonStream {
 public:
  // Appends to `out` (not cleared). `indent` < 0 writes compact text; >= 0 writes one member or
  // element per line, nested `indent` spaces per level, like nlohmann's dump(indent).
  explicit JsonStream(std::string& out, int indent = -1) : out_(out), indent_(indent) {}
  ~JsonStream() { flush(); }
  JsonStream(const JsonStream&) = delete;
  JsonStream& operator=(const JsonStream&) = delete;

  JsonStream& begin_object() { return open('{'); }
  JsonStream& end_object() { return close('}'); }
  JsonStream& begin_array() { return open('['); }
  JsonStream& end_array() { return close(']'); }

  // The next member's key; must be followed by exactly one value (or container).
  JsonStream& key(std::string_view name);
  // A key spelled in the source, the usual case: written with a copy whose size the compiler
  // knows (keys are a third of the work of a glTF's JSON).
  template <std::size_t N>
  JsonStream& key(const char (&name)[N]) {
    constexpr std::size_t kSize = N - 1;
    // Folded away for a literal; a char array that is not one (a NUL inside) is read up to it.
    if (!plain(name, kSize)) return key(std::string_view(name));
    separate();
    char* at = room(kSize + 4);
    *at++ = '"';
    std::memcpy(at, name, kSize);
    at += kSize;
    *at++ = '"';
    *at++ = ':';
    if (indent_ >= 0) *at++ = ' ';
    commit(at);
    after_key_ = true;
    return *this;
  }

  JsonStream& string(std::string_view text);
  // Non-finite values are written as null, as nlohmann does.
  JsonStream& number(double value);
  template <std::integral T>
  requires(!std::same_as<T, bool>) JsonStream& integer(T value) {
    separate();
    char* at = room(24);
    commit(std::to_chars(at, at + 24, value).ptr);
    return end_value();
  }
  // An array of integers, written in one go in compact text (rings of vertex numbers, points).
  template <std::integral T>
  JsonStream& integers(std::span<const T> values) {
    if (indent_ >= 0) {
      begin_array();
      for (T value : values) integer(value);
      return end_array();
    }
    separate();
    put('[');
    for (std::size_t i = 0; i < values.size(); ++i) {
      char* at = room(25);
      if (i > 0) *at++ = ',';
      commit(std::to_chars(at, at + 24, values[i]).ptr);
    }
    put(']');
    return end_value();
  }
  JsonStream& boolean(bool value);
  JsonStream& null();
  // A shape::Value: bool, number (a whole one as an integer; null when not finite), string, or
  // null when unset.
  JsonStream& value(const shape::Value& value);
  // Text that is already one complete JSON value, written in this stream's layout (compact).
  JsonStream& raw(std::string_view json);
  // Compact text of one or more complete values separated by commas, written as the next elements
  // of the open array: a long array formatted by the caller a chunk at a time.
  JsonStream& elements(std::string_view json) { return raw(json); }

  // An object of `attributes` (sorted by name, as std::map keeps them). When `extra_name` is not
  // empty and not an attribute name, the member extra_name: extra_text (a string) is added in
  // its sorted place.
  JsonStream& attributes(const shape::AttributeMap& attributes, std::string_view extra_name = {},
                         std::string_view extra_text = {});

  // Appends the text written so far to `out`.
  void flush() {
    out_.append(pending_.data(), used_);
    used_ = 0;
  }

 private:
  static constexpr std::size_t kPending = 4096;

  // Inline, as the rest of the hot path: a call cost more than what these do.
  JsonStream& open(char bracket) {
    separate();
    put(bracket);
    counts_.push_back(0);
    return *this;
  }
  JsonStream& close(char bracket) {
    const bool empty = counts_.back() == 0;
    counts_.pop_back();
    if (!empty && indent_ >= 0) newline(counts_.size());
    put(bracket);
    return end_value();
  }
  // Separators before a value: none after a key; else a comma after the container's previous
  // value and, when pretty, a new line at the container's depth.
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (counts_.empty()) return;
    if (counts_.back()++ > 0) put(',');
    if (indent_ >= 0) newline(counts_.size());
  }
  // After a value: the outermost one is complete when no container is open.
  JsonStream& end_value() {
    if (counts_.empty()) flush();
    return *this;
  }
  // Room for `size` (at most kPending) more bytes at the end of the buffer, flushing it first
  // when they do not fit; commit() then marks where the written bytes end.
  char* room(std::size_t size) {
    if (kPending - used_ < size) flush();
    return pending_.data() + used_;
  }
  void commit(const char* end) { used_ = static_cast<std::size_t>(end - pending_.data()); }
  void put(char c) {
    *room(1) = c;
    ++used_;
  }
  void put(std::string_view text);
  void put_escaped(std::string_view text);
  // '"', `text` and '"' (and ':', and ' ' when pretty, after a key) when `text` is short and
  // needs no escaping; else false, writing nothing.
  bool put_plain(std::string_view text, bool is_key);
  void newline(std::size_t depth);
  // No character of `text` needs escaping (nor is a NUL).
  static constexpr bool plain(const char* text, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
      const auto c = static_cast<unsigned char>(text[i]);
      if (c < 0x20U || c == '"' || c == '\\' || c >= 0x80U) return false;
    }
    return true;
  }

  std::string& out_;
  int indent_;
  std::vector<std::uint32_t> counts_;  // values written so far in each open container
  bool after_key_ = false;
  std::array<char, kPending> pending_;
  std::size_t used_ = 0;
  // The last number Grisu2 formatted and its text: numbers often come again right away.
  std::uint64_t last_number_ = 0;
  std::array<char, 32> last_text_{};
  std::size_t last_size_ = 0;  // 0: none yet
};

// `text` escaped as a JSON string body (no quotes), appended to `out`; see JsonStream.
void append_json_escaped(std::string& out, std::string_view text);

}  // namespace insula::io
