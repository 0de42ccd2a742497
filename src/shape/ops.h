// The shape operations behind the registry, one file per family (ops_extrude.cc, ops_split.cc,
// ops_comp.cc, ops_transform.cc, ops_offset.cc, ops_roof.cc, ops_insert.cc), callable directly with
// typed arguments. Every operation creates children of `id` (their scopes and geometry in their own
// scope space), marks `id` inactive on success, and creates nothing on failure. Conventions and
// choices are in docs/shape-model.md; parameters in docs/operations.md.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/roof.h"
#include "shape/operation.h"
#include "shape/shape_tree.h"

namespace insula::shape {

// Registry tables, one per family.
std::vector<Operation> extrude_operations();
std::vector<Operation> split_operations();
std::vector<Operation> comp_operations();
std::vector<Operation> transform_operations();
std::vector<Operation> offset_operations();
std::vector<Operation> roof_operations();
std::vector<Operation> insert_operations();
std::vector<Operation> scope_operations();
std::vector<Operation> inner_rectangle_operations();
std::vector<Operation> cleanup_operations();
std::vector<Operation> primitive_operations();
std::vector<Operation> convexify_operations();
std::vector<Operation> uv_operations();        // ops_uv.cc: CityEngine's texturing operations
std::vector<Operation> scatter_operations();   // ops_scatter.cc: CityEngine's scatter
std::vector<Operation> envelope_operations();  // ops_envelope.cc: CityEngine's envelope
std::vector<Operation> insert_along_uv_operations();  // ops_insert_along_uv.cc

// --- extrude (ops_extrude.cc)
// A flat shape (footprint or face) becomes a prism of `height` meters (> 0) along its normal. The
// child's scope: x as before, y = the old normal (up for a footprint), z = x cross y, size (S.x,
// height, S.y). Faces: bottom GroundSurface, top RoofSurface, sides WallSurface (kernel extrude.h).
OpResult extrude(ShapeTree& tree, ShapeId id, double height);

// --- split and repeat (ops_split.cc)
struct Piece {
  double start = 0;  // along the axis, scope space, meters
  double size = 0;
  std::uint32_t entry = 0;  // index into the size list
};
// CGA size resolution (seed 004 "Basic Split Rule"): absolute sizes are meters, relative ones a
// fraction of `total`, floating ones share what absolute and relative sizes leave, in proportion
// to their values (seed 001's weighted `rel` sizes are floating sizes). With a floating size the
// pieces sum exactly to `total`; without, pieces past `total` are dropped and the last one that
// crosses it is cut (CGA), and a shortfall stays empty. Zero-size pieces are left out.
std::vector<Piece> resolve_sizes(double total, std::span<const SizeSpec> sizes);
// Splits along `axis` into the resolved pieces; each child keeps the other two extents. Box
// geometry is cut exactly; any other closed mesh with kernel split_into_slabs (closed pieces, cut
// faces tagged FloorSurface / CeilingSurface for y cuts and InteriorWallSurface otherwise); a
// flat shape's outline is clipped in its plane (x or y only).
OpResult split(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes);
// CGA splitArea: a flat shape split along x or y so that the pieces have the resolved *areas*
// (sizes as in resolve_sizes with the shape's area as the total); cut positions by bisection on
// the area left of them, then split().
OpResult split_area(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes);
// As many pieces of about `size` meters (> 0) as fit: n = max(1, floor(S / size)), each S / n.
OpResult repeat(ShapeTree& tree, ShapeId id, Axis axis, double size);

// --- comp (ops_comp.cc)
enum class FaceSelector : std::uint8_t {
  kFront,
  kBack,
  kLeft,
  kRight,
  kTop,
  kBottom,
  kSide,
  kAll,
  kVertical,
  kHorizontal,
  kAslant,
  kNutant,
  kBorder,  // faces with an edge no other face shares (the geometry's border)
  kInside,  // the other faces
  // CityEngine's roof edge classes (edges only; ops_comp_select.cc):
  kEave,    // horizontal, at the low side of a roof plane
  kHip,     // sloped, where two roof planes meet at a convex angle
  kValley,  // sloped, where two roof planes meet at a concave angle
  kRidge,   // horizontal, where two roof planes meet at their tops
};
// The selector a CGA keyword names ("front", "ridge", ...); nullopt for any other word.
std::optional<FaceSelector> face_selector_named(std::string_view name);
// Whether a face with unit normal `n` (scope space) is selected: each face belongs to the scope
// direction its normal is closest to (front +z, back -z, left -x, right +x, top +y, bottom -y;
// ties prefer y, then z); side = front, back, left or right. CityEngine's slope classes go by the
// angle a between the normal and the scope's xz plane: horizontal |a| > 78.75 degrees, aslant
// 11.25 < a <= 78.75 (facing up), vertical |a| <= 11.25, nutant -78.75 <= a < -11.25 (facing
// down).
// kBorder and kInside depend on the mesh, not the normal: face_matches is false for them; see
// border_faces.
bool face_matches(FaceSelector selector, kernel::Vec3 n);
// Per face of `mesh`: whether one of its edges belongs to no other face (positions welded first),
// CityEngine's `border` components (`inside` are the rest): after an offset, the ring's faces.
std::vector<bool> border_faces(const kernel::Mesh& mesh);
// One flat child per selected face: scope z = outward normal, x horizontal along the face (up
// cross normal; the parent's x for faces facing up or down), y = z cross x; its outline is the face
// loop. pieces[i] = face index.
OpResult comp_faces(ShapeTree& tree, ShapeId id, FaceSelector selector);
// Face `face` of shape `id` as one such flat child (comp_faces' rule), with no bookkeeping of an
// operation result; nullopt for a degenerate face. Lua's component-from-a-face uses it too.
std::optional<ShapeId> add_face_child(ShapeTree& tree, ShapeId id, std::size_t face);
// One degenerate child per selected distinct edge (mesh_edges order; pieces[i] = that order): scope
// x along the edge, z the mean normal of the faces meeting there, size (length, 0, 0), no geometry.
OpResult comp_edges(ShapeTree& tree, ShapeId id, FaceSelector selector = FaceSelector::kAll);
// One degenerate child per edge of every face, in face and loop order (CityEngine's fe): scope x
// along the edge as the loop runs, y the face's normal, z pointing out of the face in its plane,
// size (length, 0, 0). pieces[i] counts the face edges over all faces.
OpResult comp_face_edges(ShapeTree& tree, ShapeId id);
// One point child per selected distinct vertex: the parent's axes, size 0, no geometry.
OpResult comp_vertices(ShapeTree& tree, ShapeId id, FaceSelector selector = FaceSelector::kAll);

// --- comp selectors on edges and vertices (ops_comp_select.cc)
// A distinct edge of a welded mesh and the faces that use it.
struct MeshEdge {
  std::uint32_t a = 0;  // welded vertex indices, a < b
  std::uint32_t b = 0;
  std::vector<std::uint32_t> faces;
};
// Every distinct edge of `welded`, ordered by (a, b): comp(e)'s component order.
std::vector<MeshEdge> mesh_edges(const kernel::Mesh& welded);
// Per component of `welded` (mesh_edges order for edges, vertex index for vertices): whether
// `selector` picks it. An edge's or vertex's direction is the sum of the normals of the faces
// meeting there (CityEngine: "the y-normals of the components"); border ones touch a face no other
// face meets across them. The roof classes apply to edges only.
std::vector<bool> select_edges(const kernel::Mesh& welded, std::span<const MeshEdge> edges,
                               FaceSelector selector);
std::vector<bool> select_vertices(const kernel::Mesh& welded, FaceSelector selector);

// --- transforms (ops_transform.cc); each makes one child sharing the geometry
// Moves the scope by `offset` meters along its own axes (CGA T).
OpResult translate(ShapeTree& tree, ShapeId id, kernel::Vec3 offset);
enum class Pivot : std::uint8_t { kOrigin, kCenter };
// Rotates the scope about its own x, then y, then z axis (degrees, right-hand rule; CGA R), about
// the scope origin or centre. Geometry turns with the scope.
OpResult rotate(ShapeTree& tree, ShapeId id, kernel::Vec3 degrees, Pivot pivot);
// Sets the scope size (CGA S): absolute meters or relative to the current size; geometry is
// stretched about the scope origin on axes whose old size is > 0.
OpResult scale(ShapeTree& tree, ShapeId id, SizeSpec x, SizeSpec y, SizeSpec z);
// Moves the scope along the chosen axes so its centre matches the parent shape's scope centre
// (CGA center). `axes` holds 'x', 'y', 'z'.
OpResult center(ShapeTree& tree, ShapeId id, std::string_view axes);

// --- CityEngine's scope operations (ops_scope.cc; docs/operations-cityengine.md). CityEngine names
// a shape's axes x, y (up) and z = x cross y; a volume's scope has them as they are, a flat shape's
// (Insula keeps a flat shape's normal on scope z) as x, z and -y. The world frame is x east, y up
// (world +Z), z south; the object frame is the root shape's scope read the same way.
enum class Frame : std::uint8_t { kScope, kPivot, kObject, kWorld };
// Turns the scope parallel to the frame's axes ("xyz"), or one axis ("x", "y", "z") with the
// others the projections of the current ones; the geometry stays where it is and the scope is
// refitted to it. A flat shape whose normal the new scope does not keep on z loses its outline.
OpResult align_scope_to_axes(ShapeTree& tree, ShapeId id, Frame frame, char axis,
                             const Scope* object = nullptr);
// Which face and edge alignScopeToGeometry takes: an index, or CityEngine's selector words.
struct GeometryPick {
  enum class Kind : std::uint8_t { kIndex, kLargest, kAny, kLongest, kLowest } kind = Kind::kIndex;
  std::size_t index = 0;
};
// x along the picked edge of the picked face, `up` (y or z) along the face's normal (a flat shape
// keeps the normal on z whatever `up` says), the scope refitted around the unmoved geometry.
OpResult align_scope_to_geometry(ShapeTree& tree, ShapeId id, Axis up, GeometryPick face,
                                 GeometryPick edge);
// CityEngine's alignScopeToGeometryBBox: the scope turned about the axis `axes` ("xz", "zx",
// "xy", ... in CityEngine's names) leaves out, so the two it names span the minimum-area rectangle
// around the geometry seen along the third, the first along the longer side; refitted.
OpResult align_scope_to_geometry_bbox(ShapeTree& tree, ShapeId id, std::string_view axes);
// Turns only the scope (intrinsic x, y, z degrees), then refits it to the unmoved geometry.
OpResult rotate_scope(ShapeTree& tree, ShapeId id, kernel::Vec3 degrees);
// Moves the scope origin to corner `corner` (bit 0 x, bit 1 y, bit 2 z) with the axes permuted by
// `axis_map` ("xyz", "yzx", "zxy") and pointing into the box; the box and the geometry stay put.
OpResult set_pivot(ShapeTree& tree, ShapeId id, std::string_view axis_map, int corner);
// Mirrors the geometry inside the scope on the chosen axes (faces kept outward); scope unchanged.
OpResult mirror(ShapeTree& tree, ShapeId id, bool x, bool y, bool z);
// CityEngine's translate/rotate: `absolute` sets the origin (rotation) in the frame, otherwise
// the vector (angles, applied about the frame's x, y, z in turn, about the scope origin) is added.
// Geometry moves with the scope. Insula keeps no pivot apart from the scope, so kPivot is kScope,
// and absolute in the scope frame is relative (with a warning).
// `object` is the object frame's scope (null: the tree root's).
OpResult translate_in(ShapeTree& tree, ShapeId id, bool absolute, Frame frame, kernel::Vec3 v,
                      const Scope* object = nullptr);
OpResult rotate_in(ShapeTree& tree, ShapeId id, bool absolute, Frame frame, kernel::Vec3 degrees,
                   const Scope* object = nullptr);
// The frame parameter's choices and value ("scope", "pivot", "object", "world").
Frame frame_from(std::string_view name);
// CityEngine's convert(): the position (or intrinsic x-y-z orientation, degrees) `v` given in
// frame `from` expressed in frame `to`, each frame read as CityEngine's (x, y up, z). `scope` is
// the asking shape's, `object` the initial shape's (null: the world); a scope of zero depth is a
// flat shape's (its normal on z).
kernel::Vec3 convert_between_frames(Frame from, Frame to, bool orientation, kernel::Vec3 v,
                                    const Scope& scope, const Scope* object);
// CityEngine's comp selectors in a frame: `object.front` ... `object.side` (the lot's scope read
// as CityEngine's; `street.*` the same, CityEngine's reading without street data) and
// `world.north south east west up down side` (world.south is the world frame's +z, CityEngine's
// "front"). The frame and the face selector a word names, or nullopt.
struct FrameSelector {
  Frame frame = Frame::kWorld;
  FaceSelector selector = FaceSelector::kAll;
};
std::optional<FrameSelector> frame_selector_named(std::string_view word);
// Every word frame_selector_named knows, for the comp operation's declaration.
std::vector<std::string> frame_selector_words();
// Whether a face with world-space unit normal `n` matches `selector` in its frame; `object` is
// the object frame's scope (null: the world's).
bool face_matches_in_frame(const FrameSelector& selector, kernel::Vec3 n, const Scope* object);
// comp_faces with a selector in the world or object frame (frame_selector_named); `object` is
// the object frame's scope.
OpResult comp_faces_in_frame(ShapeTree& tree, ShapeId id, const FrameSelector& selector,
                             const Scope* object);

// --- offset and setback (ops_offset.cc)
enum class OffsetPart : std::uint8_t { kInside, kBorder, kAll };
// Offsets a flat shape's outline by `distance` meters (negative shrinks: CGA offset). Children:
// the inside part (piece 0) and/or the border between outline and inside (piece 1).
OpResult offset(ShapeTree& tree, ShapeId id, double distance, OffsetPart part);
// The part named by offset's "part" argument ("inside", "border", else all).
OffsetPart offset_part(std::string_view name);
// offset's distance and part read from unbound arguments, for a caller that cuts rectangles
// itself (the CGA engine's window insets, ops_fast.h): nullopt when the distance is missing or an
// argument is anything the registry would have to bind or report.
struct OffsetRequest {
  double distance;
  OffsetPart part;
};
std::optional<OffsetRequest> offset_request(const std::vector<ArgInput>& args);
enum class EdgeSelector : std::uint8_t { kFront, kBack, kLeft, kRight, kSide, kAll };
// Cuts a strip `distance` meters (> 0) deep along the selected edges of a flat shape (edges whose
// outward normal in the scope's xy plane is closest to -y front, +y back, -x left, +x right).
// Children: the setback strip (piece 0) and the remainder (piece 1), each omitted when empty.
OpResult setback(ShapeTree& tree, ShapeId id, double distance, EdgeSelector edges);

// Per-side strip depths (meters, 0: no strip) for edges classified as setback's.
struct EdgeDepths {
  double front = 0;
  double back = 0;
  double left = 0;
  double right = 0;
};
enum class SetbackPart : std::uint8_t { kShape, kRemainder, kAll };
// The general setback (CGA shapeL, shapeU, shapeO): strips of each edge's depth; children the
// strips' union clipped to the shape (piece 0) and the remainder (piece 1), as `part` keeps.
OpResult setback(ShapeTree& tree, ShapeId id, const EdgeDepths& depths, SetbackPart part);
// The same with a depth per edge of the outline (CGA setback(float[])): the outer ring's edges
// from its first vertex, then each hole's; 0 or a missing entry: no strip; extra entries are
// ignored (as CityEngine).
OpResult setback(ShapeTree& tree, ShapeId id, std::span<const double> edge_depths,
                 SetbackPart part);
// The side an edge faces by its outward direction in scope xy, as setback classifies it: the
// direction closest to -y is front, +y back, -x left, +x right (ties go to front and back).
EdgeSelector edge_side(kernel::Vec2 outward);
// `region` (in `id`'s scope xy) as a flat child of `id` with its scope fitted to the region, the
// tag of `id`'s first face, recorded in `result` as `piece`.
void add_flat_region(ShapeTree& tree, ShapeId id, const kernel::Polygon& region,
                     std::uint32_t piece, OpResult& result);

// The `part` parameter of shapeL/U/O and innerRectangle: shape, remainder or all.
ParamDecl part_param();
SetbackPart part_from(std::string_view name);

// --- innerRectangle (ops_inner_rectangle.cc)
// The largest rectangle inside a flat shape (kernel inner_rectangle.h), its sides parallel to the
// scope (`along_edge` false) or to the outline's longest edge; children the rectangle (piece 0,
// scope x along the rectangle's side) and the rest (piece 1), as `part` keeps.
OpResult inner_rectangle(ShapeTree& tree, ShapeId id, bool along_edge, SetbackPart part);

// --- convexify and trim (ops_convexify.cc)
// One flat child per convex piece of a flat shape (kernel convex_partition); `max_length` > 0
// keeps only cut lines shorter than it.
OpResult convexify(ShapeTree& tree, ShapeId id, double max_length);

// --- scatter (ops_scatter.cc)
enum class ScatterDomain : std::uint8_t { kSurface, kVolume, kScope };
struct ScatterOptions {
  ScatterDomain domain = ScatterDomain::kSurface;
  std::size_t count = 0;  // at most kMaxScatterPoints
  bool gaussian = false;
  // CityEngine's scatterMean: center, front, back, left, right, top or bottom of the scope.
  std::string mean = "center";
  // Meters on every axis, or relative: a fraction of each scope extent (CityEngine's '0.16).
  SizeSpec stddev{0.16, SizeMode::kRelative};
};
inline constexpr std::size_t kMaxScatterPoints = 1000000;
// CityEngine's scatter: `count` point children (zero-size scope, no geometry) drawn from the
// shape's seed, on the faces (area-weighted), inside the closed mesh (an open one falls back to
// the surface, with a warning) or inside the scope box. On a surface the child's scope y is the
// face's outward normal; otherwise its axes are the shape's as CityEngine sees them (a flat
// shape's normal is y). docs/operations-cityengine.md, "scatter".
OpResult scatter(ShapeTree& tree, ShapeId id, const ScatterOptions& options);

// --- envelope (ops_envelope.cc)
// One side's limit: walls rise to `base_height` meters (>= 0), then a plane leans inwards at
// `angle` degrees from the horizontal ([0, 90]; 90: no slope).
struct EnvelopeSide {
  double base_height = 0;
  double angle = 90;
};
struct EnvelopeSpec {
  bool world_up = false;  // erect along world up (+Z) instead of the face normal
  double max_height = 0;  // > 0: the volume is cut flat there
  EnvelopeSide front, back, right, left;
};
// CityEngine's envelope: the prism over a flat shape's outline up to max_height less, per sloped
// edge, the space above its plane within the edge's zone (bounded where its plane meets its
// neighbours'); the edge's side chosen by its outward direction in the object frame (`object`,
// null: the tree root's scope) read as CityEngine's. One closed child (triangles), scope
// oriented as extrude's; the sloped faces are RoofSurface. docs/operations-cityengine.md.
OpResult envelope(ShapeTree& tree, ShapeId id, const EnvelopeSpec& spec,
                  const Scope* object = nullptr);

// --- primitives (ops_primitive.cc)
enum class PrimitiveKind : std::uint8_t { kCube, kCylinder, kQuad, kSphere, kCone, kDisk };
// Replaces the geometry by a box, an upright prism of `sides` sides, a cone of `sides` sides, a
// sphere of `sides` segments around and `divisions` rings from pole to pole, or an upward
// rectangle or disk of `sides` corners (flat children). `dims` (width, height, depth; all zero:
// fill the scope as insert() does) in CityEngine's frame: height along the up axis (a flat
// shape's normal).
OpResult primitive(ShapeTree& tree, ShapeId id, PrimitiveKind kind, int sides, kernel::Vec3 dims,
                   int divisions = 0);

// --- cleanupGeometry (ops_cleanup.cc)
// kernel::cleanup with CityEngine's tolerance scale (0..1: up to 1 m, 10 degrees, 1 m²) on the
// chosen components ("all", "vertices", "edges", "faces"); scope unchanged.
OpResult cleanup_geometry(ShapeTree& tree, ShapeId id, std::string_view components,
                          double tolerance);

// --- roof (ops_roof.cc)
// How the roof is finished beyond the kernel spec (the .bldg builder's roofs: kernel roof_solid.h).
struct RoofForm {
  double height = 0;     // > 0: the top lies this far above the eave (heights scaled); 0: by pitch
  bool closed = false;   // a closed solid: gable ends and bottom closed, a compluvium through it
  double thickness = 0;  // flat roofs: a slab this thick (a closed solid); 0: the single face
};
// A roof over a flat shape's outline (kernel roof.h), eave in the shape's plane. The child's scope
// is oriented like an extrusion (y = the old normal) and fitted to the roof.
OpResult roof(ShapeTree& tree, ShapeId id, const kernel::RoofSpec& spec, const RoofForm& form = {});

// --- insert (ops_insert.cc)
// CGA i()'s insert modes (CityEngine's alignSizeAndPosition, keepSizeAndPosition,
// keepSizeAlignPosition).
enum class InsertMode : std::uint8_t { kFit, kKeepSizeAndPosition, kKeepSizeAlignPosition };
struct InsertOptions {
  bool z_up = false;  // the asset is z up: turned -90 degrees about x first
  InsertMode mode = InsertMode::kFit;
  bool cleanup = true;  // merge vertices closer than 1e-6 of the asset's diagonal
};
// A child whose geometry is `asset` (asset space = scope space: y up) fitted as CGA i() fits it
// (docs/assets.md, "Fitting"): kFit scales the bounding box onto the scope; scope axes of size 0
// keep proportions (one zero axis: the mean of the other two scales; two: the one scale, and the
// scope moves by the scaled asset offset on those axes; three: the asset's own size and
// position). An empty asset inserts a child without geometry (CityEngine inserts nothing).
OpResult insert(ShapeTree& tree, ShapeId id, const kernel::Mesh& asset,
                const InsertOptions& options = {});

// --- helpers shared by the families (ops_common.cc)
// A closed box [0, size] in scope space, faces outward; `tags` per side in the order
// -x, +x, -y, +y, -z, +z.
std::shared_ptr<const kernel::Mesh> box_mesh(kernel::Vec3 size,
                                             std::span<const kernel::FaceTag, 6> tags);
// The default tags of a mass box: walls, ground at -y, roof at +y; face id 0 (no name), so they
// never collide with the tree's named face ids (ShapeTree::face_id).
std::array<kernel::FaceTag, 6> mass_box_tags();
// Whether `mesh` is exactly the box [0, size] (6 axis-aligned rectangles), with the tag of each
// side in the order of box_mesh.
bool is_box(const kernel::Mesh& mesh, kernel::Vec3 size, std::array<kernel::FaceTag, 6>* tags,
            double tolerance = 1e-9);
// Whether `outline` is exactly the rectangle [0, w] x [0, h].
bool is_rectangle(const kernel::Polygon& outline, double w, double h, double tolerance = 1e-9);
// A new child of `parent` whose scope has the (parent scope space) axes `x`, `y`, `z`
// (orthonormal, right-handed), fitted around `mesh` (given in parent scope space); the mesh is
// stored in the child's space. Returns the child's scope and mesh without adding anything.
struct Refit {
  Scope scope;
  kernel::Mesh mesh;
};
Refit refit(const Scope& parent, const kernel::Mesh& mesh, kernel::Vec3 x, kernel::Vec3 y,
            kernel::Vec3 z);
// The end of an operation that replaces `id` by one solid: `mesh` (parent scope space) refitted
// with the axes x, y, z as the only child (piece 0), `id` finished, `warning` passed on.
OpResult replace_with(ShapeTree& tree, ShapeId id, const kernel::Mesh& mesh, kernel::Vec3 x,
                      kernel::Vec3 y, kernel::Vec3 z, std::string warning = {});
// One child of `id` with `id`'s labels, the given scope and geometry (scope rules: the same
// grammar symbol moved), `warning` passed on; `id` finished.
OpResult relabelled_child(ShapeTree& tree, ShapeId id, const Scope& scope,
                          std::shared_ptr<const kernel::Mesh> mesh,
                          std::shared_ptr<const kernel::Polygon> outline, std::string warning = {});
// Asset `name` from the context's provider, or null with `error` set ("no asset provider", the
// provider's message, or "asset 'x' not found").
std::shared_ptr<const kernel::Mesh> find_asset(const Context& context, const std::string& name,
                                               std::string& error);
// Marks `id` inactive (it was replaced by its children) and returns `result`.
OpResult finish(ShapeTree& tree, ShapeId id, OpResult result);

}  // namespace insula::shape
