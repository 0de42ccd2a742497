#include "lang/bldg/lexer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace insula::lang::bldg {

base::Span span_of(const base::Source& source, Range range) {
  const auto [line, column] = source.locate(range.begin);
  const auto [end_line, end_column] = source.locate(std::max(range.end, range.begin + 1));
  return base::Span{source.name(), line, column, end_line, end_column};
}

namespace {

bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_ident_char(char c) {
  return is_ident_start(c) || is_digit(c);
}

struct Operator {
  std::string_view spelling;
  Tok kind;
};
// Longest spelling first so `->` wins over `-`.
constexpr Operator kOperators[] = {
    {"->", Tok::kArrow}, {"(", Tok::kLParen},    {")", Tok::kRParen},   {"{", Tok::kLBrace},
    {"}", Tok::kRBrace}, {"[", Tok::kLBracket},  {"]", Tok::kRBracket}, {",", Tok::kComma},
    {":", Tok::kColon},  {";", Tok::kSemicolon}, {"-", Tok::kMinus},    {"=", Tok::kAssign},
    {".", Tok::kDot},
};

class Lexer {
 public:
  explicit Lexer(const base::Source& source) : source_(source), text_(source.text()) {}

  LexOutput run() {
    // A UTF-8 byte order mark, as some editors write, is not a token.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    while (true) {
      skip_trivia();
      if (pos_ >= text_.size()) break;
      lex_token();
    }
    push(Tok::kEnd, pos_, pos_, "");
    return std::move(out_);
  }

 private:
  char at(std::size_t i) const { return i < text_.size() ? text_[i] : '\0'; }

  void error(std::string code, std::string message, std::size_t begin, std::size_t end) {
    out_.diagnostics.push_back(base::Diagnostic::error(
        std::move(code), std::move(message),
        span_of(source_,
                Range{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)})));
  }

  Token& push(Tok kind, std::size_t begin, std::size_t end, std::string text) {
    Token token;
    token.kind = kind;
    token.range = Range{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
    token.text = std::move(text);
    token.line_start = line_start_;
    line_start_ = false;
    out_.tokens.push_back(std::move(token));
    return out_.tokens.back();
  }

  void skip_trivia() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        line_start_ = true;
        ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '#' || (c == '/' && at(pos_ + 1) == '/')) {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (c == '/' && at(pos_ + 1) == '*') {
        skip_block_comment();
      } else {
        return;
      }
    }
  }

  void skip_block_comment() {
    const std::size_t begin = pos_;
    const std::size_t close = text_.find("*/", pos_ + 2);
    const std::size_t stop = close == std::string_view::npos ? text_.size() : close + 2;
    if (std::find(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                  text_.begin() + static_cast<std::ptrdiff_t>(stop),
                  '\n') != text_.begin() + static_cast<std::ptrdiff_t>(stop)) {
      line_start_ = true;
    }
    pos_ = stop;
    if (close == std::string_view::npos) {
      error("BLD003", "unterminated block comment", begin, begin + 2);
    }
  }

  void lex_token() {
    const char c = text_[pos_];
    if (is_ident_start(c)) return lex_identifier();
    if (is_digit(c)) return lex_number();
    if (c == '"') return lex_string();
    for (const Operator& op : kOperators) {
      if (text_.substr(pos_, op.spelling.size()) == op.spelling) {
        push(op.kind, pos_, pos_ + op.spelling.size(), std::string(op.spelling));
        pos_ += op.spelling.size();
        return;
      }
    }
    lex_bad_character();
  }

  void lex_identifier() {
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && is_ident_char(text_[pos_])) ++pos_;
    push(Tok::kIdent, begin, pos_, std::string(text_.substr(begin, pos_ - begin)));
  }

  // digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ]; a letter glued to the number (`2x`)
  // is an error rather than two tokens.
  void lex_number() {
    const std::size_t begin = pos_;
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
    const std::size_t digits_end = pos_;
    if (is_ident_char(at(pos_))) {
      while (is_ident_char(at(pos_))) ++pos_;
      error("BLD004", "malformed number '" + std::string(text_.substr(begin, pos_ - begin)) + "'",
            begin, pos_);
    }
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text_.data() + begin, text_.data() + digits_end, value);
    if (ec != std::errc() || ptr != text_.data() + digits_end || !std::isfinite(value)) {
      error("BLD004",
            "number '" + std::string(text_.substr(begin, digits_end - begin)) + "' is out of range",
            begin, digits_end);
      value = 0.0;
    }
    Token& token = push(Tok::kNumber, begin, pos_, std::string(text_.substr(begin, pos_ - begin)));
    token.number = value;
  }

  void lex_string() {
    const std::size_t begin = pos_++;
    std::string value;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') {
      if (text_[pos_] == '\\') {
        value += escape(pos_);
        continue;
      }
      value += text_[pos_++];
    }
    if (at(pos_) != '"') {
      error("BLD002", "unterminated string", begin, begin + 1);
    } else {
      ++pos_;
    }
    push(Tok::kString, begin, pos_, std::move(value));
  }

  // Resolves the escape at `i` (which holds a backslash) and moves `i` past it.
  char escape(std::size_t& i) {
    const char c = at(i + 1);
    const std::size_t begin = i;
    i += (c == '\0' || c == '\n') ? 1 : 2;
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
        error("BLD005", "unknown escape sequence in string", begin, i);
        return c == '\n' ? '\\' : c;
    }
  }

  // Non-ASCII text outside strings and comments is reported as one code point (or one invalid
  // byte), so the caret points at a whole character.
  void lex_bad_character() {
    const std::size_t begin = pos_;
    const auto byte = static_cast<unsigned char>(text_[pos_]);
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
      std::snprintf(buffer, sizeof buffer, "unexpected character '%c'", text_[pos_]);
    } else {
      std::snprintf(buffer, sizeof buffer, "unexpected character '%.*s'", static_cast<int>(length),
                    text_.data() + pos_);
    }
    pos_ += length;
    error("BLD001", buffer, begin, pos_);
  }

  const base::Source& source_;
  std::string_view text_;
  std::size_t pos_ = 0;
  bool line_start_ = true;
  LexOutput out_;
};

}  // namespace

LexOutput lex(const base::Source& source) {
  return Lexer(source).run();
}

std::string token_name(Tok kind) {
  switch (kind) {
    case Tok::kEnd:
      return "end of file";
    case Tok::kIdent:
      return "identifier";
    case Tok::kNumber:
      return "number";
    case Tok::kString:
      return "string";
    default:
      break;
  }
  for (const Operator& op : kOperators) {
    if (op.kind == kind) {
      std::string out(1, '\'');
      out.append(op.spelling);
      out += '\'';
      return out;
    }
  }
  return "token";
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case Tok::kEnd:
      return "end of file";
    case Tok::kString:
      return "string \"" + token.text + "\"";
    case Tok::kIdent:
      return "identifier '" + token.text + "'";
    case Tok::kNumber:
      return "number " + token.text;
    default:
      return "'" + token.text + "'";
  }
}

}  // namespace insula::lang::bldg
