// Helpers for the CGA derivation tests: compile a grammar text, derive lots, summarise.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/compile.h"
#include "lang/cga/derive.h"
#include "lang/cga/parser.h"

namespace insula::lang::cga::testing {

// The compiled program of `text` (a failed parse or compile fails the test and returns null).
inline std::shared_ptr<const Program> compile_text(const std::string& text,
                                                   const CompileOptions& options = {},
                                                   const std::string& name = "test.cga") {
  const base::Source source(name, text);
  base::Result<Grammar> grammar = parse(source);
  if (!grammar.ok()) {
    ADD_FAILURE() << base::render(grammar.diagnostics().front());
    return nullptr;
  }
  auto program = compile(grammar.value(), source, options);
  if (!program.ok()) {
    ADD_FAILURE() << base::render(program.diagnostics().front());
    return nullptr;
  }
  return program.value();
}

inline Lot rectangle_lot(double w, double d, std::string id = "lot") {
  Lot lot;
  lot.id = std::move(id);
  lot.polygons.push_back({{{0, 0}, {w, 0}, {w, d}, {0, d}}, {}});
  return lot;
}

inline std::vector<LotResult> derive_all(const Program& program, const std::vector<Lot>& lots,
                                         const DeriveOptions& options = {}) {
  std::vector<LotResult> out;
  for (std::size_t i = 0; i < lots.size(); ++i)
    out.push_back(derive_lot(program, lots[i], i, options));
  return out;
}

// The rendered diagnostics of a result, one per line, without source lines.
inline std::string diagnostics_text(const LotResult& r) {
  std::string out;
  for (const base::Diagnostic& d : r.diagnostics) out += base::render(d) + "\n";
  return out;
}

inline std::uint64_t symbol_count(const Program& p, const LotResult& r, const std::string& name) {
  auto it = p.symbol_ids.find(name);
  return it == p.symbol_ids.end() ? 0 : r.symbol_counts[it->second];
}

}  // namespace insula::lang::cga::testing
