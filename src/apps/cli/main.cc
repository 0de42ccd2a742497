// The `insula` command: one binary, a verb per job (design.md, "Command line").
// Exit codes: 0 done, 1 input error, 2 usage error, 3 internal error.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "apps/cli/check_command.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/mass_command.h"

namespace {

constexpr const char* kDescription =
    "Insula generates buildings and cities from rules and footprints.\n"
    "Outputs are chosen by extension: .obj (+.mtl), .glb, .gltf, .city.json, .svg, .png.";

int run(int argc, char** argv) {
  CLI::App app{kDescription, "insula"};
  app.set_version_flag("--version", std::string("insula ") + INSULA_VERSION);
  app.require_subcommand(1);
  insula::cli::MassOptions mass;
  insula::cli::add_mass_command(app, mass);
  insula::cli::CheckOptions check;
  insula::cli::add_check_command(app, check);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return insula::cli::kExitUsage;
  }
  if (app.got_subcommand("mass")) return insula::cli::run_mass(mass);
  if (app.got_subcommand("check")) return insula::cli::run_check(check);
  return insula::cli::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "insula: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "insula: internal error\n");
  }
  return insula::cli::kExitInternal;
}
