// libFuzzer target for the .bldg front-end (docs/bldg-language.md): the parser, the rules'
// moderator, the printer and the restriction-rules reader. Beyond "no crash, no hang, no
// sanitizer report" it checks their contract on every input:
//  - a failure carries at least one error, a success none; every diagnostic has a code, a message
//    and a position inside the file (line >= 1);
//  - a parsed building prints to a grammar that parses back and prints the same (canonical);
//  - the same bytes read as restriction rules keep the same contract, and accepted rules print
//    to a text that reads back to the same text.
//
// Builds: with clang and INSULA_FUZZ=ON, fuzz/CMakeLists.txt links it with -fsanitize=fuzzer.
// With -DINSULA_FUZZ_REPLAY it gets a main() that feeds the files and folders named on the
// command line. tests/lang/bldg/bldg_fuzz_replay_test.cc includes this file with
// INSULA_FUZZ_NO_ENTRY to run check_bldg() over the corpus, the catalogs and mutations.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "lang/bldg/parser.h"
#include "lang/bldg/printer.h"
#include "lang/bldg/restrictions.h"

namespace insula::fuzz {

inline std::string check_diagnostics(const std::vector<base::Diagnostic>& diagnostics, bool ok,
                                     std::size_t lines) {
  for (const base::Diagnostic& d : diagnostics) {
    if (d.message.empty() || d.code.empty()) return "diagnostic without code or message";
    if (d.span.line < 1 || d.span.line > lines + 1) return "diagnostic outside the file";
    if (base::render(d).empty()) return "empty rendering";
  }
  const bool errors = base::has_errors(diagnostics);
  if (!ok && !errors) return "failure without an error diagnostic";
  if (ok && errors) return "success with an error diagnostic";
  return {};
}

// Empty when the front-end kept its contract on `text`, else what broke.
inline std::string check_bldg(std::string_view text) {
  const std::string owned(text);
  std::size_t lines = 1;
  for (const char c : owned) lines += c == '\n' ? 1 : 0;
  const base::Source source("fuzz.bldg", owned);
  const auto building = lang::bldg::parse_building(source);
  if (std::string p = check_diagnostics(building.diagnostics(), building.ok(), lines); !p.empty()) {
    return "bldg: " + p;
  }
  if (building.ok()) {
    const std::string printed = lang::bldg::print_building(building.value());
    const base::Source again_source("printed.bldg", printed);
    const auto again = lang::bldg::parse_building(again_source);
    if (!again.ok()) return "printed grammar does not parse:\n" + printed;
    if (lang::bldg::print_building(again.value()) != printed) return "printer not canonical";
  }
  const base::Source rules_source("fuzz.rules", owned);
  const auto rules = lang::bldg::parse_restrictions(rules_source);
  if (std::string p = check_diagnostics(rules.diagnostics(), rules.ok(), lines); !p.empty()) {
    return "rules: " + p;
  }
  if (rules.ok()) {
    const std::string printed = lang::bldg::print_restrictions(rules.value());
    const base::Source again_source("printed.rules", printed);
    const auto again = lang::bldg::parse_restrictions(again_source);
    if (!again.ok()) return "printed rules do not parse";
    if (lang::bldg::print_restrictions(again.value()) != printed) return "rules printer drifts";
  }
  return {};
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_bldg(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "bldg_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "bldg_fuzz_replay"
#include "replay_main.h"
#endif
