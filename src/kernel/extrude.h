// Extrusion of planar polygons with holes into closed prisms (footprints into mass models, the
// shape layer's extrude of a face).
//
// Conventions of every prism built here (docs/kernel-meshes.md):
//  - faces are counter-clockwise seen from outside, vertices are shared, so kernel::check()
//    reports the prism closed with Euler characteristic 2 - 2 * (number of holes);
//  - the bottom cap has tag `bottom`, the top cap `top`; a cap without holes is one n-gon face, a
//    cap with holes is stored as the triangles of its triangulation, all with the cap's face id;
//  - side face k (one quad per polygon edge) has tag `side` with face id side.face_id + k, where
//    k counts the edges of the input rings in input order: the outer ring's edge i (vertex i to
//    i + 1) is k = i, then each hole's edges follow. A zero-length edge gets no face (its id is
//    skipped). Rings may come in either orientation; ids follow the input order regardless.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/transform.h"

namespace insula::kernel {

struct ExtrudeOptions {
  FaceTag bottom{SemanticClass::kGroundSurface, 0, 0};
  FaceTag top{SemanticClass::kRoofSurface, 0, 1};
  FaceTag side{SemanticClass::kWallSurface, 0, 2};  // face_id of the first side face
  // Consecutive vertices closer than this (meters) are merged before extruding.
  double tolerance = 1e-9;
};

enum class ExtrudeStatus {
  kOk,
  kInvalidHeight,        // height not finite or not > 0 (extrude_between: top <= bottom)
  kNonFinite,            // a coordinate or the frame is NaN or infinite
  kTooFewVertices,       // a ring with fewer than 3 distinct vertices
  kZeroArea,             // a ring encloses (near) zero area
  kTriangulationFailed,  // a cap with holes could not be triangulated
  kDegenerateFace,       // extrude_face: the face has no well-defined plane
};

std::string_view extrude_status_message(ExtrudeStatus status);

struct ExtrudeResult {
  ExtrudeStatus status = ExtrudeStatus::kOk;
  Mesh mesh;  // empty unless ok()
  bool ok() const { return status == ExtrudeStatus::kOk; }
};

// Prism over `footprint` (XY plane) from z = z0 to z = z0 + height; height in meters, > 0.
ExtrudeResult extrude(const Polygon& footprint, double z0, double height,
                      const ExtrudeOptions& options = {});
// Prism between two heights, z_bottom < z_top (a storey slab, a roof-less part).
ExtrudeResult extrude_between(const Polygon& footprint, double z_bottom, double z_top,
                              const ExtrudeOptions& options = {});
// extrude_between writing straight into `mesh` (a storey mesh gathering many slabs) instead of a
// fresh one: the vertices and faces appended are exactly those `mesh.append(extrude_between(...)
// .mesh)` would append, in the same order, without the temporary mesh and its copy. On failure
// nothing is added and the status says why.
ExtrudeStatus extrude_between_append(Mesh& mesh, const Polygon& footprint, double z_bottom,
                                     double z_top, const ExtrudeOptions& options = {});
// Prism over a polygon given in the XY plane of `plane` (local coordinates), extruded by
// `distance` along the plane's local z axis (non-zero; negative extrudes behind the plane). The
// bottom tag goes to the cap lying in the plane, the top tag to the moved cap. `plane` may be any
// invertible affine map; a mirroring one is handled (faces stay outward).
ExtrudeResult extrude_planar(const Polygon& local, const Transform& plane, double distance,
                             const ExtrudeOptions& options = {});
// Extrudes a planar loop of 3D points (counter-clockwise seen from the side it faces) by
// `distance` along its Newell normal: the solid grows out of the face, whose copy is the bottom.
ExtrudeResult extrude_loop(std::span<const Vec3> loop, double distance,
                           const ExtrudeOptions& options = {});
// extrude_loop over face `face` of `mesh` (the shape layer's extrude of a face).
ExtrudeResult extrude_face(const Mesh& mesh, std::size_t face, double distance,
                           const ExtrudeOptions& options = {});

// Adds the planar region `region` (outer counter-clockwise, holes clockwise, in some 2D frame of
// its plane) to `mesh` as faces over existing vertices: `ids[k]` is the mesh vertex of the k-th
// region vertex (outer ring, then each hole in order). Without holes one n-gon face is added, a
// quadrilateral with one quadrilateral hole (a window's frame) gives four quadrilaterals where
// they are convex, otherwise the triangles of its triangulation, all with `tag`. The faces run
// counter-clockwise in the 2D frame, or clockwise when `reverse`. Returns false (adding nothing)
// when `ids` has the wrong size or the triangulation fails.
bool add_region_faces(Mesh& mesh, const Polygon& region, std::span<const std::uint32_t> ids,
                      bool reverse, FaceTag tag);

}  // namespace insula::kernel
