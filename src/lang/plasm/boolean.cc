// Booleans of polyhedra (seed 002, §2: `+` and `-` on polyhedra; the library's UNION,
// INTERSECTION, DIFFERENCE, XOR) by the kernel's 3D booleans (CGAL corefinement): the result is
// one merged, closed, outward 2-manifold kept as a solid, where pyplasm leaves unmerged convex
// cells classified by random rays. Operands are 3D solids: convex cells of three dimensions (a
// conforming complex is one shell, other complexes are united cell by cell first) and earlier
// booleans' results.
#include <optional>
#include <string>
#include <utility>

#include "kernel/boolean3d.h"
#include "lang/plasm/boolean_prism.h"
#include "lang/plasm/complex_mesh.h"
#include "lang/plasm/geometry.h"

namespace insula::lang::plasm {
namespace {

constexpr std::size_t kMaxCellwiseUnion = 256;

[[noreturn]] void boolean_failure(Context& c, std::string_view who, const std::string& why,
                                  Range at) {
  c.fail("PSM415", text({"'", who, "' failed: ", why}), at);
}

kernel::Mesh combine(Context& c, const kernel::Mesh& a, const kernel::Mesh& b, kernel::BooleanOp op,
                     std::string_view who, Range at) {
  if (a.empty()) return op == kernel::BooleanOp::kUnion ? b : kernel::Mesh{};
  if (b.empty()) return op == kernel::BooleanOp::kIntersection ? kernel::Mesh{} : a;
  kernel::Boolean3dResult r = kernel::boolean3d(a, b, op);
  if (r.status != kernel::Boolean3dStatus::kOk) boolean_failure(c, who, r.message, at);
  return std::move(r.mesh);
}

// The closed mesh bounding a polyhedron's solid cells and solids. A conforming complex (cells
// that meet in whole faces) is one shell at once; `cellwise` unites the cells one by one instead,
// for complexes whose cells overlap or meet in part of a face.
kernel::Mesh operand(Context& c, const PolyPtr& p, bool cellwise, std::string_view who, Range at) {
  const FlatComplex flat = flatten_cells(*p);
  if (flat.dim > 3)
    c.fail("PSM415",
           text({"'", who, "' works on solids in 3D, found a polyhedron in ",
                 std::to_string(flat.dim), "D"}),
           at);
  c.charge(static_cast<double>(flat.cells.size()) * 8, at);
  MeshStats stats;
  kernel::Mesh out;
  if (cellwise) {
    // One 3D boolean per cell: bounded, so a large overlapping complex is an error, not minutes.
    if (flat.cells.size() > kMaxCellwiseUnion)
      c.fail("PSM415",
             text({"'", who, "': an operand of ", std::to_string(flat.cells.size()),
                   " cells that overlap or meet in part of a face is too many to unite one by one "
                   "(at most ",
                   std::to_string(kMaxCellwiseUnion), "; UNION its parts first)"}),
             at);
    for (std::uint32_t k = 0; k < flat.cells.size(); ++k) {
      const std::uint32_t one[] = {k};
      out = combine(c, out, complex_mesh(flat, one, {}, stats), kernel::BooleanOp::kUnion, who, at);
    }
  } else {
    out = complex_mesh(flat, {}, {}, stats);
  }
  if (const std::size_t flat_cells = stats.surface_cells + stats.skipped_cells; flat_cells > 0)
    c.fail("PSM415",
           text({"'", who, "' works on solids; an operand has ", std::to_string(flat_cells),
                 flat_cells == 1 ? " cell" : " cells", " of fewer than 3 dimensions"}),
           at);
  for (const kernel::Mesh& solid : flat.solids)
    out = combine(c, out, solid, kernel::BooleanOp::kUnion, who, at);
  return out;
}

bool malformed(const kernel::Boolean3dResult& r) {
  return r.status == kernel::Boolean3dStatus::kSelfIntersecting ||
         r.status == kernel::Boolean3dStatus::kNotClosed;
}

// acc op operands[i]..., retrying an operand cell by cell when its one-shell mesh is no valid
// operand (the first operand too, while acc is still that operand's own mesh). A difference or a
// union of more than two first tries acc op (the rest side by side): a - b1 - ... - bn is
// a - (b1 + ... + bn), and when the bi are disjoint their meshes together bound that union, so
// one boolean does the work of n (one at a time, each re-triangulated and re-checked the growing
// result: a wall minus 100 windows took minutes). The kernel rejects the combined mesh when the bi
// overlap, touch or nest, and then they go one by one.
// The prisms' fast path (boolean_prism.h) when every operand is made of them.
std::optional<kernel::Mesh> prisms(Context& c, const std::vector<PolyPtr>& operands,
                                   kernel::BooleanOp op, bool exclusive, Range at) {
  std::vector<FlatComplex> flat;
  for (const PolyPtr& p : operands) {
    flat.push_back(flatten_cells(*p));
    c.charge(static_cast<double>(flat.back().cells.size()) * 8, at);
  }
  return prism_boolean(flat, op, exclusive);
}

kernel::Mesh fold(Context& c, const std::vector<PolyPtr>& operands, kernel::BooleanOp op,
                  std::string_view who, Range at) {
  if (std::optional<kernel::Mesh> mesh = prisms(c, operands, op, false, at)) return *mesh;
  std::vector<kernel::Mesh> meshes;
  for (const PolyPtr& p : operands) meshes.push_back(operand(c, p, false, who, at));
  if ((op == kernel::BooleanOp::kDifference || op == kernel::BooleanOp::kUnion) &&
      meshes.size() > 2 && !meshes.front().empty()) {
    kernel::Mesh rest;
    for (std::size_t i = 1; i < meshes.size(); ++i) rest.append(meshes[i]);
    if (!rest.empty()) {
      kernel::Boolean3dResult r = kernel::boolean3d(meshes.front(), rest, op);
      if (r.status == kernel::Boolean3dStatus::kOk) return std::move(r.mesh);
    }
  }
  kernel::Mesh acc = std::move(meshes.front());
  for (std::size_t i = 1; i < operands.size(); ++i) {
    kernel::Mesh next = std::move(meshes[i]);
    if (!acc.empty() && !next.empty()) {
      kernel::Boolean3dResult r = kernel::boolean3d(acc, next, op);
      if (r.status == kernel::Boolean3dStatus::kOk) {
        acc = std::move(r.mesh);
        continue;
      }
      if (!malformed(r)) boolean_failure(c, who, r.message, at);
      if (i == 1) acc = operand(c, operands.front(), true, who, at);
      next = operand(c, operands[i], true, who, at);
    }
    acc = combine(c, acc, next, op, who, at);
  }
  return acc;
}

ValuePtr solid_value(Context& c, kernel::Mesh mesh, Range at) {
  c.charge(static_cast<double>(mesh.face_count()), at);
  if (mesh.empty()) return polyhedron_value(c, make_leaf(3, {}, {}), at);
  // CGAL numbers the result's vertices by its own bookkeeping: the order is made geometric, so
  // equal solids are equal bytes whatever else the process computed before.
  return polyhedron_value(c, make_solid(kernel::canonical_order(mesh)), at);
}

std::vector<PolyPtr> operands(Context& c, const ValuePtr& v, std::string_view who, Range at) {
  std::vector<PolyPtr> out;
  for (const ValuePtr& e : c.seq(v, who, at)) out.push_back(polyhedron(c, e, who, at));
  if (out.empty()) c.fail("PSM407", text({"'", who, "' of an empty sequence"}), at);
  return out;
}

template <kernel::BooleanOp kOp>
ValuePtr boolean_fn(Context& c, const Function& self, Args a, Range at) {
  return solid_value(c, fold(c, operands(c, a[0], self.label, at), kOp, self.label, at), at);
}

// XOR: what lies in an odd number of the operands, (a - b) + (b - a) folded.
ValuePtr xor_fn(Context& c, const Function&, Args a, Range at) {
  const std::vector<PolyPtr> ps = operands(c, a[0], "XOR", at);
  if (std::optional<kernel::Mesh> mesh = prisms(c, ps, kernel::BooleanOp::kUnion, true, at))
    return solid_value(c, std::move(*mesh), at);
  kernel::Mesh acc = fold(c, {ps.front()}, kernel::BooleanOp::kUnion, "XOR", at);
  for (std::size_t i = 1; i < ps.size(); ++i) {
    const kernel::Mesh next = fold(c, {ps[i]}, kernel::BooleanOp::kUnion, "XOR", at);
    kernel::Mesh left = combine(c, acc, next, kernel::BooleanOp::kDifference, "XOR", at);
    kernel::Mesh right = combine(c, next, acc, kernel::BooleanOp::kDifference, "XOR", at);
    acc = combine(c, left, right, kernel::BooleanOp::kUnion, "XOR", at);
  }
  return solid_value(c, std::move(acc), at);
}

const Native kBoolean[] = {
    {"DIFFERENCE", 1, boolean_fn<kernel::BooleanOp::kDifference>},
    {"INTERSECTION", 1, boolean_fn<kernel::BooleanOp::kIntersection>},
    {"UNION", 1, boolean_fn<kernel::BooleanOp::kUnion>},
    {"XOR", 1, xor_fn},
};

}  // namespace

ValuePtr polyhedron_binary(Context& c, Op op, const ValuePtr& a, const ValuePtr& b, Range at) {
  const PolyPtr& p = a->polyhedron();
  const PolyPtr& q = b->polyhedron();
  if (op == Op::kMul) return product(c, p, q, at);
  const char* who = op == Op::kAdd ? "+" : "-";
  const kernel::BooleanOp kind =
      op == Op::kAdd ? kernel::BooleanOp::kUnion : kernel::BooleanOp::kDifference;
  return solid_value(c, fold(c, {p, q}, kind, who, at), at);
}

std::span<const Native> boolean_natives() {
  return kBoolean;
}

}  // namespace insula::lang::plasm
