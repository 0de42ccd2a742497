#include "shape/query.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>

namespace insula::shape {

using kernel::Vec3;

namespace {

bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
}

enum class TokenKind { kEnd, kIdent, kString, kOpen, kClose, kNumber, kCompare, kBad };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string_view text;  // for kString: without the quotes
  std::size_t offset = 0;
};

// A small lexer shared by label expressions and attribute tests.
class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  Token next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) {
      ++pos_;
    }
    const std::size_t start = pos_;
    if (pos_ >= text_.size()) return {TokenKind::kEnd, {}, start};
    const char c = text_[pos_];
    if (c == '(' || c == ')') {
      ++pos_;
      return {c == '(' ? TokenKind::kOpen : TokenKind::kClose, text_.substr(start, 1), start};
    }
    if (c == '"') return quoted(start);
    if (is_ident_start(c)) {
      while (pos_ < text_.size() && is_ident_char(text_[pos_])) ++pos_;
      return {TokenKind::kIdent, text_.substr(start, pos_ - start), start};
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.') {
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) != 0 || text_[pos_] == '.' ||
              text_[pos_] == '-' || text_[pos_] == '+')) {
        ++pos_;
      }
      return {TokenKind::kNumber, text_.substr(start, pos_ - start), start};
    }
    if (c == '=' || c == '!' || c == '<' || c == '>') {
      ++pos_;
      if (pos_ < text_.size() && text_[pos_] == '=') ++pos_;
      return {TokenKind::kCompare, text_.substr(start, pos_ - start), start};
    }
    ++pos_;
    return {TokenKind::kBad, text_.substr(start, 1), start};
  }

 private:
  Token quoted(std::size_t start) {
    const std::size_t close = text_.find('"', start + 1);
    if (close == std::string_view::npos) {
      pos_ = text_.size();
      return {TokenKind::kBad, text_.substr(start), start};
    }
    pos_ = close + 1;
    return {TokenKind::kString, text_.substr(start + 1, close - start - 1), start};
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

// Strings are joined by append: GCC 12 warns falsely (-Wrestrict) on "x" + std::string chains.
std::string concat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out.append(p);
  return out;
}

std::string describe(const Token& t) {
  switch (t.kind) {
    case TokenKind::kEnd:
      return "end of query";
    case TokenKind::kString:
      return concat({"'\"", t.text, "\"'"});
    default:
      return concat({"'", t.text, "'"});
  }
}

base::Diagnostic query_error(std::string_view code, std::string_view source, const Token& at,
                             std::string message) {
  const auto column = static_cast<std::uint32_t>(at.offset + 1);
  const auto length = static_cast<std::uint32_t>(std::max<std::size_t>(1, at.text.size()));
  return base::Diagnostic::error(std::string(code), std::move(message),
                                 base::Span::at(std::string(source), 1, column, length));
}

}  // namespace

// Recursive descent, one method per production of the grammar in query.h.
class LabelParser {
 public:
  LabelParser(std::string_view text, std::string_view source) : lexer_(text), source_(source) {
    advance();
  }

  base::Result<LabelExpr> run() {
    const std::uint32_t root = expr();
    if (!error_ && current_.kind != TokenKind::kEnd) {
      fail(concat({"expected 'and', 'or' or end of query, found ", describe(current_)}));
    }
    if (error_) return base::Result<LabelExpr>::failure({*error_});
    // The root must be the last node: append a copy when it is not (it always is, by
    // construction, but the invariant is cheap to keep explicit).
    if (root + 1 != out_.nodes_.size()) out_.nodes_.push_back(out_.nodes_[root]);
    return std::move(out_);
  }

 private:
  void advance() { current_ = lexer_.next(); }
  bool is_keyword(std::string_view word) const {
    return current_.kind == TokenKind::kIdent && current_.text == word;
  }
  void fail(std::string message) {
    if (!error_) error_ = query_error("Q001", source_, current_, std::move(message));
  }
  std::uint32_t add(LabelExpr::Op op, std::uint32_t a, std::uint32_t b = 0) {
    out_.nodes_.push_back({op, a, b});
    return static_cast<std::uint32_t>(out_.nodes_.size() - 1);
  }

