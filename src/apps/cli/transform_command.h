// `insula transform FILE.cga --to json|xmi|dot|xml -o OUT` (seed 004, §IV and §VII): the CGA
// model-driven tooling. Also reads a BuildingGen XML back into a grammar (`--to cga` from .xml).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace insula::cli {

struct TransformOptions {
  std::string input;
  std::string to;      // json, xmi, dot, graph-json, xml, cga
  std::string output;  // -o OUT (stdout when empty)
  bool quiet = false;
};

void add_transform_command(CLI::App& app, TransformOptions& options);
int run_transform(const TransformOptions& options);

}  // namespace insula::cli
