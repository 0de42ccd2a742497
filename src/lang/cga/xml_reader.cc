#include "lang/cga/xml_reader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "lang/cga/buildinggen_xml.h"
#include "lang/cga/parser.h"
#include "lang/cga/printer.h"

namespace insula::lang::cga {
namespace {

// Thrown after an error is recorded: the first structural error ends the read (the XML is
// machine-written, so one precise message is more useful than a cascade). Never leaves this file.
struct Abort {};

bool is_natural(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

ExprPtr number(double value) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::kNumber;
  e->number = value;
  return e;
}

ExprPtr string_expr(std::string text) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::kString;
  e->text = std::move(text);
  return e;
}

class Reader {
 public:
  explicit Reader(const base::Source& source) : source_(source) {}

  base::Result<Grammar> run() {
    try {
      read();
    } catch (const Abort&) {
      return base::Result<Grammar>::failure(std::move(diags_));
    }
    return base::Result<Grammar>(std::move(grammar_));
  }

 private:
  [[noreturn]] void fail(const char* code, const std::string& message, std::size_t offset) {
    const auto [line, column] = source_.locate(offset);
    diags_.push_back(
        base::Diagnostic::error(code, message, base::Span::at(source_.name(), line, column)));
    throw Abort{};
  }

  // pugixml reports the offset of an element's name; point at its '<'.
  std::size_t offset_of(pugi::xml_node node) const {
    const std::ptrdiff_t at = node.offset_debug();
    if (at <= 0) return 0;
    const auto offset = static_cast<std::size_t>(at);
    return source_.text()[offset - 1] == '<' ? offset - 1 : offset;
  }

  // The offset of the value of attribute `name` in the start tag of `node` (the element when the
  // text cannot be found, e.g. after an entity in an earlier attribute).
  std::size_t offset_of(pugi::xml_node node, const char* name) const {
    const std::string& text = source_.text();
    const std::size_t start = offset_of(node);
    const std::size_t end = text.find('>', start);
    std::size_t at = start;
    const std::size_t length = std::strlen(name);
    while ((at = text.find(name, at + 1)) != std::string::npos && at < end) {
      const bool boundary = text[at - 1] == ' ' || text[at - 1] == '\t' || text[at - 1] == '\n' ||
                            text[at - 1] == '\r';
      std::size_t eq = at + length;
      while (eq < text.size() && (text[eq] == ' ' || text[eq] == '\t')) ++eq;
      if (boundary && eq < text.size() && text[eq] == '=') {
        const std::size_t quote = text.find_first_of("\"'", eq);
        return quote == std::string::npos ? at : quote + 1;
      }
    }
    return start;
  }

  std::string name_of(pugi::xml_node node) const { return node.name(); }