  std::uint32_t expr() {
    std::uint32_t left = and_expr();
    while (!error_ && is_keyword("or")) {
      advance();
      const std::uint32_t right = and_expr();
      left = add(LabelExpr::Op::kOr, left, right);
    }
    return left;
  }
  std::uint32_t and_expr() {
    std::uint32_t left = not_expr();
    while (!error_ && is_keyword("and")) {
      advance();
      const std::uint32_t right = not_expr();
      left = add(LabelExpr::Op::kAnd, left, right);
    }
    return left;
  }
  std::uint32_t not_expr() {
    if (is_keyword("not")) {
      advance();
      return add(LabelExpr::Op::kNot, not_expr());
    }
    return primary();
  }
  std::uint32_t primary() {
    if (error_) return 0;
    if (current_.kind == TokenKind::kOpen) {
      advance();
      const std::uint32_t inner = expr();
      if (!error_ && current_.kind != TokenKind::kClose) {
        fail(concat({"expected ')', found ", describe(current_)}));
      }
      advance();
      return inner;
    }
    const bool keyword = is_keyword("and") || is_keyword("or");
    if ((current_.kind == TokenKind::kIdent && !keyword) || current_.kind == TokenKind::kString) {
      out_.labels_.emplace_back(current_.text);
      advance();
      return add(LabelExpr::Op::kLabel, static_cast<std::uint32_t>(out_.labels_.size() - 1));
    }
    fail(concat({"expected a label or '(', found ", describe(current_)}));
    return 0;
  }

  Lexer lexer_;
  std::string_view source_;
  Token current_;
  LabelExpr out_;
  std::optional<base::Diagnostic> error_;
};

base::Result<LabelExpr> LabelExpr::parse(std::string_view text, std::string_view source_name) {
  return LabelParser(text, source_name).run();
}

bool LabelExpr::eval(const ShapeTree& tree, ShapeId id, std::uint32_t node) const {
  const Node& n = nodes_[node];
  switch (n.op) {
    case Op::kLabel:
      return tree.has_label(id, labels_[n.a]);
    case Op::kNot:
      return !eval(tree, id, n.a);
    case Op::kAnd:
      return eval(tree, id, n.a) && eval(tree, id, n.b);
    case Op::kOr:
      return eval(tree, id, n.a) || eval(tree, id, n.b);
  }
  return false;
}

bool LabelExpr::matches(const ShapeTree& tree, ShapeId id) const {
  return !nodes_.empty() && eval(tree, id, static_cast<std::uint32_t>(nodes_.size() - 1));
}

std::string LabelExpr::node_string(std::uint32_t node) const {
  const Node& n = nodes_[node];
  switch (n.op) {
    case Op::kLabel: {
      const std::string& l = labels_[n.a];
      const bool plain = !l.empty() && is_ident_start(l[0]) &&
                         std::all_of(l.begin(), l.end(), is_ident_char) && l != "and" &&
                         l != "or" && l != "not";
      return plain ? l : concat({"\"", l, "\""});
    }
    case Op::kNot:
      return concat({"(not ", node_string(n.a), ")"});
    case Op::kAnd:
      return concat({"(", node_string(n.a), " and ", node_string(n.b), ")"});
    case Op::kOr:
      return concat({"(", node_string(n.a), " or ", node_string(n.b), ")"});
  }
  return {};
}

std::string LabelExpr::to_string() const {
  return nodes_.empty() ? std::string()
                        : node_string(static_cast<std::uint32_t>(nodes_.size() - 1));
}

namespace {

std::optional<Compare> compare_from(std::string_view op) {
  static constexpr std::array<std::pair<std::string_view, Compare>, 6> kOps = {{
      {"==", Compare::kEqual},
      {"!=", Compare::kNotEqual},
      {"<", Compare::kLess},
      {"<=", Compare::kLessEqual},
      {">", Compare::kGreater},
      {">=", Compare::kGreaterEqual},
  }};
  for (const auto& [text, c] : kOps) {
    if (text == op) return c;
  }
  return std::nullopt;
}

template <typename T>
bool ordered(const T& a, const T& b, Compare op) {
  switch (op) {
    case Compare::kEqual:
      return a == b;
    case Compare::kNotEqual:
      return a != b;
    case Compare::kLess:
      return a < b;
    case Compare::kLessEqual:
      return a <= b;
    case Compare::kGreater:
      return a > b;
    case Compare::kGreaterEqual:
      return a >= b;
  }
  return false;
}

}  // namespace

