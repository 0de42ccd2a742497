// From PLaSM complexes to the meshes every writer takes (docs/plasm-language.md, "Output").
// Three-dimensional cells become their boundary: each cell's convex hull, with the faces two
// cells share (the same corners, opposite sides) removed, so a conforming complex, such as MAP's
// simplices or a product of intervals, becomes one closed shell. Two-dimensional cells become
// faces (a surface; in the plane they face +z). Cells of lower dimension have no area and are
// counted, not exported; so are cells of complexes with more than three coordinates.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/mesh.h"
#include "lang/plasm/polyhedron.h"

namespace insula::lang::plasm {

struct MeshStats {
  std::size_t solid_cells = 0;    // 3D cells
  std::size_t surface_cells = 0;  // 2D cells
  std::size_t skipped_cells = 0;  // points, segments, cells in 4D and more, hulls that failed
  // Parts holding booleans' solids beside other solids or cells whose mesh has edges shared by
  // more than two faces (solids that touch): marked, not merged (docs/plasm-language.md).
  std::size_t non_manifold_parts = 0;
};

// The faces of stored cells already hulled (FlatComplex::origin), for the complex_mesh calls of
// one flattened complex: a column placed a hundred times is hulled once.
struct HullCache {
  struct Entry {
    bool known = false;
    bool mirrored = false;  // the placement it was hulled under reverses orientation
    std::vector<std::vector<std::uint32_t>> loops;  // outward faces, indices into the cell
  };
  std::vector<Entry> entries;  // by origin
  // The mesh vertex of each point of the complex met so far (kNone: not yet), so a point shared
  // by many cells is welded once; valid because all cells of a point go to one mesh.
  static constexpr std::uint32_t kNone = 0xFFFFFFFFU;
  std::vector<std::uint32_t> vertex;
};

// The mesh of the cells of `flat` listed in `cells` (all of them when empty), faces tagged `tag`.
// With a cache, cells that flat.origin names are hulled once for all their instances.
kernel::Mesh complex_mesh(const FlatComplex& flat, std::span<const std::uint32_t> cells,
                          kernel::FaceTag tag, MeshStats& stats, HullCache* cache = nullptr);

}  // namespace insula::lang::plasm
