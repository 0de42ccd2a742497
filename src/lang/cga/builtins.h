// The built-in names of the CGA language (seed 004 §III/§VI plus the CityEngine-style extensions
// of issue 4): every operation a successor may use, every expression function and every shape
// attribute, with their arities. The checker (static checks) and the evaluator (derivation) both
// read this one table, so a name and its arity are declared once (as the shape layer's operation
// registry does for the operations themselves).
//
// Operation names follow CityEngine's CGA meaning (issue 4: "operations follow its meaning"); the
// paper's short forms (BS, RR, CS, T, S, Rx/Ry/Rz, I, Pshape) are classified by the parser
// (ast.h OpKind) and appear here too, with the same registry mapping, so one lookup covers all.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "lang/cga/ast.h"

namespace insula::lang::cga {

// Whether an operation takes a successor block `{ ... }`.
enum class BlockUse : std::uint8_t { kNone, kOptional, kRequired };

// What the keys of the block's branches are.
enum class KeyUse : std::uint8_t {
  kNone,        // branches are unkeyed successors (`{ A | B }`); roof: at most one branch
  kPositional,  // one branch per size / component, in order, unkeyed (BS, RR, CS)
  kSize,        // every branch is `size: successor` or a repeat pattern `{ ... }*` (split)
  kSelector,    // every branch is `selector: successor`, selector from `selectors`; comp also
                // accepts a non-negative integer (the face index)
};

// Argument signature: one letter per positional argument,
//   n number      s string       b boolean      v any value
//   a axis string ("x", "y" or "z", either case)
//   c component type string ("f"/"faces", "e"/"edges", "v"/"vertices")
//   z size (a number, `2r`/`'0.5` relative or `~1` floating)
//   i a bare attribute name (set(height, 3))
// A letter followed by '+' repeats one or more times, by '*' zero or more times. Alternatives
// are separated by '|' (color: "s|nnn|nnnn"). min_args/max_args are the overall bounds
// (kUnbounded for no upper bound).
inline constexpr std::uint8_t kUnbounded = 255;

struct OperationInfo {
  std::string_view name;
  OpKind kind;  // the parser's classification (kGeneric for names it does not know)
  std::uint8_t min_args;
  std::uint8_t max_args;
  std::string_view signature;
  BlockUse block;
  KeyUse keys;
  std::span<const std::string_view> selectors;  // kSelector only
  // The shape::registry() operation it runs ("split", "roof", ...); empty when the evaluator
  // handles it alone (color, set, print, report, nil: no geometry operation).
  std::string_view registry_op;
  std::string_view doc;
};

// Selector keys.
inline constexpr std::string_view kFaceSelectors[] = {"front", "back",   "left", "right",
                                                      "top",   "bottom", "side", "all"};
// setback: the strip along the chosen edges (front/back/left/right/side/all; `street` is the
// lot's first edge, i.e. front in the lot's scope) and `remainder` for what is left.
inline constexpr std::string_view kSetbackSelectors[] = {"front", "back", "left",   "right",
                                                         "side",  "all",  "street", "remainder"};
inline constexpr std::string_view kOffsetSelectors[] = {"inside", "border"};

inline constexpr OperationInfo kOperations[] = {
    // --- the paper's operations (§VI), classified by the parser
    {"BS",
     OpKind::kSplit,
     2,
     kUnbounded,
     "az+",
     BlockUse::kRequired,
     KeyUse::kPositional,
     {},
     "split",
     "basic split along an axis into the given sizes, one successor per size"},
    {"Subdiv",
     OpKind::kSplit,
     2,
     kUnbounded,
     "az+",
     BlockUse::kRequired,
     KeyUse::kPositional,
     {},
     "split",
     "long form of BS"},
    {"RR",
     OpKind::kRepeat,
     2,
     2,
     "az",
     BlockUse::kRequired,
     KeyUse::kPositional,
     {},
     "repeat",
     "repeat split: as many pieces of about the size as fit"},
    {"Repeat",
     OpKind::kRepeat,
     2,
     2,
     "az",
     BlockUse::kRequired,
     KeyUse::kPositional,
     {},
     "repeat",
     "long form of RR"},
    {"CS", OpKind::kComp, 1, kUnbounded, "cn*", BlockUse::kRequired, KeyUse::kSelector,
     kFaceSelectors, "comp",
     "component split; unkeyed branches go to the listed (or all) components in order"},
    {"Comp", OpKind::kComp, 1, kUnbounded, "cn*", BlockUse::kRequired, KeyUse::kSelector,
     kFaceSelectors, "comp", "long form of CS"},
    {"T",
     OpKind::kTranslate,
     3,
     3,
     "nnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "translate",
     "translate the scope along its own axes"},
    {"S",
     OpKind::kScale,
     3,
     3,
     "zzz",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "scale",
     "set the scope size (absolute or relative)"},
    {"Rx",
     OpKind::kRotate,
     1,
     1,
     "n",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "rotate",
     "rotate about scope x (degrees)"},
    {"Ry",
     OpKind::kRotate,
     1,
     1,
     "n",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "rotate",
     "rotate about scope y (degrees)"},
    {"Rz",
     OpKind::kRotate,
     1,
     1,
     "n",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "rotate",
     "rotate about scope z (degrees)"},
    {"I",
     OpKind::kInsert,
     1,
     1,
     "s",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "insert",
     "insert an asset (or the built-in \"cube\") scaled to the scope"},
    {"Pshape",
     OpKind::kPredefined,
     1,
     1,
     "s",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "insert",
     "predefined shape: insert an asset file"},
    // --- CityEngine-style extensions (issue 4)
    {"extrude",
     OpKind::kGeneric,
     1,
     1,
     "n",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "extrude",
     "extrude a flat shape along its normal into a prism"},
    {"split",
     OpKind::kGeneric,
     1,
     1,
     "a",
     BlockUse::kRequired,
     KeyUse::kSize,
     {},
     "split",
     "split along an axis; keys are sizes, `{ ... }*` repeats a pattern"},
    {"comp", OpKind::kGeneric, 1, 1, "c", BlockUse::kRequired, KeyUse::kSelector, kFaceSelectors,
     "comp", "component split with selectors (front, back, left, right, top, bottom, side, all)"},
    {"t",
     OpKind::kGeneric,
     3,
     3,
     "nnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "translate",
     "translate the scope along its own axes"},
    {"s",
     OpKind::kGeneric,
     3,
     3,
     "zzz",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "scale",
     "set the scope size (absolute or relative)"},
    {"r",
     OpKind::kGeneric,
     3,
     3,
     "nnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "rotate",
     "rotate about scope x, then y, then z (degrees)"},
    {"center",
     OpKind::kGeneric,
     1,
     1,
     "s",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "center",
     "center the scope on the parent's scope along the given axes (\"xyz\", \"x\", ...)"},
    {"i",
     OpKind::kGeneric,
     1,
     1,
     "s",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "insert",
     "insert an asset (or the built-in \"cube\") scaled to the scope"},
    {"primitiveCube",
     OpKind::kGeneric,
     0,
     0,
     "",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "insert",
     "replace the geometry by a box filling the scope"},
    {"offset", OpKind::kGeneric, 1, 2, "n|ns", BlockUse::kOptional, KeyUse::kSelector,
     kOffsetSelectors, "offset",
     "offset the outline (negative insets); keys inside and border, or part \"inside\"/\"border\""},
    {"setback", OpKind::kGeneric, 1, 1, "n", BlockUse::kRequired, KeyUse::kSelector,
     kSetbackSelectors, "setback",
     "cut a strip along the selected edges; key remainder for what is left"},
    {"roofHip",
     OpKind::kGeneric,
     1,
     2,
     "n|nn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "hip roof (angle, overhang)"},
    {"roofGable",
     OpKind::kGeneric,
     1,
     2,
     "n|nn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "gable roof (angle, overhang)"},
    {"roofPyramid",
     OpKind::kGeneric,
     1,
     2,
     "n|nn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "pyramid roof (angle, overhang)"},
    {"roofShed",
     OpKind::kGeneric,
     1,
     2,
     "n|nn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "shed roof (angle, overhang)"},
    {"roofMansard",
     OpKind::kGeneric,
     1,
     4,
     "n|nn|nnn|nnnn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "mansard roof (upper angle, lower angle, break height, overhang)"},
    {"roofFlat",
     OpKind::kGeneric,
     0,
     2,
     "|n|nn",
     BlockUse::kOptional,
     KeyUse::kNone,
     {},
     "roof",
     "flat roof (overhang[, thickness]: a closed slab that thick, as .bldg Flat)"},
    // --- building elements (issue 11, one engine): registry operations with their arguments in
    // the registry's declaration order (derive.cc registry_args)
    {"stair",
     OpKind::kGeneric,
     1,
     3,
     "n|nn|nnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "stair",
     "straight massive flight over a flat shape (height[, steps, max_rise])"},
    {"frame",
     OpKind::kGeneric,
     0,
     6,
     "|s|sn|snn|snnn|snnnn|snnnnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "frame",
     "door or window frame filling a flat shape (kind[, thickness, width, depth, pane, leaf])"},
    {"slab",
     OpKind::kGeneric,
     0,
     2,
     "|s|sn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "slab",
     "floor or ceiling slab over a flat shape (kind[, thickness])"},
    {"color",
     OpKind::kGeneric,
     1,
     4,
     "s|nnn|nnnn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "",
     "set the colour: \"#rrggbb\" or r, g, b (0..1)[, alpha]"},
    {"set",
     OpKind::kGeneric,
     2,
     2,
     "iv",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "",
     "set an attribute for this shape and its descendants (material, or an attr)"},
    {"print",
     OpKind::kGeneric,
     1,
     kUnbounded,
     "v+",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "",
     "print the values to stderr while deriving (debugging)"},
    {"report",
     OpKind::kGeneric,
     2,
     2,
     "sn",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "",
     "add a number to the report's per-name sum and count"},
    {"nil",
     OpKind::kGeneric,
     0,
     0,
     "",
     BlockUse::kNone,
     KeyUse::kNone,
     {},
     "",
     "remove the shape (as epsilon)"},
};

// Expression functions (lower-case, CityEngine's names).
struct FunctionInfo {
  std::string_view name;
  std::uint8_t min_args;
  std::uint8_t max_args;
  std::string_view signature;  // as OperationInfo::signature
  std::string_view doc;
};

inline constexpr FunctionInfo kFunctions[] = {
    {"rand", 0, 2, "|n|nn", "uniform in [0,1), [0,a) or [a,b) from the shape's seeded generator"},
    {"rint", 1, 1, "n", "round to the nearest integer"},
    {"round", 1, 1, "n", "round half away from zero"},
    {"floor", 1, 1, "n", "largest integer <= x"},
    {"ceil", 1, 1, "n", "smallest integer >= x"},
    {"abs", 1, 1, "n", "absolute value"},
    {"min", 2, kUnbounded, "nn+", "smallest argument"},
    {"max", 2, kUnbounded, "nn+", "largest argument"},
    {"clamp", 3, 3, "nnn", "clamp(x, lo, hi)"},
    {"sqrt", 1, 1, "n", "square root"},
    {"pow", 2, 2, "nn", "x to the power y"},
    {"exp", 1, 1, "n", "e to the power x"},
    {"ln", 1, 1, "n", "natural logarithm"},
    {"sin", 1, 1, "n", "sine (degrees, as CityEngine)"},
    {"cos", 1, 1, "n", "cosine (degrees)"},
    {"tan", 1, 1, "n", "tangent (degrees)"},
    {"asin", 1, 1, "n", "arc sine (degrees)"},
    {"acos", 1, 1, "n", "arc cosine (degrees)"},
    {"atan", 1, 1, "n", "arc tangent (degrees)"},
    {"atan2", 2, 2, "nn", "atan2(y, x) (degrees)"},
    {"p", 1, 1, "n", "true with probability x (the shape's seeded generator)"},
    {"float", 1, 1, "v", "number from a number, bool or numeric string"},
    {"str", 1, 1, "v", "text of a value"},
    {"bool", 1, 1, "v", "truth of a value"},
    {"len", 1, 1, "s", "length of a string"},
};

// Shape attributes: `Shape.sx`, `Scope.sx` (the paper writes Shape., CityEngine scope.; both
// spellings, either case of the object name). Shape.occ("all") is a call.
struct AttributeInfo {
  std::string_view name;  // the member after "Shape." / "Scope."
  std::uint8_t args;      // 0 for a value, > 0 for a member call
  std::string_view doc;
};

inline constexpr AttributeInfo kShapeAttributes[] = {
    {"sx", 0, "scope size along x (meters)"},
    {"sy", 0, "scope size along y"},
    {"sz", 0, "scope size along z"},
    {"tx", 0, "scope origin x in the lot's frame"},
    {"ty", 0, "scope origin y in the lot's frame"},
    {"tz", 0, "scope origin z in the lot's frame"},
    {"area", 0, "area of a flat shape's outline (sx * sy for a box scope)"},
    {"volume", 0, "sx * sy * sz"},
    {"depth", 0, "derivation depth of the shape"},
    {"index", 0, "index of the shape among its parent's children (split.index)"},
    {"total", 0, "number of children of the parent operation (split.total)"},
    {"occ", 1, "occlusion: \"none\", \"part\" or \"full\"; argument \"all\" (shapes of the lot)"},
};

// Object names whose members are shape attributes.
inline constexpr std::string_view kShapeObjects[] = {"Shape", "shape", "Scope",
                                                     "scope", "split", "comp"};

// Lookups (exact, case-sensitive names); null when unknown. Rotation names Rx/Ry/Rz are rows.
constexpr const OperationInfo* find_operation(std::string_view name) {
  for (const OperationInfo& op : kOperations) {
    if (op.name == name) return &op;
  }
  return nullptr;
}
constexpr const FunctionInfo* find_function(std::string_view name) {
  for (const FunctionInfo& fn : kFunctions) {
    if (fn.name == name) return &fn;
  }
  return nullptr;
}
constexpr bool is_shape_object(std::string_view object) {
  for (std::string_view o : kShapeObjects) {
    if (o == object) return true;
  }
  return false;
}
// `object.member` (object one of kShapeObjects), e.g. ("Scope", "sx").
constexpr const AttributeInfo* find_shape_attribute(std::string_view object,
                                                    std::string_view member) {
  if (!is_shape_object(object)) return nullptr;
  for (const AttributeInfo& a : kShapeAttributes) {
    if (a.name == member) return &a;
  }
  return nullptr;
}
// Whether `key` is an allowed selector of `op` (kSelector operations).
constexpr bool is_selector(const OperationInfo& op, std::string_view key) {
  for (std::string_view s : op.selectors) {
    if (s == key) return true;
  }
  return false;
}
// Whether `count` arguments fit one alternative of `signature` (letters, '+', '*', '|').
constexpr bool signature_accepts(std::string_view signature, std::size_t count) {
  std::size_t begin = 0;
  while (true) {
    std::size_t end = signature.find('|', begin);
    if (end == std::string_view::npos) end = signature.size();
    std::size_t fixed = 0;
    bool unbounded = false;
    for (std::size_t i = begin; i < end; ++i) {
      const char c = signature[i];
      if (c == '+') {
        unbounded = true;
      } else if (c == '*') {
        unbounded = true;
        --fixed;  // the letter before '*' is optional
      } else {
        ++fixed;
      }
    }
    if (count == fixed || (unbounded && count >= fixed)) return true;
    if (end == signature.size()) return false;
    begin = end + 1;
  }
}
// The expected letter of argument `index` given `count` arguments (first matching
// alternative), or '\0' when no alternative accepts `count`.
constexpr char signature_letter(std::string_view signature, std::size_t count, std::size_t index) {
  std::size_t begin = 0;
  while (true) {
    std::size_t end = signature.find('|', begin);
    if (end == std::string_view::npos) end = signature.size();
    std::string_view alt = signature.substr(begin, end - begin);
    if (signature_accepts(alt, count)) {
      std::size_t pos = 0;
      char last = '\0';
      for (std::size_t i = 0; i < alt.size(); ++i) {
        const char c = alt[i];
        if (c == '+' || c == '*') continue;
        last = c;
        if (pos == index) return c;
        ++pos;
      }
      return last;  // inside the repeated tail
    }
    if (end == signature.size()) return '\0';
    begin = end + 1;
  }
}

// The self-checks of these lookups live in tests/lang/cga/builtins_test.cc, not in static_asserts
// here: GCC with -fsanitize=undefined does not treat the loops over the tables as constant
// expressions, so a static_assert in this header broke every sanitizer build (INSULA_SANITIZE).

}  // namespace insula::lang::cga
