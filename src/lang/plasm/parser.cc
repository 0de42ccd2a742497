// Recursive-descent parser for PLaSM (seed 002), one method per production:
//
//   program    = { statement } EOF ;
//   statement  = ( "DEF" binding | expr | ) ";" ;
//   binding    = IDENT { group } "=" expr [ "WHERE" binding { "," binding } "END" ] ;
//   group      = "(" decl { ";" decl } ")" ;
//   decl       = IDENT { "," IDENT } [ "::" expr ] ;      (* the names share the predicate *)
//   expr       = range { IDENT range } ;                  (* a TOP b is TOP:<a, b> *)
//   range      = additive [ ".." additive ] ;
//   additive   = term { ( "+" | "-" ) term } ;
//   term       = power { ( "*" | "/" ) power } ;
//   power      = compose { "**" compose } ;
//   compose    = apply { "~" apply } ;
//   apply      = primary { ":" primary } ;
//   primary    = NUMBER | "-" NUMBER | STRING | IDENT | opvalue | "#" | "##"
//              | "(" expr ")" | "[" [ list ] "]" | "<" [ list ] ">"
//              | "IF" ":" "<" expr "," expr "," expr ">" ;
//   list       = expr { "," expr } ;
//   opvalue    = "+" | "-" | "*" | "/" | "**" | "~" ;     (* not followed by an operand *)
//
// Every binary level is left-associative, as in the original grammar (its yacc file declares
// them %left, `**` included). An operator where an operand is expected is the operator as a
// value when no operand follows it (`AA:-`, `C:*:(PI/6)`, `- ~ SIN`); `-` directly before a
// number is a negative literal (`S:1:-1`, `7*dm/-12`, `<-6,0>`); PLaSM has no unary minus on
// other operands (`-x` is PSM103: write `-:x`). An identifier after a complete operand is an
// infix function, unless `=` follows it (then it is the next WHERE local after a missing comma).
#include "lang/plasm/parser.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "lang/plasm/lexer.h"

namespace insula::lang::plasm {
namespace {

// Thrown after a syntax error has been recorded; caught at statement level, where the parser
// skips past the next `;`. Never leaves this file.
struct Abort {};

class Parser {
 public:
  Parser(const base::Source& source, LexOutput lexed)
      : source_(source), tokens_(std::move(lexed.tokens)), diags_(std::move(lexed.diagnostics)) {
    program_.file = source.name();
  }

  base::Result<Program> run() {
    while (!at(Tok::kEnd) && !too_many_errors()) {
      const std::size_t start = pos_;
      try {
        statement();
      } catch (const Abort&) {
        synchronize(start);
      }
    }
    std::stable_sort(diags_.begin(), diags_.end(), [](const auto& a, const auto& b) {
      return std::pair(a.span.line, a.span.column) < std::pair(b.span.line, b.span.column);
    });
    if (too_many_errors()) {
      diags_.resize(kMaxErrors);
      diags_.push_back(base::Diagnostic::error("PSM108", "too many errors; giving up",
                                               span_of(source_, peek().range)));
    }
    if (base::has_errors(diags_)) return base::Result<Program>::failure(std::move(diags_));
    return base::Result<Program>(std::move(program_), std::move(diags_));
  }

 private:
  // ---- token access ----
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  bool at(Tok kind, std::size_t ahead = 0) const { return peek(ahead).kind == kind; }
  const Token& advance() {
    const Token& token = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    prev_end_ = token.range.end;
    return token;
  }
  bool accept(Tok kind) {
    if (!at(kind)) return false;
    advance();
    return true;
  }
  const Token& expect(Tok kind, const std::string& context) {
    if (!at(kind))
      fail("PSM101", "expected " + token_name(kind) + context + ", found " + describe(peek()));
    return advance();
  }
  Range from(std::uint32_t begin) const { return Range{begin, std::max(begin, prev_end_)}; }

