#include "shape/query_expr.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "shape/ops.h"

namespace insula::shape {

namespace {

enum class Tok : std::uint8_t {
  kEnd,
  kIdent,
  kString,
  kOpen,
  kClose,
  kComma,
  kNumber,
  kCompare,
  kBad,  // an unknown character or an unterminated string (the rest of the text)
};

struct Token {
  Tok kind = Tok::kEnd;
  std::string_view text;  // kString: without quotes
  std::size_t offset = 0;
  std::size_t length = 1;
};

bool ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
}

// Tokens with their byte offsets; the parser reports a kBad token where it finds one.
class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  Token next() {
    Token t;
    scan(t);
    return t;
  }

 private:
  void scan(Token& t) {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) {
      ++pos_;
    }
    t = Token{Tok::kEnd, {}, pos_, 1};
    if (pos_ >= text_.size()) return;
    const std::size_t start = pos_;
    const char c = text_[pos_];
    if (c == '(' || c == ')' || c == ',') {
      ++pos_;
      t.kind = c == '(' ? Tok::kOpen : (c == ')' ? Tok::kClose : Tok::kComma);
      t.text = text_.substr(start, 1);
      return;
    }
    if (c == '"' || c == '\'') {
      const std::size_t close = text_.find(c, start + 1);
      if (close == std::string_view::npos) {
        pos_ = text_.size();
        t = Token{Tok::kBad, text_.substr(start), start, pos_ - start};
        return;
      }
      pos_ = close + 1;
      t = Token{Tok::kString, text_.substr(start + 1, close - start - 1), start, pos_ - start};
      return;
    }
    if (ident_start(c)) {
      while (pos_ < text_.size() && ident_char(text_[pos_])) ++pos_;
      t = Token{Tok::kIdent, text_.substr(start, pos_ - start), start, pos_ - start};
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.') {
      ++pos_;
      // Letters and digits, points, and a sign after an exponent mark (1e-5).
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) != 0 || text_[pos_] == '.' ||
              ((text_[pos_] == '-' || text_[pos_] == '+') &&
               (text_[pos_ - 1] == 'e' || text_[pos_ - 1] == 'E')))) {
        ++pos_;
      }
      t = Token{Tok::kNumber, text_.substr(start, pos_ - start), start, pos_ - start};
      return;
    }
    if (c == '=' || c == '!' || c == '<' || c == '>' || c == '~') {
      ++pos_;
      if (pos_ < text_.size() && text_[pos_] == '=') ++pos_;
      t = Token{Tok::kCompare, text_.substr(start, pos_ - start), start, pos_ - start};
      return;
    }
    ++pos_;
    t = Token{Tok::kBad, text_.substr(start, 1), start, 1};
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

std::string describe(const Token& t) {
  if (t.kind == Tok::kEnd) return "end of query";
  if (t.kind == Tok::kString) return "'\"" + std::string(t.text) + "\"'";
  std::string out = "'";
  out.append(t.text);
  out += "'";
  return out;
}

bool compare_from(std::string_view text, Compare& out) {
  if (text == "==") {
    out = Compare::kEqual;
  } else if (text == "!=" || text == "~=") {
    out = Compare::kNotEqual;
  } else if (text == "<") {
    out = Compare::kLess;
  } else if (text == "<=") {
    out = Compare::kLessEqual;
  } else if (text == ">") {
    out = Compare::kGreater;
  } else if (text == ">=") {
    out = Compare::kGreaterEqual;
  } else {
    return false;
  }
  return true;
}

bool parse_number(std::string_view text, double& out) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last && std::isfinite(out);
}

bool is_selector(std::string_view word, FaceSelector& out) {
  static constexpr std::pair<std::string_view, FaceSelector> kSelectors[] = {
      {"FRONT", FaceSelector::kFront}, {"BACK", FaceSelector::kBack},
      {"LEFT", FaceSelector::kLeft},   {"RIGHT", FaceSelector::kRight},
      {"TOP", FaceSelector::kTop},     {"BOTTOM", FaceSelector::kBottom},
      {"SIDE", FaceSelector::kSide},   {"ALL", FaceSelector::kAll}};
  for (const auto& [name, selector] : kSelectors) {
    if (word == name) {
      out = selector;
      return true;
    }
  }
  return false;
}

}  // namespace

// Recursive descent, one method per production of the grammar in query_expr.h.
class QueryParser {
 public:
  using Grammar = QueryExpr::Grammar;

