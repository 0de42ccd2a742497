#include "lang/cga/eval.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "lang/cga/colors.h"

namespace insula::lang::cga {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

bool is_number(const Value& v) {
  return std::holds_alternative<double>(v);
}
bool is_string(const Value& v) {
  return std::holds_alternative<std::string>(v);
}
const Array* array_of(const Value& v) {
  const ArrayPtr* a = std::get_if<ArrayPtr>(&v);
  return a != nullptr ? a->get() : nullptr;
}

[[noreturn]] void fail(Range range, std::string message) {
  throw EvalError{range, std::move(message)};
}

double finite_or_fail(double x, Range range, const char* what) {
  if (!std::isfinite(x)) fail(range, std::string(what) + " is not a finite number");
  return x;
}

Value compare(BinaryOp op, const Value& a, const Value& b, Range range) {
  int order = 0;
  if (is_number(a) && is_number(b)) {
    const double x = std::get<double>(a);
    const double y = std::get<double>(b);
    order = x < y ? -1 : (x > y ? 1 : 0);
  } else if (is_string(a) && is_string(b)) {
    order = std::get<std::string>(a).compare(std::get<std::string>(b));
    order = order < 0 ? -1 : (order > 0 ? 1 : 0);
  } else if (array_of(a) != nullptr && array_of(b) != nullptr) {
    if (op == BinaryOp::kEq || op == BinaryOp::kNe) {
      const bool same = equal(*array_of(a), *array_of(b));
      return op == BinaryOp::kEq ? same : !same;
    }
    if (array_of(a)->type == ElementType::kBool || array_of(b)->type == ElementType::kBool) {
      fail(range, "cannot order bool arrays");
    }
    order = compare(*array_of(a), *array_of(b));
  } else if (op == BinaryOp::kEq || op == BinaryOp::kNe) {
    // Different types are unequal; booleans compare by value.
    const bool equal = a == b;
    return op == BinaryOp::kEq ? equal : !equal;
  } else {
    fail(range,
         "cannot order a " + std::string(type_name(a)) + " and a " + std::string(type_name(b)));
  }
  switch (op) {
    case BinaryOp::kEq:
      return order == 0;
    case BinaryOp::kNe:
      return order != 0;
    case BinaryOp::kLt:
      return order < 0;
    case BinaryOp::kLe:
      return order <= 0;
    case BinaryOp::kGt:
      return order > 0;
    default:
      return order >= 0;
  }
}

double arithmetic(BinaryOp op, double x, double y, Range range) {
  switch (op) {
    case BinaryOp::kAdd:
      return x + y;
    case BinaryOp::kSub:
      return x - y;
    case BinaryOp::kMul:
      return x * y;
    case BinaryOp::kDiv:
      if (y == 0) fail(range, "division by zero");
      return x / y;
    default:
      if (y == 0) fail(range, "modulo by zero");
      return std::fmod(x, y);
  }
}

double number_arg(const std::vector<Value>& args, std::size_t i, Range range) {
  return as_number(args[i], range);
}

}  // namespace

std::string_view type_name(const Value& value) {
  if (const Array* a = array_of(value)) return array_type_name(a->type);
  if (std::holds_alternative<double>(value)) return "number";
  if (std::holds_alternative<std::string>(value)) return "string";
  if (std::holds_alternative<bool>(value)) return "bool";
  return "null";
}

double as_number(const Value& value, Range range) {
  if (const double* d = std::get_if<double>(&value)) return *d;
  if (const bool* b = std::get_if<bool>(&value)) return *b ? 1.0 : 0.0;
  fail(range, "expected a number, got a " + std::string(type_name(value)));
}

bool as_bool(const Value& value, Range range) {
  if (const bool* b = std::get_if<bool>(&value)) return *b;
  if (const double* d = std::get_if<double>(&value)) return *d != 0;
  fail(range, "expected a condition (bool), got a " + std::string(type_name(value)));
}

std::string as_text(const Value& value) {
  if (const Array* a = array_of(value)) return print_text(*a);
  return shape::to_string(to_shape(value));
}

