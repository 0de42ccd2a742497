// Static semantics of what CityEngine's dialect adds to the grammar model (issue 20;
// docs/cityengine-dialect.md): functions and constants, rule parameters and parametric rule
// calls, `case` / percentage chains, annotations and the start rules they mark.
#include <cmath>

#include "base/format.h"

#include "lang/cga/checker_internal.h"
#include "lang/cga/cityengine_names.h"

namespace insula::lang::cga::detail {
namespace {

// Annotations CityEngine documents (docs/cityengine-dialect.md §3, "Annotations").
constexpr std::string_view kKnownAnnotations[] = {
    "StartRule",    "Group",     "Order",        "Range",
    "Enum",         "Hidden",    "Description",  "Color",
    "File",         "Directory", "Distance",     "Angle",
    "Percent",      "Handle",    "DisplayName",  "RuleFileDescription",
    "MaterialFile", "Out",       "InPolygon",    "InMesh",
    "InLine",       "InPoint",   "InPointCloud", "NoParallel",
    "Dimension",    "Units",     "Hiddden",
};

std::string count_text(const std::set<std::size_t>& counts) {
  std::string out;
  for (std::size_t n : counts) {
    if (!out.empty()) out += " or ";
    out += std::to_string(n);
  }
  return out;
}

}  // namespace

void Checker::declare_functions() {
  for (const FunctionDecl& fn : grammar_.functions) {
    auto [it, inserted] = functions_[fn.name].emplace(fn.params.size(), &fn);
    if (!inserted) {
      error("CGA330",
            "function '" + fn.name + "' with " + std::to_string(fn.params.size()) +
                " parameters is defined twice (first at line " +
                std::to_string(source_.locate(it->second->name_range.begin).first) + ")",
            fn.name_range);
    }
  }
}

void Checker::check_functions() {
  for (const FunctionDecl& fn : grammar_.functions) {
    if (attributes_.count(fn.name)) {
      error("CGA330", "'" + fn.name + "' is both an attribute and a function", fn.name_range);
    }
    check_annotations(fn.annotations);
    params_ = &fn.params;
    check_expr(*fn.body);
    params_ = nullptr;
  }
  for (const AttrDecl& attr : grammar_.attrs) check_annotations(attr.annotations);
  for (const ImportDecl& imp : grammar_.imports) check_annotations(imp.annotations);
}

// Unknown annotations are kept (tools may read them) and named, never an error.
void Checker::check_annotations(const std::vector<Annotation>& annotations) {
  for (const Annotation& a : annotations) {
    if (!contains(kKnownAnnotations, a.name)) {
      warning("CGA430", "unknown annotation '@" + a.name + "' (kept, no effect)", a.range);
    }
  }
}

void Checker::declare_rule_arities() {
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) rule_arities_[rule.predecessor].insert(rule.params.size());
  }
}

// `Floor(3)`: a rule of that name must take that many parameters. A name with no rule at all is
// a leaf (CityEngine warns; Insula lists it among the terminals).
void Checker::check_symbol_call(const Item& item) {
  for (const ExprPtr& arg : item.args) check_expr(*arg);
  if (item.terminal) return;  // `Name.` labels a leaf: no rule is called
  auto it = rule_arities_.find(item.name);
  if (it == rule_arities_.end() || it->second.count(item.args.size())) return;
  error("CGA331",
        "rule '" + item.name + "' takes " + count_text(it->second) + " parameter" +
            (it->second.size() == 1 && *it->second.begin() == 1 ? "" : "s") + ", called with " +
            std::to_string(item.args.size()),
        item.range);
}

// `case c : A ... else : B` and `30% : A ... else : B`. Constant percentages must be in
// [0, 100] and sum to at most 100 (the `else` branch takes the rest).
void Checker::check_chain(const Item& item) {
  double sum = 0;
  bool constant = true;
  for (const Branch& branch : item.branches) {
    if (branch.key) {
      check_expr(*branch.key);
      if (item.kind == ItemKind::kChance) {
        const std::optional<Constant> value = fold(*branch.key);
        if (!value) {
          constant = false;
        } else if (!(value->value >= 0 && value->value <= 100)) {
          error("CGA332", "a percentage must be in [0, 100]", branch.key->range);
        } else {
          sum += value->value;
        }
      }
    }
    check_sequence(branch.items);
  }
  if (item.kind == ItemKind::kChance && constant && sum > 100 + 1e-9) {
    error("CGA332", "the percentages sum to " + base::shortest_number(sum) + ", more than 100",
          item.branches.front().key->range);
  }
}

// A call of a function of the grammar: true when `expr` is one (and checked here).
bool Checker::check_user_call(const Expr& expr) {
  const Expr& callee = *expr.operands[0];
  const std::string name = dotted_name(callee);  // `f(x)`, an imported `alias.f(x)`
  if (!functions_.count(name)) return false;
  const std::size_t count = expr.operands.size() - 1;
  if (function(name, count) == nullptr) {
    error("CGA312",
          "function '" + name + "' takes " + arities(name) + ", found " + std::to_string(count),
          callee.range);
  }
  for (std::size_t i = 1; i < expr.operands.size(); ++i) check_expr(*expr.operands[i]);
  return true;
}

const FunctionDecl* Checker::function(std::string_view name, std::size_t count) const {
  auto it = functions_.find(name);
  if (it == functions_.end()) return nullptr;
  auto fn = it->second.find(count);
  return fn == it->second.end() ? nullptr : fn->second;
}

std::string Checker::arities(std::string_view name) const {
  std::set<std::size_t> counts;
  if (auto it = functions_.find(name); it != functions_.end()) {
    for (const auto& [count, fn] : it->second) counts.insert(count);
  }
  return count_text(counts) +
         (counts.size() == 1 && *counts.begin() == 1 ? " argument" : " arguments");
}

bool Checker::is_parameter(std::string_view name) const {
  if (params_ == nullptr) return false;
  for (const std::string& p : *params_) {
    if (p == name) return true;
  }
  return false;
}

// The rules marked `@StartRule` (CityEngine offers them as start rules).
std::vector<std::string> Checker::start_rules() const {
  std::vector<std::string> out;
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) {
      for (const Annotation& a : rule.annotations) {
        if (a.name == "StartRule") out.push_back(rule.predecessor);
      }
    }
  }
  return out;
}

}  // namespace insula::lang::cga::detail