  QueryParser(std::string_view text, std::string_view source, Grammar grammar)
      : lexer_(text), source_(source), grammar_(grammar) {
    advance();
  }

  base::Result<QueryExpr> run() {
    if (grammar_ == Grammar::kAttribute) return run_attribute();
    const std::uint32_t root = expr();
    if (!failed_ && current_.kind != Tok::kEnd) {
      fail("expected 'and', 'or' or end of query, found " + describe(current_));
    }
    if (failed_) return base::Result<QueryExpr>::failure({error_});
    if (root + 1 != out_.nodes_.size()) out_.nodes_.push_back(out_.nodes_[root]);
    return std::move(out_);
  }

 private:
  using Kind = QueryExpr::Kind;

  base::Result<QueryExpr> run_attribute() {
    if (current_.kind != Tok::kIdent && current_.kind != Tok::kString) {
      fail("expected an attribute name, found " + describe(current_));
    } else {
      const Token name = current_;
      advance();
      attribute(name);
    }
    if (!failed_ && current_.kind != Tok::kEnd) {
      fail("expected end of query, found " + describe(current_));
    }
    if (failed_) return base::Result<QueryExpr>::failure({error_});
    return std::move(out_);
  }

  void advance() { current_ = lexer_.next(); }
  bool keyword(std::string_view word) const {
    return current_.kind == Tok::kIdent && current_.text == word;
  }
  void fail(std::string message) {
    if (failed_) return;
    failed_ = true;
    error_ = base::Diagnostic::error(
        grammar_ == Grammar::kAttribute ? "Q002" : "Q001", std::move(message),
        base::Span::at(std::string(source_), 1, static_cast<std::uint32_t>(current_.offset + 1),
                       static_cast<std::uint32_t>(current_.length)));
  }
  static QueryExpr::Node make(Kind kind, std::uint32_t a = 0, std::uint32_t b = 0,
                              std::string text = {}) {
    QueryExpr::Node node;
    node.kind = kind;
    node.a = a;
    node.b = b;
    node.text = std::move(text);
    return node;
  }
  std::uint32_t add(QueryExpr::Node node) {
    out_.nodes_.push_back(std::move(node));
    return static_cast<std::uint32_t>(out_.nodes_.size() - 1);
  }
  bool expect(Tok kind, const char* what) {
    if (current_.kind == kind) {
      advance();
      return true;
    }
    fail(std::string("expected ") + what + ", found " + describe(current_));
    return false;
  }

  std::uint32_t expr() {
    std::uint32_t left = and_expr();
    while (!failed_ && keyword("or")) {
      advance();
      const std::uint32_t right = and_expr();
      left = add(make(Kind::kOr, left, right));
    }
    return left;
  }
  std::uint32_t and_expr() {
    std::uint32_t left = not_expr();
    while (!failed_ && keyword("and")) {
      advance();
      const std::uint32_t right = not_expr();
      left = add(make(Kind::kAnd, left, right));
    }
    return left;
  }
  std::uint32_t not_expr() {
    if (keyword("not")) {
      advance();
      const std::uint32_t inner = not_expr();
      return add(make(Kind::kNot, inner));
    }
    return primary();
  }

  std::uint32_t primary() {
    if (failed_) return 0;
    if (current_.kind == Tok::kOpen) {
      advance();
      const std::uint32_t inner = expr();
      expect(Tok::kClose, "')'");
      return inner;
    }
    if (current_.kind == Tok::kString) {
      const std::string label(current_.text);
      advance();
      return add(make(Kind::kLabel, 0, 0, label));
    }
    if (current_.kind != Tok::kIdent || keyword("and") || keyword("or")) {
      fail("expected a label or '(', found " + describe(current_));
      return 0;
    }
    const Token word = current_;
    advance();
    if (current_.kind == Tok::kOpen && grammar_ == Grammar::kShapes) return function(word);
    if (current_.kind == Tok::kCompare && grammar_ == Grammar::kShapes) return attribute(word);
    QueryExpr::Node node = make(Kind::kLabel, 0, 0, std::string(word.text));
    FaceSelector selector{};
    if (grammar_ == Grammar::kFaces && is_selector(word.text, selector)) {
      node.kind = Kind::kFaceSelector;
      node.a = static_cast<std::uint32_t>(selector);
    }
    return add(std::move(node));
  }

