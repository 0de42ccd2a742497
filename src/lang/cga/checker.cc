// Static semantics of CGA grammars, grammar-level part: attributes, priority sets, rule ids, the
// start symbol and reachability (seed 004 §II, §IV.B; issue 4). Successors and operations are in
// checker_successors.cc, expressions in checker_exprs.cc.
#include "lang/cga/checker.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <functional>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "lang/cga/checker_internal.h"

namespace insula::lang::cga {
namespace detail {
namespace {

// Calls `visit` on every item of `items`, through blocks and (nested) repeat patterns.
template <typename Visit>
void for_each_item(const std::vector<Item>& items, const Visit& visit);

template <typename Visit>
void for_each_item(const std::vector<Branch>& branches, const Visit& visit) {
  for (const Branch& branch : branches) {
    for_each_item(branch.pattern, visit);
    for_each_item(branch.items, visit);
  }
}

template <typename Visit>
void for_each_item(const std::vector<Item>& items, const Visit& visit) {
  for (const Item& item : items) {
    visit(item);
    if (!item.branches.empty()) for_each_item(item.branches, visit);
  }
}

template <typename Visit>
void for_each_symbol(const std::vector<Item>& items, const Visit& visit) {
  for_each_item(items, [&](const Item& item) {
    if (item.kind == ItemKind::kSymbol) visit(item);
  });
}

std::string line_of(const base::Source& source, Range range) {
  return std::to_string(source.locate(range.begin).first);
}

// A rule as named in messages: "rule 3" or, for an unnamed rule, "the rule for Lot".
std::string rule_name(const Rule& rule) {
  if (!rule.id.empty()) return "rule '" + rule.id + "'";
  return "the rule for '" + rule.predecessor + "'";
}

}  // namespace

Checker::Checker(const Grammar& grammar, const base::Source& source, const CheckOptions& options)
    : grammar_(grammar), source_(source), options_(options) {
  known_.insert(options.known_attributes.begin(), options.known_attributes.end());
}

void Checker::error(std::string code, std::string message, Range range) {
  diagnostics_.push_back(
      base::Diagnostic::error(std::move(code), std::move(message), span_of(source_, range)));
}

void Checker::warning(std::string code, std::string message, Range range) {
  diagnostics_.push_back(
      base::Diagnostic::warning(std::move(code), std::move(message), span_of(source_, range)));
}

void Checker::file_error(std::string code, std::string message) {
  diagnostics_.push_back(base::Diagnostic::error(std::move(code), std::move(message),
                                                 base::Span::whole(source_.name())));
}

CheckResult Checker::run() {
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) result_.rules.push_back(CheckedRule{&rule, set.priority});
  }
  declare_rule_arities();
  declare_functions();
  declare_attributes();
  check_functions();
  check_priority_sets();
  check_rule_ids();
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) check_rule(rule);
  }
  check_attribute_cycles();
  choose_start();
  compute_reachability();
  report_unused();

  // Sorted by position; file-wide diagnostics (line 0) first; stable for equal positions so
  // the order of checks decides ties.
  std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                   [](const base::Diagnostic& a, const base::Diagnostic& b) {
                     return std::tie(a.span.line, a.span.column) <
                            std::tie(b.span.line, b.span.column);
                   });
  result_.ok = !base::has_errors(diagnostics_);
  result_.diagnostics = std::move(diagnostics_);
  return std::move(result_);
}

// `attr name = value`: names are unique; defaults may use other attributes (in any order, as in
// CityEngine) but not themselves through a cycle.
void Checker::declare_attributes() {
  collect_set_targets();
  for (const AttrDecl& attr : grammar_.attrs) {
    auto [it, inserted] = attributes_.emplace(attr.name, &attr);
    if (!inserted) {
      error("CGA316",
            "attribute '" + attr.name + "' is declared twice (first at line " +
                line_of(source_, it->second->name_range) + ")",
            attr.name_range);
    }
  }
  for (const AttrDecl& attr : grammar_.attrs) {
    if (attributes_.at(attr.name) != &attr || !attr.value) continue;
    current_attribute_ = &attr;
    check_expr(*attr.value);
    current_attribute_ = nullptr;
  }
}

