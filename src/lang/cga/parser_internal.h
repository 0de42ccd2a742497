// The CGA parser's shared machinery (token access, diagnostics, error recovery, successors,
// blocks and expressions), used by both readers: seed 004's concrete syntax (parser.cc) and
// CityEngine's dialect (parser_cityengine.cc). One grammar model (ast.h), two readers (issue 20).
// Not a public API: parser.h is.
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "lang/cga/lexer.h"
#include "lang/cga/operations.h"
#include "lang/cga/parser.h"

namespace insula::lang::cga::detail {

// Thrown after a syntax error has been recorded; caught at rule level, where the parser skips
// to the next rule. Never leaves the parser.
struct Abort {};

// Which syntax a file is written in: CityEngine's when it has a construct seed 004 lacks
// (`version`, annotations, `import`, `const`, functions, parametric rules, `case`, percentages,
// terminal `Name.`), seed 004's otherwise (also for the files both read alike).
Dialect detect_dialect(const std::vector<Token>& tokens);

class Parser {
 public:
  Parser(const base::Source& source, LexOutput lexed, Dialect dialect)
      : source_(source), tokens_(std::move(lexed.tokens)), diags_(std::move(lexed.diagnostics)) {
    grammar_.file = source.name();
    grammar_.dialect = dialect;
  }

  base::Result<Grammar> run() {
    run_top_level();
    if (cityengine()) ce_resolve_calls();
    return finish();
  }

 private:
  void run_top_level() {
    while (!at(Tok::kEnd) && !too_many_errors()) {
      try {
        item_start_ = pos_;
        if (cityengine()) {
          ce_top_level();
        } else {
          parse_top_level();
        }
      } catch (const Abort&) {
        if (cityengine()) {
          ce_synchronize();
        } else {
          synchronize();
        }
      }
    }
  }

  base::Result<Grammar> finish() {
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

  // ---- seed 004's top level (parser.cc) ----
  void parse_top_level();
  void parse_attr();
  void parse_priority();
  static bool is_natural(const std::string& text);
  PrioritySet& current_set(std::uint32_t begin);
  void parse_rule();
  Alternative parse_alternative();
  ExprPtr parse_probability();

  // ---- CityEngine's top level and successors (parser_cityengine.cc) ----
  void ce_top_level();
  void ce_synchronize();
  bool ce_starts_top_level() const;
  bool ce_starts_item() const;
  std::size_t after_parens(std::size_t from) const;
  std::size_t after_dotted_name(std::size_t from) const;
  // At `.Name` of a dotted rule name `alias.Name -->` (or `alias.Name(a) -->`).
  bool is_rule_name_ahead() const;
  std::vector<Annotation> ce_annotations();
  void ce_version();
  void ce_import(std::vector<Annotation> annotations);
  void ce_attr(std::vector<Annotation> annotations, bool is_const);
  void ce_rule_or_function(std::vector<Annotation> annotations);
  // An annotation argument CGA has no expression for, as its text: `Post*`, `Side^2`,
  // `{.1, 0, 0}`; null when the argument is an expression.
  ExprPtr ce_annotation_text();
  // `start Name -->` and `extension Name -->`: the keyword before a rule's name.
  bool ce_at_rule_keyword() const;
  void float_keyless_branches(Item& item);
  void ce_keyword_rule(std::vector<Annotation> annotations);
  // A rule head at the cursor: `Name -->` or `Name(a, b) -->`.
  bool ce_at_rule_head() const;
  Rule ce_rule(Token name, std::vector<std::string> params, std::vector<Annotation> annotations);
  std::vector<std::string> ce_params();
  std::vector<Item> ce_body();
  Item ce_select_item(ItemKind kind);
  Item ce_symbol_or_operation();
  std::string ce_qualified_name();
  ExprPtr ce_select_expr();
  bool ce_at_chance() const;
  void ce_resolve_calls();
  bool at_word(std::string_view word, std::size_t ahead = 0) const {
    return at(Tok::kIdent, ahead) && peek(ahead).text == word;
  }
  bool cityengine() const { return grammar_.dialect == Dialect::kCityEngine; }

  // ---- successors ----
  bool starts_item() const {
    if (cityengine()) return ce_starts_item();
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
    if (cityengine()) return ce_body();
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
      track_brackets(items.back(), open);
    }
    for (const Range& range : open) report("CGA107", "'[' is never closed by ']'", range);
    return items;
  }