Value apply_unary(UnaryOp op, const Value& v, Range range) {
  if (op == UnaryOp::kNot) return !as_bool(v, range);
  if (op == UnaryOp::kNegate) return -as_number(v, range);
  fail(range, "a relative ('r) or floating (~) size is only allowed as a split or scale size");
}

Value apply_binary(BinaryOp op, const Value& a, const Value& b, Range range) {
  switch (op) {
    case BinaryOp::kOr:
      return as_bool(a, range) || as_bool(b, range);
    case BinaryOp::kAnd:
      return as_bool(a, range) && as_bool(b, range);
    case BinaryOp::kEq:
    case BinaryOp::kNe:
    case BinaryOp::kLt:
    case BinaryOp::kLe:
    case BinaryOp::kGt:
    case BinaryOp::kGe:
      return compare(op, a, b, range);
    case BinaryOp::kAdd:
      if (is_string(a) || is_string(b)) return as_text(a) + as_text(b);
      [[fallthrough]];
    default:
      if (array_of(a) != nullptr || array_of(b) != nullptr) {
        fail(range, "arithmetic on a " + std::string(type_name(array_of(a) ? a : b)) +
                        " (CityEngine's element-wise operators are written .+ .- .* ./)");
      }
      return arithmetic(op, as_number(a, range), as_number(b, range), range);
  }
}

// CityEngine computes its math functions as IEEE floats: ln(0) is -inf, sqrt(-1) NaN, no
// error (isnan / isinf test them); seed 004 grammars keep the errors of apply_function.
std::optional<double> ieee_math(Function f, const std::vector<Value>& args) {
  if (args.empty() || !std::holds_alternative<double>(args[0])) return std::nullopt;
  const double x = std::get<double>(args[0]);
  switch (f) {
    case Function::kSqrt:
      return std::sqrt(x);
    case Function::kLn:
      return std::log(x);
    case Function::kLog10:
      return std::log10(x);
    case Function::kExp:
      return std::exp(x);
    case Function::kTan:
      return std::tan(x * kDeg);
    case Function::kPow:
      if (args.size() != 2 || !std::holds_alternative<double>(args[1])) return std::nullopt;
      return std::pow(x, std::get<double>(args[1]));
    default:
      return std::nullopt;
  }
}

bool is_random(Function f) {
  return f == Function::kRand || f == Function::kP || f == Function::kListRandom ||
         f == Function::kPrint || f == Function::kGetGeoCoord || f == Function::kUvExtent ||
         f == Function::kStartRule || is_file_function(f);
}

bool is_file_function(Function f) {
  return f == Function::kFileExists || f == Function::kFileSearch || f == Function::kFileRandom ||
         f == Function::kAssetInfo || f == Function::kImageInfo || f == Function::kImageBestRatio ||
         f == Function::kImagesSortRatio || f == Function::kReadStringTable ||
         f == Function::kReadFloatTable || f == Function::kAssetsSortSize ||
         f == Function::kAssetsSortRatio || f == Function::kAssetBestSize ||
         f == Function::kAssetBestRatio || f == Function::kAssetApproxSize ||
         f == Function::kAssetApproxRatio || f == Function::kAssetFitSize;
}

namespace {

// A CityEngine string list: items each ended by ';' (a last item without ';' counts too).
std::vector<std::string> list_items(const std::string& list) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (begin < list.size()) {
    std::size_t end = list.find(';', begin);
    if (end == std::string::npos) end = list.size();
    items.push_back(list.substr(begin, end - begin));
    begin = end + 1;
  }
  return items;
}

std::string list_of(const std::vector<std::string>& items, std::size_t begin, std::size_t end) {
  std::string out;
  for (std::size_t i = begin; i < end && i < items.size(); ++i) out.append(items[i]).append(";");
  return out;
}

std::size_t occurrences(const std::string& s, const std::string& match) {
  if (match.empty()) return 0;
  std::size_t n = 0;
  for (std::size_t at = s.find(match); at != std::string::npos;
       at = s.find(match, at + match.size())) {
    ++n;
  }
  return n;
}

