// Being written (issue: ontology-based building grammar, §4.3).
#include "apps/cli/random_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>

#include "apps/cli/exit_codes.h"

namespace insula::cli {

void add_random_command(CLI::App& app, RandomOptions& options) {
  CLI::App* random = app.add_subcommand("random", "stochastic traversable buildings (seed 000)");
  random->add_option("--count", options.count, "how many buildings")->check(CLI::Range(1, 100000));
  random->add_option("--seed", options.seed, "random seed");
  random->add_option("-o,--output", options.output_dir, "output folder")->required();
}

int run_random(const RandomOptions& options) {
  std::fprintf(stderr, "insula: %s: random is not available yet\n", options.output_dir.c_str());
  return kExitInternal;
}

}  // namespace insula::cli
