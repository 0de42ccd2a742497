// Static semantics of successors (seed 004 §IV.B constraints 1-5) and of operations: names,
// arities, argument kinds, blocks and their keys from operations.h, which reads them (and the
// value ranges and choices of constant arguments) from the shape operation registry
// (shape/operation.h), so nothing about an operation is written twice.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "lang/cga/checker_internal.h"
#include "lang/cga/cityengine_names.h"
#include "shape/operation.h"

namespace insula::lang::cga::detail {
namespace {

// §IV.B constraint 5: "successors.probability->sum = 1", compared with this tolerance.
constexpr double kProbabilityTolerance = 1e-9;

// Built by append: GCC 12 reports a false -Wrestrict on `"'" + std::string(...)`.
std::string quoted(std::string_view name) {
  std::string out = "'";
  out.append(name);
  out += '\'';
  return out;
}

std::string number_text(double value) {
  std::string text = std::to_string(value);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

// A declared bound in a message: the short form unless it would hide the value (a minimum of
// 1e-09 is not "0").
std::string bound_text(double value) {
  const std::string text = number_text(value);
  if (std::strtod(text.c_str(), nullptr) == value) return text;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string plural(std::size_t count, std::string_view word) {
  std::string out = std::to_string(count) + " ";
  if (count == 1) return out.append(word);
  return out.append(word == "index" ? "indices" : std::string(word) + "s");
}

// Scope rules of §II/§VI (T, S, Rx/Ry/Rz, I) and their CityEngine forms (t, s, r, center, i,
// primitiveCube): the operations that give the shapes of their successor a scope.
bool is_scope_rule(const Item& item) {
  if (item.kind != ItemKind::kOp) return false;
  if (item.has_block) return false;  // an operation with a block hands its result on
  const OperationInfo* info = find_operation(item.name);
  if (!info) return false;
  const std::string_view op = info->registry_op;
  return op == "translate" || op == "scale" || op == "rotate" || op == "center" || op == "insert";
}

// The string arguments of shape operations may be bare words: an asset name (`I(box)`), the
// axes of center or the part of offset (`offset(-1, inside)`). Elsewhere (color, report, print)
// an identifier is an attribute.
bool takes_word(const OperationInfo& info) {
  return info.op != nullptr;
}

// An enum parameter that also takes a whole number (shape::kIndexChoice).
bool takes_index(const shape::ParamDecl* p) {
  return p != nullptr &&
         std::find(p->choices.begin(), p->choices.end(), shape::kIndexChoice) != p->choices.end();
}

// ε, or CityEngine's `nil()`.
bool is_empty_shape(const Item& item) {
  return item.kind == ItemKind::kEmpty || (item.kind == ItemKind::kOp && item.name == "nil");
}

}  // namespace

void Checker::check_rule(const Rule& rule) {
  params_ = &rule.params;
  check_annotations(rule.annotations);
  if (rule.condition) check_expr(*rule.condition);
  for (const Alternative& alt : rule.alternatives) check_sequence(alt.items);
  check_probabilities(rule);
  params_ = nullptr;
}

// §IV.B constraint 1 (each probability in (0, 1]) and constraint 5 (the parts of a rule with
// more than one sum to 1). Only constant probabilities can be checked statically; one that uses
// an attribute or a function is evaluated by the derivation. Parts without a probability share
// what the others leave equally (derive.cc's choice; all parts without one are equally likely),
// so with some parts given, their constant sum must leave a positive share (CGA306); with every
// part given, the sum must be 1 (CGA305).
void Checker::check_probabilities(const Rule& rule) {
  const std::size_t parts = rule.alternatives.size();
  std::size_t given = 0;
  std::size_t constant = 0;
  double sum = 0.0;
  const Expr* last = nullptr;
  for (const Alternative& alt : rule.alternatives) {
    if (!alt.probability) continue;
    ++given;
    last = alt.probability.get();
    check_expr(*alt.probability);
    const std::optional<Constant> value = fold(*alt.probability);
    if (!value || value->relative || value->floating) continue;
    ++constant;
    sum += value->value;
    if (!(value->value > 0.0 && value->value <= 1.0)) {
      error("CGA301",
            "probability " + number_text(value->value) +
                " is not in (0, 1] (seed 004 §IV.B, constraint 1)",
            alt.probability->range);
    }
  }
  if (parts < 2 || given == 0 || constant != given) return;
  if (given < parts) {
    if (1.0 - sum > kProbabilityTolerance) return;
    for (const Alternative& alt : rule.alternatives) {
      if (alt.probability) continue;
      error("CGA306",
            "this part of the rule has no probability and the others' sum to " + number_text(sum) +
                ", leaving it none (seed 004 §IV.B, constraint 1)",
            alt.range);
      break;
    }
    return;
  }
  if (std::abs(sum - 1.0) > kProbabilityTolerance) {
    error("CGA305",
          "the probabilities of the " + std::to_string(parts) + " parts of the rule sum to " +
              number_text(sum) + ", not 1 (seed 004 §IV.B, constraint 5)",
          last->range);
  }
}

void Checker::check_sequence(const std::vector<Item>& items) {
  check_empty_shape(items);
  for (const Item& item : items) check_item(item);
}

// §IV.B constraint 3: "if self.oclIsTypeOf(Empty) then self.scope->size() = 0". The scope rules
// of a successor (T, S, Rx/Ry/Rz, I and their CityEngine forms) set the scope of the shapes of
// that successor; `[` and `]` delimit regions whose scope changes do not leak out. So ε is an
// error when a scope rule stands in the same region of the same item sequence (before or after
// it; nested blocks and bracketed sub-regions are other regions). ε together with anything else
// is legal but has no effect (warning CGA406).
void Checker::check_empty_shape(const std::vector<Item>& items) {
  if (std::none_of(items.begin(), items.end(), is_empty_shape)) return;
  // Region of each item: brackets open a new region and return to the enclosing one.
  std::vector<std::size_t> region(items.size(), 0);
  std::vector<std::size_t> open{0};
  std::size_t next = 1;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].kind == ItemKind::kPush) {
      open.push_back(next++);
    } else if (items[i].kind == ItemKind::kPop && open.size() > 1) {
      open.pop_back();
    }
    region[i] = open.back();
  }
  bool reported = false;
  for (std::size_t e = 0; e < items.size(); ++e) {
    if (!is_empty_shape(items[e])) continue;
    for (std::size_t s = 0; s < items.size(); ++s) {
      if (region[s] != region[e] || !is_scope_rule(items[s])) continue;
      if (cityengine()) {  // CityEngine deletes the shape whatever came before NIL
        warning("CGA406", "'NIL' removes the shape the operations before it changed",
                items[e].range);
        reported = true;
        break;
      }
      error("CGA303",
            "the empty shape has no scope, but the scope rule " + quoted(items[s].name) +
                " is in the same successor (seed 004 §IV.B, constraint 3)",
            items[e].range);
      reported = true;
      break;
    }
  }
  if (!reported && items.size() > 1) {
    const auto empty = std::find_if(items.begin(), items.end(), is_empty_shape);
    warning("CGA406", "the empty shape next to other successors has no effect", empty->range);
  }
}