// A count or index argument: a whole number, clamped to [0, size].
std::size_t index_arg(double x, std::size_t size) {
  if (!(x > 0)) return 0;
  return std::min(size, static_cast<std::size_t>(std::floor(x)));
}

// A part of a file path as CityEngine's utility functions split it ('/' and '\\' both separate).
std::string path_part(Function f, const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t name_at = slash == std::string::npos ? 0 : slash + 1;
  const std::string name = path.substr(name_at);
  const std::size_t dot = name.rfind('.');
  switch (f) {
    case Function::kFileDirectory:
      return path.substr(0, name_at);
    case Function::kFileBasename:
      return dot == std::string::npos ? name : name.substr(0, dot);
    case Function::kFileExtension:
      return dot == std::string::npos ? std::string() : name.substr(dot);
    default:
      return name;
  }
}

Value string_function(Function f, const std::vector<Value>& args, Range range) {
  const auto text = [&](std::size_t i) { return as_text(args[i]); };
  const auto x = [&](std::size_t i) { return number_arg(args, i, range); };
  switch (f) {
    case Function::kFind: {
      const std::string s = text(0);
      const std::string match = text(1);
      const std::size_t nth = args.size() > 2 ? index_arg(x(2), s.size()) : 0;
      std::size_t at = s.find(match);
      for (std::size_t k = 0; k < nth && at != std::string::npos; ++k) at = s.find(match, at + 1);
      return at == std::string::npos ? -1.0 : static_cast<double>(at);
    }
    case Function::kSubstring: {
      const std::string s = text(0);
      const std::size_t begin = index_arg(x(1), s.size());
      const std::size_t end = index_arg(x(2), s.size());
      return end > begin ? s.substr(begin, end - begin) : std::string();
    }
    case Function::kCount:
      return static_cast<double>(occurrences(text(0), text(1)));
    case Function::kReplace: {
      std::string s = text(0);
      const std::string from = text(1);
      const std::string to = text(2);
      if (from.empty()) return s;
      for (std::size_t at = s.find(from); at != std::string::npos;
           at = s.find(from, at + to.size())) {
        s.replace(at, from.size(), to);
      }
      return s;
    }
    case Function::kGetPrefix: {
      const std::string s = text(0);
      const std::size_t at = s.find(text(1));
      return at == std::string::npos ? s : s.substr(0, at);
    }
    case Function::kGetSuffix: {
      const std::string s = text(0);
      const std::string match = text(1);
      const std::size_t at = match.empty() ? std::string::npos : s.rfind(match);
      return at == std::string::npos ? s : s.substr(at + match.size());
    }
    case Function::kFileName:
    case Function::kFileBasename:
    case Function::kFileDirectory:
    case Function::kFileExtension:
      return path_part(f, text(0));
    case Function::kListTerminate: {
      std::string list = text(0);
      if (!list.empty() && list.back() != ';') list += ';';
      return list;
    }
    case Function::kGetRange: {  // CityEngine's utility library: getRange("a_f3_t2", "f", "_t")
      const std::string s = text(0);
      const std::string start = text(1);
      const std::size_t at = s.find(start);
      if (at == std::string::npos) return std::string();
      const std::size_t begin = at + start.size();
      const std::size_t end = s.find(text(2), begin);
      return s.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    }
    default:
      break;
  }
  const std::vector<std::string> items = list_items(text(0));
  switch (f) {
    case Function::kListSize:
      return static_cast<double>(items.size());
    case Function::kListItem: {
      const double i = x(1);
      if (!(i >= 0) || i >= static_cast<double>(items.size())) return std::string();
      return items[static_cast<std::size_t>(i)];
    }
    case Function::kListFirst:
      return items.empty() ? std::string() : items.front();
    case Function::kListLast:
      return items.empty() ? std::string() : items.back();
    case Function::kListRange:
      return list_of(items, index_arg(x(1), items.size()), index_arg(x(2), items.size()));
    case Function::kListIndex: {
      const auto it = std::find(items.begin(), items.end(), text(1));
      return it == items.end() ? -1.0 : static_cast<double>(it - items.begin());
    }
    case Function::kListCount:
      return static_cast<double>(std::count(items.begin(), items.end(), text(1)));
    case Function::kListAdd:
      return list_of(items, 0, items.size()) + text(1) + ";";
    case Function::kListRemove: {
      std::vector<std::string> kept = items;
      std::erase(kept, text(1));
      return list_of(kept, 0, kept.size());
    }
    default:
      fail(range, "internal: not a string function");
  }
}

}  // namespace

