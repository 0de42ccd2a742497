// `insula build FILE.lua [--seed N] [--assets DIR]... [--set name=value]... [-o OUT]...
// [--report R.json]`: runs a component program (seed 001) in the sandboxed runtime, collects the
// tree's leaves and writes them. Assets (OBJ, GLB/glTF, FBX, DAE) are read only from the asset
// folders: the program's folder, its assets/ folder and the --assets folders.
#include <cstdio>
#include <filesystem>

#include "apps/cli/asset_folders.h"
#include "apps/cli/assets.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/plasm_assets.h"
#include "lang/lua/runtime.h"

namespace insula::cli {
namespace {

namespace fs = std::filesystem;

// --set values: limit_* entries set the runtime limits, the others become params.<name>.
bool apply_sets(const BuildOptions& options, lua::RunOptions& run, std::string& error) {
  std::vector<std::pair<std::string, shape::Value>> sets;
  if (!parse_sets(options.sets, sets, error)) return false;
  for (auto& [name, value] : sets) {
    const double* number = std::get_if<double>(&value);
    const bool limit = name.rfind("limit_", 0) == 0;
    if (limit && (number == nullptr || *number < 1 || *number > 1e15)) {
      error = "--set " + name + ": expected a number >= 1";
      return false;
    }
    if (name == "limit_instructions") {
      run.limits.instructions = static_cast<std::uint64_t>(*number);
    } else if (name == "limit_memory_mb") {
      run.limits.memory_bytes = static_cast<std::size_t>(*number) << 20;
    } else if (name == "limit_depth") {
      run.limits.call_depth = static_cast<int>(std::min(*number, 1e6));
    } else if (name == "limit_components") {
      run.limits.components = static_cast<std::size_t>(*number);
    } else if (limit) {
      error = "--set " + name +
              ": unknown limit (limit_instructions, limit_memory_mb, limit_depth, "
              "limit_components)";
      return false;
    } else {
      run.params.emplace_back(name, std::move(value));
    }
  }
  return true;
}

void count_geometry(const shape::Scene& scene, nlohmann::json& report) {
  std::size_t parts = 0;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  for (const shape::Building& b : scene.buildings) {
    for (const shape::Part& part : b.parts) {
      const kernel::Mesh& mesh = part.instance_of ? *part.instance_of : part.mesh;
      ++parts;
      vertices += mesh.vertex_count();
      triangles += mesh.triangle_count();
    }
  }
  report["buildings"] = scene.buildings.size();
  report["parts"] = parts;
  report["vertices"] = vertices;
  report["triangles"] = triangles;
}

// The program's own folder and its assets/ folder, then every --assets folder: the examples keep
// their meshes beside them, so `insula build examples/lua/hotel.lua` finds them (docs/lua-api.md).
std::vector<std::string> asset_folders(const BuildOptions& options) {
  const fs::path own = fs::path(options.input).parent_path();
  std::vector<std::string> folders = {own.empty() ? "." : own.string(), (own / "assets").string()};
  folders.insert(folders.end(), options.assets.begin(), options.assets.end());
  return folders;
}

}  // namespace

int build_lua(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  lua::RunOptions run;
  run.seed = options.seed;
  std::string error;
  if (!apply_sets(options, run, error)) {
    std::fprintf(stderr, "insula: %s\n", error.c_str());
    return kExitUsage;
  }
  for (const std::string& folder : options.assets) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
      std::fprintf(stderr, "insula: --assets %s: not a directory\n", folder.c_str());
      return kExitUsage;
    }
  }
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  const base::Source source(options.input, *text);
  const io::AssetLibrary library = folder_assets(asset_folders(options));
  const PlasmAssets assets(asset_folders(options), &library);  // FILE.psm#EXPRESSION parts
  run.assets = &assets;
  if (!options.quiet) {
    run.print = [&](const std::string& line) {
      std::fprintf(stderr, "%s: %s\n", options.input.c_str(), line.c_str());
    };
  }
  nlohmann::json report;
  Stopwatch stage;
  lua::Runtime runtime(std::move(run));
  const std::vector<base::Diagnostic> diagnostics = runtime.run(source);
  report["seconds"]["run"] = stage.seconds();
  print_diagnostics(diagnostics, source, options.quiet);
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (base::has_errors(diagnostics)) return kExitInput;
  stage = Stopwatch();
  shape::Scene scene = lua::collect_program(runtime.program());
  // texture() images come from the asset folders, as the program's assets do.
  const std::vector<std::string> folders = asset_folders(options);
  const std::vector<io::TextureFailure> textures =
      io::load_textures(scene, [&](std::string_view name, std::string& why) {
        return find_in_folders(folders, std::filesystem::path(name), std::string(name), why);
      });
  report["seconds"]["collect"] = stage.seconds();
  report_missing_textures(textures, options.input, options.quiet, report);
  const lua::RunStats stats = runtime.stats();
  report["input"] = options.input;
  report["seed"] = options.seed;
  report["components"] = runtime.tree().size();
  report["roots"] = runtime.tree().roots().size();
  report["operations"] = stats.operations;
  report["lua"] = {{"instructions", stats.instructions}, {"peak_memory_bytes", stats.peak_memory}};
  count_geometry(scene, report);
  return finish_build(options, scene, report, total);
}

}  // namespace insula::cli