// `set(name, value)` declares `name` for the shape and its descendants when no `attr` does
// (as the compiler does), so `name` is defined in every expression of the grammar.
void Checker::collect_set_targets() {
  const auto visit = [&](const Item& item) {
    if (item.kind == ItemKind::kOp && item.name == "set" && !item.args.empty()) {
      if (item.args[0]->kind == ExprKind::kString) known_.insert(item.args[0]->text);
      if (const std::string name = dotted_name(*item.args[0]); !name.empty()) known_.insert(name);
    }
  };
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) {
      for (const Alternative& alt : rule.alternatives) for_each_item(alt.items, visit);
    }
  }
}

void Checker::check_attribute_cycles() {
  // Depth-first search over attribute_deps_; a back edge closes a cycle, reported once at the
  // first attribute of the cycle in declaration order.
  enum class Mark { kNew, kActive, kDone };
  std::map<std::string, Mark, std::less<>> marks;
  std::vector<std::string> path;
  std::function<void(const std::string&)> visit = [&](const std::string& name) {
    marks[name] = Mark::kActive;
    path.push_back(name);
    for (const std::string& next : attribute_deps_[name]) {
      const Mark mark = marks.count(next) ? marks[next] : Mark::kNew;
      if (mark == Mark::kActive) {
        const auto begin = std::find(path.begin(), path.end(), next);
        std::string chain;
        for (auto it = begin; it != path.end(); ++it) chain += *it + " -> ";
        chain += next;
        const AttrDecl* decl = attributes_.at(next);
        error("CGA317", "attribute '" + next + "' depends on itself (" + chain + ")",
              decl->name_range);
      } else if (mark == Mark::kNew) {
        visit(next);
      }
    }
    path.pop_back();
    marks[name] = Mark::kDone;
  };
  for (const AttrDecl& attr : grammar_.attrs) {
    if (!marks.count(attr.name)) visit(attr.name);
  }
}

// §VI: a PrioritySet ends with the header of the next one; the same number twice is legal
// syntax but almost always a copy-paste slip, so it is a warning (the rules of both sets keep
// that priority).
void Checker::check_priority_sets() {
  std::map<std::uint32_t, const PrioritySet*> seen;
  for (const PrioritySet& set : grammar_.sets) {
    if (set.implicit) continue;
    auto [it, inserted] = seen.emplace(set.priority, &set);
    if (!inserted) {
      warning("CGA404",
              "priority " + std::to_string(set.priority) + " is declared again (first at line " +
                  line_of(source_, it->second->range) + ")",
              set.range);
    }
  }
}

// §II: "id is a unique identifier for the rule". The issue asks for uniqueness within a priority
// set (an error); the same id in two sets is legal but ambiguous in messages (a warning).
void Checker::check_rule_ids() {
  std::map<std::string, std::pair<const Rule*, std::uint32_t>, std::less<>> global;
  for (const PrioritySet& set : grammar_.sets) {
    std::map<std::string, const Rule*, std::less<>> local;
    for (const Rule& rule : set.rules) {
      if (rule.id.empty()) continue;
      auto [it, inserted] = local.emplace(rule.id, &rule);
      if (!inserted) {
        error("CGA307",
              "duplicate rule id '" + rule.id + "' in priority set " +
                  std::to_string(set.priority) + " (first at line " +
                  line_of(source_, it->second->id_range) + ")",
              rule.id_range);
        continue;
      }
      auto [git, ginserted] = global.emplace(rule.id, std::make_pair(&rule, set.priority));
      if (!ginserted) {
        warning("CGA405",
                "rule id '" + rule.id + "' is also used in priority set " +
                    std::to_string(git->second.second) + " (line " +
                    line_of(source_, git->second.first->id_range) + ")",
                rule.id_range);
      }
    }
  }
}

