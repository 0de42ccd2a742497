#include "lang/cga/model_json.h"

#include <nlohmann/json.hpp>

#include <string_view>

namespace insula::lang::cga {
namespace {

using nlohmann::json;

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

class Writer {
 public:
  explicit Writer(const base::Source& source) : source_(source) {}

  json grammar(const Grammar& g) {
    json out = {{"format", kModelJsonFormat}, {"version", kModelJsonVersion}, {"file", g.file}};
    json attrs = json::array();
    for (const AttrDecl& a : g.attrs) {
      attrs.push_back({{"name", a.name},
                       {"value", expr(*a.value)},
                       {"range", range(a.range)},
                       {"nameRange", range(a.name_range)}});
    }
    out["attributes"] = std::move(attrs);
    json sets = json::array();
    for (const PrioritySet& set : g.sets) {
      json rules = json::array();
      for (const Rule& r : set.rules) rules.push_back(rule(r));
      sets.push_back({{"priority", set.priority},
                      {"implicit", set.implicit},
                      {"range", range(set.range)},
                      {"rules", std::move(rules)}});
    }
    out["prioritySets"] = std::move(sets);
    return out;
  }

 private:
  json range(Range r) const {
    const base::Span span = span_of(source_, r);
    return {{"line", span.line},
            {"column", span.column},
            {"endLine", span.end_line},
            {"endColumn", span.end_column}};
  }

  json rule(const Rule& r) {
    json parts = json::array();
    for (const Alternative& alt : r.alternatives) {
      parts.push_back({{"arrow", alt.arrow},
                       {"probability", alt.probability ? expr(*alt.probability) : json()},
                       {"successors", items(alt.items)},
                       {"range", range(alt.range)}});
    }
    json out = {{"id", r.id},
                {"predecessor", r.predecessor},
                {"condition", r.condition ? expr(*r.condition) : json()},
                {"ruleParts", std::move(parts)},
                {"range", range(r.range)},
                {"predecessorRange", range(r.predecessor_range)}};
    if (!r.id.empty()) out["idRange"] = range(r.id_range);
    return out;
  }

  json items(const std::vector<Item>& list) {
    json out = json::array();
    for (const Item& it : list) out.push_back(item(it));
    return out;
  }

  json item(const Item& it) {
    switch (it.kind) {
      case ItemKind::kSymbol:
        return {{"kind", "symbol"}, {"name", it.name}, {"range", range(it.range)}};
      case ItemKind::kEmpty:
        return {{"kind", "empty"}, {"range", range(it.range)}};
      case ItemKind::kPush:
        return {{"kind", "push"}, {"range", range(it.range)}};
      case ItemKind::kPop:
        return {{"kind", "pop"}, {"range", range(it.range)}};
      case ItemKind::kOp:
        break;
    }
    json args = json::array();
    for (const ExprPtr& a : it.args) args.push_back(expr(*a));
    json out = {{"kind", "operation"},      {"operation", operation_name(it.op)},
                {"name", it.name},          {"arguments", std::move(args)},
                {"hasBlock", it.has_block}, {"branches", branches(it.branches)},
                {"range", range(it.range)}};
    if (it.op == OpKind::kRotate) out["axis"] = std::string(1, it.axis);
    return out;
  }

  json branches(const std::vector<Branch>& list) {
    json out = json::array();
    for (const Branch& b : list) {
      out.push_back({{"key", b.key ? expr(*b.key) : json()},
                     {"repeat", b.repeat},
                     {"pattern", branches(b.pattern)},
                     {"successors", items(b.items)},
                     {"range", range(b.range)}});
    }
    return out;
  }

  json expr(const Expr& e) {
    json out;
    switch (e.kind) {
      case ExprKind::kNumber:
        out = {{"kind", "number"}, {"value", e.number}};
        break;
      case ExprKind::kString:
        out = {{"kind", "string"}, {"value", e.text}};
        break;
      case ExprKind::kBool:
        out = {{"kind", "boolean"}, {"value", e.boolean}};
        break;
      case ExprKind::kIdent:
        out = {{"kind", "identifier"}, {"name", e.text}};
        break;
      case ExprKind::kMember:
        out = {{"kind", "member"}, {"object", expr(*e.operands[0])}, {"member", e.text}};
        break;
      case ExprKind::kCall: {
        json args = json::array();
        for (std::size_t i = 1; i < e.operands.size(); ++i) args.push_back(expr(*e.operands[i]));
        out = {{"kind", "call"}, {"callee", expr(*e.operands[0])}, {"arguments", std::move(args)}};
        break;
      }
      case ExprKind::kUnary:
        out = {{"kind", "unary"},
               {"operator", unary_name(e.unary_op)},
               {"operand", expr(*e.operands[0])}};
        break;
      case ExprKind::kBinary:
        out = {{"kind", "binary"},
               {"operator", binary_name(e.binary_op)},
               {"left", expr(*e.operands[0])},
               {"right", expr(*e.operands[1])}};
        break;
    }
    out["range"] = range(e.range);
    return out;
  }

  const base::Source& source_;
};

}  // namespace

std::string model_json(const Grammar& grammar, const base::Source& source) {
  // Strings in the AST are bytes from the source; invalid UTF-8 (allowed inside CGA strings) is
  // replaced rather than thrown on, so any parsed grammar serialises.
  return Writer(source).grammar(grammar).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace insula::lang::cga
