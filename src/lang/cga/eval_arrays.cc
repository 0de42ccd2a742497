// CityEngine's arrays (CGA 2019.0 and later; docs/cga-cityengine.md, "Arrays"): literals,
// the index operator and the array functions. Their semantics follow CityEngine's reference
// pages arrayTypes, func_array, func_index, func_size, func_nRows, func_nColumns,
// func_findFirst, func_sortIndices, func_transpose, func_floatArray (and bool/string),
// func_readTable and the utility library's listToArray / listFromArray.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>

#include "lang/cga/eval.h"

namespace insula::lang::cga {

namespace {

// Arrays larger than this are an error (CityEngine's default limit, "Procedural Runtime
// preferences": 100000 elements).
constexpr std::size_t kMaxElements = 100000;

[[noreturn]] void fail(Range range, std::string message) {
  throw EvalError{range, std::move(message)};
}

const Array& array_arg(const std::vector<Value>& args, std::size_t i, const char* function,
                       Range range) {
  const ArrayPtr* a = std::get_if<ArrayPtr>(&args[i]);
  if (a == nullptr) {
    fail(range,
         std::string(function) + "() expects an array, got a " + std::string(type_name(args[i])));
  }
  return **a;
}

// A block of a literal's row: `rows` x `columns` elements.
struct Block {
  std::size_t rows = 1;
  std::size_t columns = 1;
  const std::vector<shape::Value>* items = nullptr;  // null: the scalar `scalar`
  shape::Value scalar;
};

std::string element_name(ElementType type) {
  const std::string_view name = array_type_name(type);
  return std::string(name.substr(0, name.size() - 2));  // "float[]" -> "float"
}

void check_type(std::optional<ElementType>& type, ElementType next, Range range) {
  if (type && *type != next) {
    fail(range, "array elements must all be of one type, found " + element_name(*type) + " and " +
                    element_name(next));
  }
  type = next;
}

// One `;`-row of a literal: blocks side by side, all as tall as the first non-empty one.
std::vector<Block> row_blocks(const std::vector<Value>& values, std::optional<ElementType>& type,
                              Range range) {
  std::vector<Block> blocks;
  for (const Value& v : values) {
    Block b;
    if (const ArrayPtr* a = std::get_if<ArrayPtr>(&v)) {
      check_type(type, (*a)->type, range);
      if ((*a)->items.empty()) continue;  // an empty array adds nothing
      b.rows = (*a)->rows;
      b.columns = (*a)->columns;
      b.items = &(*a)->items;
    } else {
      b.scalar = to_shape(v);
      const ElementType* t = element_type_of(b.scalar);
      if (t == nullptr) fail(range, "an array element is null");
      check_type(type, *t, range);
    }
    if (!blocks.empty() && blocks.front().rows != b.rows) {
      fail(range, "the parts of an array row have " + std::to_string(blocks.front().rows) +
                      " and " + std::to_string(b.rows) + " rows");
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

// A non-negative whole index below `count`, or nullopt (negative, too large, not a number).
std::optional<std::size_t> position(double x, std::size_t count) {
  if (!(x >= 0) || !(x < static_cast<double>(count))) return std::nullopt;
  return static_cast<std::size_t>(std::floor(x));
}

Value converted(const Array& a, ElementType to) {
  std::vector<shape::Value> items;
  items.reserve(a.items.size());
  for (const shape::Value& v : a.items) {
    if (to == ElementType::kString) {
      items.push_back(shape::to_string(v));
    } else if (const std::string* s = std::get_if<std::string>(&v)) {
      // CityEngine reads the leading number ("5+6" is 5) and NaN when there is none.
      char* end = nullptr;
      const double d = std::strtod(s->c_str(), &end);
      if (to == ElementType::kFloat) {
        items.push_back(end == s->c_str() ? std::nan("") : d);
      } else {
        const bool no = *s == "false" || *s == "f" || (end != s->c_str() && d == 0);
        items.push_back(!no);
      }
    } else if (const bool* b = std::get_if<bool>(&v)) {
      if (to == ElementType::kFloat) {
        items.emplace_back(*b ? 1.0 : 0.0);
      } else {
        items.emplace_back(*b);
      }
    } else if (to == ElementType::kFloat) {
      items.emplace_back(std::get<double>(v));
    } else {
      items.emplace_back(std::get<double>(v) != 0);
    }
  }
  return make_array(to, a.rows, a.columns, std::move(items));
}

Value find(const Array& a, const std::vector<Value>& args, bool first, Range range) {
  const shape::Value target = to_shape(args[1]);
  const double epsilon = args.size() > 2 ? as_number(args[2], range) : 0.0;
  const auto matches = [&](const shape::Value& v) {
    const double* x = std::get_if<double>(&v);
    const double* y = std::get_if<double>(&target);
    if (x != nullptr && y != nullptr) return std::fabs(*x - *y) <= epsilon;
    return v == target;
  };
  const std::size_t n = a.items.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = first ? k : n - 1 - k;
    if (matches(a.items[i])) return static_cast<double>(i);
  }
  return -1.0;
}

// Per row, the linear indices of its elements in ascending order (stable).
Value sort_indices(const Array& a, Range range) {
  if (a.type == ElementType::kBool) fail(range, "sortIndices() expects a float[] or string[]");
  std::vector<shape::Value> out;
  out.reserve(a.items.size());
  for (std::size_t r = 0; r < a.rows; ++r) {
    std::vector<std::size_t> order(a.columns);
    std::iota(order.begin(), order.end(), r * a.columns);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      return element_less(a.items[i], a.items[j]);
    });
    for (std::size_t i : order) out.emplace_back(static_cast<double>(i));
  }
  return make_array(ElementType::kFloat, a.rows, a.columns, std::move(out));
}

Value transposed(const Array& a) {
  std::vector<shape::Value> out;
  out.reserve(a.items.size());
  for (std::size_t c = 0; c < a.columns; ++c) {
    for (std::size_t r = 0; r < a.rows; ++r) out.push_back(a.items[r * a.columns + c]);
  }
  return make_array(a.type, a.columns, a.rows, std::move(out));
}

Value strings_of(const std::vector<std::string>& items) {
  std::vector<shape::Value> out(items.begin(), items.end());
  return make_row(ElementType::kString, std::move(out));
}

// The positions an index names: a number, or an array of numbers (row by row) or of booleans
// (the positions that are true). `shape` gets the dimensions of a numeric index array.
std::vector<double> positions(const Value& index, Range range, std::size_t& rows,
                              std::size_t& columns) {
  rows = columns = 1;
  const ArrayPtr* p = std::get_if<ArrayPtr>(&index);
  if (p == nullptr) return {as_number(index, range)};
  const Array& a = **p;
  std::vector<double> out;
  if (a.type == ElementType::kBool) {
    for (std::size_t i = 0; i < a.items.size(); ++i) {
      if (std::get<bool>(a.items[i])) out.push_back(static_cast<double>(i));
    }
    columns = out.size();
    return out;
  }
  if (a.type != ElementType::kFloat) fail(range, "an index array must be a float[] or bool[]");
  for (const shape::Value& v : a.items) out.push_back(std::get<double>(v));
  rows = a.rows;
  columns = a.columns;
  return out;
}

template <typename Element>
Value index_by_arrays(const Array& a, std::span<const Value> indices, Range range,
                      Element&& element) {
  std::vector<shape::Value> items;
  std::size_t rows = 1;
  std::size_t columns = 1;
  if (indices.size() == 1) {  // linear; the result has the index array's shape
    for (double i : positions(indices[0], range, rows, columns)) {
      items.push_back(
          element(position(i, a.items.size()), "index " + shape::to_string(shape::Value(i)) +
                                                   " is outside the array's " +
                                                   std::to_string(a.items.size()) + " elements"));
    }
  } else {  // rows x columns of the picked rows and columns
    std::size_t r1 = 0, c1 = 0, r2 = 0, c2 = 0;
    const std::vector<double> picked_rows = positions(indices[0], range, r1, c1);
    const std::vector<double> picked_columns = positions(indices[1], range, r2, c2);
    for (double r : picked_rows) {
      for (double c : picked_columns) {
        const std::optional<std::size_t> row = position(r, a.rows);
        const std::optional<std::size_t> column = position(c, a.columns);
        items.push_back(
            element(row && column ? std::optional(*row * a.columns + *column) : std::nullopt,
                    "index [" + shape::to_string(shape::Value(r)) + ", " +
                        shape::to_string(shape::Value(c)) + "] is outside the array's " +
                        std::to_string(a.rows) + " x " + std::to_string(a.columns) + " elements"));
      }
    }
    rows = picked_rows.size();
    columns = picked_columns.size();
  }
  return make_array(a.type, rows, columns, std::move(items));
}

}  // namespace

Value apply_elementwise(BinaryOp op, const Value& a, const Value& b, Range range) {
  const ArrayPtr* xp = std::get_if<ArrayPtr>(&a);
  const ArrayPtr* yp = std::get_if<ArrayPtr>(&b);
  const Array* x = xp != nullptr ? xp->get() : nullptr;
  const Array* y = yp != nullptr ? yp->get() : nullptr;
  if (x == nullptr && y == nullptr) return apply_binary(op, a, b, range);
  if (x != nullptr && y != nullptr && (x->rows != y->rows || x->columns != y->columns)) {
    fail(range, "element-wise operands of " + std::to_string(x->rows) + " x " +
                    std::to_string(x->columns) + " and " + std::to_string(y->rows) + " x " +
                    std::to_string(y->columns) + " elements");
  }
  const Array& like = x != nullptr ? *x : *y;
  std::optional<ElementType> type;
  std::vector<shape::Value> items;
  items.reserve(like.items.size());
  for (std::size_t i = 0; i < like.items.size(); ++i) {
    const Value left = x != nullptr ? from_shape(x->items[i]) : a;
    const Value right = y != nullptr ? from_shape(y->items[i]) : b;
    shape::Value result = to_shape(apply_binary(op, left, right, range));
    const ElementType* t = element_type_of(result);
    if (t == nullptr) fail(range, "an element-wise result is not a float, bool or string");
    check_type(type, *t, range);
    items.push_back(std::move(result));
  }
  // An empty array keeps its kind: comparisons and logic give bools, the rest the operand's.
  const bool logical = op != BinaryOp::kAdd && op != BinaryOp::kSub && op != BinaryOp::kMul &&
                       op != BinaryOp::kDiv && op != BinaryOp::kMod;
  return make_array(type.value_or(logical ? ElementType::kBool : like.type), like.rows,
                    like.columns, std::move(items));
}

Value array_literal(const std::vector<std::vector<Value>>& groups, Range range) {
  std::optional<ElementType> type;
  std::vector<shape::Value> items;
  std::size_t rows = 0;
  std::size_t columns = 0;
  for (const std::vector<Value>& group : groups) {
    const std::vector<Block> blocks = row_blocks(group, type, range);
    if (blocks.empty()) continue;
    std::size_t width = 0;
    for (const Block& b : blocks) width += b.columns;
    if (rows > 0 && width != columns) {
      fail(range, "array rows of " + std::to_string(columns) + " and " + std::to_string(width) +
                      " columns");
    }
    columns = width;
    for (std::size_t r = 0; r < blocks.front().rows; ++r) {
      for (const Block& b : blocks) {
        if (b.items == nullptr) {
          items.push_back(b.scalar);
          continue;
        }
        const auto begin = b.items->begin() + static_cast<std::ptrdiff_t>(r * b.columns);
        items.insert(items.end(), begin, begin + static_cast<std::ptrdiff_t>(b.columns));
      }
    }
    rows += blocks.front().rows;
    if (items.size() > kMaxElements) {
      fail(range, "an array of more than " + std::to_string(kMaxElements) + " elements");
    }
  }
  if (!type) {
    fail(range,
         "an array needs at least one element (floatArray(), boolArray() and "
         "stringArray() make empty ones)");
  }
  return make_array(*type, rows, columns, std::move(items));
}

Value index_array(const Value& array, std::span<const Value> indices, Range range,
                  std::string& warning) {
  const ArrayPtr* p = std::get_if<ArrayPtr>(&array);
  if (p == nullptr) fail(range, "cannot index a " + std::string(type_name(array)));
  const Array& a = **p;
  const shape::Value fallback = default_element(a.type);
  std::string outside;  // the first index outside the array
  const auto element = [&](std::optional<std::size_t> at, const std::string& where) {
    if (at) return a.items[*at];
    if (outside.empty()) outside = where;
    return fallback;
  };
  const bool by_arrays = std::any_of(indices.begin(), indices.end(), [](const Value& i) {
    return std::holds_alternative<ArrayPtr>(i);
  });
  Value out;
  if (!by_arrays && indices.size() == 1) {
    const double i = as_number(indices[0], range);
    out = from_shape(
        element(position(i, a.items.size()), "index " + as_text(i) + " is outside the array's " +
                                                 std::to_string(a.items.size()) + " elements"));
  } else if (!by_arrays) {
    const double r = as_number(indices[0], range);
    const double c = as_number(indices[1], range);
    const std::optional<std::size_t> row = position(r, a.rows);
    const std::optional<std::size_t> column = position(c, a.columns);
    out = from_shape(
        element(row && column ? std::optional(*row * a.columns + *column) : std::nullopt,
                "index [" + as_text(r) + ", " + as_text(c) + "] is outside the array's " +
                    std::to_string(a.rows) + " x " + std::to_string(a.columns) + " elements"));
  } else {
    out = index_by_arrays(a, indices, range, element);
  }
  if (!outside.empty()) {
    warning = outside + "; the value is " +
              (std::holds_alternative<std::string>(fallback) ? std::string("\"\"")
                                                             : shape::to_string(fallback)) +
              " (CityEngine's default)";
  }
  return out;
}

bool is_array_function(Function f) {
  switch (f) {
    case Function::kSize:
    case Function::kNRows:
    case Function::kNColumns:
    case Function::kFindFirst:
    case Function::kFindLast:
    case Function::kSortIndices:
    case Function::kTranspose:
    case Function::kFloatArray:
    case Function::kBoolArray:
    case Function::kStringArray:
    case Function::kListToArray:
    case Function::kListFromArray:
    case Function::kRange:
      return true;
    default:
      return false;
  }
}

Value array_function(Function f, const std::vector<Value>& args, Range range) {
  switch (f) {
    case Function::kFloatArray:
    case Function::kBoolArray:
    case Function::kStringArray: {
      const ElementType to = f == Function::kFloatArray  ? ElementType::kFloat
                             : f == Function::kBoolArray ? ElementType::kBool
                                                         : ElementType::kString;
      if (args.empty()) return make_array(to, 0, 0, {});
      return converted(array_arg(args, 0, "floatArray", range), to);
    }
    case Function::kRange: {
      const double base = as_number(args.front(), range);
      const double step = args.size() == 3 ? as_number(args[1], range) : 1.0;
      const double limit = as_number(args.back(), range);
      std::vector<shape::Value> items;
      if (!std::isfinite(base) || !std::isfinite(step) || !std::isfinite(limit)) {
        fail(range, "the colon operator needs finite numbers");
      }
      for (double i = 0; step != 0; ++i) {
        const double v = base + i * step;
        if (step > 0 ? v > limit : v < limit) break;
        if (items.size() == kMaxElements) {
          fail(range, "an array of more than " + std::to_string(kMaxElements) + " elements");
        }
        items.emplace_back(v);
      }
      return make_row(ElementType::kFloat, std::move(items));
    }
    case Function::kListToArray: {
      std::vector<std::string> items;
      const std::string list = as_text(args[0]);
      std::size_t begin = 0;
      while (begin < list.size()) {
        const std::size_t end = std::min(list.find(';', begin), list.size());
        items.push_back(list.substr(begin, end - begin));
        begin = end + 1;
      }
      return strings_of(items);
    }
    default:
      break;
  }
  const char* name = f == Function::kSize            ? "size"
                     : f == Function::kNRows         ? "nRows"
                     : f == Function::kNColumns      ? "nColumns"
                     : f == Function::kTranspose     ? "transpose"
                     : f == Function::kSortIndices   ? "sortIndices"
                     : f == Function::kListFromArray ? "listFromArray"
                                                     : "findFirst";
  const Array& a = array_arg(args, 0, name, range);
  switch (f) {
    case Function::kSize:
      return static_cast<double>(a.items.size());
    case Function::kNRows:
      return static_cast<double>(a.rows);
    case Function::kNColumns:
      return static_cast<double>(a.columns);
    case Function::kFindFirst:
    case Function::kFindLast:
      return find(a, args, f == Function::kFindFirst, range);
    case Function::kSortIndices:
      return sort_indices(a, range);
    case Function::kTranspose:
      return transposed(a);
    case Function::kListFromArray: {
      std::string list;
      for (const shape::Value& v : a.items) list.append(shape::to_string(v)).append(";");
      return list;
    }
    default:
      fail(range, "internal: not an array function");
  }
}

Value read_table(const std::string& text, bool floats) {
  const std::string first_line = text.substr(0, text.find('\n'));
  char delimiter = ',';
  for (char c : {',', ';', '\t', ' '}) {
    if (first_line.find(c) != std::string::npos) {
      delimiter = c;
      break;
    }
  }
  std::vector<std::vector<std::string>> rows;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = std::min(text.find('\n', begin), text.size());
    std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::size_t from = 0;
    while (true) {
      const std::size_t to = std::min(line.find(delimiter, from), line.size());
      cells.push_back(line.substr(from, to - from));
      if (to == line.size()) break;
      from = to + 1;
    }
    rows.push_back(std::move(cells));
  }
  std::size_t columns = 0;
  for (const auto& r : rows) columns = std::max(columns, r.size());
  std::vector<shape::Value> items;
  for (const auto& r : rows) {
    for (std::size_t c = 0; c < columns; ++c) items.push_back(c < r.size() ? r[c] : std::string());
  }
  Value table = make_array(ElementType::kString, rows.size(), columns, std::move(items));
  if (!floats) return table;
  return converted(*std::get<ArrayPtr>(table), ElementType::kFloat);
}

}  // namespace insula::lang::cga
