#include "lang/plasm/ast_dump.h"

#include <initializer_list>
#include <string_view>

#include "base/format.h"

namespace insula::lang::plasm {

std::string_view op_name(Op op) {
  constexpr std::string_view kNames[] = {"+", "-", "*", "/", "**", "~", "#", "##"};
  return kNames[static_cast<int>(op)];
}

namespace {

// Concatenation through append: GCC 12 reports a false -Wrestrict on `"(" + std::string(...)`.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (const std::string_view part : parts) out.append(part);
  return out;
}

void append_list(std::string& out, std::string_view head, const Expr& e) {
  out += '(';
  out.append(head);
  for (const ExprPtr& operand : e.operands) {
    out += ' ';
    out += dump(*operand);
  }
  out += ')';
}

class Dumper {
 public:
  explicit Dumper(const base::Source& source) : source_(source) {}

  std::string program(const Program& p) {
    out_ = cat({"(program ", base::quoted_string(p.file)});
    for (const Statement& st : p.statements) {
      if (st.is_def) {
        def(st.def, 1);
      } else {
        line(1, cat({"(expr", at(st.range), " ", dump(*st.expr), ")"}));
      }
    }
    out_ += ")\n";
    return std::move(out_);
  }

 private:
  std::string at(Range range) const {
    const auto [l, c] = source_.locate(range.begin);
    return cat({" @", std::to_string(l), ":", std::to_string(c)});
  }

  void line(int depth, const std::string& text) {
    out_ += '\n';
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += text;
  }

  void def(const Def& d, int depth) {
    std::string head = cat({"(def ", d.name, at(d.range)});
    for (const ParamGroup& g : d.groups) {
      head += ' ';
      head += group(g);
    }
    line(depth, head);
    line(depth + 1, dump(*d.body));
    if (d.has_where) {
      line(depth + 1, "(where");
      for (const Def& local : d.locals) def(local, depth + 2);
      out_ += ')';
    }
    out_ += ')';
  }

  static std::string group(const ParamGroup& g) {
    std::string out = "(";
    for (std::size_t i = 0; i < g.decls.size(); ++i) {
      if (i > 0) out += "; ";
      const ParamDecl& decl = g.decls[i];
      for (std::size_t k = 0; k < decl.names.size(); ++k) {
        if (k > 0) out += ' ';
        out += decl.names[k].text;
      }
      if (decl.predicate) {
        out += " :: ";
        out += dump(*decl.predicate);
      }
    }
    out += ')';
    return out;
  }

  const base::Source& source_;
  std::string out_;
};

}  // namespace

std::string dump(const Program& program, const base::Source& source) {
  return Dumper(source).program(program);
}

std::string dump(const Expr& e) {
  std::string out;
  switch (e.kind) {
    case ExprKind::kNumber:
      return base::shortest_number(e.number);
    case ExprKind::kString:
      return base::quoted_string(e.text);
    case ExprKind::kName:
      return e.text;
    case ExprKind::kOperator:
      return cat({"(op ", op_name(e.op), ")"});
    case ExprKind::kApply:
      append_list(out, ":", e);
      return out;
    case ExprKind::kCompose:
      append_list(out, "~", e);
      return out;
    case ExprKind::kConstruct:
      append_list(out, "cons", e);
      return out;
    case ExprKind::kSequence:
      append_list(out, "seq", e);
      return out;
    case ExprKind::kRange:
      append_list(out, "..", e);
      return out;
    case ExprKind::kBinary:
      append_list(out, op_name(e.op), e);
      return out;
    case ExprKind::kInfix:
      append_list(out, cat({"infix ", e.text}), e);
      return out;
    case ExprKind::kIf:
      append_list(out, "if", e);
      return out;
  }
  return out;
}

}  // namespace insula::lang::plasm