void Checker::check_item(const Item& item) {
  if (item.kind == ItemKind::kSymbol) {
    if (cityengine()) check_symbol_call(item);
    return;
  }
  if (item.kind == ItemKind::kCase || item.kind == ItemKind::kChance) return check_chain(item);
  if (item.kind != ItemKind::kOp) return;
  if (!item.dropped.empty()) {
    warning("CGA905",
            "'" + item.name + "': the arguments after the overhang (" + item.dropped +
                ") are not supported; the roof is built without them",
            item.range);
  }
  if (item.along_uv) {
    warning("CGA904",
            "split along texture coordinates: Insula's shapes carry none here, so this splits "
            "along the scope's " +
                item.args[0]->text + " axis in meters",
            item.range);
  }
  const OperationInfo* info = find_operation(item.name);
  if (!info) {
    if (cityengine() && contains(kDetailOperations, item.name)) {
      warning("CGA903",
              "CityEngine operation '" + item.name +
                  "' is not supported yet; it is skipped (the model lacks only that detail)",
              item.range);
    } else if (cityengine() && contains(kUnsupportedOperations, item.name)) {
      error("CGA901", "CityEngine operation '" + item.name + "' is not supported", item.range);
    } else {
      error("CGA311", "unknown operation '" + item.name + "'", item.range);
    }
    for (const ExprPtr& arg : item.args) check_expr(*arg, ExprRole::kBareWord);
    for (const Branch& branch : item.branches) check_branch_items(branch);
    return;
  }
  const std::size_t count = item.args.size();
  // CityEngine's r(scopeOrigin | scopeCenter, x, y, z): the angles are numbers.
  if (cityengine() && item.name == "r" && count == 4) {
    const std::string pivot = dotted_name(*item.args[0]);
    if (pivot == "scopeOrigin" || pivot == "scopeCenter") {
      for (std::size_t i = 1; i < count; ++i) check_expr(*item.args[i]);
      return;
    }
  }
  if (!signature_accepts(info->signature, count)) {
    std::string wanted = std::to_string(info->min_args);
    if (info->max_args == kUnbounded) {
      wanted = "at least " + wanted;
    } else if (info->max_args != info->min_args) {
      wanted += " to " + std::to_string(info->max_args);
    }
    error("CGA312",
          quoted(item.name) + " expects " + wanted + " argument" + (wanted == "1" ? "" : "s") +
              ", found " + std::to_string(count),
          item.range);
    // Still resolve the names (no spurious "never used" for the attributes they read).
    for (const ExprPtr& arg : item.args) check_expr(*arg, ExprRole::kBareWord);
  } else {
    check_arguments(item, *info);
  }
  if (info->block == BlockUse::kRequired && !item.has_block) {
    error("CGA318", quoted(item.name) + " needs a successor block '{ ... }'", item.range);
  } else if (info->block == BlockUse::kNone && item.has_block) {
    error("CGA318", quoted(item.name) + " takes no successor block", item.range);
  }
  switch (info->kind) {
    case OpKind::kSplit:
      check_split(item);
      break;
    case OpKind::kRepeat:
      check_repeat(item);
      break;
    case OpKind::kComp:
      check_comp(item);
      break;
    case OpKind::kRotate:
      check_rotation(item);
      break;
    default:
      check_generic(item, *info);
      break;
  }
  for (const Branch& branch : item.branches) check_branch_items(branch);
}

