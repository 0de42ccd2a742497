#include "shape/query.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <utility>

#include "shape/query_expr.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

template <typename T>
bool ordered(const T& a, const T& b, Compare op) {
  switch (op) {
    case Compare::kEqual:
      return a == b;
    case Compare::kNotEqual:
      return a != b;
    case Compare::kLess:
      return a < b;
    case Compare::kLessEqual:
      return a <= b;
    case Compare::kGreater:
      return a > b;
    case Compare::kGreaterEqual:
      return a >= b;
  }
  return false;
}

}  // namespace

bool compare(double a, Compare op, double b) {
  return ordered(a, b, op);
}

bool value_matches(const Value* v, Compare op, const Value& value) {
  if (v == nullptr || v->index() != value.index()) return op == Compare::kNotEqual;
  if (const auto* d = std::get_if<double>(v)) return ordered(*d, std::get<double>(value), op);
  if (const auto* s = std::get_if<std::string>(v)) {
    return ordered(*s, std::get<std::string>(value), op);
  }
  if (op != Compare::kEqual && op != Compare::kNotEqual) return false;
  return (*v == value) == (op == Compare::kEqual);
}

bool AttributeTest::matches(const ShapeTree& tree, ShapeId id) const {
  return value_matches(tree.attribute(id, name), op, value);
}

base::Result<LabelExpr> LabelExpr::parse(std::string_view text, std::string_view source_name) {
  auto parsed = QueryExpr::parse(text, source_name, QueryExpr::Grammar::kLabels);
  if (!parsed.ok()) return base::Result<LabelExpr>::failure(parsed.diagnostics());
  LabelExpr out;
  out.expr_ = std::make_shared<const QueryExpr>(std::move(parsed.value()));
  return out;
}

bool LabelExpr::matches(const ShapeTree& tree, ShapeId id) const {
  return QueryExpr::Evaluator(*expr_, tree).matches(id);
}

std::string LabelExpr::to_string() const {
  return expr_->to_string();
}

base::Result<AttributeTest> AttributeTest::parse(std::string_view text,
                                                 std::string_view source_name) {
  auto parsed = QueryExpr::parse(text, source_name, QueryExpr::Grammar::kAttribute);
  if (!parsed.ok()) return base::Result<AttributeTest>::failure(parsed.diagnostics());
  const QueryExpr::Node& node = parsed->nodes()[parsed->root()];
  return AttributeTest{node.text, node.compare, node.value};
}

namespace {

std::vector<ShapeId> candidates(const ShapeTree& tree, QuerySet set, ShapeId under) {
  std::vector<ShapeId> ids = under == kNoShape ? tree.all() : tree.subtree(under);
  std::sort(ids.begin(), ids.end());
  std::erase_if(ids, [&](ShapeId id) {
    return (set == QuerySet::kActive && !tree[id].active) ||
           (set == QuerySet::kLeaves && !tree[id].children.empty());
  });
  return ids;
}

template <typename Predicate>
std::vector<ShapeId> filter(const ShapeTree& tree, QuerySet set, ShapeId under, Predicate keep) {
  std::vector<ShapeId> ids = candidates(tree, set, under);
  std::erase_if(ids, [&](ShapeId id) { return !keep(id); });
  return ids;
}

}  // namespace

std::vector<ShapeId> query(const ShapeTree& tree, const LabelExpr& expr, QuerySet set,
                           ShapeId under) {
  QueryExpr::Evaluator evaluator(expr.expr(), tree);
  return filter(tree, set, under, [&](ShapeId id) { return evaluator.matches(id); });
}

std::vector<ShapeId> query(const ShapeTree& tree, const AttributeTest& test, QuerySet set,
                           ShapeId under) {
  return filter(tree, set, under, [&](ShapeId id) { return test.matches(tree, id); });
}

