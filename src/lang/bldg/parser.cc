// Recursive-descent parser for the building grammar (seed 000, §3.1), one method per production:
//
//   file   = { rule | ";" } EOF ;
//   rule   = SYMBOL "->" FUNCTION "(" [ value { "," value } ] ")" [ ":" set ] [ ";" ] ;
//   set    = "{" [ SYMBOL { "," SYMBOL } [ "," ] ] "}" ;
//   value  = NUMBER | "-" NUMBER | STRING | IDENT | point | ring | call ;
//   point  = "(" signed "," signed ")" ;
//   ring   = "[" point { "," point } [ "," ] "]" ;
//   call   = IDENT "(" [ value { "," value } ] ")" ;
//   signed = [ "-" ] NUMBER ;
//
// The parser only checks the form; what the functions mean is the moderator's (moderator.cc).
#include "lang/bldg/parser.h"

#include <algorithm>

namespace insula::lang::bldg {
namespace {

// Thrown after a syntax error has been recorded; caught at rule level, where the parser skips
// to the next rule. Never leaves this file.
struct Abort {};

class Parser {
 public:
  Parser(const base::Source& source, LexOutput lexed)
      : source_(source), tokens_(std::move(lexed.tokens)), diags_(std::move(lexed.diagnostics)) {}

  SyntaxOutput run() {
    while (!at(Tok::kEnd) && !too_many_errors()) {
      if (accept(Tok::kSemicolon)) continue;
      item_start_ = pos_;
      depth_ = 0;
      try {
        out_.rules.push_back(parse_rule());
      } catch (const Abort&) {
        synchronize();
      }
    }
    out_.diagnostics = std::move(diags_);
    return std::move(out_);
  }

 private:
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
    if (!at(kind)) {
      fail("BLD101", "expected " + token_name(kind) + context + ", found " + describe(peek()));
    }
    return advance();
  }
  Range from(std::uint32_t begin) const { return Range{begin, std::max(begin, prev_end_)}; }

  bool too_many_errors() const { return static_cast<int>(diags_.size()) > kMaxErrors; }
  [[noreturn]] void fail(std::string code, std::string message) {
    diags_.push_back(base::Diagnostic::error(std::move(code), std::move(message),
                                             span_of(source_, peek().range)));
    throw Abort{};
  }

  bool starts_rule() const { return at(Tok::kIdent) && at(Tok::kArrow, 1); }

  // Skips to the first token of a line that starts a rule, or past a `;`. The failing token is
  // skipped when the rule consumed nothing, so the parser always moves on.
  void synchronize() {
    if (pos_ == item_start_ && !at(Tok::kEnd)) advance();
    while (!at(Tok::kEnd)) {
      if (accept(Tok::kSemicolon)) return;
      if (peek().line_start && starts_rule()) return;
      advance();
    }
  }

  SymbolRef symbol_ref(const Token& token) { return SymbolRef{token.text, token.range}; }

  RuleSyntax parse_rule() {
    if (!starts_rule()) {
      fail("BLD102", "expected a rule 'symbol -> function(...)', found " + describe(peek()));
    }
    RuleSyntax rule;
    rule.symbol = symbol_ref(advance());
    advance();  // ->
    rule.function = symbol_ref(expect(Tok::kIdent, " (a function) after '->'"));
    const std::uint32_t args_begin =
        expect(Tok::kLParen, " after the function name '" + rule.function.name + "'").range.begin;
    rule.args = parse_arguments("'" + rule.function.name + "'");
    rule.args_range = from(args_begin);
    if (accept(Tok::kColon)) parse_set(rule);
    accept(Tok::kSemicolon);
    rule.range = from(rule.symbol.range.begin);
    return rule;
  }

