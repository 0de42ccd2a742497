#include "lang/bldg/lexer.h"

#include <string_view>

#include "base/scanner.h"

namespace insula::lang::bldg {

base::Span span_of(const base::Source& source, Range range) {
  return base::span_of(source, range.begin, range.end);
}

namespace {

struct Operator {
  std::string_view spelling;
  Tok kind;
};
// Longest spelling first so `->` wins over `-`.
constexpr Operator kOperators[] = {
    {"->", Tok::kArrow}, {"(", Tok::kLParen},    {")", Tok::kRParen},   {"{", Tok::kLBrace},
    {"}", Tok::kRBrace}, {"[", Tok::kLBracket},  {"]", Tok::kRBracket}, {",", Tok::kComma},
    {":", Tok::kColon},  {";", Tok::kSemicolon}, {"-", Tok::kMinus},    {"=", Tok::kAssign},
    {".", Tok::kDot},
};

class Lexer {
 public:
  explicit Lexer(const base::Source& source) : scan_(source, kCodes) {}

  LexOutput run() {
    // A UTF-8 byte order mark, as some editors write, is not a token.
    scan_.skip_bom();
    while (true) {
      scan_.skip_trivia();
      if (scan_.at_end()) break;
      lex_token();
    }
    push(Tok::kEnd, scan_.pos(), scan_.pos(), "");
    out_.diagnostics = scan_.take_diagnostics();
    return std::move(out_);
  }

 private:
  static constexpr base::ScanCodes kCodes = {"BLD001", "BLD002", "BLD003", "BLD004", "BLD005"};

  Token& push(Tok kind, std::size_t begin, std::size_t end, std::string text) {
    Token token;
    token.kind = kind;
    token.range = Range{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
    token.text = std::move(text);
    token.line_start = scan_.take_line_start();
    out_.tokens.push_back(std::move(token));
    return out_.tokens.back();
  }

  void lex_token() {
    const std::size_t begin = scan_.pos();
    const char c = scan_.peek();
    if (base::is_ident_start(c)) return lex_identifier();
    if (base::is_digit(c)) return lex_number();
    if (c == '"') {
      std::string value = scan_.scan_string();
      push(Tok::kString, begin, scan_.pos(), std::move(value));
      return;
    }
    for (const Operator& op : kOperators) {
      if (scan_.starts_with(op.spelling)) {
        push(op.kind, begin, begin + op.spelling.size(), std::string(op.spelling));
        scan_.advance(op.spelling.size());
        return;
      }
    }
    scan_.bad_character();
  }

  void lex_identifier() {
    const std::size_t begin = scan_.pos();
    const std::string_view word = scan_.scan_identifier();
    push(Tok::kIdent, begin, scan_.pos(), std::string(word));
  }

  // digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ]; a letter glued to the number (`2x`)
  // is an error rather than two tokens.
  void lex_number() {
    const std::size_t begin = scan_.pos();
    const std::size_t digits_end = scan_.scan_digits();
    const double value = scan_.finish_number(begin, digits_end);
    Token& token =
        push(Tok::kNumber, begin, scan_.pos(), std::string(scan_.slice(begin, scan_.pos())));
    token.number = value;
  }

  base::Scanner scan_;
  LexOutput out_;
};

}  // namespace

LexOutput lex(const base::Source& source) {
  return Lexer(source).run();
}

std::string token_name(Tok kind) {
  switch (kind) {
    case Tok::kEnd:
      return "end of file";
    case Tok::kIdent:
      return "identifier";
    case Tok::kNumber:
      return "number";
    case Tok::kString:
      return "string";
    default:
      break;
  }
  for (const Operator& op : kOperators) {
    if (op.kind == kind) {
      std::string out(1, '\'');
      out.append(op.spelling);
      out += '\'';
      return out;
    }
  }
  return "token";
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case Tok::kEnd:
      return "end of file";
    case Tok::kString:
      return "string \"" + token.text + "\"";
    case Tok::kIdent:
      return "identifier '" + token.text + "'";
    case Tok::kNumber:
      return "number " + token.text;
    default:
      return "'" + token.text + "'";
  }
}

}  // namespace insula::lang::bldg
