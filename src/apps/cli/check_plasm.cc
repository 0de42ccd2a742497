// `insula check FILE.psm`: the PLaSM front half (lexer, parser, checker); every diagnostic goes
// to stderr, the summary line only when there is no error.
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"
#include "lang/plasm/checker.h"
#include "lang/plasm/parser.h"

namespace insula::cli {

std::optional<std::string> check_plasm(const base::Source& source, bool quiet) {
  base::Result<lang::plasm::Program> program = lang::plasm::parse(source);
  if (!program.ok()) {
    print_diagnostics(program.diagnostics(), source, quiet);
    return std::nullopt;
  }
  const lang::plasm::CheckResult checked = lang::plasm::check(program.value(), source);
  print_diagnostics(checked.diagnostics, source, quiet);
  if (!checked.ok) return std::nullopt;
  const auto plural = [](std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
  };
  return plural(checked.functions, "function") + ", " + plural(checked.values, "value") + ", " +
         plural(checked.expressions, "expression");
}

}  // namespace insula::cli
