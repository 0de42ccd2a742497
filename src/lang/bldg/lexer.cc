#include "lang/bldg/lexer.h"

#include <string_view>

#include "base/token_lexer.h"

namespace insula::lang::bldg {

base::Span span_of(const base::Source& source, Range range) {
  return base::span_of(source, range.begin, range.end);
}

namespace {

// Longest spelling first so `->` wins over `-`.
constexpr base::Spelling<Tok> kOperators[] = {
    {"->", Tok::kArrow}, {"(", Tok::kLParen},    {")", Tok::kRParen},   {"{", Tok::kLBrace},
    {"}", Tok::kRBrace}, {"[", Tok::kLBracket},  {"]", Tok::kRBracket}, {",", Tok::kComma},
    {":", Tok::kColon},  {";", Tok::kSemicolon}, {"-", Tok::kMinus},    {"=", Tok::kAssign},
    {".", Tok::kDot},
};

class Lexer : public base::TokenLexer<Lexer, LexOutput, Tok> {
 public:
  explicit Lexer(const base::Source& source) : TokenLexer(source, kCodes) {
    // A UTF-8 byte order mark, as some editors write, is not a token.
    scan_.skip_bom();
  }

  void lex_token() {
    const std::size_t begin = scan_.pos();
    const char c = scan_.peek();
    if (base::is_ident_start(c)) {
      const std::string_view word = scan_.scan_identifier();
      push(Tok::kIdent, begin, scan_.pos(), std::string(word));
    } else if (base::is_digit(c)) {
      // digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ]; a letter glued to the number
      // (`2x`) is an error rather than two tokens.
      push_number(Tok::kNumber, begin, scan_.scan_digits());
    } else if (c == '"') {
      push_string(Tok::kString);
    } else if (!push_operator(kOperators)) {
      scan_.bad_character();
    }
  }

 private:
  static constexpr base::ScanCodes kCodes = {"BLD001", "BLD002", "BLD003", "BLD004", "BLD005"};
};

}  // namespace

LexOutput lex(const base::Source& source) {
  return Lexer(source).run();
}

std::string token_name(Tok kind) {
  std::string name = base::token_kind_name(kind, kOperators);
  return name.empty() ? "token" : name;
}

std::string describe(const Token& token) {
  return base::describe_token(token);
}

}  // namespace insula::lang::bldg
