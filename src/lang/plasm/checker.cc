#include "lang/plasm/checker.h"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "base/format.h"
#include "lang/plasm/builtins.h"

namespace insula::lang::plasm {
namespace {

constexpr int kNoNode = -1;

// What a name is bound to in one scope.
struct Entry {
  std::string text;    // as written where it was defined
  Range range;         // where it was defined
  int node = kNoNode;  // a value binding's node in the dependency graph
};

struct Scope {
  const Scope* parent = nullptr;
  std::map<std::string, Entry> names;  // by case-folded key
};

class Checker {
 public:
  explicit Checker(const base::Source& source) : source_(source) {}

  CheckResult run(const Program& program) {
    CheckResult result;
    Scope top;
    for (const Statement& st : program.statements) {
      if (!st.is_def) {
        ++result.expressions;
        continue;
      }
      (st.def.is_function() ? result.functions : result.values) += 1;
      if (const auto it = top.names.find(st.def.key); it != top.names.end()) {
        report("PSM302",
               "'" + st.def.name + "' is already defined at line " + line_of(it->second.range) +
                   " (names are case-insensitive)",
               st.def.name_range);
        continue;
      }
      top.names.emplace(st.def.key, entry_of(st.def));
    }
    for (const Statement& st : program.statements) {
      if (st.is_def) {
        definition(st.def, top, node_of(top, st.def));
      } else {
        expr(*st.expr, top, kNoNode);
      }
    }
    find_cycles();
    std::stable_sort(diags_.begin(), diags_.end(), [](const auto& a, const auto& b) {
      return std::pair(a.span.line, a.span.column) < std::pair(b.span.line, b.span.column);
    });
    result.ok = !base::has_errors(diags_);
    result.diagnostics = std::move(diags_);
    return result;
  }

 private:
  void report(std::string code, std::string message, Range range) {
    diags_.push_back(
        base::Diagnostic::error(std::move(code), std::move(message), span_of(source_, range)));
  }
  std::string line_of(Range range) const {
    return std::to_string(source_.locate(range.begin).first);
  }

  // A new entry for `def`; value bindings become nodes of the dependency graph.
  Entry entry_of(const Def& def) {
    Entry entry{def.name, def.name_range, kNoNode};
    if (!def.is_function()) {
      entry.node = static_cast<int>(nodes_.size());
      nodes_.push_back(&def);
      edges_.emplace_back();
    }
    return entry;
  }
  // The node of `def` as registered in `scope` (kNoNode for functions and duplicates).
  static int node_of(const Scope& scope, const Def& def) {
    const auto it = scope.names.find(def.key);
    if (it == scope.names.end() || it->second.range.begin != def.name_range.begin) return kNoNode;
    return it->second.node;
  }

  void definition(const Def& def, const Scope& outer, int node) {
    Scope inner{&outer, {}};
    // A predicate sees the parameters of the earlier groups: they are bound when it runs.
    Scope earlier{&outer, {}};
    for (const ParamGroup& group : def.groups) {
      for (const ParamDecl& decl : group.decls) {
        if (decl.predicate) expr(*decl.predicate, earlier, kNoNode);
        for (const Param& p : decl.names) {
          if (const auto it = inner.names.find(p.key); it != inner.names.end()) {
            report("PSM304", "parameter '" + p.text + "' of '" + def.name + "' is declared twice",
                   p.range);
            continue;
          }
          inner.names.emplace(p.key, Entry{p.text, p.range, kNoNode});
        }
      }
      earlier.names = inner.names;
    }
    for (const Def& local : def.locals) {
      if (const auto it = inner.names.find(local.key); it != inner.names.end()) {
        report("PSM303",
               "'" + local.name + "' is already defined in '" + def.name + "' at line " +
                   line_of(it->second.range),
               local.name_range);
        continue;
      }
      inner.names.emplace(local.key, entry_of(local));
    }
    expr(*def.body, inner, node);
    for (const Def& local : def.locals) definition(local, inner, node_of(inner, local));
  }

  const Entry* resolve(const Scope& scope, const std::string& key) const {
    for (const Scope* s = &scope; s != nullptr; s = s->parent) {
      if (const auto it = s->names.find(key); it != s->names.end()) return &it->second;
    }
    return nullptr;
  }

  // Resolves a use of a name: an edge in the dependency graph, or PSM301. Returns the builtin it
  // names when no definition hides it.
  const Builtin* use(const std::string& text, const std::string& key, Range range,
                     const Scope& scope, int node) {
    if (const Entry* entry = resolve(scope, key)) {
      if (node != kNoNode && entry->node != kNoNode) edges_[node].push_back(entry->node);
      return nullptr;
    }
    if (const Builtin* builtin = find_builtin(key)) return builtin;
    std::string message = "unknown name '" + text + "'";
    if (const std::string near = nearest(scope, key); !near.empty()) {
      message += "; did you mean '" + near + "'?";
    }
    report("PSM301", message, range);
    return nullptr;
  }