  void read() {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(
        source_.text().data(), source_.text().size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
      fail("CGA520", std::string("malformed XML: ") + parsed.description(),
           static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)));
    }
    grammar_.file = source_.name();
    pugi::xml_node root = doc.document_element();
    if (!root || name_of(root) != "BuildingGen") {
      fail("CGA521", "expected the root element <BuildingGen>", root ? offset_of(root) : 0);
    }
    no_attributes(root);
    pugi::xml_node rules;
    pugi::xml_node terminals;
    for (pugi::xml_node child : children(root)) {
      const std::string name = name_of(child);
      if (name == "Rules" && !rules) {
        rules = child;
      } else if (name == "Terminals" && !terminals) {
        terminals = child;
      } else {
        fail("CGA521",
             "unexpected element <" + name +
                 "> in <BuildingGen> (expected one <Rules> "
                 "and at most one <Terminals>)",
             offset_of(child));
      }
    }
    if (!rules) fail("CGA521", "<BuildingGen> has no <Rules>", offset_of(root));
    if (terminals) read_terminals(terminals);
    read_rules(rules);
    check_references();
  }

  // Element children of `node`; text and CDATA are errors (comments and PIs are skipped).
  std::vector<pugi::xml_node> children(pugi::xml_node node) {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node child : node.children()) {
      if (child.type() == pugi::node_element) {
        out.push_back(child);
      } else if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
        fail("CGA521", "unexpected text in <" + name_of(node) + ">", offset_of(node));
      }
    }
    return out;
  }

  void no_attributes(pugi::xml_node node, std::initializer_list<const char*> allowed = {}) {
    for (pugi::xml_attribute a : node.attributes()) {
      bool ok = false;
      for (const char* name : allowed) ok = ok || std::strcmp(name, a.name()) == 0;
      if (!ok) {
        fail("CGA524",
             "unknown attribute '" + std::string(a.name()) + "' on <" + name_of(node) + ">",
             offset_of(node, a.name()));
      }
    }
  }

  std::string symbol_name(pugi::xml_node node) {
    const std::string name = name_of(node);
    if (!is_identifier(name)) {
      fail("CGA522",
           "<" + name +
               "> is not a CGA shape symbol (letters, digits and '_', not a "
               "keyword)",
           offset_of(node));
    }
    return name;
  }

  void read_terminals(pugi::xml_node terminals) {
    no_attributes(terminals);
    for (pugi::xml_node child : children(terminals)) {
      if (name_of(child) == "predefined-shape") {
        predefined_file(child);
        continue;
      }
      terminals_.insert(symbol_name(child));
      no_attributes(child);
      if (!children(child).empty()) fail("CGA521", "a terminal has no children", offset_of(child));
    }
  }

  std::string predefined_file(pugi::xml_node node) {
    no_attributes(node, {"file"});
    if (!node.attribute("file")) {
      fail("CGA521", "<predefined-shape> needs a file attribute", offset_of(node));
    }
    if (!children(node).empty()) {
      fail("CGA521", "<predefined-shape> has no children", offset_of(node));
    }
    return node.attribute("file").value();
  }

  void read_rules(pugi::xml_node rules) {
    no_attributes(rules, {"priority"});
    PrioritySet set;
    set.implicit = true;
    if (pugi::xml_attribute priority = rules.attribute("priority")) {
      const std::string text = priority.value();
      if (!is_natural(text) || text.size() > 10 || std::stod(text) > 4294967295.0) {
        fail("CGA524", "priority must be a natural number, found '" + text + "'",
             offset_of(rules, "priority"));
      }
      set.implicit = false;
      set.priority = static_cast<std::uint32_t>(std::stoul(text));
    }
    for (pugi::xml_node group : children(rules)) {
      const std::string predecessor = symbol_name(group);
      no_attributes(group);
      predecessors_.insert(predecessor);
      const std::vector<pugi::xml_node> list = children(group);
      if (list.empty()) fail("CGA521", "<" + predecessor + "> has no rules", offset_of(group));
      for (pugi::xml_node r : list) set.rules.push_back(read_rule(r, predecessor));
    }
    if (!set.implicit || !set.rules.empty()) grammar_.sets.push_back(std::move(set));
  }

  Rule read_rule(pugi::xml_node node, const std::string& predecessor) {
    const std::string name = name_of(node);
    Rule rule;
    rule.predecessor = predecessor;
    rule.id = name.substr(1);
    if (name[0] != 'R' || !(rule.id.empty() || is_natural(rule.id) || is_identifier(rule.id))) {
      fail("CGA523", "expected a rule element R<id> (R12, Rroof or R), found <" + name + ">",
           offset_of(node));
    }
    no_attributes(node, {"condition"});
    if (pugi::xml_attribute condition = node.attribute("condition")) {
      if (rule.id.empty()) {
        fail("CGA530", "an unnamed rule <R> cannot have a condition", offset_of(node, "condition"));
      }
      rule.condition = expression(condition.value(), false, offset_of(node, "condition"));
    }
    const std::vector<pugi::xml_node> parts = children(node);
    if (parts.empty()) fail("CGA521", "<" + name + "> has no successor", offset_of(node));
    for (pugi::xml_node part : parts) rule.alternatives.push_back(read_part(part));
    if (rule.id.empty() && rule.alternatives.front().arrow == "~>") {
      fail("CGA530", "an unnamed rule <R> needs arrow=\"->\" or arrow=\"-->\" on its first part",
           offset_of(parts.front()));
    }
    return rule;
  }

  Alternative read_part(pugi::xml_node node) {
    const std::string kind = name_of(node);
    Alternative alt;
    alt.arrow = "~>";
    if (pugi::xml_attribute arrow = node.attribute("arrow")) {
      alt.arrow = arrow.value();
      if (alt.arrow != "~>" && alt.arrow != "->" && alt.arrow != "-->") {
        fail("CGA528", "arrow must be '~>', '->' or '-->', found '" + alt.arrow + "'",
             offset_of(node, "arrow"));
      }
    }
    if (pugi::xml_attribute p = node.attribute("probability")) {
      alt.probability = expression(p.value(), true, offset_of(node, "probability"));
    }
    if (kind == "Substitute") {
      no_attributes(node, {"arrow", "probability"});
      alt.items = elements(single_child(node, "Elements"));
      return alt;
    }
    if (kind != "Fixed" && kind != "Repeat") {
      fail("CGA521", "expected <Fixed>, <Repeat> or <Substitute>, found <" + kind + ">",
           offset_of(node));
    }
    no_attributes(node, {"arrow", "probability", "operation"});
    alt.items.push_back(read_split(node, kind == "Fixed"));
    return alt;
  }

  pugi::xml_node single_child(pugi::xml_node node, const char* name) {
    pugi::xml_node found;
    for (pugi::xml_node child : children(node)) {
      if (name_of(child) != name) continue;
      if (found) fail("CGA521", std::string("more than one <") + name + ">", offset_of(child));
      found = child;
    }
    if (!found) {
      fail("CGA521", "<" + name_of(node) + "> needs <" + name + ">", offset_of(node));
    }
    return found;
  }

  Item read_split(pugi::xml_node node, bool fixed) {
    Item item;
    item.kind = ItemKind::kOp;
    item.op = fixed ? OpKind::kSplit : OpKind::kRepeat;
    item.has_block = true;
    item.name = fixed ? "BS" : "RR";
    if (pugi::xml_attribute op = node.attribute("operation")) {
      item.name = op.value();
      const bool ok = fixed ? (item.name == "BS" || item.name == "Subdiv")
                            : (item.name == "RR" || item.name == "Repeat");
      if (!ok) {
        fail("CGA528",
             std::string("operation must be ") + (fixed ? "'BS' or 'Subdiv'" : "'RR' or 'Repeat'") +
                 ", found '" + item.name + "'",
             offset_of(node, "operation"));
      }
    }
    for (pugi::xml_node child : children(node)) {
      const std::string name = name_of(child);
      if (name != "xProportions" && name != "yProportions" && name != "Elements") {
        fail("CGA521", "unexpected <" + name + "> in <" + name_of(node) + ">", offset_of(child));
      }
    }
    const pugi::xml_node x = single_child(node, "xProportions");
    const pugi::xml_node y = single_child(node, "yProportions");
    const bool along_x = !x.attributes().empty();
    if (along_x == !y.attributes().empty()) {
      fail("CGA525", "exactly one of <xProportions> and <yProportions> must hold sizes",
           offset_of(node));
    }
    item.args.push_back(string_expr(along_x ? "X" : "Y"));
    proportions(along_x ? x : y, along_x ? "xr" : "yr", item);
    const std::size_t sizes = item.args.size() - 1;
    if (!fixed && sizes != 1) {
      fail("CGA525", "<Repeat> has exactly one size", offset_of(along_x ? x : y));
    }
    for (Item& shape : elements(single_child(node, "Elements"))) {
      Branch branch;
      branch.items.push_back(std::move(shape));
      item.branches.push_back(std::move(branch));
    }
    return item;
  }

  void proportions(pugi::xml_node node, const std::string& prefix, Item& item) {
    if (!children(node).empty()) fail("CGA521", "proportions have no children", offset_of(node));
    std::size_t index = 1;
    for (pugi::xml_attribute a : node.attributes()) {
      const std::string expected = prefix + std::to_string(index++);
      if (a.name() != expected) {
        fail("CGA525",
             "expected attribute '" + expected + "' on <" + name_of(node) + ">, found '" +
                 a.name() + "'",
             offset_of(node, a.name()));
      }
      item.args.push_back(size(a.value(), offset_of(node, a.name())));
    }
  }

  // "2.0" (absolute) or "1r" (relative), the sizes of §II.
  ExprPtr size(std::string text, std::size_t offset) {
    const bool relative = !text.empty() && text.back() == 'r';
    if (relative) text.pop_back();
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(value) || value < 0 || text[0] == '-' || text[0] == '+') {
      fail("CGA526",
           "a size is a non-negative number, optionally with 'r' (relative), found '" + text +
               (relative ? "r" : "") + "'",
           offset);
    }
    if (!relative) return number(value);
    auto rel = std::make_unique<Expr>();
    rel->kind = ExprKind::kUnary;
    rel->unary_op = UnaryOp::kRelative;
    rel->operands.push_back(number(value));
    return rel;
  }

  std::vector<Item> elements(pugi::xml_node node) {
    no_attributes(node);
    std::vector<Item> items;
    for (pugi::xml_node child : children(node)) {
      Item item;
      const std::string name = name_of(child);
      if (name == "empty-shape") {
        no_attributes(child);
        item.kind = ItemKind::kEmpty;
        item.name = "\xCE\xB5";
      } else if (name == "predefined-shape") {
        item.kind = ItemKind::kOp;
        item.op = OpKind::kPredefined;
        item.name = "Pshape";
        item.args.push_back(string_expr(predefined_file(child)));
      } else {
        item.kind = ItemKind::kSymbol;
        item.name = symbol_name(child);
        no_attributes(child);
        if (!children(child).empty()) {
          fail("CGA521", "a shape in <Elements> has no children", offset_of(child));
        }
        references_.emplace_back(item.name, offset_of(child));
      }
      items.push_back(std::move(item));
    }
    if (items.empty()) fail("CGA521", "<Elements> lists no shape", offset_of(node));
    return items;
  }

  // Parses `text` as one CGA expression by embedding it in a one-rule grammar (a condition, or a
  // parenthesised probability) and checking that nothing else was parsed.
  ExprPtr expression(const std::string& text, bool probability, std::size_t offset) {
    const std::string wrapped =
        probability ? "1: X ~> X : (" + text + ")" : "1: X : " + text + " ~> X";
    const base::Source embedded(source_.name(), wrapped);
    base::Result<Grammar> parsed = parse(embedded);
    const char* what = probability ? "probability" : "condition";
    if (!parsed.ok()) {
      fail("CGA527",
           std::string("invalid ") + what + " '" + text +
               "': " + parsed.diagnostics().front().message,
           offset);
    }
    Grammar& g = parsed.value();
    const bool one_rule = g.attrs.empty() && g.sets.size() == 1 && g.sets[0].rules.size() == 1;
    Rule* rule = one_rule ? &g.sets[0].rules[0] : nullptr;
    const bool shape = rule && rule->alternatives.size() == 1 &&
                       rule->alternatives[0].items.size() == 1 &&
                       rule->alternatives[0].items[0].kind == ItemKind::kSymbol;
    ExprPtr* result = nullptr;
    if (shape && probability && !rule->condition) result = &rule->alternatives[0].probability;
    if (shape && !probability && !rule->alternatives[0].probability) result = &rule->condition;
    if (!result || !*result) {
      fail("CGA527", std::string("invalid ") + what + " '" + text + "': not one expression",
           offset);
    }
    return std::move(*result);
  }

  void check_references() {
    for (const auto& [name, offset] : references_) {
      if (!predecessors_.count(name) && !terminals_.count(name)) {
        fail("CGA529",
             "shape '" + name + "' is neither the predecessor of a rule nor listed in <Terminals>",
             offset);
      }
    }
  }

  const base::Source& source_;
  Grammar grammar_;
  std::vector<base::Diagnostic> diags_;
  std::set<std::string> predecessors_;
  std::set<std::string> terminals_;
  std::vector<std::pair<std::string, std::size_t>> references_;
};

}  // namespace

base::Result<Grammar> read_buildinggen_xml(const base::Source& xml) {
  return Reader(xml).run();
}

}  // namespace insula::lang::cga
