// The builtins of this stage: the FL toolbox (Backus's combinators as PLaSM names them), numbers,
// predicates. Each takes its arguments curried (AA:f:x is the native AA with arity 2).
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

#include "base/format.h"
#include "lang/plasm/eval_context.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {
namespace {

using Args = std::span<const ValuePtr>;

bool is_integer(const Value& v) {
  return v.is_number() && v.number() == std::floor(v.number());
}

std::size_t natural(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  const double n = c.number(v, who, at);
  if (n < 0 || n != std::floor(n) || n > 1e15)
    c.fail("PSM402", text({"'", std::string(who), "' needs a natural number, found ", summary(*v)}),
           at);
  return static_cast<std::size_t>(n);
}

const Sequence& nonempty(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  const Sequence& s = c.seq(v, who, at);
  if (s.empty()) c.fail("PSM407", text({"'", std::string(who), "' of an empty sequence"}), at);
  return s;
}

ValuePtr id_fn(Context&, const Function&, Args a, Range) {
  return a[0];
}

ValuePtr k_fn(Context&, const Function&, Args a, Range) {
  return a[0];
}

ValuePtr aa_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = c.seq(a[1], "AA", at);
  // A user function over several elements: one task per element (parallel.cc).
  if (s.size() >= 2 && a[0]->function().def != nullptr)
    return c.sequence(c.parallel(
                          s.size(), [&](std::size_t k) { return c.apply(a[0], s[k], at); }, at),
                      at);
  Sequence out;
  out.reserve(s.size());
  for (const ValuePtr& x : s) out.push_back(c.apply(a[0], x, at));
  return c.sequence(std::move(out), at);
}

ValuePtr distl_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "DISTL", at);
  Sequence out;
  for (const ValuePtr& y : c.seq(pair[1], "DISTL", at))
    out.push_back(c.sequence(Sequence{pair[0], y}, at));
  return c.sequence(std::move(out), at);
}

ValuePtr distr_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "DISTR", at);
  Sequence out;
  for (const ValuePtr& x : c.seq(pair[0], "DISTR", at))
    out.push_back(c.sequence(Sequence{x, pair[1]}, at));
  return c.sequence(std::move(out), at);
}

ValuePtr al_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "AL", at);
  Sequence out{pair[0]};
  const Sequence& rest = c.seq(pair[1], "AL", at);
  out.insert(out.end(), rest.begin(), rest.end());
  return c.sequence(std::move(out), at);
}

ValuePtr ar_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "AR", at);
  Sequence out = c.seq(pair[0], "AR", at);
  out.push_back(pair[1]);
  return c.sequence(std::move(out), at);
}

ValuePtr cat_fn(Context& c, const Function&, Args a, Range at) {
  Sequence out;
  for (const ValuePtr& part : c.seq(a[0], "CAT", at)) {
    const Sequence& s = c.seq(part, "CAT", at);
    out.insert(out.end(), s.begin(), s.end());
  }
  return c.sequence(std::move(out), at);
}

ValuePtr len_fn(Context& c, const Function&, Args a, Range at) {
  return make_number(static_cast<double>(c.seq(a[0], "LEN", at).size()));
}

ValuePtr select(Context& c, std::size_t k, const ValuePtr& v, std::string_view who, Range at) {
  const Sequence& s = c.seq(v, who, at);
  if (k < 1 || k > s.size())
    c.fail("PSM407",
           text({"'", std::string(who), "' selects element ", std::to_string(k),
                 " of a sequence of ", std::to_string(s.size())}),
           at);
  return s[k - 1];
}

template <std::size_t K>
ValuePtr s_fn(Context& c, const Function& self, Args a, Range at) {
  return select(c, K, a[0], self.label, at);
}

ValuePtr sel_fn(Context& c, const Function&, Args a, Range at) {
  return select(c, natural(c, a[0], "SEL", at), a[1], "SEL", at);
}

ValuePtr first_fn(Context& c, const Function&, Args a, Range at) {
  return nonempty(c, a[0], "FIRST", at).front();
}

ValuePtr last_fn(Context& c, const Function&, Args a, Range at) {
  return nonempty(c, a[0], "LAST", at).back();
}

