// Mesh goldens of the examples (tests/data/plasm/mesh/<name>.mesh): what `insula build` draws for
// each examples/plasm/*.psm, per building and part: faces, vertices, volume, area, bounding box
// (rounded to 1e-6) and whether the welded mesh is closed. A program that draws nothing keeps
// its diagnostic as its golden. Regenerate with INSULA_UPDATE_GOLDEN=1, and read the diff.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "io/svg_reader.h"
#include "kernel/mesh.h"
#include "lang/plasm/output.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

std::string fixed(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", x);
  return std::strcmp(buffer, "-0.000000") == 0 ? "0.000000" : buffer;
}

std::string point(kernel::Vec3 p) {
  std::ostringstream out;
  out << "(" << fixed(p.x) << ", " << fixed(p.y) << ", " << fixed(p.z) << ")";
  return out.str();
}

std::string part_summary(const shape::Part& part) {
  const kernel::Mesh welded = kernel::weld(part.mesh);
  const kernel::MeshCheck check = kernel::check(welded);
  const kernel::Bounds3 box = part.mesh.bounds();
  std::ostringstream out;
  out << "  part " << part.name;
  if (const auto it = part.attributes.find("plasm_path"); it != part.attributes.end())
    out << " [" << shape::to_string(it->second) << "]";
  out << "\n    faces " << part.mesh.face_count() << ", vertices " << welded.vertex_count()
      << ", components " << check.components << ", closed " << (check.closed ? "yes" : "no")
      << ", non-manifold edges " << check.non_manifold_edges << "\n    volume "
      << fixed(kernel::volume(part.mesh)) << ", area " << fixed(kernel::surface_area(part.mesh))
      << "\n    bounds " << point(box.min) << " - " << point(box.max) << "\n";
  return out.str();
}

// SVG drawings beside the example, read by io's reader as `insula build` reads them.
OutlineReader drawings_beside(const std::filesystem::path& file) {
  const std::filesystem::path folder = file.parent_path();
  return [folder](const std::string& name, std::vector<Outline>& out, std::string& error) {
    const auto outlines = io::read_svg(testing::read_file(folder / name), name);
    if (!outlines.ok()) {
      error = base::render(outlines.diagnostics().front());
      return false;
    }
    for (const io::SvgOutline& o : outlines.value()) {
      Outline copy{o.id, {}, o.closed};
      for (const kernel::Vec2& p : o.points) copy.xy.insert(copy.xy.end(), {p.x, p.y});
      out.push_back(std::move(copy));
    }
    return true;
  };
}

std::string scene_summary(const std::filesystem::path& file) {
  const base::Source source(file.filename().string(), testing::read_file(file));
  const auto program = parse(source);
  if (!program.ok()) return base::render(program.diagnostics().front()) + "\n";
  const auto out = program_scene(program.value(), source, {}, drawings_beside(file));
  if (!out.ok()) return base::render(out.diagnostics().front()) + "\n";
  std::ostringstream text;
  text << "cells: " << out->stats.solid_cells << " solid, " << out->stats.surface_cells
       << " surface, " << out->stats.skipped_cells << " not drawn\n";
  for (const shape::Building& b : out->scene.buildings) {
    text << "building " << b.id << ": " << b.parts.size() << " parts\n";
    for (const shape::Part& part : b.parts) text << part_summary(part);
  }
  return text.str();
}

TEST(PlasmMeshGolden, EveryExampleMatchesItsGolden) {
  const auto files = testing::files_in(testing::examples_dir(), ".psm");
  ASSERT_GE(files.size(), 9U);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    insula::test::expect_golden(testing::data_dir() / "mesh" / (file.stem().string() + ".mesh"),
                                scene_summary(file));
  }
}

}  // namespace
}  // namespace insula::lang::plasm
