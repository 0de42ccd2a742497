// The checker's working state, shared by checker.cc (rules, ids, start symbol, reachability,
// attributes), checker_successors.cc (successors, operations, §IV.B constraints 1-5) and
// checker_exprs.cc (expressions: identifiers, functions, constant folding). Not a public API.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"
#include "lang/cga/checker.h"
#include "lang/cga/geometry_functions.h"
#include "lang/cga/operations.h"
#include "shape/operation.h"

namespace insula::lang::cga::detail {

// The value of an expression made only of literals and arithmetic (no attribute, since
// attributes can be overridden from outside with --set or lot properties). Relative (`2r`) and
// floating (`~2`) sizes fold to their number with the mode recorded.
struct Constant {
  double value = 0.0;
  bool relative = false;
  bool floating = false;
};
std::optional<Constant> fold(const Expr& expr);

// Where an expression stands decides which bare words and sizes it may be.
enum class ExprRole {
  kValue,     // a number, string or boolean value: identifiers must be defined
  kSize,      // a split, repeat or scale size: may be relative (`2r`, `'0.5`) or floating (`~1`)
  kBareWord,  // an operation argument that may be a bare word (an axis, an asset or enum name)
};

class Checker {
 public:
  Checker(const Grammar& grammar, const base::Source& source, const CheckOptions& options);
  CheckResult run();

  // ---- diagnostics
  void error(std::string code, std::string message, Range range);
  void warning(std::string code, std::string message, Range range);
  void file_error(std::string code, std::string message);

  // ---- checker_exprs.cc
  void check_expr(const Expr& expr, ExprRole role = ExprRole::kValue);

 private:
  // ---- checker.cc
  void declare_attributes();
  void collect_set_targets();
  void check_attribute_cycles();
  void check_priority_sets();
  void check_rule_ids();
  void choose_start();
  void compute_reachability();
  void report_unused();

  // ---- checker_successors.cc
  void check_rule(const Rule& rule);
  void check_probabilities(const Rule& rule);
  void check_sequence(const std::vector<Item>& items);
  void check_empty_shape(const std::vector<Item>& items);
  void check_item(const Item& item);
  void check_arguments(const Item& item, const OperationInfo& info);
  void check_split(const Item& item);
  void check_repeat(const Item& item);
  void check_comp(const Item& item);
  void check_rotation(const Item& item);
  void check_generic(const Item& item, const OperationInfo& info);
  void check_registry_ranges(const Item& item, const OperationInfo& info);
  void check_registry_choice(const Item& item, std::size_t index, const shape::ParamDecl& param);
  void check_axis(const Expr& expr, bool combinations);
  std::optional<CompType> check_comp_type(const Expr& expr);
  void check_plain_branches(const Item& item, std::size_t expected, const char* what);
  void check_selector_keys(const Item& item, const std::vector<std::string>& selectors,
                           bool indices);
  void check_size_keys(const Item& item, const std::vector<Branch>& branches);
  void check_branch_items(const Branch& branch);

  // CityEngine's geometry.du, dv, uMin, uMax, vMin, vMax (the names after "geometry.").
  static bool is_uv_extent(std::string_view name);
  // ---- checker_cityengine.cc (CityEngine's dialect: functions, parameters, chains, annotations)
  bool cityengine() const { return grammar_.dialect == Dialect::kCityEngine; }
  void declare_functions();
  void check_functions();
  void check_annotations(const std::vector<Annotation>& annotations);
  void declare_rule_arities();
  void check_symbol_call(const Item& item);
  void check_chain(const Item& item);
  bool check_user_call(const Expr& expr);
  bool is_parameter(std::string_view name) const;
  // The grammar's function `name` taking `count` arguments; null when there is none.
  const FunctionDecl* function(std::string_view name, std::size_t count) const;
  std::string arities(std::string_view name) const;  // "1 or 2
  std::vector<std::string> start_rules() const;

  // ---- checker_exprs.cc
  void check_call(const Expr& expr);
  void check_occlusion_query(const Expr& expr);
  void check_convert(const Expr& expr);
  void check_geometry_call(const Expr& expr, const shape::GeometryQueryInfo& query);
  void check_comp_function(const Expr& expr);
  void check_member(const Expr& expr);
  void check_identifier(const Expr& expr, ExprRole role);

  const Grammar& grammar_;
  const base::Source& source_;
  const CheckOptions& options_;
  std::vector<base::Diagnostic> diagnostics_;
  CheckResult result_;

  std::map<std::string, const AttrDecl*, std::less<>> attributes_;
  std::set<std::string, std::less<>> known_;  // CheckOptions::known_attributes
  std::set<std::string, std::less<>> used_attributes_;
  // The attribute whose default is being checked (for the dependency graph), or null.
  const AttrDecl* current_attribute_ = nullptr;
  std::map<std::string, std::set<std::string>, std::less<>> attribute_deps_;
  // CityEngine overloads functions by their number of parameters: name -> count -> function.
  std::map<std::string, std::map<std::size_t, const FunctionDecl*>, std::less<>> functions_;
  // Parameter counts of each rule name (CityEngine overloads rules by their number of parameters).
  std::map<std::string, std::set<std::size_t>, std::less<>> rule_arities_;
  const std::vector<std::string>* params_ = nullptr;  // of the rule or function being checked
};

}  // namespace insula::lang::cga::detail