Value apply_function(Function f, const std::vector<Value>& args, Range range) {
  const auto x = [&](std::size_t i) { return number_arg(args, i, range); };
  switch (f) {
    case Function::kRint:
      return std::nearbyint(x(0));
    case Function::kRound:
      return std::round(x(0));
    case Function::kFloor:
      return std::floor(x(0));
    case Function::kCeil:
      return std::ceil(x(0));
    case Function::kAbs:
      return std::fabs(x(0));
    case Function::kMin:
    case Function::kMax: {
      double r = x(0);
      for (std::size_t i = 1; i < args.size(); ++i) {
        r = f == Function::kMin ? std::min(r, x(i)) : std::max(r, x(i));
      }
      return r;
    }
    case Function::kClamp:
      return std::clamp(x(0), std::min(x(1), x(2)), std::max(x(1), x(2)));
    case Function::kSqrt:
      if (x(0) < 0) fail(range, "sqrt of a negative number");
      return std::sqrt(x(0));
    case Function::kPow:
      return finite_or_fail(std::pow(x(0), x(1)), range, "pow");
    case Function::kExp:
      return finite_or_fail(std::exp(x(0)), range, "exp");
    case Function::kLn:
      if (!(x(0) > 0)) fail(range, "ln of a number <= 0");
      return std::log(x(0));
    case Function::kSin:
      return std::sin(x(0) * kDeg);
    case Function::kCos:
      return std::cos(x(0) * kDeg);
    case Function::kTan:
      return finite_or_fail(std::tan(x(0) * kDeg), range, "tan");
    case Function::kAsin:
      return std::asin(std::clamp(x(0), -1.0, 1.0)) / kDeg;
    case Function::kAcos:
      return std::acos(std::clamp(x(0), -1.0, 1.0)) / kDeg;
    case Function::kAtan:
      return std::atan(x(0)) / kDeg;
    case Function::kAtan2:
      return std::atan2(x(0), x(1)) / kDeg;
    case Function::kFloat:
      if (const std::string* s = std::get_if<std::string>(&args[0])) {
        char* end = nullptr;
        const double d = std::strtod(s->c_str(), &end);
        // A text that is no number is NaN, as CityEngine's float() gives (isnan tests it).
        if (s->empty() || end != s->c_str() + s->size()) return std::nan("");
        return d;
      }
      return x(0);
    case Function::kStr:
      return as_text(args[0]);
    case Function::kBool:
      if (const std::string* s = std::get_if<std::string>(&args[0])) return !s->empty();
      return as_bool(args[0], range);
    case Function::kFindFirst:
    case Function::kFindLast:
      if (is_string(args[0])) {  // the utility library's string forms
        const std::string text = as_text(args[0]);
        const std::string match = as_text(args[1]);
        const std::size_t at = f == Function::kFindFirst ? text.find(match) : text.rfind(match);
        return at == std::string::npos ? -1.0 : static_cast<double>(at);
      }
      return array_function(f, args, range);
    case Function::kLen:
      if (!is_string(args[0])) fail(range, "len() expects a string");
      return static_cast<double>(std::get<std::string>(args[0]).size());
    case Function::kLog10:
      if (!(x(0) > 0)) fail(range, "log10 of a number <= 0");
      return std::log10(x(0));
    case Function::kIsNan:
      return std::isnan(x(0));
    case Function::kIsInf:
      return std::isinf(x(0));
    case Function::kFind:
    case Function::kSubstring:
    case Function::kCount:
    case Function::kReplace:
    case Function::kGetPrefix:
    case Function::kGetSuffix:
    case Function::kGetRange:
    case Function::kListTerminate:
    case Function::kFileName:
    case Function::kFileBasename:
    case Function::kFileDirectory:
    case Function::kFileExtension:
    case Function::kListSize:
    case Function::kListItem:
    case Function::kListFirst:
    case Function::kListLast:
    case Function::kListRange:
    case Function::kListIndex:
    case Function::kListCount:
    case Function::kListAdd:
    case Function::kListRemove:
      return string_function(f, args, range);
    case Function::kColorRGBToHex:
      return hex_color(x(0), x(1), x(2), 1, false);
    case Function::kColorHSVToHex: {
      const auto [r, g, b] = rgb_of_hsv(x(0), x(1), x(2));
      return hex_color(r, g, b, 1, false);
    }
    case Function::kColorRamp: {
      const std::optional<std::string> hex = color_ramp(as_text(args[0]), x(1));
      if (!hex) {
        fail(range, "unknown colour ramp '" + as_text(args[0]) +
                        "' (whiteToBlack, greenToRed, yellowToRed, redToBlue, orangeToBlue, "
                        "brownToBlue, spectrum)");
      }
      return *hex;
    }
    case Function::kColorHexToR:
    case Function::kColorHexToG:
    case Function::kColorHexToB:
    case Function::kColorHexToO:
    case Function::kColorHexToH:
    case Function::kColorHexToS:
    case Function::kColorHexToV: {
      // A shape no colour was set on is white (material.color.r reads it so).
      const bool unset = std::holds_alternative<std::monostate>(args[0]);
      const auto rgba = rgba_of_hex(unset ? std::string("#ffffff") : as_text(args[0]));
      if (!rgba) fail(range, "'" + as_text(args[0]) + "' is not a colour (\"#rrggbb\")");
      const auto& c = *rgba;
      const auto hsv = hsv_of_rgb(c[0], c[1], c[2]);
      switch (f) {
        case Function::kColorHexToR:
          return c[0];
        case Function::kColorHexToG:
          return c[1];
        case Function::kColorHexToB:
          return c[2];
        case Function::kColorHexToO:
          return c[3];
        case Function::kColorHexToH:
          return hsv[0];
        case Function::kColorHexToS:
          return hsv[1];
        default:
          return hsv[2];
      }
    }
    default:
      if (is_array_function(f)) return array_function(f, args, range);
      fail(range, "internal: random function evaluated without a generator");
  }
}

