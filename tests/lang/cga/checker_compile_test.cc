// Differential test of the checker against the compiler (compile.h): every token mutation of the
// example and corpus grammars that the checker accepts must also compile, so `insula build` never
// stops in the compiler (CGA5xx) on a grammar `insula check` passed. The checker may reject more
// (the §IV.B constraints are its own); the converse is not asserted.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

#include "lang/cga/checker.h"
#include "lang/cga/compile.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

TEST(CgaCheckerCompile, WhatTheCheckerAcceptsCompiles) {
  std::vector<std::string> corpus;
  for (const auto& path : files_in(data_dir(), ".cga")) corpus.push_back(read_file(path));
  const auto examples = std::filesystem::path(INSULA_SOURCE_DIR) / "examples" / "cga";
  if (std::filesystem::exists(examples)) {
    for (const auto& path : files_in(examples, ".cga")) corpus.push_back(read_file(path));
  }
  // Replacements that keep many mutants parseable: numbers, sizes, words, operations, blocks.
  const std::vector<std::string> words = {
      "0",     "-1",        "1.5",        "400",   "ε",    "[",        "]",       "\"XY\"",
      "\"q\"", "A",         "front",      "split", "comp", "T",        "Rx",      ":",
      "|",     "~>",        "2r",         "~1",    "x",    "Shape.sx", "rand(1)", "nil()",
      "\"f\"", "offset(1)", "extrude(2)", "{ A }", "'0.5"};
  std::uint64_t state = 12345;  // fixed seed: deterministic
  std::size_t accepted = 0;
  for (const std::string& text : corpus) {
    if (text.empty()) continue;
    for (int round = 0; round < 500; ++round) {
      std::string mutated = text;
      for (int k = 0; k < 2; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        const std::size_t end = std::min(mutated.size(), at + 1 + (state >> 7) % 3);
        mutated.replace(at, end - at, words[(state >> 17) % words.size()]);
      }
      const base::Source source("m.cga", mutated);
      const auto grammar = parse(source);
      if (!grammar.ok() || !check(grammar.value(), source).ok) continue;
      ++accepted;
      const auto program = compile(grammar.value(), source);
      ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front(), &source) << "\n"
                                << mutated;
    }
  }
  EXPECT_GT(accepted, 500U);
}

}  // namespace
}  // namespace insula::lang::cga
