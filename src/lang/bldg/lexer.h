// Tokens of the building grammar (.bldg) and of restriction rules (.rules), seed 000 §3.1 and
// §3.3; docs/bldg-language.md. The lexer never fails as a whole: a bad character becomes a
// diagnostic and is skipped, so the parser still sees the rest of the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/diagnostic.h"

namespace insula::lang::bldg {

// Byte offsets [begin, end) into the source text.
struct Range {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

enum class Tok {
  kEnd,
  kIdent,
  kNumber,
  kString,  // text holds the value with escapes resolved
  kArrow,   // ->
  kLParen,
  kRParen,
  kLBrace,
  kRBrace,
  kLBracket,
  kRBracket,
  kComma,
  kColon,
  kSemicolon,
  kMinus,
  kAssign,
  kDot,
};

struct Token {
  Tok kind = Tok::kEnd;
  Range range;
  std::string text;  // identifier name, string value, or the spelling of other tokens
  double number = 0.0;
  bool line_start = false;  // first token on its line (used for error recovery)
};

struct LexOutput {
  std::vector<Token> tokens;  // always ends with one kEnd token
  std::vector<base::Diagnostic> diagnostics;
};

// Splits `source` into tokens; comments (`#`, `//`, `/* */`) and whitespace are skipped.
LexOutput lex(const base::Source& source);

// "'->'", "identifier", ...: a token kind in messages.
std::string token_name(Tok kind);
// The token as shown in "found ..." messages: its spelling, or "end of file".
std::string describe(const Token& token);
// The span of a byte range (at least one byte wide).
base::Span span_of(const base::Source& source, Range range);

}  // namespace insula::lang::bldg
