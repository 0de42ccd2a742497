// PLaSM parts for the other front-ends (issue 13, "One engine, three ways in"): a CGA i() or a Lua
// insert names an asset `FILE.psm#EXPRESSION`, and the expression, evaluated with the file's DEFs
// in scope, gives the mesh the insert fits to the scope, like an OBJ asset
// (docs/plasm-language.md, "Parts for CGA and Lua"). The app resolves the file; this layer only
// evaluates. `FILE.psm` alone means the file's last expression.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "kernel/mesh.h"
#include "lang/plasm/eval.h"

namespace insula::lang::plasm {

// Splits an asset name at its first '#': {"col.psm", "columna:<1, 10, 0.5>"}; the expression is
// empty when there is no '#'.
std::pair<std::string, std::string> split_part_name(std::string_view name);

// The mesh of `expression` evaluated after the program `file` (every part's mesh appended),
// turned into the asset convention (y up: PLaSM's z becomes y, its y becomes -z). Null with
// `error` set to the first diagnostic, rendered, when the program or the expression fails or
// gives no polyhedron with area.
std::shared_ptr<const kernel::Mesh> part_mesh(const base::Source& file, std::string_view expression,
                                              std::string& error, Budgets budgets = {});

}  // namespace insula::lang::plasm
