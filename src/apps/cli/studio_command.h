// `insula studio [DIR] [--port N] [--host H]` (issue 15; docs/studio.md): the local web studio on
// DIR's files (apps/studio/server.h), until Ctrl-C.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace insula::cli {

struct StudioCommandOptions {
  std::string folder = ".";
  std::string host = "127.0.0.1";
  int port = 0;
};

void add_studio_command(CLI::App& app, StudioCommandOptions& options);
int run_studio(const StudioCommandOptions& options);

}  // namespace insula::cli
