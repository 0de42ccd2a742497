// `insula check FILE.cga`.
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"
#include "lang/cga/parser.h"

namespace insula::cli {

std::optional<std::string> check_cga(const base::Source& source, bool quiet) {
  base::Result<lang::cga::Grammar> grammar = lang::cga::parse(source);
  print_diagnostics(grammar.diagnostics(), source, quiet);
  if (!grammar.ok()) return std::nullopt;
  std::size_t rules = 0;
  for (const auto& set : grammar->sets) rules += set.rules.size();
  return std::to_string(rules) + " rules, " + std::to_string(grammar->attrs.size()) + " attributes";
}

}  // namespace insula::cli