void Checker::check_branch_items(const Branch& branch) {
  for (const Branch& inner : branch.pattern) check_branch_items(inner);
  check_sequence(branch.items);
}

// Arguments by the letters of the operation's signature (operations.h). Literal values of the
// wrong kind are errors; computed values are checked by the derivation.
void Checker::check_arguments(const Item& item, const OperationInfo& info) {
  const std::size_t count = item.args.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Expr& arg = *item.args[i];
    const char letter = signature_letter(info.signature, count, i);
    const std::string which = "argument " + std::to_string(i + 1) + " of " + quoted(item.name);
    switch (letter) {
      case 'a':
        // RR/Repeat and the paper's BS/Subdiv take axis combinations; CityEngine's split one axis.
        check_axis(arg, info.kind == OpKind::kRepeat || info.kind == OpKind::kSplit);
        break;
      case 'c':
        if (arg.kind == ExprKind::kString || arg.kind == ExprKind::kIdent) {
          check_comp_type(arg);  // check_comp reads the type again without reporting
        } else {
          error("CGA320", which + " must be a component type string", arg.range);
        }
        break;
      case 'i':
        // set(name, value) declares `name` when no attr does (collect_set_targets).
        if (arg.kind != ExprKind::kString && dotted_name(arg).empty()) {
          error("CGA320", which + " must be an attribute name", arg.range);
        }
        break;
      case 's':
        if (arg.kind == ExprKind::kNumber && takes_index(info.param_of(i))) {
          break;  // a face or edge index where a word may stand (alignScopeToGeometry)
        }
        if (arg.kind == ExprKind::kNumber || arg.kind == ExprKind::kBool ||
            (arg.kind == ExprKind::kUnary && fold(arg))) {
          error("CGA320", which + " must be a string", arg.range);
        } else {
          check_expr(arg, takes_word(info) ? ExprRole::kBareWord : ExprRole::kValue);
        }
        break;
      case 'n':
      case 'z':
        if (arg.kind == ExprKind::kString || arg.kind == ExprKind::kBool) {
          error("CGA320", which + " must be a number", arg.range);
        } else {
          // CityEngine's t('1, 0, 0) moves by the scope's size: a size there too.
          const bool size = letter == 'z' || (cityengine() && info.registry_op == "translate");
          check_expr(arg, size ? ExprRole::kSize : ExprRole::kValue);
        }
        break;
      default:
        check_expr(arg);
        break;
    }
  }
}

