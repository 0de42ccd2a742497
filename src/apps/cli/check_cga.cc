// `insula check FILE.cga`: parse (parser.h), then the static semantics (checker.h); every
// diagnostic goes to stderr, and the summary line only when there is no error.
#include <optional>
#include <string>

#include "apps/cli/cga_source.h"
#include "apps/cli/front_ends.h"
#include "lang/cga/checker.h"
#include "lang/cga/parser.h"

namespace insula::cli {

std::optional<std::string> check_cga(const base::Source& source, bool quiet) {
  return check_cga(source, quiet, std::string(), std::string());
}

std::optional<std::string> check_cga(const base::Source& file, bool quiet, const std::string& start,
                                     const std::string& workspace) {
  const CgaSource loaded = load_cga(file.name(), file.text(), workspace);
  const base::Source& source = *loaded.source;
  const base::Result<lang::cga::Grammar>& grammar = loaded.grammar;
  print_diagnostics(grammar.diagnostics(), source, quiet);
  if (!grammar.ok()) return std::nullopt;
  lang::cga::CheckOptions options;
  options.start = start;
  const lang::cga::CheckResult checked = lang::cga::check(grammar.value(), source, options);
  print_diagnostics(checked.diagnostics, source, quiet);
  if (!checked.ok) return std::nullopt;
  std::size_t warnings = 0;
  for (const base::Diagnostic& d : checked.diagnostics) {
    if (d.severity == base::Severity::kWarning) ++warnings;
  }
  const std::size_t reachable = checked.reachable_rules().size();
  return std::to_string(checked.rules.size()) + " rules (" + std::to_string(reachable) +
         " reachable), " + std::to_string(grammar->attrs.size()) + " attributes, start '" +
         checked.start_symbol + "', " + std::to_string(warnings) + " warning" +
         (warnings == 1 ? "" : "s");
}

}  // namespace insula::cli
