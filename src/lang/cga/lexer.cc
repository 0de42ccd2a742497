#include "lang/cga/lexer.h"

#include <string_view>

#include "base/token_lexer.h"

namespace insula::lang::cga {

base::Span span_of(const base::Source& source, Range range) {
  return base::span_of(source, range.begin, range.end);
}

namespace {

struct Keyword {
  std::string_view word;
  Tok kind;
};
constexpr Keyword kKeywords[] = {
    {"PRIORITY", Tok::kPriority}, {"attr", Tok::kAttr},       {"true", Tok::kTrue},
    {"false", Tok::kFalse},       {"and", Tok::kAnd},         {"or", Tok::kOr},
    {"not", Tok::kNot},           {"epsilon", Tok::kEpsilon}, {"NIL", Tok::kEpsilon},
};

// Operators, longest spelling first so `-->` wins over `->` and `-`.
constexpr base::Spelling<Tok> kOperators[] = {
    {".==", Tok::kElementwise},
    {".!=", Tok::kElementwise},
    {".<=", Tok::kElementwise},
    {".>=", Tok::kElementwise},
    {".&&", Tok::kElementwise},
    {".||", Tok::kElementwise},
    {".<", Tok::kElementwise},
    {".>", Tok::kElementwise},
    {".+", Tok::kElementwise},
    {".-", Tok::kElementwise},
    {".*", Tok::kElementwise},
    {"./", Tok::kElementwise},
    {"-->", Tok::kLongArrow},
    {"->", Tok::kArrow},
    {"~>", Tok::kTildeArrow},
    {"==", Tok::kEq},
    {"!=", Tok::kNe},
    {"<>", Tok::kNe},
    {"<=", Tok::kLe},
    {">=", Tok::kGe},
    {"&&", Tok::kAnd},
    {"||", Tok::kOr},
    {":", Tok::kColon},
    {";", Tok::kSemicolon},
    {",", Tok::kComma},
    {"|", Tok::kBar},
    {"{", Tok::kLBrace},
    {"}", Tok::kRBrace},
    {"[", Tok::kLBracket},
    {"]", Tok::kRBracket},
    {"(", Tok::kLParen},
    {")", Tok::kRParen},
    {".", Tok::kDot},
    {"+", Tok::kPlus},
    {"-", Tok::kMinus},
    {"*", Tok::kStar},
    {"/", Tok::kSlash},
    {"%", Tok::kPercent},
    {"~", Tok::kTilde},
    {"'", Tok::kQuote},
    {"=", Tok::kAssign},
    {"<", Tok::kLt},
    {">", Tok::kGt},
    {"!", Tok::kNot},
    {"@", Tok::kAt},
    {"^", Tok::kCaret},
};

// 'text' (built by appending: GCC 12 reports a false -Wrestrict on "'" + std::string).
std::string quote(std::string_view text) {
  std::string out(1, '\'');
  out.append(text);
  out += '\'';
  return out;
}

constexpr std::string_view kEpsilonUtf8 = "\xCE\xB5";  // U+03B5 GREEK SMALL LETTER EPSILON

class Lexer : public base::TokenLexer<Lexer, LexOutput, Tok> {
 public:
  explicit Lexer(const base::Source& source) : TokenLexer(source, kCodes) {}

  void lex_token() {
    const std::size_t begin = scan_.pos();
    const char c = scan_.peek();
    if (base::is_ident_start(c)) {
      lex_identifier();
    } else if (base::is_digit(c) || (c == '.' && base::is_digit(scan_.at(begin + 1)))) {
      lex_number();
    } else if (c == '"') {
      push_string(Tok::kString);
    } else if (scan_.starts_with(kEpsilonUtf8)) {
      push(Tok::kEpsilon, begin, begin + kEpsilonUtf8.size(), "ε");
      scan_.advance(kEpsilonUtf8.size());
    } else if (c == '.' && scan_.at(begin + 1) == '/' &&
               (scan_.at(begin + 2) == '/' || scan_.at(begin + 2) == '*')) {
      push(Tok::kDot, begin, begin + 1, ".");  // `Wall.// note`: a terminal, then a comment
      scan_.advance(1);
    } else if (!push_operator(kOperators)) {
      scan_.bad_character();
    }
  }

 private:
  static constexpr base::ScanCodes kCodes = {"CGA001", "CGA002", "CGA003", "CGA004", "CGA005"};

  void lex_identifier() {
    const std::size_t begin = scan_.pos();
    const std::string_view word = scan_.scan_identifier();
    Tok kind = Tok::kIdent;
    for (const Keyword& keyword : kKeywords) {
      if (keyword.word == word) kind = keyword.kind;
    }
    push(kind, begin, scan_.pos(), std::string(word));
  }

  // digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ] [ 'r' ]; a letter glued to the number
  // (`2x`, `3rd`) is an error rather than two tokens.
  void lex_number() {
    const std::size_t begin = scan_.pos();
    const std::size_t digits_end = scan_.scan_digits();
    bool relative = false;
    if (scan_.peek() == 'r' && !base::is_ident_char(scan_.at(digits_end + 1))) {
      relative = true;
      scan_.advance(1);
    }
    push_number(Tok::kNumber, begin, digits_end).relative = relative;
  }
};

}  // namespace

LexOutput lex(const base::Source& source) {
  return Lexer(source).run();
}

std::string token_name(Tok kind) {
  switch (kind) {
    case Tok::kEpsilon:
      return "'ε'";
    case Tok::kPriority:
      return "'PRIORITY'";
    case Tok::kAttr:
      return "'attr'";
    default:
      break;
  }
  if (std::string name = base::token_kind_name(kind, kOperators); !name.empty()) return name;
  for (const Keyword& keyword : kKeywords) {
    if (keyword.kind == kind) return quote(keyword.word);
  }
  return "token";
}

std::string describe(const Token& token) {
  return base::describe_token(token);
}

}  // namespace insula::lang::cga
