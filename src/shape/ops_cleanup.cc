// CityEngine's cleanupGeometry over the kernel's mesh cleanup (kernel/mesh_cleanup.h).
#include <cmath>

#include "kernel/mesh_cleanup.h"
#include "shape/ops.h"

namespace insula::shape {

OpResult cleanup_geometry(ShapeTree& tree, ShapeId id, std::string_view components,
                          double tolerance) {
  const Shape& s = tree[id];
  if (!s.mesh) return OpResult::failure("the shape has no geometry");
  // CityEngine's scale: tolerance 1 merges vertices 1 m apart, takes 10 degrees as collinear or
  // coplanar and 1 m² as degenerate; in between, linearly.
  kernel::CleanupOptions options;
  options.merge_distance = std::max(tolerance, 1e-7);
  options.angle_degrees = 10 * tolerance;
  options.max_area = tolerance;
  const bool all = components == "all";
  options.faces = all || components == "faces";
  options.edges = all || components == "edges";
  options.vertices = all || components == "vertices";
  auto mesh = std::make_shared<kernel::Mesh>(kernel::cleanup(*s.mesh, options));
  // Merging and dropping never move a vertex beyond the tolerance, so the scope still fits; a
  // hole-free flat shape's outline is its one face again.
  std::shared_ptr<const kernel::Polygon> outline = s.outline;
  if (outline && outline->holes.empty() && mesh->face_count() == 1) {
    auto o = std::make_shared<kernel::Polygon>();
    for (std::uint32_t v : mesh->face(0)) o->outer.push_back(kernel::drop(mesh->position(v)));
    outline = std::move(o);
  }
  return relabelled_child(tree, id, s.scope, std::move(mesh), std::move(outline));
}

std::vector<Operation> cleanup_operations() {
  std::vector<Operation> ops;
  ops.push_back({"cleanupGeometry",
                 "Merges vertices closer than the tolerance and, as chosen, drops duplicate and "
                 "degenerate faces, merges coplanar neighbour faces and drops collinear vertices "
                 "(CGA cleanupGeometry); a closed mesh stays closed.",
                 {{"components",
                   ParamType::kEnum,
                   "faces: duplicate and degenerate faces; edges: edges between coplanar faces; "
                   "vertices: collinear vertices; all: every step (vertices are merged always)",
                   ArgValue{std::string("all")},
                   {"all", "vertices", "edges", "faces"},
                   {},
                   {}},
                  {"tolerance",
                   ParamType::kNumber,
                   "0: exact matches only; 1: 1 m, 10 degrees, 1 m² (linear in between)",
                   ArgValue{0.0},
                   {},
                   0.0,
                   1.0}},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
                   return cleanup_geometry(t, id, a.string("components"), a.number("tolerance"));
                 }});
  return ops;
}

}  // namespace insula::shape
