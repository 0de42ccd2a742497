// The bad-input catalog tests/data/bldg/bad/*.bldg: each file's first diagnostic, exactly, and
// no model from any of them (seed 000, §3.3: malformed rules never reach the geometry).
#include <gtest/gtest.h>

#include <map>

#include "test_util.h"

namespace insula::lang::bldg {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

const std::map<std::string, std::string>& expected_first_lines() {
  static const std::map<std::string, std::string> kExpected = {
      {"bad_character", "bad_character.bldg:4:24: error[BLD001]: unexpected character '$'"},
      {"bad_escape", "bad_escape.bldg:1:17: error[BLD005]: unknown escape sequence in string"},
      {"building_without_outline",
       "building_without_outline.bldg:1:14: error[BLD202]: 'building' expects a name and an "
       "outline (a ring or geojson(file, feature)), found 1"},
      {"cycle",
       "cycle.bldg:5:21: error[BLD213]: cycle: 'a' is among its own successors (through 'c')"},
      {"detached_cycle",
       "detached_cycle.bldg:6:21: error[BLD213]: cycle: 'x' is among its own successors (through "
       "'y')"},
      {"division_outside_floor",
       "division_outside_floor.bldg:1:51: error[BLD220]: division 'r' is outside a floor "
       "(divisions belong to a floor)"},
      {"door_between_storeys",
       "door_between_storeys.bldg:7:14: error[BLD233]: door 'd' joins rooms on storeys 0 and 1 "
       "(use 'stair' between storeys)"},
      {"door_to_container",
       "door_to_container.bldg:7:14: error[BLD231]: transition 'd' names 'a', which is not a room"},
      {"door_to_itself",
       "door_to_itself.bldg:5:14: error[BLD232]: door 'd' connects room 'r' with itself"},
      {"door_too_narrow",
       "door_too_narrow.bldg:5:18: error[BLD205]: width 0.1 is out of range [0.3, 20] (or 0 for "
       "the default)"},
      {"door_unknown_room",
       "door_unknown_room.bldg:5:14: error[BLD230]: transition 'd' names unknown division "
       "'kitchen'"},
      {"duplicate_symbol",
       "duplicate_symbol.bldg:5:1: error[BLD210]: symbol 'r' is already defined at line 4"},
      {"empty_floor",
       "empty_floor.bldg:3:16: error[BLD207]: 'f' needs successors: ': {symbol, ...}' after "
       "'floor(...)'"},
      {"entrance_not_bool",
       "entrance_not_bool.bldg:4:30: error[BLD203]: parameter of 'room' must be true or false "
       "(entrance), found the name 'yes'"},
      {"floor_outside_part",
       "floor_outside_part.bldg:1:48: error[BLD220]: floor 'f' is outside a building part"},
      {"fractional_walls",
       "fractional_walls.bldg:4:24: error[BLD203]: number of walls must be a whole number, found "
       "4.5"},
      {"geojson_arity",
       "geojson_arity.bldg:1:18: error[BLD202]: 'geojson' expects 2 parameters (file, feature), "
       "found 1"},
      {"hole_outside",
       "hole_outside.bldg:1:45: error[BLD206]: invalid outline: hole 1 lies outside the outer "
       "ring"},
      {"malformed_number", "malformed_number.bldg:3:12: error[BLD004]: malformed number '3m'"},
      {"missing_arrow",
       "missing_arrow.bldg:3:1: error[BLD102]: expected a rule 'symbol -> function(...)', found "
       "identifier 'f'"},
      {"missing_value",
       "missing_value.bldg:4:17: error[BLD103]: expected a value (number, string, name, point or "
       "ring), found ','"},
      {"negative_height",
       "negative_height.bldg:2:25: error[BLD205]: roof height -2 is out of range [0, 100]"},
      {"negative_windows",
       "negative_windows.bldg:4:27: error[BLD205]: number of windows -1 is out of range [0, 32]"},
      {"no_building",
       "no_building.bldg:1:1: error[BLD215]: no building axiom: one rule must be 'symbol -> "
       "building(name, outline)'"},
      {"outline_two_points",
       "outline_two_points.bldg:1:18: error[BLD206]: invalid outline: a ring needs at least 3 "
       "points, found 2"},
      {"part_parameter_count",
       "part_parameter_count.bldg:2:18: error[BLD202]: 'buildingpart' expects 2 parameters (roof, "
       "height), found 1"},
      {"part_without_floors",
       "part_without_floors.bldg:2:18: error[BLD221]: building part 'p' has no floors: ': {floor, "
       "...}' after 'buildingpart(...)'"},
      {"point_one_coordinate",
       "point_one_coordinate.bldg:1:33: error[BLD101]: expected ',' between the coordinates of a "
       "point, found ')'"},
      {"ring_without_comma",
       "ring_without_comma.bldg:1:31: error[BLD101]: expected ']' or ',' in the ring, found '('"},
      {"room_with_successors",
       "room_with_successors.bldg:4:26: error[BLD207]: 'r' is a room, a final symbol: it takes no "
       "successors"},
      {"self_intersecting_outline",
       "self_intersecting_outline.bldg:1:18: error[BLD206]: invalid outline: outer ring: edges 1-2 "
       "and 3-0 cross at (4, 3)"},
      {"set_without_comma",
       "set_without_comma.bldg:3:19: error[BLD101]: expected ',' or '}' in the set of 'f', found "
       "identifier 's'"},
      {"size_not_a_label",
       "size_not_a_label.bldg:4:17: error[BLD203]: parameter of 'room' must be a size label "
       "(small, medium or big), found a number"},
      {"stair_down",
       "stair_down.bldg:7:15: error[BLD233]: stair 'd' must go one storey up, from storey 1 to 2, "
       "but 'r' is on storey 0"},
      {"storey_too_low",
       "storey_too_low.bldg:3:12: error[BLD205]: storey height 1.2 is out of range [2, 20] (or 0 "
       "for the default)"},
      {"symbol_used_twice",
       "symbol_used_twice.bldg:5:21: error[BLD214]: symbol 'r' is already used in the set of 'a' "
       "(each symbol is used once: the rules form a tree)"},
      {"truncated_rule",
       "truncated_rule.bldg:6:1: error[BLD101]: expected '(' after the function name 'building', "
       "found end of file"},
      {"two_buildings",
       "two_buildings.bldg:5:6: error[BLD215]: a second building axiom 'c' (a file describes one "
       "building)"},
      {"unclosed_parameters",
       "unclosed_parameters.bldg:5:1: error[BLD101]: expected ')' to close the parameters of "
       "'room', found end of file"},
      {"unclosed_set",
       "unclosed_set.bldg:4:1: error[BLD101]: expected ',' or '}' in the set of 'f', found "
       "identifier 'r'"},
      {"undefined_symbol", "undefined_symbol.bldg:3:20: error[BLD211]: undefined symbol 'kitchen'"},
      {"unknown_function",
       "unknown_function.bldg:4:6: error[BLD201]: unknown function 'chamber' (building, "
       "buildingparts, buildingpart, floor, divisions, room, door, entrance, window, stair)"},
      {"unknown_roof",
       "unknown_roof.bldg:2:19: error[BLD204]: unknown roof kind 'Dome' (Flat, Pyramid, Hip, "
       "Mansard, HoledMansard, None, Gable, HipGlued)"},
      {"unterminated_comment",
       "unterminated_comment.bldg:5:1: error[BLD003]: unterminated block comment"},
      {"unterminated_string", "unterminated_string.bldg:4:11: error[BLD002]: unterminated string"},
      {"unused_symbol",
       "unused_symbol.bldg:5:1: error[BLD212]: unused symbol 'k' (no successor set refers to it)"},
  };
  return kExpected;
}

TEST(BldgBadInput, EveryCatalogFileHasItsExactFirstDiagnostic) {
  const auto files = files_in(data_dir() / "bad", ".bldg");
  ASSERT_GE(files.size(), 25U);
  insula::test::expect_catalog_first_lines(
      files, expected_first_lines(), [](const std::filesystem::path& path) -> std::string {
        const base::Source source(path.filename().string(), read_file(path));
        const auto result = parse_building(source);
        EXPECT_FALSE(result.ok());
        if (result.diagnostics().empty()) return "no diagnostic";
        return base::render(result.diagnostics().front());
      });
}

}  // namespace
}  // namespace insula::lang::bldg