  // ---- diagnostics ----
  bool too_many_errors() const { return static_cast<int>(diags_.size()) > kMaxErrors; }
  void report(std::string code, std::string message, Range range) {
    diags_.push_back(
        base::Diagnostic::error(std::move(code), std::move(message), span_of(source_, range)));
  }
  [[noreturn]] void fail(std::string code, std::string message) {
    report(std::move(code), std::move(message), peek().range);
    throw Abort{};
  }

  // Skips past the next `;`, or to the next `DEF`; always moves on by at least one token.
  void synchronize(std::size_t start) {
    if (pos_ == start && !at(Tok::kEnd)) advance();
    while (!at(Tok::kEnd)) {
      if (accept(Tok::kSemicolon) || at(Tok::kDef)) return;
      advance();
    }
  }

  class Nest {
   public:
    explicit Nest(Parser& parser, int extra = 0) : parser_(parser) {
      if (++parser_.depth_ + extra > kMaxNesting) {
        --parser_.depth_;  // no destructor runs for a constructor that throws
        parser_.fail("PSM105", "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
      }
    }
    ~Nest() { --parser_.depth_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;

   private:
    Parser& parser_;
  };

  // ---- statements and bindings ----
  void statement() {
    if (accept(Tok::kSemicolon)) return;
    Statement st;
    const std::uint32_t begin = peek().range.begin;
    if (accept(Tok::kDef)) {
      st.is_def = true;
      st.def = binding("'DEF'");
      expect(Tok::kSemicolon, " after the definition of '" + st.def.name + "'");
    } else if (starts_operand() || operator_value(peek().kind)) {
      st.expr = expr();
      expect(Tok::kSemicolon, " after the expression");
    } else {
      fail("PSM102", "expected 'DEF' or an expression, found " + describe(peek()));
    }
    st.range = from(begin);
    program_.statements.push_back(std::move(st));
  }

  Def binding(const std::string& after) {
    Nest nest(*this);
    Def def;
    const Token& name = expect(Tok::kIdent, " (the name being defined) after " + after);
    def.name = name.text;
    def.key = name.key;
    def.name_range = name.range;
    while (at(Tok::kLParen)) def.groups.push_back(group());
    expect(Tok::kAssign, def.groups.empty() ? " after the name '" + def.name + "'"
                                            : " after the parameters of '" + def.name + "'");
    def.body = expr();
    if (accept(Tok::kWhere)) {
      def.has_where = true;
      do {
        def.locals.push_back(binding("WHERE or ','"));
      } while (accept(Tok::kComma));
      expect(Tok::kEndKw, " or ',' after the locals of '" + def.name + "'");
    }
    def.range = from(name.range.begin);
    return def;
  }

  ParamGroup group() {
    ParamGroup group;
    const std::uint32_t begin = advance().range.begin;  // '('
    do {
      ParamDecl decl;
      do {
        const Token& name = expect(Tok::kIdent, " (a parameter name)");
        decl.names.push_back(Param{name.text, name.key, name.range});
      } while (accept(Tok::kComma));
      if (accept(Tok::kTypeSep)) {
        if (!starts_operand() && !operator_value(peek().kind)) {
          fail("PSM104",
               "expected an expression (the predicate) after '::', found " + describe(peek()));
        }
        decl.predicate = expr();
      }
      group.decls.push_back(std::move(decl));
    } while (accept(Tok::kSemicolon));
    expect(Tok::kRParen, " to close the parameter group");
    group.range = from(begin);
    return group;
  }

  // ---- expressions ----
  ExprPtr make(ExprKind kind, Range range) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->range = range;
    return e;
  }
  ExprPtr make_pair(ExprKind kind, ExprPtr left, ExprPtr right) {
    ExprPtr e = make(kind, Range{left->range.begin, right->range.end});
    e->operands.push_back(std::move(left));
    e->operands.push_back(std::move(right));
    return e;
  }

