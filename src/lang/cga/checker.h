// Static semantics of CGA grammars (seed 004, §IV.B, plus the checks of issue 4). The parser
// (parser.h) guarantees the syntax and the fixed arities of the paper's operations; the checker
// decides whether a parsed Grammar is a well-formed model:
//   - the five OCL constraints of §IV.B: a probability is in (0, 1] (1), a rotation angle in
//     [0, 360] (2), the empty shape has no scope (3), a component split's index list matches its
//     successors (4), the probabilities of a rule's parts sum to 1 (5);
//   - duplicate rule ids in a priority set, unknown split axes and component types, unknown
//     generic operations and wrong arities (operations.h: the shape operation registry),
//     undefined identifiers in expressions;
//   - warnings: rules unreachable from the start symbol, unused attributes, paper spellings of
//     component types that are mapped to the canonical ones.
// Codes: CGA3xx errors, CGA4xx warnings; the table is in docs/cga-language.md, "Static semantics".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

struct CheckOptions {
  // The start symbol (`--start SYMBOL`). Empty: the predecessor of the first rule of the priority
  // set with the lowest priority number (seed 004 §II: derivation goes from low detail, priority
  // 1, to high detail).
  std::string start;
  // Names that expressions may use besides the grammar's `attr`s and the shape attributes
  // (Shape.*, Scope.*): lot properties and `--set NAME=...` names supplied from outside.
  std::vector<std::string> known_attributes;
};

// One rule of the checked grammar. Pointers point into the Grammar given to check(), which must
// outlive the result.
struct CheckedRule {
  const Rule* rule = nullptr;
  std::uint32_t priority = 0;  // of its priority set
  bool reachable = false;      // derivable from the start symbol
};

struct CheckResult {
  // Errors and warnings, sorted by position (file-wide diagnostics, line 0, first), each at the
  // offending token.
  std::vector<base::Diagnostic> diagnostics;
  bool ok = false;  // no error (warnings allowed)
  // The start symbol actually used (from CheckOptions::start or the default rule above); empty
  // when the grammar has no rule.
  std::string start_symbol;
  // Every rule in source order (priority sets in file order, rules in set order).
  std::vector<CheckedRule> rules;
  // Symbols that appear in successors but are the predecessor of no rule: terminals (legal),
  // sorted, each once.
  std::vector<std::string> terminals;
  // Reachable rules only, in source order (the rules a derivation can ever apply).
  std::vector<const Rule*> reachable_rules() const;
};

// Checks `grammar` (parsed from `source`, used for positions). Never throws, never prints.
CheckResult check(const Grammar& grammar, const base::Source& source,
                  const CheckOptions& options = {});

// ---- normalisation shared with the derivation ----

// The scope axes named by a split or repeat axis string (§VI: "X", "Y", "Z", "XY", "XZ", "YZ",
// "XYZ", either case): the canonical lower-case spelling ("x", "xy", ...), or nullopt.
std::optional<std::string> canonical_axis(std::string_view text);

// Component types of CS/Comp/comp (§II "faces", "edges", "vertices", "side faces"; §VI writes
// "faces", "edges", "verticles", "sidefaces"; CityEngine's "f", "e", "v").
enum class CompType { kFaces, kEdges, kVertices, kSideFaces, kFaceEdges };
struct CompTypeSpelling {
  CompType type = CompType::kFaces;
  // The text is one of the paper's non-canonical spellings ("edge", "verticles", "side faces",
  // "vertices's", ...): accepted, with warning CGA401 from the checker.
  bool nonstandard = false;
};
std::optional<CompTypeSpelling> comp_type_of(std::string_view text);
// "faces", "edges", "vertices", "sidefaces".
std::string_view comp_type_name(CompType type);

// A text dump of the checked model (start symbol, rules with priority and reachability,
// terminals, attributes), one fact per line; the "checked model" golden stage.
std::string dump_checked(const Grammar& grammar, const CheckResult& result);

}  // namespace insula::lang::cga
