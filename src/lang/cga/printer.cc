// AST -> `.cga` text. The parser's grammar (parser.cc) decides what the printer must take care
// of: expressions are parenthesised by precedence level only where the parser would otherwise
// build a different tree; a probability that is not a number or a negation is parenthesised
// (parser.cc, `probability`); blocks stay on one line, because a line starting with `key :`
// inside a block reads as the start of the next rule; attributes end with `;` so a value is
// never continued by the next line.
#include "lang/cga/printer.h"

#include <cmath>
#include <string_view>

#include "base/format.h"

namespace insula::lang::cga {
namespace {

// Precedence levels of parser.cc, low to high. An operand printed inside an operator of level L
// needs parentheses when its own level is below what the parser accepts at that position.
enum Level : int {
  kOrLevel = 1,
  kAndLevel = 2,
  kNotLevel = 3,
  kCompareLevel = 4,
  kAddLevel = 5,
  kMulLevel = 6,
  kUnaryLevel = 7,
  kPostfixLevel = 8,
};

int binary_level(BinaryOp op) {
  switch (op) {
    case BinaryOp::kOr:
      return kOrLevel;
    case BinaryOp::kAnd:
      return kAndLevel;
    case BinaryOp::kAdd:
    case BinaryOp::kSub:
      return kAddLevel;
    case BinaryOp::kMul:
    case BinaryOp::kDiv:
    case BinaryOp::kMod:
      return kMulLevel;
    default:
      return kCompareLevel;
  }
}

std::string_view binary_spelling(BinaryOp op) {
  constexpr std::string_view kSpellings[] = {"||", "&&", "==", "!=", "<", "<=", ">",
                                             ">=", "+",  "-",  "*",  "/", "%"};
  return kSpellings[static_cast<int>(op)];
}

bool is_plain_relative(const Expr& expr) {
  return expr.kind == ExprKind::kUnary && expr.unary_op == UnaryOp::kRelative &&
         expr.operands[0]->kind == ExprKind::kNumber && expr.operands[0]->number >= 0;
}

// The level at which `expr` is produced by the parser (what it can appear under unwrapped).
int level_of(const Expr& expr) {
  switch (expr.kind) {
    case ExprKind::kUnary:
      if (is_plain_relative(expr)) return kPostfixLevel;  // `2r` is one token
      return expr.unary_op == UnaryOp::kNot ? kNotLevel : kUnaryLevel;
    case ExprKind::kBinary:
      return binary_level(expr.binary_op);
    case ExprKind::kNumber:
      return expr.number < 0 ? kUnaryLevel : kPostfixLevel;
    default:
      return kPostfixLevel;
  }
}

class ExprPrinter {
 public:
  std::string take() { return std::move(out_); }

  void expr(const Expr& e) {
    switch (e.kind) {
      case ExprKind::kNumber:
        if (e.number < 0) out_ += '-';
        out_ += number_text(std::abs(e.number));
        return;
      case ExprKind::kString:
        out_ += string_literal(e.text);
        return;
      case ExprKind::kBool:
        out_ += e.boolean ? "true" : "false";
        return;
      case ExprKind::kIdent:
        out_ += e.text;
        return;
      case ExprKind::kMember:
        operand(*e.operands[0], kPostfixLevel);
        out_ += '.';
        out_ += e.text;
        return;
      case ExprKind::kCall:
        call(e);
        return;
      case ExprKind::kUnary:
        unary(e);
        return;
      case ExprKind::kBinary:
        binary(e);
        return;
    }
  }

 private:
  void operand(const Expr& e, int min_level) {
    const bool wrap = level_of(e) < min_level;
    if (wrap) out_ += '(';
    expr(e);
    if (wrap) out_ += ')';
  }

  void call(const Expr& e) {
    operand(*e.operands[0], kPostfixLevel);
    out_ += '(';
    for (std::size_t i = 1; i < e.operands.size(); ++i) {
      if (i > 1) out_ += ", ";
      expr(*e.operands[i]);
    }
    out_ += ')';
  }

  void unary(const Expr& e) {
    if (is_plain_relative(e)) {
      out_ += number_text(e.operands[0]->number);
      out_ += 'r';
      return;
    }
    switch (e.unary_op) {
      case UnaryOp::kNot:
        // `!x == 1` already means !(x == 1), but reads as (!x) == 1: comparisons get parentheses.
        out_ += '!';
        return operand(*e.operands[0], kAddLevel);
      case UnaryOp::kNegate:
        out_ += '-';
        break;
      case UnaryOp::kFloating:
        out_ += '~';
        break;
      case UnaryOp::kRelative:
        out_ += '\'';
        break;
    }
    // A nested prefix operator is separated by a space (`- -x`: `--x` could read as an arrow's
    // start), not parenthesised: parentheses are a nesting level each, so a chain of prefixes
    // the parser accepted would print as one nested twice as deep, past its limit (found by
    // cga_fuzz). A negative number literal keeps its parentheses, so that it stays one literal.
    const Expr& inner = *e.operands[0];
    if (inner.kind == ExprKind::kUnary && inner.unary_op != UnaryOp::kNot) {
      out_ += ' ';
      return operand(inner, kUnaryLevel);
    }
    operand(inner, level_of(inner) == kUnaryLevel ? kPostfixLevel : kUnaryLevel);
  }