  bool starts_operand(std::size_t ahead = 0) const {
    switch (peek(ahead).kind) {
      case Tok::kNumber:
      case Tok::kString:
      case Tok::kIdent:
      case Tok::kLParen:
      case Tok::kLBracket:
      case Tok::kLt:
      case Tok::kHash:
      case Tok::kHashHash:
      case Tok::kIf:
        return true;
      default:
        return false;
    }
  }

  static std::optional<Op> operator_value(Tok kind) {
    switch (kind) {
      case Tok::kPlus:
        return Op::kAdd;
      case Tok::kMinus:
        return Op::kSub;
      case Tok::kStar:
        return Op::kMul;
      case Tok::kSlash:
        return Op::kDiv;
      case Tok::kPower:
        return Op::kPow;
      case Tok::kTilde:
        return Op::kCompose;
      default:
        return std::nullopt;
    }
  }

  // Left-associative chain of `next` joined by the operators `op_of` names; `length` bounds the
  // depth of the left-deep tree like nesting does.
  template <typename Next, typename OpOf>
  ExprPtr chain(Next next, OpOf op_of) {
    ExprPtr left = (this->*next)();
    int length = 0;
    while (const std::optional<std::pair<ExprKind, Op>> op = op_of(peek().kind)) {
      Nest nest(*this, ++length);
      advance();
      ExprPtr e = make_pair(op->first, std::move(left), (this->*next)());
      e->op = op->second;
      left = std::move(e);
    }
    return left;
  }

  ExprPtr expr() {
    Nest nest(*this);
    ExprPtr left = range();
    int length = 0;
    while (at(Tok::kIdent) && !at(Tok::kAssign, 1)) {
      Nest link(*this, ++length);
      const Token& name = advance();
      if (!starts_operand() && !operator_value(peek().kind)) {
        fail("PSM104", "expected an expression after the infix function '" + name.text +
                           "', found " + describe(peek()));
      }
      ExprPtr e = make_pair(ExprKind::kInfix, std::move(left), range());
      e->text = name.text;
      e->key = name.key;
      e->name_range = name.range;
      left = std::move(e);
    }
    return left;
  }

  ExprPtr range() {
    ExprPtr left = additive();
    if (!accept(Tok::kDotDot)) return left;
    return make_pair(ExprKind::kRange, std::move(left), additive());
  }

  using OpPair = std::optional<std::pair<ExprKind, Op>>;

  ExprPtr additive() {
    return chain(&Parser::term, [](Tok k) -> OpPair {
      if (k == Tok::kPlus) return std::pair(ExprKind::kBinary, Op::kAdd);
      if (k == Tok::kMinus) return std::pair(ExprKind::kBinary, Op::kSub);
      return std::nullopt;
    });
  }
  ExprPtr term() {
    return chain(&Parser::power, [](Tok k) -> OpPair {
      if (k == Tok::kStar) return std::pair(ExprKind::kBinary, Op::kMul);
      if (k == Tok::kSlash) return std::pair(ExprKind::kBinary, Op::kDiv);
      return std::nullopt;
    });
  }
  ExprPtr power() {
    return chain(&Parser::compose, [](Tok k) -> OpPair {
      if (k == Tok::kPower) return std::pair(ExprKind::kBinary, Op::kPow);
      return std::nullopt;
    });
  }
  ExprPtr compose() {
    return chain(&Parser::apply, [](Tok k) -> OpPair {
      if (k == Tok::kTilde) return std::pair(ExprKind::kCompose, Op::kCompose);
      return std::nullopt;
    });
  }
  ExprPtr apply() {
    return chain(&Parser::primary, [](Tok k) -> OpPair {
      if (k == Tok::kColon) return std::pair(ExprKind::kApply, Op::kAdd);
      return std::nullopt;
    });
  }

