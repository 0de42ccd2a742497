// Queries over a shape tree (seed 001 §3.3): label expressions, attribute tests, subtrees,
// proximity and occlusion. Queries never change the tree. The query language itself (one lexer
// and parser for every front-end, its grammar) is shape/query_expr.h.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "shape/shape_tree.h"

namespace insula::shape {

class QueryExpr;

// A label expression (labels joined by and, or, not and parentheses; QueryExpr::Grammar::kLabels).
class LabelExpr {
 public:
  // Parses `text`; errors carry code "Q001" and the column in `source_name`.
  static base::Result<LabelExpr> parse(std::string_view text,
                                       std::string_view source_name = "<query>");
  bool matches(const ShapeTree& tree, ShapeId id) const;
  // The expression in canonical fully parenthesised form, e.g. "(room and (not corridor))".
  std::string to_string() const;
  const QueryExpr& expr() const { return *expr_; }

 private:
  std::shared_ptr<const QueryExpr> expr_;  // immutable, shared by copies
};

enum class Compare : std::uint8_t { kEqual, kNotEqual, kLess, kLessEqual, kGreater, kGreaterEqual };

// `a op b` on numbers.
bool compare(double a, Compare op, double b);
// Whether an attribute value (null when the shape has none) satisfies `op value`: numbers compare
// numerically, strings lexicographically, booleans only with == and !=; a missing value or a type
// mismatch is false, except for != which is then true. The rule of AttributeTest and of every
// front-end's attribute queries.
bool value_matches(const Value* v, Compare op, const Value& value);

// `name op value` on the attribute a shape sees (inherited). Numbers compare numerically, strings
// lexicographically, booleans only with == and !=; a missing attribute or a type mismatch is false
// (except != which is then true).
struct AttributeTest {
  std::string name;
  Compare op = Compare::kEqual;
  Value value;

  bool matches(const ShapeTree& tree, ShapeId id) const;
  // Parses `name op value` with op one of == != < <= > >=, value a number, true, false or a
  // double-quoted string. Errors carry code "Q002".
  static base::Result<AttributeTest> parse(std::string_view text,
                                           std::string_view source_name = "<query>");
};

enum class QuerySet { kAll, kActive, kLeaves };

// Shapes of `set` (optionally restricted to the subtree of `under`, seed 001 §3.3: "the parsing
// will be limited to these components and their children") matching the expression, in id order.
std::vector<ShapeId> query(const ShapeTree& tree, const LabelExpr& expr,
                           QuerySet set = QuerySet::kAll, ShapeId under = kNoShape);
std::vector<ShapeId> query(const ShapeTree& tree, const AttributeTest& test,
                           QuerySet set = QuerySet::kAll, ShapeId under = kNoShape);
// Strict descendants of `id`, in id order.
std::vector<ShapeId> descendants(const ShapeTree& tree, ShapeId id);

// Shapes among `candidates` (other than `id`) whose scope centre lies within `distance` meters of
// `id`'s scope centre, nearest first (ties by id).
std::vector<ShapeId> within_distance(const ShapeTree& tree, ShapeId id, double distance,
                                     const std::vector<ShapeId>& candidates);

// Fraction in [0, 1] of `id`'s scope covered by the union of the `others`' scope boxes (seed 001
// §3.3). Box approximation: each other box is replaced by its axis-aligned bounds in `id`'s scope
// frame (exact when the boxes share axes, as split results do; conservative when rotated). For a
// volume the covered volume is measured; for a flat scope (one size 0, e.g. a wall face) the
// covered area of the face, counting boxes that reach within `tolerance` meters of the face plane
// (so a room touching a wall face occludes it). A degenerate scope (a line or point) gives 0.
double occlusion(const ShapeTree& tree, ShapeId id, const std::vector<ShapeId>& others,
                 double tolerance = 1e-3);

}  // namespace insula::shape