namespace insula::lang::bldg {
namespace {

TEST(BldgModerator, ReportsEveryProblemOfAFileInOrder) {
  const std::string all = testing::errors(
      "b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p, d1, d2, s}\n"
      "p -> buildingpart(Flat, 3) : {f, g}\n"
      "f -> floor() : {a, b2}\n"
      "g -> floor() : {c}\n"
      "a -> room(hall, small)\n"
      "b2 -> room(hall, small)\n"
      "c -> room(hall, small)\n"
      "d1 -> door(a, c)\n"
      "d2 -> door(a, nowhere)\n"
      "s -> stair(c, a)\n");
  EXPECT_EQ(all,
            "t.bldg:8:15: error[BLD233]: door 'd1' joins rooms on storeys 0 and 1 (use 'stair' "
            "between storeys)\n"
            "t.bldg:9:15: error[BLD230]: transition 'd2' names unknown division 'nowhere'\n"
            "t.bldg:10:15: error[BLD233]: stair 's' must go one storey up, from storey 1 to 2, "
            "but 'a' is on storey 0\n");
}

TEST(BldgModerator, SyntaxErrorsHideStructureChecksButKeepParameterChecks) {
  const std::string all = testing::errors(
      "b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p}\n"
      "p -> buildingpart(Flat, 3) : {f}\n"
      "f floor() : {r}\n"
      "r -> room(hall, tiny)\n");
  EXPECT_EQ(all,
            "t.bldg:3:1: error[BLD102]: expected a rule 'symbol -> function(...)', found "
            "identifier 'f'\n"
            "t.bldg:4:17: error[BLD204]: unknown size label 'tiny' (small, medium or big)\n");
}

TEST(BldgModerator, ErrorsStopAtFifty) {
  std::string text =
      "b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p}\n"
      "p -> buildingpart(Flat, 3) : {f}\nf -> floor() : {r}\n"
      "r -> room(hall, small)\n";
  for (int i = 0; i < 80; ++i) {
    text += 'x';  // appended: GCC 12 -O3 reports a false -Wrestrict on "x" + std::string
    text += std::to_string(i);
    text += " -> room(hall, small)\n";
  }
  const base::Source source("t.bldg", text);
  const auto result = parse_building(source);
  ASSERT_EQ(result.diagnostics().size(), 51U);
  EXPECT_EQ(result.diagnostics().back().code, "BLD108");
}

TEST(BldgModerator, StructureRulesOfTheOntology) {
  // §4.1: parts hold floors, floors hold divisions; containers need children.
  EXPECT_EQ(testing::first_error("b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p}\n"
                                 "p -> buildingpart(Flat, 3) : {f}\n"
                                 "f -> floor() : {q}\n"
                                 "q -> buildingpart(Flat, 3) : {g}\n"
                                 "g -> floor() : {r}\n"
                                 "r -> room(hall, small)\n"),
            "t.bldg:3:17: error[BLD220]: building part 'q' cannot be inside a floor or division");
  EXPECT_EQ(testing::first_error("b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p, t}\n"
                                 "p -> buildingpart(Flat, 3) : {f}\n"
                                 "f -> floor() : {t2}\n"
                                 "t2 -> window(r)\n"
                                 "t -> entrance(f)\n"),
            "t.bldg:3:16: error[BLD207]: 'f' holds only transitions; it needs a division");
  EXPECT_EQ(testing::first_error("b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p}\n"
                                 "p -> buildingpart(Flat, 3) : {f}\n"
                                 "f -> floor() : {r}\n"
                                 "r -> room(hall, small)\n"
                                 "b2 -> divisions() : {b}\n"),
            "t.bldg:5:1: error[BLD212]: unused symbol 'b2' (no successor set refers to it)");
}

TEST(BldgModerator, AnyBytesGiveADiagnosticNotACrash) {
  for (const std::string& text :
       {std::string(), std::string("\0\0\0", 3), std::string("->->->"), std::string("a -> b(((((("),
        std::string(5000, '{'), std::string("x -> building(\"\xFF\", [(1e400, 0)])")}) {
    const base::Source source("t.bldg", text);
    const auto result = parse_building(source);
    EXPECT_FALSE(result.ok());
    ASSERT_FALSE(result.diagnostics().empty());
    EXPECT_GE(result.diagnostics().front().span.line, 1U);
  }
}

}  // namespace
}  // namespace insula::lang::bldg

namespace insula::lang::bldg {
namespace {

// Found by bldg_fuzz: a symbol first reached as the root of a detached cycle, then used again
// from another detached cycle, has no parent to name (it crashed the moderator).
TEST(BldgModerator, ReuseAcrossDetachedCycles) {
  const std::string all = testing::errors(
      "b -> building(x, [(0,0),(8,0),(8,6),(0,6)]) : {p}\n"
      "p -> buildingpart(Flat, 3) : {f}\n"
      "f -> floor() : {r}\n"
      "r -> room(hall, small)\n"
      "a -> divisions() : {b2}\n"
      "b2 -> divisions() : {a}\n"
      "c -> divisions() : {d}\n"
      "d -> divisions() : {c, a}\n");
  EXPECT_EQ(all,
            "t.bldg:6:22: error[BLD213]: cycle: 'a' is among its own successors (through 'b2')\n"
            "t.bldg:8:21: error[BLD213]: cycle: 'c' is among its own successors (through 'd')\n"
            "t.bldg:8:24: error[BLD214]: symbol 'a' is already used in another set (each symbol "
            "is used once: the rules form a tree)\n");
}

}  // namespace
}  // namespace insula::lang::bldg
