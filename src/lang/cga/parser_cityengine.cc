// CityEngine's dialect of CGA (issue 20; docs/cityengine-dialect.md), read into the same grammar
// model as seed 004's syntax (ast.h):
//
//   file       = [ "version" STRING ] { { annotation } item } EOF ;
//   annotation = "@" IDENT [ "(" [ arg { "," arg } ] ")" ] ;   arg = [ IDENT "=" ] expr ;
//   item       = "import" IDENT ":" STRING [ "(" [ import_arg { "," import_arg } ] ")" ]
//              | "attr" IDENT [ params ] "=" expr
//              | "const" IDENT [ params ] "=" expr
//              | "style" IDENT [ "extends" IDENT ]
//              | IDENT [ params ] "-->" body            (* a rule *)
//              | IDENT [ params ] "=" expr ;            (* a function *)
//   import_arg = IDENT [ "=" expr ] ;                    (* protect, or override *)
//   params     = "(" [ param { "," param } ] ")" ;      param = [ type ] IDENT ;
//   body       = select | { successor } ;
//   select     = "case" expr ":" body { "case" expr ":" body } "else" ":" body
//              | chance ":" body { chance ":" body } "else" ":" body ;
//   chance     = ( NUMBER | name | "(" expr ")" ) "%" ;
//   successor  = "NIL" | "[" | "]" | name "." | name [ "(" args ")" [ block [ "*" ] ] ] ;
//   name       = IDENT { "." IDENT } ;                   (* no space around the dots *)
//
// A rule's body ends where the next declaration starts (no terminator). A chain of `case` or
// percentage branches ends with its `else` branch; a branch body that starts with `case` (or a
// percentage) is a nested chain, so nesting needs no brackets. Expressions add `case`/percentage
// chains as values, arrays `[a, b]` and indexing `a[i]` (parser_internal.h).
#include <cctype>
#include <map>
#include <set>

#include "lang/cga/cityengine_names.h"
#include "lang/cga/parser_internal.h"

