#include "lang/graph/expr.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace insula::lang::graph {
namespace {

constexpr int kMaxDepth = 100;
// Chains of binary operators and postfixes are parsed by loops, not under the nesting bound, and
// build left-nested trees as deep as they are long. The type checker and the evaluator walk such
// spines in loops, but Expr's copy and destructor still recurse along them; bounding the
// operators bounds that depth: a 20,000-deep chain is copied, run and destroyed by `insula build`
// within 2 MB of stack (docs/graph-executor.md, "Expressions").
constexpr int kMaxOperators = 20000;

bool letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

class Parser {
 public:
  Parser(std::string_view text, ExprError& error) : t_(text), error_(error) {}

  std::optional<Expr> run() {
    skip();
    if (at_ >= t_.size()) return fail("expected an expression after '='", at_);
    std::optional<Expr> e = expr();
    if (!e) return std::nullopt;
    skip();
    if (at_ < t_.size())
      return fail("unexpected '" + std::string(1, t_[at_]) + "' after the expression", at_);
    return e;
  }

 private:
  std::nullopt_t fail(std::string message, std::size_t where) {
    if (error_.message.empty()) error_ = ExprError{"G023", std::move(message), where};
    return std::nullopt;
  }
  void skip() {
    while (at_ < t_.size() && (t_[at_] == ' ' || t_[at_] == '\t' || t_[at_] == '\n')) ++at_;
  }
  bool word(std::string_view w) {
    skip();
    if (t_.substr(at_, w.size()) != w) return false;
    const std::size_t after = at_ + w.size();
    if (letter(w[0]) && after < t_.size() && (letter(t_[after]) || digit(t_[after]))) return false;
    at_ = after;
    return true;
  }
  // Counts one more operator node; false (G023) past kMaxOperators, before the tree grows deeper.
  bool another_operator(std::size_t where) {
    if (++operators_ <= kMaxOperators) return true;
    fail("expression too long (more than " + std::to_string(kMaxOperators) + " operators)", where);
    return false;
  }
  Expr binary(std::string op, std::size_t where, Expr l, Expr r) {
    Expr e;
    e.kind = Expr::Kind::kBinary;
    e.name = std::move(op);
    e.at = where;
    e.begin = l.begin;
    e.end = r.end;
    e.args.push_back(std::move(l));
    e.args.push_back(std::move(r));
    return e;
  }
  std::optional<Expr> expr() {
    if (++depth_ > kMaxDepth) return fail("expression nested deeper than 100 levels", at_);
    std::optional<Expr> e = disjunction();
    --depth_;
    return e;
  }
  std::optional<Expr> disjunction() {
    std::optional<Expr> l = conjunction();
    while (l) {
      skip();
      const std::size_t where = at_;
      if (!word("or")) break;
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> r = conjunction();
      if (!r) return std::nullopt;
      l = binary("or", where, std::move(*l), std::move(*r));
    }
    return l;
  }
  std::optional<Expr> conjunction() {
    std::optional<Expr> l = negation();
    while (l) {
      skip();
      const std::size_t where = at_;
      if (!word("and")) break;
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> r = negation();
      if (!r) return std::nullopt;
      l = binary("and", where, std::move(*l), std::move(*r));
    }
    return l;
  }
  std::optional<Expr> negation() {
    skip();
    const std::size_t where = at_;
    if (word("not")) {
      if (++depth_ > kMaxDepth) return fail("expression nested deeper than 100 levels", where);
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> inner = negation();
      --depth_;
      if (!inner) return std::nullopt;
      Expr e;
      e.kind = Expr::Kind::kUnary;
      e.name = "not";
      e.at = e.begin = where;
      e.end = inner->end;
      e.args.push_back(std::move(*inner));
      return e;
    }
    return comparison();
  }
  std::optional<Expr> comparison() {
    std::optional<Expr> l = sum();
    if (!l) return std::nullopt;
    skip();
    for (const char* op : {"==", "!=", "<=", ">=", "<", ">"}) {
      if (t_.substr(at_, std::string_view(op).size()) != op) continue;
      const std::size_t where = at_;
      at_ += std::string_view(op).size();
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> r = sum();
      if (!r) return std::nullopt;
      return binary(op, where, std::move(*l), std::move(*r));
    }
    return l;
  }
  std::optional<Expr> sum() {
    std::optional<Expr> l = product();
    while (l) {
      skip();
      if (at_ >= t_.size() || (t_[at_] != '+' && t_[at_] != '-')) break;
      const std::size_t where = at_++;
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> r = product();
      if (!r) return std::nullopt;
      l = binary(std::string(1, t_[where]), where, std::move(*l), std::move(*r));
    }
    return l;
  }
  std::optional<Expr> product() {
    std::optional<Expr> l = unary();
    while (l) {
      skip();
      if (at_ >= t_.size() || (t_[at_] != '*' && t_[at_] != '/' && t_[at_] != '%')) break;
      const std::size_t where = at_++;
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> r = unary();
      if (!r) return std::nullopt;
      l = binary(std::string(1, t_[where]), where, std::move(*l), std::move(*r));
    }
    return l;
  }
  std::optional<Expr> unary() {
    skip();
    if (at_ < t_.size() && t_[at_] == '-') {
      const std::size_t where = at_++;
      if (++depth_ > kMaxDepth) return fail("expression nested deeper than 100 levels", where);
      if (!another_operator(where)) return std::nullopt;
      std::optional<Expr> inner = unary();
      --depth_;
      if (!inner) return std::nullopt;
      Expr e;
      e.kind = Expr::Kind::kUnary;
      e.name = "-";
      e.at = e.begin = where;
      e.end = inner->end;
      e.args.push_back(std::move(*inner));
      return e;
    }
    return postfix();
  }
  std::optional<Expr> postfix() {
    std::optional<Expr> e = primary();
    while (e) {
      skip();
      if (at_ < t_.size() && t_[at_] == '.') {
        const std::size_t where = at_++;
        if (!another_operator(where)) return std::nullopt;
        if (at_ >= t_.size() || (t_[at_] != 'x' && t_[at_] != 'y' && t_[at_] != 'z') ||
            (at_ + 1 < t_.size() && (letter(t_[at_ + 1]) || digit(t_[at_ + 1])))) {
          return fail("expected x, y or z after '.'", at_);
        }
        Expr m;
        m.kind = Expr::Kind::kMember;
        m.name = std::string(1, t_[at_++]);
        m.at = where;
        m.begin = e->begin;
        m.end = at_;
        m.args.push_back(std::move(*e));
        e = std::move(m);
      } else if (at_ < t_.size() && t_[at_] == '[') {
        const std::size_t where = at_++;
        if (!another_operator(where)) return std::nullopt;
        std::optional<Expr> index = expr();
        if (!index) return std::nullopt;
        skip();
        if (at_ >= t_.size() || t_[at_] != ']') return fail("expected ']' after the index", at_);
        ++at_;
        Expr i;
        i.kind = Expr::Kind::kIndex;
        i.at = where;
        i.begin = e->begin;
        i.end = at_;
        i.args.push_back(std::move(*e));
        i.args.push_back(std::move(*index));
        e = std::move(i);
      } else {
        break;
      }
    }
    return e;
  }
  std::string name() {
    const std::size_t begin = at_;
    while (at_ < t_.size() && (letter(t_[at_]) || digit(t_[at_]))) ++at_;
    return std::string(t_.substr(begin, at_ - begin));
  }
  // Comma-separated expressions up to `close`, after the opening bracket.
  bool list(char close, std::vector<Expr>& out, const std::string& what) {
    skip();
    if (at_ < t_.size() && t_[at_] == close) {
      ++at_;
      return true;
    }
    for (;;) {
      std::optional<Expr> item = expr();
      if (!item) return false;
      out.push_back(std::move(*item));
      skip();
      if (at_ < t_.size() && t_[at_] == ',') {
        ++at_;
        continue;
      }
      if (at_ < t_.size() && t_[at_] == close) {
        ++at_;
        return true;
      }
      fail("expected '" + std::string(1, close) + "' after " + what, at_);
      return false;
    }
  }
  std::optional<Expr> primary() {
    skip();
    Expr e;
    e.begin = e.at = at_;
    if (at_ >= t_.size()) return fail("expected a value at the end of the expression", at_);
    const char c = t_[at_];
    if (digit(c) || (c == '.' && at_ + 1 < t_.size() && digit(t_[at_ + 1]))) {
      const std::size_t begin = at_;
      bool real = false;
      while (at_ < t_.size() && (digit(t_[at_]) || t_[at_] == '.')) real |= t_[at_++] == '.';
      if (at_ < t_.size() && (t_[at_] == 'e' || t_[at_] == 'E')) {
        real = true;
        ++at_;
        if (at_ < t_.size() && (t_[at_] == '+' || t_[at_] == '-')) ++at_;
        while (at_ < t_.size() && digit(t_[at_])) ++at_;
      }
      const std::string_view spelled = t_.substr(begin, at_ - begin);
      if (real) {
        e.kind = Expr::Kind::kNumber;
        const auto [end, ec] =
            std::from_chars(spelled.data(), spelled.data() + spelled.size(), e.number);
        if (ec != std::errc() || end != spelled.data() + spelled.size() ||
            !std::isfinite(e.number)) {
          return fail("malformed number '" + std::string(spelled) + "'", begin);
        }
      } else {
        e.kind = Expr::Kind::kInteger;
        const auto [end, ec] =
            std::from_chars(spelled.data(), spelled.data() + spelled.size(), e.integer);
        if (ec != std::errc())
          return fail("integer '" + std::string(spelled) + "' is too large", begin);
        e.number = static_cast<double>(e.integer);
      }
      e.end = at_;
      return e;
    }
    if (c == '\'' || c == '"') {
      const std::size_t close = t_.find(c, at_ + 1);
      if (close == std::string_view::npos) return fail("unterminated string", at_);
      e.kind = Expr::Kind::kString;
      e.text = std::string(t_.substr(at_ + 1, close - at_ - 1));
      at_ = close + 1;
      e.end = at_;
      return e;
    }
    if (c == '[') {
      ++at_;
      e.kind = Expr::Kind::kList;
      if (!list(']', e.args, "the list's items")) return std::nullopt;
      e.end = at_;
      return e;
    }
    if (c == '(') {
      ++at_;
      std::optional<Expr> inner = expr();
      if (!inner) return std::nullopt;
      skip();
      if (at_ >= t_.size() || t_[at_] != ')') return fail("expected ')'", at_);
      ++at_;
      return inner;
    }
    if (c == '@') {
      ++at_;
      e.kind = Expr::Kind::kAttribute;
      if (at_ >= t_.size() || !letter(t_[at_]))
        return fail("expected an attribute name after '@'", at_);
      e.name = name();
      e.end = at_;
      return e;
    }
    if (!letter(c)) return fail("unexpected '" + std::string(1, c) + "'", at_);
    const std::string n = name();
    if (n == "true" || n == "false") {
      e.kind = Expr::Kind::kBool;
      e.boolean = n == "true";
      e.end = at_;
      return e;
    }
    if (at_ < t_.size() && t_[at_] == '@') {
      ++at_;
      e.kind = Expr::Kind::kPortAttribute;
      e.scope = n;
      if (at_ >= t_.size() || !letter(t_[at_]))
        return fail("expected an attribute name after '@'", at_);
      e.at = at_ - 1;
      e.name = name();
      e.end = at_;
      return e;
    }
    skip();
    if (at_ < t_.size() && t_[at_] == '(') {
      ++at_;
      e.kind = Expr::Kind::kCall;
      e.name = n;
      if (!list(')', e.args, "the arguments of '" + n + "'")) return std::nullopt;
      e.end = at_;
      return e;
    }
    e.kind = Expr::Kind::kParameter;
    e.name = n;
    e.end = e.begin + n.size();
    return e;
  }

