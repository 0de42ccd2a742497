#include "io/json_stream.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <variant>

#include <nlohmann/json.hpp>

namespace insula::io {
namespace {

// Length of the well-formed UTF-8 sequence starting at text[i] (Unicode 15, table 3-7: no
// overlong forms, no surrogates, nothing above U+10FFFF), or 0 when there is none.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0U;
  };
  const auto tail = [&](std::size_t k) { return (byte(k) & 0xC0U) == 0x80U; };
  const unsigned c = byte(0);
  if (c < 0x80U) return 1;
  if (c >= 0xC2U && c <= 0xDFU) return tail(1) ? 2 : 0;
  if (c >= 0xE0U && c <= 0xEFU) {
    const unsigned lo = c == 0xE0U ? 0xA0U : 0x80U;
    const unsigned hi = c == 0xEDU ? 0x9FU : 0xBFU;
    return byte(1) >= lo && byte(1) <= hi && tail(2) ? 3 : 0;
  }
  if (c >= 0xF0U && c <= 0xF4U) {
    const unsigned lo = c == 0xF0U ? 0x90U : 0x80U;
    const unsigned hi = c == 0xF4U ? 0x8FU : 0xBFU;
    return byte(1) >= lo && byte(1) <= hi && tail(2) && tail(3) ? 4 : 0;
  }
  return 0;
}

bool needs_escape(unsigned char c) {
  return c < 0x20U || c == '"' || c == '\\' || c >= 0x80U;
}

void append_escaped_char(std::string& out, unsigned char c) {
  switch (c) {
    case '"':
      out += "\\\"";
      return;
    case '\\':
      out += "\\\\";
      return;
    case '\b':
      out += "\\b";
      return;
    case '\f':
      out += "\\f";
      return;
    case '\n':
      out += "\\n";
      return;
    case '\r':
      out += "\\r";
      return;
    case '\t':
      out += "\\t";
      return;
    default:
      break;
  }
  static constexpr char kHex[] = "0123456789abcdef";
  const char escaped[6] = {'\\', 'u', '0', '0', kHex[c >> 4U], kHex[c & 0xFU]};
  out.append(escaped, 6);
}

}  // namespace

void append_json_escaped(std::string& out, std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    // Copy the longest run that needs no attention in one go (the common case: plain ASCII).
    std::size_t run = i;
    while (run < text.size() && !needs_escape(static_cast<unsigned char>(text[run]))) ++run;
    out.append(text.data() + i, run - i);
    i = run;
    if (i == text.size()) break;
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80U) {
      append_escaped_char(out, c);
      ++i;
    } else if (const std::size_t n = utf8_length(text, i); n > 0) {
      out.append(text.data() + i, n);
      i += n;
    } else {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER for one ill-formed byte
      ++i;
    }
  }
}

JsonStream& JsonStream::open(char bracket) {
  std::array<char, 2> buffer;
  char* at = separator(buffer.data());
  *at++ = bracket;
  out_.append(buffer.data(), at);
  counts_.push_back(0);
  return *this;
}

JsonStream& JsonStream::close(char bracket) {
  const bool empty = counts_.back() == 0;
  counts_.pop_back();
  if (!empty) newline(counts_.size());
  out_ += bracket;
  return *this;
}

void JsonStream::newline(std::size_t depth) {
  if (indent_ < 0) return;
  out_ += '\n';
  out_.append(depth * static_cast<std::size_t>(indent_), ' ');
}

// Separators before a value: none after a key; else a comma after the container's previous value
// and, when pretty, a new line at the container's depth.
void JsonStream::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (counts_.empty()) return;
  if (counts_.back()++ > 0) out_ += ',';
  newline(counts_.size());
}

// Compact text: the separator a value needs (a comma, or nothing) written at `at`, returning the
// end, so that the separator and the value go out in one append. Pretty text: before_value().
char* JsonStream::separator(char* at) {
  if (indent_ >= 0) {
    before_value();
  } else if (after_key_) {
    after_key_ = false;
  } else if (!counts_.empty() && counts_.back()++ > 0) {
    *at++ = ',';
  }
  return at;
}

