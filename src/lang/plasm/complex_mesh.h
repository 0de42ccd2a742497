// From PLaSM complexes to the meshes every writer takes (docs/plasm-language.md, "Output").
// Three-dimensional cells become their boundary: each cell's convex hull, with the faces two
// cells share (the same corners, opposite sides) removed, so a conforming complex, such as MAP's
// simplices or a product of intervals, becomes one closed shell. Two-dimensional cells become
// faces (a surface; in the plane they face +z). Cells of lower dimension have no area and are
// counted, not exported; so are cells of complexes with more than three coordinates.
#pragma once

#include <cstdint>
#include <span>

#include "kernel/mesh.h"
#include "lang/plasm/polyhedron.h"

namespace insula::lang::plasm {

struct MeshStats {
  std::size_t solid_cells = 0;    // 3D cells
  std::size_t surface_cells = 0;  // 2D cells
  std::size_t skipped_cells = 0;  // points, segments, cells in 4D and more, hulls that failed
};

// The mesh of the cells of `flat` listed in `cells` (all of them when empty), faces tagged `tag`.
kernel::Mesh complex_mesh(const FlatComplex& flat, std::span<const std::uint32_t> cells,
                          kernel::FaceTag tag, MeshStats& stats);

}  // namespace insula::lang::plasm
