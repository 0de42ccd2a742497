// The bad-input catalog tests/data/cga/bad/*.cga: each file's first diagnostic, exactly.
#include <gtest/gtest.h>

#include <map>

#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

const std::map<std::string, std::string>& expected_first_lines() {
  static const std::map<std::string, std::string> kExpected = {
      {"bad_character", "bad_character.cga:1:11: error[CGA001]: unexpected character '$'"},
      {"unterminated_string", "unterminated_string.cga:1:16: error[CGA002]: unterminated string"},
      {"unterminated_comment",
       "unterminated_comment.cga:2:1: error[CGA003]: unterminated block comment"},
      {"malformed_number", "malformed_number.cga:1:17: error[CGA004]: malformed number '2x'"},
      {"bad_escape", "bad_escape.cga:1:18: error[CGA005]: unknown escape sequence in string"},
      {"missing_arrow",
       "missing_arrow.cga:1:6: error[CGA101]: expected '~>', '->' or '-->' before the successor, "
       "found identifier 'B'"},
      {"missing_successor",
       "missing_successor.cga:1:9: error[CGA103]: expected a successor (a shape, an operation, "
       "'ε', '[' or ']'), found ':'"},
      {"stray_arrow",
       "stray_arrow.cga:2:1: error[CGA102]: expected a rule, 'PRIORITY' or 'attr', found '~>'"},
      {"priority_not_number",
       "priority_not_number.cga:1:10: error[CGA110]: expected the priority (a natural number) "
       "after 'PRIORITY', found identifier 'one'"},
      {"priority_fraction",
       "priority_fraction.cga:1:10: error[CGA110]: expected the priority (a natural number) after "
       "'PRIORITY', found number 1.5"},
      {"priority_missing_colon",
       "priority_missing_colon.cga:2:1: error[CGA101]: expected ':' after the priority, found "
       "number 1"},
      {"rule_id_fraction",
       "rule_id_fraction.cga:1:1: error[CGA109]: a rule id must be a natural number or an "
       "identifier, found number 1.5"},
      {"missing_predecessor",
       "missing_predecessor.cga:1:4: error[CGA101]: expected identifier (the predecessor symbol) "
       "after the rule id, found '~>'"},
      {"unclosed_block",
       "unclosed_block.cga:2:1: error[CGA101]: expected '}' or '|' in the successor block, found "
       "number 2"},
      {"unclosed_arguments",
       "unclosed_arguments.cga:1:19: error[CGA101]: expected ')' to close the argument list of "
       "'T', found identifier 'B'"},
      {"unmatched_pop", "unmatched_pop.cga:1:11: error[CGA106]: ']' without a matching '['"},
      {"unclosed_push", "unclosed_push.cga:1:9: error[CGA107]: '[' is never closed by ']'"},
      {"split_arity",
       "split_arity.cga:1:9: error[CGA201]: 'BS' expects at least 2 arguments, found 1"},
      {"translate_arity",
       "translate_arity.cga:1:9: error[CGA201]: 'T' expects 3 arguments, found 2"},
      {"repeat_without_block",
       "repeat_without_block.cga:1:9: error[CGA202]: 'RR' needs a successor block '{ ... }'"},
      {"scale_with_block", "scale_with_block.cga:1:9: error[CGA203]: 'S' takes no successor block"},
      {"axis_not_string",
       "axis_not_string.cga:1:12: error[CGA204]: the first argument of 'BS' must be a string (the "
       "axis)"},
      {"comp_type_not_string",
       "comp_type_not_string.cga:1:12: error[CGA204]: the first argument of 'CS' must be a string "
       "(the component type)"},
      {"assign_in_condition",
       "assign_in_condition.cga:1:17: error[CGA101]: expected '==' to compare, found '='"},
      {"chained_comparison",
       "chained_comparison.cga:1:14: error[CGA101]: comparisons cannot be chained; use 'and' to "
       "combine them"},
      {"missing_condition",
       "missing_condition.cga:1:8: error[CGA104]: expected an expression, found '~>'"},
      {"bad_probability",
       "bad_probability.cga:1:13: error[CGA101]: expected a probability (a number or a "
       "parenthesised expression), found identifier 'high'"},
      {"empty_branch",
       "empty_branch.cga:1:28: error[CGA103]: expected a successor (a shape, an operation, 'ε', "
       "'[' or ']'), found '}'"},
      {"pattern_without_star",
       "pattern_without_star.cga:1:30: error[CGA101]: expected '*' after a repeat pattern '{ ... "
       "}', found '}'"},
      {"non_ascii_symbol", "non_ascii_symbol.cga:1:12: error[CGA001]: unexpected character 'ê'"},
      {"control_byte", "control_byte.cga:1:10: error[CGA001]: unexpected byte 0x01"},
      {"attr_without_name",
       "attr_without_name.cga:1:6: error[CGA101]: expected identifier (attribute name) after "
       "'attr', found '='"},
      // 1: A : ( ... : every '(' nests twice (parenthesis, inner expression), so the 51st
      // parenthesis, at column 8 + 50, is the one that goes past 100 levels.
      {"deep_parentheses",
       "deep_parentheses.cga:1:58: error[CGA105]: nesting deeper than 100 levels"},
      // 1: A ~> split("x"){ { { ... : the block is level 1, pattern k is level k + 1, so
      // pattern 100 (column 21 + 2 * 99) fails.
      {"deep_patterns", "deep_patterns.cga:1:219: error[CGA105]: nesting deeper than 100 levels"},
  };
  return kExpected;
}

TEST(CgaBadInput, EveryCatalogFileHasItsExactFirstDiagnostic) {
  const auto files = files_in(data_dir() / "bad", ".cga");
  ASSERT_GE(files.size(), 20U);
  insula::test::expect_catalog_first_lines(
      files, expected_first_lines(), [](const std::filesystem::path& path) {
        return testing::first_error(read_file(path), path.filename().string());
      });
}

}  // namespace
}  // namespace insula::lang::cga
