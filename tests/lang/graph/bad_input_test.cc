// The bad-input catalog tests/data/graph/bad/*.graph.json: every diagnostic of graph-format.md
// §12 that is found before running, each file's first diagnostic exactly (with its notes);
// expression errors point at their character inside the string, escapes counted as written.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "test_util.h"

namespace insula::lang::graph {
namespace {

const std::map<std::string, std::string>& expected() {
  static const std::map<std::string, std::string> kExpected = {
      {"attribute_in_expression.graph",
       "attribute_in_expression.graph.json:5:84: error[G020]: unknown attribute 'heigth' (did you "
       "mean 'height'?)"},
      {"entity_in_collective.graph",
       "entity_in_collective.graph.json:4:79: error[G022]: parameter 'amount' of 'top' "
       "(list.amount_filter) is evaluated once per execution and cannot read '@area'"},
      {"expression_result_type.graph",
       "expression_result_type.graph.json:4:66: error[G024]: parameter 'if' of 'big' "
       "(flow.condition) needs a bool; '= area() * 2' gives a number"},
      {"expression_syntax.graph",
       "expression_syntax.graph.json:3:80: error[G023]: expected ')' after the arguments of "
       "'max'"},
      {"expression_types.graph",
       "expression_types.graph.json:5:67: error[G024]: '@kind' is a string; '>' needs numbers"},
      {"source_without_entity.graph",
       "source_without_entity.graph.json:3:72: error[G022]: parameter 'width' of 'lot' "
       "(create.rectangle) has no current entity (no input port is connected) and cannot read "
       "'@w'"},
      {"unknown_graph_parameter.graph",
       "unknown_graph_parameter.graph.json:4:72: error[G021]: unknown graph parameter 'flors' "
       "(did you mean 'floors'?)"},
      {"bad_edge_string.graph",
       "bad_edge_string.graph.json:2:14: error[G002]: edge 'a.out => b.in' is not written "
       "'node.port -> node.port'"},
      {"integer_out_of_range.graph",
       "integer_out_of_range.graph.json:3:67: error[G025]: create.grid: parameter 'columns' "
       "expects an integer; got a number"},
      {"bad_name.graph",
       "bad_name.graph.json:1:62: error[G002]: node id '2nd' is not a valid name (letters, digits "
       "and '_', not starting with a digit)"},
      {"control_character.graph",
       "control_character.graph.json:1:114: error[G001]: invalid JSON: syntax error while parsing "
       "value - invalid string: control character U+0001 (SOH) must be escaped to \\u0001; last "
       "read: '\"\\u00e9\\t\\u0001<U+0001>'"},
      {"cycle_without_exit.graph",
       "cycle_without_exit.graph.json:4:13: warning[W001]: cycle a -> b -> a has no way out: "
       "entities entering it can never leave"},
      {"duplicate_edge.graph",
       "duplicate_edge.graph.json:6:31: error[G017]: duplicate edge 'a.out -> b.in'"},
      {"duplicate_field.graph",
       "duplicate_field.graph.json:1:82: error[G002]: duplicate field 'nodes'"},
      {"duplicate_id.graph",
       "duplicate_id.graph.json:4:13: error[G011]: duplicate node id 'mass' (first defined at "
       "line 3)"},
      {"edge_from_input.graph",
       "edge_from_input.graph.json:6:15: error[G016]: edge 'a.in -> b.in': 'a.in' is an input "
       "port"},
      {"enum_without_choices.graph",
       "enum_without_choices.graph.json:1:67: error[G002]: parameter 'kind': missing field "
       "'choices' (an enum lists its choices)"},
      {"error_in_subgraph_file.graph",
       "parts/broken.graph.json:3:5: error[G021]: shape.extrude: missing required parameter "
       "'height'\nnote: in subgraph 'wall' (parts/broken.graph.json)"},
      {"fixed_mode.graph",
       "fixed_mode.graph.json:4:73: error[G015]: port 'in' of 'sort' (list.order_by) is always "
       "collective"},
      {"gate_modes.graph",
       "gate_modes.graph.json:6:44: error[G030]: gate 'Lot': ports 'a.in' (single) and 'b.in' "
       "(collective) disagree"},
      {"inferred_type_over_cycle.graph",
       "inferred_type_over_cycle.graph.json:8:86: error[G013]: edge 'again.out -> mass.in': "
       "'again.out' carries path entities but 'mass.in' (shape.extrude) accepts shape entities"},
      {"invalid_json.graph",
       "invalid_json.graph.json:1:94: error[G001]: invalid JSON: syntax error while parsing value "
       "- unexpected ']'; expected '[', '{', or a literal"},
      {"leaf_in_subgraph.graph",
       "leaf_in_subgraph.graph.json:7:17: warning[W020]: subgraph 'house': leaf port "
       "'faces.rest' is not an output gate; its entities are dropped\nnote: in subgraph 'house' "
       "(#house)"},
      {"missing_parameter.graph",
       "missing_parameter.graph.json:3:5: error[G021]: create.rectangle: missing required "
       "parameter 'depth'"},
      {"missing_subgraph_file.graph",
       "missing_subgraph_file.graph.json:3:51: error[G031]: cannot read subgraph "
       "'parts/hous.graph.json': no such file"},
      {"missing_type.graph",
       "missing_type.graph.json:1:54: error[G002]: node 'a': missing field 'type'"},
      {"missing_version.graph",
       "missing_version.graph.json:1:1: error[G002]: missing field 'version'"},
      {"negative_seed.graph",
       "negative_seed.graph.json:1:64: error[G002]: field 'seed' must be an integer >= 0"},
      {"not_a_choice.graph",
       "not_a_choice.graph.json:4:63: error[G025]: shape.roof: parameter 'type' must be one of "
       "flat, shed, gable, hip, pyramid, mansard, holed_mansard, gambrel, half_hipped, saltbox, "
       "round, dome, onion; got 'bana'"},
      {"out_of_range.graph",
       "out_of_range.graph.json:4:68: error[G025]: shape.extrude: parameter 'height' must be >= "
       "0; got -3"},
      {"subgraph_cycle.graph",
       "subgraph_cycle.graph.json:4:72: error[G032]: subgraph cycle: #loop -> #loop\nnote: in "
       "subgraph 'outer' (#loop)"},
      {"subgraph_outside.graph",
       "subgraph_outside.graph.json:3:51: error[G031]: cannot read subgraph "
       "'../bad/escape.graph.json': it leads outside the graph's folder"},
      {"unconnected_port.graph",
       "unconnected_port.graph.json:4:13: error[G014]: required input port 'ray.targets' is not "
       "connected"},
      {"unknown_attribute.graph",
       "unknown_attribute.graph.json:5:64: error[G020]: unknown attribute 'heigth' (did you mean "
       "'height'?)"},
      {"unknown_edge_node.graph",
       "unknown_edge_node.graph.json:5:26: error[G012]: edge 'lot.out -> mas.in': no node 'mas'"},
      {"unknown_field.graph",
       "unknown_field.graph.json:1:43: error[G002]: unknown field 'nodez' (expected one of: "
       "format, version, name, doc, seed, parameters, attributes, nodes, edges, gates, "
       "subgraphs, limits, ui)"},
      {"unknown_inline_subgraph.graph",
       "unknown_inline_subgraph.graph.json:2:60: error[G031]: no inline subgraph '#nowhere' "
       "(define it under 'subgraphs')"},
      {"unknown_parameter.graph",
       "unknown_parameter.graph.json:4:58: error[G021]: unknown parameter 'heigth' of "
       "shape.extrude (did you mean 'height'?)"},
      {"unknown_port.graph",
       "unknown_port.graph.json:7:37: error[G012]: edge 'mass.output -> roof.in': node 'mass' "
       "(shape.extrude) has no output port 'output'; its output ports are: out"},
      {"unknown_type.graph",
       "unknown_type.graph.json:4:29: error[G010]: unknown node type 'shape.extrud' (did you mean "
       "'shape.extrude'?)"},
      {"unwritten_node_attribute.graph",
       "unwritten_node_attribute.graph.json:5:56: error[G020]: node 'n' (list.count) writes no "
       "attribute 'indx' (did you mean 'index'?); it writes: index, count"},
      {"version_2.graph",
       "version_2.graph.json:1:40: error[G003]: unsupported format version 2 (this reader knows "
       "1)"},
      {"wrong_entity_type.graph",
       "wrong_entity_type.graph.json:6:14: error[G013]: edge 'streets.out -> mass.in': "
       "'streets.out' carries path entities but 'mass.in' (shape.extrude) accepts shape "
       "entities"},
  };
  return kExpected;
}

TEST(GraphBadInput, EveryCatalogFileHasItsExactFirstDiagnostic) {
  const auto files = insula::test::files_in(testing::data_dir() / "bad", ".json");
  ASSERT_GE(files.size(), 43U);
  insula::test::expect_catalog_first_lines(
      files, expected(), [](const std::filesystem::path& path) {
        const auto checked = testing::read_and_check(path.parent_path(), path.filename().string());
        return testing::first_diagnostic(checked);
      });
}

// Every code of §12 that can be found before running has a file in the catalog.
TEST(GraphBadInput, CatalogCoversEveryCheckTimeCode) {
  std::set<std::string> codes;
  for (const auto& [stem, line] : expected()) {
    const std::size_t open = line.find('[');
    codes.insert(line.substr(open + 1, line.find(']') - open - 1));
  }
  for (const char* code :
       {"G001", "G002", "G003", "G010", "G011", "G012", "G013", "G014", "G015", "G016", "G017",
        "G020", "G021", "G025", "G030", "G031", "G032", "W001", "W020"}) {
    EXPECT_TRUE(codes.count(code)) << code;
  }
}

// A checked file has no error; the catalog's errors fail the check, its warnings do not.
TEST(GraphBadInput, WarningsAloneKeepTheGraphValid) {
  const auto checked =
      testing::read_and_check(testing::data_dir() / "bad", "cycle_without_exit.graph.json");
  ASSERT_TRUE(checked.document.ok());
  EXPECT_TRUE(checked.result.ok);
}

}  // namespace
}  // namespace insula::lang::graph
