// The values of CGA expressions: shape::Value's null, bool, number and string, plus CityEngine's
// arrays (float[], bool[], string[]; 1-D and, since CGA 2020.0, 2-D; docs/cga-cityengine.md,
// "Arrays"). Arrays live only inside the CGA front-end: where a value leaves it (an exported
// attribute, the report) an array becomes text (to_shape), so the shape layer, the exporters,
// Lua and graphs never see one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "shape/value.h"

namespace insula::lang::cga {

enum class ElementType : std::uint8_t { kFloat, kBool, kString };

// A rectangular array, row-major. A 1-D array is one row; an empty one has no rows.
struct Array {
  ElementType type = ElementType::kFloat;
  std::size_t rows = 0;
  std::size_t columns = 0;
  std::vector<shape::Value> items;  // rows * columns values, each of `type`
};
using ArrayPtr = std::shared_ptr<const Array>;

// null, boolean, number, string, array (shared: copying a value does not copy its elements).
using Value = std::variant<std::monostate, bool, double, std::string, ArrayPtr>;

// "float[]", "bool[]", "string[]".
std::string_view array_type_name(ElementType type);
// 0, false or "": what CityEngine puts where an array has no element (an index out of range,
// a component no selector took).
shape::Value default_element(ElementType type);
// The element type of a scalar (null has none: nullptr).
const ElementType* element_type_of(const shape::Value& v);

// An array of `rows` x `columns` elements (row-major) of `type`.
ArrayPtr make_array(ElementType type, std::size_t rows, std::size_t columns,
                    std::vector<shape::Value> items);
// A 1-D array (one row) of `items`.
ArrayPtr make_row(ElementType type, std::vector<shape::Value> items);

// CityEngine's printed form: "(3)[1,2,3]" for one row, "(2x2)[1,2;3,4]" for more (CityEngine
// prints 2-D arrays over several lines; one line keeps print() and report lines whole).
std::string print_text(const Array& a);
// CGA's literal syntax, strings quoted: "[1,2,3]", "[1,2;3,4]", "[\"a\",\"b\"]" (exports).
std::string literal_text(const Array& a);

// The order of two elements of one type: numbers, texts, false before true.
bool element_less(const shape::Value& x, const shape::Value& y);
// Equal dimensions and equal elements.
bool equal(const Array& a, const Array& b);
// CityEngine's order of arrays: element by element, row by row; with equal first rows the one
// with fewer columns, then the one with fewer rows, is less. -1, 0 or 1.
int compare(const Array& a, const Array& b);

// A value leaving the front-end: arrays as their literal text.
shape::Value to_shape(const Value& v);
// A scalar (also an array's element) as a value.
Value from_shape(const shape::Value& v);

}  // namespace insula::lang::cga