std::vector<ShapeId> descendants(const ShapeTree& tree, ShapeId id) {
  std::vector<ShapeId> out = tree.subtree(id);
  out.erase(out.begin());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<ShapeId> within_distance(const ShapeTree& tree, ShapeId id, double distance,
                                     const std::vector<ShapeId>& candidates_in) {
  const Vec3 c = tree[id].scope.center();
  std::vector<std::pair<double, ShapeId>> hits;
  for (ShapeId other : candidates_in) {
    if (other == id) continue;
    const double d = length(tree[other].scope.center() - c);
    if (d <= distance) hits.emplace_back(d, other);
  }
  std::sort(hits.begin(), hits.end());
  std::vector<ShapeId> out;
  for (const auto& [d, other] : hits) out.push_back(other);
  return out;
}

namespace {

// Axis-aligned box in the target's scope frame.
struct Box {
  std::array<double, 3> min;
  std::array<double, 3> max;
};

Box box_in_frame(const Scope& frame, const Scope& other) {
  Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const Vec3& corner : other.corners()) {
    const Vec3 p = frame.to_local(corner);
    const std::array<double, 3> q = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      b.min[k] = std::min(b.min[k], q[k]);
      b.max[k] = std::max(b.max[k], q[k]);
    }
  }
  return b;
}

// Measure (area or volume) of the union of boxes over the listed dimensions, clipped to
// [0, size]: coordinate compression, then each cell tested against every box. O(n^(d+1)) for n
// boxes in d dimensions, fine for the handful of neighbours a query compares.
double union_measure(std::vector<Box> boxes, const std::array<double, 3>& size,
                     const std::vector<int>& dims) {
  std::array<std::vector<double>, 3> cuts;
  for (int d : dims) {
    cuts[d] = {0.0, size[d]};
    for (Box& b : boxes) {
      b.min[d] = std::clamp(b.min[d], 0.0, size[d]);
      b.max[d] = std::clamp(b.max[d], 0.0, size[d]);
      cuts[d].push_back(b.min[d]);
      cuts[d].push_back(b.max[d]);
    }
    std::sort(cuts[d].begin(), cuts[d].end());
    cuts[d].erase(std::unique(cuts[d].begin(), cuts[d].end()), cuts[d].end());
  }
  double total = 0;
  std::array<std::size_t, 3> cell{0, 0, 0};
  // Iterate over every cell of the grid spanned by the used dimensions.
  const auto count = [&](int d) { return cuts[d].size() - 1; };
  std::size_t cells = 1;
  for (int d : dims) cells *= count(d);
  for (std::size_t flat = 0; flat < cells; ++flat) {
    std::size_t rest = flat;
    double measure = 1;
    std::array<double, 3> mid{};
    for (int d : dims) {
      cell[d] = rest % count(d);
      rest /= count(d);
      measure *= cuts[d][cell[d] + 1] - cuts[d][cell[d]];
      mid[d] = (cuts[d][cell[d] + 1] + cuts[d][cell[d]]) / 2;
    }
    if (measure <= 0) continue;
    const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) {
      return std::all_of(dims.begin(), dims.end(),
                         [&](int d) { return mid[d] > b.min[d] && mid[d] < b.max[d]; });
    });
    if (covered) total += measure;
  }
  return total;
}

}  // namespace

double occlusion(const ShapeTree& tree, ShapeId id, const std::vector<ShapeId>& others,
                 double tolerance) {
  const Scope& scope = tree[id].scope;
  const std::array<double, 3> size = {scope.size.x, scope.size.y, scope.size.z};
  std::vector<int> dims;
  int flat_dim = -1;
  for (int d = 0; d < 3; ++d) {
    if (size[d] > 0) {
      dims.push_back(d);
    } else {
      flat_dim = d;
    }
  }
  if (dims.size() < 2) return 0;
  std::vector<Box> boxes;
  for (ShapeId other : others) {
    if (other == id) continue;
    const Box b = box_in_frame(scope, tree[other].scope);
    // A flat target only sees boxes reaching its plane (projection along the normal).
    if (dims.size() == 2 && (b.max[flat_dim] < -tolerance || b.min[flat_dim] > tolerance)) {
      continue;
    }
    boxes.push_back(b);
  }
  double whole = 1;
  for (int d : dims) whole *= size[d];
  return std::clamp(union_measure(std::move(boxes), size, dims) / whole, 0.0, 1.0);
}

}  // namespace insula::shape
