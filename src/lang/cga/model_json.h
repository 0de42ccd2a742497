// The CGA AST as JSON (seed 004 §IV: the AST is the metamodel, so this is a faithful
// serialisation of the model): grammar, attributes, priority sets, production rules, rule parts
// (alternatives), successor items, split branches and expressions, each with its source range as
// 1-based line and column. The schema is docs/cga-model.schema.json; docs/cga-model.md shows an
// example.
#pragma once

#include <string>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// Identifies the document kind in the "format" member.
inline constexpr const char* kModelJsonFormat = "insula-cga-model";
inline constexpr int kModelJsonVersion = 1;

// The JSON text of `grammar` parsed from `source` (used to turn byte ranges into line:col),
// indented by two spaces, ending with a newline.
std::string model_json(const Grammar& grammar, const base::Source& source);

}  // namespace insula::lang::cga