ValuePtr tail_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = nonempty(c, a[0], "TAIL", at);
  return c.sequence(Sequence(s.begin() + 1, s.end()), at);
}

ValuePtr butlast_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = nonempty(c, a[0], "BUTLAST", at);
  return c.sequence(Sequence(s.begin(), s.end() - 1), at);
}

ValuePtr reverse_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = c.seq(a[0], "REVERSE", at);
  return c.sequence(Sequence(s.rbegin(), s.rend()), at);
}

ValuePtr list_fn(Context& c, const Function&, Args a, Range at) {
  return c.sequence(Sequence{a[0]}, at);
}

ValuePtr c_fn(Context& c, const Function&, Args a, Range at) {
  return c.apply(a[0], c.sequence(Sequence{a[1], a[2]}, at), at);
}

ValuePtr insr_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = nonempty(c, a[1], "INSR", at);
  ValuePtr acc = s.back();
  for (std::size_t i = s.size() - 1; i-- > 0;)
    acc = c.apply(a[0], c.sequence(Sequence{s[i], acc}, at), at);
  return acc;
}

ValuePtr insl_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = nonempty(c, a[1], "INSL", at);
  ValuePtr acc = s.front();
  for (std::size_t i = 1; i < s.size(); ++i)
    acc = c.apply(a[0], c.sequence(Sequence{acc, s[i]}, at), at);
  return acc;
}

ValuePtr cons_fn(Context& c, const Function&, Args a, Range at) {
  Sequence out;
  for (const ValuePtr& f : c.seq(a[0], "CONS", at)) out.push_back(c.apply(f, a[1], at));
  return c.sequence(std::move(out), at);
}

ValuePtr comp_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& fs = c.seq(a[0], "COMP", at);
  ValuePtr x = a[1];
  for (std::size_t i = fs.size(); i-- > 0;) x = c.apply(fs[i], x, at);
  return x;
}

ValuePtr trans_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& rows = c.seq(a[0], "TRANS", at);
  if (rows.empty()) return a[0];
  const std::size_t width = c.seq(rows[0], "TRANS", at).size();
  Sequence out;
  for (std::size_t j = 0; j < width; ++j) {
    Sequence column;
    for (const ValuePtr& row : rows) {
      const Sequence& r = c.seq(row, "TRANS", at);
      if (r.size() != width)
        c.fail("PSM404",
               text({"'TRANS' needs rows of one length, found ", std::to_string(width), " and ",
                     std::to_string(r.size())}),
               at);
      column.push_back(r[j]);
    }
    out.push_back(c.sequence(std::move(column), at));
  }
  return c.sequence(std::move(out), at);
}

ValuePtr fromto_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "FROMTO", at);
  return fromto(c, pair[0], pair[1], "FROMTO", at);
}

ValuePtr intsto_fn(Context& c, const Function&, Args a, Range at) {
  return fromto(c, make_number(1), a[0], "INTSTO", at);
}

ValuePtr repeat_fn(Context& c, const Function&, Args a, Range at) {
  return repeat(c, a[0], a[1], false, at);
}

// The functions of one number, told apart by the builtin's name.
ValuePtr math_fn(Context& c, const Function& self, Args a, Range at) {
  const double x = c.number(a[0], self.label, at);
  const std::string& f = self.label;
  const double y = f == "ABS"    ? std::fabs(x)
                   : f == "SIN"  ? std::sin(x)
                   : f == "COS"  ? std::cos(x)
                   : f == "TAN"  ? std::tan(x)
                   : f == "ASIN" ? std::asin(x)
                   : f == "ACOS" ? std::acos(x)
                   : f == "ATAN" ? std::atan(x)
                   : f == "EXP"  ? std::exp(x)
                   : f == "LN"   ? (x > 0 ? std::log(x) : NAN)
                                 : std::sqrt(x);
  return c.result(y, f, at);
}

ValuePtr atan2_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& pair = c.seq_of(a[0], 2, "ATAN2", at);
  return c.result(std::atan2(c.number(pair[0], "ATAN2", at), c.number(pair[1], "ATAN2", at)),
                  "ATAN2", at);
}

