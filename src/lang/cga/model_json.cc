#include "lang/cga/model_json.h"

#include <string_view>

#include "lang/cga/json_out.h"

namespace insula::lang::cga {
namespace {

std::string_view unary_name(UnaryOp op) {
  constexpr std::string_view kNames[] = {"not", "negate", "relative", "floating"};
  return kNames[static_cast<int>(op)];
}

std::string_view binary_name(BinaryOp op) {
  constexpr std::string_view kNames[] = {"or", "and", "==", "!=", "<", "<=", ">",
                                         ">=", "+",   "-",  "*",  "/", "%"};
  return kNames[static_cast<int>(op)];
}

std::string_view operation_name(OpKind kind) {
  constexpr std::string_view kNames[] = {"basicSplit", "repeat",     "componentSplit",
                                         "translate",  "scale",      "rotate",
                                         "insert",     "predefined", "generic"};
  return kNames[static_cast<int>(kind)];
}

std::string_view item_kind_name(ItemKind kind) {
  constexpr std::string_view kNames[] = {"symbol",    "empty", "push",  "pop",
                                         "operation", "case",  "chance"};
  return kNames[static_cast<int>(kind)];
}

// Streams the grammar in the member order of docs/cga-model.schema.json.
class Writer {
 public:
  explicit Writer(const base::Source& source) : source_(source) {}

  std::string grammar(const Grammar& g) {
    out_.begin_object();
    field("format", kModelJsonFormat);
    out_.key("version");
    out_.integer(kModelJsonVersion);
    field("file", g.file);
    out_.key("attributes");
    out_.begin_array();
    for (const AttrDecl& a : g.attrs) {
      out_.begin_object();
      field("name", a.name);
      out_.key("value");
      expr(*a.value);
      range("range", a.range);
      range("nameRange", a.name_range);
      out_.end_object();
    }
    out_.end_array();
    out_.key("prioritySets");
    out_.begin_array();
    for (const PrioritySet& set : g.sets) {
      out_.begin_object();
      out_.key("priority");
      out_.integer(set.priority);
      out_.key("implicit");
      out_.boolean(set.implicit);
      range("range", set.range);
      out_.key("rules");
      out_.begin_array();
      for (const Rule& r : set.rules) rule(r);
      out_.end_array();
      out_.end_object();
    }
    out_.end_array();
    out_.end_object();
    return out_.take();
  }

 private:
  void field(std::string_view name, std::string_view value) {
    out_.key(name);
    out_.string(value);
  }

  void range(std::string_view name, Range r) {
    const base::Span span = span_of(source_, r);
    out_.key(name);
    out_.inline_object({{"line", span.line},
                        {"column", span.column},
                        {"endLine", span.end_line},
                        {"endColumn", span.end_column}});
  }

  void optional_expr(std::string_view name, const ExprPtr& e) {
    out_.key(name);
    if (e) {
      expr(*e);
    } else {
      out_.null();
    }
  }

  void rule(const Rule& r) {
    out_.begin_object();
    field("id", r.id);
    field("predecessor", r.predecessor);
    optional_expr("condition", r.condition);
    out_.key("ruleParts");
    out_.begin_array();
    for (const Alternative& alt : r.alternatives) {
      out_.begin_object();
      field("arrow", alt.arrow);
      optional_expr("probability", alt.probability);
      items("successors", alt.items);
      range("range", alt.range);
      out_.end_object();
    }
    out_.end_array();
    range("range", r.range);
    range("predecessorRange", r.predecessor_range);
    if (!r.id.empty()) range("idRange", r.id_range);
    out_.end_object();
  }

  void items(std::string_view name, const std::vector<Item>& list) {
    out_.key(name);
    out_.begin_array();
    for (const Item& it : list) item(it);
    out_.end_array();
  }

