#include "lang/graph/json.h"

#include <nlohmann/json.hpp>

#include <iterator>

namespace insula::lang::graph {

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const JsonMember& m : members) {
    if (m.key == key) return &m.value;
  }
  return nullptr;
}

std::string_view kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::kNull:
      return "null";
    case JsonValue::Kind::kBool:
      return "a boolean";
    case JsonValue::Kind::kInteger:
    case JsonValue::Kind::kNumber:
      return "a number";
    case JsonValue::Kind::kString:
      return "a string";
    case JsonValue::Kind::kArray:
      return "an array";
    case JsonValue::Kind::kObject:
      return "an object";
  }
  return "a value";
}

namespace {

// An input iterator over the text that publishes how many bytes the parser has taken.
struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* at = nullptr;
  const char* base = nullptr;
  std::size_t* consumed = nullptr;

  reference operator*() const { return *at; }
  CountingIterator& operator++() {
    ++at;
    *consumed = static_cast<std::size_t>(at - base);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at == other.at; }
  bool operator!=(const CountingIterator& other) const { return at != other.at; }
};

bool number_byte(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// Builds the tree from SAX events. Events arrive when a token has been read: `consumed` is then
// just past it (past one more byte for numbers, whose end the lexer finds by reading beyond it).
class Builder {
 public:
  Builder(std::string_view text, const std::size_t* consumed) : text_(text), consumed_(consumed) {}

  bool null() { return add(JsonValue::Kind::kNull, *consumed_ - 4); }
  bool boolean(bool value) {
    if (!add(JsonValue::Kind::kBool, *consumed_ - (value ? 4 : 5))) return false;
    last_->boolean = value;
    return true;
  }
  bool number_integer(std::int64_t value) {
    if (!add(JsonValue::Kind::kInteger, number_start())) return false;
    last_->integer = value;
    last_->number = static_cast<double>(value);
    return true;
  }
  bool number_unsigned(std::uint64_t value) {
    const bool fits = value <= static_cast<std::uint64_t>(INT64_MAX);
    if (!add(fits ? JsonValue::Kind::kInteger : JsonValue::Kind::kNumber, number_start())) {
      return false;
    }
    if (fits) last_->integer = static_cast<std::int64_t>(value);
    last_->number = static_cast<double>(value);
    return true;
  }
  bool number_float(double value, const std::string&) {
    if (!add(JsonValue::Kind::kNumber, number_start())) return false;
    last_->number = value;
    return true;
  }
  bool string(std::string& value) {
    if (!add(JsonValue::Kind::kString, string_start())) return false;
    last_->text = std::move(value);
    return true;
  }
  bool binary(std::vector<std::uint8_t>&) { return false; }
  bool start_object(std::size_t) { return open(JsonValue::Kind::kObject); }
  bool key(std::string& key) {
    JsonValue& object = *stack_.back();
    object.members.push_back(JsonMember{std::move(key), string_start(), {}});
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(JsonValue::Kind::kArray); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    error_offset_ = position > 0 ? position - 1 : 0;
    std::string what = e.what();
    // "[json.exception.parse_error.101] parse error at line 1, column 2: <reason>"
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    error_ = colon == std::string::npos ? what : what.substr(colon + 2);
    return false;
  }

  JsonValue& root() { return root_; }
  const std::string& error() const { return error_; }
  std::size_t error_offset() const { return error_offset_; }

 private:
  std::size_t number_start() const {
    std::size_t end = std::min(*consumed_, text_.size());
    if (end > 0 && !number_byte(text_[end - 1])) --end;
    while (end > 0 && number_byte(text_[end - 1])) --end;
    return end;
  }
  // The opening quote of the string that ends just before `consumed`: the nearest quote before
  // the closing one that no odd run of backslashes escapes.
  std::size_t string_start() const {
    std::size_t i = *consumed_ - 1;  // the closing quote
    while (i > 0) {
      --i;
      if (text_[i] != '"') continue;
      std::size_t slashes = 0;
      while (i > slashes && text_[i - 1 - slashes] == '\\') ++slashes;
      if (slashes % 2 == 0) return i;
    }
    return 0;
  }
  JsonValue* slot() {
    if (stack_.empty()) {
      if (rooted_) return nullptr;
      rooted_ = true;
      return &root_;
    }
    JsonValue& parent = *stack_.back();
    if (parent.kind == JsonValue::Kind::kArray) {
      parent.items.emplace_back();
      return &parent.items.back();
    }
    return &parent.members.back().value;
  }
  bool add(JsonValue::Kind kind, std::size_t offset) {
    last_ = slot();
    if (last_ == nullptr) return false;
    last_->kind = kind;
    last_->offset = offset;
    return true;
  }
  bool open(JsonValue::Kind kind) {
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
      error_offset_ = *consumed_ - 1;
      error_ = "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels";
      return false;
    }
    if (!add(kind, *consumed_ - 1)) return false;
    stack_.push_back(last_);
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  std::string_view text_;
  const std::size_t* consumed_;
  JsonValue root_;
  bool rooted_ = false;
  JsonValue* last_ = nullptr;
  std::vector<JsonValue*> stack_;
  std::string error_;
  std::size_t error_offset_ = 0;
};

}  // namespace

base::Result<JsonValue> parse_json(const base::Source& source) {
  const std::string& text = source.text();
  std::size_t consumed = 0;
  Builder builder(text, &consumed);
  const CountingIterator first{text.data(), text.data(), &consumed};
  const CountingIterator last{text.data() + text.size(), text.data(), &consumed};
  const bool ok = nlohmann::json::sax_parse(first, last, &builder);
  if (!ok) {
    const auto [line, column] = source.locate(builder.error_offset());
    std::string reason = builder.error().empty() ? "unexpected input" : builder.error();
    return base::Result<JsonValue>::failure({base::Diagnostic::error(
        "G001", "invalid JSON: " + reason, base::Span::at(source.name(), line, column))});
  }
  return std::move(builder.root());
}

std::size_t string_byte_offset(const base::Source& source, const JsonValue& value,
                               std::size_t index) {
  const std::string& text = source.text();
  std::size_t at = value.offset + 1;  // past the opening quote
  std::size_t decoded = 0;
  while (at < text.size() && text[at] != '"' && decoded < index) {
    if (text[at] != '\\') {
      ++at;
      ++decoded;
      continue;
    }
    if (at + 1 < text.size() && text[at + 1] == 'u') {
      // \uXXXX: one code point of 1 to 3 UTF-8 bytes, or 4 with its low surrogate.
      unsigned code = 0;
      for (std::size_t k = at + 2; k < at + 6 && k < text.size(); ++k) {
        const char c = text[k];
        code = code * 16 + static_cast<unsigned>(c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10);
      }
      if (code >= 0xD800 && code <= 0xDBFF) {
        at += 12;
        decoded += 4;
      } else {
        at += 6;
        decoded += code < 0x80 ? 1 : code < 0x800 ? 2 : 3;
      }
    } else {
      at += 2;
      ++decoded;
    }
  }
  return at;
}

}  // namespace insula::lang::graph