// §VI: "<axis> can be X, Y or Z as well as combinations of these (XY, YZ, XZ or XYZ)" for RR
// (a grid of cells of about the size along each named axis), and BasicSplitRule "like
// RepeatRule, also takes <axis>" (the paper's own example is `BS("XY", 3, 5, 7)`): a nested split
// along each named axis by the same sizes (docs/cga-language.md, Decisions). CityEngine's
// split(axis){ ... } takes one axis. A bare word (`split(y)`) is the axis unless it names an
// attribute.
void Checker::check_axis(const Expr& expr, bool combinations) {
  if (expr.kind != ExprKind::kString && expr.kind != ExprKind::kIdent) {
    error("CGA308", "the split axis must be written as a word (\"x\" or x), not computed",
          expr.range);
    check_expr(expr);
    return;
  }
  const std::optional<std::string> axis = canonical_axis(expr.text);
  if (!axis || (!combinations && axis->size() != 1)) {
    error("CGA308",
          "unknown split axis \"" + expr.text + "\" (expected " +
              (combinations ? "X, Y, Z, XY, XZ, YZ or XYZ" : "x, y or z") + ")",
          expr.range);
  }
}

std::optional<CompType> Checker::check_comp_type(const Expr& expr) {
  const std::optional<CompTypeSpelling> type = comp_type_of(expr.text);
  if (!type) {
    error("CGA309",
          "unknown component type \"" + expr.text +
              "\" (expected faces, edges, vertices or sidefaces)",
          expr.range);
    return std::nullopt;
  }
  if (type->nonstandard) {
    warning("CGA401",
            "component type \"" + expr.text + "\" is read as \"" +
                std::string(comp_type_name(type->type)) + "\"",
            expr.range);
  }
  return type->type;
}

// BS/Subdiv (§II "Basic Split Rule"): one successor per size, no keys; sizes must not be
// negative (zero-size pieces are left out by shape::resolve_sizes).
void Checker::check_split(const Item& item) {
  for (std::size_t i = 1; i < item.args.size(); ++i) {
    const std::optional<Constant> value = fold(*item.args[i]);
    if (value && value->value < 0.0) {
      error("CGA319", "split size " + number_text(value->value) + " is negative",
            item.args[i]->range);
    }
  }
  if (item.args.size() >= 2) check_plain_branches(item, item.args.size() - 1, "size");
}

// RR/Repeat (§II "Repeat Rule"): one successor, a positive size.
void Checker::check_repeat(const Item& item) {
  if (item.args.size() == 2) {
    const std::optional<Constant> value = fold(*item.args[1]);
    if (value && !(value->value > 0.0)) {
      error("CGA319", "repeat size " + number_text(value->value) + " is not positive",
            item.args[1]->range);
    }
  }
  check_plain_branches(item, 1, "");
}

