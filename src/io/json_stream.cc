#include "io/json_stream.h"

#include <algorithm>
#include <array>
#include <bit>
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

// The escape sequence of an ASCII character that needs one.
std::string_view escaped_char(unsigned char c, std::array<char, 6>& buffer) {
  switch (c) {
    case '"':
      return "\\\"";
    case '\\':
      return "\\\\";
    case '\b':
      return "\\b";
    case '\f':
      return "\\f";
    case '\n':
      return "\\n";
    case '\r':
      return "\\r";
    case '\t':
      return "\\t";
    default:
      break;
  }
  static constexpr char kHex[] = "0123456789abcdef";
  buffer = {'\\', 'u', '0', '0', kHex[c >> 4U], kHex[c & 0xFU]};
  return {buffer.data(), buffer.size()};
}

// `text` escaped, handed to `append` piece by piece: runs that need no attention whole (the
// common case: plain ASCII), escape sequences, well-formed UTF-8 sequences, U+FFFD for a byte
// that begins none.
template <typename Append>
void escape(std::string_view text, Append&& append) {
  std::size_t i = 0;
  std::array<char, 6> buffer{};
  while (i < text.size()) {
    std::size_t run = i;
    while (run < text.size() && !needs_escape(static_cast<unsigned char>(text[run]))) ++run;
    if (run > i) append(text.substr(i, run - i));
    i = run;
    if (i == text.size()) break;
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80U) {
      append(escaped_char(c, buffer));
      ++i;
    } else if (const std::size_t n = utf8_length(text, i); n > 0) {
      append(text.substr(i, n));
      i += n;
    } else {
      append("\xEF\xBF\xBD");  // U+FFFD REPLACEMENT CHARACTER for one ill-formed byte
      ++i;
    }
  }
}

// `n` <= 32 bytes copied in two overlapping moves of a fixed size: the library call a copy of
// unknown size becomes cost more than the rest of writing a key or a short string.
void copy_short(char* to, const char* from, std::size_t n) {
  const auto two_moves = [&]<std::size_t kSize>() {
    std::array<char, kSize> head;
    std::array<char, kSize> tail;
    std::memcpy(head.data(), from, kSize);
    std::memcpy(tail.data(), from + n - kSize, kSize);
    std::memcpy(to, head.data(), kSize);
    std::memcpy(to + n - kSize, tail.data(), kSize);
  };
  if (n >= 16) {
    two_moves.template operator()<16>();
  } else if (n >= 8) {
    two_moves.template operator()<8>();
  } else if (n >= 4) {
    two_moves.template operator()<4>();
  } else if (n > 0) {
    to[0] = from[0];
    to[n / 2] = from[n / 2];
    to[n - 1] = from[n - 1];
  }
}

}  // namespace

void append_json_escaped(std::string& out, std::string_view text) {
  escape(text, [&out](std::string_view piece) { out += piece; });
}

void JsonStream::put(std::string_view text) {
  if (text.size() > kPending - used_) {
    flush();
    if (text.size() > kPending) {
      out_ += text;
      return;
    }
  }
  std::memcpy(pending_.data() + used_, text.data(), text.size());
  used_ += text.size();
}

void JsonStream::put_escaped(std::string_view text) {
  escape(text, [this](std::string_view piece) { put(piece); });
}

// Pretty text only.
void JsonStream::newline(std::size_t depth) {
  put('\n');
  for (std::size_t spaces = depth * static_cast<std::size_t>(indent_); spaces > 0;) {
    const std::size_t n = std::min<std::size_t>(spaces, 64);
    char* at = room(n);
    std::memset(at, ' ', n);
    commit(at + n);
    spaces -= n;
  }
}

// Most keys and strings (ids, types, names) are short and need no escaping: checked first, they
// are copied whole rather than run by run.
bool JsonStream::put_plain(std::string_view text, bool is_key) {
  constexpr std::size_t kShort = 32;
  if (text.size() > kShort || !plain(text.data(), text.size())) return false;
  char* at = room(kShort + 4);
  *at++ = '"';
  copy_short(at, text.data(), text.size());
  at += text.size();
  *at++ = '"';
  if (is_key) {
    *at++ = ':';
    if (indent_ >= 0) *at++ = ' ';
  }
  commit(at);
  return true;
}

JsonStream& JsonStream::key(std::string_view name) {
  separate();
  if (!put_plain(name, true)) {
    put('"');
    put_escaped(name);
    put(indent_ < 0 ? "\":" : "\": ");
  }
  after_key_ = true;
  return *this;
}

JsonStream& JsonStream::string(std::string_view text) {
  separate();
  if (!put_plain(text, false)) {
    put('"');
    put_escaped(text);
    put('"');
  }
  return end_value();
}

// nlohmann's own Grisu2 formatter, so numbers come out exactly as json::dump() prints them
// (std::to_chars would give the same value, but not always the same digits or layout: "3" vs
// "3.0", "1e-07" vs "1e-7"). A whole number below 1e15 is printed by it as its digits and ".0"
// (checked against it on 66 million values), which std::to_chars of the integer gives faster.
JsonStream& JsonStream::number(double value) {
  separate();
  constexpr std::size_t kLongest = 32;
  char* at = room(kLongest);
  char* const end = at + kLongest;
  if (!std::isfinite(value)) {
    at = std::copy_n("null", 4, at);
  } else if (value != 0 && std::abs(value) < 1e15 && std::trunc(value) == value) {
    at = std::to_chars(at, end, static_cast<std::int64_t>(value)).ptr;
    at = std::copy_n(".0", 2, at);
  } else if (last_size_ > 0 && std::bit_cast<std::uint64_t>(value) == last_number_) {
    at = std::copy_n(last_text_.data(), last_size_, at);  // the same again (a scale's s, s, s)
  } else {
    char* const begin = at;
    at = nlohmann::detail::to_chars(at, end, value);
    last_number_ = std::bit_cast<std::uint64_t>(value);
    last_size_ = static_cast<std::size_t>(at - begin);
    std::copy(begin, at, last_text_.data());
  }
  commit(at);
  return end_value();
}

JsonStream& JsonStream::boolean(bool value) {
  separate();
  put(value ? "true" : "false");
  return end_value();
}

JsonStream& JsonStream::null() {
  separate();
  put("null");
  return end_value();
}

// An attribute's whole number is written as an integer (`1810`, not `1810.0`), as JavaScript's
// JSON.stringify writes it: the values keep one number type (shape::Value), and a year, a level
// count or an OSM id read back as integers in Python, CityJSON tools and databases.
JsonStream& JsonStream::value(const shape::Value& value) {
  if (const auto* b = std::get_if<bool>(&value)) return boolean(*b);
  if (const auto* d = std::get_if<double>(&value)) {
    constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
    if (std::abs(*d) >= kExactIntegers || std::trunc(*d) != *d) return number(*d);
    return integer(static_cast<std::int64_t>(*d));
  }
  if (const auto* s = std::get_if<std::string>(&value)) return string(*s);
  return null();
}

JsonStream& JsonStream::raw(std::string_view json) {
  separate();
  put(json);
  return end_value();
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
