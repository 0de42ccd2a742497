#include "lang/cga/buildinggen_xml.h"

#include <pugixml.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "lang/cga/printer.h"
#include "lang/cga/xml_text.h"

namespace insula::lang::cga {
namespace {

bool is_size_literal(const Expr& e) {
  if (e.kind == ExprKind::kNumber) return true;
  return e.kind == ExprKind::kUnary && e.unary_op == UnaryOp::kRelative &&
         e.operands[0]->kind == ExprKind::kNumber;
}

// Fig. 16 writes proportions as "1.0"; relative sizes keep the language's `r` suffix.
std::string size_text(const Expr& e) {
  if (e.kind == ExprKind::kUnary) return number_text(e.operands[0]->number) + "r";
  std::string text = number_text(e.number);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

bool is_scope_rule(const Item& it) {
  if (it.kind == ItemKind::kPush || it.kind == ItemKind::kPop) return true;
  if (it.kind != ItemKind::kOp) return false;
  return it.op == OpKind::kTranslate || it.op == OpKind::kScale || it.op == OpKind::kRotate ||
         it.op == OpKind::kInsert;
}

bool is_component_split(const Item& it) {
  return it.kind == ItemKind::kOp &&
         (it.op == OpKind::kComp || (it.op == OpKind::kGeneric && it.name == "comp"));
}

bool is_split_or_repeat(const Item& it) {
  return it.kind == ItemKind::kOp && (it.op == OpKind::kSplit || it.op == OpKind::kRepeat);
}

// The axis of a BS/RR as written, when BuildingGen has proportions for it ("X" or "Y").
std::string split_axis(const Item& it) {
  if (it.args.empty() || it.args[0]->kind != ExprKind::kString) return {};
  const std::string& axis = it.args[0]->text;
  return axis == "X" || axis == "Y" ? axis : std::string();
}

bool mentions_symbol(const std::vector<Item>& items, const std::string& symbol);

bool mentions_symbol(const std::vector<Branch>& branches, const std::string& symbol) {
  for (const Branch& b : branches) {
    if (mentions_symbol(b.pattern, symbol) || mentions_symbol(b.items, symbol)) return true;
  }
  return false;
}

bool mentions_symbol(const std::vector<Item>& items, const std::string& symbol) {
  for (const Item& it : items) {
    if (it.kind == ItemKind::kSymbol && it.name == symbol) return true;
    if (mentions_symbol(it.branches, symbol)) return true;
  }
  return false;
}

class Checker {
 public:
  explicit Checker(const base::Source& source) : source_(source) {}

  std::vector<base::Diagnostic> run(const Grammar& g) {
    for (const AttrDecl& a : g.attrs) {
      error("CGA507",
            "attribute '" + a.name +
                "' cannot be expressed in BuildingGen XML (it has no "
                "attributes)",
            a.range);
    }
    if (g.sets.size() > 1) {
      error("CGA504",
            "there can be only one priority set in BuildingGen XML (found " +
                std::to_string(g.sets.size()) + ")",
            g.sets[1].range);
    }
    bool facade = false;
    for (const PrioritySet& set : g.sets) {
      for (const Rule& r : set.rules) {
        rule(r);
        facade = facade || r.predecessor == kBuildingGenStartSymbol;
        for (const Alternative& alt : r.alternatives) {
          facade = facade || mentions_symbol(alt.items, kBuildingGenStartSymbol);
        }
      }
    }
    if (!facade) {
      diags_.push_back(
          base::Diagnostic::error("CGA502",
                                  std::string("the default ") + kBuildingGenStartSymbol +
                                      " shape is not defined (BuildingGen derives from it)",
                                  base::Span::at(source_.name(), 1, 1)));
    }
    std::stable_sort(diags_.begin(), diags_.end(), [](const auto& a, const auto& b) {
      return std::pair(a.span.line, a.span.column) < std::pair(b.span.line, b.span.column);
    });
    return std::move(diags_);
  }

 private:
  void error(const char* code, std::string message, Range range) {
    diags_.push_back(base::Diagnostic::error(code, std::move(message), span_of(source_, range)));
  }

  void text(const std::string& value, Range range) {
    if (!is_xml_text(value)) {
      error("CGA508", "text with control characters or invalid UTF-8 cannot be written to XML",
            range);
    }
  }

  void rule(const Rule& r) {
    if (r.predecessor.empty()) error("CGA505", "every rule must have a predecessor shape", r.range);
    if (!r.params.empty()) {
      error("CGA507",
            "rule parameters cannot be expressed in BuildingGen XML ('" + r.predecessor + "')",
            r.range);
    }
    if (r.condition) text(print(*r.condition), r.condition->range);
    for (const Alternative& alt : r.alternatives) alternative(alt);
  }

  void alternative(const Alternative& alt) {
    if (alt.probability) text(print(*alt.probability), alt.probability->range);
    bool scoped = false;
    for (std::size_t i = 0; i < alt.items.size(); ++i) {
      const Item& it = alt.items[i];
      if (is_split_or_repeat(it) && alt.items.size() > 1) {
        error("CGA507",
              "'" + it.name + "' must be the whole successor of a rule part in BuildingGen XML",
              it.range);
      }
      if (it.kind == ItemKind::kEmpty && scoped) {
        error("CGA501", "empty shapes cannot have a scope", it.range);
      }
      scoped = scoped || is_scope_rule(it);
      item(it, true);
    }
  }

  // `top` is false inside a split's branches, where only single shapes are allowed.
  void item(const Item& it, bool top) {
    if (is_scope_rule(it)) {
      error("CGA503", "scope rules are not acceptable in BuildingGen XML ('" + it.name + "')",
            it.range);
      return;
    }
    if (is_component_split(it)) {
      error("CGA506", "component splits are not supported by BuildingGen XML ('" + it.name + "')",
            it.range);
      return;
    }
    if (it.kind != ItemKind::kOp) return;
    if (it.op == OpKind::kPredefined) {
      if (!it.args.empty()) text(it.args[0]->text, it.args[0]->range);
      return;
    }
    if (it.op == OpKind::kGeneric) {
      error("CGA507", "operation '" + it.name + "' cannot be expressed in BuildingGen XML",
            it.range);
      return;
    }
    if (!top) {
      error("CGA507",
            "a nested '" + it.name +
                "' cannot be expressed in BuildingGen XML (Elements are "
                "shapes)",
            it.range);
      return;
    }
    split(it);
  }

  void split(const Item& it) {
    if (split_axis(it).empty() && !it.args.empty()) {
      error("CGA507", "BuildingGen XML splits along \"X\" or \"Y\" only", it.args[0]->range);
    }
    for (std::size_t i = 1; i < it.args.size(); ++i) {
      if (!is_size_literal(*it.args[i])) {
        error("CGA507",
              "BuildingGen XML sizes are numbers or relative numbers ('2', '1r'), found '" +
                  print(*it.args[i]) + "'",
              it.args[i]->range);
      }
    }
    for (const Branch& b : it.branches) {
      if (b.repeat) {
        error("CGA507", "repeat patterns cannot be expressed in BuildingGen XML", b.range);
      } else if (b.key) {
        error("CGA507", "keyed branches cannot be expressed in BuildingGen XML", b.key->range);
      } else if (b.items.size() != 1) {
        error("CGA507", "each branch must be exactly one shape in BuildingGen XML", b.range);
      } else {
        item(b.items[0], false);
      }
    }
  }

  const base::Source& source_;
  std::vector<base::Diagnostic> diags_;
};

class Writer {
 public:
  std::string run(const Grammar& g) {
    pugi::xml_document doc;
    pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "utf-8";
    pugi::xml_node root = doc.append_child("BuildingGen");
    pugi::xml_node rules = root.append_child("Rules");
    if (!g.sets.empty()) {
      const PrioritySet& set = g.sets.front();
      if (!set.implicit) rules.append_attribute("priority") = set.priority;
      for (const Rule& r : set.rules) predecessors_.insert(r.predecessor);
      for (const Rule& r : set.rules) rule(rules, r);
    }
    pugi::xml_node terminals = root.append_child("Terminals");
    for (const std::string& name : terminal_order_) {
      if (name.rfind("file:", 0) == 0) {
        terminals.append_child("predefined-shape").append_attribute("file") = name.c_str() + 5;
      } else {
        terminals.append_child(name.c_str());
      }
    }
    std::ostringstream out;
    doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
  }

 private:
  void rule(pugi::xml_node rules, const Rule& r) {
    auto [group, inserted] = groups_.emplace(r.predecessor, pugi::xml_node());
    if (inserted) group->second = rules.append_child(r.predecessor.c_str());
    pugi::xml_node node = group->second.append_child(("R" + r.id).c_str());
    if (r.condition) node.append_attribute("condition") = print(*r.condition).c_str();
    for (const Alternative& alt : r.alternatives) alternative(node, alt);
  }

  void alternative(pugi::xml_node parent, const Alternative& alt) {
    const Item& first = alt.items.front();
    pugi::xml_node node;
    if (is_split_or_repeat(first)) {
      const bool fixed = first.op == OpKind::kSplit;
      node = parent.append_child(fixed ? "Fixed" : "Repeat");
      if (first.name != (fixed ? "BS" : "RR")) {
        node.append_attribute("operation") = first.name.c_str();
      }
    } else {
      node = parent.append_child("Substitute");
    }
    if (alt.arrow != "~>") node.append_attribute("arrow") = alt.arrow.c_str();
    if (alt.probability) node.append_attribute("probability") = print(*alt.probability).c_str();
    if (!is_split_or_repeat(first)) {
      elements(node, alt.items);
      return;
    }
    const std::string axis = split_axis(first);
    pugi::xml_node x = node.append_child("xProportions");
    pugi::xml_node y = node.append_child("yProportions");
    pugi::xml_node sizes = axis == "X" ? x : y;
    const std::string prefix = axis == "X" ? "xr" : "yr";
    for (std::size_t i = 1; i < first.args.size(); ++i) {
      sizes.append_attribute((prefix + std::to_string(i)).c_str()) =
          size_text(*first.args[i]).c_str();
    }
    pugi::xml_node list = node.append_child("Elements");
    for (const Branch& b : first.branches) shape(list, b.items.front());
  }

  void elements(pugi::xml_node parent, const std::vector<Item>& items) {
    pugi::xml_node list = parent.append_child("Elements");
    for (const Item& it : items) shape(list, it);
  }

  void shape(pugi::xml_node list, const Item& it) {
    if (it.kind == ItemKind::kEmpty) {
      list.append_child("empty-shape");
    } else if (it.kind == ItemKind::kSymbol) {
      list.append_child(it.name.c_str());
      if (!predecessors_.count(it.name)) terminal(it.name);
    } else {
      const std::string& file = it.args.front()->text;
      list.append_child("predefined-shape").append_attribute("file") = file.c_str();
      terminal("file:" + file);
    }
  }

  void terminal(const std::string& key) {
    if (seen_terminals_.insert(key).second) terminal_order_.push_back(key);
  }

  std::map<std::string, pugi::xml_node> groups_;
  std::set<std::string> predecessors_;
  std::set<std::string> seen_terminals_;
  std::vector<std::string> terminal_order_;
};

}  // namespace

std::vector<base::Diagnostic> check_buildinggen(const Grammar& grammar,
                                                const base::Source& source) {
  return Checker(source).run(grammar);
}

base::Result<std::string> buildinggen_xml(const Grammar& grammar, const base::Source& source) {
  std::vector<base::Diagnostic> diagnostics = check_buildinggen(grammar, source);
  if (!diagnostics.empty()) return base::Result<std::string>::failure(std::move(diagnostics));
  return Writer().run(grammar);
}

}  // namespace insula::lang::cga
