// Recursive-descent parser for CGA (seed 004 §VI), one method per production:
//
//   grammar      = { attr_decl | priority | rule | ";" } EOF ;
//   attr_decl    = "attr" IDENT "=" expr [ ";" ] ;
//   priority     = "PRIORITY" NATURAL ":" ;          (* the rules after it form the set *)
//   rule         = rule_id ":" IDENT [ ":" expr ] alternative { alternative } [ ";" ]
//                | IDENT ( "->" | "-->" ) successor [ ":" probability ]
//                        { alternative } [ ";" ] ;   (* unnamed rule, no condition *)
//   rule_id      = NATURAL | IDENT ;
//   alternative  = ( "~>" | "->" | "-->" ) successor [ ":" probability ] ;
//   probability  = NUMBER | "-" NUMBER | "(" expr ")" ;
//   successor    = item { item } ;
//   item         = IDENT | operation | EPSILON | "[" | "]" ;
//   operation    = IDENT "(" [ expr { "," expr } ] ")" [ block ] ;
//   block        = "{" branch { ( "|" | "," ) branch } "}" ;
//   branch       = "{" branch { ( "|" | "," ) branch } "}" "*"      (* repeat pattern *)
//                | [ expr ":" ] successor ;           (* size or selector key *)
//   expr         = and_expr { ( "||" | "or" ) and_expr } ;
//   and_expr     = not_expr { ( "&&" | "and" ) not_expr } ;
//   not_expr     = ( "!" | "not" ) not_expr | comparison ;
//   comparison   = additive [ ( "==" | "!=" | "<>" | "<" | "<=" | ">" | ">=" ) additive ] ;
//   additive     = term { ( "+" | "-" ) term } ;
//   term         = unary { ( "*" | "/" | "%" ) unary } ;
//   unary        = ( "-" | "~" | "'" ) unary | postfix ;
//   postfix      = primary { "." IDENT | "(" [ expr { "," expr } ] ")" } ;
//   primary      = NUMBER [ "r" ] | STRING | "true" | "false" | IDENT | "(" expr ")" ;
//   EPSILON      = "ε" | "epsilon" | "NIL" ;
//
// Where a rule ends is decided with at most three tokens of lookahead inside a successor: an
// identifier followed by ":" and then anything but a probability starts the next rule
// (`4: Wall ~> ...`), as does an identifier followed by "->" or "-->".
#include "lang/cga/parser.h"

#include <algorithm>
#include <optional>
#include <string>

#include "lang/cga/lexer.h"
#include "lang/cga/operations.h"

namespace insula::lang::cga {
namespace {

// Thrown after a syntax error has been recorded; caught at rule level, where the parser skips
// to the next rule. Never leaves this file.
struct Abort {};

class Parser {
 public:
  Parser(const base::Source& source, LexOutput lexed)
      : source_(source), tokens_(std::move(lexed.tokens)), diags_(std::move(lexed.diagnostics)) {
    grammar_.file = source.name();
  }

  base::Result<Grammar> run() {
    while (!at(Tok::kEnd) && !too_many_errors()) {
      try {
        item_start_ = pos_;
        parse_top_level();
      } catch (const Abort&) {
        synchronize();
      }
    }
    std::stable_sort(diags_.begin(), diags_.end(), [](const auto& a, const auto& b) {
      return std::pair(a.span.line, a.span.column) < std::pair(b.span.line, b.span.column);
    });
    if (too_many_errors()) {
      diags_.resize(kMaxErrors);
      diags_.push_back(base::Diagnostic::error("CGA108", "too many errors; giving up",
                                               span_of(source_, peek().range)));
    }
    if (base::has_errors(diags_)) return base::Result<Grammar>::failure(std::move(diags_));
    return base::Result<Grammar>(std::move(grammar_), std::move(diags_));
  }

