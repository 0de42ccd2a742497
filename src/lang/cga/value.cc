#include "lang/cga/value.h"

#include <algorithm>

namespace insula::lang::cga {

std::string_view array_type_name(ElementType type) {
  switch (type) {
    case ElementType::kFloat:
      return "float[]";
    case ElementType::kBool:
      return "bool[]";
    case ElementType::kString:
      return "string[]";
  }
  return "float[]";
}

shape::Value default_element(ElementType type) {
  switch (type) {
    case ElementType::kFloat:
      return 0.0;
    case ElementType::kBool:
      return false;
    case ElementType::kString:
      return std::string();
  }
  return 0.0;
}

const ElementType* element_type_of(const shape::Value& v) {
  static constexpr ElementType kTypes[] = {ElementType::kFloat, ElementType::kBool,
                                           ElementType::kString};
  if (std::holds_alternative<double>(v)) return &kTypes[0];
  if (std::holds_alternative<bool>(v)) return &kTypes[1];
  if (std::holds_alternative<std::string>(v)) return &kTypes[2];
  return nullptr;
}

ArrayPtr make_array(ElementType type, std::size_t rows, std::size_t columns,
                    std::vector<shape::Value> items) {
  auto a = std::make_shared<Array>();
  a->type = type;
  a->rows = items.empty() ? 0 : rows;
  a->columns = items.empty() ? 0 : columns;
  a->items = std::move(items);
  return a;
}

ArrayPtr make_row(ElementType type, std::vector<shape::Value> items) {
  const std::size_t columns = items.size();
  return make_array(type, 1, columns, std::move(items));
}

namespace {

std::string joined(const Array& a, bool quote) {
  std::string out = "[";
  for (std::size_t i = 0; i < a.items.size(); ++i) {
    if (i > 0) out += a.columns > 0 && i % a.columns == 0 ? ';' : ',';
    const shape::Value& v = a.items[i];
    if (quote && std::holds_alternative<std::string>(v)) {
      out += '"';
      for (char c : std::get<std::string>(v)) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      out += '"';
    } else {
      out += shape::to_string(v);
    }
  }
  return out + "]";
}

}  // namespace

std::string print_text(const Array& a) {
  const std::string dims = a.rows <= 1 ? std::to_string(a.items.size())
                                       : std::to_string(a.rows) + "x" + std::to_string(a.columns);
  return "(" + dims + ")" + joined(a, false);
}

std::string literal_text(const Array& a) {
  return joined(a, true);
}

bool element_less(const shape::Value& x, const shape::Value& y) {
  if (const double* a = std::get_if<double>(&x)) {
    const double* b = std::get_if<double>(&y);
    return b != nullptr && *a < *b;
  }
  if (const std::string* a = std::get_if<std::string>(&x)) {
    const std::string* b = std::get_if<std::string>(&y);
    return b != nullptr && *a < *b;
  }
  const bool* a = std::get_if<bool>(&x);
  const bool* b = std::get_if<bool>(&y);
  return a != nullptr && b != nullptr && !*a && *b;
}

bool equal(const Array& a, const Array& b) {
  return a.type == b.type && a.rows == b.rows && a.columns == b.columns && a.items == b.items;
}

int compare(const Array& a, const Array& b) {
  const std::size_t rows = std::min(a.rows, b.rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t columns = std::min(a.columns, b.columns);
    for (std::size_t c = 0; c < columns; ++c) {
      const shape::Value& x = a.items[r * a.columns + c];
      const shape::Value& y = b.items[r * b.columns + c];
      if (element_less(x, y)) return -1;
      if (element_less(y, x)) return 1;
    }
    if (a.columns != b.columns) return a.columns < b.columns ? -1 : 1;
  }
  if (a.rows != b.rows) return a.rows < b.rows ? -1 : 1;
  return 0;
}

shape::Value to_shape(const Value& v) {
  if (const ArrayPtr* a = std::get_if<ArrayPtr>(&v)) return literal_text(**a);
  return std::visit(
      [](const auto& x) -> shape::Value {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, ArrayPtr>) {
          return shape::Value{};
        } else {
          return x;
        }
      },
      v);
}

Value from_shape(const shape::Value& v) {
  return std::visit([](const auto& x) -> Value { return x; }, v);
}

}  // namespace insula::lang::cga
