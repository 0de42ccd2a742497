#include "base/scanner.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace insula::base {

Span span_of(const Source& source, std::size_t begin, std::size_t end) {
  const auto [line, column] = source.locate(begin);
  const auto [end_line, end_column] = source.locate(std::max(end, begin + 1));
  return Span{source.name_at(begin), line, column, end_line, end_column};
}

void Scanner::error(std::string_view code, std::string message, std::size_t begin,
                    std::size_t end) {
  diagnostics_.push_back(
      Diagnostic::error(std::string(code), std::move(message), span(begin, end)));
}

void Scanner::skip_bom() {
  if (pos_ == 0 && starts_with("\xEF\xBB\xBF")) pos_ = 3;
}

void Scanner::skip_trivia() {
  const std::string_view text = this->text();
  while (pos_ < text.size()) {
    const char c = text[pos_];
    if (c == '\n') {
      line_start_ = true;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '#' || (c == '/' && at(pos_ + 1) == '/')) {
      while (pos_ < text.size() && text[pos_] != '\n') ++pos_;
    } else if (c == '/' && at(pos_ + 1) == '*') {
      skip_block_comment();
    } else {
      return;
    }
  }
}

void Scanner::skip_block_comment() {
  const std::string_view text = this->text();
  const std::size_t begin = pos_;
  const std::size_t close = text.find("*/", pos_ + 2);
  const std::size_t stop = close == std::string_view::npos ? text.size() : close + 2;
  if (text.substr(pos_, stop - pos_).find('\n') != std::string_view::npos) line_start_ = true;
  pos_ = stop;
  if (close == std::string_view::npos) {
    error(codes_.unterminated_comment, "unterminated block comment", begin, begin + 2);
  }
}

std::string_view Scanner::scan_identifier() {
  const std::size_t begin = pos_;
  while (is_ident_char(at(pos_))) ++pos_;
  return slice(begin, pos_);
}

std::size_t Scanner::scan_digits() {
  while (is_digit(at(pos_))) ++pos_;
  if (at(pos_) == '.' && is_digit(at(pos_ + 1))) {
    ++pos_;
    while (is_digit(at(pos_))) ++pos_;
  }
  if ((at(pos_) == 'e' || at(pos_) == 'E') &&
      (is_digit(at(pos_ + 1)) ||
       ((at(pos_ + 1) == '+' || at(pos_ + 1) == '-') && is_digit(at(pos_ + 2))))) {
    pos_ += 2;
    while (is_digit(at(pos_))) ++pos_;
  }
  return pos_;
}

double Scanner::finish_number(std::size_t begin, std::size_t digits_end) {
  if (is_ident_char(at(pos_))) {
    while (is_ident_char(at(pos_))) ++pos_;
    error(codes_.bad_number, "malformed number '" + std::string(slice(begin, pos_)) + "'", begin,
          pos_);
  }
  const std::string_view text = this->text();
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data() + begin, text.data() + digits_end, value);
  if (ec != std::errc() || ptr != text.data() + digits_end || !std::isfinite(value)) {
    error(codes_.bad_number,
          "number '" + std::string(slice(begin, digits_end)) + "' is out of range", begin,
          digits_end);
    value = 0.0;
  }
  return value;
}

std::string Scanner::scan_string() {
  const std::size_t begin = pos_++;
  std::string value;
  while (!at_end() && at(pos_) != '"' && at(pos_) != '\n') {
    if (at(pos_) == '\\') {
      value += escape();
      continue;
    }
    value += at(pos_++);
  }
  if (at(pos_) != '"') {
    error(codes_.unterminated_string, "unterminated string", begin, begin + 1);
  } else {
    ++pos_;
  }
  return value;
}

// Resolves the escape at the cursor (which holds a backslash) and moves past it; a backslash at
// the end of a line or of the text stays a backslash.
char Scanner::escape() {
  const char c = at(pos_ + 1);
  const std::size_t begin = pos_;
  pos_ += (c == '\0' || c == '\n') ? 1 : 2;
  switch (c) {
    case '"':
      return '"';
    case '\\':
      return '\\';
    case 'n':
      return '\n';
    case 't':
      return '\t';
    default:
      error(codes_.bad_escape, "unknown escape sequence in string", begin, pos_);
      return c == '\n' ? '\\' : c;
  }
}

void Scanner::bad_character() {
  const std::size_t begin = pos_;
  const auto byte = static_cast<unsigned char>(at(pos_));
  std::size_t length = 1;
  if (byte >= 0xC2 && byte <= 0xF4) length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : 2;
  for (std::size_t k = 1; k < length; ++k) {
    const auto next = static_cast<unsigned char>(at(pos_ + k));
    if ((next & 0xC0) != 0x80) length = 1;
  }
  char buffer[48];
  if (byte < 0x20 || byte == 0x7F || (byte >= 0x80 && length == 1)) {
    std::snprintf(buffer, sizeof buffer, "unexpected byte 0x%02X", byte);
  } else if (length == 1) {
    std::snprintf(buffer, sizeof buffer, "unexpected character '%c'", at(pos_));
  } else {
    std::snprintf(buffer, sizeof buffer, "unexpected character '%.*s'", static_cast<int>(length),
                  text().data() + pos_);
  }
  pos_ += length;
  error(codes_.bad_character, buffer, begin, pos_);
}

}  // namespace insula::base
