// `insula build FILE.psm [-o OUT]... [--report R.json]`: parses, checks and evaluates a PLaSM
// program (seed 002) and writes the polyhedra its expression statements give
// (docs/plasm-language.md, "Output").
#include <cstdio>

#include <tbb/global_control.h>

#include <algorithm>
#include <filesystem>
#include <thread>

#include "apps/cli/asset_folders.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/stopwatch.h"
#include "io/svg_reader.h"
#include "lang/plasm/checker.h"
#include "lang/plasm/output.h"
#include "lang/plasm/parser.h"

namespace insula::cli {
namespace {

// SVG drawings a program names, read from its own folder (confined like assets) by io's reader.
lang::plasm::OutlineReader drawing_reader(const std::string& input) {
  const std::filesystem::path own = std::filesystem::path(input).parent_path();
  std::vector<std::string> folders = {own.empty() ? "." : own.string()};
  return [folders](const std::string& file, std::vector<lang::plasm::Outline>& out,
                   std::string& error) {
    const std::optional<std::filesystem::path> path = find_in_folders(folders, file, file, error);
    if (!path) return false;
    const std::optional<std::string> text = read_input_file(path->string());
    if (!text) {
      error = "cannot read '" + file + "'";
      return false;
    }
    base::Result<std::vector<io::SvgOutline>> outlines = io::read_svg(*text, file);
    if (!outlines.ok()) {
      error = base::render(outlines.diagnostics().front());
      return false;
    }
    for (io::SvgOutline& o : outlines.value()) {
      lang::plasm::Outline copy{std::move(o.id), {}, o.closed};
      for (const kernel::Vec2& p : o.points) copy.xy.insert(copy.xy.end(), {p.x, p.y});
      out.push_back(std::move(copy));
    }
    return true;
  };
}

}  // namespace

int build_plasm(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  const base::Source source(options.input, *text);
  base::Result<lang::plasm::Program> program = lang::plasm::parse(source);
  if (!program.ok()) {
    print_diagnostics(program.diagnostics(), source, options.quiet);
    return kExitInput;
  }
  const lang::plasm::CheckResult checked = lang::plasm::check(program.value(), source);
  print_diagnostics(checked.diagnostics, source, options.quiet);
  if (!checked.ok) return kExitInput;
  nlohmann::json report;
  Stopwatch stage;
  // Sequences and AA run their elements as parallel tasks; the output is the same for any
  // --threads (docs/plasm-language.md, "Parallel evaluation").
  const int threads = options.threads > 0
                          ? options.threads
                          : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  std::optional<base::Result<lang::plasm::ProgramOutput>> evaluated;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    lang::plasm::Budgets budgets;
    budgets.stop = [] { return interrupted(); };
    evaluated.emplace(lang::plasm::program_scene(program.value(), source, budgets,
                                                 drawing_reader(options.input)));
  }
  base::Result<lang::plasm::ProgramOutput>& output = *evaluated;
  report["seconds"]["evaluate"] = stage.seconds();
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (!output.ok()) {
    print_diagnostics(output.diagnostics(), source, options.quiet);
    return kExitInput;
  }
  const lang::plasm::ProgramOutput& out = output.value();
  std::size_t parts = 0;
  std::size_t triangles = 0;
  for (const shape::Building& b : out.scene.buildings) {
    parts += b.parts.size();
    for (const shape::Part& p : b.parts) triangles += p.mesh.triangle_count();
  }
  if (out.stats.skipped_cells > 0 && !options.quiet)
    std::fprintf(stderr,
                 "%s: warning: %zu cells not drawn (points, segments, or cells in 4D and more)\n",
                 options.input.c_str(), out.stats.skipped_cells);
  report["input"] = options.input;
  report["threads"] = threads;
  report["steps"] = out.steps;
  report["buildings"] = out.scene.buildings.size();
  report["parts"] = parts;
  report["triangles"] = triangles;
  if (out.stats.non_manifold_parts > 0 && !options.quiet)
    std::fprintf(stderr,
                 "%s: warning: %zu parts hold solids that touch (edges of more than two faces; "
                 "attribute non_manifold_edges)\n",
                 options.input.c_str(), out.stats.non_manifold_parts);
  report["non_manifold_parts"] = out.stats.non_manifold_parts;
  report["cells"] = {{"solid", out.stats.solid_cells},
                     {"surface", out.stats.surface_cells},
                     {"not_drawn", out.stats.skipped_cells}};
  return finish_build(options, out.scene, report, total);
}

}  // namespace insula::cli