  std::string_view t_;
  ExprError& error_;
  std::size_t at_ = 0;
  int depth_ = 0;
  int operators_ = 0;
};

struct Function {
  const char* name;
  int min_args;
  int max_args;
  ValueType result;  // kAny: the type of the second argument (if)
  ValueType args;    // every argument's type (kAny: any)
  bool entity;       // reads the current entity
};

constexpr std::array<Function, 30> kFunctions = {{
    {"abs", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"min", 2, 16, ValueType::kNumber, ValueType::kNumber, false},
    {"max", 2, 16, ValueType::kNumber, ValueType::kNumber, false},
    {"floor", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"ceil", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"round", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"sqrt", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"pow", 2, 2, ValueType::kNumber, ValueType::kNumber, false},
    {"clamp", 3, 3, ValueType::kNumber, ValueType::kNumber, false},
    {"sin", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"cos", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"tan", 1, 1, ValueType::kNumber, ValueType::kNumber, false},
    {"atan2", 2, 2, ValueType::kNumber, ValueType::kNumber, false},
    {"if", 3, 3, ValueType::kAny, ValueType::kAny, false},
    {"rand", 0, 2, ValueType::kNumber, ValueType::kNumber, false},
    {"randint", 2, 2, ValueType::kInteger, ValueType::kInteger, false},
    {"vec", 3, 3, ValueType::kVec3, ValueType::kNumber, false},
    {"dist", 2, 2, ValueType::kNumber, ValueType::kVec3, false},
    {"length", 1, 1, ValueType::kNumber, ValueType::kVec3, false},
    {"str", 1, 1, ValueType::kString, ValueType::kAny, false},
    {"len", 1, 1, ValueType::kInteger, ValueType::kString, false},
    {"size", 1, 1, ValueType::kInteger, ValueType::kList, false},
    {"area", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"perimeter", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"volume", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"sx", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"sy", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"sz", 0, 0, ValueType::kNumber, ValueType::kAny, true},
    {"pos", 0, 0, ValueType::kVec3, ValueType::kAny, true},
    {"centroid", 0, 0, ValueType::kVec3, ValueType::kAny, true},
}};
// normal() and type() complete the entity properties.
constexpr std::array<Function, 2> kMoreFunctions = {{
    {"normal", 0, 0, ValueType::kVec3, ValueType::kAny, true},
    {"type", 0, 0, ValueType::kString, ValueType::kAny, true},
}};

const Function* find_function(std::string_view name) {
  for (const Function& f : kFunctions) {
    if (name == f.name) return &f;
  }
  for (const Function& f : kMoreFunctions) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

bool numeric(ValueType t) {
  return t == ValueType::kNumber || t == ValueType::kInteger;
}

std::string a_type(ValueType t) {
  switch (t) {
    case ValueType::kInteger:
      return "an integer";
    case ValueType::kAny:
      return "a value";
    default:
      return "a " + std::string(value_type_name(t));
  }
}

class TypeChecker {
 public:
  TypeChecker(std::string_view text, const ExprScope& scope, ExprError& error)
      : t_(text), scope_(scope), error_(error) {}

  // Chains of binary operators and postfixes nest to the left without the parser counting a
  // level, so their left spine is walked in a loop (as the evaluator does): recursion only
  // follows the levels the parser bounds.
  std::optional<ValueType> type(const Expr& e) {
    std::vector<const Expr*> spine;
    const Expr* leaf = &e;
    while (chained(*leaf)) {
      spine.push_back(leaf);
      leaf = &leaf->args[0];
    }
    std::optional<ValueType> t = primary(*leaf);
    for (auto it = spine.rbegin(); t && it != spine.rend(); ++it) t = apply(**it, *t);
    return t;
  }

 private:
  static bool chained(const Expr& e) {
    return e.kind == Expr::Kind::kBinary || e.kind == Expr::Kind::kMember ||
           e.kind == Expr::Kind::kIndex;
  }

  std::optional<ValueType> primary(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::kNumber:
        return ValueType::kNumber;
      case Expr::Kind::kInteger:
        return ValueType::kInteger;
      case Expr::Kind::kString:
        return ValueType::kString;
      case Expr::Kind::kBool:
        return ValueType::kBool;
      case Expr::Kind::kList:
        for (const Expr& item : e.args) {
          if (!type(item)) return std::nullopt;
        }
        return ValueType::kList;
      case Expr::Kind::kAttribute:
      case Expr::Kind::kPortAttribute:
        return attribute(e);
      case Expr::Kind::kParameter: {
        const std::optional<ValueType> p = scope_.parameter(e.name);
        if (!p) {
          return fail(
              "G021",
              "unknown graph parameter '" + e.name + "'" + suggest(e.name, scope_.parameters),
              e.at);
        }
        return *p == ValueType::kEnum ? ValueType::kString : *p;
      }
      case Expr::Kind::kCall:
        return call(e);
      case Expr::Kind::kUnary: {
        const std::optional<ValueType> a = type(e.args[0]);
        if (!a) return std::nullopt;
        if (e.name == "not") return need(e.args[0], *a, ValueType::kBool, "not", "a bool");
        if (*a == ValueType::kAny || numeric(*a) || *a == ValueType::kVec3) return *a;
        return mismatch(e.args[0], *a, "-", "numbers", e.at);
      }
      default:
        return std::nullopt;  // chained kinds never reach here
    }
  }

  // A chained node whose left operand has type `a`.
  std::optional<ValueType> apply(const Expr& e, ValueType a) {
    if (e.kind == Expr::Kind::kMember) {
      if (a != ValueType::kVec3 && a != ValueType::kAny) {
        return mismatch(e.args[0], a, "." + e.name, "a vec3", e.at);
      }
      return ValueType::kNumber;
    }
    if (e.kind == Expr::Kind::kIndex) {
      const std::optional<ValueType> i = type(e.args[1]);
      if (!i) return std::nullopt;
      if (*i != ValueType::kInteger && *i != ValueType::kAny) {
        return mismatch(e.args[1], *i, "[]", "an integer index", e.at);
      }
      if (a == ValueType::kVec3) return ValueType::kNumber;
      if (a == ValueType::kList || a == ValueType::kAny) return ValueType::kAny;
      return mismatch(e.args[0], a, "[]", "a list or a vec3", e.at);
    }
    return binary(e, a);
  }

  std::nullopt_t fail(const std::string& code, std::string message, std::size_t at) {
    if (error_.message.empty()) error_ = ExprError{code, std::move(message), at};
    return std::nullopt;
  }
  static std::string suggest(const std::string& word, const std::vector<std::string>& names) {
    const std::string near = nearest(word, names);
    return near.empty() ? "" : " (did you mean '" + near + "'?)";
  }
  std::string spelled(const Expr& e) const {
    return std::string(t_.substr(e.begin, e.end - e.begin));
  }
  // G024: `'@kind' is a string; '>' needs numbers`.
  std::nullopt_t mismatch(const Expr& operand, ValueType t, const std::string& op,
                          const std::string& needs, std::size_t at) {
    return fail("G024",
                "'" + spelled(operand) + "' is " + a_type(t) + "; '" + op + "' needs " + needs, at);
  }
  std::optional<ValueType> need(const Expr& operand, ValueType t, ValueType wanted,
                                const std::string& op, const std::string& needs) {
    if (t == wanted || t == ValueType::kAny || (wanted == ValueType::kNumber && numeric(t))) {
      return wanted;
    }
    return mismatch(operand, t, op, needs, operand.begin);
  }
  std::optional<ValueType> attribute(const Expr& e) {
    if (e.kind == Expr::Kind::kPortAttribute && !scope_.input_port(e.scope)) {
      return fail("G012",
                  "no input port '" + e.scope + "' to read '" + e.scope + "@" + e.name + "' from",
                  e.begin);
    }
    if (e.kind == Expr::Kind::kAttribute && !scope_.entity_readable) {
      return fail("G022", scope_.not_readable_because + " cannot read '@" + e.name + "'", e.at);
    }
    const std::optional<ValueType> a = scope_.attribute(e.name);
    if (!a) {
      return fail("G020", "unknown attribute '" + e.name + "'" + suggest(e.name, scope_.attributes),
                  e.at);
    }
    return a;
  }
  std::optional<ValueType> call(const Expr& e) {
    const Function* f = find_function(e.name);
    if (f == nullptr) {
      std::vector<std::string> names;
      for (const Function& g : kFunctions) names.emplace_back(g.name);
      for (const Function& g : kMoreFunctions) names.emplace_back(g.name);
      return fail("G023", "unknown function '" + e.name + "'" + suggest(e.name, names), e.at);
    }
    const int n = static_cast<int>(e.args.size());
    if (n < f->min_args || n > f->max_args || (e.name == "rand" && n == 1)) {
      const std::string count = f->min_args == f->max_args ? std::to_string(f->min_args)
                                : e.name == "rand"         ? "0 or 2"
                                                   : std::to_string(f->min_args) + " or more";
      return fail("G023",
                  "'" + e.name + "' takes " + count + " argument" + (count == "1" ? "" : "s") +
                      ", found " + std::to_string(n),
                  e.at);
    }
    if (f->entity && !scope_.entity_readable) {
      return fail("G022", scope_.not_readable_because + " cannot read '" + e.name + "()'", e.at);
    }
    std::vector<ValueType> types;
    for (const Expr& a : e.args) {
      const std::optional<ValueType> t = type(a);
      if (!t) return std::nullopt;
      types.push_back(*t);
    }
    if (e.name == "if") {
      if (!need(e.args[0], types[0], ValueType::kBool, "if", "a bool")) return std::nullopt;
      if (types[1] == types[2]) return types[1];
      if (numeric(types[1]) && numeric(types[2])) return ValueType::kNumber;
      if (types[1] == ValueType::kAny || types[2] == ValueType::kAny) return ValueType::kAny;
      return fail("G024",
                  "'if' gives " + a_type(types[1]) + " or " + a_type(types[2]) +
                      "; both branches must have one type",
                  e.at);
    }
    if (e.name == "len" && types[0] == ValueType::kList) return ValueType::kInteger;
    if (e.name == "size" && types[0] == ValueType::kVec3) return ValueType::kInteger;
    if (f->args != ValueType::kAny) {
      for (std::size_t i = 0; i < types.size(); ++i) {
        const std::string needs = f->args == ValueType::kNumber ? "numbers" : a_type(f->args) + "s";
        if (!need(e.args[i], types[i], f->args, e.name, needs)) return std::nullopt;
      }
    }
    if ((e.name == "abs" || e.name == "min" || e.name == "max" || e.name == "clamp") &&
        std::all_of(types.begin(), types.end(),
                    [](ValueType t) { return t == ValueType::kInteger; })) {
      return ValueType::kInteger;
    }
    return f->result;
  }
  std::optional<ValueType> binary(const Expr& e, ValueType left) {
    const std::optional<ValueType> l = left;
    const std::optional<ValueType> r = type(e.args[1]);
    if (!r) return std::nullopt;
    const std::string& op = e.name;
    if (op == "and" || op == "or") {
      if (!need(e.args[0], *l, ValueType::kBool, op, "bools")) return std::nullopt;
      if (!need(e.args[1], *r, ValueType::kBool, op, "bools")) return std::nullopt;
      return ValueType::kBool;
    }
    if (*l == ValueType::kAny || *r == ValueType::kAny) {
      return op == "==" || op == "!=" || op == "<" || op == "<=" || op == ">" || op == ">="
                 ? ValueType::kBool
                 : ValueType::kAny;
    }
    if (op == "==" || op == "!=") {
      if (*l == *r || (numeric(*l) && numeric(*r))) return ValueType::kBool;
      return fail("G024",
                  "'" + spelled(e.args[0]) + "' is " + a_type(*l) + " and '" + spelled(e.args[1]) +
                      "' is " + a_type(*r) + "; '" + op + "' compares values of one type",
                  e.at);
    }
    if (op == "<" || op == "<=" || op == ">" || op == ">=") {
      if (!numeric(*l)) return mismatch(e.args[0], *l, op, "numbers", e.args[0].begin);
      if (!numeric(*r)) return mismatch(e.args[1], *r, op, "numbers", e.args[1].begin);
      return ValueType::kBool;
    }
    if (op == "+" && *l == ValueType::kString && *r == ValueType::kString)
      return ValueType::kString;
    if ((op == "+" || op == "-") && *l == ValueType::kVec3 && *r == ValueType::kVec3) {
      return ValueType::kVec3;
    }
    if ((op == "*" || op == "/") && *l == ValueType::kVec3 && numeric(*r)) return ValueType::kVec3;
    if (op == "*" && numeric(*l) && *r == ValueType::kVec3) return ValueType::kVec3;
    if (!numeric(*l)) return mismatch(e.args[0], *l, op, "numbers", e.args[0].begin);
    if (!numeric(*r)) return mismatch(e.args[1], *r, op, "numbers", e.args[1].begin);
    if (op != "/" && *l == ValueType::kInteger && *r == ValueType::kInteger) {
      return ValueType::kInteger;
    }
    return ValueType::kNumber;
  }

  std::string_view t_;
  const ExprScope& scope_;
  ExprError& error_;
};

}  // namespace

std::optional<Expr> parse_expression(std::string_view text, ExprError& error) {
  return Parser(text, error).run();
}

std::optional<ValueType> check_expression(const Expr& expr, std::string_view text,
                                          const ExprScope& scope, ExprError& error) {
  return TypeChecker(text, scope, error).type(expr);
}

}  // namespace insula::lang::graph
