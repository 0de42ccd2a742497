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

#include "lang/cga/parser_internal.h"

namespace insula::lang::cga {
namespace detail {

void Parser::parse_top_level() {
  if (at(Tok::kAttr)) return parse_attr();
  if (at(Tok::kPriority)) return parse_priority();
  if (accept(Tok::kSemicolon)) return;
  if (starts_rule()) return parse_rule();
  fail("CGA102", "expected a rule, 'PRIORITY' or 'attr', found " + describe(peek()));
}

void Parser::parse_attr() {
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

void Parser::parse_priority() {
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

bool Parser::is_natural(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

PrioritySet& Parser::current_set(std::uint32_t begin) {
  if (grammar_.sets.empty()) {
    PrioritySet set;
    set.implicit = true;
    set.range = Range{begin, begin};
    grammar_.sets.push_back(std::move(set));
  }
  return grammar_.sets.back();
}

void Parser::parse_rule() {
  Rule rule;
  const std::uint32_t begin = peek().range.begin;
  if (at(Tok::kColon, 1)) {
    const Token& id = advance();
    if (id.kind == Tok::kNumber && !is_natural(id.text)) {
      report("CGA109", "a rule id must be a natural number or an identifier, found " + describe(id),
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
    fail("CGA101", "expected '~>', '->' or '-->' before the successor, found " + describe(peek()));
  }
  while (at_arrow()) rule.alternatives.push_back(parse_alternative());
  accept(Tok::kSemicolon);
  rule.range = from(begin);
  current_set(begin).rules.push_back(std::move(rule));
}

Alternative Parser::parse_alternative() {
  Alternative alternative;
  const Token& arrow = advance();
  alternative.arrow = arrow.text;
  alternative.items = parse_successor();
  if (accept(Tok::kColon)) alternative.probability = parse_probability();
  alternative.range = from(arrow.range.begin);
  return alternative;
}

ExprPtr Parser::parse_probability() {
  if (at(Tok::kNumber) || at(Tok::kMinus)) return parse_unary();
  if (at(Tok::kLParen)) return parse_primary();
  fail("CGA101", "expected a probability (a number or a parenthesised expression), found " +
                     describe(peek()));
}

}  // namespace detail

base::Result<Grammar> parse(const base::Source& source, Dialect dialect) {
  return detail::Parser(source, lex(source), dialect).run();
}

base::Result<Grammar> parse(const base::Source& source) {
  LexOutput lexed = lex(source);
  const Dialect dialect = detail::detect_dialect(lexed.tokens);
  return detail::Parser(source, std::move(lexed), dialect).run();
}

}  // namespace insula::lang::cga
