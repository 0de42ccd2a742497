#include "lang/cga/operations.h"

#include <algorithm>
#include <map>

namespace insula::lang::cga {

namespace {

// A CGA spelling of a registry operation. `args` lists the positional arguments: registry
// parameter names, space separated. `name:L` reads the parameter with CGA letter L instead of
// its registry type (the paper's axis combinations, CGA's component type spellings, sizes);
// `#name` is an argument CGA adds (CS's component indices, letter n); a trailing `+` or `*` makes
// the last argument repeat; a final `...` appends the operation's other parameters in declaration
// order, except the ones named `!name` and the ones `fixed` sets. Aliases with `...` take a
// parameter added to the registry as their next argument, with no edit here.
struct Alias {
  std::string_view name;
  OpKind kind;
  std::string_view op;
  std::string_view args;
  std::string_view fixed;  // "param=value"
  std::uint8_t min_args;
  BlockUse block;
  KeyUse keys;
  // kSelector keys: the choices of a registry parameter plus CGA's own words; `pieces:P` keys
  // the pieces of the operation by the choices of P (offset: inside = piece 0, border = 1).
  std::string_view selectors;
  bool string_first;     // seed 004's strict forms (parser CGA204)
  std::string_view doc;  // empty: the registry operation's
};

constexpr Alias kAliases[] = {
    // the paper's operations (seed 004 §VI)
    {"BS", OpKind::kSplit, "split", "axis:a sizes:z+", "", 2, BlockUse::kRequired,
     KeyUse::kPositional, "", true,
     "basic split along an axis into the given sizes, one successor per size"},
    {"Subdiv", OpKind::kSplit, "split", "axis:a sizes:z+", "", 2, BlockUse::kRequired,
     KeyUse::kPositional, "", true, "long form of BS"},
    {"RR", OpKind::kRepeat, "repeat", "axis:a size:z", "", 2, BlockUse::kRequired,
     KeyUse::kPositional, "", true, "repeat split: as many pieces of about the size as fit"},
    {"Repeat", OpKind::kRepeat, "repeat", "axis:a size:z", "", 2, BlockUse::kRequired,
     KeyUse::kPositional, "", true, "long form of RR"},
    {"CS", OpKind::kComp, "comp", "type:c #indices*", "", 1, BlockUse::kRequired, KeyUse::kSelector,
     "select", true,
     "component split; unkeyed branches go to the listed (or all) components in order"},
    {"Comp", OpKind::kComp, "comp", "type:c #indices*", "", 1, BlockUse::kRequired,
     KeyUse::kSelector, "select", true, "long form of CS"},
    {"T", OpKind::kTranslate, "translate", "x y z", "", 3, BlockUse::kNone, KeyUse::kNone, "",
     false, ""},
    {"S", OpKind::kScale, "scale", "x y z", "", 3, BlockUse::kNone, KeyUse::kNone, "", false, ""},
    {"Rx", OpKind::kRotate, "rotate", "x", "", 1, BlockUse::kNone, KeyUse::kNone, "", false,
     "rotate about scope x (degrees)"},
    {"Ry", OpKind::kRotate, "rotate", "y", "", 1, BlockUse::kNone, KeyUse::kNone, "", false,
     "rotate about scope y (degrees)"},
    {"Rz", OpKind::kRotate, "rotate", "z", "", 1, BlockUse::kNone, KeyUse::kNone, "", false,
     "rotate about scope z (degrees)"},
    {"I", OpKind::kInsert, "insert", "asset", "", 1, BlockUse::kNone, KeyUse::kNone, "", false,
     "insert an asset (or the built-in \"cube\") as a new shape in the scope"},
    {"Pshape", OpKind::kPredefined, "insert", "asset", "", 1, BlockUse::kNone, KeyUse::kNone, "",
     true, "predefined shape: insert an asset file"},
    // CityEngine's spellings (issue 4)
    {"extrude", OpKind::kGeneric, "extrude", "height ...", "", 1, BlockUse::kNone, KeyUse::kNone,
     "", false, ""},
    {"split", OpKind::kGeneric, "split", "axis:a", "", 1, BlockUse::kRequired, KeyUse::kSize, "",
     false, "split along an axis; keys are sizes, `{ ... }*` repeats a pattern"},
    {"comp", OpKind::kGeneric, "comp", "type:c", "", 1, BlockUse::kRequired, KeyUse::kSelector,
     "select", false, ""},
    {"splitArea", OpKind::kGeneric, "splitArea", "axis:a sizes:z*", "", 1, BlockUse::kOptional,
     KeyUse::kSize, "", false,
     "split a flat shape into pieces of the given areas: CityEngine's keyed block "
     "`splitArea(x){ 100 : A | ~1 : B }` (repeats too), or the sizes as arguments"},
    {"t", OpKind::kGeneric, "translate", "x y z", "", 3, BlockUse::kNone, KeyUse::kNone, "", false,
     ""},
    {"s", OpKind::kGeneric, "scale", "x y z", "", 3, BlockUse::kNone, KeyUse::kNone, "", false, ""},
    {"r", OpKind::kGeneric, "rotate", "x y z", "", 3, BlockUse::kNone, KeyUse::kNone, "", false,
     "rotate about scope x, then y, then z (degrees)"},
    {"translate", OpKind::kGeneric, "translate", "mode frame x y z", "", 5, BlockUse::kNone,
     KeyUse::kNone, "", false,
     "move the scope: rel adds, abs sets, in the scope/object/world frame"},
    {"rotate", OpKind::kGeneric, "rotate", "mode frame x y z", "", 5, BlockUse::kNone,
     KeyUse::kNone, "", false,
     "turn the scope: rel adds, abs sets, in the scope/object/world frame"},
    {"center", OpKind::kGeneric, "center", "axes ...", "", 1, BlockUse::kNone, KeyUse::kNone, "",
     false, "center the scope on the scope of the shape the rule rewrites"},
    {"i", OpKind::kGeneric, "insert", "asset ...", "", 1, BlockUse::kNone, KeyUse::kNone, "", false,
     ""},
    {"offset", OpKind::kGeneric, "offset", "distance part ...", "", 1, BlockUse::kOptional,
     KeyUse::kSelector, "pieces:part", false, ""},
    {"setback", OpKind::kGeneric, "setback", "distance ... !edges", "", 1, BlockUse::kRequired,
     KeyUse::kSelector,
     "edges street remainder world.north world.south world.east world.west world.side "
     "object.front object.back object.left object.right object.side streetSide noStreetSide "
     "uv.left uv.right uv.bottom uv.top",
     false, "cut a strip along the selected edges; key remainder for what is left"},
    {"shapeL", OpKind::kGeneric, "shapeL", "frontWidth leftWidth", "", 2, BlockUse::kOptional,
     KeyUse::kSelector, "pieces:part", false, ""},
    {"shapeU", OpKind::kGeneric, "shapeU", "frontWidth rightWidth leftWidth", "", 3,
     BlockUse::kOptional, KeyUse::kSelector, "pieces:part", false, ""},
    {"shapeO", OpKind::kGeneric, "shapeO", "frontWidth rightWidth backWidth leftWidth", "", 4,
     BlockUse::kOptional, KeyUse::kSelector, "pieces:part", false, ""},
    {"innerRectangle", OpKind::kGeneric, "innerRectangle", "align", "", 0, BlockUse::kOptional,
     KeyUse::kSelector, "pieces:part", false, ""},
    {"innerRect", OpKind::kGeneric, "innerRectangle", "", "", 0, BlockUse::kOptional,
     KeyUse::kSelector, "pieces:part", false,
     "CityEngine's older spelling of innerRectangle(scope)"},
    {"roofHip", OpKind::kGeneric, "roof", "pitch overhang ... !mansard_pitch !break_height",
     "type=hip", 1, BlockUse::kOptional, KeyUse::kNone, "", false, "hip roof"},
    {"roofGable", OpKind::kGeneric, "roof", "pitch overhang ... !mansard_pitch !break_height",
     "type=gable", 1, BlockUse::kOptional, KeyUse::kNone, "", false, "gable roof"},
    {"roofPyramid", OpKind::kGeneric, "roof", "pitch overhang ... !mansard_pitch !break_height",
     "type=pyramid", 1, BlockUse::kOptional, KeyUse::kNone, "", false, "pyramid roof"},
    {"roofShed", OpKind::kGeneric, "roof", "pitch overhang ... !mansard_pitch !break_height",
     "type=shed", 1, BlockUse::kOptional, KeyUse::kNone, "", false, "shed roof"},
    {"roofMansard", OpKind::kGeneric, "roof", "pitch mansard_pitch break_height overhang ...",
     "type=mansard", 1, BlockUse::kOptional, KeyUse::kNone, "", false, "mansard roof"},
    // .bldg's Flat roof is roofFlat(overhang, thickness): the slab thickness comes second.
    {"roofFlat", OpKind::kGeneric, "roof",
     "overhang thickness ... !pitch !mansard_pitch !break_height", "type=flat", 0,
     BlockUse::kOptional, KeyUse::kNone, "", false,
     "flat roof; with a thickness a closed slab that thick over the outline grown by the overhang"},
};

// Successor items that are not shape operations.
struct BuiltIn {
  std::string_view name;
  std::uint8_t min_args;
  std::uint8_t max_args;
  std::string_view signature;
  std::string_view doc;
};

constexpr BuiltIn kBuiltIns[] = {
    {"color", 1, 4, "s|nnn|nnnn", "set the colour: \"#rrggbb\" or r, g, b (0..1)[, alpha]"},
    {"set", 2, 2, "iv",
     "set an attribute for this shape and its descendants (material, or an attr)"},
    {"print", 1, kUnbounded, "v+", "print the values to stderr while deriving (debugging)"},
    {"report", 2, 2, "sv",
     "add a number to the report's per-name sum and count (a text counts under \"name=text\")"},
    {"nil", 0, 0, "", "remove the shape (as epsilon)"},
    {"label", 1, 1, "s",
     "mark the shape as an occluder under this label (CityEngine's touches/inside/overlaps)"},
};

std::vector<std::string_view> words(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    if (end > i) out.push_back(text.substr(i, end - i));
    i = end + 1;
  }
  return out;
}

char letter_of(shape::ParamType type) {
  switch (type) {
    case shape::ParamType::kNumber:
    case shape::ParamType::kInteger:
      return 'n';
    case shape::ParamType::kString:
    case shape::ParamType::kEnum:
      return 's';
    case shape::ParamType::kBool:
      return 'b';
    case shape::ParamType::kSize:
    case shape::ParamType::kSizeList:
      return 'z';
  }
  return 'v';
}

// "az+" for letters {a, z}, the last repeating, at least `min` arguments; "n|nn" for {n, n}
// with one required.
std::string signature_of(const std::string& letters, bool variadic, std::size_t min) {
  if (variadic) {
    std::string out = letters;
    out += min >= letters.size() ? '+' : '*';
    return out;
  }
  std::string out;
  for (std::size_t k = min; k <= letters.size(); ++k) {
    if (k > min) out += '|';
    out.append(letters, 0, k);
  }
  return out;
}

// Positional arguments of an alias against the registry operation `op`.
void resolve_args(const Alias& alias, const shape::Operation& op, OperationInfo& info,
                  std::string& letters, bool& variadic) {
  std::vector<std::string_view> taken;
  bool rest = false;
  for (std::string_view word : words(alias.args)) {
    if (word == "...") {
      rest = true;
      continue;
    }
    if (word.front() == '!') {
      taken.push_back(word.substr(1));
      continue;
    }
    if (word.back() == '+' || word.back() == '*') {
      variadic = true;
      word.remove_suffix(1);
    }
    const std::size_t colon = word.find(':');
    std::string_view name = word.substr(0, colon);
    const shape::ParamDecl* param = nullptr;
    char letter = 'n';
    if (name.front() == '#') {
      name.remove_prefix(1);
    } else {
      param = op.param(name);
      if (param != nullptr) letter = letter_of(param->type);
      taken.push_back(name);
    }
    if (colon != std::string_view::npos) letter = word[colon + 1];
    info.params.push_back(param);
    letters += letter;
  }
  for (std::string_view word : words(alias.fixed)) {
    const std::size_t eq = word.find('=');
    const std::string_view name = word.substr(0, eq);
    info.fixed.push_back({std::string(name), std::string(word.substr(eq + 1))});
    taken.push_back(name);
  }
  if (!rest) return;
  for (const shape::ParamDecl& p : op.params) {
    if (std::find(taken.begin(), taken.end(), p.name) != taken.end()) continue;
    info.params.push_back(&p);
    letters += letter_of(p.type);
  }
}

void resolve_selectors(const Alias& alias, const shape::Operation& op, OperationInfo& info) {
  for (std::string_view word : words(alias.selectors)) {
    std::string_view name = word;
    if (name.substr(0, 7) == "pieces:") {
      name.remove_prefix(7);
      info.selectors_are_pieces = true;
    }
    const shape::ParamDecl* param = op.param(name);
    if (param == nullptr) {
      info.selectors.emplace_back(word);
      continue;
    }
    for (const std::string& choice : param->choices) {
      // `all` keeps every piece; it names no piece of its own.
      if (!info.selectors_are_pieces || choice != "all") info.selectors.push_back(choice);
    }
  }
}

OperationInfo from_alias(const Alias& alias, const shape::Operation& op) {
  OperationInfo info;
  info.name = alias.name;
  info.kind = alias.kind;
  info.block = alias.block;
  info.keys = alias.keys;
  info.string_first = alias.string_first;
  info.op = &op;
  info.registry_op = op.name;
  info.doc = alias.doc.empty() ? op.doc : std::string(alias.doc);
  std::string letters;
  bool variadic = false;
  resolve_args(alias, op, info, letters, variadic);
  resolve_selectors(alias, op, info);
  info.min_args = alias.min_args;
  info.max_args = variadic ? kUnbounded : static_cast<std::uint8_t>(letters.size());
  info.signature = signature_of(letters, variadic, alias.min_args);
  return info;
}

// A registry operation under its own name: every parameter in declaration order, the ones up to
// the last required one required; one optional block whose successor gets every child.
OperationInfo from_registry(const shape::Operation& op) {
  OperationInfo info;
  info.name = op.name;
  info.block = BlockUse::kOptional;
  info.op = &op;
  info.registry_op = op.name;
  info.doc = op.doc;
  std::string letters;
  for (std::size_t i = 0; i < op.params.size(); ++i) {
    info.params.push_back(&op.params[i]);
    letters += letter_of(op.params[i].type);
    if (!op.params[i].default_value) info.min_args = static_cast<std::uint8_t>(i + 1);
  }
  const bool variadic = !op.params.empty() && op.params.back().type == shape::ParamType::kSizeList;
  info.max_args = variadic ? kUnbounded : static_cast<std::uint8_t>(letters.size());
  info.signature = signature_of(letters, variadic, info.min_args);
  return info;
}

OperationInfo from_built_in(const BuiltIn& b) {
  OperationInfo info;
  info.name = b.name;
  info.min_args = b.min_args;
  info.max_args = b.max_args;
  info.signature = b.signature;
  info.doc = b.doc;
  return info;
}

const std::vector<OperationInfo>& table() {
  static const std::vector<OperationInfo> kTable = [] {
    std::map<std::string, OperationInfo, std::less<>> all;
    const shape::Registry& registry = shape::registry();
    for (const shape::Operation& op : registry.operations()) all[op.name] = from_registry(op);
    for (const Alias& alias : kAliases) {
      if (const shape::Operation* op = registry.find(alias.op)) {
        all[std::string(alias.name)] = from_alias(alias, *op);
      }
    }
    for (const BuiltIn& b : kBuiltIns) all[std::string(b.name)] = from_built_in(b);
    std::vector<OperationInfo> out;
    for (auto& [name, info] : all) out.push_back(std::move(info));
    return out;
  }();
  return kTable;
}

}  // namespace

