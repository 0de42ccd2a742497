#include "lang/graph/eval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace insula::lang::graph {
namespace {

std::string a_type(const Value& v) {
  switch (v.type()) {
    case ValueType::kInteger:
      return "an integer";
    default:
      return "a " + std::string(value_type_name(v.type()));
  }
}

bool finite(const Value& v) {
  if (v.type() == ValueType::kNumber) return std::isfinite(v.number());
  if (v.type() != ValueType::kVec3) return true;
  const kernel::Vec3 p = v.vec();
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool both_integers(const Value& a, const Value& b) {
  return a.type() == ValueType::kInteger && b.type() == ValueType::kInteger;
}

// An integer, or a number with an integral value in range (an index, randint's bounds).
std::optional<std::int64_t> integral(const Value& v) {
  if (!v.is_number()) return std::nullopt;
  const std::optional<Value> i = convert(v, ValueType::kInteger);
  if (!i) return std::nullopt;
  return i->integer();
}

// Degrees reduced to [0, period) exactly (fmod is exact), so whole-degree angles hit the table.
double reduce_degrees(double x, double period) {
  double r = std::fmod(x, period);
  if (r < 0) r += period;
  return r >= period ? 0 : r;  // a tiny negative r rounds up to the period
}

// sin of an angle in degrees, exact at multiples of 30 degrees (sin(30) is 0.5, sin(180) is 0).
double sin_degrees(double x) {
  const double r = reduce_degrees(x, 360);
  if (std::fmod(r, 30) == 0) {
    const double s60 = std::sqrt(3.0) / 2;
    const std::array<double, 12> table = {0, 0.5, s60, 1, s60, 0.5, 0, -0.5, -s60, -1, -s60, -0.5};
    return table[static_cast<std::size_t>(r / 30)];
  }
  return std::sin(r * std::numbers::pi / 180);
}

// The evaluated arguments of one function call.
struct Call {
  const Expr& expr;
  std::vector<Value> args;
  EvalEnv& env;
  EvalError& error;

  std::nullopt_t fail(std::string message) const {
    error = EvalError{std::move(message), expr.at};
    return std::nullopt;
  }
  double num(std::size_t i) const { return args[i].number(); }
  bool integers() const {
    return std::all_of(args.begin(), args.end(),
                       [](const Value& v) { return v.type() == ValueType::kInteger; });
  }
  // "sqrt(-1)" for domain messages.
  std::string spelled() const {
    std::string out = expr.name + "(";
    for (std::size_t i = 0; i < args.size(); ++i) out += (i ? ", " : "") + to_string(args[i]);
    return out + ")";
  }
};

using Body = std::optional<Value> (*)(Call&);
enum class Args : std::uint8_t { kNumbers, kIntegers, kVec3s, kAny };

std::optional<Value> call_abs(Call& c) {
  if (c.integers()) {
    const std::int64_t i = c.args[0].integer();
    if (i == INT64_MIN) return c.fail("integer overflow in 'abs'");
    return Value(i < 0 ? -i : i);
  }
  return Value(std::fabs(c.num(0)));
}
std::optional<Value> min_max(Call& c, bool max) {
  if (c.integers()) {
    std::int64_t best = c.args[0].integer();
    for (const Value& v : c.args)
      best = max ? std::max(best, v.integer()) : std::min(best, v.integer());
    return Value(best);
  }
  double best = c.num(0);
  for (const Value& v : c.args)
    best = max ? std::max(best, v.number()) : std::min(best, v.number());
  return Value(best);
}
std::optional<Value> call_min(Call& c) {
  return min_max(c, false);
}
std::optional<Value> call_max(Call& c) {
  return min_max(c, true);
}
std::optional<Value> call_floor(Call& c) {
  return Value(std::floor(c.num(0)));
}
std::optional<Value> call_ceil(Call& c) {
  return Value(std::ceil(c.num(0)));
}
std::optional<Value> call_round(Call& c) {
  return Value(std::round(c.num(0)));  // halves away from zero
}
std::optional<Value> call_sqrt(Call& c) {
  if (c.num(0) < 0) return c.fail(c.spelled() + " is not a real number");
  return Value(std::sqrt(c.num(0)));
}
std::optional<Value> call_pow(Call& c) {
  const double p = std::pow(c.num(0), c.num(1));
  if (std::isnan(p)) return c.fail(c.spelled() + " is not a real number");
  if (!std::isfinite(p)) return c.fail(c.spelled() + " is not finite");
  return Value(p);
}
std::optional<Value> call_clamp(Call& c) {
  const bool integers = c.integers();
  if (integers ? c.args[1].integer() > c.args[2].integer() : c.num(1) > c.num(2)) {
    return c.fail("clamp's lower bound " + to_string(c.args[1]) + " is above its upper bound " +
                  to_string(c.args[2]));
  }
  if (integers)
    return Value(std::clamp(c.args[0].integer(), c.args[1].integer(), c.args[2].integer()));
  return Value(std::clamp(c.num(0), c.num(1), c.num(2)));
}
std::optional<Value> call_sin(Call& c) {
  return Value(sin_degrees(c.num(0)));
}
std::optional<Value> call_cos(Call& c) {
  return Value(sin_degrees(reduce_degrees(c.num(0), 360) + 90));
}
std::optional<Value> call_tan(Call& c) {
  const double r = reduce_degrees(c.num(0), 180);
  if (r == 90) return c.fail(c.spelled() + " is not finite");
  if (r == 0) return Value(0.0);
  if (r == 45) return Value(1.0);
  if (r == 135) return Value(-1.0);
  return Value(std::tan(r * std::numbers::pi / 180));
}
std::optional<Value> call_atan2(Call& c) {
  return Value(std::atan2(c.num(0), c.num(1)) * (180 / std::numbers::pi));
}
std::optional<Value> call_rand(Call& c) {
  if (c.args.empty()) return Value(c.env.rng().unit());
  return Value(c.env.rng().uniform(c.num(0), c.num(1)));
}
std::optional<Value> call_randint(Call& c) {
  return Value(c.env.rng().integer(c.args[0].integer(), c.args[1].integer()));
}
std::optional<Value> call_vec(Call& c) {
  return Value(kernel::Vec3{c.num(0), c.num(1), c.num(2)});
}
std::optional<Value> call_dist(Call& c) {
  return Value(kernel::length(c.args[0].vec() - c.args[1].vec()));
}
std::optional<Value> call_length(Call& c) {
  return Value(kernel::length(c.args[0].vec()));
}
std::optional<Value> call_str(Call& c) {
  return Value(to_string(c.args[0]));
}
std::optional<Value> call_len(Call& c) {
  const Value& v = c.args[0];
  if (v.type() == ValueType::kString) return Value(static_cast<std::int64_t>(v.text().size()));
  if (v.type() == ValueType::kList) return Value(static_cast<std::int64_t>(v.list().size()));
  return c.fail("'len' needs a string or a list, found " + a_type(v));
}
std::optional<Value> call_size(Call& c) {
  const Value& v = c.args[0];
  if (v.type() == ValueType::kList) return Value(static_cast<std::int64_t>(v.list().size()));
  if (v.type() == ValueType::kVec3) return Value(std::int64_t{3});
  return c.fail("'size' needs a list or a vec3, found " + a_type(v));
}
std::optional<Value> call_property(Call& c) {
  std::string message;
  std::optional<Value> v = c.env.property(c.expr.name, message);
  if (!v)
    return c.fail(message.empty() ? c.expr.name + "() does not apply to this entity" : message);
  return v;
}

struct Builtin {
  const char* name;
  int min_args;
  int max_args;
  Args args;
  Body body;
};

// if() is not here: it evaluates only one of its branches (Evaluator::call_if).
constexpr std::array<Builtin, 31> kBuiltins = {{
    {"abs", 1, 1, Args::kNumbers, call_abs},
    {"min", 2, 16, Args::kNumbers, call_min},
    {"max", 2, 16, Args::kNumbers, call_max},
    {"floor", 1, 1, Args::kNumbers, call_floor},
    {"ceil", 1, 1, Args::kNumbers, call_ceil},
    {"round", 1, 1, Args::kNumbers, call_round},
    {"sqrt", 1, 1, Args::kNumbers, call_sqrt},
    {"pow", 2, 2, Args::kNumbers, call_pow},
    {"clamp", 3, 3, Args::kNumbers, call_clamp},
    {"sin", 1, 1, Args::kNumbers, call_sin},
    {"cos", 1, 1, Args::kNumbers, call_cos},
    {"tan", 1, 1, Args::kNumbers, call_tan},
    {"atan2", 2, 2, Args::kNumbers, call_atan2},
    {"rand", 0, 2, Args::kNumbers, call_rand},
    {"randint", 2, 2, Args::kIntegers, call_randint},
    {"vec", 3, 3, Args::kNumbers, call_vec},
    {"dist", 2, 2, Args::kVec3s, call_dist},
    {"length", 1, 1, Args::kVec3s, call_length},
    {"str", 1, 1, Args::kAny, call_str},
    {"len", 1, 1, Args::kAny, call_len},
    {"size", 1, 1, Args::kAny, call_size},
    {"area", 0, 0, Args::kAny, call_property},
    {"perimeter", 0, 0, Args::kAny, call_property},
    {"volume", 0, 0, Args::kAny, call_property},
    {"sx", 0, 0, Args::kAny, call_property},
    {"sy", 0, 0, Args::kAny, call_property},
    {"sz", 0, 0, Args::kAny, call_property},
    {"pos", 0, 0, Args::kAny, call_property},
    {"centroid", 0, 0, Args::kAny, call_property},
    {"normal", 0, 0, Args::kAny, call_property},
    {"type", 0, 0, Args::kAny, call_property},
}};

const Builtin* find_builtin(const std::string& name) {
  for (const Builtin& b : kBuiltins) {
    if (name == b.name) return &b;
  }
  return nullptr;
}

class Evaluator {
 public:
  Evaluator(EvalEnv& env, EvalError& error) : env_(env), error_(error) {}

  // Chains of binary operators and postfixes (`1 + 2 + 3`, `a[0][1]`) nest to the left without
  // the parser counting a level, so their left spine is walked in a loop: recursion only follows
  // the levels the parser bounds.
  std::optional<Value> eval(const Expr& e) {
    std::vector<const Expr*> spine;
    const Expr* leaf = &e;
    while (chained(*leaf)) {
      spine.push_back(leaf);
      leaf = &leaf->args[0];
    }
    std::optional<Value> v = primary(*leaf);
    for (auto it = spine.rbegin(); v && it != spine.rend(); ++it) v = apply(**it, std::move(*v));
    return v;
  }

 private:
  static bool chained(const Expr& e) {
    return e.kind == Expr::Kind::kBinary || e.kind == Expr::Kind::kMember ||
           e.kind == Expr::Kind::kIndex;
  }
  std::nullopt_t fail(std::string message, std::size_t at) {
    error_ = EvalError{std::move(message), at};
    return std::nullopt;
  }

  std::optional<Value> primary(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::kNumber:
        return Value(e.number);
      case Expr::Kind::kInteger:
        return Value(e.integer);
      case Expr::Kind::kString:
        return Value(e.text);
      case Expr::Kind::kBool:
        return Value(e.boolean);
      case Expr::Kind::kList: {
        ValueList items;
        items.reserve(e.args.size());
        for (const Expr& item : e.args) {
          std::optional<Value> v = eval(item);
          if (!v) return std::nullopt;
          items.push_back(std::move(*v));
        }
        return Value(std::move(items));
      }
      case Expr::Kind::kAttribute:
      case Expr::Kind::kPortAttribute:
        return attribute(e);
      case Expr::Kind::kParameter:
        return env_.parameter(e.name);
      case Expr::Kind::kCall:
        return call(e);
      case Expr::Kind::kUnary:
        return unary(e);
      default:
        return fail("malformed expression", e.at);  // chained kinds never reach here
    }
  }

  std::optional<Value> apply(const Expr& e, Value left) {
    if (e.kind == Expr::Kind::kMember) return member(e, left);
    if (e.kind == Expr::Kind::kBinary && (e.name == "and" || e.name == "or")) {
      return logic(e, left);
    }
    std::optional<Value> right = eval(e.args[1]);
    if (!right) return std::nullopt;
    if (e.kind == Expr::Kind::kIndex) return index(e, left, *right);
    return binary(e, left, *right);
  }

  std::optional<Value> attribute(const Expr& e) {
    std::optional<Value> v = env_.attribute(e.scope, e.name);
    if (v) return v;
    if (e.scope.empty()) return fail("no current entity to read '@" + e.name + "' from", e.at);
    return fail("no entity at port '" + e.scope + "' this round", e.at);
  }

  std::optional<Value> unary(const Expr& e) {
    std::optional<Value> v = eval(e.args[0]);
    if (!v) return std::nullopt;
    if (e.name == "not") {
      if (v->type() != ValueType::kBool)
        return fail("'not' needs a bool, found " + a_type(*v), e.at);
      return Value(!v->boolean());
    }
    switch (v->type()) {
      case ValueType::kInteger:
        if (v->integer() == INT64_MIN) return fail("integer overflow in '-'", e.at);
        return Value(-v->integer());
      case ValueType::kNumber:
        return Value(-v->number());
      case ValueType::kVec3:
        return Value(-v->vec());
      default:
        return fail("'-' needs a number or a vec3, found " + a_type(*v), e.at);
    }
  }

  std::optional<Value> logic(const Expr& e, const Value& left) {
    const bool is_and = e.name == "and";
    if (left.type() != ValueType::kBool) {
      return fail("'" + e.name + "' needs bools, found " + a_type(left), e.at);
    }
    if (left.boolean() != is_and) return left;  // false and ..., true or ...
    std::optional<Value> right = eval(e.args[1]);
    if (!right) return std::nullopt;
    if (right->type() != ValueType::kBool) {
      return fail("'" + e.name + "' needs bools, found " + a_type(*right), e.at);
    }
    return right;
  }

  std::optional<Value> member(const Expr& e, const Value& v) {
    if (v.type() != ValueType::kVec3) {
      return fail("'." + e.name + "' needs a vec3, found " + a_type(v), e.at);
    }
    const kernel::Vec3 p = v.vec();
    return Value(e.name == "x" ? p.x : e.name == "y" ? p.y : p.z);
  }

  std::optional<Value> index(const Expr& e, const Value& base, const Value& at) {
    if (base.type() != ValueType::kList && base.type() != ValueType::kVec3) {
      return fail("'[]' needs a list or a vec3, found " + a_type(base), e.at);
    }
    if (!at.is_number()) return fail("'[]' needs an integer index, found " + a_type(at), e.at);
    const std::optional<std::int64_t> i = integral(at);
    if (!i) return fail("index " + to_string(at) + " is not an integer", e.at);
    if (base.type() == ValueType::kVec3) {
      if (*i < 0 || *i > 2)
        return fail("index " + std::to_string(*i) + " is outside the vec3", e.at);
      const kernel::Vec3 p = base.vec();
      return Value(*i == 0 ? p.x : *i == 1 ? p.y : p.z);
    }
    const ValueList& items = base.list();
    if (*i < 0 || static_cast<std::uint64_t>(*i) >= items.size()) {
      return fail(
          "index " + std::to_string(*i) + " is outside the list of " + std::to_string(items.size()),
          e.at);
    }
    return items[static_cast<std::size_t>(*i)];
  }

  std::optional<Value> binary(const Expr& e, const Value& l, const Value& r) {
    const std::string& op = e.name;
    if (op == "==" || op == "!=") {
      if (l.type() != r.type() && !(l.is_number() && r.is_number())) {
        return fail(
            "'" + op + "' compares values of one type, found " + a_type(l) + " and " + a_type(r),
            e.at);
      }
      return Value((l == r) == (op == "=="));
    }
    if (op == "<" || op == "<=" || op == ">" || op == ">=") return compare(e, l, r);
    if (l.is_number() && r.is_number()) return arithmetic(e, l, r);
    if (op == "+" && l.type() == ValueType::kString && r.type() == ValueType::kString) {
      return Value(l.text() + r.text());
    }
    std::optional<kernel::Vec3> v = vector(op, l, r);
    if (v) {
      if (!finite(*v)) {
        const bool by_zero = op == "/" && r.number() == 0;
        return fail(by_zero ? "division by zero" : "number overflow in '" + op + "'", e.at);
      }
      return Value(*v);
    }
    return fail("'" + op + "' cannot take " + a_type(l) + " and " + a_type(r), e.at);
  }

  static std::optional<kernel::Vec3> vector(const std::string& op, const Value& l, const Value& r) {
    const bool lv = l.type() == ValueType::kVec3;
    const bool rv = r.type() == ValueType::kVec3;
    if (lv && rv && op == "+") return l.vec() + r.vec();
    if (lv && rv && op == "-") return l.vec() - r.vec();
    if (lv && r.is_number() && op == "*") return l.vec() * r.number();
    if (lv && r.is_number() && op == "/") return l.vec() / r.number();
    if (l.is_number() && rv && op == "*") return l.number() * r.vec();
    return std::nullopt;
  }

  std::optional<Value> compare(const Expr& e, const Value& l, const Value& r) {
    for (const Value* v : {&l, &r}) {
      if (!v->is_number()) return fail("'" + e.name + "' needs numbers, found " + a_type(*v), e.at);
    }
    // long double holds every int64 exactly, so integer with number compares exactly.
    const auto exact = [](const Value& v) {
      return v.type() == ValueType::kInteger ? static_cast<long double>(v.integer())
                                             : static_cast<long double>(v.number());
    };
    const long double a = exact(l);
    const long double b = exact(r);
    const std::string& op = e.name;
    return Value(op == "<" ? a < b : op == "<=" ? a <= b : op == ">" ? a > b : a >= b);
  }

  std::optional<Value> arithmetic(const Expr& e, const Value& l, const Value& r) {
    const char op = e.name[0];
    if (both_integers(l, r) && op != '/') {
      const std::int64_t a = l.integer();
      const std::int64_t b = r.integer();
      std::int64_t out = 0;
      bool overflow = false;
      switch (op) {
        case '+':
          overflow = __builtin_add_overflow(a, b, &out);
          break;
        case '-':
          overflow = __builtin_sub_overflow(a, b, &out);
          break;
        case '*':
          overflow = __builtin_mul_overflow(a, b, &out);
          break;
        default:  // '%': C++'s remainder takes the sign of the left operand, as §5 asks
          if (b == 0) return fail("modulo by zero", e.at);
          out = b == -1 ? 0 : a % b;  // INT64_MIN % -1 traps on x86
          break;
      }
      if (overflow) return fail("integer overflow in '" + e.name + "'", e.at);
      return Value(out);
    }
    const double a = l.number();
    const double b = r.number();
    double out = 0;
    switch (op) {
      case '+':
        out = a + b;
        break;
      case '-':
        out = a - b;
        break;
      case '*':
        out = a * b;
        break;
      case '/':
        if (b == 0) return fail("division by zero", e.at);
        out = a / b;
        break;
      default:
        if (b == 0) return fail("modulo by zero", e.at);
        out = std::fmod(a, b);
        break;
    }
    if (!std::isfinite(out)) return fail("number overflow in '" + e.name + "'", e.at);
    return Value(out);
  }

  std::optional<Value> call(const Expr& e) {
    if (e.name == "if") return call_if(e);
    const Builtin* b = find_builtin(e.name);
    if (b == nullptr) return fail("unknown function '" + e.name + "'", e.at);
    const int n = static_cast<int>(e.args.size());
    if (n < b->min_args || n > b->max_args || (e.name == "rand" && n == 1)) {
      return fail("wrong number of arguments to '" + e.name + "'", e.at);
    }
    Call c{e, {}, env_, error_};
    c.args.reserve(e.args.size());
    for (const Expr& a : e.args) {
      std::optional<Value> v = eval(a);
      if (!v) return std::nullopt;
      c.args.push_back(std::move(*v));
    }
    if (!check_args(c, b->args)) return std::nullopt;
    std::optional<Value> v = b->body(c);
    // Finite arguments inside each function's domain give a non-finite result only by overflow.
    if (v && !finite(*v)) return fail("number overflow in '" + e.name + "'", e.at);
    return v;
  }

  // The argument types the checker accepted for known types, again for list elements (kAny).
  static bool check_args(Call& c, Args want) {
    for (Value& v : c.args) {
      std::string needs;
      if (want == Args::kNumbers && !v.is_number()) needs = "numbers, found " + a_type(v);
      if (want == Args::kVec3s && v.type() != ValueType::kVec3) needs = "vec3s, found " + a_type(v);
      if (want == Args::kIntegers) {
        const std::optional<std::int64_t> i = integral(v);
        if (i) v = Value(*i);
        if (!i) needs = "integers, found " + (v.is_number() ? to_string(v) : a_type(v));
      }
      if (!needs.empty()) {
        c.fail("'" + c.expr.name + "' needs " + needs);
        return false;
      }
    }
    return true;
  }

  std::optional<Value> call_if(const Expr& e) {
    if (e.args.size() != 3) return fail("wrong number of arguments to 'if'", e.at);
    std::optional<Value> c = eval(e.args[0]);
    if (!c) return std::nullopt;
    if (c->type() != ValueType::kBool) return fail("'if' needs a bool, found " + a_type(*c), e.at);
    return eval(e.args[c->boolean() ? 1 : 2]);
  }

  EvalEnv& env_;
  EvalError& error_;
};

}  // namespace

std::optional<Value> evaluate(const Expr& expr, EvalEnv& env, EvalError& error) {
  return Evaluator(env, error).eval(expr);
}

}  // namespace insula::lang::graph
