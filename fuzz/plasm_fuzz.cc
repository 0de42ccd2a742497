// libFuzzer target for the PLaSM front-end (docs/plasm-language.md): lexer, parser, checker,
// evaluator.
// For any bytes:
//   - parse() fails with at least one error, every diagnostic positioned and coded PSM, or
//     succeeds with no error;
//   - a parsed program dumps (ast_dump.h) to the same text when a comment is appended to the
//     source (comments and trailing text change nothing), and the checker's diagnostics are
//     positioned PSM3xx codes, with ok exactly when there is no error;
//   - a checked program evaluates (with small budgets, so no input runs long) to values or to one
//     positioned PSM4xx diagnostic, the same one on a second run.
//   - a program that evaluates converts to a scene as `insula build` does (program_scene, the same
//     small budgets) or fails with one PSM4xx diagnostic (PSM420, nothing drawn, names the file
//     only); every part's mesh has finite positions and faces of at least 3 valid vertices, and
//     a second conversion gives the same parts, counts and measures.
// Builds as fuzz/geojson_fuzz.cc: libFuzzer with clang and INSULA_FUZZ=ON, a replay main with
// INSULA_FUZZ_REPLAY; tests/lang/plasm/plasm_fuzz_replay_test.cc includes it with
// INSULA_FUZZ_NO_ENTRY.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/plasm/ast_dump.h"
#include "lang/plasm/checker.h"
#include "lang/plasm/eval.h"
#include "lang/plasm/output.h"
#include "lang/plasm/parser.h"

namespace insula::fuzz {

// Empty when every diagnostic is positioned, has a message and a code starting with `prefix`.
inline std::string check_diagnostics(const std::vector<base::Diagnostic>& diagnostics,
                                     std::string_view prefix) {
  for (const base::Diagnostic& d : diagnostics) {
    if (d.message.empty()) return "empty diagnostic message";
    if (d.span.line == 0 || d.span.column == 0)
      return "diagnostic without a position: " + d.message;
    if (d.code.rfind(prefix, 0) != 0) return "unexpected diagnostic code " + d.code;
  }
  return {};
}

// The meshes of a scene as text (per part: its name, counts and measures), or what is wrong with
// them. Not the vertex order: the kernel's booleans (CGAL corefinement) number the vertices of
// one result differently from one call to the next in a process.
inline std::string scene_text(const shape::Scene& scene, std::string& problem) {
  std::string text;
  for (const shape::Building& b : scene.buildings) {
    for (const shape::Part& part : b.parts) {
      const kernel::Mesh& m = part.mesh;
      for (const kernel::Vec3& p : m.positions())
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          problem = "a mesh position is not finite";
      for (std::size_t f = 0; f < m.face_count(); ++f) {
        if (m.face(f).size() < 3) problem = "a face with fewer than 3 vertices";
        for (std::uint32_t v : m.face(f))
          if (v >= m.vertex_count()) problem = "a face names a vertex the mesh lacks";
      }
      char measures[128];
      std::snprintf(measures, sizeof measures, " %zu %zu %.6g %.6g\n", m.vertex_count(),
                    m.face_count(), kernel::volume(m), kernel::surface_area(m));
      text += b.id + " " + part.name + measures;
    }
  }
  return text;
}

// The contract of program_scene for a program whose values evaluate.
inline std::string check_scene(const lang::plasm::Program& program, const base::Source& source,
                               const lang::plasm::Budgets& budgets) {
  const auto scene = lang::plasm::program_scene(program, source, budgets);
  if (!scene.ok()) {
    if (scene.diagnostics().size() != 1) return "conversion failed without exactly one diagnostic";
    const base::Diagnostic& d = scene.diagnostics()[0];
    if (d.code == "PSM420") return d.span.file == source.name() ? "" : "PSM420 names no file";
    return check_diagnostics(scene.diagnostics(), "PSM4");
  }
  std::string problem;
  const std::string text = scene_text(scene.value().scene, problem);
  if (!problem.empty()) return problem;
  const auto again = lang::plasm::program_scene(program, source, budgets);
  if (!again.ok()) return "a second conversion failed";
  return scene_text(again.value().scene, problem) == text ? "" : "scenes differ between runs";
}

// Empty when every contract above holds for `bytes`, else what broke.
inline std::string check_plasm(std::string_view bytes) {
  const base::Source source("fuzz.psm", std::string(bytes));
  const base::Result<lang::plasm::Program> result = lang::plasm::parse(source);
  if (!result.ok()) {
    if (!base::has_errors(result.diagnostics())) return "failure without an error diagnostic";
    return check_diagnostics(result.diagnostics(), "PSM");
  }
  if (base::has_errors(result.diagnostics())) return "success with an error diagnostic";
  const std::string dumped = lang::plasm::dump(result.value(), source);
  const base::Source commented("fuzz.psm", std::string(bytes) + "\n% fuzz %\n");
  const base::Result<lang::plasm::Program> again = lang::plasm::parse(commented);
  if (!again.ok()) return "an appended comment broke the parse";
  if (lang::plasm::dump(again.value(), commented) != dumped)
    return "an appended comment changed the AST";
  const lang::plasm::CheckResult checked = lang::plasm::check(result.value(), source);
  if (checked.ok == base::has_errors(checked.diagnostics))
    return "check ok disagrees with its errors";
  if (!checked.ok) return check_diagnostics(checked.diagnostics, "PSM3");
  lang::plasm::Budgets budgets;
  budgets.steps = 20'000;
  budgets.depth = 200;
  budgets.cells = 100'000;
  budgets.nesting = 50;
  const auto values = lang::plasm::value_summaries(result.value(), source, budgets);
  const auto again_values = lang::plasm::value_summaries(result.value(), source, budgets);
  if (values.ok() != again_values.ok()) return "evaluation is not deterministic";
  if (values.ok()) {
    if (values.value() != again_values.value()) return "values differ between runs";
    return check_scene(result.value(), source, budgets);
  }
  if (values.diagnostics().size() != 1) return "evaluation failed without exactly one diagnostic";
  if (base::render(values.diagnostics()[0]) != base::render(again_values.diagnostics()[0]))
    return "evaluation errors differ between runs";
  return check_diagnostics(values.diagnostics(), "PSM4");
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_plasm(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "plasm_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "plasm_fuzz_replay"
#define INSULA_FUZZ_REPLAY_RECURSIVE  // the test data nests its bad-input catalog
#include "replay_main.h"
#endif
