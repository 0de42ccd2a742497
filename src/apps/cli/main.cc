// The `insula` command: one binary, a verb per job (design.md, "Command line").
// Exit codes: 0 done, 1 input error, 2 usage error, 3 internal error.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "apps/cli/build_command.h"
#include "apps/cli/check_command.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/mass_command.h"
#include "apps/cli/random_command.h"
#include "apps/cli/transform_command.h"

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
  insula::cli::BuildOptions build;
  insula::cli::add_build_command(app, build);
  insula::cli::TransformOptions transform;
  insula::cli::add_transform_command(app, transform);
  insula::cli::RandomOptions random;
  insula::cli::add_random_command(app, random);
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
  if (app.got_subcommand("build")) return insula::cli::run_build(build);
  if (app.got_subcommand("transform")) return insula::cli::run_transform(transform);
  if (app.got_subcommand("random")) return insula::cli::run_random(random);
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