// LT:a:x is x < a, and so on: the bound is the first argument, as in C:LT:0.
template <int Cmp>
ValuePtr compare_fn(Context& c, const Function& self, Args a, Range at) {
  const double bound = c.number(a[0], self.label, at);
  const double x = c.number(a[1], self.label, at);
  switch (Cmp) {
    case 0:
      return make_bool(x < bound);
    case 1:
      return make_bool(x <= bound);
    case 2:
      return make_bool(x > bound);
    default:
      return make_bool(x >= bound);
  }
}

ValuePtr eq_fn(Context& c, const Function&, Args a, Range at) {
  const Sequence& s = c.seq(a[0], "EQ", at);
  for (std::size_t i = 1; i < s.size(); ++i)
    if (!equal(s[0], s[i])) return make_bool(false);
  return make_bool(true);
}

ValuePtr and_fn(Context& c, const Function&, Args a, Range at) {
  bool all = true;
  for (const ValuePtr& v : c.seq(a[0], "AND", at))
    all = c.truth(v, "each element of AND", at) && all;
  return make_bool(all);
}

ValuePtr or_fn(Context& c, const Function&, Args a, Range at) {
  bool any = false;
  for (const ValuePtr& v : c.seq(a[0], "OR", at)) any = c.truth(v, "each element of OR", at) || any;
  return make_bool(any);
}

ValuePtr not_fn(Context& c, const Function&, Args a, Range at) {
  return make_bool(!c.truth(a[0], "the argument of NOT", at));
}

template <bool (*P)(const Value&)>
ValuePtr predicate_fn(Context&, const Function&, Args a, Range) {
  return make_bool(P(*a[0]));
}

bool any_value(const Value&) {
  return true;
}
bool is_bool(const Value& v) {
  return v.is_bool();
}
bool is_fun(const Value& v) {
  return v.is_function();
}
bool is_int(const Value& v) {
  return is_integer(v);
}
bool is_intpos(const Value& v) {
  return is_integer(v) && v.number() > 0;
}
bool is_nat(const Value& v) {
  return is_integer(v) && v.number() >= 0;
}
bool is_num(const Value& v) {
  return v.is_number();
}
bool is_pol(const Value& v) {
  return v.kind() == Kind::kPolyhedron;
}
bool is_realpos(const Value& v) {
  return v.is_number() && v.number() > 0;
}
bool is_seq(const Value& v) {
  return v.is_sequence();
}
bool is_string(const Value& v) {
  return v.kind() == Kind::kString;
}

ValuePtr isseqof_fn(Context& c, const Function&, Args a, Range at) {
  if (!a[1]->is_sequence()) return make_bool(false);
  for (const ValuePtr& x : a[1]->sequence())
    if (!c.truth(c.apply(a[0], x, at), "the predicate of ISSEQOF", at)) return make_bool(false);
  return make_bool(true);
}

