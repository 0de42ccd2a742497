#include "io/json_text.h"

#include <array>
#include <nlohmann/json.hpp>

namespace insula::io::json_text {
namespace {

using nlohmann::json;

// Offset and message of the first syntax error, found by a validating SAX pass (no exceptions).
class ErrorCatcher : public nlohmann::json_sax<json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& e) override {
    // `position` counts the bytes read: the last one read is where the error shows. A number
    // overflow is reported after the whole token, so point at its start instead.
    offset = position > 0 ? position - 1 : 0;
    if (e.id == 406 && position >= last_token.size()) offset = position - last_token.size();
    // Escape bytes outside printable ASCII: the message may quote the invalid UTF-8 it rejects.
    for (const char c : std::string_view(e.what())) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte >= 0x20 && byte < 0x7F) {
        message += c;
      } else {
        constexpr char kHex[] = "0123456789abcdef";
        message += "\\x";
        message += kHex[byte >> 4];
        message += kHex[byte & 15];
      }
    }
    if (message.rfind("[json.exception.", 0) == 0) message.erase(0, message.find("] ") + 2);
    if (message.rfind("parse error at line", 0) == 0) message.erase(0, message.find(": ") + 2);
    return false;
  }

  std::size_t offset = 0;
  std::string message;
};

}  // namespace

std::size_t skip_string(std::string_view text, std::size_t pos) {
  for (++pos; pos < text.size(); ++pos) {
    if (text[pos] == '\\') {
      ++pos;
    } else if (text[pos] == '"') {
      return pos + 1;
    }
  }
  return text.size();
}

Layout scan_layout(std::string_view text, std::size_t root, std::size_t max_depth) {
  Layout out;
  const bool object_root = root < text.size() && text[root] == '{';
  std::size_t depth = 0;
  std::string_view last_key;    // the last string at depth 1
  bool features_value = false;  // the next value is the root's "features" member
  bool in_features = false;     // inside that array
  const auto element_at = [&](std::size_t pos) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos < text.size() && text[pos] != ']') out.elements.push_back(pos);
  };
  // Bytes that matter here; the rest (digits, letters, whitespace) are skipped a run at a time.
  static constexpr auto kStructural = [] {
    std::array<bool, 256> table{};
    for (const char c : std::string_view("\"[]{}:,")) table[static_cast<unsigned char>(c)] = true;
    return table;
  }();
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!kStructural[static_cast<unsigned char>(text[i])]) {
      if (!features_value) {
        while (i + 1 < text.size() && !kStructural[static_cast<unsigned char>(text[i + 1])]) ++i;
        continue;
      }
      if (is_space(text[i])) continue;
    }
    const char c = text[i];
    const bool value_start = features_value && c != ':';
    if (value_start) features_value = false;
    if (c == '"') {
      const std::size_t end = skip_string(text, i);
      if (depth == 1) last_key = text.substr(i + 1, end - i - 2);
      i = end - 1;
    } else if (c == ':') {
      if (depth == 1 && object_root && last_key == "features") {
        features_value = true;  // the last "features" member counts, as in nlohmann
        out.features_at = out.features_end = kNoOffset;
        out.elements.clear();
      }
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) {
        out.too_deep = i;
        return out;
      }
      if (value_start && c == '[' && depth == 2) {
        in_features = true;
        out.features_at = i;
        element_at(i + 1);
      }
    } else if (c == ']' || c == '}') {
      if (depth == 2 && in_features) {
        in_features = false;
        if (c == ']') out.features_end = i + 1;  // '}' would leave the array unparsed
      }
      if (depth > 0) --depth;
    } else if (c == ',' && depth == 2 && in_features) {
      element_at(i + 1);
    }
  }
  if (out.features_end == kNoOffset) out.features_at = kNoOffset;
  return out;
}

std::size_t TextLocator::skip_space(std::size_t pos) const {
  if (pos == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
  while (pos < text_.size() && is_space(text_[pos])) ++pos;
  return pos;
}

std::size_t TextLocator::skip_value(std::size_t pos) const {
  if (pos >= text_.size()) return text_.size();
  if (text_[pos] == '"') return skip_string(text_, pos);
  if (text_[pos] != '[' && text_[pos] != '{') {
    while (pos < text_.size() && !is_space(text_[pos]) && text_[pos] != ',' && text_[pos] != ']' &&
           text_[pos] != '}') {
      ++pos;
    }
    return pos;
  }
  std::size_t depth = 0;
  for (; pos < text_.size(); ++pos) {
    const char c = text_[pos];
    if (c == '"') {
      pos = skip_string(text_, pos) - 1;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if ((c == ']' || c == '}') && --depth == 0) {
      return pos + 1;
    }
  }
  return text_.size();
}

std::size_t TextLocator::member(std::size_t pos, std::string_view key) const {
  if (pos >= text_.size() || text_[pos] != '{') return kNoOffset;
  std::size_t found = kNoOffset;
  pos = skip_space(pos + 1);
  while (pos < text_.size() && text_[pos] == '"') {
    const std::size_t key_end = skip_string(text_, pos);
    const std::string_view name = text_.substr(pos + 1, key_end - pos - 2);
    pos = skip_space(key_end);
    if (pos >= text_.size() || text_[pos] != ':') break;
    pos = skip_space(pos + 1);
    if (name == key) found = pos;
    pos = skip_space(skip_value(pos));
    if (pos >= text_.size() || text_[pos] != ',') break;
    pos = skip_space(pos + 1);
  }
  return found;
}

std::size_t TextLocator::element(std::size_t pos, std::size_t index) const {
  if (pos >= text_.size() || text_[pos] != '[') return kNoOffset;
  pos = skip_space(pos + 1);
  for (std::size_t i = 0; pos < text_.size() && text_[pos] != ']'; ++i) {
    if (i == index) return pos;
    pos = skip_space(skip_value(pos));
    if (pos >= text_.size() || text_[pos] != ',') break;
    pos = skip_space(pos + 1);
  }
  return kNoOffset;
}

std::size_t TextLocator::follow(std::size_t pos, const std::vector<PathStep>& path) const {
  for (const PathStep& step : path) {
    const std::size_t next = step.key.empty() ? element(pos, step.index) : member(pos, step.key);
    if (next == kNoOffset) break;
    pos = next;
  }
  return pos;
}

SyntaxError first_syntax_error(std::string_view text) {
  ErrorCatcher catcher;
  json::sax_parse(text.data(), text.data() + text.size(), &catcher);
  return {catcher.offset, std::move(catcher.message)};
}

}  // namespace insula::io::json_text