  void binary(const Expr& e) {
    const int level = binary_level(e.binary_op);
    // Chains are left-associative; a comparison takes additive operands on both sides.
    const int left = level == kCompareLevel ? kAddLevel : level;
    const int right = level == kCompareLevel ? kAddLevel : level + 1;
    operand(*e.operands[0], left);
    out_ += ' ';
    out_ += binary_spelling(e.binary_op);
    out_ += ' ';
    operand(*e.operands[1], right);
  }

  std::string out_;
};

class GrammarPrinter {
 public:
  std::string run(const Grammar& g) {
    for (const AttrDecl& attr : g.attrs) {
      out_ += "attr " + attr.name + " = " + print(*attr.value) + ";\n";
    }
    for (const PrioritySet& set : g.sets) {
      if (!out_.empty()) out_ += '\n';
      if (!set.implicit) out_ += "PRIORITY " + std::to_string(set.priority) + ":\n";
      for (const Rule& rule : set.rules) this->rule(rule);
    }
    return std::move(out_);
  }

 private:
  void rule(const Rule& r) {
    if (r.id.empty()) {
      out_ += r.predecessor;
    } else {
      out_ += r.id + ": " + r.predecessor;
      if (r.condition) {
        out_ += " : ";
        out_ += print(*r.condition);
      }
    }
    for (std::size_t i = 0; i < r.alternatives.size(); ++i) {
      if (i > 0) out_ += "\n   ";
      alternative(r.alternatives[i]);
    }
    out_ += '\n';
  }

  void alternative(const Alternative& alt) {
    out_ += ' ';
    out_ += alt.arrow;
    items(alt.items);
    if (!alt.probability) return;
    const Expr& p = *alt.probability;
    const bool bare = p.kind == ExprKind::kNumber ||
                      (p.kind == ExprKind::kUnary && p.unary_op == UnaryOp::kNegate) ||
                      is_plain_relative(p);
    out_ += bare ? " : " : " : (";
    out_ += print(p);
    if (!bare) out_ += ')';
  }

  void items(const std::vector<Item>& list) {
    for (const Item& it : list) {
      out_ += ' ';
      item(it);
    }
  }

  void item(const Item& it) {
    switch (it.kind) {
      case ItemKind::kSymbol:
        out_ += it.name;
        return;
      case ItemKind::kEmpty:
        out_ += "\xCE\xB5";  // ε, the paper's spelling
        return;
      case ItemKind::kPush:
        out_ += '[';
        return;
      case ItemKind::kPop:
        out_ += ']';
        return;
      case ItemKind::kOp:
        break;
    }
    out_ += it.name + "(";
    for (std::size_t i = 0; i < it.args.size(); ++i) {
      if (i > 0) out_ += ", ";
      out_ += print(*it.args[i]);
    }
    out_ += ')';
    if (it.has_block) block(it.branches);
  }

  void block(const std::vector<Branch>& branches) {
    out_ += '{';
    for (std::size_t i = 0; i < branches.size(); ++i) {
      if (i > 0) out_ += " |";
      branch(branches[i]);
    }
    out_ += " }";
  }

  void branch(const Branch& b) {
    if (b.repeat) {
      out_ += ' ';
      block(b.pattern);
      out_ += '*';
      return;
    }
    if (b.key) {
      out_ += ' ';
      out_ += print(*b.key);
      out_ += ':';
    }
    items(b.items);
  }

  std::string out_;
};

}  // namespace

std::string number_text(double value) {
  return base::shortest_number(value);
}

std::string string_literal(const std::string& text) {
  return base::quoted_string(text);
}

bool is_identifier(const std::string& name) {
  if (name.empty()) return false;
  const auto start = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  if (!start(name[0])) return false;
  for (const char c : name) {
    if (!start(c) && !(c >= '0' && c <= '9')) return false;
  }
  constexpr std::string_view kKeywords[] = {"PRIORITY", "attr", "true",    "false", "and",
                                            "or",       "not",  "epsilon", "NIL"};
  for (const std::string_view keyword : kKeywords) {
    if (keyword == name) return false;
  }
  return true;
}

std::string print(const Expr& expr) {
  ExprPrinter printer;
  printer.expr(expr);
  return printer.take();
}

std::string print(const Grammar& grammar) {
  return GrammarPrinter().run(grammar);
}

}  // namespace insula::lang::cga
