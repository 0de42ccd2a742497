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
  kSelectLevel = 0,  // CityEngine's `case` / percentage chains: only at an expression's start
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

std::string_view binary_spelling(BinaryOp op, bool elementwise = false) {
  constexpr std::string_view kElementwise[] = {".||", ".&&", ".==", ".!=", ".<", ".<=", ".>",
                                               ".>=", ".+",  ".-",  ".*",  "./", "%"};
  if (elementwise) return kElementwise[static_cast<int>(op)];
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
    case ExprKind::kCase:
    case ExprKind::kChance:
      return kSelectLevel;
    default:
      return kPostfixLevel;
  }
}

std::string print_expr(const Expr& expr);

// A stochastic branch's key as CityEngine's parser recognises it: a number, a (qualified) name or
// a parenthesised expression, then `%`.
std::string percentage(const Expr& key) {
  const bool bare = (key.kind == ExprKind::kNumber && key.number >= 0) ||
                    key.kind == ExprKind::kIdent ||
                    (key.kind == ExprKind::kMember && key.operands[0]->kind == ExprKind::kIdent);
  std::string out = bare ? "" : "(";
  out += print_expr(key);
  out += bare ? "%" : ")%";
  return out;
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
      case ExprKind::kCase:
      case ExprKind::kChance:
        select(e);
        return;
      case ExprKind::kArray:
        out_ += '[';
        elements(e);
        out_ += ']';
        return;
      case ExprKind::kIndex:
        operand(*e.operands[0], kPostfixLevel);
        out_ += '[';
        for (std::size_t i = 1; i < e.operands.size(); ++i) {
          if (i > 1) out_ += ", ";
          expr(*e.operands[i]);
        }
        out_ += ']';
        return;
      case ExprKind::kComp:
        comp_function(e);
        return;
      case ExprKind::kRange:
        for (std::size_t i = 0; i < e.operands.size(); ++i) {
          if (i > 0) out_ += ':';
          operand(*e.operands[i], kPostfixLevel);
        }
        return;
    }
  }

  // An array's elements, or its rows separated by `;`.
  void elements(const Expr& e) {
    for (std::size_t i = 0; i < e.operands.size(); ++i) {
      if (i > 0) out_ += e.boolean ? "; " : ", ";
      if (e.boolean) {
        elements(*e.operands[i]);
      } else {
        expr(*e.operands[i]);
      }
    }
  }

  // `comp(fe) { front : 1 | back = 2 }`.
  void comp_function(const Expr& e) {
    out_ += "comp(";
    expr(*e.operands[0]);
    out_ += ") { ";
    for (std::size_t i = 1; i + 1 < e.operands.size(); i += 2) {
      if (i > 1) out_ += " | ";
      expr(*e.operands[i]);
      out_ += e.text[i / 2] == '=' ? " = " : " : ";
      expr(*e.operands[i + 1]);
    }
    out_ += " }";
  }

  // `case c : v ... else : w` and `30% : v ... else : w` (CityEngine).
  void select(const Expr& e) {
    const std::size_t pairs = e.operands.size() / 2;
    for (std::size_t i = 0; i < pairs; ++i) {
      if (i > 0) out_ += ' ';
      if (e.kind == ExprKind::kCase) {
        out_ += "case ";
        expr(*e.operands[2 * i]);
      } else {
        out_ += percentage(*e.operands[2 * i]);
      }
      out_ += " : ";
      expr(*e.operands[2 * i + 1]);
    }
    out_ += " else : ";
    expr(*e.operands.back());
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
    out_ += binary_spelling(e.binary_op, e.elementwise);
    out_ += ' ';
    operand(*e.operands[1], right);
  }

  std::string out_;
};

