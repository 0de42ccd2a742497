// The query language of every front-end (seed 001 §3.3): label expressions with and/or/not,
// extended with the paper's other criteria, so Fig. 3's
//   query("wall and not parent(corridor) and occlusion(corridor) > 0")
// is one string. One lexer and one parser serve four grammars (QueryExpr::Grammar): label
// expressions alone (LabelExpr), one attribute test (AttributeTest), shape queries (Lua's query)
// and face queries (Lua's fquery). Grammar (EBNF; keywords are lower case; labels with spaces are
// quoted with ' or "):
//   expr      = and_expr { "or" and_expr } ;
//   and_expr  = not_expr { "and" not_expr } ;
//   not_expr  = "not" not_expr | primary ;
//   primary   = "(" expr ")"
//             | "parent" "(" expr [ "," number ] ")"   (* an ancestor within n levels, default any
//             *) | "child" "(" expr ")"                   (* some child matches *) | "occlusion"
//             "(" expr ")" compare number (* fraction covered by the matches *) | "near" "(" expr
//             "," number ")"          (* scope centres within d meters *) | "active" "(" ")" |
//             "leaf" "(" ")" | "flat" "(" ")" | name compare literal                   (* attribute
//             test, inherited values *) | label ;
//   compare   = "==" | "!=" | "<" | "<=" | ">" | ">=" ;
//   literal   = number | "true" | "false" | quoted string ;
// Label expressions are expr with primary = "(" expr ")" | label; an attribute test is one
// `name compare literal`.
// Face queries (fquery) use the same syntax over faces: the upper-case selectors FRONT BACK LEFT
// RIGHT TOP BOTTOM SIDE ALL (face_matches) and face-id names as labels. Region queries
// (rquery) match region names as labels.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/vec.h"
#include "shape/query.h"
#include "shape/shape_tree.h"
#include "shape/value.h"

namespace insula::shape {

class QueryExpr {
 public:
  enum class Kind : std::uint8_t {
    kLabel,
    kNot,
    kAnd,
    kOr,
    kParent,
    kChild,
    kOcclusion,
    kNear,
    kActive,
    kLeaf,
    kFlat,
    kAttribute,
    kFaceSelector,
  };
  struct Node {
    Kind kind = Kind::kLabel;
    std::uint32_t a = 0;  // child node (kNot, kAnd, kOr, kParent, kChild, kOcclusion, kNear)
    std::uint32_t b = 0;  // second child (kAnd, kOr)
    std::string text;     // label, or attribute name
    Compare compare = Compare::kEqual;
    double number = 0;  // threshold, distance, parent depth (0 = any)
    Value value;
  };

  enum class Grammar : std::uint8_t {
    kLabels,     // label expressions: labels, and, or, not, parentheses
    kAttribute,  // exactly one attribute test
    kShapes,     // the whole grammar above
    kFaces,      // label expressions with face selectors (attribute tests and tree criteria not)
  };

  // Parses a query of `grammar`. Errors: code "Q002" for kAttribute, else "Q001", column inside
  // `text`, file `source_name`.
  static base::Result<QueryExpr> parse(std::string_view text,
                                       std::string_view source_name = "<query>",
                                       Grammar grammar = Grammar::kShapes);
  // parse with Grammar::kFaces.
  static base::Result<QueryExpr> parse_faces(std::string_view text,
                                             std::string_view source_name = "<query>");

  // Evaluation over one tree. Sub-results of occlusion() and near() are computed once per
  // evaluator (the shapes matching the inner expression and their world boxes).
  class Evaluator {
   public:
    Evaluator(const QueryExpr& expr, const ShapeTree& tree);
    ~Evaluator();
    bool matches(ShapeId id);

   private:
    struct Cache;
    bool eval(ShapeId id, std::uint32_t node);
    const QueryExpr& expr_;
    const ShapeTree& tree_;
    std::vector<std::unique_ptr<Cache>> caches_;  // per node, on demand
  };

  // Face `face` of `mesh` (normal in scope space), face id name `face_name` ("" when none).
  bool matches_face(kernel::Vec3 normal, std::string_view face_name) const;
  // A region name against a label expression (no other criteria).
  bool matches_name(std::string_view name) const;
  // The expression in canonical fully parenthesised form, e.g. "(room and (not corridor))"; the
  // label-expression part of the grammar only (other nodes print as "?").
  std::string to_string() const;

  const std::vector<Node>& nodes() const { return nodes_; }
  std::uint32_t root() const { return static_cast<std::uint32_t>(nodes_.size() - 1); }

 private:
  friend class QueryParser;
  bool eval_face(std::uint32_t node, kernel::Vec3 normal, std::string_view face_name) const;
  std::vector<Node> nodes_;  // the root is the last node
};

}  // namespace insula::shape
