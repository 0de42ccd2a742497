#include "lang/cga/model_xmi.h"

#include <cstdint>
#include <string_view>
#include <vector>

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

// Streams XML with two-space indentation: a grammar of a few MB gives tens of MB of XMI, which a
// DOM would hold several times over (docs/PERFORMANCE.md). Attributes go right after
// open(); children follow; close() ends the innermost element.
class XmlOut {
 public:
  XmlOut() { out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"; }

  void open(std::string_view name) {
    finish_start_tag();
    indent();
    out_ += '<';
    out_ += name;
    open_.emplace_back(name);
    pending_ = true;
  }

  // An attribute of the element just opened; text XML cannot carry is replaced (xml_text.h).
  void attribute(std::string_view name, std::string_view value) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    for (const char c : to_xml_text(value)) escaped(c);
    out_ += '"';
  }

  void attribute(std::string_view name, std::uint32_t value) {
    attribute(name, std::string_view(std::to_string(value)));
  }

  void close() {
    const std::string name = std::move(open_.back());
    open_.pop_back();
    if (pending_) {
      out_ += " />\n";
      pending_ = false;
      return;
    }
    indent();
    out_ += "</";
    out_ += name;
    out_ += ">\n";
  }

  std::string take() { return std::move(out_); }

 private:
  void escaped(char c) {
    switch (c) {
      case '&':
        out_ += "&amp;";
        break;
      case '<':
        out_ += "&lt;";
        break;
      case '>':
        out_ += "&gt;";
        break;
      case '"':
        out_ += "&quot;";
        break;
      case '\n':
        out_ += "&#10;";
        break;
      case '\r':
        out_ += "&#13;";
        break;
      case '\t':
        out_ += "&#9;";
        break;
      default:
        out_ += c;
    }
  }

  void finish_start_tag() {
    if (!pending_) return;
    out_ += ">\n";
    pending_ = false;
  }

  void indent() { out_.append(open_.size() * 2, ' '); }

  std::string out_;
  std::vector<std::string> open_;  // names of the open elements
  bool pending_ = false;           // the innermost start tag still takes attributes
};

class Writer {
 public:
  explicit Writer(const base::Source& source) : source_(source) {}

  std::string grammar(const Grammar& g) {
    out_.open(std::string(kCgaNsPrefix) + ":ShapeGrammar");
    out_.attribute("xmi:version", "2.0");
    out_.attribute("xmlns:xmi", "http://www.omg.org/XMI");
    out_.attribute("xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance");
    out_.attribute("xmlns:cga", kCgaNsUri);
    out_.attribute("file", g.file);
    for (const AttrDecl& a : g.attrs) {
      out_.open("attributes");
      located(a.range);
      out_.attribute("name", a.name);
      expr("value", *a.value);
      out_.close();
    }
    for (const PrioritySet& set : g.sets) {
      out_.open("prioritySets");
      located(set.range);
      out_.attribute("priority", set.priority);
      if (set.implicit) out_.attribute("implicit", "true");
      for (const Rule& r : set.rules) rule(r);
      out_.close();
    }
    out_.close();
    return out_.take();
  }

 private:
  void located(Range range) {
    const base::Span span = span_of(source_, range);
    out_.attribute("line", span.line);
    out_.attribute("column", span.column);
    out_.attribute("endLine", span.end_line);
    out_.attribute("endColumn", span.end_column);
  }

  // Opens `feature` as an instance of `eclass` (xsi:type, as EMF writes a subclass instance).
  void typed(std::string_view feature, std::string_view eclass, Range range) {
    out_.open(feature);
    out_.attribute("xsi:type", std::string(kCgaNsPrefix) + ":" + std::string(eclass));
    located(range);
  }

  void rule(const Rule& r) {
    out_.open("rules");
    located(r.range);
    if (!r.id.empty()) out_.attribute("id", r.id);
    out_.attribute("predecessor", r.predecessor);
    if (r.condition) expr("condition", *r.condition);
    for (const Alternative& alt : r.alternatives) {
      out_.open("ruleParts");
      located(alt.range);
      out_.attribute("arrow", alt.arrow);
      if (alt.probability) expr("probability", *alt.probability);
      for (const Item& it : alt.items) item(it);
      out_.close();
    }
    out_.close();
  }

