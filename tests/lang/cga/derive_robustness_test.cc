// Bad and odd input never crashes or hangs the engine: every CGA corpus file, every truncation of
// it and a set of byte mutations that still parse and compile is derived (small limits) on a
// rectangle, an L-shaped and a degenerate-ish thin lot; each run ends ok or with error diagnostics.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "derive_util.h"
#include "lang/cga/derive.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

std::vector<Lot> odd_lots() {
  Lot l;
  l.id = "l";
  l.polygons.push_back({{{0, 0}, {12, 0}, {12, 4}, {4, 4}, {4, 10}, {0, 10}}, {}});
  Lot thin;
  thin.id = "thin";
  thin.polygons.push_back({{{0, 0}, {30, 0}, {30, 0.05}, {0, 0.05}}, {}});
  return {testing::rectangle_lot(14, 9), l, thin};
}

// Derives `text` if it parses and compiles; false when it did not get that far.
bool derive_text(const std::string& text, const std::vector<Lot>& lots) {
  const base::Source source("fuzz.cga", text);
  base::Result<Grammar> grammar = parse(source);
  if (!grammar.ok()) return false;
  auto program = compile(grammar.value(), source);
  if (!program.ok()) return false;
  DeriveOptions options;
  options.limits.max_depth = 200;
  options.limits.max_shapes = 20000;
  for (std::size_t i = 0; i < lots.size(); ++i) {
    const LotResult r = derive_lot(*program.value(), lots[i], i, options);
    if (!r.ok) {
      EXPECT_TRUE(base::has_errors(r.diagnostics)) << text;
    }
    EXPECT_LE(r.shapes, options.limits.max_shapes + 1) << text;
  }
  return true;
}

std::vector<std::filesystem::path> corpus() {
  auto files = testing::files_in(testing::data_dir(), ".cga");
  for (const auto& f : testing::files_in(testing::data_dir() / "derive", ".cga")) {
    files.push_back(f);
  }
  return files;
}

TEST(DeriveRobustness, CorpusTruncationsAndMutations) {
  const std::vector<Lot> lots = odd_lots();
  std::size_t derived = 0;
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return state >> 33;
  };
  for (const auto& path : corpus()) {
    SCOPED_TRACE(path.string());
    const std::string text = testing::read_file(path);
    derived += derive_text(text, lots) ? 1 : 0;
    // Truncations at line ends (every prefix of whole lines).
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1)) {
      derived += derive_text(text.substr(0, at), lots) ? 1 : 0;
    }
    // Mutations: a digit, an operator or a size marker replaced somewhere.
    static constexpr char kBytes[] = "0123456789~'r-*/{}|:()";
    for (int k = 0; k < 60 && !text.empty(); ++k) {
      std::string m = text;
      m[next() % m.size()] = kBytes[next() % (sizeof kBytes - 1)];
      derived += derive_text(m, lots) ? 1 : 0;
    }
  }
  EXPECT_GT(derived, 50U);  // enough inputs got as far as the engine
}

TEST(DeriveRobustness, PathologicalGrammars) {
  const std::vector<Lot> lots = odd_lots();
  const char* grammars[] = {
      "Lot --> split(\"x\"){ { ~0: A }* }\n",
      "Lot --> split(\"x\"){ { 0: A }* | ~1: B }\n",
      "Lot --> split(\"x\"){ 1e-12: A | ~1e300: B }\n",
      "Lot --> RR(\"XYZ\", 0.001){ A }\n",
      "Lot --> split(\"z\"){ 1: A }\n",
      "Lot --> S(0, 0, 0) split(\"x\"){ 1: A }\n",
      "Lot --> extrude(1e9) comp(\"e\"){ A } \nA --> comp(\"v\"){ B }\n",
      "Lot --> offset(-100){ inside: A | border: B }\n",
      "Lot --> setback(1000){ front: A | remainder: B }\n",
      "Lot --> roofMansard(89, 89, 0, 0){ R }\n",
      "Lot --> [ [ [ ] ] ] A\n",
      "Lot --> r(1e308, 0, 0) T(1e308, 0, 0) extrude(1) A\n",
      "attr a = b\nattr b = a\nLot --> extrude(a) A\n",
      "Lot --> i(\"nothing.obj\") Pshape(\"none.obj\") A\n",
      "Lot --> color(\"red\") A\n",
      "Lot --> A A A A A A A A\nA --> Lot\n",
  };
  for (const char* g : grammars) {
    SCOPED_TRACE(g);
    EXPECT_TRUE(derive_text(g, lots));
  }
}

}  // namespace
}  // namespace insula::lang::cga
