// The bad-input catalog tests/data/plasm/bad/*.psm: each file's first diagnostic (parser, then
// checker, then evaluator, then the conversion to a scene), exactly; each within a second.
#include <gtest/gtest.h>

#include <chrono>
#include <map>

#include "test_util.h"

namespace insula::lang::plasm {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

const std::map<std::string, std::string>& expected_first_lines() {
  static const std::map<std::string, std::string> kExpected = {
      {"bad_character", "bad_character.psm:1:11: error[PSM001]: unexpected character '$'"},
      {"bad_escape", "bad_escape.psm:1:11: error[PSM005]: unknown escape sequence in string"},
      {"builtin_arity",
       "builtin_arity.psm:1:9: error[PSM306]: 'TRUNCONE' takes a sequence of 3 values, found 2"},
      {"control_byte", "control_byte.psm:2:9: error[PSM001]: unexpected byte 0x01"},
      {"cycle",
       "cycle.psm:1:5: error[PSM305]: the value of 'a' depends on itself: a -> b -> c -> a"},
      // DEF a = ((( ... : every '(' nests twice (parenthesis, inner expression), so the 50th
      // parenthesis, at column 9 + 49, is the one that goes past 100 levels.
      {"deep_parentheses",
       "deep_parentheses.psm:1:58: error[PSM105]: nesting deeper than 100 levels"},
      {"def_without_assign",
       "def_without_assign.psm:1:7: error[PSM101]: expected '=' after the name 'a', found number "
       "1"},
      {"def_without_name",
       "def_without_name.psm:1:5: error[PSM101]: expected identifier (the name being defined) "
       "after 'DEF', found '='"},
      {"duplicate_def",
       "duplicate_def.psm:2:5: error[PSM302]: 'A' is already defined at line 1 (names are "
       "case-insensitive)"},
      {"duplicate_local",
       "duplicate_local.psm:2:14: error[PSM303]: 'B' is already defined in 'f' at line 2"},
      {"duplicate_parameter",
       "duplicate_parameter.psm:1:19: error[PSM304]: parameter 'A' of 'f' is declared twice"},
      {"empty_group",
       "empty_group.psm:1:8: error[PSM101]: expected identifier (a parameter name), found ')'"},
      {"if_two_functions",
       "if_two_functions.psm:1:9: error[PSM107]: IF:<...> takes 3 functions (predicate, then, "
       "else), found 2"},
      {"if_without_sequence",
       "if_without_sequence.psm:1:9: error[PSM106]: IF is written IF:<predicate, then, else>"},
      // Any-arity builtins may be used infix; CUBOID is then the geometry stage's.
      {"infix_wrong_kind",
       "infix_wrong_kind.psm:1:9: error[PSM402]: 'TOP' needs a polyhedron, found a number 2"},
      {"infix_without_right",
       "infix_without_right.psm:1:14: error[PSM104]: expected an expression after the infix "
       "function 'TOP', found ';'"},
      // Names are case-insensitive: the local arch hides the function Arch it calls.
      {"local_hides_function",
       "local_hides_function.psm:3:7: error[PSM305]: the value of 'arch' depends on itself: arch "
       "-> arch"},
      {"local_cycle",
       "local_cycle.psm:2:7: error[PSM305]: the value of 'y' depends on itself: y -> z -> y"},
      {"malformed_number", "malformed_number.psm:1:9: error[PSM004]: malformed number '2x'"},
      {"missing_operand",
       "missing_operand.psm:1:13: error[PSM104]: expected an expression, found ';'"},
      {"missing_semicolon",
       "missing_semicolon.psm:2:1: error[PSM101]: expected ';' after the definition of 'a', found "
       "'DEF'"},
      {"stray_paren",
       "stray_paren.psm:1:1: error[PSM102]: expected 'DEF' or an expression, found ')'"},
      {"triple_colon",
       "triple_colon.psm:1:34: error[PSM104]: expected an expression (the predicate) after '::', "
       "found ':'"},
      {"unary_minus",
       "unary_minus.psm:1:11: error[PSM103]: PLaSM has no unary minus: write -:x to negate x (or a "
       "literal such as -1)"},
      {"unclosed_construction",
       "unclosed_construction.psm:1:16: error[PSM101]: expected ']' or ',' to close the "
       "construction '[', found ';'"},
      {"unclosed_group",
       "unclosed_group.psm:1:18: error[PSM101]: expected ')' to close the parameter group, found "
       "'='"},
      {"unclosed_sequence",
       "unclosed_sequence.psm:1:14: error[PSM101]: expected '>' or ',' to close the sequence '<', "
       "found ';'"},
      {"unknown_builtin",
       "unknown_builtin.psm:1:9: error[PSM301]: unknown name 'IsReel'; did you mean 'ISREAL'?"},
      {"unknown_local",
       "unknown_local.psm:1:41: error[PSM301]: unknown name 'Vault_8th'; did you mean 'vault8th'?"},
      {"unknown_name",
       "unknown_name.psm:1:53: error[PSM301]: unknown name 'd'; did you mean 'dm'?"},
      {"unterminated_comment",
       "unterminated_comment.psm:2:1: error[PSM003]: unterminated comment: '%' without its closing "
       "'%'"},
      {"unterminated_string", "unterminated_string.psm:1:9: error[PSM002]: unterminated string"},
      {"where_missing_comma",
       "where_missing_comma.psm:3:3: error[PSM101]: expected 'END' or ',' after the locals of 'f', "
       "found identifier 'c'"},
      {"where_without_end",
       "where_without_end.psm:3:1: error[PSM101]: expected 'END' or ',' after the locals of 'f', "
       "found ';'"},
      // Runtime diagnostics (the evaluator, PSM4xx).
      {"apply_not_function",
       "apply_not_function.psm:1:9: error[PSM401]: cannot apply a sequence <1, 2>: it is not a "
       "function"},
      {"division_by_zero", "division_by_zero.psm:1:16: error[PSM405]: division by zero"},
      {"group_arity",
       "group_arity.psm:2:9: error[PSM404]: 'f' takes a sequence of 2 values for its parameters "
       "(a, b::IsNum), found a sequence <1, 2, 3>"},
      {"memory_budget",
       "memory_budget.psm:1:9: error[PSM413]: evaluation needs more than 4000000 cells of memory "
       "(the memory budget)"},
      {"struct_wrong_kind",
       "struct_wrong_kind.psm:1:12: error[PSM402]: 'STRUCT' holds polyhedra and transformations, "
       "found a number 2 at position 2"},
      {"nesting_budget",
       "nesting_budget.psm:1:9: error[PSM413]: a value nests deeper than 500 levels (the nesting "
       "budget)"},
      {"not_finite", "not_finite.psm:1:9: error[PSM406]: 'LN' gives no finite number here"},
      {"overlapping_operand",
       "overlapping_operand.psm:1:1: error[PSM415]: '-': an operand of 300 cells that overlap or "
       "meet in part of a face is too many to unite one by one (at most 256; UNION its parts "
       "first)"},
      {"predicate_fails",
       "predicate_fails.psm:2:9: error[PSM403]: 'fact': parameter 'n' must satisfy IsNat, found "
       "-3"},
      {"predicate_not_bool",
       "predicate_not_bool.psm:1:9: error[PSM409]: the predicate of IF must give TRUE or FALSE, "
       "found a number 3"},
      {"runaway_recursion",
       "runaway_recursion.psm:1:22: error[PSM412]: recursion deeper than 2000 levels (the depth "
       "budget)"},
      {"runtime_cycle",
       "runtime_cycle.psm:2:13: error[PSM408]: the value of 'a' depends on itself (found while "
       "evaluating it)"},
      {"select_out_of_range",
       "select_out_of_range.psm:1:9: error[PSM407]: 'S3' selects element 3 of a sequence of 2"},
      // The geometry stage (PSM402 wrong arguments, PSM413-416, PSM420).
      {"bezier_mismatch",
       "bezier_mismatch.psm:1:1: error[PSM402]: 'BEZIER': control point 2 has 3 coordinates, the "
       "others 2"},
      {"boolean_2d",
       "boolean_2d.psm:1:1: error[PSM415]: '+' works on solids; an operand has 1 cell of fewer "
       "than 3 dimensions"},
      {"cuboid_13", "cuboid_13.psm:1:1: error[PSM402]: 'CUBOID' needs 1 to 7 sizes, found 13"},
      {"deep_struct",
       "deep_struct.psm:2:1: error[PSM413]: a polyhedron nests deeper than 2000 levels of STRUCT"},
      {"geometry_wrong_kind",
       "geometry_wrong_kind.psm:1:1: error[PSM402]: 'CUBOID' needs a sequence, found a string "
       "\"wide\""},
      // Charged to the memory budget before anything is allocated.
      {"intervals_budget",
       "intervals_budget.psm:1:1: error[PSM413]: evaluation needs more than 4000000 cells of "
       "memory (the memory budget)"},
      {"map_not_number",
       "map_not_number.psm:1:1: error[PSM402]: 'MAP': a coordinate function gave a string \"x\", "
       "not a number"},
      {"map_of_boolean",
       "map_of_boolean.psm:1:1: error[PSM416]: 'MAP' works on convex cells, and the result of a "
       "boolean is a solid without them (apply 'MAP' to the operands instead)"},
      {"measure_not_polyhedron",
       "measure_not_polyhedron.psm:1:1: error[PSM402]: 'MIN' needs a polyhedron, found a "
       "sequence <0, 1>"},
      {"mkpol_bad_cell",
       "mkpol_bad_cell.psm:1:1: error[PSM402]: 'MKPOL': a polyhedral cell names convex cell 2; "
       "there are 1"},
      {"mkpol_bad_vertex",
       "mkpol_bad_vertex.psm:1:1: error[PSM402]: 'MKPOL': convex cell 1 names vertex 4; there "
       "are 3"},
      {"no_polyhedron",
       "no_polyhedron.psm: error[PSM420]: nothing to build: no expression statement gives a "
       "polyhedron with area (a DEF alone is not drawn; end the file with an expression such as "
       "`column:<1, 10, 0.5>;`)"},
      {"rotate_equal_axes",
       "rotate_equal_axes.psm:1:1: error[PSM402]: 'R' needs two different coordinate indices and "
       "one angle, as R:<1, 2>:angle"},
      {"translate_mismatch",
       "translate_mismatch.psm:1:1: error[PSM402]: 'T' needs as many values as coordinate "
       "indices, found 2 and 1"},
      {"wrong_kind",
       "wrong_kind.psm:1:9: error[PSM402]: 'SIN' needs a number, found a string \"a\""},
  };
  return kExpected;
}

TEST(PlasmBadInput, EveryCatalogFileHasItsExactFirstDiagnostic) {
  const auto files = files_in(data_dir() / "bad", ".psm");
  ASSERT_GE(files.size(), 60U);
  insula::test::expect_catalog_first_lines(
      files, expected_first_lines(), [](const std::filesystem::path& path) {
        const auto start = std::chrono::steady_clock::now();
        std::string first = testing::first_build_error(read_file(path), path.filename().string());
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  1.0)
            << path.filename();
        return first;
      });
}

}  // namespace
}  // namespace insula::lang::plasm
