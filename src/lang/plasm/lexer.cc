#include "lang/plasm/lexer.h"

#include <string_view>

#include "base/scanner.h"
#include "base/token_lexer.h"

namespace insula::lang::plasm {

base::Span span_of(const base::Source& source, Range range) {
  return base::span_of(source, range.begin, range.end);
}

std::string name_key(std::string_view text) {
  std::string key(text);
  for (char& c : key) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return key;
}

namespace {

struct Keyword {
  std::string_view word;  // upper case: keywords are case-insensitive like every name
  Tok kind;
};
constexpr Keyword kKeywords[] = {
    {"DEF", Tok::kDef}, {"WHERE", Tok::kWhere}, {"END", Tok::kEndKw}, {"IF", Tok::kIf}};

// Longest spelling first, so `::` wins over `:`, `**` over `*`, `##` over `#`.
constexpr base::Spelling<Tok> kOperators[] = {
    {"::", Tok::kTypeSep},  {"**", Tok::kPower}, {"##", Tok::kHashHash}, {"..", Tok::kDotDot},
    {":", Tok::kColon},     {"~", Tok::kTilde},  {"[", Tok::kLBracket},  {"]", Tok::kRBracket},
    {"<", Tok::kLt},        {">", Tok::kGt},     {"+", Tok::kPlus},      {"-", Tok::kMinus},
    {"*", Tok::kStar},      {"/", Tok::kSlash},  {"#", Tok::kHash},      {",", Tok::kComma},
    {";", Tok::kSemicolon}, {"=", Tok::kAssign}, {"(", Tok::kLParen},    {")", Tok::kRParen},
};

constexpr base::ScanCodes kCodes = {"PSM001", "PSM002", "PSM003", "PSM004", "PSM005"};

// Not base::TokenLexer: its trivia are `#`, `//` and `/* */`, while PLaSM's comments are
// `% ... %` and `#` is an operator. The characters are still read by base::Scanner.
class Lexer {
 public:
  explicit Lexer(const base::Source& source) : scan_(source, kCodes) {}

  LexOutput run() {
    scan_.skip_bom();
    while (skip_trivia()) {
      const std::size_t begin = scan_.pos();
      const char c = scan_.peek();
      if (base::is_ident_start(c)) {
        identifier();
      } else if (base::is_digit(c)) {
        const std::size_t digits_end = scan_.scan_digits();
        const double value = scan_.finish_number(begin, digits_end);
        push(Tok::kNumber, begin, std::string(scan_.slice(begin, scan_.pos()))).number = value;
      } else if (c == '"') {
        std::string value = scan_.scan_string();
        push(Tok::kString, begin, std::move(value));
      } else if (!operator_token()) {
        scan_.bad_character();
      }
    }
    push(Tok::kEnd, scan_.pos(), "");
    out_.diagnostics = scan_.take_diagnostics();
    return std::move(out_);
  }

 private:
  // Skips whitespace and comments; false at the end of the text. A comment runs from `%` to the
  // next `%` and may span lines.
  bool skip_trivia() {
    while (!scan_.at_end()) {
      const char c = scan_.peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        scan_.advance(1);
      } else if (c == '%') {
        const std::size_t begin = scan_.pos();
        const std::size_t close = scan_.text().find('%', begin + 1);
        if (close == std::string_view::npos) {
          scan_.error(kCodes.unterminated_comment,
                      "unterminated comment: '%' without its closing '%'", begin, begin + 1);
          scan_.advance(scan_.text().size() - begin);
          return false;
        }
        scan_.advance(close + 1 - begin);
      } else {
        return true;
      }
    }
    return false;
  }

  Token& push(Tok kind, std::size_t begin, std::string text) {
    Token token;
    token.kind = kind;
    token.range = Range{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(scan_.pos())};
    token.text = std::move(text);
    out_.tokens.push_back(std::move(token));
    return out_.tokens.back();
  }

  void identifier() {
    const std::size_t begin = scan_.pos();
    const std::string_view word = scan_.scan_identifier();
    std::string key = name_key(word);
    Tok kind = Tok::kIdent;
    for (const Keyword& keyword : kKeywords) {
      if (keyword.word == key) kind = keyword.kind;
    }
    push(kind, begin, std::string(word)).key = std::move(key);
  }

  bool operator_token() {
    for (const auto& op : kOperators) {
      if (scan_.starts_with(op.text)) {
        const std::size_t begin = scan_.pos();
        scan_.advance(op.text.size());
        push(op.kind, begin, std::string(op.text));
        return true;
      }
    }
    return false;
  }

  base::Scanner scan_;
  LexOutput out_;
};

}  // namespace

LexOutput lex(const base::Source& source) {
  return Lexer(source).run();
}

std::string token_name(Tok kind) {
  if (std::string name = base::token_kind_name(kind, kOperators); !name.empty()) return name;
  for (const Keyword& keyword : kKeywords) {
    if (keyword.kind == kind) {
      std::string out(1, '\'');
      out.append(keyword.word);
      out += '\'';
      return out;
    }
  }
  return "token";
}

std::string describe(const Token& token) {
  return base::describe_token(token);
}

}  // namespace insula::lang::plasm