bool compare(double a, Compare op, double b) {
  return ordered(a, b, op);
}

bool value_matches(const Value* v, Compare op, const Value& value) {
  if (v == nullptr || v->index() != value.index()) return op == Compare::kNotEqual;
  if (const auto* d = std::get_if<double>(v)) return ordered(*d, std::get<double>(value), op);
  if (const auto* s = std::get_if<std::string>(v)) {
    return ordered(*s, std::get<std::string>(value), op);
  }
  if (op != Compare::kEqual && op != Compare::kNotEqual) return false;
  return (*v == value) == (op == Compare::kEqual);
}

bool AttributeTest::matches(const ShapeTree& tree, ShapeId id) const {
  return value_matches(tree.attribute(id, name), op, value);
}

base::Result<AttributeTest> AttributeTest::parse(std::string_view text,
                                                 std::string_view source_name) {
  using R = base::Result<AttributeTest>;
  Lexer lexer(text);
  const Token name = lexer.next();
  if (name.kind != TokenKind::kIdent && name.kind != TokenKind::kString) {
    return R::failure(
        {query_error("Q002", source_name, name,
                     concat({"expected an attribute name, found ", describe(name)}))});
  }
  const Token op = lexer.next();
  const auto compare = op.kind == TokenKind::kCompare ? compare_from(op.text) : std::nullopt;
  if (!compare) {
    return R::failure(
        {query_error("Q002", source_name, op,
                     concat({"expected one of == != < <= > >=, found ", describe(op)}))});
  }
  const Token value = lexer.next();
  AttributeTest test{std::string(name.text), *compare, {}};
  if (value.kind == TokenKind::kString) {
    test.value = std::string(value.text);
  } else if (value.kind == TokenKind::kIdent && (value.text == "true" || value.text == "false")) {
    test.value = value.text == "true";
  } else {
    double d = 0;
    const char* end = value.text.data() + value.text.size();
    const auto [ptr, ec] = std::from_chars(value.text.data(), end, d);
    if (value.kind != TokenKind::kNumber || ec != std::errc() || ptr != end) {
      return R::failure({query_error(
          "Q002", source_name, value,
          concat({"expected a number, true, false or a quoted string, found ", describe(value)}))});
    }
    test.value = d;
  }
  const Token rest = lexer.next();
  if (rest.kind != TokenKind::kEnd) {
    return R::failure({query_error("Q002", source_name, rest,
                                   concat({"expected end of query, found ", describe(rest)}))});
  }
  return test;
}

namespace {

std::vector<ShapeId> candidates(const ShapeTree& tree, QuerySet set, ShapeId under) {
  std::vector<ShapeId> ids = under == kNoShape ? tree.all() : tree.subtree(under);
  std::sort(ids.begin(), ids.end());
  std::erase_if(ids, [&](ShapeId id) {
    return (set == QuerySet::kActive && !tree[id].active) ||
           (set == QuerySet::kLeaves && !tree[id].children.empty());
  });
  return ids;
}

template <typename Predicate>
std::vector<ShapeId> filter(const ShapeTree& tree, QuerySet set, ShapeId under, Predicate keep) {
  std::vector<ShapeId> ids = candidates(tree, set, under);
  std::erase_if(ids, [&](ShapeId id) { return !keep(id); });
  return ids;
}

}  // namespace

std::vector<ShapeId> query(const ShapeTree& tree, const LabelExpr& expr, QuerySet set,
                           ShapeId under) {
  return filter(tree, set, under, [&](ShapeId id) { return expr.matches(tree, id); });
}

std::vector<ShapeId> query(const ShapeTree& tree, const AttributeTest& test, QuerySet set,
                           ShapeId under) {
  return filter(tree, set, under, [&](ShapeId id) { return test.matches(tree, id); });
}

