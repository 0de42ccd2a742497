// Being written (issue: CGA model-driven tooling).
#include "apps/cli/transform_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>

#include "apps/cli/exit_codes.h"

namespace insula::cli {

void add_transform_command(CLI::App& app, TransformOptions& options) {
  CLI::App* transform =
      app.add_subcommand("transform", "model transformations of a CGA grammar (seed 004)");
  transform->add_option("INPUT", options.input, "a .cga grammar")->required();
  transform->add_option("--to", options.to, "json, xmi, dot, graph-json, xml or cga")->required();
  transform->add_option("-o,--output", options.output, "output file (default: standard output)");
  transform->add_flag("-q,--quiet", options.quiet, "print errors only");
}

int run_transform(const TransformOptions& options) {
  std::fprintf(stderr, "insula: %s: transform is not available yet\n", options.input.c_str());
  return kExitInternal;
}

}  // namespace insula::cli
