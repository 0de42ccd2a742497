#include "lang/plasm/output.h"

#include <filesystem>
#include <utility>
#include <vector>

#include "kernel/mesh.h"

namespace insula::lang::plasm {

shape::Building polyhedron_building(const Polyhedron& polyhedron, const std::string& id,
                                    MeshStats& stats) {
  shape::Building building;
  building.id = id;
  const FlatComplex flat = flatten(polyhedron);
  std::vector<std::vector<std::uint32_t>> cells(flat.groups.size());
  for (std::uint32_t k = 0; k < flat.cells.size(); ++k) cells[flat.group[k]].push_back(k);
  std::vector<std::vector<std::uint32_t>> solids(flat.groups.size());
  for (std::uint32_t k = 0; k < flat.solids.size(); ++k) solids[flat.solid_group[k]].push_back(k);
  HullCache hulls;
  for (std::size_t g = 0; g < flat.groups.size(); ++g) {
    if (cells[g].empty() && solids[g].empty()) continue;
    shape::Part part;
    part.name = flat.groups[g].part.empty() ? id : flat.groups[g].part;
    part.kind = shape::PartKind::kBuildingPart;
    if (!flat.groups[g].path.empty()) part.attributes["plasm_path"] = flat.groups[g].path;
    if (!cells[g].empty()) part.mesh = complex_mesh(flat, cells[g], {}, stats, &hulls);
    for (std::uint32_t k : solids[g]) {
      if (flat.dim > 3) {
        ++stats.skipped_cells;
        continue;
      }
      ++stats.solid_cells;
      part.mesh.append(flat.solids[k]);
    }
    // A boolean's solid is a closed 2-manifold; several in one part (a boolean per cell, as
    // Listing 8's roof does) may touch along faces or edges. Such a part is marked.
    if (!solids[g].empty() && solids[g].size() + cells[g].size() > 1) {
      const kernel::MeshCheck check = kernel::check(kernel::weld(part.mesh));
      if (check.non_manifold_edges > 0) {
        part.attributes["non_manifold_edges"] = static_cast<double>(check.non_manifold_edges);
        ++stats.non_manifold_parts;
      }
    }
    if (!part.mesh.empty()) building.parts.push_back(std::move(part));
  }
  return building;
}

base::Result<ProgramOutput> program_scene(const Program& program, const base::Source& source,
                                          Budgets budgets, OutlineReader outlines) {
  Evaluator evaluator(program, source, budgets);
  evaluator.set_outline_reader(std::move(outlines));
  ProgramOutput out;
  const std::string stem = std::filesystem::path(source.name()).stem().string();
  for (std::size_t i = 0; i < program.statements.size(); ++i) {
    const Statement& s = program.statements[i];
    if (s.is_def) continue;
    base::Result<ValuePtr> value = evaluator.statement(i);
    if (!value.ok()) return base::Result<ProgramOutput>::failure(value.diagnostics());
    if (!value.value()->is_polyhedron()) continue;
    const std::uint32_t line = source.locate(s.range.begin).first;
    shape::Building b = polyhedron_building(*value.value()->polyhedron(),
                                            stem + "-line" + std::to_string(line), out.stats);
    if (!b.parts.empty()) out.scene.buildings.push_back(std::move(b));
  }
  out.steps = evaluator.steps_used();
  if (out.scene.buildings.empty())
    return base::Result<ProgramOutput>::failure({base::Diagnostic::error(
        "PSM420",
        "nothing to build: no expression statement gives a polyhedron with area (a DEF alone "
        "is not drawn; end the file with an expression such as `column:<1, 10, 0.5>;`)",
        base::Span::whole(source.name()))});
  return base::Result<ProgramOutput>(std::move(out));
}

}  // namespace insula::lang::plasm