namespace {

// A function of the grammar, evaluated in the caller's shape with its own arguments.
Value call(const Program& program, const ENode& n, EvalContext& context) {
  const CFunction& fn = program.functions[n.a];
  std::vector<Value> args;
  args.reserve(n.kids.size());
  for (std::uint32_t k : n.kids) args.push_back(evaluate(program, k, context));
  if (context.call_depth >= kMaxCallDepth) {
    fail(n.range, "function '" + fn.name + "' nested " + std::to_string(kMaxCallDepth) +
                      " calls deep (a function that calls itself without end?)");
  }
  const std::span<const Value> saved = context.frame;
  context.frame = args;
  ++context.call_depth;
  try {
    Value result = evaluate(program, fn.body, context);
    --context.call_depth;
    context.frame = saved;
    return result;
  } catch (...) {
    --context.call_depth;
    context.frame = saved;
    throw;
  }
}

// A literal's rows (op 1: each kid a row node) or its one row (op 0).
Value array_node(const Program& program, const ENode& n, EvalContext& context) {
  std::vector<std::vector<Value>> groups;
  const auto row = [&](const ENode& r) {
    std::vector<Value> values;
    values.reserve(r.kids.size());
    for (std::uint32_t k : r.kids) values.push_back(evaluate(program, k, context));
    groups.push_back(std::move(values));
  };
  if (n.op == 0) {
    row(n);
  } else {
    for (std::uint32_t k : n.kids) row(program.nodes[k]);
  }
  return array_literal(groups, n.range);
}

}  // namespace