// Branches of a positional block: exactly `expected` unkeyed successors.
void Checker::check_plain_branches(const Item& item, std::size_t expected, const char* what) {
  for (const Branch& branch : item.branches) {
    if (branch.repeat) {
      error("CGA318", quoted(item.name) + " takes no repeat pattern (use split)", branch.range);
      return;
    }
    if (branch.key) {
      error("CGA318", quoted(item.name) + " takes no branch keys", branch.key->range);
      return;
    }
  }
  if (item.has_block && item.branches.size() != expected) {
    const std::string wanted =
        *what ? "one successor per " + std::string(what) + " (" + std::to_string(expected) + ")"
              : plural(expected, "successor");
    error(
        "CGA318",
        quoted(item.name) + " needs " + wanted + ", found " + std::to_string(item.branches.size()),
        item.range);
  }
}

// CS/Comp and comp (§II "Component Split Rule", §IV.B constraint 4): with an index list, one
// unkeyed successor per index; without, either one successor for every component or branches
// keyed by selector (front, side, ... or a component index; CityEngine's comp).
void Checker::check_comp(const Item& item) {
  std::optional<CompType> type;
  if (!item.args.empty()) {
    if (const auto spelling = comp_type_of(item.args[0]->text)) type = spelling->type;
  }
  std::set<double> indices;
  for (std::size_t i = 1; i < item.args.size(); ++i) {
    const std::optional<Constant> value = fold(*item.args[i]);
    if (!value || value->relative || value->floating || value->value < 0.0 ||
        value->value != std::floor(value->value)) {
      error("CGA310", "a component index must be a natural number", item.args[i]->range);
    } else if (!indices.insert(value->value).second) {
      error("CGA310", "component index " + number_text(value->value) + " is listed twice",
            item.args[i]->range);
    }
  }
  if (!item.has_block) return;
  const std::size_t listed = item.args.empty() ? 0 : item.args.size() - 1;
  const bool keyed = std::any_of(item.branches.begin(), item.branches.end(),
                                 [](const Branch& b) { return b.key != nullptr; });
  if (listed > 0 || !keyed) {
    const std::size_t wanted = listed > 0 ? listed : 1;
    if (keyed || item.branches.size() != wanted) {
      error("CGA304",
            listed > 0 ? "the component split lists " + plural(listed, "index") + " but has " +
                             plural(item.branches.size(), "successor") +
                             (keyed ? " with keys" : "") + " (seed 004 §IV.B, constraint 4)"
                       : "a component split without an index list sends every component to "
                         "one successor, found " +
                             std::to_string(item.branches.size()) +
                             " (give an index list or selector keys; seed 004 §IV.B, "
                             "constraint 4)",
            item.range);
    }
    return;
  }
  static const std::vector<std::string> kNone;
  const OperationInfo* info = find_operation(item.name);
  check_selector_keys(item, info ? info->selectors : kNone, /*indices=*/true);
  if (type == CompType::kEdges) return;
  for (const Branch& branch : item.branches) {  // CityEngine's roof edge classes
    const Expr* key = branch.key.get();
    if (key != nullptr && key->kind == ExprKind::kIdent &&
        (key->text == "eave" || key->text == "hip" || key->text == "valley" ||
         key->text == "ridge")) {
      error("CGA315", "selector '" + key->text + "' applies to edges only (comp(e))", key->range);
    }
  }
}