  // `open` holds the `[` not yet closed in the sequence being parsed.
  void track_brackets(const Item& item, std::vector<Range>& open) {
    if (item.kind == ItemKind::kPush) open.push_back(item.range);
    if (item.kind != ItemKind::kPop) return;
    if (open.empty()) {
      report("CGA106", "']' without a matching '['", item.range);
    } else {
      open.pop_back();
    }
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
        if (cityengine()) return ce_symbol_or_operation();
        if (at(Tok::kLParen, 1)) return parse_operation();
        item.kind = ItemKind::kSymbol;
        break;
    }
    advance();
    // CityEngine accepts `NIL.` (a terminal's dot after NIL; Esri's own massing rules).
    if (cityengine() && item.kind == ItemKind::kEmpty && at(Tok::kDot) &&
        peek().range.begin == token.range.end) {
      advance();
    }
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
      if (cityengine() && at(Tok::kStar)) {
        // CityEngine's `split(y){ ~3 : Floor }*`: the whole block is the repeat pattern.
        Branch repeat;
        repeat.range = from(item.branches.front().range.begin);
        advance();
        repeat.repeat = true;
        repeat.pattern = std::move(item.branches);
        item.branches.clear();
        item.branches.push_back(std::move(repeat));
      }
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
      if (branches.back().repeat || !branches.back().items.empty() || branches.back().key) continue;
      // CityEngine's group without `*` (`split(x){ { a : A | b : B } | ... }`): its parts
      // stand in the enclosing block.
      std::vector<Branch> group = std::move(branches.back().pattern);
      branches.pop_back();
      for (Branch& part : group) branches.push_back(std::move(part));
    } while (accept(Tok::kBar) || accept(Tok::kComma));
    expect(Tok::kRBrace, " or '|' in the successor block");
    return branches;
  }

  Branch parse_branch() {
    Branch branch;
    const std::uint32_t begin = peek().range.begin;
    if (at(Tok::kLBrace)) {
      branch.pattern = parse_block();
      if (cityengine() && !at(Tok::kStar)) {  // a group: parse_block splices its parts
        branch.range = from(begin);
        return branch;
      }
      branch.repeat = true;
      expect(Tok::kStar, " after a repeat pattern '{ ... }'");
    } else {
      if (branch_has_key()) {
        branch.key = parse_expr();
        // CityEngine: `selector = successor` puts every selected component in one shape.
        if (cityengine() && accept(Tok::kAssign)) {
          branch.merged = true;
        } else {
          expect(Tok::kColon, " after the size or selector of a branch");
        }
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
      if (!cityengine() && i > pos_ && tokens_[i].line_start && i + 1 < tokens_.size() &&
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
        case Tok::kAssign:
          if (depth == 0 && cityengine()) return true;
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

  // CityEngine's element-wise operator at the cursor (`.==`, `.+`, ...) when it is one of the
  // operators `op_of` accepts in its plain spelling.
  template <typename OpOf>
  std::optional<BinaryOp> elementwise_at(OpOf op_of) const {
    if (!at(Tok::kElementwise)) return std::nullopt;
    const std::string_view plain = std::string_view(peek().text).substr(1);
    for (const auto& [spelling, kind] : kPlainOperators) {
      if (spelling == plain) return op_of(kind);
    }
    return std::nullopt;
  }
  static constexpr std::pair<std::string_view, Tok> kPlainOperators[] = {
      {"==", Tok::kEq},  {"!=", Tok::kNe},   {"<=", Tok::kLe},  {">=", Tok::kGe},
      {"<", Tok::kLt},   {">", Tok::kGt},    {"&&", Tok::kAnd}, {"||", Tok::kOr},
      {"+", Tok::kPlus}, {"-", Tok::kMinus}, {"*", Tok::kStar}, {"/", Tok::kSlash}};

  // Left-associative chains build left-deep trees; `chain` bounds their depth like nesting.
  template <typename Next, typename OpOf>
  ExprPtr parse_chain(Next next, OpOf op_of) {
    ExprPtr left = (this->*next)();
    int chain = 0;
    while (true) {
      std::optional<BinaryOp> op = op_of(peek().kind);
      const bool elementwise = !op && (op = elementwise_at(op_of));
      if (!op) return left;
      Nest nest(*this, ++chain);
      advance();
      left = make_binary(*op, std::move(left), (this->*next)());
      left->elementwise = elementwise;
    }
  }

  ExprPtr parse_expr() {
    Nest nest(*this);
    if (cityengine() && (at_word("case") || ce_at_chance())) return ce_select_expr();
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
    // (CityEngine's `top = Roof` branch key ends at its `=`.)
    if (at(Tok::kAssign) && !cityengine()) fail("CGA101", "expected '==' to compare, found '='");
    std::optional<BinaryOp> op = comparison_op(peek().kind);
    const bool elementwise = !op && (op = elementwise_at(&comparison_op));
    if (!op) return left;
    advance();
    ExprPtr result = make_binary(*op, std::move(left), parse_additive());
    result->elementwise = elementwise;
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
    // In CityEngine's dialect `30% :` starts a stochastic branch: that `%` is no modulo.
    const bool percent_is_mod = !cityengine();
    ExprPtr left = parse_unary();
    int chain = 0;
    while (true) {
      std::optional<BinaryOp> op;
      if (at(Tok::kStar)) op = BinaryOp::kMul;
      if (at(Tok::kSlash)) op = BinaryOp::kDiv;
      if (at(Tok::kPercent) && (percent_is_mod || !at(Tok::kColon, 1))) op = BinaryOp::kMod;
      const bool elementwise = !op && (op = elementwise_at([](Tok k) -> std::optional<BinaryOp> {
                                         if (k == Tok::kStar) return BinaryOp::kMul;
                                         if (k == Tok::kSlash) return BinaryOp::kDiv;
                                         return std::nullopt;
                                       }));
      if (!op) return left;
      Nest nest(*this, ++chain);
      advance();
      left = make_binary(*op, std::move(left), parse_unary());
      left->elementwise = elementwise;
    }
  }

  ExprPtr parse_unary() {
    UnaryOp op;
    if (cityengine() && at(Tok::kPlus)) {  // CityEngine accepts a unary plus (`d/2 + +x`)
      Nest nest(*this);
      advance();
      return parse_unary();
    }
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
    // CityEngine's size prefixes take the whole sum after them (`~h*0.8 : A`, `'1 - d`).
    if (cityengine() && op != UnaryOp::kNegate) return make_unary(op, begin, parse_additive());
    return make_unary(op, begin, parse_unary());
  }

  ExprPtr parse_postfix() {
    ExprPtr expr = parse_primary();
    int chain = 0;
    while (at(Tok::kDot) || at(Tok::kLParen) ||
           (cityengine() && at(Tok::kLBracket) && !peek().line_start)) {
      Nest nest(*this, ++chain);
      if (accept(Tok::kLBracket)) {  // CityEngine's array index `a[i]`, `a[r, c]`
        ExprPtr index = make(ExprKind::kIndex, expr->range);
        index->operands.push_back(std::move(expr));
        index->operands.push_back(parse_element());
        if (accept(Tok::kComma)) index->operands.push_back(parse_element());
        expect(Tok::kRBracket, " to close the index");
        index->range.end = prev_end_;
        expr = std::move(index);
        continue;
      }
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
      if (cityengine() && at(Tok::kLBrace)) {  // comp(fe){ sel : value } as a value (2019.0)
        expr = comp_function(std::move(call));
        continue;
      }
      expr = std::move(call);
    }
    return expr;
  }

  // An element inside `[ ]`: an expression, or CityEngine's colon operator `a:b`, `a:s:b`.
  ExprPtr parse_element() {
    ExprPtr first = parse_expr();
    if (!at(Tok::kColon)) return first;
    ExprPtr range = make(ExprKind::kRange, first->range);
    range->operands.push_back(std::move(first));
    while (range->operands.size() < 3 && accept(Tok::kColon)) {
      range->operands.push_back(parse_expr());
    }
    range->range.end = prev_end_;
    return range;
  }

  // CityEngine's comp function: `comp(type) { selector : value | selector = value | ... }`.
  ExprPtr comp_function(ExprPtr call) {
    const Expr& callee = *call->operands[0];
    if (callee.kind != ExprKind::kIdent || callee.text != "comp" || call->operands.size() != 2) {
      fail("CGA902", callee.kind == ExprKind::kIdent && callee.text == "comp"
                         ? "CityEngine's comp() function with a scope alignment is not supported"
                         : "a '{' block after a function call (only comp() takes one)");
    }
    ExprPtr comp = make(ExprKind::kComp, call->range);
    comp->operands.push_back(std::move(call->operands[1]));
    expect(Tok::kLBrace, "");
    do {
      comp->operands.push_back(parse_expr());
      if (accept(Tok::kAssign)) {
        comp->text += '=';
      } else {
        expect(Tok::kColon, " or '=' after the selector of a comp() branch");
        comp->text += ':';
      }
      comp->operands.push_back(parse_expr());
    } while (accept(Tok::kBar));
    expect(Tok::kRBrace, " or '|' in the block of comp()");
    comp->range.end = prev_end_;
    return comp;
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
      case Tok::kLBracket: {
        if (!cityengine()) break;
        Nest nest(*this);
        const std::uint32_t begin = advance().range.begin;
        // `[a, b; c, d]`: rows separated by `;` (CityEngine 2020.0), each a kArray of its own.
        ExprPtr array = make(ExprKind::kArray, Range{begin, begin});
        std::vector<ExprPtr> rows;
        if (!at(Tok::kRBracket)) {
          while (true) {
            array->operands.push_back(parse_element());
            if (accept(Tok::kComma)) continue;
            if (!accept(Tok::kSemicolon)) break;
            ExprPtr row = make(ExprKind::kArray, Range{array->operands.front()->range.begin,
                                                       array->operands.back()->range.end});
            row->operands = std::move(array->operands);
            array->operands.clear();
            rows.push_back(std::move(row));
          }
        }
        expect(Tok::kRBracket, " to close the array");
        array->range = from(begin);
        if (!rows.empty()) {
          ExprPtr last = make(ExprKind::kArray, Range{array->operands.front()->range.begin,
                                                      array->operands.back()->range.end});
          last->operands = std::move(array->operands);
          rows.push_back(std::move(last));
          array->operands = std::move(rows);
          array->boolean = true;
        }
        return array;
      }
      default:
        break;
    }
    fail("CGA104", "expected an expression, found " + describe(token));
  }

  const base::Source& source_;
  std::vector<Token> tokens_;
  std::vector<base::Diagnostic> diags_;
  std::size_t pos_ = 0;
  std::size_t item_start_ = 0;  // first token of the top-level item being parsed
  std::uint32_t prev_end_ = 0;
  int depth_ = 0;
  // Inside `[ case ... ]` (CityEngine): a `]` the branch did not open ends the branch's body.
  int select_in_bracket_ = 0;
  Grammar grammar_;
};

}  // namespace insula::lang::cga::detail