  void item(const Item& it) {
    out_.begin_object();
    field("kind", item_kind_name(it.kind));
    if (it.kind == ItemKind::kSymbol) {
      field("name", it.name);
      if (!it.args.empty()) {
        out_.key("arguments");
        out_.begin_array();
        for (const ExprPtr& a : it.args) expr(*a);
        out_.end_array();
      }
      if (it.terminal) {
        out_.key("terminal");
        out_.boolean(true);
      }
    }
    if (it.kind == ItemKind::kCase || it.kind == ItemKind::kChance)
      branches("branches", it.branches);
    if (it.kind == ItemKind::kOp) {
      field("operation", operation_name(it.op));
      field("name", it.name);
      if (it.op == OpKind::kRotate) field("axis", std::string_view(&it.axis, 1));
      out_.key("arguments");
      out_.begin_array();
      for (const ExprPtr& a : it.args) expr(*a);
      out_.end_array();
      out_.key("hasBlock");
      out_.boolean(it.has_block);
      branches("branches", it.branches);
    }
    range("range", it.range);
    out_.end_object();
  }

  void branches(std::string_view name, const std::vector<Branch>& list) {
    out_.key(name);
    out_.begin_array();
    for (const Branch& b : list) {
      out_.begin_object();
      optional_expr("key", b.key);
      if (b.merged) {
        out_.key("merged");
        out_.boolean(true);
      }
      out_.key("repeat");
      out_.boolean(b.repeat);
      branches("pattern", b.pattern);
      items("successors", b.items);
      range("range", b.range);
      out_.end_object();
    }
    out_.end_array();
  }

  void expr(const Expr& e) {
    out_.begin_object();
    switch (e.kind) {
      case ExprKind::kNumber:
        field("kind", "number");
        out_.key("value");
        out_.number(e.number);
        break;
      case ExprKind::kString:
        field("kind", "string");
        field("value", e.text);
        break;
      case ExprKind::kBool:
        field("kind", "boolean");
        out_.key("value");
        out_.boolean(e.boolean);
        break;
      case ExprKind::kIdent:
        field("kind", "identifier");
        field("name", e.text);
        break;
      case ExprKind::kMember:
        field("kind", "member");
        out_.key("object");
        expr(*e.operands[0]);
        field("member", e.text);
        break;
      case ExprKind::kCall:
        field("kind", "call");
        out_.key("callee");
        expr(*e.operands[0]);
        out_.key("arguments");
        out_.begin_array();
        for (std::size_t i = 1; i < e.operands.size(); ++i) expr(*e.operands[i]);
        out_.end_array();
        break;
      case ExprKind::kUnary:
        field("kind", "unary");
        field("operator", unary_name(e.unary_op));
        out_.key("operand");
        expr(*e.operands[0]);
        break;
      case ExprKind::kBinary:
        field("kind", "binary");
        field("operator", binary_name(e.binary_op));
        if (e.elementwise) {
          out_.key("elementwise");
          out_.boolean(true);
        }
        out_.key("left");
        expr(*e.operands[0]);
        out_.key("right");
        expr(*e.operands[1]);
        break;
      case ExprKind::kCase:
      case ExprKind::kChance:
      case ExprKind::kArray:
      case ExprKind::kIndex:
      case ExprKind::kComp:
      case ExprKind::kRange: {
        constexpr std::string_view kKinds[] = {"case", "chance", "array", "index", "comp", "range"};
        field("kind", kKinds[static_cast<int>(e.kind) - static_cast<int>(ExprKind::kCase)]);
        if (e.kind == ExprKind::kArray && e.boolean) field("rows", "true");
        if (e.kind == ExprKind::kComp) field("operators", e.text);
        out_.key("operands");
        out_.begin_array();
        for (const ExprPtr& operand : e.operands) expr(*operand);
        out_.end_array();
        break;
      }
    }
    range("range", e.range);
    out_.end_object();
  }

  const base::Source& source_;
  JsonOut out_;
};

}  // namespace

std::string model_json(const Grammar& grammar, const base::Source& source) {
  return Writer(source).grammar(grammar);
}

}  // namespace insula::lang::cga