std::vector<ShapeId> descendants(const ShapeTree& tree, ShapeId id) {
  std::vector<ShapeId> out = tree.subtree(id);
  out.erase(out.begin());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<ShapeId> within_distance(const ShapeTree& tree, ShapeId id, double distance,
                                     const std::vector<ShapeId>& candidates_in) {
  const Vec3 c = tree[id].scope.center();
  std::vector<std::pair<double, ShapeId>> hits;
  for (ShapeId other : candidates_in) {
    if (other == id) continue;
    const double d = length(tree[other].scope.center() - c);
    if (d <= distance) hits.emplace_back(d, other);
  }
  std::sort(hits.begin(), hits.end());
  std::vector<ShapeId> out;
  for (const auto& [d, other] : hits) out.push_back(other);
  return out;
}

namespace {

// Axis-aligned box in the target's scope frame.
struct Box {
  std::array<double, 3> min;
  std::array<double, 3> max;
};

Box box_in_frame(const Scope& frame, const Scope& other) {
  Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const Vec3& corner : other.corners()) {
    const Vec3 p = frame.to_local(corner);
    const std::array<double, 3> q = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      b.min[k] = std::min(b.min[k], q[k]);
      b.max[k] = std::max(b.max[k], q[k]);
    }
  }
  return b;
}

// Measure (area or volume) of the union of boxes over the listed dimensions, clipped to
// [0, size]: coordinate compression, then each cell tested against every box. O(n^(d+1)) for n
// boxes in d dimensions, fine for the handful of neighbours a query compares.
double union_measure(std::vector<Box> boxes, const std::array<double, 3>& size,
                     const std::vector<int>& dims) {
  std::array<std::vector<double>, 3> cuts;
  for (int d : dims) {
    cuts[d] = {0.0, size[d]};
    for (Box& b : boxes) {
      b.min[d] = std::clamp(b.min[d], 0.0, size[d]);
      b.max[d] = std::clamp(b.max[d], 0.0, size[d]);
      cuts[d].push_back(b.min[d]);
      cuts[d].push_back(b.max[d]);
    }
    std::sort(cuts[d].begin(), cuts[d].end());
    cuts[d].erase(std::unique(cuts[d].begin(), cuts[d].end()), cuts[d].end());
  }
  double total = 0;
  std::array<std::size_t, 3> cell{0, 0, 0};
  // Iterate over every cell of the grid spanned by the used dimensions.
  const auto count = [&](int d) { return cuts[d].size() - 1; };
  std::size_t cells = 1;
  for (int d : dims) cells *= count(d);
  for (std::size_t flat = 0; flat < cells; ++flat) {
    std::size_t rest = flat;
    double measure = 1;
    std::array<double, 3> mid{};
    for (int d : dims) {
      cell[d] = rest % count(d);
      rest /= count(d);
      measure *= cuts[d][cell[d] + 1] - cuts[d][cell[d]];
      mid[d] = (cuts[d][cell[d] + 1] + cuts[d][cell[d]]) / 2;
    }
    if (measure <= 0) continue;
    const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) {
      return std::all_of(dims.begin(), dims.end(),
                         [&](int d) { return mid[d] > b.min[d] && mid[d] < b.max[d]; });
    });
    if (covered) total += measure;
  }
  return total;
}

}  // namespace

double occlusion(const ShapeTree& tree, ShapeId id, const std::vector<ShapeId>& others,
                 double tolerance) {
  const Scope& scope = tree[id].scope;
  const std::array<double, 3> size = {scope.size.x, scope.size.y, scope.size.z};
  std::vector<int> dims;
  int flat_dim = -1;
  for (int d = 0; d < 3; ++d) {
    if (size[d] > 0) {
      dims.push_back(d);
    } else {
      flat_dim = d;
    }
  }
  if (dims.size() < 2) return 0;
  std::vector<Box> boxes;
  for (ShapeId other : others) {
    if (other == id) continue;
    const Box b = box_in_frame(scope, tree[other].scope);
    // A flat target only sees boxes reaching its plane (projection along the normal).
    if (dims.size() == 2 && (b.max[flat_dim] < -tolerance || b.min[flat_dim] > tolerance)) {
      continue;
    }
    boxes.push_back(b);
  }
  double whole = 1;
  for (int d : dims) whole *= size[d];
  return std::clamp(union_measure(std::move(boxes), size, dims) / whole, 0.0, 1.0);
}

}  // namespace insula::shape