// Every branch keyed by a distinct selector (or, for comp, a component index).
void Checker::check_selector_keys(const Item& item, const std::vector<std::string>& selectors,
                                  bool indices) {
  std::set<std::string> seen;
  for (const Branch& branch : item.branches) {
    if (branch.repeat) {
      error("CGA318", quoted(item.name) + " takes no repeat pattern (use split)", branch.range);
      continue;
    }
    if (!branch.key) {
      error("CGA318", "this branch of " + quoted(item.name) + " needs a selector key",
            branch.range);
      continue;
    }
    const Expr& key = *branch.key;
    std::string name;
    if (key.kind == ExprKind::kIdent || key.kind == ExprKind::kString ||
        (key.kind == ExprKind::kMember && !dotted_name(key).empty())) {
      name = key.kind == ExprKind::kMember ? dotted_name(key) : key.text;
      // setback's `street.front`: without street data CityEngine reads the lot's own sides.
      if (name.starts_with("street.") &&
          std::find(selectors.begin(), selectors.end(), "street") != selectors.end()) {
        name = name.substr(7);
      }
      const bool known = std::find(selectors.begin(), selectors.end(), name) != selectors.end();
      if (!known && indices && cityengine() &&
          (attributes_.count(name) || known_.count(name) || function(name, 0) != nullptr)) {
        check_expr(key);  // CityEngine: a constant or attribute holding the index
        continue;
      }
      if (!known) {
        std::string list;
        for (const std::string& s : selectors) list += (list.empty() ? "" : ", ") + s;
        error("CGA315",
              "unknown selector '" + name + "' for " + quoted(item.name) + " (expected " + list +
                  (indices ? " or an index" : "") + ")",
              key.range);
        continue;
      }
    } else {
      const std::optional<Constant> value = fold(key);
      if (indices && !value && cityengine() && key.kind != ExprKind::kMember) {
        // CityEngine: an index computed per shape (`comp(f) { n + 1 = Door | ... }`).
        check_expr(key);
        continue;
      }
      if (indices && value && cityengine() && !value->relative && !value->floating &&
          value->value >= 0.0 && value->value != std::floor(value->value)) {
        warning("CGA323",
                "component index " + number_text(value->value) +
                    " is not a whole number: read as " + number_text(std::round(value->value)),
                key.range);
        name = number_text(std::round(value->value));
        if (!seen.insert(name).second) {
          error("CGA315", "selector '" + name + "' appears twice", key.range);
        }
        continue;
      }
      if (!indices || !value || value->relative || value->floating || value->value < 0.0 ||
          value->value != std::floor(value->value)) {
        error("CGA315",
              std::string("a key of ") + quoted(item.name) + " must be a selector name" +
                  (indices ? " or a component index" : ""),
              key.range);
        continue;
      }
      name = number_text(value->value);
    }
    if (!seen.insert(name).second) {
      error("CGA315", "selector '" + name + "' appears twice", key.range);
    }
  }
}

// Keys of CityEngine's split: sizes (absolute, relative `'0.5`/`1r`, floating `~2`) or a repeat
// pattern `{ ... }*` of keyed branches.
void Checker::check_size_keys(const Item& item, const std::vector<Branch>& branches) {
  for (const Branch& branch : branches) {
    if (branch.repeat) {
      check_size_keys(item, branch.pattern);
      continue;
    }
    if (!branch.key) {
      error("CGA318", "this branch of " + quoted(item.name) + " needs a size key ('2: A')",
            branch.range);
      continue;
    }
    check_expr(*branch.key, ExprRole::kSize);
    if (branch.key->kind == ExprKind::kString || branch.key->kind == ExprKind::kBool) {
      error("CGA320", "a split size must be a number", branch.key->range);
      continue;
    }
    const std::optional<Constant> value = fold(*branch.key);
    if (value && value->value < 0.0) {
      error("CGA319", "split size " + number_text(value->value) + " is negative",
            branch.key->range);
    }
  }
}

// §IV.B constraint 2: "self.angle >= 0 and self.angle <= 360" for the RotationRule Rx/Ry/Rz.
// CityEngine's r(x, y, z) allows any angle and is not the paper's RotationRule.
void Checker::check_rotation(const Item& item) {
  if (item.args.size() != 1) return;
  const std::optional<Constant> value = fold(*item.args[0]);
  if (value && !value->relative && !value->floating &&
      !(value->value >= 0.0 && value->value <= 360.0)) {
    error("CGA302",
          "rotation angle " + number_text(value->value) +
              " is not in [0, 360] (seed 004 §IV.B, constraint 2)",
          item.args[0]->range);
  }
}

