// Goldens of the report's `graph` section (§13) for example graphs: every count, leaf and
// entity record (attributes, areas, volumes, scopes) as `insula build --report` writes them,
// wall times left out. Regenerate with INSULA_REGENERATE=1 after a deliberate change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lang/graph/output.h"
#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

// Numbers rounded to 1e-6 (as the CGA derivation goldens), so compilers and sanitizer builds
// that round the last bit differently agree.
void round_numbers(nlohmann::ordered_json& value) {
  if (value.is_number_float()) {
    const double r = std::round(value.get<double>() * 1e6) / 1e6;
    value = r == 0 ? 0.0 : r;
    return;
  }
  if (!value.is_structured()) return;  // a primitive iterates as itself
  for (auto& item : value) round_numbers(item);
}

std::string report_of(const std::string& example) {
  const std::filesystem::path folder = std::filesystem::path(INSULA_SOURCE_DIR) / "examples/graph";
  Checked checked = read_and_check(folder, example);
  EXPECT_TRUE(checked.result.ok) << first_diagnostic(checked);
  if (!checked.result.ok) return "";
  const RunResult run = run_graph(checked.document.value(), checked.result, {});
  EXPECT_TRUE(run.ok);
  nlohmann::ordered_json report = graph_report(run);
  for (auto& [id, runs] : report["node_runs"].items()) runs.erase("seconds");
  round_numbers(report);
  return report.dump(1) + "\n";
}

void expect_golden(const std::string& example, const std::string& golden) {
  const std::string path = (data_dir() / "golden" / golden).string();
  const std::string actual = report_of(example);
  if (std::getenv("INSULA_REGENERATE") != nullptr) std::ofstream(path, std::ios::binary) << actual;
  std::ifstream in(path, std::ios::binary);
  std::stringstream expected;
  expected << in.rdbuf();
  EXPECT_EQ(actual, expected.str()) << path << " differs: run with INSULA_REGENERATE=1";
}

TEST(ReportGolden, FootprintTiles) {
  expect_golden("footprint_tiles.graph.json", "footprint_tiles.report.json");
}

TEST(ReportGolden, LotSubdivision) {
  expect_golden("lot_subdivision.graph.json", "lot_subdivision.report.json");
}

TEST(ReportGolden, SubgraphsAndSigns) {
  expect_golden("street_houses.graph.json", "street_houses.report.json");
}

}  // namespace
}  // namespace insula::lang::graph::testing
