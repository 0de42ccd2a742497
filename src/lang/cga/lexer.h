// Tokens of the CGA language (seed 004, §VI). The lexer never fails as a whole: a bad character
// becomes a diagnostic and is skipped, so the parser still sees the rest of the file.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

enum class Tok {
  kEnd,
  kIdent,
  kNumber,   // number; relative = true for `2r`
  kString,   // text holds the value with escapes resolved
  kEpsilon,  // `ε`, `epsilon` or `NIL`
  kPriority,
  kAttr,
  kTrue,
  kFalse,
  kAnd,         // `&&` or `and`
  kOr,          // `||` or `or`
  kNot,         // `!` or `not`
  kArrow,       // ->
  kLongArrow,   // -->
  kTildeArrow,  // ~>
  kColon,
  kSemicolon,
  kComma,
  kBar,
  kLBrace,
  kRBrace,
  kLBracket,
  kRBracket,
  kLParen,
  kRParen,
  kDot,
  kPlus,
  kMinus,
  kStar,
  kSlash,
  kPercent,
  kTilde,
  kQuote,  // ' (CityEngine's relative-size prefix)
  kAssign,
  kEq,
  kNe,  // `!=` or `<>`
  kLt,
  kLe,
  kGt,
  kGe,
  kAt,           // @ (CityEngine's annotations)
  kElementwise,  // CityEngine's element-wise operators on arrays: `.==`, `.+`, ...; text as written
  kCaret,        // ^ (only in CityEngine's annotations: `@Handle(shape=Name^2)`)
};

struct Token {
  Tok kind = Tok::kEnd;
  Range range;
  std::string text;  // identifier name, string value, or the spelling of other tokens
  double number = 0.0;
  bool relative = false;    // number written with the `r` suffix
  bool line_start = false;  // first token on its line (used for error recovery)
};

struct LexOutput {
  std::vector<Token> tokens;  // always ends with one kEnd token
  std::vector<base::Diagnostic> diagnostics;
};

// Splits `source` into tokens. Comments (`//`, `/* */`, `#`) and whitespace are skipped.
LexOutput lex(const base::Source& source);

// A short human name for a token kind, used in messages ("'~>'", "identifier").
std::string token_name(Tok kind);

// The token as shown in "found ..." messages: its spelling, or "end of file".
std::string describe(const Token& token);

}  // namespace insula::lang::cga
