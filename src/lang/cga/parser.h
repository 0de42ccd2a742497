// Parser of the CGA shape grammar language: the concrete syntax of seed 004 §VI plus the
// CityEngine-style extensions of issue 4. The grammar (EBNF) is at the top of parser.cc and in
// docs/cga-language.md.
#pragma once

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// Deepest nesting of blocks, patterns and parenthesised or unary expressions the parser accepts;
// deeper input gets error CGA105 instead of exhausting the stack.
inline constexpr int kMaxNesting = 100;
// After this many errors the parser stops with CGA108.
inline constexpr int kMaxErrors = 50;

// Parses a whole `.cga` file. On success the grammar comes with no error diagnostics; otherwise
// the result is a failure holding every error found (the parser skips to the next rule after
// each one), sorted by position, each `file:line:col` at the offending token. Never throws,
// never prints; any byte sequence is accepted as input.
base::Result<Grammar> parse(const base::Source& source);
// The same in a given dialect (an imported rule file is CityEngine's whatever it contains).
base::Result<Grammar> parse(const base::Source& source, Dialect dialect);

}  // namespace insula::lang::cga