constexpr Native kNatives[] = {
    {"AA", 2, aa_fn},
    {"ABS", 1, math_fn},
    {"ACOS", 1, math_fn},
    {"AL", 1, al_fn},
    {"AND", 1, and_fn},
    {"AR", 1, ar_fn},
    {"ASIN", 1, math_fn},
    {"ATAN", 1, math_fn},
    {"ATAN2", 1, atan2_fn},
    {"BUTLAST", 1, butlast_fn},
    {"C", 3, c_fn},
    {"CAT", 1, cat_fn},
    {"COMP", 2, comp_fn},
    {"CONS", 2, cons_fn},
    {"COS", 1, math_fn},
    {"DISTL", 1, distl_fn},
    {"DISTR", 1, distr_fn},
    {"EQ", 1, eq_fn},
    {"EXP", 1, math_fn},
    {"FIRST", 1, first_fn},
    {"FROMTO", 1, fromto_fn},
    {"GE", 2, compare_fn<3>},
    {"GT", 2, compare_fn<2>},
    {"ID", 1, id_fn},
    {"INSL", 2, insl_fn},
    {"INSR", 2, insr_fn},
    {"INTSTO", 1, intsto_fn},
    {"ISBOOL", 1, predicate_fn<is_bool>},
    {"ISFUN", 1, predicate_fn<is_fun>},
    {"ISINT", 1, predicate_fn<is_int>},
    {"ISINTPOS", 1, predicate_fn<is_intpos>},
    {"ISNAT", 1, predicate_fn<is_nat>},
    {"ISNUM", 1, predicate_fn<is_num>},
    {"ISPOL", 1, predicate_fn<is_pol>},
    {"ISREAL", 1, predicate_fn<is_num>},
    {"ISREALPOS", 1, predicate_fn<is_realpos>},
    {"ISSEQ", 1, predicate_fn<is_seq>},
    {"ISSEQOF", 2, isseqof_fn},
    {"ISSTRING", 1, predicate_fn<is_string>},
    {"K", 2, k_fn},
    {"LAST", 1, last_fn},
    {"LE", 2, compare_fn<1>},
    {"LEN", 1, len_fn},
    {"LIST", 1, list_fn},
    {"LN", 1, math_fn},
    {"LT", 2, compare_fn<0>},
    {"NOT", 1, not_fn},
    {"OR", 1, or_fn},
    {"REPEAT", 2, repeat_fn},
    {"REVERSE", 1, reverse_fn},
    {"S1", 1, s_fn<1>},
    {"S2", 1, s_fn<2>},
    {"S3", 1, s_fn<3>},
    {"S4", 1, s_fn<4>},
    {"S5", 1, s_fn<5>},
    {"S6", 1, s_fn<6>},
    {"S7", 1, s_fn<7>},
    {"S8", 1, s_fn<8>},
    {"S9", 1, s_fn<9>},
    {"SEL", 2, sel_fn},
    {"SIN", 1, math_fn},
    {"SQRT", 1, math_fn},
    {"TAIL", 1, tail_fn},
    {"TAN", 1, math_fn},
    {"TRANS", 1, trans_fn},
    {"TT", 1, predicate_fn<any_value>},
};

}  // namespace

std::span<const Native> natives() {
  return kNatives;
}

const Native* find_native(std::string_view key) {
  static const std::unordered_map<std::string_view, const Native*> index = [] {
    std::unordered_map<std::string_view, const Native*> m;
    for (const Native& n : kNatives) m.emplace(n.name, &n);
    for (const auto& table :
         {geometry_natives(), map_natives(), complex_natives(), boolean_natives(), place_natives()})
      for (const Native& n : table) m.emplace(n.name, &n);
    return m;
  }();
  const auto it = index.find(key);
  return it == index.end() ? nullptr : it->second;
}

ValuePtr find_constant(std::string_view key) {
  static const ValuePtr pi = make_number(std::numbers::pi);
  static const ValuePtr yes = make_bool(true);
  static const ValuePtr no = make_bool(false);
  if (key == "PI") return pi;
  if (key == "TRUE") return yes;
  if (key == "FALSE") return no;
  return nullptr;
}

ValuePtr fromto(Context& c, const ValuePtr& from, const ValuePtr& to, std::string_view who,
                Range at) {
  const double a = c.number(from, who, at);
  const double b = c.number(to, who, at);
  if (a != std::floor(a) || b != std::floor(b))
    c.fail("PSM402",
           text({"'", std::string(who), "' needs integers, found ", base::shortest_number(a),
                 " and ", base::shortest_number(b)}),
           at);
  const double count = b >= a ? b - a + 1 : 0;
  c.charge(count, at);
  Sequence items;
  items.reserve(static_cast<std::size_t>(count));
  // By index: at large magnitudes i + 1 == i, and a loop on the value would never end.
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k)
    items.push_back(make_number(a + static_cast<double>(k)));
  return c.sequence(std::move(items), at);
}

ValuePtr repeat(Context& c, const ValuePtr& n, const ValuePtr& x, bool cat, Range at) {
  const char* who = cat ? "##" : "#";
  const std::size_t count = natural(c, n, who, at);
  const Sequence* parts = cat ? &c.seq(x, who, at) : nullptr;
  const double total = static_cast<double>(count) * (cat ? static_cast<double>(parts->size()) : 1);
  c.charge(total, at);
  Sequence out;
  if (total == 0) return c.sequence(std::move(out), at);  // not count empty copies one by one
  out.reserve(static_cast<std::size_t>(total));
  for (std::size_t i = 0; i < count; ++i) {
    if (cat) {
      out.insert(out.end(), parts->begin(), parts->end());
    } else {
      out.push_back(x);
    }
  }
  return c.sequence(std::move(out), at);
}

}  // namespace insula::lang::plasm
