// The `insula` command: one binary, a verb per job (design.md, "Command line").
// Exit codes: 0 done, 1 input error, 2 usage error, 3 internal error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "apps/cli/build_command.h"
#include "apps/cli/check_command.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_command.h"
#include "apps/cli/memory.h"
#include "apps/cli/random_command.h"
#include "apps/cli/ranks.h"
#include "apps/cli/studio_command.h"
#include "apps/cli/transform_command.h"
#include "apps/cli/warnings.h"
#include "base/format.h"

namespace {

constexpr const char* kDescription =
    "Insula generates buildings and cities from rules and footprints.\n"
    "Outputs are chosen by extension: .obj (+.mtl), .glb, .gltf, .city.json, .city.jsonl "
    "(CityJSONSeq), .svg, .png.";

// A first argument that is no verb and no option: CLI11 would only say that a subcommand is
// required, so the verbs are named here, the nearest one first when it is close.
bool unknown_verb(const CLI::App& app, const std::string& word) {
  if (word.empty() || word[0] == '-') return false;
  std::string nearest;
  std::size_t best = 3;  // suggest only within two edits
  std::string verbs;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == word) return false;
    verbs += (verbs.empty() ? "" : ", ") + sub->get_name();
    if (const std::size_t d = insula::base::edit_distance(word, sub->get_name()); d < best) {
      best = d;
      nearest = sub->get_name();
    }
  }
  std::fprintf(stderr, "insula: unknown command '%s'", word.c_str());
  if (!nearest.empty()) std::fprintf(stderr, "; did you mean '%s'?", nearest.c_str());
  std::fprintf(stderr, "\ncommands: %s (insula --help)\n", verbs.c_str());
  return true;
}

// Runs the chosen verb; the verbs that write files do so with the interrupt handlers installed
// (for good: see interrupt.h), and a run that was interrupted before its commit point exits with
// 128 + the signal whatever the verb returned.
template <typename Run>
int run_writing(const Run& run, bool quiet) {
  insula::cli::install_interrupt_handlers();
  const int code = run();
  insula::cli::finish_warnings(quiet);
  if (insula::cli::interrupted() && code != insula::cli::kExitDone) {
    return insula::cli::interrupt_exit_code();
  }
  return code;
}

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
  insula::cli::StudioCommandOptions studio;
  insula::cli::add_studio_command(app, studio);
  if (argc > 1 && unknown_verb(app, argv[1])) return insula::cli::kExitUsage;
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
  if (app.got_subcommand("mass")) {
    return run_writing([&] { return insula::cli::run_mass(mass); },
                       mass.quiet || !insula::cli::Ranks::leader());
  }
  if (app.got_subcommand("build")) {
    return run_writing([&] { return insula::cli::run_build(build); },
                       build.quiet || !insula::cli::Ranks::leader());
  }
  // Under mpirun only `mass` and `build` share their work (3D Tiles); any other verb runs on the
  // leader alone.
  if (insula::cli::Ranks::shared() && !insula::cli::Ranks::leader()) return insula::cli::kExitDone;
  if (app.got_subcommand("check")) {
    const int code = insula::cli::run_check(check);
    insula::cli::finish_warnings(check.quiet);
    return code;
  }
  if (app.got_subcommand("transform")) return insula::cli::run_transform(transform);
  if (app.got_subcommand("studio")) return insula::cli::run_studio(studio);
  if (app.got_subcommand("random")) {
    return run_writing([&] { return insula::cli::run_random(random); }, random.quiet);
  }
  return insula::cli::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  insula::cli::use_huge_pages();
  insula::cli::Ranks::start(argc, argv);
  // MPI ends after the verb, whatever it returned (a verb's collective calls are all made).
  struct StopRanks {
    ~StopRanks() { insula::cli::Ranks::stop(); }
  } stop_ranks;
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "insula: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "insula: internal error\n");
  }
  insula::cli::Ranks::abort(insula::cli::kExitInternal);
  return insula::cli::kExitInternal;
}