void Checker::check_generic(const Item& item, const OperationInfo& info) {
  if (item.name == "comp") {
    check_comp(item);
  } else if (info.keys == KeyUse::kSize) {
    check_size_keys(item, item.branches);
  } else if (info.keys == KeyUse::kSelector && item.has_block) {
    check_selector_keys(item, info.selectors, false);
  } else if (info.keys == KeyUse::kNone && item.has_block) {
    check_plain_branches(item, 1, "");
  }
  check_registry_ranges(item, info);
}

// Constant arguments against the bounds and choices the registry declares for the parameter they
// become. Arguments CGA reads its own way (the paper's axis combinations, component type
// spellings) are checked by check_axis and check_comp_type instead.
void Checker::check_registry_ranges(const Item& item, const OperationInfo& info) {
  for (std::size_t i = 0; i < item.args.size(); ++i) {
    const shape::ParamDecl* param = info.param_of(i);
    const char letter = signature_letter(info.signature, item.args.size(), i);
    if (param == nullptr || letter == 'a' || letter == 'c') continue;
    if (param->type == shape::ParamType::kEnum) {
      check_registry_choice(item, i, *param);
      continue;
    }
    const std::optional<Constant> value = fold(*item.args[i]);
    if (!value || value->relative || value->floating) continue;
    // CityEngine extrudes a negative height behind the face (derive_registry.cc).
    if (cityengine() && info.registry_op == "extrude" && param->name == "height" &&
        value->value < 0) {
      continue;
    }
    // CityEngine's s() mirrors on a negative size (derive_registry.cc, scale_mirrored).
    if (cityengine() && info.registry_op == "scale" && value->value < 0) continue;
    const bool low = param->min && value->value < *param->min;
    const bool high = param->max && value->value > *param->max;
    if (!low && !high) continue;
    std::string range;
    if (param->min && param->max) {
      range = "in [" + bound_text(*param->min) + ", " + bound_text(*param->max) + "]";
    } else if (param->min) {
      range = ">= " + bound_text(*param->min);
    } else {
      range = "<= " + bound_text(*param->max);
    }
    error("CGA319",
          "argument " + std::to_string(i + 1) + " of " + quoted(item.name) + " (" + param->name +
              ") is " + number_text(value->value) + ", must be " + range,
          item.args[i]->range);
  }
}

}  // namespace insula::lang::cga::detail

namespace insula::lang::cga::detail {

// A literal (or bare-word) argument that becomes an enum parameter of the registry must be one
// of its choices, in either case (`center("XZ")`, `offset(-1, "inside")`).
void Checker::check_registry_choice(const Item& item, std::size_t index,
                                    const shape::ParamDecl& param) {
  const Expr& arg = *item.args[index];
  const bool word =
      arg.kind == ExprKind::kString ||
      (arg.kind == ExprKind::kIdent && !attributes_.count(arg.text) && !known_.count(arg.text) &&
       function(arg.text, 0) == nullptr &&  // a constant holding the word is checked when run
       (params_ == nullptr ||
        std::find(params_->begin(), params_->end(), arg.text) == params_->end()));
  if (!word) return;
  std::string text = arg.text;
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (std::find(param.choices.begin(), param.choices.end(), text) != param.choices.end()) return;
  std::string list;
  for (const std::string& choice : param.choices) list += (list.empty() ? "" : ", ") + choice;
  error("CGA319",
        "argument " + std::to_string(index + 1) + " of " + quoted(item.name) + " (" + param.name +
            ") is \"" + arg.text + "\", must be one of " + list,
        arg.range);
}

}  // namespace insula::lang::cga::detail