// Issue 4: the start symbol is the predecessor of the first rule of the lowest priority set
// unless --start names one.
void Checker::choose_start() {
  const PrioritySet* lowest = nullptr;
  for (const PrioritySet& set : grammar_.sets) {
    if (set.rules.empty()) continue;
    if (!lowest || set.priority < lowest->priority) lowest = &set;
  }
  if (!lowest && cityengine() && options_.start.empty()) {  // constants for others to import
    diagnostics_.push_back(
        base::Diagnostic::warning("CGA433", "the file has no rules: none can start a derivation",
                                  base::Span::whole(source_.name())));
    return;
  }
  if (!lowest) {
    file_error("CGA314", "the grammar has no rules");
    return;
  }
  if (options_.start.empty()) {
    result_.start_symbol = lowest->rules.front().predecessor;
    // CityEngine: the first `@StartRule`, else a rule named Lot, else the first rule; only rules
    // without parameters can start (docs/cityengine-dialect.md).
    if (cityengine()) {
      const std::vector<std::string> marked = start_rules();
      const auto startable = [&](const std::string& name) {
        auto it = rule_arities_.find(name);
        return it != rule_arities_.end() && it->second.count(0);
      };
      result_.start_symbol.clear();
      for (const std::string& name : marked) {
        if (result_.start_symbol.empty() && startable(name)) result_.start_symbol = name;
      }
      if (result_.start_symbol.empty() && startable("Lot")) result_.start_symbol = "Lot";
      // Else the first rule no other rule calls (a file's entry point, as the author would pick
      // it in CityEngine's inspector), then the first rule.
      std::unordered_set<std::string_view> called;
      for (const CheckedRule& r : result_.rules) {
        for (const Alternative& alt : r.rule->alternatives) {
          for_each_symbol(alt.items, [&](const Item& item) {
            if (item.name != r.rule->predecessor) called.insert(item.name);
          });
        }
      }
      for (const CheckedRule& r : result_.rules) {
        if (result_.start_symbol.empty() && r.rule->params.empty() &&
            !called.count(r.rule->predecessor)) {
          result_.start_symbol = r.rule->predecessor;
        }
      }
      for (const CheckedRule& r : result_.rules) {
        if (result_.start_symbol.empty() && r.rule->params.empty()) {
          result_.start_symbol = r.rule->predecessor;
        }
      }
      if (result_.start_symbol.empty()) {  // a library, for other files to import
        diagnostics_.push_back(base::Diagnostic::warning(
            "CGA433", "every rule takes parameters: none can start a derivation",
            base::Span::whole(source_.name())));
      }
    }
    return;
  }
  const bool found =
      std::any_of(result_.rules.begin(), result_.rules.end(),
                  [&](const CheckedRule& r) { return r.rule->predecessor == options_.start; });
  if (!found) {
    file_error("CGA314", "the start symbol '" + options_.start + "' is the predecessor of no rule");
    return;
  }
  if (cityengine() && !rule_arities_.at(options_.start).count(0)) {
    file_error("CGA314", "the start rule '" + options_.start +
                             "' takes parameters; a derivation starts from a rule without");
    return;
  }
  result_.start_symbol = options_.start;
}

// Symbols reachable from the start symbol through successors (conditions and probabilities are
// ignored: any of them may hold at derivation time). Rules of unreachable predecessors never
// apply: warning CGA402.
void Checker::compute_reachability() {
  // One walk over the successors (symbols per rule), hash containers: the check stays well
  // under the parse time on large grammars (docs/PERFORMANCE.md).
  std::unordered_map<std::string_view, std::vector<std::size_t>> by_predecessor;
  std::vector<std::vector<std::string_view>> symbols(result_.rules.size());
  std::unordered_set<std::string_view> successors;
  for (std::size_t r = 0; r < result_.rules.size(); ++r) {
    by_predecessor[result_.rules[r].rule->predecessor].push_back(r);
    for (const Alternative& alt : result_.rules[r].rule->alternatives) {
      for_each_symbol(alt.items, [&](const Item& item) {
        if (successors.insert(item.name).second || symbols[r].empty() ||
            symbols[r].back() != item.name) {
          symbols[r].push_back(item.name);
        }
      });
    }
  }
  for (const std::string_view symbol : successors) {
    if (!by_predecessor.count(symbol)) result_.terminals.emplace_back(symbol);
  }
  std::sort(result_.terminals.begin(), result_.terminals.end());
  if (result_.start_symbol.empty()) return;

  std::unordered_set<std::string_view> seen{result_.start_symbol};
  std::vector<std::string_view> queue{result_.start_symbol};
  // Every rule CityEngine offers as a start rule is derived from on some lot.
  const std::vector<std::string> marked = start_rules();
  for (const std::string& start : marked) {
    if (seen.insert(start).second) queue.push_back(start);
  }
  while (!queue.empty()) {
    const std::string_view symbol = queue.back();
    queue.pop_back();
    auto it = by_predecessor.find(symbol);
    if (it == by_predecessor.end()) continue;
    for (const std::size_t r : it->second) {
      result_.rules[r].reachable = true;
      for (const std::string_view next : symbols[r]) {
        if (seen.insert(next).second) queue.push_back(next);
      }
    }
  }
  for (const CheckedRule& checked : result_.rules) {
    if (checked.reachable) continue;
    const Rule& rule = *checked.rule;
    warning("CGA402",
            rule_name(rule) + " is unreachable: '" + rule.predecessor +
                "' is not derived from the start symbol '" + result_.start_symbol + "'",
            rule.id.empty() ? rule.predecessor_range : rule.id_range);
  }
}