  // parent(e[, n]) child(e) occlusion(e) op t near(e, d) active() leaf() flat()
  std::uint32_t function(const Token& word) {
    const std::string_view name = word.text;
    advance();  // '('
    if (name == "active" || name == "leaf" || name == "flat") {
      expect(Tok::kClose, "')'");
      return add(
          make(name == "active" ? Kind::kActive : (name == "leaf" ? Kind::kLeaf : Kind::kFlat)));
    }
    if (name != "parent" && name != "child" && name != "occlusion" && name != "near") {
      current_ = word;
      fail("unknown query function '" + std::string(name) +
           "' (use parent, child, occlusion, near, active, leaf, flat)");
      return 0;
    }
    const std::uint32_t inner = expr();
    QueryExpr::Node node = make(Kind::kParent, inner);
    if (name == "parent" && current_.kind == Tok::kComma) {
      advance();
      node.number = number("a depth");
      if (!failed_ && (node.number < 1 || node.number != std::floor(node.number))) {
        fail("parent depth must be a whole number >= 1");
      }
    }
    if (name == "near") {
      expect(Tok::kComma, "',' and a distance");
      node.number = number("a distance");
      node.kind = Kind::kNear;
    }
    expect(Tok::kClose, "')'");
    if (name == "child") node.kind = Kind::kChild;
    if (name == "occlusion") {
      node.kind = Kind::kOcclusion;
      if (current_.kind != Tok::kCompare || !compare_from(current_.text, node.compare)) {
        fail("expected a comparison after occlusion(...), found " + describe(current_));
        return 0;
      }
      advance();
      node.number = number("a fraction");
    }
    return add(std::move(node));
  }

  double number(const char* what) {
    double value = 0;
    if (failed_) return 0;
    if (current_.kind != Tok::kNumber || !parse_number(current_.text, value)) {
      fail(std::string("expected ") + what + ", found " + describe(current_));
      return 0;
    }
    advance();
    return value;
  }

  std::uint32_t attribute(const Token& name) {
    QueryExpr::Node node = make(Kind::kAttribute, 0, 0, std::string(name.text));
    if (current_.kind != Tok::kCompare || !compare_from(current_.text, node.compare)) {
      fail("expected one of == != < <= > >=, found " + describe(current_));
      return 0;
    }
    advance();
    if (current_.kind == Tok::kString) {
      node.value = std::string(current_.text);
    } else if (current_.kind == Tok::kIdent &&
               (current_.text == "true" || current_.text == "false")) {
      node.value = current_.text == "true";
    } else {
      double d = 0;
      if (current_.kind != Tok::kNumber || !parse_number(current_.text, d)) {
        fail("expected a number, true, false or a quoted string, found " + describe(current_));
        return 0;
      }
      node.value = d;
    }
    advance();
    return add(std::move(node));
  }

  Lexer lexer_;
  std::string_view source_;
  Grammar grammar_;
  Token current_;
  bool failed_ = false;
  base::Diagnostic error_;
  QueryExpr out_;
};

base::Result<QueryExpr> QueryExpr::parse(std::string_view text, std::string_view source_name,
                                         Grammar grammar) {
  return QueryParser(text, source_name, grammar).run();
}

base::Result<QueryExpr> QueryExpr::parse_faces(std::string_view text,
                                               std::string_view source_name) {
  return parse(text, source_name, Grammar::kFaces);
}

namespace {

bool plain_label(const std::string& l) {
  return !l.empty() && ident_start(l[0]) && std::all_of(l.begin(), l.end(), ident_char) &&
         l != "and" && l != "or" && l != "not";
}

}  // namespace

std::string QueryExpr::to_string() const {
  std::string out;
  const auto write = [&](const auto& self, std::uint32_t index) -> void {
    const Node& n = nodes_[index];
    switch (n.kind) {
      case Kind::kLabel:
        out += plain_label(n.text) ? n.text : "\"" + n.text + "\"";
        return;
      case Kind::kNot:
        out += "(not ";
        self(self, n.a);
        out += ")";
        return;
      case Kind::kAnd:
      case Kind::kOr:
        out += "(";
        self(self, n.a);
        out += n.kind == Kind::kAnd ? " and " : " or ";
        self(self, n.b);
        out += ")";
        return;
      default:
        out += "?";
        return;
    }
  };
  if (!nodes_.empty()) write(write, root());
  return out;
}

// ---- evaluation

namespace {

struct WorldBox {
  kernel::Vec3 min;
  kernel::Vec3 max;
};

WorldBox world_box(const Scope& scope) {
  WorldBox b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const kernel::Vec3& c : scope.corners()) {
    b.min = {std::min(b.min.x, c.x), std::min(b.min.y, c.y), std::min(b.min.z, c.z)};
    b.max = {std::max(b.max.x, c.x), std::max(b.max.y, c.y), std::max(b.max.z, c.z)};
  }
  return b;
}