  void item(const Item& it) {
    switch (it.kind) {
      case ItemKind::kSymbol:
        typed("successors", "SymbolShape", it.range);
        out_.attribute("symbol", it.name);
        if (it.terminal) out_.attribute("terminal", "true");
        for (const ExprPtr& a : it.args) expr("arguments", *a);
        break;
      case ItemKind::kCase:
      case ItemKind::kChance:
        typed("successors", it.kind == ItemKind::kCase ? "CaseChain" : "ChanceChain", it.range);
        for (const Branch& b : it.branches) branch("branches", b);
        break;
      case ItemKind::kEmpty:
        typed("successors", "EmptyShape", it.range);
        break;
      case ItemKind::kPush:
        typed("successors", "PushRule", it.range);
        break;
      case ItemKind::kPop:
        typed("successors", "PopRule", it.range);
        break;
      case ItemKind::kOp:
        typed("successors", operation_class(it.op), it.range);
        out_.attribute("name", it.name);
        if (it.has_block) out_.attribute("hasBlock", "true");
        if (it.op == OpKind::kRotate) out_.attribute("axis", std::string_view(&it.axis, 1));
        for (const ExprPtr& a : it.args) expr("arguments", *a);
        for (const Branch& b : it.branches) branch("branches", b);
        break;
    }
    out_.close();
  }

  void branch(std::string_view feature, const Branch& b) {
    out_.open(feature);
    located(b.range);
    if (b.repeat) out_.attribute("repeat", "true");
    if (b.merged) out_.attribute("merged", "true");
    if (b.key) expr("key", *b.key);
    for (const Branch& inner : b.pattern) branch("pattern", inner);
    for (const Item& it : b.items) item(it);
    out_.close();
  }

  void expr(std::string_view feature, const Expr& e) {
    switch (e.kind) {
      case ExprKind::kNumber:
        typed(feature, "NumberLiteral", e.range);
        out_.attribute("value", number_text(e.number));
        break;
      case ExprKind::kString:
        typed(feature, "StringLiteral", e.range);
        out_.attribute("value", e.text);
        break;
      case ExprKind::kBool:
        typed(feature, "BooleanLiteral", e.range);
        out_.attribute("value", e.boolean ? "true" : "false");
        break;
      case ExprKind::kIdent:
        typed(feature, "Identifier", e.range);
        out_.attribute("name", e.text);
        break;
      case ExprKind::kMember:
        typed(feature, "MemberAccess", e.range);
        out_.attribute("member", e.text);
        expr("object", *e.operands[0]);
        break;
      case ExprKind::kCall:
        typed(feature, "Call", e.range);
        expr("callee", *e.operands[0]);
        for (std::size_t i = 1; i < e.operands.size(); ++i) expr("arguments", *e.operands[i]);
        break;
      case ExprKind::kUnary:
        typed(feature, "UnaryExpression", e.range);
        out_.attribute("operator", unary_literal(e.unary_op));
        expr("operand", *e.operands[0]);
        break;
      case ExprKind::kBinary:
        typed(feature, "BinaryExpression", e.range);
        out_.attribute("operator", binary_literal(e.binary_op));
        expr("left", *e.operands[0]);
        expr("right", *e.operands[1]);
        break;
      case ExprKind::kCase:
      case ExprKind::kChance:
      case ExprKind::kArray:
      case ExprKind::kIndex:
      case ExprKind::kComp:
      case ExprKind::kRange: {
        constexpr std::string_view kTypes[] = {"CaseExpression", "ChanceExpression", "ArrayLiteral",
                                               "IndexAccess",    "CompFunction",     "Range"};
        typed(feature, kTypes[static_cast<int>(e.kind) - static_cast<int>(ExprKind::kCase)],
              e.range);
        if (e.kind == ExprKind::kArray && e.boolean) out_.attribute("rows", "true");
        if (e.kind == ExprKind::kComp) out_.attribute("operators", e.text);
        for (const ExprPtr& operand : e.operands) expr("operands", *operand);
        break;
      }
    }
    out_.close();
  }

  const base::Source& source_;
  XmlOut out_;
};

}  // namespace

std::string model_xmi(const Grammar& grammar, const base::Source& source) {
  return Writer(source).grammar(grammar);
}

}  // namespace insula::lang::cga