const shape::ParamDecl* OperationInfo::param_of(std::size_t index) const {
  if (params.empty()) return nullptr;
  if (index < params.size()) return params[index];
  return max_args == kUnbounded ? params.back() : nullptr;
}

std::span<const OperationInfo> operations() {
  return table();
}

const OperationInfo* find_operation(std::string_view name) {
  const std::vector<OperationInfo>& all = table();
  auto it =
      std::lower_bound(all.begin(), all.end(), name,
                       [](const OperationInfo& op, std::string_view n) { return op.name < n; });
  return it != all.end() && it->name == name ? &*it : nullptr;
}

bool is_selector(const OperationInfo& op, std::string_view key) {
  return std::find(op.selectors.begin(), op.selectors.end(), key) != op.selectors.end();
}

std::vector<std::string> cga_spellings(const shape::Operation& op) {
  std::vector<std::string> out;
  for (const OperationInfo& info : operations()) {
    if (info.op != &op) continue;
    std::string text = info.name + "(";
    for (std::size_t i = 0; i < info.params.size(); ++i) {
      if (i > 0) text += ", ";
      text += info.params[i] != nullptr ? info.params[i]->name : "indices";
      if (i + 1 == info.params.size() && info.max_args == kUnbounded) text += "...";
    }
    text += ")";
    for (const shape::ArgInput& f : info.fixed) {
      text += " " + f.name + "=" + shape::to_string(f.value);
    }
    switch (info.keys) {
      case KeyUse::kPositional:
        text += " { A | B | ... }";
        break;
      case KeyUse::kSize:
        text += " { size: A | ... }";
        break;
      case KeyUse::kSelector:
        text += " { selector: A | ... }";
        break;
      case KeyUse::kNone:
        break;
    }
    out.push_back(std::move(text));
  }
  return out;
}

}  // namespace insula::lang::cga
