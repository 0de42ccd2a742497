// Unification of polygon meshes (seed 003, §4.1: "unification does the additional step of finding
// and connecting common faces, vertices, and edges" after merging) and the grouping behind its
// "adjacency merge" (Fig. 6: tiles are merged and unified when they share edges).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "kernel/mesh.h"

namespace insula::kernel {

// The mesh with its common parts connected, in five steps (docs/graph-executor.md, "Merging and
// unification"):
// 1. vertices within `tolerance` are welded (kernel::weld: grid hashing over neighbouring cells,
//    the first vertex wins); faces left with fewer than 3 vertices or thinner than `tolerance`
//    (area <= tolerance x longest edge / 2) are dropped;
// 2. faces over the same vertex cycle are kept once (the first, with its tag), and a cycle found
//    in both directions (two solids touching along a face) is dropped altogether: the faces
//    cancel;
// 3. faces that share an edge, have equal tags, face the same way and lie within `tolerance` of
//    the first one's plane are joined into one polygon, as long as the result stays one simple
//    loop: a region that would enclose a hole is left as several hole-free faces (Mesh's
//    invariant);
// 4. a vertex with exactly two neighbours that lies on the segment between them (within
//    `tolerance`) is dropped from every loop (it only subdivided a straight edge);
// 5. unused vertices are removed (the others keep their order).
// Faces keep their tags; joined faces take the first one's. Tolerances below 1e-9 m act as
// 1e-9 m.
Mesh unify(const Mesh& mesh, double tolerance);

// The meshes grouped by shared edges: two meshes are linked when an edge of one has both ends
// within `tolerance` of the ends of an edge of the other (edges that overlap only in part do not
// link); groups are the connected components, each listed in input order, groups in the order of
// their first member. A mesh without faces is a group of its own.
std::vector<std::vector<std::size_t>> group_by_shared_edges(std::span<const Mesh> meshes,
                                                            double tolerance);

}  // namespace insula::kernel
