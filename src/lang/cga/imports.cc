#include "lang/cga/imports.h"

#include <algorithm>
#include <set>
#include <utility>

#include "lang/cga/operations.h"
#include "lang/cga/parser.h"

namespace insula::lang::cga {
namespace {

// ---- moving an imported file's ranges to its place in the combined source

void shift(Range& r, std::uint32_t by) {
  r.begin += by;
  r.end += by;
}

void shift(Expr& e, std::uint32_t by) {
  shift(e.range, by);
  for (ExprPtr& operand : e.operands) shift(*operand, by);
}

void shift(std::vector<Item>& items, std::uint32_t by);

void shift(Branch& b, std::uint32_t by) {
  shift(b.range, by);
  if (b.key) shift(*b.key, by);
  for (Branch& part : b.pattern) shift(part, by);
  shift(b.items, by);
}

void shift(std::vector<Item>& items, std::uint32_t by) {
  for (Item& item : items) {
    shift(item.range, by);
    for (ExprPtr& arg : item.args) shift(*arg, by);
    for (Branch& b : item.branches) shift(b, by);
  }
}

void shift(std::vector<Annotation>& annotations, std::uint32_t by) {
  for (Annotation& a : annotations) {
    shift(a.range, by);
    for (ExprPtr& arg : a.args) shift(*arg, by);
  }
}

void shift(Rule& rule, std::uint32_t by) {
  shift(rule.range, by);
  shift(rule.id_range, by);
  shift(rule.predecessor_range, by);
  if (rule.condition) shift(*rule.condition, by);
  shift(rule.annotations, by);
  for (Alternative& alt : rule.alternatives) {
    shift(alt.range, by);
    shift(alt.items, by);
  }
}

void shift(Grammar& g, std::uint32_t by) {
  for (ImportDecl& i : g.imports) {
    shift(i.range, by);
    shift(i.alias_range, by);
    shift(i.path_range, by);
    for (auto& [name, value] : i.overrides) {
      if (value) shift(*value, by);
    }
    for (Rule& rule : i.rule_overrides) shift(rule, by);
    shift(i.annotations, by);
  }
  for (AttrDecl& a : g.attrs) {
    shift(a.range, by);
    shift(a.name_range, by);
    if (a.value) shift(*a.value, by);
    shift(a.annotations, by);
  }
  for (FunctionDecl& f : g.functions) {
    shift(f.range, by);
    shift(f.name_range, by);
    shift(*f.body, by);
    shift(f.annotations, by);
  }
  for (PrioritySet& set : g.sets) {
    shift(set.range, by);
    for (Rule& rule : set.rules) shift(rule, by);
  }
}

// ---- giving an imported grammar's names their alias

class Renamer {
 public:
  Renamer(const Grammar& g, std::string alias) : prefix_(std::move(alias) + ".") {
    for (const AttrDecl& a : g.attrs) values_.insert(a.name);
    for (const FunctionDecl& f : g.functions) values_.insert(f.name);
    for (const PrioritySet& set : g.sets) {
      for (const Rule& rule : set.rules) rules_.insert(rule.predecessor);
    }
  }

  void run(Grammar& g) {
    for (AttrDecl& a : g.attrs) {
      a.name = prefix_ + a.name;
      if (a.value) expr(*a.value);
    }
    for (FunctionDecl& f : g.functions) {
      f.name = prefix_ + f.name;
      params_ = &f.params;
      expr(*f.body);
      params_ = nullptr;
    }
    for (PrioritySet& set : g.sets) {
      for (Rule& rule : set.rules) {
        rule.predecessor = prefix_ + rule.predecessor;
        // The imported file's start rules are not the importing file's.
        std::erase_if(rule.annotations, [](const Annotation& a) { return a.name == "StartRule"; });
        params_ = &rule.params;
        if (rule.condition) expr(*rule.condition);
        for (Alternative& alt : rule.alternatives) items(alt.items);
        params_ = nullptr;
      }
    }
  }

