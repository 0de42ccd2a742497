#include "lang/cga/ast_dump.h"

#include <initializer_list>
#include <string_view>

#include "base/format.h"

namespace insula::lang::cga {
namespace {

// Concatenation through append: GCC 12 reports a false -Wrestrict on `"(" + std::string(...)`.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (const std::string_view part : parts) out.append(part);
  return out;
}

std::string number_text(double value) {
  return base::shortest_number(value);
}

std::string quoted(std::string_view text) {
  return base::quoted_string(text);
}

std::string_view unary_name(UnaryOp op) {
  switch (op) {
    case UnaryOp::kNot:
      return "not";
    case UnaryOp::kNegate:
      return "neg";
    case UnaryOp::kRelative:
      return "rel";
    case UnaryOp::kFloating:
      return "float";
  }
  return "?";
}

std::string_view binary_name(BinaryOp op) {
  constexpr std::string_view kNames[] = {"or", "and", "==", "!=", "<", "<=", ">",
                                         ">=", "+",   "-",  "*",  "/", "%"};
  return kNames[static_cast<int>(op)];
}

std::string_view op_kind_name(OpKind kind) {
  constexpr std::string_view kNames[] = {"split",  "repeat", "comp",       "translate", "scale",
                                         "rotate", "insert", "predefined", "op"};
  return kNames[static_cast<int>(kind)];
}

class Dumper {
 public:
  explicit Dumper(const base::Source& source) : source_(source) {}

  std::string grammar(const Grammar& g) {
    out_ = "(grammar " + quoted(g.file);
    if (g.dialect == Dialect::kCityEngine) line(1, "(dialect cityengine)");
    if (!g.version.empty()) line(1, "(version " + quoted(g.version) + ")");
    for (const ImportDecl& imp : g.imports) {
      std::string text = cat({"(import ", imp.alias, " ", quoted(imp.path)});
      if (imp.has_list) text += " list";
      for (const std::string& name : imp.protected_attrs) text += " (protect " + name + ")";
      for (const auto& [name, value] : imp.overrides) {
        text += cat({" (override ", name, " ", dump(*value), ")"});
      }
      for (const Rule& r : imp.rule_overrides) text += " (redefine " + r.predecessor + ")";
      line(1, text + at(imp.range) + annotations(imp.annotations) + ")");
    }
    for (const AttrDecl& attr : g.attrs) {
      line(1, "(attr " + attr.name + at(attr.range) + " " + dump(*attr.value) +
                  annotations(attr.annotations) + ")");
    }
    for (const FunctionDecl& fn : g.functions) {
      line(1, cat({fn.is_const ? "(const " : "(function ", fn.name, params(fn.params), " ",
                   dump(*fn.body), at(fn.range), annotations(fn.annotations), ")"}));
    }
    for (const std::string& style : g.styles) line(1, "(style " + style + ")");
    for (const PrioritySet& set : g.sets) priority_set(set);
    out_ += ")\n";
    return std::move(out_);
  }

 private:
  std::string at(Range range) const {
    const auto [l, c] = source_.locate(range.begin);
    return " @" + std::to_string(l) + ":" + std::to_string(c);
  }

  static std::string params(const std::vector<std::string>& names) {
    if (names.empty()) return "";
    std::string out = " (params";
    for (const std::string& n : names) out.append(" ").append(n);
    return out + ")";
  }

  static std::string annotations(const std::vector<Annotation>& list) {
    std::string out;
    for (const Annotation& a : list) {
      out += " (@" + a.name;
      for (std::size_t i = 0; i < a.args.size(); ++i) {
        out += ' ';
        if (!a.keys[i].empty()) out.append(a.keys[i]).append("=");
        out += dump(*a.args[i]);
      }
      out += ')';
    }
    return out;
  }

  void line(int depth, const std::string& text) {
    out_ += '\n';
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += text;
  }

  void priority_set(const PrioritySet& set) {
    line(1, "(priority " + std::to_string(set.priority) + (set.implicit ? " implicit" : "") +
                at(set.range));
    for (const Rule& rule : set.rules) this->rule(rule);
    out_ += ')';
  }

