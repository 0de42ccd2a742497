// Parser and rules' moderator of the building grammar (seed 000, §3.1 and §3.3). The grammar
// (EBNF) is at the top of parser.cc and in docs/bldg-language.md; the moderator's checks are in
// moderator.cc.
#pragma once

#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/vec.h"
#include "lang/bldg/lexer.h"
#include "lang/bldg/model.h"

namespace insula::lang::bldg {

// Deepest nesting of calls inside parameters; deeper input gets BLD105, not a stack overflow.
inline constexpr int kMaxNesting = 32;
// After this many errors the parser (and the moderator) stop with BLD108.
inline constexpr int kMaxErrors = 50;

// ---- syntax tree: what the text says, before the moderator gives it meaning ----

struct Value {
  enum class Kind { kNumber, kString, kIdent, kPoint, kRing, kCall };
  Kind kind = Kind::kNumber;
  Range range;
  double number = 0;               // kNumber (sign applied)
  std::string text;                // kString value, kIdent or kCall name
  std::vector<kernel::Vec2> ring;  // kPoint (one point) or kRing
  std::vector<Value> args;         // kCall
};

struct SymbolRef {
  std::string name;
  Range range;
};

struct RuleSyntax {
  SymbolRef symbol;
  SymbolRef function;
  std::vector<Value> args;
  Range args_range;  // from '(' to ')'
  bool has_set = false;
  Range set_range;  // from '{' to '}'
  std::vector<SymbolRef> set;
  Range range;
};

struct SyntaxOutput {
  std::vector<RuleSyntax> rules;
  std::vector<base::Diagnostic> diagnostics;  // lexical and syntax errors
};

// The rules of a .bldg file as written. Never throws; after a syntax error skips to the next
// rule (a line starting with `symbol ->`, or past a `;`).
SyntaxOutput parse_rules(const base::Source& source);

// ---- the checked model ----

// Parses and moderates a whole .bldg file: on success the Building with warnings only (e.g.
// BLD240); otherwise a failure holding every error found, sorted by position, each
// `file:line:col` at the offending token. Never throws, never prints; any byte sequence is
// accepted as input. The outline of a `geojson(...)` building is left empty (outline_file and
// outline_feature are set): the caller reads the file.
base::Result<Building> parse_building(const base::Source& source);

}  // namespace insula::lang::bldg