// The common case of a key or a short string in compact text, separator, quotes and all in one
// append: most of what the exports write is short keys and names, where appending piece by
// piece cost more than the bytes.
bool JsonStream::append_short(std::string_view text, std::string_view after) {
  constexpr std::size_t kShort = 64;
  if (indent_ >= 0 || text.size() > kShort) return false;
  // The text is checked as it is copied in at 2; the quote goes at 1, and a comma at 0 if needed.
  std::array<char, kShort + 4> buffer;
  char* at = buffer.data() + 2;
  for (char c : text) {
    if (needs_escape(static_cast<unsigned char>(c))) return false;
    *at++ = c;
  }
  for (char c : after) *at++ = c;
  buffer[1] = '"';
  const char* start = separator(buffer.data()) == buffer.data() ? buffer.data() + 1 : buffer.data();
  out_.append(start, static_cast<std::size_t>(at - start));
  return true;
}

JsonStream& JsonStream::key(std::string_view name) {
  if (!append_short(name, "\":")) {
    before_value();
    out_ += '"';
    append_json_escaped(out_, name);
    out_ += indent_ < 0 ? "\":" : "\": ";
  }
  after_key_ = true;
  return *this;
}

JsonStream& JsonStream::string(std::string_view text) {
  if (append_short(text, "\"")) return *this;
  before_value();
  out_ += '"';
  append_json_escaped(out_, text);
  out_ += '"';
  return *this;
}

// nlohmann's own Grisu2 formatter, so numbers come out exactly as json::dump() prints them
// (std::to_chars would give the same value, but not always the same digits or layout: "3" vs
// "3.0", "1e-07" vs "1e-7").
// A whole number below 1e15 is printed by it as its digits and ".0" (checked against it on 66
// million values), which std::to_chars of the integer gives faster.
JsonStream& JsonStream::number(double value) {
  std::array<char, 64> buffer;
  char* at = separator(buffer.data());
  char* const end = buffer.data() + buffer.size();
  if (!std::isfinite(value)) {
    at = std::copy_n("null", 4, at);
  } else if (value != 0 && std::abs(value) < 1e15 && std::trunc(value) == value) {
    at = std::to_chars(at, end, static_cast<std::int64_t>(value)).ptr;
    at = std::copy_n(".0", 2, at);
  } else {
    at = nlohmann::detail::to_chars(at, end, value);
  }
  out_.append(buffer.data(), at);
  return *this;
}

void JsonStream::append_integer(std::int64_t value) {
  std::array<char, 24> buffer;
  char* at = separator(buffer.data());
  out_.append(buffer.data(), std::to_chars(at, buffer.data() + buffer.size(), value).ptr);
}

void JsonStream::append_integer(std::uint64_t value) {
  std::array<char, 24> buffer;
  char* at = separator(buffer.data());
  out_.append(buffer.data(), std::to_chars(at, buffer.data() + buffer.size(), value).ptr);
}

JsonStream& JsonStream::boolean(bool value) {
  before_value();
  out_ += value ? "true" : "false";
  return *this;
}

JsonStream& JsonStream::null() {
  before_value();
  out_ += "null";
  return *this;
}

JsonStream& JsonStream::value(const shape::Value& value) {
  if (const auto* b = std::get_if<bool>(&value)) return boolean(*b);
  if (const auto* d = std::get_if<double>(&value)) return number(*d);
  if (const auto* s = std::get_if<std::string>(&value)) return string(*s);
  return null();
}

JsonStream& JsonStream::raw(std::string_view json) {
  before_value();
  out_ += json;
  return *this;
}

JsonStream& JsonStream::attributes(const shape::AttributeMap& attributes,
                                   std::string_view extra_name, std::string_view extra_text) {
  bool extra_pending = !extra_name.empty() && !attributes.contains(extra_name);
  begin_object();
  for (const auto& [name, value] : attributes) {
    if (extra_pending && extra_name < std::string_view(name)) {
      key(extra_name).string(extra_text);
      extra_pending = false;
    }
    key(name).value(value);
  }
  if (extra_pending) key(extra_name).string(extra_text);
  return end_object();
}

}  // namespace insula::io