  void rule(const Rule& r) {
    std::string head = "(rule " + (r.id.empty() ? std::string("_") : r.id) + at(r.range) +
                       " (pred " + r.predecessor + ")";
    head += params(r.params);
    head += annotations(r.annotations);
    if (r.condition) head += " (cond " + dump(*r.condition) + ")";
    line(2, head);
    for (const Alternative& alt : r.alternatives) {
      std::string text = "(alt " + alt.arrow + at(alt.range);
      if (alt.probability) text += " (prob " + dump(*alt.probability) + ")";
      line(3, text);
      for (const Item& item : alt.items) this->item(item, 4);
      out_ += ')';
    }
    out_ += ')';
  }

  void item(const Item& it, int depth) {
    switch (it.kind) {
      case ItemKind::kSymbol: {
        std::string text = cat({"(sym ", it.name, it.terminal ? "." : "", at(it.range)});
        for (const ExprPtr& arg : it.args) text.append(" ").append(dump(*arg));
        return line(depth, text + ")");
      }
      case ItemKind::kCase:
      case ItemKind::kChance:
        line(depth, std::string(it.kind == ItemKind::kCase ? "(case" : "(chance") + at(it.range));
        for (const Branch& branch : it.branches) this->branch(branch, depth + 1);
        out_ += ')';
        return;
      case ItemKind::kEmpty:
        return line(depth, "(eps" + at(it.range) + ")");
      case ItemKind::kPush:
        return line(depth, "(push" + at(it.range) + ")");
      case ItemKind::kPop:
        return line(depth, "(pop" + at(it.range) + ")");
      case ItemKind::kOp:
        break;
    }
    std::string head = cat({"(", op_kind_name(it.op), " ", it.name});
    if (it.op == OpKind::kRotate) {
      head += " axis=";
      head += it.axis;
    }
    head += at(it.range) + " (";
    for (std::size_t i = 0; i < it.args.size(); ++i) {
      if (i > 0) head += ' ';
      head += dump(*it.args[i]);
    }
    head += ')';
    if (it.has_block) head += " block";
    line(depth, head);
    for (const Branch& branch : it.branches) this->branch(branch, depth + 1);
    out_ += ')';
  }

  void branch(const Branch& b, int depth) {
    std::string head = std::string(b.repeat ? "(pattern" : "(branch") + at(b.range);
    if (b.key) head += (b.merged ? " (merged-key " : " (key ") + dump(*b.key) + ")";
    line(depth, head);
    for (const Branch& inner : b.pattern) branch(inner, depth + 1);
    for (const Item& it : b.items) item(it, depth + 1);
    out_ += ')';
  }

  const base::Source& source_;
  std::string out_;
};

}  // namespace

std::string dump(const Expr& expr) {
  switch (expr.kind) {
    case ExprKind::kNumber:
      return number_text(expr.number);
    case ExprKind::kString:
      return quoted(expr.text);
    case ExprKind::kBool:
      return expr.boolean ? "true" : "false";
    case ExprKind::kIdent:
      return expr.text;
    case ExprKind::kMember:
      return "(. " + dump(*expr.operands[0]) + " " + expr.text + ")";
    case ExprKind::kCall: {
      std::string out = "(call";
      for (const ExprPtr& operand : expr.operands) {
        out += ' ';
        out += dump(*operand);
      }
      return out + ")";
    }
    case ExprKind::kCase:
    case ExprKind::kChance:
    case ExprKind::kArray:
    case ExprKind::kIndex:
    case ExprKind::kComp:
    case ExprKind::kRange: {
      constexpr std::string_view kHeads[] = {"(case",  "(chance", "(array",
                                             "(index", "(comp",   "(range"};
      std::string out(kHeads[static_cast<int>(expr.kind) - static_cast<int>(ExprKind::kCase)]);
      if (expr.kind == ExprKind::kArray && expr.boolean) out += ";";
      if (expr.kind == ExprKind::kComp) out += " " + expr.text;
      for (const ExprPtr& operand : expr.operands) {
        out += ' ';
        out += dump(*operand);
      }
      return out + ")";
    }
    case ExprKind::kUnary:
      return cat({"(", unary_name(expr.unary_op), " ", dump(*expr.operands[0]), ")"});
    case ExprKind::kBinary:
      return cat({"(", expr.elementwise ? "." : "", binary_name(expr.binary_op), " ",
                  dump(*expr.operands[0]), " ", dump(*expr.operands[1]), ")"});
  }
  return "?";
}

std::string dump(const Grammar& grammar, const base::Source& source) {
  return Dumper(source).grammar(grammar);
}

}  // namespace insula::lang::cga