  // The visible name nearest to `key`: within two edits (one for names of one or two letters),
  // then preferring the same first letter, inner scopes, and alphabetical order.
  std::string nearest(const Scope& scope, const std::string& key) const {
    const std::size_t limit = key.size() <= 2 ? 1 : 2;
    std::tuple<std::size_t, bool, int, std::string> best{limit + 1, true, 0, ""};
    std::string found;
    const auto consider = [&](const std::string& candidate, const std::string& shown, int depth) {
      const std::tuple<std::size_t, bool, int, std::string> cost{
          base::edit_distance(key, candidate), candidate[0] != key[0], depth, candidate};
      if (cost < best) {
        best = cost;
        found = shown;
      }
    };
    int depth = 0;
    for (const Scope* s = &scope; s != nullptr; s = s->parent, ++depth) {
      for (const auto& [candidate, entry] : s->names) consider(candidate, entry.text, depth);
    }
    for (const Builtin& b : builtins()) consider(std::string(b.name), std::string(b.name), depth);
    return found;
  }

  void arity(const Builtin* builtin, std::size_t count, Range range, bool infix) {
    if (builtin == nullptr || builtin->arity == kAnyArity) return;
    if (count == static_cast<std::size_t>(builtin->arity)) return;
    const std::string name(builtin->name);
    if (infix) {
      report("PSM306",
             "'" + name + "' takes a sequence of " + std::to_string(builtin->arity) +
                 " values, so it cannot be used as an infix (binary) function",
             range);
      return;
    }
    report("PSM306",
           "'" + name + "' takes a sequence of " + std::to_string(builtin->arity) +
               " values, found " + std::to_string(count),
           range);
  }

  void expr(const Expr& e, const Scope& scope, int node) {
    switch (e.kind) {
      case ExprKind::kName:
        use(e.text, e.key, e.range, scope, node);
        return;
      case ExprKind::kInfix:
        arity(use(e.text, e.key, e.name_range, scope, node), 2, e.name_range, true);
        break;
      case ExprKind::kApply: {
        const Expr& f = *e.operands[0];
        const Expr& x = *e.operands[1];
        if (f.kind == ExprKind::kName && x.kind == ExprKind::kSequence) {
          arity(use(f.text, f.key, f.range, scope, node), x.operands.size(), e.range, false);
          expr(x, scope, node);
          return;
        }
        break;
      }
      default:
        break;
    }
    for (const ExprPtr& operand : e.operands) expr(*operand, scope, node);
  }

  // A value binding that needs its own value is an error, not a hang (issue 13): a cycle in the
  // graph of value bindings, found by an iterative depth-first search in source order.
  void find_cycles() {
    enum Color { kWhite, kGray, kBlack };
    std::vector<Color> color(nodes_.size(), kWhite);
    std::vector<bool> reported(nodes_.size(), false);
    for (std::size_t root = 0; root < nodes_.size(); ++root) {
      if (color[root] != kWhite) continue;
      std::vector<std::pair<int, std::size_t>> stack{{static_cast<int>(root), 0}};
      color[root] = kGray;
      while (!stack.empty()) {
        auto& [n, next] = stack.back();
        if (next == edges_[n].size()) {
          color[n] = kBlack;
          stack.pop_back();
          continue;
        }
        const int m = edges_[n][next++];
        if (color[m] == kWhite) {
          color[m] = kGray;
          stack.emplace_back(m, 0);
        } else if (color[m] == kGray && !reported[m]) {
          cycle(stack, m, reported);
        }
      }
    }
  }

  void cycle(const std::vector<std::pair<int, std::size_t>>& stack, int start,
             std::vector<bool>& reported) {
    std::string path;
    bool in = false;
    for (const auto& [n, next] : stack) {
      in = in || n == start;
      if (!in) continue;
      reported[n] = true;
      path += nodes_[n]->name + " -> ";
    }
    path += nodes_[start]->name;
    report("PSM305", "the value of '" + nodes_[start]->name + "' depends on itself: " + path,
           nodes_[start]->name_range);
  }

  const base::Source& source_;
  std::vector<base::Diagnostic> diags_;
  std::vector<const Def*> nodes_;
  std::vector<std::vector<int>> edges_;
};

}  // namespace

CheckResult check(const Program& program, const base::Source& source) {
  return Checker(source).run(program);
}

}  // namespace insula::lang::plasm