 private:
  bool is_param(const std::string& name) const {
    return params_ != nullptr &&
           std::find(params_->begin(), params_->end(), name) != params_->end();
  }

  // A name of the imported file's (possibly dotted: its own imports) becomes `alias.name`.
  void expr(Expr& e) {
    if (e.kind == ExprKind::kIdent || e.kind == ExprKind::kMember) {
      const std::string name = dotted_name(e);
      if (!name.empty() && values_.count(name) && !is_param(name)) {
        e.kind = ExprKind::kIdent;
        e.text = prefix_ + name;
        e.operands.clear();
        return;
      }
    }
    for (ExprPtr& operand : e.operands) expr(*operand);
  }

  void items(std::vector<Item>& list) {
    for (Item& item : list) {
      if (item.kind == ItemKind::kSymbol && rules_.count(item.name))
        item.name = prefix_ + item.name;
      for (ExprPtr& arg : item.args) expr(*arg);
      const OperationInfo* op = find_operation(item.name);
      for (Branch& b : item.branches) branch(b, op);
    }
  }

  // A key that is a selector word of the operation stays that word even when the file has an
  // attribute of its name (Esri's massmodeling_01: `attr shape` and `shapeL(...) { shape : A }`).
  void branch(Branch& b, const OperationInfo* op) {
    const bool selector =
        b.key && op != nullptr && b.key->kind == ExprKind::kIdent && is_selector(*op, b.key->text);
    if (b.key && !selector) expr(*b.key);
    for (Branch& part : b.pattern) branch(part, op);
    items(b.items);
  }

  std::string prefix_;
  std::set<std::string> values_;
  std::set<std::string> rules_;
  const std::vector<std::string>* params_ = nullptr;
};

// Whether `e` reads the name `name` (a dotted one: `Zoning.Floor_Count_Min`).
bool mentions(const Expr& e, const std::string& name) {
  if ((e.kind == ExprKind::kIdent || e.kind == ExprKind::kMember) && dotted_name(e) == name) {
    return true;
  }
  return std::any_of(e.operands.begin(), e.operands.end(),
                     [&](const ExprPtr& operand) { return mentions(*operand, name); });
}

// Propagation: the imported attribute `alias.x` takes the importer's `x` unless protected or
// the importer's `x` reads `alias.x` (Esri's `attr Floor_Count_Min = Zoning.Floor_Count_Min`:
// the library's default, not a cycle); an override `(x = expr)` gives it `expr`.
void propagate(Grammar& imported, const ImportDecl& decl, const Grammar& importer) {
  const std::string prefix = decl.alias + ".";
  for (AttrDecl& a : imported.attrs) {
    const std::string name = a.name.substr(prefix.size());
    bool overridden = false;
    for (const auto& [key, value] : decl.overrides) {
      if (key == name && value) {
        a.value = clone(*value);
        overridden = true;
      }
    }
    if (overridden) continue;
    const bool protect_all =
        decl.has_list && decl.overrides.empty() && decl.protected_attrs.empty();
    const bool protect =
        protect_all || std::find(decl.protected_attrs.begin(), decl.protected_attrs.end(), name) !=
                           decl.protected_attrs.end();
    if (protect) continue;
    for (const AttrDecl& own : importer.attrs) {
      if (own.name != name || (own.value && mentions(*own.value, a.name))) continue;
      auto ref = std::make_unique<Expr>();
      ref->kind = ExprKind::kIdent;
      ref->text = name;
      ref->range = decl.range;
      a.value = std::move(ref);
    }
  }
}

template <typename T>
void append(std::vector<T>& into, std::vector<T>& from) {
  for (T& x : from) into.push_back(std::move(x));
}

class Resolver {
 public:
  Resolver(base::Source& source, const ImportLoader& load) : source_(source), load_(load) {}