  ExprPtr primary() {
    const Token& token = peek();
    switch (token.kind) {
      case Tok::kNumber: {
        advance();
        ExprPtr e = make(ExprKind::kNumber, token.range);
        e->number = token.number;
        e->text = token.text;
        return e;
      }
      case Tok::kString: {
        advance();
        ExprPtr e = make(ExprKind::kString, token.range);
        e->text = token.text;
        return e;
      }
      case Tok::kIdent: {
        advance();
        ExprPtr e = make(ExprKind::kName, token.range);
        e->text = token.text;
        e->key = token.key;
        return e;
      }
      case Tok::kHash:
      case Tok::kHashHash: {
        advance();
        ExprPtr e = make(ExprKind::kOperator, token.range);
        e->op = token.kind == Tok::kHash ? Op::kRepeat : Op::kRepeatCat;
        e->text = token.text;
        return e;
      }
      case Tok::kLParen: {
        Nest nest(*this);
        advance();
        ExprPtr inner = expr();
        expect(Tok::kRParen, " to close '('");
        return inner;
      }
      case Tok::kLBracket:
        return list(ExprKind::kConstruct, Tok::kRBracket, " or ',' to close the construction '['");
      case Tok::kLt:
        return list(ExprKind::kSequence, Tok::kGt, " or ',' to close the sequence '<'");
      case Tok::kIf:
        return if_form();
      default:
        return operator_primary();
    }
  }

  ExprPtr operator_primary() {
    const Token& token = peek();
    const std::optional<Op> op = operator_value(token.kind);
    if (!op) fail("PSM104", "expected an expression, found " + describe(token));
    if (token.kind == Tok::kMinus && at(Tok::kNumber, 1)) {
      const std::uint32_t begin = advance().range.begin;
      const Token& number = advance();
      ExprPtr e = make(ExprKind::kNumber, from(begin));
      e->number = -number.number;
      e->text = "-" + number.text;
      return e;
    }
    if (starts_operand(1)) {
      if (token.kind == Tok::kMinus) {
        fail("PSM103", "PLaSM has no unary minus: write -:x to negate x (or a literal such as -1)");
      }
      fail("PSM104", "expected an expression, found " + describe(token));
    }
    advance();
    ExprPtr e = make(ExprKind::kOperator, token.range);
    e->op = *op;
    e->text = token.text;
    return e;
  }

  ExprPtr list(ExprKind kind, Tok close, const std::string& context) {
    Nest nest(*this);
    const std::uint32_t begin = advance().range.begin;
    ExprPtr e = make(kind, Range{begin, begin});
    if (!at(close)) {
      do {
        e->operands.push_back(expr());
      } while (accept(Tok::kComma));
    }
    expect(close, context);
    e->range = from(begin);
    return e;
  }

  ExprPtr if_form() {
    const Token& keyword = advance();
    if (!at(Tok::kColon) || !at(Tok::kLt, 1)) {
      report("PSM106", "IF is written IF:<predicate, then, else>", keyword.range);
      throw Abort{};
    }
    advance();  // ':'
    ExprPtr seq = list(ExprKind::kSequence, Tok::kGt, " or ',' to close IF:<...>");
    if (seq->operands.size() != 3) {
      report("PSM107",
             "IF:<...> takes 3 functions (predicate, then, else), found " +
                 std::to_string(seq->operands.size()),
             from(keyword.range.begin));
    }
    ExprPtr e = make(ExprKind::kIf, from(keyword.range.begin));
    e->text = keyword.text;
    e->operands = std::move(seq->operands);
    return e;
  }

  const base::Source& source_;
  std::vector<Token> tokens_;
  std::vector<base::Diagnostic> diags_;
  std::size_t pos_ = 0;
  std::uint32_t prev_end_ = 0;
  int depth_ = 0;
  Program program_;
};

}  // namespace

base::Result<Program> parse(const base::Source& source) {
  return Parser(source, lex(source)).run();
}

}  // namespace insula::lang::plasm
