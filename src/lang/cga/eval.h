// Evaluation of CGA expressions (conditions §VI, probabilities, operation arguments) over values
// null / bool / number / string / array (value.h). The pure operators are free functions used both
// for constant folding (compile.cc) and at derivation time (derive.cc); errors are thrown as
// EvalError and become diagnostics where the engine catches them, at the expression's position.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/cga/ast.h"
#include "lang/cga/compile.h"
#include "lang/cga/value.h"
#include "shape/geometry_queries.h"
#include "shape/ops.h"
#include "shape/rng.h"
#include "shape/scope.h"

namespace insula::lang::cga {

// An evaluation failure at `range` (thrown inside the CGA front-end only; never crosses it).
struct EvalError {
  Range range;
  std::string message;
};

// "number", "string", "bool", "null", "float[]", "bool[]", "string[]".
std::string_view type_name(const Value& value);
// The number in `value` or an EvalError at `range` ("expected a number, got a string").
double as_number(const Value& value, Range range);
// Truth of a condition: booleans as they are, numbers != 0; anything else is an error.
bool as_bool(const Value& value, Range range);
// The string in `value` (numbers and booleans are formatted, as str(); arrays as print shows
// them, value.h's print_text).
std::string as_text(const Value& value);

Value apply_unary(UnaryOp op, const Value& v, Range range);
// `+` concatenates when either side is a string; comparisons compare numbers numerically,
// strings lexicographically and arrays as value.h's compare; `and`/`or` need booleans (or
// numbers). Arithmetic on arrays is an error (CityEngine's element-wise `.+` is apply_elementwise).
Value apply_binary(BinaryOp op, const Value& a, const Value& b, Range range);
// CityEngine's element-wise operators (`.==`, `.+`, ...): apply_binary on each pair of elements
// of two arrays of one size, or of an array's elements and a value; an array of the results.
Value apply_elementwise(BinaryOp op, const Value& a, const Value& b, Range range);
// Functions that need no random generator (everything but rand and p).
Value apply_function(Function f, const std::vector<Value>& args, Range range);
// Whether `f` needs the derivation (a random generator or the app's files): never folded.
bool is_random(Function f);
bool is_file_function(Function f);

// ---- arrays (eval_arrays.cc)
// An array literal: `groups` are its `;`-separated rows, each a list of values put side by side
// (a scalar is one element, an array its columns); the rows are stacked. Mixed element types,
// rows of unequal width and an empty literal are errors at `range`.
Value array_literal(const std::vector<std::vector<Value>>& groups, Range range);
// `a[i]` (linear, row-major) or `a[r, c]`. An index outside the array gives the element type's
// default (0, false, "") as CityEngine, and sets `warning`.
Value index_array(const Value& array, std::span<const Value> indices, Range range,
                  std::string& warning);
// size, nRows, nColumns, findFirst, findLast, sortIndices, transpose, floatArray, boolArray,
// stringArray, listToArray, listFromArray.
Value array_function(Function f, const std::vector<Value>& args, Range range);
bool is_array_function(Function f);
// readStringTable / readFloatTable: a CSV text as a 2-D array (the delimiter is the first of
// ',', ';', tab or blank found in the first line).
Value read_table(const std::string& text, bool floats);

// What an expression may read while deriving: the shape's scope and attributes, its random
// generator, and the lot-level attribute values. Implemented by the engine.
class EvalContext {
 public:
  virtual ~EvalContext() = default;
  virtual Value attribute(std::uint32_t attr, Range range) = 0;
  virtual double shape_attribute(ShapeAttr attr) = 0;
  // CityEngine's inside/overlaps/touches: whether the shape stands so to an occluder of `target`
  // (labelled `label`; "" any).
  // CityEngine's convert(): `v` from frame `from` into frame `to` (positions, or orientations
  // in degrees), the frames the shape's own (shape::convert_between_frames).
  virtual kernel::Vec3 convert(shape::Frame from, shape::Frame to, bool orientation,
                               kernel::Vec3 v) = 0;
  virtual bool occlusion_query(OcclusionRelation relation, OcclusionTarget target,
                               const std::string& label) = 0;
  // CityEngine's minimumDistance(target, label): to the nearest such occluder (+inf: none).
  virtual double minimum_distance(OcclusionTarget target, const std::string& label) = 0;
  // CityEngine's geometry.* (shape/geometry_queries.h) on the shape's geometry.
  virtual double geometry(shape::GeometryQuery query, std::uint8_t option, double tolerance) = 0;
  // comp.sel: the selector of the comp branch the shape came from ("" when none).
  virtual std::string comp_selector() = 0;
  // "none", "part" or "full" for Shape.occ(`what`).
  virtual std::string occlusion(const std::string& what, Range range) = 0;
  virtual shape::Rng& rng() = 0;
  // fileExists, fileSearch, fileRandom, assetInfo, imageInfo, readStringTable, readFloatTable
  // (derive.h, FileQueries).
  virtual Value file_function(Function f, const std::vector<Value>& args, Range range) = 0;
  // CityEngine's comp function `comp(fe){ sel : value | ... }` (Program::comp_functions[index]):
  // one value per component of the current shape.
  virtual Value comp_function(std::uint32_t index, Range range) = 0;
  // geometry.du/dv/uMin/uMax/vMin/vMax (`which` 0..5) of uv set `set`; du and dv in meters
  // when `unit_space`. 0 when the shape has no such set.
  virtual double uv_extent(std::uint8_t which, int set, bool unit_space) = 0;
  // getGeoCoord(x | y | lon | lat) of the current shape's scope origin.
  virtual double geo_coord(const std::string& which, Range range) = 0;
  // print() used as a function: the text goes where the print operation's lines go.
  virtual void print(Range range, const std::string& text) = 0;
  // A run-time warning at `range` (an array index out of range).
  virtual void warning(Range range, std::string message) = 0;

  // The arguments of the rule or function being evaluated (ECode::kParam reads them).
  std::span<const Value> frame;
  std::uint32_t call_depth = 0;  // nested function calls (recursion is bounded)
};

// Deepest nesting of function calls before evaluation stops with an error (a function calling
// itself without end).
inline constexpr std::uint32_t kMaxCallDepth = 200;

// Evaluates node `expr` of `program`.
Value evaluate(const Program& program, std::uint32_t expr, EvalContext& context);

}  // namespace insula::lang::cga