void Checker::report_unused() {
  // Read by the derivation itself: the default lot without --lot is lotWidth x lotDepth
  // (derive.cc, default_lot), so declaring them is a use.
  static constexpr std::string_view kReadByDerivation[] = {"lotWidth", "lotDepth"};
  for (const AttrDecl& attr : grammar_.attrs) {
    if (attributes_.at(attr.name) != &attr) continue;
    if (used_attributes_.count(attr.name)) continue;
    // An imported library's attributes (alias.name) need not all be used by one importer.
    if (cityengine() && attr.name.find('.') != std::string::npos) continue;
    if (std::find(std::begin(kReadByDerivation), std::end(kReadByDerivation), attr.name) !=
        std::end(kReadByDerivation)) {
      continue;
    }
    warning("CGA403", "attribute '" + attr.name + "' is never used", attr.name_range);
  }
}

}  // namespace detail

std::vector<const Rule*> CheckResult::reachable_rules() const {
  std::vector<const Rule*> out;
  for (const CheckedRule& rule : rules) {
    if (rule.reachable) out.push_back(rule.rule);
  }
  return out;
}

CheckResult check(const Grammar& grammar, const base::Source& source, const CheckOptions& options) {
  return detail::Checker(grammar, source, options).run();
}

std::optional<std::string> canonical_axis(std::string_view text) {
  static constexpr std::string_view kAxes[] = {"x", "y", "z", "xy", "xz", "yz", "xyz"};
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string_view axis : kAxes) {
    if (lower == axis) return lower;
  }
  return std::nullopt;
}

std::optional<CompTypeSpelling> comp_type_of(std::string_view text) {
  struct Entry {
    std::string_view text;
    CompType type;
    bool nonstandard;
  };
  // §II: "faces", "edges", "vertices's", "side faces"; §VI: "faces", "edges", "verticles",
  // "sidefaces" and the example CS("edge", 3); CityEngine: "f", "e", "v", "vertices".
  static constexpr Entry kTypes[] = {
      {"faces", CompType::kFaces, false},         {"f", CompType::kFaces, false},
      {"edges", CompType::kEdges, false},         {"e", CompType::kEdges, false},
      {"vertices", CompType::kVertices, false},   {"v", CompType::kVertices, false},
      {"sidefaces", CompType::kSideFaces, false}, {"face", CompType::kFaces, true},
      {"edge", CompType::kEdges, true},           {"vertex", CompType::kVertices, true},
      {"verticles", CompType::kVertices, true},   {"vertices's", CompType::kVertices, true},
      {"side faces", CompType::kSideFaces, true}, {"side_faces", CompType::kSideFaces, true},
      {"sideface", CompType::kSideFaces, true},   {"fe", CompType::kFaceEdges, false},
  };
  for (const Entry& entry : kTypes) {
    if (entry.text == text) return CompTypeSpelling{entry.type, entry.nonstandard};
  }
  return std::nullopt;
}

std::string_view comp_type_name(CompType type) {
  switch (type) {
    case CompType::kFaces:
      return "faces";
    case CompType::kEdges:
      return "edges";
    case CompType::kVertices:
      return "vertices";
    case CompType::kSideFaces:
      return "sidefaces";
    case CompType::kFaceEdges:
      return "fe";
  }
  return "faces";
}

std::string dump_checked(const Grammar& grammar, const CheckResult& result) {
  std::string out = "start " + result.start_symbol + "\n";
  out += std::string("ok ") + (result.ok ? "yes" : "no") + "\n";
  for (const AttrDecl& attr : grammar.attrs) out += "attr " + attr.name + "\n";
  for (const CheckedRule& checked : result.rules) {
    const Rule& rule = *checked.rule;
    out += "rule " + (rule.id.empty() ? std::string("-") : rule.id) + " priority " +
           std::to_string(checked.priority) + " " + rule.predecessor + " alternatives " +
           std::to_string(rule.alternatives.size()) +
           (checked.reachable ? " reachable" : " unreachable") + "\n";
  }
  for (const std::string& terminal : result.terminals) out += "terminal " + terminal + "\n";
  for (const base::Diagnostic& d : result.diagnostics) out += base::render(d) + "\n";
  return out;
}

}  // namespace insula::lang::cga
