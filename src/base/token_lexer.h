// The token level shared by the front-end lexers (lang/cga/lexer.cc, lang/bldg/lexer.cc): the
// loop over the text, tokens with their byte range and line-start flag, operators matched from a
// table, strings. A lexer derives from TokenLexer and says what its tokens are; the characters
// themselves are read by base::Scanner.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "base/scanner.h"

namespace insula::base {

// An operator of a front-end and its token kind.
template <class Tok>
struct Spelling {
  std::string_view text;
  Tok kind;
};

// Output has `tokens` (a vector of Token) and `diagnostics`; Token has `kind` (Tok, with a kEnd),
// `range` (two std::uint32_t byte offsets, begin and end), `text`, `number` and `line_start`.
// Derived defines `void lex_token()`, called at each character that starts a token.
template <class Derived, class Output, class Tok>
class TokenLexer {
 public:
  using Token = typename decltype(Output::tokens)::value_type;

  // Every token of the text, then one kEnd token; lexical errors become diagnostics.
  Output run() {
    while (true) {
      scan_.skip_trivia();
      if (scan_.at_end()) break;
      static_cast<Derived*>(this)->lex_token();
    }
    push(Tok::kEnd, scan_.pos(), scan_.pos(), "");
    out_.diagnostics = scan_.take_diagnostics();
    return std::move(out_);
  }

 protected:
  TokenLexer(const Source& source, ScanCodes codes) : scan_(source, codes) {}

  Token& push(Tok kind, std::size_t begin, std::size_t end, std::string text) {
    Token token;
    token.kind = kind;
    token.range =
        decltype(token.range){static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
    token.text = std::move(text);
    token.line_start = scan_.take_line_start();
    out_.tokens.push_back(std::move(token));
    return out_.tokens.back();
  }

  // At `"`: a string token whose text is the value with escapes resolved.
  void push_string(Tok kind) {
    const std::size_t begin = scan_.pos();
    std::string value = scan_.scan_string();
    push(kind, begin, scan_.pos(), std::move(value));
  }

  // Ends the number that starts at `begin` and whose digits end at `digits_end` (after a suffix
  // the front-end took, if any): Scanner::finish_number, then a token with its value in `number`.
  Token& push_number(Tok kind, std::size_t begin, std::size_t digits_end) {
    const double value = scan_.finish_number(begin, digits_end);
    Token& token = push(kind, begin, scan_.pos(), std::string(scan_.slice(begin, scan_.pos())));
    token.number = value;
    return token;
  }

  // The first operator of `table` (longest spellings first, so `->` wins over `-`) the text at
  // the cursor starts with, pushed as a token; false when none does.
  template <std::size_t N>
  bool push_operator(const Spelling<Tok> (&table)[N]) {
    for (const Spelling<Tok>& op : table) {
      if (scan_.starts_with(op.text)) {
        push(op.kind, scan_.pos(), scan_.pos() + op.text.size(), std::string(op.text));
        scan_.advance(op.text.size());
        return true;
      }
    }
    return false;
  }

  Scanner scan_;
  Output out_;
};

// The name of a token kind in messages: "end of file", "identifier", "number" or "string" for
// the kinds every front-end has, `'->'` for an operator of `table`; empty for any other kind.
template <class Tok, std::size_t N>
std::string token_kind_name(Tok kind, const Spelling<Tok> (&table)[N]) {
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
  for (const Spelling<Tok>& op : table) {
    if (op.kind == kind) {
      std::string out(1, '\'');  // appended: GCC 12 reports a false -Wrestrict on "'" + string
      out.append(op.text);
      out += '\'';
      return out;
    }
  }
  return {};
}

// The token as shown in "found ..." messages: its spelling, or "end of file".
template <class Token>
std::string describe_token(const Token& token) {
  using Tok = decltype(token.kind);
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

}  // namespace insula::base
