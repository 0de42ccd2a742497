#include "apps/cli/studio_command.h"

#include <CLI/CLI.hpp>

#include <filesystem>

#include "apps/cli/interrupt.h"
#include "apps/studio/server.h"

namespace insula::cli {

void add_studio_command(CLI::App& app, StudioCommandOptions& options) {
  CLI::App* studio = app.add_subcommand(
      "studio", "serve the web studio on DIR's files (prints the URL with its access token)");
  studio->add_option("dir", options.folder, "the folder to work on (default: .)");
  studio->add_option("--port", options.port, "port to listen on (default: any free port)")
      ->check(CLI::Range(0, 65535));
  studio->add_option("--host", options.host,
                     "address to bind (default 127.0.0.1: this machine only)");
}

int run_studio(const StudioCommandOptions& options) {
  install_interrupt_handlers();
  studio::StudioOptions serving;
  serving.folder = options.folder;
  serving.host = options.host;
  serving.port = options.port;
  serving.executable = std::filesystem::read_symlink("/proc/self/exe");
  serving.web = INSULA_WEB_DIR;
  serving.stop_requested = [] { return interrupted(); };
  return studio::serve(serving);
}

}  // namespace insula::cli