class GrammarPrinter {
 public:
  std::string run(const Grammar& g) {
    cityengine_ = g.dialect == Dialect::kCityEngine;
    if (cityengine_) declarations(g);
    for (const AttrDecl& attr : g.attrs) {
      annotations(attr.annotations);
      out_ += "attr " + attr.name + " = " + print(*attr.value) + ";\n";
    }
    for (const FunctionDecl& fn : g.functions) {
      annotations(fn.annotations);
      out_ += (fn.is_const ? "const " : "") + fn.name;
      if (!fn.params.empty() || !fn.is_const) params(fn.params);
      out_ += " = " + print(*fn.body) + ";\n";
    }
    for (const PrioritySet& set : g.sets) {
      if (!out_.empty()) out_ += '\n';
      if (!set.implicit) out_ += "PRIORITY " + std::to_string(set.priority) + ":\n";
      for (const Rule& rule : set.rules) this->rule(rule);
    }
    for (const std::string& style : g.styles) out_ += "style " + style + "\n";
    return std::move(out_);
  }

 private:
  void declarations(const Grammar& g) {
    if (!g.version.empty()) out_ += "version " + string_literal(g.version) + "\n";
    for (const ImportDecl& imp : g.imports) {
      annotations(imp.annotations);
      out_ += "import " + imp.alias + " : " + string_literal(imp.path);
      if (imp.has_list) {
        std::vector<std::string> entries = imp.protected_attrs;
        for (const auto& [name, value] : imp.overrides)
          entries.push_back(name + " = " + print(*value));
        for (const Rule& r : imp.rule_overrides) entries.push_back(rule_text(r));
        out_ += " (";
        for (std::size_t i = 0; i < entries.size(); ++i) {
          if (i > 0) out_ += ", ";
          out_ += entries[i];
        }
        out_ += ')';
      }
      out_ += '\n';
    }
  }

  void annotations(const std::vector<Annotation>& list) {
    for (const Annotation& a : list) {
      out_ += "@" + a.name;
      if (!a.args.empty()) {
        out_ += '(';
        for (std::size_t i = 0; i < a.args.size(); ++i) {
          if (i > 0) out_ += ", ";
          if (!a.keys[i].empty()) out_ += a.keys[i] + " = ";
          out_ += print(*a.args[i]);
        }
        out_ += ')';
      }
      out_ += '\n';
    }
  }

  void params(const std::vector<std::string>& names) {
    out_ += '(';
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (i > 0) out_ += ", ";
      out_ += names[i];
    }
    out_ += ')';
  }

  // A rule on one line (an import's redefinition), without its newline.
  std::string rule_text(const Rule& r) {
    std::string saved = std::move(out_);
    out_.clear();
    rule(r);
    std::string text = std::move(out_);
    out_ = std::move(saved);
    if (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
  }

  void rule(const Rule& r) {
    annotations(r.annotations);
    if (r.id.empty() || cityengine_) {
      out_ += r.predecessor;
      if (!r.params.empty()) params(r.params);
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
        if (!it.args.empty()) {
          out_ += '(';
          for (std::size_t i = 0; i < it.args.size(); ++i) {
            if (i > 0) out_ += ", ";
            out_ += print(*it.args[i]);
          }
          out_ += ')';
        }
        if (it.terminal) out_ += '.';
        return;
      case ItemKind::kCase:
      case ItemKind::kChance:
        for (std::size_t i = 0; i < it.branches.size(); ++i) {
          const Branch& b = it.branches[i];
          if (i > 0) out_ += ' ';
          if (!b.key) {
            out_ += "else :";
          } else if (it.kind == ItemKind::kCase) {
            out_ += "case " + print(*b.key) + " :";
          } else {
            out_ += percentage(*b.key) + " :";
          }
          items(b.items);
        }
        return;
      case ItemKind::kEmpty:
        out_ += cityengine_ ? "NIL" : "\xCE\xB5";  // ε, the paper's spelling
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
      out_ += b.merged ? " =" : ":";
    }
    items(b.items);
  }

  std::string out_;
  bool cityengine_ = false;
};

std::string print_expr(const Expr& expr) {
  ExprPrinter printer;
  printer.expr(expr);
  return printer.take();
}

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
  return print_expr(expr);
}

std::string print(const Grammar& grammar) {
  return GrammarPrinter().run(grammar);
}

}  // namespace insula::lang::cga
