// The component operations of seed 001 (Leblanc, Houle, Poulin: "Component-based Modeling of
// Complete Buildings") that the CGA families of ops.h do not cover: slicing with left-over
// policies (§3.4.3), constraints that snap or repel split and slice boundaries (§3.5), booleans of
// 2D and 3D components with the §3.4.3 result placement, joint extrusion of adjacent faces
// (Fig. 6), instancing with clipping to the parent (§3.4.3), connection to regions (§3.4.2),
// doors and windows cut into wall geometry (§4.4), furniture placed on regions without
// overlapping openings (§4.5) and solid geometry with texture coordinates (§3.6). One file per
// family: ops_slice.cc, ops_boolean.cc, ops_joint.cc, ops_instance.cc, ops_opening.cc.
// docs/lua-geometry.md describes the conventions; docs/operations.md the registry entries.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/wall.h"
#include "shape/ops.h"
#include "shape/shape_tree.h"

namespace insula::shape {

// Registry tables of these families.
std::vector<Operation> component_operations();

// --- slice and constraints (ops_slice.cc)

// Where the space left over by a slice goes (§3.4.3): to the first piece, to the last, half to
// the first and half to the last, or spread evenly over every piece.
enum class LeftOver : std::uint8_t { kFirst, kLast, kBoth, kSpread };

// A constraint (§3.5): a world-space box (a plane when one extent is 0) that attracts (snap) or
// pushes away (repel) the boundaries a split or slice creates. Reduced to 1D along the operation's
// axis (§3.5: "reducing the problem into 1D"): the box covers [lo, hi] along the axis; a
// constraint only acts on a component whose extent it overlaps across the other two axes.
enum class ConstraintKind : std::uint8_t { kSnap, kRepel };
struct Constraint {
  ConstraintKind kind = ConstraintKind::kSnap;
  Scope box;
  // Snap: a boundary within `distance` meters of lo or hi moves onto the nearest of them.
  // Repel: a boundary inside [lo - distance, hi + distance] moves to the nearer end.
  double distance = 0;
};

// The constraint as an interval [lo, hi] along `axis` of `scope` (scope coordinates), or nothing
// when it does not overlap the scope across the other two axes.
struct Interval {
  double lo = 0;
  double hi = 0;
};
std::optional<Interval> constraint_interval(const Scope& scope, Axis axis, const Constraint& c);

// Moves the inner boundaries of `pieces` (which tile [0, total]) by the constraints: snaps first,
// then repulsions; boundaries stay ordered within [0, total] and pieces that shrink to nothing are
// dropped. Piece entries are kept.
std::vector<Piece> constrain_pieces(const Scope& scope, Axis axis, std::vector<Piece> pieces,
                                    std::span<const Constraint> constraints);

// Pieces of a slice: n = floor(S / size) pieces of `size` (at least one) with the left-over
// distributed by `policy`. Every piece has entry 0.
std::vector<Piece> slice_pieces(double total, double size, LeftOver policy);

// Slices along `axis` into pieces of `size` meters (> 0) with the left-over policy, then applies
// the constraints. Children in order along the axis; pieces[i] = 0.
OpResult slice(ShapeTree& tree, ShapeId id, Axis axis, double size, LeftOver policy,
               std::span<const Constraint> constraints = {});
// The specialised slice of §3.5: cuts at every constraint's lo and hi strictly inside the scope
// (e.g. the floor planes of the storeys around a stairwell). Fails when no constraint cuts.
OpResult slice_at(ShapeTree& tree, ShapeId id, Axis axis, std::span<const Constraint> constraints);
// split() of ops.h with the boundaries moved by the constraints.
OpResult split_constrained(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes,
                           std::span<const Constraint> constraints);

// --- booleans of components (ops_boolean.cc)

// Union and intersection of a set of components (all flat and coplanar, or all 3D). §3.4.3: "the
// result is stored as a root component to avoid conflicts in parent attributes": one new root per
// connected result region (2D) or one root (3D), with the first component's axes.
OpResult unite_components(ShapeTree& tree, std::span<const ShapeId> ids);
OpResult intersect_components(ShapeTree& tree, std::span<const ShapeId> ids);
// `id` minus every cutter; §3.4.3: the result is stored as child(ren) of `id`. Cutters that do not
// overlap are ignored; when none overlaps the child is a copy of `id`'s boundary.
// Prisms along parallel y axes (rooms, shafts) are cut exactly in 2D and re-extruded; other 3D
// boundaries go through kernel::boolean3d (CGAL corefinement). Faces keep their face ids.
OpResult subtract_components(ShapeTree& tree, ShapeId id, std::span<const ShapeId> cutters);

// --- joint extrusion (ops_joint.cc)

// Extrudes a set of flat components together by `distance` meters along their normals (negative:
// against them, e.g. room walls grown inward). Fig. 6: every vertex shared by several faces of
// the set moves by the one offset that keeps `distance` from each of their planes, so an edge
// shared by two faces is extruded along their bisector and the two prisms share that face (walls
// meet in mitres instead of overlapping). One closed 3D child per face (pieces[i] = index into
// `faces`), scope axes those of its face. Faces: the moved cap is the visible surface (floor,
// ceiling or interior wall inward; wall, roof outward) with the face's face id; the cap in the
// face's plane and the rims are ClosureSurface.
OpResult extrude_joint(ShapeTree& tree, std::span<const ShapeId> faces, double distance);

// --- instancing and connection (ops_instance.cc)

// Explicit creation (§3.4.3 "Instancing"): a box component with the given scope (in `parent`'s
// scope space: origin offset and axes of the parent, `size` meters) as a child of `parent`, or a
// root when parent == kNoShape (then `offset` is world). With `clip` (the default in the paper)
// the boundary is clipped by the parent's boundary; a child entirely outside fails.
OpResult instance_box(ShapeTree& tree, ShapeId parent, kernel::Vec3 offset, kernel::Vec3 size,
                      bool clip = true);
// A flat child of `parent` from face `face` of its boundary (§3.4.3: "A face of a boundary ...
// needs to be converted into 2D components"), keeping the face's tag and face id.
OpResult face_component(ShapeTree& tree, ShapeId parent, std::size_t face);

// Connection (§3.4.2): a child of the region's owner whose connector (the bottom centre of its
// box: x and z centred, y = 0) sits at `placement` (owner scope space; angles in degrees about
// the owner's x, y, z) and whose geometry is `mesh` (shared, not copied: repeated decorations
// become mesh instances, §4.5) scaled by nothing: the scope size is the mesh's extent.
struct Connected {
  ShapeId id = kNoShape;
  std::string error;
};
Connected connect_mesh(ShapeTree& tree, ShapeId owner, const RegionPlacement& placement,
                       std::shared_ptr<const kernel::Mesh> mesh);
// `mesh` moved so its bounding box starts at the origin, with the connector convention above:
// the form connect_mesh shares between instances (cache it per asset).
std::shared_ptr<const kernel::Mesh> normalized_asset(const kernel::Mesh& mesh);

// Furniture and fixtures (§4.5): up to `attempts` random placements in region `region` of `owner`
// (sample() with the owner's generator advanced by `draw`), keeping the first whose box does not
// come within `clearance` meters of any `avoid` component's box (doors with their swing, windows).
// Fails with "no free place" when none fits.
struct PlaceOptions {
  std::vector<ShapeId> avoid;
  double clearance = 0;
  int attempts = 32;
  std::uint64_t draw = 0;  // which draw of the owner's stream (several pieces on one region)
};
Connected place_on_region(ShapeTree& tree, ShapeId owner, std::size_t region,
                          std::shared_ptr<const kernel::Mesh> mesh, const PlaceOptions& options);
// Whether two scope boxes come closer than `clearance` (separating axis test on oriented boxes).
bool boxes_overlap(const Scope& a, const Scope& b, double clearance = 0);

// --- openings and solid geometry (ops_opening.cc)

enum class OpeningKind : std::uint8_t { kDoor, kWindow };
// A door or window (§4.4) as a 3D child of a flat wall component `face`: scope axes those of the
// face (x along the wall, y up, z its normal), box [u - width/2, u + width/2] x [sill, sill +
// height] x [-depth, depth] so it reaches through the walls on both sides of the face. Its
// geometry is the "union" half of the composite operation: a frame and a leaf or pane. Labels
// "door"/"window" and "opening" are added.
struct OpeningSpec {
  OpeningKind kind = OpeningKind::kDoor;
  double u = 0;  // centre along the face's x, meters
  double sill = 0;
  double width = 0.9;
  double height = 2.1;
  double depth = 0.5;
  double frame = 0.05;  // frame profile width, meters
};
OpResult add_opening(ShapeTree& tree, ShapeId face, const OpeningSpec& spec);

// Solid geometry (§3.6, Figure 3's solidGeometry): a child labelled "solid" holding the
// component's boundary as geometry with every opening of `openings` whose box pierces it cut out
// (the "subtract" half of §4.4's composite operation). Walls that are prisms through their face
// (joint extrusion, extrude) are cut with kernel/wall.h (planar, no 3D boolean): the mitred ends
// are split off with kernel::split and the middle slab is rebuilt with the openings; any other
// boundary, and openings the planar path rejects (reaching into a mitred end, overlapping another
// opening), go through kernel::boolean3d piece by piece. The child's attribute "openings_cut"
// counts the openings cut. `uv_scale` > 0 asks writers for texture coordinates
// (planar per face, `uv_scale` meters per texture repeat; kernel/uv.h), recorded as the
// attribute "uv_scale". The child has attribute "component" = the component's first label.
struct SolidOptions {
  std::vector<ShapeId> openings;
  double uv_scale = 1;
  std::string material;  // optional attribute "material" on the geometry
};
OpResult solid_geometry(ShapeTree& tree, ShapeId id, const SolidOptions& options);

// The opening of `opening` as a kernel::Opening in the wall frame of a wall component (u along
// its face's x, v along its y), or nothing when it does not pierce the wall (not parallel, no
// overlap through the thickness or along the face).
std::optional<kernel::Opening> opening_in_wall(const ShapeTree& tree, ShapeId wall,
                                               ShapeId opening);

}  // namespace insula::shape
