// Tokens of PLaSM (seed 002; docs/plasm-language.md, "Lexical syntax"). The lexer never fails as
// a whole: a bad character becomes a diagnostic and is skipped, so the parser sees the rest.
#pragma once

#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"

namespace insula::lang::plasm {

enum class Tok {
  kEnd,
  kIdent,   // text as written, key case-folded
  kNumber,  // number
  kString,  // text holds the value with escapes resolved
  kDef,
  kWhere,
  kEndKw,  // END
  kIf,
  kColon,      // :
  kTypeSep,    // ::
  kTilde,      // ~
  kLBracket,   // [
  kRBracket,   // ]
  kLt,         // <  (opens a sequence)
  kGt,         // >  (closes a sequence)
  kDotDot,     // ..
  kPlus,       // +
  kMinus,      // -
  kStar,       // *
  kSlash,      // /
  kPower,      // **
  kHash,       // #
  kHashHash,   // ##
  kComma,      // ,
  kSemicolon,  // ;
  kAssign,     // =
  kLParen,     // (
  kRParen,     // )
};

struct Token {
  Tok kind = Tok::kEnd;
  Range range;
  std::string text;  // identifier as written, string value, or the spelling of other tokens
  std::string key;   // kIdent: the case-folded name
  double number = 0.0;
};

struct LexOutput {
  std::vector<Token> tokens;  // always ends with one kEnd token
  std::vector<base::Diagnostic> diagnostics;
};

// Splits `source` into tokens; whitespace and `% ... %` comments are skipped.
LexOutput lex(const base::Source& source);

// A short name for a token kind in messages ("':'", "identifier", "'END'").
std::string token_name(Tok kind);

// The token as shown in "found ..." messages.
std::string describe(const Token& token);

}  // namespace insula::lang::plasm