namespace insula::lang::cga::detail {

namespace {

bool is_arrow(Tok kind) {
  return kind == Tok::kLongArrow || kind == Tok::kArrow;
}

bool is_type_word(std::string_view word) {
  return word == "float" || word == "string" || word == "bool";
}

// CityEngine argument forms that Insula runs as the plain form (docs/cityengine-dialect.md,
// "Differences"): `extrude(type, d)` extrudes along the face normal (the same as world.up on a
// lot, CityEngine's common case), `split(axis, adjust|noAdjust)` splits as split(axis).
void drop_form_words(Item& item) {
  // `y`: CityEngine 2011's world axis spelling (extrude(y, 0.1) in Piccoli's rules).
  static constexpr std::string_view kExtrudeTypes[] = {
      "world.y", "y", "world.up", "world.up.flatTop", "face.normal", "vertex.normal"};
  if (item.name == "extrude" && item.args.size() == 2 &&
      contains(kExtrudeTypes, dotted_name(*item.args[0]))) {
    item.args.erase(item.args.begin());
  }
  if (item.name == "split" && item.args.size() == 2) {
    const std::string word = dotted_name(*item.args[1]);
    if (word == "adjust" || word == "noAdjust") item.args.pop_back();
  }
  // roofHip(angle, overhang, even) and roofGable(angle, overhangX, overhangY, even, index):
  // Insula's third roof argument is its height, so CityEngine's later ones are dropped (the
  // checker warns: the ridges follow the planes, the gable's overhang is overhangX all round,
  // its ridge runs along the longest edges).
  static constexpr std::pair<std::string_view, std::string_view> kRoofExtras[] = {
      {"roofHip", "even"}, {"roofGable", "overhangY, even and index"}};
  for (const auto& [roof, extras] : kRoofExtras) {
    const bool by_value = !item.args.empty() && (dotted_name(*item.args[0]) == "byAngle" ||
                                                 dotted_name(*item.args[0]) == "byHeight");
    const std::size_t kept = by_value ? 3 : 2;
    if (item.name == roof && item.args.size() > kept) {
      item.args.resize(kept);
      item.dropped = std::string(extras);
    }
  }
  // `split(u|v, unitSpace|uvSpace, uvSet)`: along texture coordinates, which a lot has none of;
  // Insula splits along the scope's x (u) or y (v) instead (docs/cga-cityengine.md).
  if (item.name == "split" && item.args.size() == 3) {
    const std::string axis = dotted_name(*item.args[0]);
    const std::string space = dotted_name(*item.args[1]);
    if ((axis == "u" || axis == "v") && (space == "unitSpace" || space == "uvSpace")) {
      item.args.resize(1);
      item.args[0]->text = axis == "u" ? "x" : "y";
      item.along_uv = true;
    }
  }
}

}  // namespace

// ---- top level

void Parser::ce_top_level() {
  std::vector<Annotation> annotations = ce_annotations();
  if (at_word("version") && at(Tok::kString, 1)) return ce_version();
  if (at_word("import") && at(Tok::kIdent, 1)) return ce_import(std::move(annotations));
  if (at(Tok::kAttr)) return ce_attr(std::move(annotations), false);
  if (at_word("const") && at(Tok::kIdent, 1)) return ce_attr(std::move(annotations), true);
  if (at_word("style") && at(Tok::kIdent, 1)) {
    advance();
    grammar_.styles.push_back(advance().text);
    if (at_word("extends") && at(Tok::kIdent, 1)) {
      advance();
      advance();
    }
    return;
  }
  if (ce_at_rule_keyword()) return ce_keyword_rule(std::move(annotations));
  if (at(Tok::kIdent)) return ce_rule_or_function(std::move(annotations));
  if (accept(Tok::kSemicolon)) return;
  fail("CGA102",
       "expected a rule, a function, 'attr', 'const' or 'import', found " + describe(peek()));
}

bool Parser::ce_starts_top_level() const {
  if (at(Tok::kAt) || at(Tok::kAttr) || ce_at_rule_keyword()) return true;
  if ((at_word("version") && at(Tok::kString, 1)) || (at_word("import") && at(Tok::kIdent, 1)) ||
      (at_word("const") && at(Tok::kIdent, 1)) || (at_word("style") && at(Tok::kIdent, 1))) {
    return true;
  }
  if (!at(Tok::kIdent)) return false;
  const std::size_t name_end = after_dotted_name(pos_);
  if (name_end >= tokens_.size()) return false;
  const Tok next = tokens_[name_end].kind;
  const bool dotted = name_end > pos_ + 1;  // an imported rule's name: a rule, never a function
  if (is_arrow(next) || (!dotted && next == Tok::kAssign)) return true;
  if (next != Tok::kLParen) return false;
  const std::size_t after = after_parens(name_end);
  return after < tokens_.size() &&
         (is_arrow(tokens_[after].kind) || (!dotted && tokens_[after].kind == Tok::kAssign));
}

bool Parser::ce_at_rule_head() const {
  if (!at(Tok::kIdent) || pos_ + 1 >= tokens_.size()) return false;
  const Tok next = tokens_[pos_ + 1].kind;
  if (is_arrow(next)) return true;
  if (next != Tok::kLParen) return false;
  const std::size_t after = after_parens(pos_ + 1);
  return after < tokens_.size() && is_arrow(tokens_[after].kind);
}

bool Parser::ce_at_rule_keyword() const {
  if (!(at_word("start") || at_word("extension")) || !at(Tok::kIdent, 1)) return false;
  std::size_t i = pos_ + 2;
  if (i < tokens_.size() && tokens_[i].kind == Tok::kLParen) i = after_parens(i);
  return i < tokens_.size() && is_arrow(tokens_[i].kind);
}

// CityEngine 2022.0's `start Name --> ...` marks the file's start rule, which the file and its
// importers may also call `start` (`start(20)`, `alias.start`): a rule `start` passing its
// arguments on is added. `extension Name --> ...` is a rule an importer may redefine; Insula
// lets an import redefine any rule, so the keyword changes nothing else.
void Parser::ce_keyword_rule(std::vector<Annotation> annotations) {
  const bool start = advance().text == "start";
  const Token name = advance();
  std::vector<std::string> params;
  if (at(Tok::kLParen)) params = ce_params();
  if (start) {
    Annotation mark;
    mark.name = "StartRule";
    mark.range = name.range;
    annotations.push_back(std::move(mark));
  }
  Rule rule = ce_rule(name, params, std::move(annotations));
  if (!grammar_.styles.empty()) return;
  if (start && name.text != "start") {
    Rule alias;
    alias.predecessor = "start";
    alias.predecessor_range = name.range;
    alias.id_range = name.range;
    alias.range = name.range;
    alias.params = params;
    Alternative pass;
    pass.arrow = "-->";
    pass.range = name.range;
    Item call;
    call.kind = ItemKind::kSymbol;
    call.name = name.text;
    call.range = name.range;
    for (const std::string& p : params) {
      ExprPtr arg = make(ExprKind::kIdent, name.range);
      arg->text = p;
      call.args.push_back(std::move(arg));
    }
    pass.items.push_back(std::move(call));
    alias.alternatives.push_back(std::move(pass));
    current_set(name.range.begin).rules.push_back(std::move(alias));
  }
  current_set(name.range.begin).rules.push_back(std::move(rule));
}

Rule Parser::ce_rule(Token name, std::vector<std::string> params,
                     std::vector<Annotation> annotations) {
  Rule rule;
  rule.predecessor = name.text;
  rule.predecessor_range = name.range;
  rule.id_range = name.range;
  rule.params = std::move(params);
  rule.annotations = std::move(annotations);
  Alternative alternative;
  const Token& arrow = advance();
  alternative.arrow = arrow.text;
  alternative.items = ce_body();
  alternative.range = from(arrow.range.begin);
  rule.alternatives.push_back(std::move(alternative));
  rule.range = from(name.range.begin);
  return rule;
}

bool Parser::is_rule_name_ahead() const {
  const std::size_t end = after_dotted_name(pos_ - 1);
  if (end >= tokens_.size()) return false;
  if (is_arrow(tokens_[end].kind)) return true;
  if (tokens_[end].kind != Tok::kLParen) return false;
  const std::size_t after = after_parens(end);
  return after < tokens_.size() && is_arrow(tokens_[after].kind);
}

// The index of the token after the name starting at `from`: `Name` or an imported rule's
// `alias.Name` (CityEngine: a rule of the importing file given to an imported file's name).
std::size_t Parser::after_dotted_name(std::size_t from) const {
  // The parts touch (`a.B`): `Wall.` ending a line before `a.B -->` is a terminal, not a name.
  std::size_t i = from + 1;
  while (i + 1 < tokens_.size() && tokens_[i].kind == Tok::kDot &&
         tokens_[i + 1].kind == Tok::kIdent && tokens_[i].range.begin == tokens_[i - 1].range.end &&
         tokens_[i + 1].range.begin == tokens_[i].range.end) {
    i += 2;
  }
  return i;
}

// The index of the token after the parenthesis group opening at `from` (tokens_.size() when it
// is never closed). A rule head `Name(a, b) -->` and a call `Name(a, b) X` differ only there.
std::size_t Parser::after_parens(std::size_t from) const {
  int depth = 0;
  for (std::size_t i = from; i < tokens_.size(); ++i) {
    const Tok kind = tokens_[i].kind;
    if (kind == Tok::kLParen) ++depth;
    if (kind == Tok::kRParen && --depth == 0) return i + 1;
    if (kind == Tok::kEnd || kind == Tok::kLBrace || kind == Tok::kRBrace) break;
  }
  return tokens_.size();
}

// Skips to the next line that starts a declaration.
void Parser::ce_synchronize() {
  if (pos_ == item_start_ && !at(Tok::kEnd)) advance();
  while (!at(Tok::kEnd)) {
    if (peek().line_start && ce_starts_top_level()) return;
    advance();
  }
}

std::vector<Annotation> Parser::ce_annotations() {
  std::vector<Annotation> annotations;
  while (at(Tok::kAt)) {
    Annotation a;
    const std::uint32_t begin = advance().range.begin;
    a.name = expect(Tok::kIdent, " (the annotation name) after '@'").text;
    if (accept(Tok::kLParen) && !accept(Tok::kRParen)) {
      do {
        std::string key;
        if (at(Tok::kIdent) && at(Tok::kAssign, 1)) {
          key = advance().text;
          advance();
        }
        a.keys.push_back(std::move(key));
        // @Handle(shape=Post*, ...), @Handle(shape=Side^2, translate={.1, 0, 0}): a shape name
        // pattern or a brace list, kept as its text.
        if (ExprPtr raw = ce_annotation_text()) {
          a.args.push_back(std::move(raw));
          continue;
        }
        a.args.push_back(parse_expr());
      } while (accept(Tok::kComma));
      expect(Tok::kRParen, " to close the annotation's arguments");
    }
    a.range = from(begin);
    annotations.push_back(std::move(a));
  }
  return annotations;
}

ExprPtr Parser::ce_annotation_text() {
  const bool pattern = at(Tok::kIdent) && (at(Tok::kStar, 1) || at(Tok::kCaret, 1));
  if (!pattern && !at(Tok::kLBrace)) return nullptr;
  const std::uint32_t begin = peek().range.begin;
  std::string text;
  int depth = 0;
  do {
    if (at(Tok::kEnd) || (depth > 0 && peek().line_start && ce_starts_top_level())) {
      fail("CGA101", "expected '}' to close the annotation's list");
    }
    const Token& t = advance();
    depth += t.kind == Tok::kLBrace ? 1 : t.kind == Tok::kRBrace ? -1 : 0;
    if (!text.empty() && t.kind != Tok::kComma && text.back() != '{' && t.kind != Tok::kRBrace &&
        text.back() != '^' && t.kind != Tok::kCaret && t.kind != Tok::kStar) {
      text += ' ';
    }
    text += t.kind == Tok::kNumber ? shape::to_string(shape::Value(t.number)) : t.text;
  } while (depth > 0 || (pattern && (at(Tok::kStar) || at(Tok::kCaret) || at(Tok::kNumber))));
  ExprPtr raw = make(ExprKind::kString, {begin, tokens_[pos_ - 1].range.end});
  raw->text = std::move(text);
  return raw;
}

void Parser::ce_version() {
  advance();
  const Token& version = advance();
  if (!grammar_.version.empty()) {
    report("CGA112", "a second 'version' line (the first said \"" + grammar_.version + "\")",
           version.range);
  }
  grammar_.version = version.text;
}

void Parser::ce_import(std::vector<Annotation> annotations) {
  ImportDecl decl;
  decl.annotations = std::move(annotations);
  const std::uint32_t begin = advance().range.begin;
  const Token& alias = advance();
  decl.alias = alias.text;
  decl.alias_range = alias.range;
  if (at(Tok::kLParen)) {  // `import alias (styleA, styleB) : "file"`: styles are not kept
    pos_ = after_parens(pos_);
    if (pos_ >= tokens_.size()) pos_ = tokens_.size() - 1;
  }
  expect(Tok::kColon, " after the import's alias");
  const Token& path = expect(Tok::kString, " (the rule file's path) after 'import alias :'");
  decl.path = path.text;
  decl.path_range = path.range;
  if (accept(Tok::kLParen)) {
    decl.has_list = true;
    if (!accept(Tok::kRParen)) {
      do {
        if (ce_at_rule_head()) {  // `Name(a) --> ...`: a rule redefined
          const Token name = advance();
          std::vector<std::string> params;
          if (at(Tok::kLParen)) params = ce_params();
          decl.rule_overrides.push_back(ce_rule(name, std::move(params), {}));
          continue;
        }
        const Token& name =
            expect(Tok::kIdent, " (an attribute name or a rule) in the import's list");
        if (accept(Tok::kAssign)) {
          decl.overrides.emplace_back(name.text, parse_expr());
        } else {
          decl.protected_attrs.push_back(name.text);
        }
      } while (accept(Tok::kComma));
      expect(Tok::kRParen, " to close the import's list");
    }
  }
  decl.range = from(begin);
  grammar_.imports.push_back(std::move(decl));
}

// `attr name = expr`, `const name = expr` and their parameterised forms (functions).
void Parser::ce_attr(std::vector<Annotation> annotations, bool is_const) {
  const std::uint32_t begin = advance().range.begin;
  if (at(Tok::kIdent) && at(Tok::kLParen, 1)) {
    const Token& name = advance();
    FunctionDecl fn;
    fn.name = name.text;
    fn.name_range = name.range;
    fn.params = ce_params();
    expect(Tok::kAssign, " after the function's parameters");
    fn.body = parse_expr();
    fn.is_const = is_const;
    fn.annotations = std::move(annotations);
    fn.range = from(begin);
    if (grammar_.styles.empty()) grammar_.functions.push_back(std::move(fn));
    return;
  }
  const Token& name = expect(Tok::kIdent, is_const ? " after 'const'" : " after 'attr'");
  expect(Tok::kAssign, " after the name");
  ExprPtr value = parse_expr();
  if (!grammar_.styles.empty()) return;  // docs/cityengine-dialect.md: the Default style is kept
  if (is_const) {
    FunctionDecl fn;
    fn.name = name.text;
    fn.name_range = name.range;
    fn.body = std::move(value);
    fn.is_const = true;
    fn.annotations = std::move(annotations);
    fn.range = from(begin);
    grammar_.functions.push_back(std::move(fn));
    return;
  }
  AttrDecl decl;
  decl.name = name.text;
  decl.name_range = name.range;
  decl.value = std::move(value);
  decl.annotations = std::move(annotations);
  decl.range = from(begin);
  grammar_.attrs.push_back(std::move(decl));
}

void Parser::ce_rule_or_function(std::vector<Annotation> annotations) {
  Token name = advance();
  const std::uint32_t begin = name.range.begin;
  while (at(Tok::kDot) && at(Tok::kIdent, 1) && is_rule_name_ahead()) {
    advance();
    const Token& part = advance();
    name.text += "." + part.text;
    name.range.end = part.range.end;
  }
  std::vector<std::string> params;
  if (at(Tok::kLParen)) params = ce_params();
  if (is_arrow(peek().kind)) {
    Rule rule = ce_rule(name, std::move(params), std::move(annotations));
    if (grammar_.styles.empty()) current_set(begin).rules.push_back(std::move(rule));
    return;
  }
  if (accept(Tok::kAssign)) {
    FunctionDecl fn;
    fn.name = name.text;
    fn.name_range = name.range;
    fn.params = std::move(params);
    fn.body = parse_expr();
    fn.annotations = std::move(annotations);
    fn.range = from(begin);
    if (grammar_.styles.empty()) grammar_.functions.push_back(std::move(fn));
    return;
  }
  fail("CGA101", "expected '-->' (a rule) or '=' (a function) after '" + name.text + "', found " +
                     describe(peek()));
}

std::vector<std::string> Parser::ce_params() {
  std::vector<std::string> params;
  expect(Tok::kLParen, "");
  if (accept(Tok::kRParen)) return params;
  do {
    // An optional type: `float h`, `string[] names`.
    if (at(Tok::kIdent) && is_type_word(peek().text) &&
        (at(Tok::kIdent, 1) || at(Tok::kLBracket, 1))) {
      advance();
      if (accept(Tok::kLBracket)) expect(Tok::kRBracket, " after '[' in an array type");
    }
    params.push_back(expect(Tok::kIdent, " (a parameter name)").text);
  } while (accept(Tok::kComma));
  expect(Tok::kRParen, " to close the parameter list");
  return params;
}

// ---- bodies

bool Parser::ce_starts_item() const {
  switch (peek().kind) {
    case Tok::kEpsilon:
    case Tok::kLBracket:
    case Tok::kRBracket:
      return true;
    case Tok::kIdent:
      if (at_word("case") || at_word("else")) return false;
      return !ce_starts_top_level();
    default:
      return false;
  }
}

// `30% :`, `prob% :`, `(a + b)% :`.
bool Parser::ce_at_chance() const {
  std::size_t i = pos_;
  if (at(Tok::kNumber)) {
    ++i;
  } else if (at(Tok::kIdent)) {
    ++i;
    while (i + 1 < tokens_.size() && tokens_[i].kind == Tok::kDot &&
           tokens_[i + 1].kind == Tok::kIdent) {
      i += 2;
    }
  } else if (at(Tok::kLParen)) {
    i = after_parens(pos_);
  } else {
    return false;
  }
  return i + 1 < tokens_.size() && tokens_[i].kind == Tok::kPercent &&
         tokens_[i + 1].kind == Tok::kColon;
}

std::vector<Item> Parser::ce_body() {
  Nest nest(*this);
  std::vector<Item> items;
  std::vector<Range> open;
  while (true) {
    // A chain right at the start of a body is that body (nesting); later, a `case` or a
    // percentage belongs to the chain around it.
    if (items.empty() && at_word("case")) {
      items.push_back(ce_select_item(ItemKind::kCase));
      break;
    }
    if (items.empty() && ce_at_chance()) {
      items.push_back(ce_select_item(ItemKind::kChance));
      break;
    }
    if (select_in_bracket_ > 0 && open.empty() && at(Tok::kRBracket)) break;
    // `[ case c : A else : B ]`: the chain ends at the bracket that closes it.
    if (!items.empty() && items.back().kind == ItemKind::kPush &&
        (at_word("case") || ce_at_chance())) {
      ++select_in_bracket_;
      items.push_back(ce_select_item(at_word("case") ? ItemKind::kCase : ItemKind::kChance));
      --select_in_bracket_;
      continue;
    }
    if (!ce_starts_item()) break;
    items.push_back(parse_item());
    track_brackets(items.back(), open);
  }
  for (const Range& range : open) report("CGA107", "'[' is never closed by ']'", range);
  if (items.empty()) {
    fail("CGA103",
         "expected a successor (a shape, an operation, 'NIL', '[', ']', 'case' or a "
         "percentage), found " +
             describe(peek()));
  }
  return items;
}

Item Parser::ce_select_item(ItemKind kind) {
  Item item;
  item.kind = kind;
  item.name = kind == ItemKind::kCase ? "case" : "%";
  const std::uint32_t begin = peek().range.begin;
  const char* what = kind == ItemKind::kCase ? "condition" : "percentage";
  while (kind == ItemKind::kCase ? at_word("case") : ce_at_chance()) {
    Branch branch;
    const std::uint32_t branch_begin = peek().range.begin;
    if (kind == ItemKind::kCase) {
      advance();
      branch.key = parse_expr();
    } else {
      branch.key = parse_unary();
      expect(Tok::kPercent, "");
    }
    expect(Tok::kColon, std::string(" after the ") + what);
    branch.items = ce_body();
    branch.range = from(branch_begin);
    item.branches.push_back(std::move(branch));
  }
  if (!at_word("else")) {
    fail("CGA111", std::string("expected 'else :' to end the ") +
                       (kind == ItemKind::kCase ? "'case'" : "percentage") + " chain, found " +
                       describe(peek()));
  }
  Branch otherwise;
  const std::uint32_t else_begin = advance().range.begin;
  expect(Tok::kColon, " after 'else'");
  otherwise.items = ce_body();
  otherwise.range = from(else_begin);
  item.branches.push_back(std::move(otherwise));
  item.range = from(begin);
  return item;
}

// `alias.Name`: dots glued to identifiers on both sides.
std::string Parser::ce_qualified_name() {
  std::string name = advance().text;
  while (at(Tok::kDot) && at(Tok::kIdent, 1) &&
         tokens_[pos_].range.begin == tokens_[pos_ - 1].range.end &&
         tokens_[pos_ + 1].range.begin == tokens_[pos_].range.end) {
    advance();
    name += '.';
    name += advance().text;
  }
  return name;
}

// A successor shape (`Facade`, `Floor(3)`, `imp.Lot`, terminal `Leaf.`) or an operation. Which
// of `Name(...)` is an operation and which a rule call is decided once every rule is known
// (resolve_calls in run()): parsed as an operation here.
Item Parser::ce_symbol_or_operation() {
  if (at(Tok::kLParen, 1)) return parse_operation();
  Item item;
  const std::uint32_t begin = peek().range.begin;
  item.kind = ItemKind::kSymbol;
  item.name = ce_qualified_name();
  if (at(Tok::kLParen)) {
    advance();
    if (!at(Tok::kRParen)) {
      do {
        item.args.push_back(parse_expr());
      } while (accept(Tok::kComma));
    }
    expect(Tok::kRParen, " to close the arguments of '" + item.name + "'");
  } else if (at(Tok::kDot)) {
    advance();
    item.terminal = true;
  }
  item.range = from(begin);
  return item;
}

// `Name(args)` parsed as an operation is a rule call when a rule of that name exists or no
// operation does (an imported `alias.Rule(...)`, or a rule the checker reports as undefined).
// A split branch written without a size (`| split(y){ ... } |` in Esri's own tutorials) takes
// what is left, as `~1`.
void Parser::float_keyless_branches(Item& item) {
  for (Branch& b : item.branches) {
    if (b.repeat || b.key || b.items.empty()) continue;
    ExprPtr one = make(ExprKind::kNumber, {b.range.begin, b.range.begin});
    one->number = 1;
    b.key = make_unary(UnaryOp::kFloating, b.range.begin, std::move(one));
  }
}

void Parser::ce_resolve_calls() {
  std::map<std::string, std::set<std::size_t>, std::less<>> rules;  // name -> parameter counts
  for (const PrioritySet& set : grammar_.sets) {
    for (const Rule& rule : set.rules) rules[rule.predecessor].insert(rule.params.size());
  }
  // A call is the file's rule unless an operation of that name takes it and no rule of the name
  // has that many parameters (a rule `i --> ...` beside `i("cube")` calls).
  const auto calls_rule = [&](const Item& item) {
    const auto it = rules.find(item.name);
    if (it == rules.end()) return false;
    return find_operation(item.name) == nullptr || item.args.empty() ||
           it->second.count(item.args.size()) > 0;
  };
  // A repeat's parts live in `pattern`, everything else in `items`.
  const auto walk = [&](auto& self, Branch& branch) -> void {
    for (Item& item : branch.items) {
      const bool cityengine_op =
          contains(kUnsupportedOperations, item.name) || contains(kDetailOperations, item.name);
      if (item.kind == ItemKind::kOp && !item.has_block &&
          (calls_rule(item) || (find_operation(item.name) == nullptr && !cityengine_op))) {
        item.kind = ItemKind::kSymbol;
        item.op = OpKind::kGeneric;
      }
      if (item.kind == ItemKind::kOp) drop_form_words(item);
      if (item.kind == ItemKind::kOp && item.name == "split") float_keyless_branches(item);
      for (Branch& inner : item.branches) self(self, inner);
    }
    for (Branch& part : branch.pattern) self(self, part);
  };
  const auto resolve = [&](Rule& rule) {
    for (Alternative& alternative : rule.alternatives) {
      Branch whole;
      whole.items = std::move(alternative.items);
      walk(walk, whole);
      alternative.items = std::move(whole.items);
    }
  };
  for (PrioritySet& set : grammar_.sets) {
    for (Rule& rule : set.rules) resolve(rule);
  }
  // An import's redefinitions call this file's rules.
  for (ImportDecl& decl : grammar_.imports) {
    for (Rule& rule : decl.rule_overrides) resolve(rule);
  }
}

// ---- expressions

ExprPtr Parser::ce_select_expr() {
  const bool is_case = at_word("case");
  const std::uint32_t begin = peek().range.begin;
  ExprPtr expr = make(is_case ? ExprKind::kCase : ExprKind::kChance, Range{begin, begin});
  while (is_case ? at_word("case") : ce_at_chance()) {
    if (is_case) {
      advance();
      expr->operands.push_back(parse_expr());
    } else {
      expr->operands.push_back(parse_unary());
      expect(Tok::kPercent, "");
    }
    expect(Tok::kColon, is_case ? " after the condition" : " after the percentage");
    expr->operands.push_back(parse_expr());
  }
  if (!at_word("else")) {
    fail("CGA111", std::string("expected 'else :' to end the ") +
                       (is_case ? "'case'" : "percentage") + " chain, found " + describe(peek()));
  }
  advance();
  expect(Tok::kColon, " after 'else'");
  expr->operands.push_back(parse_expr());
  expr->range = from(begin);
  return expr;
}

// ---- dialect detection

Dialect detect_dialect(const std::vector<Token>& tokens) {
  const auto kind = [&](std::size_t i) { return i < tokens.size() ? tokens[i].kind : Tok::kEnd; };
  const auto word = [&](std::size_t i, std::string_view w) {
    return kind(i) == Tok::kIdent && tokens[i].text == w;
  };
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    switch (t.kind) {
      case Tok::kPriority:
      case Tok::kTildeArrow:
        return Dialect::kSeed004;
      case Tok::kAt:
        return Dialect::kCityEngine;
      case Tok::kDot:  // a terminal `Leaf.` (a member access is glued to its name)
        if (i > 0 && tokens[i - 1].kind == Tok::kIdent &&
            !(kind(i + 1) == Tok::kIdent && tokens[i + 1].range.begin == t.range.end)) {
          return Dialect::kCityEngine;
        }
        break;
      case Tok::kNumber:
        if (kind(i + 1) == Tok::kPercent && kind(i + 2) == Tok::kColon) {
          return Dialect::kCityEngine;
        }
        if (t.line_start && kind(i + 1) == Tok::kColon) return Dialect::kSeed004;
        break;
      case Tok::kIdent:
        if (i == 0 && t.text == "version" && kind(1) == Tok::kString) return Dialect::kCityEngine;
        if (t.text == "case" || (t.text == "else" && kind(i + 1) == Tok::kColon)) {
          return Dialect::kCityEngine;
        }
        if (!t.line_start) break;
        if ((word(i, "import") || word(i, "const")) && kind(i + 1) == Tok::kIdent) {
          return Dialect::kCityEngine;
        }
        if (kind(i + 1) == Tok::kAssign) return Dialect::kCityEngine;  // a function
        if (kind(i + 1) == Tok::kColon && kind(i + 2) == Tok::kIdent) return Dialect::kSeed004;
        if (kind(i + 1) == Tok::kLParen) {
          int depth = 0;
          std::size_t j = i + 1;
          for (; j < tokens.size(); ++j) {
            if (tokens[j].kind == Tok::kLParen) ++depth;
            if (tokens[j].kind == Tok::kRParen && --depth == 0) break;
          }
          if (is_arrow(kind(j + 1)) || kind(j + 1) == Tok::kAssign) return Dialect::kCityEngine;
        }
        break;
      default:
        break;
    }
  }
  return Dialect::kSeed004;
}

}  // namespace insula::lang::cga::detail
