// Evaluation of CGA expressions (conditions §VI, probabilities, operation arguments) over values
// null / bool / number / string (shape::Value). The pure operators are free functions used both for
// constant folding (compile.cc) and at derivation time (derive.cc); errors are thrown as EvalError
// and become diagnostics where the engine catches them, at the expression's position.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/cga/ast.h"
#include "lang/cga/compile.h"
#include "shape/geometry_queries.h"
#include "shape/rng.h"
#include "shape/scope.h"
#include "shape/value.h"

namespace insula::lang::cga {

// An evaluation failure at `range` (thrown inside the CGA front-end only; never crosses it).
struct EvalError {
  Range range;
  std::string message;
};

// "number", "string", "bool", "null".
std::string_view type_name(const shape::Value& value);
// The number in `value` or an EvalError at `range` ("expected a number, got a string").
double as_number(const shape::Value& value, Range range);
// Truth of a condition: booleans as they are, numbers != 0; anything else is an error.
bool as_bool(const shape::Value& value, Range range);
// The string in `value` (numbers and booleans are formatted, as str()).
std::string as_text(const shape::Value& value);

shape::Value apply_unary(UnaryOp op, const shape::Value& v, Range range);
// `+` concatenates when either side is a string; comparisons compare numbers numerically and
// strings lexicographically; `and`/`or` need booleans (or numbers).
shape::Value apply_binary(BinaryOp op, const shape::Value& a, const shape::Value& b, Range range);
// Functions that need no random generator (everything but rand and p).
shape::Value apply_function(Function f, const std::vector<shape::Value>& args, Range range);
// Whether `f` needs the derivation (a random generator or the app's files): never folded.
bool is_random(Function f);
bool is_file_function(Function f);

// What an expression may read while deriving: the shape's scope and attributes, its random
// generator, and the lot-level attribute values. Implemented by the engine.
class EvalContext {
 public:
  virtual ~EvalContext() = default;
  virtual shape::Value attribute(std::uint32_t attr, Range range) = 0;
  virtual double shape_attribute(ShapeAttr attr) = 0;
  // CityEngine's inside/overlaps/touches: whether the shape stands so to an occluder of `target`
  // (labelled `label`; "" any).
  virtual bool occlusion_query(OcclusionRelation relation, OcclusionTarget target,
                               const std::string& label) = 0;
  // CityEngine's geometry.* (shape/geometry_queries.h) on the shape's geometry.
  virtual double geometry(shape::GeometryQuery query, std::uint8_t option, double tolerance) = 0;
  // comp.sel: the selector of the comp branch the shape came from ("" when none).
  virtual std::string comp_selector() = 0;
  // "none", "part" or "full" for Shape.occ(`what`).
  virtual std::string occlusion(const std::string& what, Range range) = 0;
  virtual shape::Rng& rng() = 0;
  // fileExists, fileSearch, fileRandom, assetInfo, imageInfo (derive.h, FileQueries).
  virtual shape::Value file_function(Function f, const std::vector<shape::Value>& args,
                                     Range range) = 0;

  // The arguments of the rule or function being evaluated (ECode::kParam reads them).
  std::span<const shape::Value> frame;
  std::uint32_t call_depth = 0;  // nested function calls (recursion is bounded)
};

// Deepest nesting of function calls before evaluation stops with an error (a function calling
// itself without end).
inline constexpr std::uint32_t kMaxCallDepth = 200;

// Evaluates node `expr` of `program`.
shape::Value evaluate(const Program& program, std::uint32_t expr, EvalContext& context);

}  // namespace insula::lang::cga