  // After '(' up to and including ')'.
  std::vector<Value> parse_arguments(const std::string& owner) {
    std::vector<Value> args;
    if (accept(Tok::kRParen)) return args;
    while (true) {
      args.push_back(parse_value());
      if (accept(Tok::kComma)) continue;
      expect(Tok::kRParen, " to close the parameters of " + owner);
      return args;
    }
  }

  void parse_set(RuleSyntax& rule) {
    rule.has_set = true;
    const std::uint32_t begin =
        expect(Tok::kLBrace, " (the set of resulting symbols) after ':'").range.begin;
    while (!at(Tok::kRBrace)) {
      if (!at(Tok::kIdent)) {
        fail("BLD101", "expected a symbol or '}' in the set of '" + rule.symbol.name + "', found " +
                           describe(peek()));
      }
      rule.set.push_back(symbol_ref(advance()));
      if (!accept(Tok::kComma) && !at(Tok::kRBrace)) {
        fail("BLD101", "expected ',' or '}' in the set of '" + rule.symbol.name + "', found " +
                           describe(peek()));
      }
    }
    advance();
    rule.set_range = from(begin);
  }

  Value parse_value() {
    Value value;
    const Token& first = peek();
    value.range = first.range;
    switch (first.kind) {
      case Tok::kNumber:
      case Tok::kMinus:
        value.kind = Value::Kind::kNumber;
        value.number = parse_signed();
        break;
      case Tok::kString:
        value.kind = Value::Kind::kString;
        value.text = advance().text;
        break;
      case Tok::kIdent:
        value.text = advance().text;
        value.kind = Value::Kind::kIdent;
        if (at(Tok::kLParen)) parse_call(value);
        break;
      case Tok::kLParen:
        value.kind = Value::Kind::kPoint;
        value.ring.push_back(parse_point());
        break;
      case Tok::kLBracket:
        value.kind = Value::Kind::kRing;
        parse_ring(value);
        break;
      default:
        fail("BLD103",
             "expected a value (number, string, name, point or ring), found " + describe(first));
    }
    value.range = from(first.range.begin);
    return value;
  }

  void parse_call(Value& value) {
    if (++depth_ > kMaxNesting) {
      fail("BLD105", "calls nested deeper than " + std::to_string(kMaxNesting) + " levels");
    }
    advance();  // (
    value.kind = Value::Kind::kCall;
    value.args = parse_arguments("'" + value.text + "'");
    --depth_;
  }

  double parse_signed() {
    const bool negative = accept(Tok::kMinus);
    if (!at(Tok::kNumber)) {
      fail("BLD103", std::string("expected a number") + (negative ? " after '-'" : "") +
                         ", found " + describe(peek()));
    }
    const double number = advance().number;
    return negative ? -number : number;
  }

  kernel::Vec2 parse_point() {
    expect(Tok::kLParen, " to start a point '(x, y)'");
    kernel::Vec2 p;
    p.x = parse_signed();
    expect(Tok::kComma, " between the coordinates of a point");
    p.y = parse_signed();
    expect(Tok::kRParen, " to close a point '(x, y)'");
    return p;
  }

  void parse_ring(Value& value) {
    advance();  // [
    while (true) {
      if (!at(Tok::kLParen)) {
        fail("BLD101", "expected a point '(x, y)' in the ring, found " + describe(peek()));
      }
      value.ring.push_back(parse_point());
      if (accept(Tok::kComma)) {
        if (accept(Tok::kRBracket)) return;
        continue;
      }
      expect(Tok::kRBracket, " or ',' in the ring");
      return;
    }
  }

  const base::Source& source_;
  std::vector<Token> tokens_;
  std::vector<base::Diagnostic> diags_;
  std::size_t pos_ = 0;
  std::size_t item_start_ = 0;
  std::uint32_t prev_end_ = 0;
  int depth_ = 0;
  SyntaxOutput out_;
};

}  // namespace

SyntaxOutput parse_rules(const base::Source& source) {
  return Parser(source, lex(source)).run();
}

}  // namespace insula::lang::bldg
