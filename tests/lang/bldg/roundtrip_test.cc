// Grammar -> model -> grammar round trips (issue 3 "Tests"): for every good grammar and for
// stochastic buildings, parse(print(m)) is m again (every field but source locations) and the
// printed text is canonical: print(parse(print(m))) == print(m).
#include <gtest/gtest.h>

#include <cstdlib>

#include "lang/bldg/printer.h"
#include "lang/bldg/stochastic.h"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

using testing::dump;

void expect_round_trip(const Building& model, const std::string& what) {
  SCOPED_TRACE(what);
  const std::string text = print_building(model);
  const base::Source source(what + ".printed.bldg", text);
  const auto again = parse_building(source);
  ASSERT_TRUE(again.ok()) << testing::errors(text) << text;
  EXPECT_EQ(dump(again.value()), dump(model)) << text;
  EXPECT_EQ(print_building(again.value()), text);
}

TEST(BldgRoundTrip, EveryGoodGrammar) {
  const auto files = testing::files_in(testing::data_dir(), ".bldg");
  ASSERT_GE(files.size(), 6U);
  for (const auto& path : files) {
    const Building model = testing::parse_ok(testing::read_file(path), path.filename().string());
    expect_round_trip(model, path.stem().string());
  }
}

// The canonical text of every good grammar, kept as a golden so a change of the printed form is
// deliberate (regenerate with INSULA_UPDATE_GOLDEN=1).
TEST(BldgRoundTrip, PrintedFormGoldens) {
  const std::filesystem::path golden_dir = testing::data_dir() / "golden";
  for (const auto& path : testing::files_in(testing::data_dir(), ".bldg")) {
    SCOPED_TRACE(path.filename().string());
    const std::string printed =
        print_building(testing::parse_ok(testing::read_file(path), path.filename().string()));
    insula::test::expect_golden(golden_dir / path.filename(), printed);
  }
}

TEST(BldgRoundTrip, StochasticBuildingsOfEveryShape) {
  for (const RandomShape shape :
       {RandomShape::kConvex, RandomShape::kL, RandomShape::kU, RandomShape::kT, RandomShape::kH}) {
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      RandomSpec spec;
      spec.shape = shape;
      spec.rooms_min = 2;
      spec.rooms_max = 9;
      expect_round_trip(random_building(spec, seed),
                        std::string(random_shape_name(shape)) + std::to_string(seed));
    }
  }
}

TEST(BldgRoundTrip, CommentsLayoutAndCaseDoNotMatter) {
  const Building messy = testing::parse_ok(
      "/* any order */ r -> DIVISION(\"wine cellar\", Big, 5, 1)\n"
      "f -> floor(2.5, VERTICAL):{r,}   # trailing comma\n"
      "b -> building(\"B \\\"1\\\"\", [(0,0),(6,0),(6,5),(0,5),]) : {p, w}; p -> "
      "buildingpart(gable, 2) : {f}\n"
      "w -> window(r, 1.1)\n");
  const std::string text = print_building(messy);
  EXPECT_EQ(text,
            "# \"B \\\"1\\\"\": ontology-based building grammar (seed 000; docs/bldg-language.md)\n"
            "b -> building(\"B \\\"1\\\"\", [(0, 0), (6, 0), (6, 5), (0, 5)]) : {p, w}\n"
            "p -> buildingpart(Gable, 2) : {f}\n"
            "f -> floor(2.5, vertical) : {r}\n"
            "r -> room(\"wine cellar\", big, 5, 1)\n"
            "w -> window(r, 1.1)\n");
  expect_round_trip(messy, "messy");
}

}  // namespace
}  // namespace insula::lang::bldg
