// Booleans of right prisms along one axis as 2D booleans of their sections, extruded
// (boolean_prism.cc); the 3D boolean's fast path for walls with holes.
#pragma once

#include <optional>
#include <vector>

#include "kernel/boolean3d.h"
#include "kernel/mesh.h"
#include "lang/plasm/polyhedron.h"

namespace insula::lang::plasm {

// operands[0] op operands[1] op ... (or their symmetric difference with `exclusive`), when every
// cell is a right prism along one axis: the first operand's and, except in a difference, all
// others' over the same interval of it; in a difference the others' through it or beside it.
// nullopt when the operands are not such prisms.
std::optional<kernel::Mesh> prism_boolean(const std::vector<FlatComplex>& operands,
                                          kernel::BooleanOp op, bool exclusive = false);

}  // namespace insula::lang::plasm