Value evaluate(const Program& program, std::uint32_t expr, EvalContext& context) {
  const ENode& n = program.nodes[expr];
  switch (n.code) {
    case ECode::kConst:
      return program.consts[n.a];
    case ECode::kAttr: {
      Value v = context.attribute(n.a, n.range);
      if (n.op == 1 && std::holds_alternative<std::monostate>(v)) return std::string();
      return v;
    }
    case ECode::kShapeAttr:
      return context.shape_attribute(static_cast<ShapeAttr>(n.a));
    case ECode::kOcc:
      return context.occlusion(as_text(evaluate(program, n.kids[0], context)), n.range);
    case ECode::kUnary:
      return apply_unary(static_cast<UnaryOp>(n.op), evaluate(program, n.kids[0], context),
                         n.range);
    case ECode::kBinary: {
      const auto op = static_cast<BinaryOp>(n.op);
      const Value a = evaluate(program, n.kids[0], context);
      if (n.a != 0) return apply_elementwise(op, a, evaluate(program, n.kids[1], context), n.range);
      // and / or short-circuit (a condition guarding a division stays safe).
      if (op == BinaryOp::kAnd && !as_bool(a, n.range)) return false;
      if (op == BinaryOp::kOr && as_bool(a, n.range)) return true;
      const Value b = evaluate(program, n.kids[1], context);
      // CityEngine divides as IEEE floats: x / 0 is an infinity and 0 / 0 NaN, no error (the
      // operations that take them then say so); seed 004 grammars keep the error.
      if (program.cityengine && op == BinaryOp::kDiv && std::holds_alternative<double>(a) &&
          std::holds_alternative<double>(b) && std::get<double>(b) == 0) {
        return std::get<double>(a) / std::get<double>(b);
      }
      return apply_binary(op, a, b, n.range);
    }
    case ECode::kFunction: {
      const auto f = static_cast<Function>(n.a);
      std::vector<Value> args;
      args.reserve(n.kids.size());
      for (std::uint32_t k : n.kids) args.push_back(evaluate(program, k, context));
      if (f == Function::kRand) {
        const double lo = args.size() == 2 ? as_number(args[0], n.range) : 0.0;
        const double hi = args.empty()       ? 1.0
                          : args.size() == 1 ? as_number(args[0], n.range)
                                             : as_number(args[1], n.range);
        return context.rng().uniform(lo, hi);
      }
      if (f == Function::kP) return context.rng().unit() < as_number(args[0], n.range);
      if (is_file_function(f)) return context.file_function(f, args, n.range);
      if (f == Function::kGetGeoCoord) return context.geo_coord(as_text(args[0]), n.range);
      if (f == Function::kStartRule) return std::string(program.symbol_name(program.start));
      if (f == Function::kUvExtent) {
        // uv sets 0..9, as the texturing operations' (checked before the cast: NaN or a huge
        // value would make it undefined).
        const double set = as_number(args[0], n.range);
        if (!(set >= 0 && set <= 9) || set != std::floor(set)) {
          fail(n.range, "a uv set is a whole number 0..9, got " +
                            (std::isnan(set) ? std::string("NaN") : as_text(args[0])));
        }
        return context.uv_extent(n.op, static_cast<int>(set), as_bool(args[1], n.range));
      }
      if (f == Function::kPrint) {
        context.print(n.range, as_text(args[0]));
        return args[0];
      }
      if (f == Function::kListRandom) {
        const std::vector<std::string> items = list_items(as_text(args[0]));
        if (items.empty()) return std::string();
        return items[std::min(
            items.size() - 1,
            static_cast<std::size_t>(context.rng().unit() * static_cast<double>(items.size())))];
      }
      if (program.cityengine) {
        if (const std::optional<double> v = ieee_math(f, args)) return *v;
      }
      return apply_function(f, args, n.range);
    }
    case ECode::kCompSel:
      return context.comp_selector();
    case ECode::kConvert: {
      kernel::Vec3 v;
      if (n.kids.size() == 3) {
        v = {as_number(evaluate(program, n.kids[0], context), n.range),
             as_number(evaluate(program, n.kids[1], context), n.range),
             as_number(evaluate(program, n.kids[2], context), n.range)};
      } else {
        const Value coordinates = evaluate(program, n.kids[0], context);
        const auto* array = std::get_if<ArrayPtr>(&coordinates);
        if (array == nullptr || (*array)->type != ElementType::kFloat ||
            (*array)->items.size() != 3) {
          fail(n.range, "convert() takes a float[] of 3 coordinates");
        }
        v = {std::get<double>((*array)->items[0]), std::get<double>((*array)->items[1]),
             std::get<double>((*array)->items[2])};
      }
      const kernel::Vec3 r =
          context.convert(static_cast<shape::Frame>(n.a & 3),
                          static_cast<shape::Frame>(n.a >> 2 & 3), (n.a >> 4 & 1) != 0, v);
      if (n.op == 3) return make_row(ElementType::kFloat, {r.x, r.y, r.z});
      return n.op == 0 ? r.x : n.op == 1 ? r.y : r.z;
    }
    case ECode::kOcclusion: {
      const auto relation = static_cast<OcclusionRelation>(n.op);
      auto target = static_cast<OcclusionTarget>(n.a);
      const bool computed = target == OcclusionTarget::kComputed;
      if (computed) {  // sel(expr): "intra", "inter" or "all"
        const std::string word = as_text(evaluate(program, n.kids.back(), context));
        if (word != "intra" && word != "inter" && word != "all") {
          fail(n.range,
               "the target of an occlusion query is intra, inter or all, got '" + word + "'");
        }
        target = word == "intra"   ? OcclusionTarget::kIntra
                 : word == "inter" ? OcclusionTarget::kInter
                                   : OcclusionTarget::kAll;
      }
      const std::size_t labels = n.kids.size() - (computed ? 1 : 0);
      const std::string label =
          labels == 0 ? std::string() : as_text(evaluate(program, n.kids[0], context));
      if (relation == OcclusionRelation::kMinimumDistance) {
        return context.minimum_distance(target, label);
      }
      return context.occlusion_query(relation, target, label);
    }
    case ECode::kGeometry: {
      const double tolerance =
          n.kids.empty() ? 0 : as_number(evaluate(program, n.kids[0], context), n.range);
      const auto query = static_cast<shape::GeometryQuery>(n.a);
      const double value = context.geometry(query, n.op, tolerance);
      if (shape::is_test(query)) return value != 0;
      return value;
    }
    case ECode::kParam:
      if (n.a >= context.frame.size()) fail(n.range, "internal: parameter outside its rule");
      return context.frame[n.a];
    case ECode::kCall:
      return call(program, n, context);
    case ECode::kCase: {
      const std::size_t last = n.kids.size() - 1;
      for (std::size_t i = 0; i < last; i += 2) {
        const ENode& condition = program.nodes[n.kids[i]];
        if (as_bool(evaluate(program, n.kids[i], context), condition.range)) {
          return evaluate(program, n.kids[i + 1], context);
        }
      }
      return evaluate(program, n.kids[last], context);
    }
    case ECode::kArray:
      return array_node(program, n, context);
    case ECode::kIndex: {
      const Value array = evaluate(program, n.kids[0], context);
      std::vector<Value> indices;
      for (std::size_t k = 1; k < n.kids.size(); ++k) {
        indices.push_back(evaluate(program, n.kids[k], context));
      }
      std::string warning;
      Value v = index_array(array, indices, n.range, warning);
      if (!warning.empty()) context.warning(n.range, std::move(warning));
      return v;
    }
    case ECode::kCompFunc:
      return context.comp_function(n.a, n.range);
    case ECode::kChance: {
      const std::size_t last = n.kids.size() - 1;
      double draw = context.rng().unit() * 100.0;
      for (std::size_t i = 0; i < last; i += 2) {
        const double percent = as_number(evaluate(program, n.kids[i], context), n.range);
        if (draw < percent) return evaluate(program, n.kids[i + 1], context);
        draw -= percent;
      }
      return evaluate(program, n.kids[last], context);
    }
  }
  return Value{};
}

}  // namespace insula::lang::cga