  std::vector<base::Diagnostic> run(Grammar& g) {
    std::vector<std::string> chain{g.file};
    resolve(g, chain);
    return std::move(diags_);
  }

 private:
  void error(std::string code, std::string message, Range range) {
    diags_.push_back(
        base::Diagnostic::error(std::move(code), std::move(message), span_of(source_, range)));
  }

  void resolve(Grammar& g, std::vector<std::string>& chain) {
    for (ImportDecl& decl : g.imports) {
      std::string why;
      std::optional<ImportedFile> file = load_(decl.path, g.file, why);
      if (!file) {
        error("CGA340", "cannot import \"" + decl.path + "\": " + why, decl.path_range);
        continue;
      }
      if (std::find(chain.begin(), chain.end(), file->name) != chain.end()) {
        error("CGA341", "\"" + decl.path + "\" imports itself (through " + chain.back() + ")",
              decl.path_range);
        continue;
      }
      if (static_cast<int>(chain.size()) > kMaxImportDepth) {
        error("CGA342", "imports nested deeper than " + std::to_string(kMaxImportDepth),
              decl.path_range);
        continue;
      }
      const base::Source own(file->name, file->text);
      base::Result<Grammar> parsed = parse(own, Dialect::kCityEngine);
      for (const base::Diagnostic& d : parsed.diagnostics()) diags_.push_back(d);
      if (!parsed.ok()) continue;
      Grammar imported = std::move(parsed.value());
      const auto base = static_cast<std::uint32_t>(source_.append(file->name, file->text));
      shift(imported, base);
      chain.push_back(file->name);
      resolve(imported, chain);
      chain.pop_back();
      Renamer(imported, decl.alias).run(imported);
      redefine(imported, decl);
      propagate(imported, decl, g);
      merge(g, imported);
    }
  }

  // `import a : "f.cga" (Roof(x) --> ...)`: the rule takes the place of the imported file's
  // `Roof` (CityEngine's extension rules), its body in the importing file's names.
  void redefine(Grammar& imported, ImportDecl& decl) {
    for (Rule& rule : decl.rule_overrides) {
      const std::string name = rule.predecessor;
      rule.predecessor = decl.alias + "." + name;
      bool found = false;
      for (PrioritySet& set : imported.sets) {
        found =
            std::erase_if(set.rules,
                          [&](const Rule& r) { return r.predecessor == rule.predecessor; }) > 0 ||
            found;
      }
      if (!found) {
        error("CGA343", "\"" + decl.path + "\" has no rule '" + name + "' to redefine",
              rule.predecessor_range);
        continue;
      }
      if (imported.sets.empty()) imported.sets.emplace_back().implicit = true;
      imported.sets.front().rules.push_back(std::move(rule));
    }
    decl.rule_overrides.clear();
  }

  static void merge(Grammar& into, Grammar& imported) {
    append(into.attrs, imported.attrs);
    append(into.functions, imported.functions);
    // A rule the importing file writes under the imported name (`volume.Slab --> ...`) takes
    // the place of the imported file's own (CityEngine's rule override through an import).
    std::set<std::string> own;
    for (const PrioritySet& set : into.sets) {
      for (const Rule& rule : set.rules) own.insert(rule.predecessor);
    }
    if (into.sets.empty()) {
      PrioritySet set;
      set.implicit = true;
      into.sets.push_back(std::move(set));
    }
    for (PrioritySet& set : imported.sets) {
      std::erase_if(set.rules, [&](const Rule& r) { return own.count(r.predecessor) > 0; });
      append(into.sets.front().rules, set.rules);
    }
  }

  base::Source& source_;
  const ImportLoader& load_;
  std::vector<base::Diagnostic> diags_;
};

}  // namespace

std::vector<base::Diagnostic> resolve_imports(Grammar& grammar, base::Source& source,
                                              const ImportLoader& load) {
  if (grammar.imports.empty()) return {};
  return Resolver(source, load).run(grammar);
}

}  // namespace insula::lang::cga
