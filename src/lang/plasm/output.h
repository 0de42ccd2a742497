// What `insula build F.psm` writes (docs/plasm-language.md, "Output"): every expression
// statement whose value is a polyhedron becomes a building of the shared scene; its parts are the
// instances of the innermost top-level DEFs that produced its cells (a column placed ten times is
// ten `columna` parts), each with the path of DEF and WHERE names above it as attribute
// `plasm_path`. Cells outside any top-level DEF form one part named after the building.
#pragma once

#include <string>

#include "base/diagnostic.h"
#include "lang/plasm/ast.h"
#include "lang/plasm/complex_mesh.h"
#include "lang/plasm/eval.h"
#include "shape/scene.h"

namespace insula::lang::plasm {

struct ProgramOutput {
  shape::Scene scene;
  MeshStats stats;
  std::uint64_t steps = 0;
};

// Evaluates the program and converts its polyhedra. Fails with the first runtime error, or when
// no expression gives a polyhedron with area (PSM420).
// `outlines` reads the drawings SVG names (none: SVG fails).
base::Result<ProgramOutput> program_scene(const Program& program, const base::Source& source,
                                          Budgets budgets = {}, OutlineReader outlines = {});

// The scene of one polyhedron, as one building named `id`.
shape::Building polyhedron_building(const Polyhedron& polyhedron, const std::string& id,
                                    MeshStats& stats);

}  // namespace insula::lang::plasm
