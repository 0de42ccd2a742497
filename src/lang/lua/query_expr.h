// The query language of Lua component programs (seed 001 §3.3): label expressions with and/or/not
// (shape::LabelExpr's syntax) extended with the paper's other criteria, so Fig. 3's
//   query("wall and not parent(corridor) and occlusion(corridor) > 0")
// is one string. Grammar (EBNF; keywords are lower case; labels with spaces are quoted with ' or
// "):
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
// Face queries (fquery) use the same syntax over faces: the upper-case selectors FRONT BACK LEFT
// RIGHT TOP BOTTOM SIDE ALL (shape::face_matches) and face-id names as labels. Region queries
// (rquery) match region names as labels.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "shape/query.h"
#include "shape/shape_tree.h"

namespace insula::lua {

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
    shape::Compare compare = shape::Compare::kEqual;
    double number = 0;  // threshold, distance, parent depth (0 = any)
    shape::Value value;
  };

  // Parses a component query. Errors: code "Q001", column inside `text`, file `source_name`.
  static base::Result<QueryExpr> parse(std::string_view text,
                                       std::string_view source_name = "<query>");
  // Parses a face query (upper-case selectors allowed; attribute tests and tree criteria not).
  static base::Result<QueryExpr> parse_faces(std::string_view text,
                                             std::string_view source_name = "<query>");

  // Evaluation over one tree. Sub-results of occlusion() and near() are computed once per
  // evaluator (the shapes matching the inner expression and their world boxes).
  class Evaluator {
   public:
    Evaluator(const QueryExpr& expr, const shape::ShapeTree& tree);
    ~Evaluator();
    bool matches(shape::ShapeId id);

   private:
    struct Cache;
    bool eval(shape::ShapeId id, std::uint32_t node);
    const QueryExpr& expr_;
    const shape::ShapeTree& tree_;
    std::vector<std::unique_ptr<Cache>> caches_;  // per node, on demand
  };

  // Face `face` of `mesh` (normal in scope space), face id name `face_name` ("" when none).
  bool matches_face(kernel::Vec3 normal, std::string_view face_name) const;
  // A region name against a label expression (no other criteria).
  bool matches_name(std::string_view name) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  std::uint32_t root() const { return static_cast<std::uint32_t>(nodes_.size() - 1); }

 private:
  friend class QueryParser;
  bool eval_face(std::uint32_t node, kernel::Vec3 normal, std::string_view face_name) const;
  std::vector<Node> nodes_;  // the root is the last node
};

}  // namespace insula::lua
