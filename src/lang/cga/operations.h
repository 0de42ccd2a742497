// CGA's operations (docs/cga-language.md, "Operations"). CGA keeps no operation table of its own:
// every operation of the shape registry (shape/operation.h) is a CGA operation under its own name,
// its arguments the registry's parameters in declaration order, and a small alias table
// (operations.cc) adds the spellings of seed 004 (BS, RR, CS, T, S, Rx, I, Pshape) and CityEngine
// (split, comp, roofHip, i, ...) with their positional order. Arity, argument kinds, ranges and
// defaults come from the registry's declarations; an alias says only what CGA adds: blocks and
// their keys, the paper's axis combinations, component index lists, how many arguments are
// required, and the arguments a spelling fixes (roofHip: the roof type). So a parameter added to a
// registered operation is usable and checked in CGA with no other edit. The successor items that
// are not shape operations (color, set, print, report, nil) have letter signatures here too.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/cga/ast.h"
#include "lang/cga/functions.h"
#include "shape/operation.h"

namespace insula::lang::cga {

// Whether an operation takes a successor block `{ ... }`.
enum class BlockUse : std::uint8_t { kNone, kOptional, kRequired };

// What the keys of the block's branches are.
enum class KeyUse : std::uint8_t {
  kNone,        // branches are unkeyed successors (`{ A | B }`); roof: at most one branch
  kPositional,  // one branch per size / component, in order, unkeyed (BS, RR, CS)
  kSize,        // every branch is `size: successor` or a repeat pattern `{ ... }*` (split)
  kSelector,    // every branch is `selector: successor`; comp also accepts a component index
};

// Argument signature: one letter per positional argument,
//   n number      s string       b boolean      v any value
//   a axis string ("x", "y" or "z", either case; BS and RR also combinations such as "XY")
//   c component type string ("f"/"faces", "e"/"edges", "v"/"vertices", "sidefaces")
//   z size (a number, `2r`/`'0.5` relative or `~1` floating)
//   i a bare attribute name (set(height, 3))
// A letter followed by '+' repeats one or more times, by '*' zero or more times. Alternatives
// are separated by '|' (color: "s|nnn|nnnn"). For shape operations the signature is generated
// from the registry's parameter types. signature_accepts and signature_letter (functions.h) read
// it.

struct OperationInfo {
  std::string name;
  OpKind kind = OpKind::kGeneric;  // the parser's classification of the paper's spellings
  std::uint8_t min_args = 0;
  std::uint8_t max_args = 0;  // kUnbounded: no upper bound
  std::string signature;
  BlockUse block = BlockUse::kNone;
  KeyUse keys = KeyUse::kNone;
  std::vector<std::string> selectors;  // kSelector only
  bool string_first = false;           // seed 004's strict forms: the first argument is a string
  // The registry operation it runs; null for color, set, print, report and nil.
  const shape::Operation* op = nullptr;
  std::string registry_op;  // op->name, or empty
  // params[i]: the registry parameter argument i becomes (null: an argument CGA adds, such as
  // CS's component indices); a variadic last argument repeats the last entry.
  std::vector<const shape::ParamDecl*> params;
  std::vector<shape::ArgInput> fixed;  // arguments the spelling fixes (roofHip: type = hip)
  // kSelector with pieces: selectors[k] keys the children of piece k (offset: inside, border).
  bool selectors_are_pieces = false;
  std::string doc;

  // The registry parameter of argument `index` (null when CGA's own or past the end).
  const shape::ParamDecl* param_of(std::size_t index) const;
};

// Every CGA operation: the aliases, the registry's operations under their own names and the
// built-ins, sorted by name. Built on first use from shape::registry() (immutable afterwards).
std::span<const OperationInfo> operations();

// Exact, case-sensitive lookup; null when unknown.
const OperationInfo* find_operation(std::string_view name);

// Whether `key` is an allowed selector of `op` (kSelector operations).
bool is_selector(const OperationInfo& op, std::string_view key);

// How a registry operation is written in CGA: "roofHip(pitch, overhang)", one entry per spelling
// that runs it (docs/operations.md).
std::vector<std::string> cga_spellings(const shape::Operation& op);

}  // namespace insula::lang::cga
