#include "lang/cga/model_xmi.h"

#include <pugixml.hpp>

#include <sstream>
#include <string_view>

#include "lang/cga/printer.h"
#include "lang/cga/xml_text.h"

namespace insula::lang::cga {
namespace {

// Enum literals of docs/cga.ecore (UnaryOperator, BinaryOperator), in AST enum order.
std::string_view unary_literal(UnaryOp op) {
  constexpr std::string_view kNames[] = {"not", "negate", "relative", "floating"};
  return kNames[static_cast<int>(op)];
}

std::string_view binary_literal(BinaryOp op) {
  constexpr std::string_view kNames[] = {"or", "and", "eq",  "ne",  "lt",  "le", "gt",
                                         "ge", "add", "sub", "mul", "div", "mod"};
  return kNames[static_cast<int>(op)];
}

// The EClass of an operation item.
std::string_view operation_class(OpKind kind) {
  constexpr std::string_view kNames[] = {"BasicSplitRule",  "RepeatRule",      "ComponentSplitRule",
                                         "TranslationRule", "ScaleRule",       "RotationRule",
                                         "InsertionRule",   "PredefinedShape", "GenericOperation"};
  return kNames[static_cast<int>(kind)];
}

class Writer {
 public:
  explicit Writer(const base::Source& source) : source_(source) {}

  void grammar(pugi::xml_node root, const Grammar& g) {
    root.append_attribute("xmi:version") = "2.0";
    root.append_attribute("xmlns:xmi") = "http://www.omg.org/XMI";
    root.append_attribute("xmlns:xsi") = "http://www.w3.org/2001/XMLSchema-instance";
    root.append_attribute("xmlns:cga") = kCgaNsUri;
    text(root, "file", g.file);
    for (const AttrDecl& a : g.attrs) {
      pugi::xml_node node = root.append_child("attributes");
      located(node, a.range);
      text(node, "name", a.name);
      expr(node, "value", *a.value);
    }
    for (const PrioritySet& set : g.sets) {
      pugi::xml_node node = root.append_child("prioritySets");
      located(node, set.range);
      node.append_attribute("priority") = set.priority;
      if (set.implicit) node.append_attribute("implicit") = "true";
      for (const Rule& r : set.rules) rule(node, r);
    }
  }

 private:
  void text(pugi::xml_node node, const char* name, std::string_view value) {
    node.append_attribute(name) = to_xml_text(value).c_str();
  }

  void located(pugi::xml_node node, Range range) {
    const base::Span span = span_of(source_, range);
    node.append_attribute("line") = span.line;
    node.append_attribute("column") = span.column;
    node.append_attribute("endLine") = span.end_line;
    node.append_attribute("endColumn") = span.end_column;
  }

  pugi::xml_node typed(pugi::xml_node parent, const char* feature, std::string_view eclass) {
    pugi::xml_node node = parent.append_child(feature);
    node.append_attribute("xsi:type") = ("cga:" + std::string(eclass)).c_str();
    return node;
  }

  void rule(pugi::xml_node parent, const Rule& r) {
    pugi::xml_node node = parent.append_child("rules");
    located(node, r.range);
    if (!r.id.empty()) text(node, "id", r.id);
    text(node, "predecessor", r.predecessor);
    if (r.condition) expr(node, "condition", *r.condition);
    for (const Alternative& alt : r.alternatives) {
      pugi::xml_node part = node.append_child("ruleParts");
      located(part, alt.range);
      text(part, "arrow", alt.arrow);
      if (alt.probability) expr(part, "probability", *alt.probability);
      for (const Item& it : alt.items) item(part, "successors", it);
    }
  }

  void item(pugi::xml_node parent, const char* feature, const Item& it) {
    pugi::xml_node node;
    switch (it.kind) {
      case ItemKind::kSymbol:
        node = typed(parent, feature, "SymbolShape");
        text(node, "symbol", it.name);
        break;
      case ItemKind::kEmpty:
        node = typed(parent, feature, "EmptyShape");
        break;
      case ItemKind::kPush:
        node = typed(parent, feature, "PushRule");
        break;
      case ItemKind::kPop:
        node = typed(parent, feature, "PopRule");
        break;
      case ItemKind::kOp:
        node = typed(parent, feature, operation_class(it.op));
        text(node, "name", it.name);
        if (it.has_block) node.append_attribute("hasBlock") = "true";
        if (it.op == OpKind::kRotate) text(node, "axis", std::string(1, it.axis));
        for (const ExprPtr& a : it.args) expr(node, "arguments", *a);
        for (const Branch& b : it.branches) branch(node, "branches", b);
        break;
    }
    located(node, it.range);
  }

  void branch(pugi::xml_node parent, const char* feature, const Branch& b) {
    pugi::xml_node node = parent.append_child(feature);
    located(node, b.range);
    if (b.repeat) node.append_attribute("repeat") = "true";
    if (b.key) expr(node, "key", *b.key);
    for (const Branch& inner : b.pattern) branch(node, "pattern", inner);
    for (const Item& it : b.items) item(node, "successors", it);
  }

  void expr(pugi::xml_node parent, const char* feature, const Expr& e) {
    pugi::xml_node node;
    switch (e.kind) {
      case ExprKind::kNumber:
        node = typed(parent, feature, "NumberLiteral");
        node.append_attribute("value") = number_text(e.number).c_str();
        break;
      case ExprKind::kString:
        node = typed(parent, feature, "StringLiteral");
        text(node, "value", e.text);
        break;
      case ExprKind::kBool:
        node = typed(parent, feature, "BooleanLiteral");
        node.append_attribute("value") = e.boolean ? "true" : "false";
        break;
      case ExprKind::kIdent:
        node = typed(parent, feature, "Identifier");
        text(node, "name", e.text);
        break;
      case ExprKind::kMember:
        node = typed(parent, feature, "MemberAccess");
        text(node, "member", e.text);
        expr(node, "object", *e.operands[0]);
        break;
      case ExprKind::kCall:
        node = typed(parent, feature, "Call");
        expr(node, "callee", *e.operands[0]);
        for (std::size_t i = 1; i < e.operands.size(); ++i) expr(node, "arguments", *e.operands[i]);
        break;
      case ExprKind::kUnary:
        node = typed(parent, feature, "UnaryExpression");
        text(node, "operator", unary_literal(e.unary_op));
        expr(node, "operand", *e.operands[0]);
        break;
      case ExprKind::kBinary:
        node = typed(parent, feature, "BinaryExpression");
        text(node, "operator", binary_literal(e.binary_op));
        expr(node, "left", *e.operands[0]);
        expr(node, "right", *e.operands[1]);
        break;
    }
    located(node, e.range);
  }

  const base::Source& source_;
};

}  // namespace

std::string model_xmi(const Grammar& grammar, const base::Source& source) {
  pugi::xml_document doc;
  pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  declaration.append_attribute("encoding") = "UTF-8";
  const std::string root_name = std::string(kCgaNsPrefix) + ":ShapeGrammar";
  Writer(source).grammar(doc.append_child(root_name.c_str()), grammar);
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace insula::lang::cga