 private:
  // ---- token access ----
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  bool at(Tok kind, std::size_t ahead = 0) const { return peek(ahead).kind == kind; }
  bool at_arrow(std::size_t ahead = 0) const {
    return at(Tok::kTildeArrow, ahead) || at(Tok::kArrow, ahead) || at(Tok::kLongArrow, ahead);
  }
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
  const Token& expect(Tok kind, std::string_view context) {
    if (!at(kind)) {
      fail("CGA101",
           "expected " + token_name(kind) + std::string(context) + ", found " + describe(peek()));
    }
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

  // Skips to the next token that can start a top-level item: `PRIORITY`, `attr`, past a `;`,
  // or the first token of a line that looks like `id :` or `Pred -->`. The token that failed is
  // kept when the failed item consumed something (it may start the next rule) and skipped
  // otherwise, so the parser always moves on.
  void synchronize() {
    if (pos_ == item_start_ && !at(Tok::kEnd)) advance();
    while (!at(Tok::kEnd)) {
      if (at(Tok::kPriority) || at(Tok::kAttr)) return;
      if (accept(Tok::kSemicolon)) return;
      if (peek().line_start && starts_rule()) return;
      advance();
    }
  }
  bool starts_rule() const {
    if ((at(Tok::kNumber) || at(Tok::kIdent)) && at(Tok::kColon, 1)) return true;
    return at(Tok::kIdent) && (at(Tok::kArrow, 1) || at(Tok::kLongArrow, 1));
  }

  // Counts one level of nesting for the lifetime of the guard.
  class Nest {
   public:
    explicit Nest(Parser& parser, int extra = 0) : parser_(parser) {
      if (++parser_.depth_ + extra > kMaxNesting) {
        --parser_.depth_;  // no destructor runs for a constructor that throws
        parser_.fail("CGA105", "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
      }
    }
    ~Nest() { --parser_.depth_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;

   private:
    Parser& parser_;
  };

  // ---- top level ----
  void parse_top_level() {
    if (at(Tok::kAttr)) return parse_attr();
    if (at(Tok::kPriority)) return parse_priority();
    if (accept(Tok::kSemicolon)) return;
    if (starts_rule()) return parse_rule();
    fail("CGA102", "expected a rule, 'PRIORITY' or 'attr', found " + describe(peek()));
  }

  void parse_attr() {
    AttrDecl decl;
    const std::uint32_t begin = advance().range.begin;
    const Token& name = expect(Tok::kIdent, " (attribute name) after 'attr'");
    decl.name = name.text;
    decl.name_range = name.range;
    expect(Tok::kAssign, " after the attribute name");
    decl.value = parse_expr();
    accept(Tok::kSemicolon);
    decl.range = from(begin);
    grammar_.attrs.push_back(std::move(decl));
  }

  void parse_priority() {
    const std::uint32_t begin = advance().range.begin;
    const Token& number = peek();
    if (!at(Tok::kNumber) || !is_natural(number.text) || number.number > 4294967295.0) {
      fail("CGA110",
           "expected the priority (a natural number) after 'PRIORITY', found " + describe(number));
    }
    advance();
    expect(Tok::kColon, " after the priority");
    PrioritySet set;
    set.priority = static_cast<std::uint32_t>(number.number);
    set.range = from(begin);
    grammar_.sets.push_back(std::move(set));
  }

  static bool is_natural(const std::string& text) {
    return !text.empty() &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  }

  PrioritySet& current_set(std::uint32_t begin) {
    if (grammar_.sets.empty()) {
      PrioritySet set;
      set.implicit = true;
      set.range = Range{begin, begin};
      grammar_.sets.push_back(std::move(set));
    }
    return grammar_.sets.back();
  }

  void parse_rule() {
    Rule rule;
    const std::uint32_t begin = peek().range.begin;
    if (at(Tok::kColon, 1)) {
      const Token& id = advance();
      if (id.kind == Tok::kNumber && !is_natural(id.text)) {
        report("CGA109",
               "a rule id must be a natural number or an identifier, found " + describe(id),
               id.range);
      }
      rule.id = id.text;
      rule.id_range = id.range;
      advance();  // ':'
      const Token& pred = expect(Tok::kIdent, " (the predecessor symbol) after the rule id");
      rule.predecessor = pred.text;
      rule.predecessor_range = pred.range;
      if (accept(Tok::kColon)) rule.condition = parse_expr();
    } else {
      const Token& pred = advance();
      rule.predecessor = pred.text;
      rule.predecessor_range = pred.range;
    }
    if (!at_arrow()) {
      fail("CGA101",
           "expected '~>', '->' or '-->' before the successor, found " + describe(peek()));
    }
    while (at_arrow()) rule.alternatives.push_back(parse_alternative());
    accept(Tok::kSemicolon);
    rule.range = from(begin);
    current_set(begin).rules.push_back(std::move(rule));
  }

  Alternative parse_alternative() {
    Alternative alternative;
    const Token& arrow = advance();
    alternative.arrow = arrow.text;
    alternative.items = parse_successor();
    if (accept(Tok::kColon)) alternative.probability = parse_probability();
    alternative.range = from(arrow.range.begin);
    return alternative;
  }

  ExprPtr parse_probability() {
    if (at(Tok::kNumber) || at(Tok::kMinus)) return parse_unary();
    if (at(Tok::kLParen)) return parse_primary();
    fail("CGA101", "expected a probability (a number or a parenthesised expression), found " +
                       describe(peek()));
  }

  // ---- successors ----
  bool starts_item() const {
    switch (peek().kind) {
      case Tok::kEpsilon:
      case Tok::kLBracket:
      case Tok::kRBracket:
        return true;
      case Tok::kIdent:
        if (at(Tok::kColon, 1)) {
          return at(Tok::kNumber, 2) || at(Tok::kLParen, 2) || at(Tok::kMinus, 2);
        }
        return !at(Tok::kArrow, 1) && !at(Tok::kLongArrow, 1);
      default:
        return false;
    }
  }

  // Push and pop must balance within one successor sequence (§II: the stack saves and restores
  // the scope of the shape being rewritten).
  std::vector<Item> parse_successor() {
    // The first item after an arrow is never the start of the next rule, so `~> B : p` reports
    // the bad probability rather than a missing successor.
    const bool first_is_symbol = at(Tok::kIdent) && at(Tok::kColon, 1);
    if (!first_is_symbol && !starts_item()) {
      fail("CGA103", "expected a successor (a shape, an operation, 'ε', '[' or ']'), found " +
                         describe(peek()));
    }
    std::vector<Item> items;
    std::vector<Range> open;
    while (items.empty() ? (first_is_symbol || starts_item()) : starts_item()) {
      items.push_back(parse_item());
      const Item& item = items.back();
      if (item.kind == ItemKind::kPush) open.push_back(item.range);
      if (item.kind == ItemKind::kPop) {
        if (open.empty()) {
          report("CGA106", "']' without a matching '['", item.range);
        } else {
          open.pop_back();
        }
      }
    }
    for (const Range& range : open) report("CGA107", "'[' is never closed by ']'", range);
    return items;
  }

  Item parse_item() {
    const Token& token = peek();
    Item item;
    item.range = token.range;
    item.name = token.text;
    switch (token.kind) {
      case Tok::kEpsilon:
        item.kind = ItemKind::kEmpty;
        break;
      case Tok::kLBracket:
        item.kind = ItemKind::kPush;
        break;
      case Tok::kRBracket:
        item.kind = ItemKind::kPop;
        break;
      default:
        if (at(Tok::kLParen, 1)) return parse_operation();
        item.kind = ItemKind::kSymbol;
        break;
    }
    advance();
    return item;
  }

  Item parse_operation() {
    Item item;
    item.kind = ItemKind::kOp;
    const Token& name = advance();
    item.name = name.text;
    advance();  // '('
    if (!at(Tok::kRParen)) {
      do {
        item.args.push_back(parse_expr());
      } while (accept(Tok::kComma));
    }
    expect(Tok::kRParen, " to close the argument list of '" + item.name + "'");
    if (at(Tok::kLBrace)) {
      item.has_block = true;
      item.branches = parse_block();
    }
    item.range = from(name.range.begin);
    classify(item);
    return item;
  }

  std::vector<Branch> parse_block() {
    Nest nest(*this);
    expect(Tok::kLBrace, "");
    std::vector<Branch> branches;
    do {
      branches.push_back(parse_branch());
    } while (accept(Tok::kBar) || accept(Tok::kComma));
    expect(Tok::kRBrace, " or '|' in the successor block");
    return branches;
  }

  Branch parse_branch() {
    Branch branch;
    const std::uint32_t begin = peek().range.begin;
    if (at(Tok::kLBrace)) {
      branch.repeat = true;
      branch.pattern = parse_block();
      expect(Tok::kStar, " after a repeat pattern '{ ... }'");
    } else {
      if (branch_has_key()) {
        branch.key = parse_expr();
        expect(Tok::kColon, " after the size or selector of a branch");
      }
      branch.items = parse_successor();
    }
    branch.range = from(begin);
    return branch;
  }

  // A branch has a key when a ':' appears before its end ('|', ',' or '}') outside brackets.
  // Linear in the branch length; nested blocks rescan, bounded by kMaxNesting.
  bool branch_has_key() const {
    int depth = 0;
    for (std::size_t i = pos_; i < tokens_.size(); ++i) {
      // A line that begins with `id :` is the next rule: the block was left open.
      if (i > pos_ && tokens_[i].line_start && i + 1 < tokens_.size() &&
          tokens_[i + 1].kind == Tok::kColon) {
        return false;
      }
      switch (tokens_[i].kind) {
        case Tok::kLParen:
        case Tok::kLBrace:
          ++depth;
          break;
        case Tok::kRParen:
        case Tok::kRBrace:
          if (--depth < 0) return false;
          break;
        case Tok::kBar:
        case Tok::kComma:
          if (depth == 0) return false;
          break;
        case Tok::kColon:
          if (depth == 0) return true;
          break;
        case Tok::kEnd:
        case Tok::kTildeArrow:
        case Tok::kArrow:
        case Tok::kLongArrow:
          return false;
        default:
          break;
      }
    }
    return false;
  }

  // ---- operation kinds and arity (§VI) ----
  // The paper's spellings (BS, RR, CS, T, S, Rx/Ry/Rz, I, Pshape; operations.h) have a kind of
  // their own and a strict form: their arity, block and string first argument are checked here.
  static bool is_rotation(const std::string& name) {
    return name.size() == 2 && name[0] == 'R' &&
           std::string_view("xyzXYZ").find(name[1]) != std::string_view::npos;
  }

  void classify(Item& item) {
    item.op = OpKind::kGeneric;
    std::string name = item.name;
    if (is_rotation(name)) name[1] = static_cast<char>(name[1] | 0x20);  // RX reads as Rx
    const OperationInfo* info = find_operation(name);
    if (info == nullptr || info->kind == OpKind::kGeneric) return;
    item.op = info->kind;
    if (info->kind == OpKind::kRotate) item.axis = name[1];
    check_spec(item, *info);
  }

  void check_spec(const Item& item, const OperationInfo& info) {
    const std::size_t count = item.args.size();
    const bool unbounded = info.max_args == kUnbounded;
    const std::string quoted = "'" + item.name + "'";
    if (count < info.min_args || (!unbounded && count > info.max_args)) {
      std::string wanted = std::to_string(info.min_args);
      if (unbounded) wanted = "at least " + wanted;
      report("CGA201",
             quoted + " expects " + wanted + " argument" +
                 (info.min_args == 1 && info.max_args == 1 ? "" : "s") + ", found " +
                 std::to_string(count),
             item.range);
    }
    const bool block = info.block == BlockUse::kRequired;
    if (block && !item.has_block) {
      report("CGA202", quoted + " needs a successor block '{ ... }'", item.range);
    }
    if (!block && item.has_block) {
      report("CGA203", quoted + " takes no successor block", item.range);
    }
    if (info.string_first && count > 0 && item.args[0]->kind != ExprKind::kString) {
      report("CGA204",
             "the first argument of " + quoted + " must be a string (" +
                 first_argument_role(info.kind) + ")",
             item.args[0]->range);
    }
  }

  static std::string first_argument_role(OpKind kind) {
    switch (kind) {
      case OpKind::kComp:
        return "the component type";
      case OpKind::kPredefined:
        return "the file name";
      default:
        return "the axis";
    }
  }

  // ---- expressions ----
  ExprPtr make(ExprKind kind, Range range) {
    auto expr = std::make_unique<Expr>();
    expr->kind = kind;
    expr->range = range;
    return expr;
  }
  ExprPtr make_binary(BinaryOp op, ExprPtr left, ExprPtr right) {
    ExprPtr expr = make(ExprKind::kBinary, Range{left->range.begin, right->range.end});
    expr->binary_op = op;
    expr->operands.push_back(std::move(left));
    expr->operands.push_back(std::move(right));
    return expr;
  }
  ExprPtr make_unary(UnaryOp op, std::uint32_t begin, ExprPtr operand) {
    ExprPtr expr = make(ExprKind::kUnary, Range{begin, operand->range.end});
    expr->unary_op = op;
    expr->operands.push_back(std::move(operand));
    return expr;
  }

  // Left-associative chains build left-deep trees; `chain` bounds their depth like nesting.
  template <typename Next, typename OpOf>
  ExprPtr parse_chain(Next next, OpOf op_of) {
    ExprPtr left = (this->*next)();
    int chain = 0;
    while (auto op = op_of(peek().kind)) {
      Nest nest(*this, ++chain);
      advance();
      left = make_binary(*op, std::move(left), (this->*next)());
    }
    return left;
  }

  ExprPtr parse_expr() {
    Nest nest(*this);
    return parse_chain(&Parser::parse_and, [](Tok k) -> std::optional<BinaryOp> {
      if (k == Tok::kOr) return BinaryOp::kOr;
      return std::nullopt;
    });
  }

  ExprPtr parse_and() {
    return parse_chain(&Parser::parse_not, [](Tok k) -> std::optional<BinaryOp> {
      if (k == Tok::kAnd) return BinaryOp::kAnd;
      return std::nullopt;
    });
  }

  ExprPtr parse_not() {
    if (!at(Tok::kNot)) return parse_comparison();
    Nest nest(*this);
    const std::uint32_t begin = advance().range.begin;
    return make_unary(UnaryOp::kNot, begin, parse_not());
  }

  static std::optional<BinaryOp> comparison_op(Tok kind) {
    switch (kind) {
      case Tok::kEq:
        return BinaryOp::kEq;
      case Tok::kNe:
        return BinaryOp::kNe;
      case Tok::kLt:
        return BinaryOp::kLt;
      case Tok::kLe:
        return BinaryOp::kLe;
      case Tok::kGt:
        return BinaryOp::kGt;
      case Tok::kGe:
        return BinaryOp::kGe;
      default:
        return std::nullopt;
    }
  }

  ExprPtr parse_comparison() {
    ExprPtr left = parse_additive();
    if (at(Tok::kAssign)) fail("CGA101", "expected '==' to compare, found '='");
    const std::optional<BinaryOp> op = comparison_op(peek().kind);
    if (!op) return left;
    advance();
    ExprPtr result = make_binary(*op, std::move(left), parse_additive());
    if (comparison_op(peek().kind)) {
      fail("CGA101", "comparisons cannot be chained; use 'and' to combine them");
    }
    return result;
  }

  ExprPtr parse_additive() {
    return parse_chain(&Parser::parse_term, [](Tok k) -> std::optional<BinaryOp> {
      if (k == Tok::kPlus) return BinaryOp::kAdd;
      if (k == Tok::kMinus) return BinaryOp::kSub;
      return std::nullopt;
    });
  }

  ExprPtr parse_term() {
    return parse_chain(&Parser::parse_unary, [](Tok k) -> std::optional<BinaryOp> {
      if (k == Tok::kStar) return BinaryOp::kMul;
      if (k == Tok::kSlash) return BinaryOp::kDiv;
      if (k == Tok::kPercent) return BinaryOp::kMod;
      return std::nullopt;
    });
  }

  ExprPtr parse_unary() {
    UnaryOp op;
    if (at(Tok::kMinus)) {
      op = UnaryOp::kNegate;
    } else if (at(Tok::kTilde)) {
      op = UnaryOp::kFloating;
    } else if (at(Tok::kQuote)) {
      op = UnaryOp::kRelative;
    } else {
      return parse_postfix();
    }
    Nest nest(*this);
    const std::uint32_t begin = advance().range.begin;
    return make_unary(op, begin, parse_unary());
  }

  ExprPtr parse_postfix() {
    ExprPtr expr = parse_primary();
    int chain = 0;
    while (at(Tok::kDot) || at(Tok::kLParen)) {
      Nest nest(*this, ++chain);
      if (accept(Tok::kDot)) {
        const Token& member = expect(Tok::kIdent, " (a member name) after '.'");
        ExprPtr access = make(ExprKind::kMember, Range{expr->range.begin, member.range.end});
        access->text = member.text;
        access->operands.push_back(std::move(expr));
        expr = std::move(access);
        continue;
      }
      advance();  // '('
      ExprPtr call = make(ExprKind::kCall, expr->range);
      call->operands.push_back(std::move(expr));
      if (!at(Tok::kRParen)) {
        do {
          call->operands.push_back(parse_expr());
        } while (accept(Tok::kComma));
      }
      expect(Tok::kRParen, " to close the argument list");
      call->range.end = prev_end_;
      expr = std::move(call);
    }
    return expr;
  }

  ExprPtr parse_primary() {
    const Token& token = peek();
    switch (token.kind) {
      case Tok::kNumber: {
        advance();
        ExprPtr number = make(ExprKind::kNumber, token.range);
        number->number = token.number;
        if (!token.relative) return number;
        number->range.end -= 1;  // the suffix belongs to the relative node
        return relative_of(std::move(number), token.range);
      }
      default:
        return parse_primary_other();
    }
  }

  ExprPtr relative_of(ExprPtr number, Range range) {
    ExprPtr expr = make(ExprKind::kUnary, range);
    expr->unary_op = UnaryOp::kRelative;
    expr->operands.push_back(std::move(number));
    return expr;
  }

  ExprPtr parse_primary_other() {
    const Token& token = peek();
    switch (token.kind) {
      case Tok::kString:
      case Tok::kIdent: {
        advance();
        ExprPtr expr =
            make(token.kind == Tok::kString ? ExprKind::kString : ExprKind::kIdent, token.range);
        expr->text = token.text;
        return expr;
      }
      case Tok::kTrue:
      case Tok::kFalse: {
        advance();
        ExprPtr expr = make(ExprKind::kBool, token.range);
        expr->boolean = token.kind == Tok::kTrue;
        return expr;
      }
      case Tok::kLParen: {
        Nest nest(*this);
        advance();
        ExprPtr inner = parse_expr();
        expect(Tok::kRParen, " to close '('");
        return inner;
      }
      default:
        fail("CGA104", "expected an expression, found " + describe(token));
    }
  }

  const base::Source& source_;
  std::vector<Token> tokens_;
  std::vector<base::Diagnostic> diags_;
  std::size_t pos_ = 0;
  std::size_t item_start_ = 0;  // first token of the top-level item being parsed
  std::uint32_t prev_end_ = 0;
  int depth_ = 0;
  Grammar grammar_;
};

}  // namespace

base::Result<Grammar> parse(const base::Source& source) {
  return Parser(source, lex(source)).run();
}

}  // namespace insula::lang::cga
