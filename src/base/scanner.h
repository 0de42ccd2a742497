// The character level shared by the front-end lexers (lang/cga/lexer.cc, lang/bldg/lexer.cc): a
// cursor over the source text that skips whitespace and comments (`#`, `//`, `/* */`), scans
// identifiers, numbers and double-quoted strings, and reports lexical errors as diagnostics with
// the front-end's own codes. Each lexer keeps its token set, keywords and operators; the scanner
// never fails as a whole, so the parser still sees the rest of the file after a bad character.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"

namespace insula::base {

inline bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
inline bool is_ident_char(char c) {
  return is_ident_start(c) || is_digit(c);
}

// The span of the bytes [begin, end) of `source`, at least one byte wide.
Span span_of(const Source& source, std::size_t begin, std::size_t end);

// The diagnostic codes a front-end gives to the scanner's errors (e.g. CGA001..CGA005).
struct ScanCodes {
  std::string_view bad_character;         // a byte or code point no token starts with
  std::string_view unterminated_string;   // `"` without its closing `"` on the same line
  std::string_view unterminated_comment;  // `/*` without `*/`
  std::string_view bad_number;            // `2x`, or a number out of double range
  std::string_view bad_escape;            // a backslash not followed by `"`, `\`, `n` or `t`
};

class Scanner {
 public:
  Scanner(const Source& source, ScanCodes codes) : source_(source), codes_(codes) {}

  std::string_view text() const { return source_.text(); }
  std::size_t pos() const { return pos_; }
  bool at_end() const { return pos_ >= text().size(); }
  // The byte at `i`, or '\0' past the end.
  char at(std::size_t i) const { return i < text().size() ? text()[i] : '\0'; }
  char peek() const { return at(pos_); }
  bool starts_with(std::string_view spelling) const {
    return text().substr(pos_, spelling.size()) == spelling;
  }
  void advance(std::size_t n) { pos_ += n; }
  std::string_view slice(std::size_t begin, std::size_t end) const {
    return text().substr(begin, end - begin);
  }

  // True once for the first token of each line (and of the file): the parsers resynchronise on
  // line starts after an error. Reading it clears it until the next newline.
  bool take_line_start() {
    const bool was = line_start_;
    line_start_ = false;
    return was;
  }

  // Skips a UTF-8 byte order mark at the very start, as some editors write.
  void skip_bom();
  // Skips whitespace and comments; an unterminated block comment is reported and ends the text.
  void skip_trivia();
  // At an identifier start: moves past [A-Za-z_][A-Za-z0-9_]* and returns it.
  std::string_view scan_identifier();
  // At a digit: moves past digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ] and returns the
  // end of those digits. A front-end may then take a suffix of its own (CGA's `r`) before calling
  // finish_number.
  std::size_t scan_digits();
  // Ends the number starting at `begin` whose digits end at `digits_end`: letters glued to it
  // (`2x`) are an error rather than a second token; returns the value of the digits, 0 when out
  // of range (reported).
  double finish_number(std::size_t begin, std::size_t digits_end);
  // At `"`: moves past the string literal and returns its value with escapes resolved. A string
  // ends at the end of its line; a missing `"` is reported.
  std::string scan_string();
  // Reports the character at the cursor (one whole UTF-8 code point, or one invalid byte, so the
  // caret points at a whole character) and moves past it.
  void bad_character();

  Span span(std::size_t begin, std::size_t end) const { return span_of(source_, begin, end); }
  void error(std::string_view code, std::string message, std::size_t begin, std::size_t end);

  std::vector<Diagnostic> take_diagnostics() { return std::move(diagnostics_); }

 private:
  void skip_block_comment();
  char escape();

  const Source& source_;
  ScanCodes codes_;
  std::size_t pos_ = 0;
  bool line_start_ = true;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace insula::base