bool overlaps(const WorldBox& a, const WorldBox& b, double margin) {
  return a.min.x <= b.max.x + margin && b.min.x <= a.max.x + margin &&
         a.min.y <= b.max.y + margin && b.min.y <= a.max.y + margin &&
         a.min.z <= b.max.z + margin && b.min.z <= a.max.z + margin;
}

}  // namespace

// The shapes matching an inner expression of occlusion() / near(), with their world boxes.
struct QueryExpr::Evaluator::Cache {
  std::vector<ShapeId> ids;
  std::vector<WorldBox> boxes;
};

QueryExpr::Evaluator::Evaluator(const QueryExpr& expr, const ShapeTree& tree)
    : expr_(expr), tree_(tree), caches_(expr.nodes_.size()) {}

QueryExpr::Evaluator::~Evaluator() = default;

bool QueryExpr::Evaluator::matches(ShapeId id) {
  return eval(id, expr_.root());
}

bool QueryExpr::Evaluator::eval(ShapeId id, std::uint32_t index) {
  const Node& node = expr_.nodes_[index];
  switch (node.kind) {
    case Kind::kLabel:
      return tree_.has_label(id, node.text);
    case Kind::kNot:
      return !eval(id, node.a);
    case Kind::kAnd:
      return eval(id, node.a) && eval(id, node.b);
    case Kind::kOr:
      return eval(id, node.a) || eval(id, node.b);
    case Kind::kParent: {
      std::size_t depth = 0;
      for (ShapeId p = tree_.parent(id); p != kNoShape; p = tree_.parent(p)) {
        if (node.number > 0 && ++depth > static_cast<std::size_t>(node.number)) break;
        if (eval(p, node.a)) return true;
      }
      return false;
    }
    case Kind::kChild:
      return std::any_of(tree_.children(id).begin(), tree_.children(id).end(),
                         [&](ShapeId c) { return eval(c, node.a); });
    case Kind::kActive:
      return tree_[id].active;
    case Kind::kLeaf:
      return tree_.children(id).empty();
    case Kind::kFlat:
      return tree_[id].is_flat();
    case Kind::kAttribute:
      return value_matches(tree_.attribute(id, node.text), node.compare, node.value);
    case Kind::kOcclusion:
    case Kind::kNear:
      break;
    case Kind::kFaceSelector:
      return false;
  }
  // occlusion() and near(): the inner matches once, then a box prefilter per candidate.
  std::unique_ptr<Cache>& cache = caches_[index];
  if (!cache) {
    cache = std::make_unique<Cache>();
    for (ShapeId s = 0; s < tree_.size(); ++s) {
      if (!eval(s, node.a)) continue;
      cache->ids.push_back(s);
      cache->boxes.push_back(world_box(tree_[s].scope));
    }
  }
  const WorldBox mine = world_box(tree_[id].scope);
  const double margin = node.kind == Kind::kNear ? node.number : 1e-3;
  std::vector<ShapeId> close;
  for (std::size_t i = 0; i < cache->ids.size(); ++i) {
    if (cache->ids[i] != id && overlaps(mine, cache->boxes[i], margin)) {
      close.push_back(cache->ids[i]);
    }
  }
  if (node.kind == Kind::kNear) {
    return !within_distance(tree_, id, node.number, close).empty();
  }
  return compare(occlusion(tree_, id, close), node.compare, node.number);
}

bool QueryExpr::matches_face(kernel::Vec3 normal, std::string_view face_name) const {
  return eval_face(root(), normal, face_name);
}

bool QueryExpr::matches_name(std::string_view name) const {
  return eval_face(root(), {}, name);
}

bool QueryExpr::eval_face(std::uint32_t index, kernel::Vec3 normal,
                          std::string_view face_name) const {
  const Node& node = nodes_[index];
  switch (node.kind) {
    case Kind::kLabel:
      return node.text == face_name;
    case Kind::kFaceSelector:
      return face_matches(static_cast<FaceSelector>(node.a), normal);
    case Kind::kNot:
      return !eval_face(node.a, normal, face_name);
    case Kind::kAnd:
      return eval_face(node.a, normal, face_name) && eval_face(node.b, normal, face_name);
    case Kind::kOr:
      return eval_face(node.a, normal, face_name) || eval_face(node.b, normal, face_name);
    default:
      return false;
  }
}

}  // namespace insula::shape
