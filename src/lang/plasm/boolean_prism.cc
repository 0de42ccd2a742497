// Booleans of right prisms along one axis (walls with window holes, floors with stair holes, the
// usual case in buildings): when every convex cell of the operands is a right prism along the same
// coordinate axis, all of the first operand's over one interval of it and every other operand's
// either over that interval (union, intersection, xor) or through it (difference), the 3D boolean
// is the 2D boolean of their sections (kernel::boolean2d, exact on a micrometre grid) extruded
// over the interval (kernel::extrude_between): the same closed 2-manifold the 3D boolean gives,
// without a corefinement. Anything else falls back to the kernel's 3D boolean (boolean.cc).
#include <algorithm>
#include <cmath>
#include <optional>

#include "kernel/boolean2d.h"
#include "kernel/convex_hull.h"
#include "kernel/extrude.h"
#include "lang/plasm/boolean_prism.h"

namespace insula::lang::plasm {
namespace {

using kernel::Vec2;
using kernel::Vec3;

// The two coordinates that with `axis` make a right-handed frame (u, v, axis).
std::pair<int, int> section_axes(int axis) {
  return {(axis + 1) % 3, (axis + 2) % 3};
}

struct Prism {
  double lo = 0;
  double hi = 0;
  kernel::Polygon section;
};

// The cell as a right prism along `axis`: its points lie on two planes across the axis and have
// the same section on both; nullopt otherwise.
std::optional<Prism> as_prism(const FlatComplex& flat, const Cell& cell, int axis) {
  Prism p;
  bool first = true;
  for (std::uint32_t v : cell) {
    const double x = flat.point(v)[axis];
    p.lo = first ? x : std::min(p.lo, x);
    p.hi = first ? x : std::max(p.hi, x);
    first = false;
  }
  const double tolerance = 1e-9 * std::max({1.0, std::abs(p.lo), std::abs(p.hi)});
  if (!(p.hi - p.lo > tolerance)) return std::nullopt;
  const auto [u, w] = section_axes(axis);
  std::vector<Vec2> low, high;
  for (std::uint32_t v : cell) {
    const double* q = flat.point(v);
    if (std::abs(q[axis] - p.lo) <= tolerance) {
      low.push_back({q[u], q[w]});
    } else if (std::abs(q[axis] - p.hi) <= tolerance) {
      high.push_back({q[u], q[w]});
    } else {
      return std::nullopt;
    }
  }
  const kernel::Hull2Result a = kernel::convex_hull_2d(low);
  const kernel::Hull2Result b = kernel::convex_hull_2d(high);
  if (!a.ok() || !b.ok() || a.ring.size() != b.ring.size()) return std::nullopt;
  for (std::size_t i = 0; i < a.ring.size(); ++i) {
    if (std::abs(a.ring[i].x - b.ring[i].x) > tolerance ||
        std::abs(a.ring[i].y - b.ring[i].y) > tolerance)
      return std::nullopt;
  }
  p.section.outer = a.ring;
  return p;
}

// The sections of an operand's cells, when all are prisms along `axis` whose interval is
// [lo, hi] (exact) or, with `through`, contains it; cells beside the interval are left out.
std::optional<std::vector<kernel::Polygon>> sections(const FlatComplex& flat, int axis, double lo,
                                                     double hi, bool through) {
  if (flat.dim != 3 || !flat.solids.empty()) return std::nullopt;
  std::vector<kernel::Polygon> out;
  const double tolerance = 1e-9 * std::max({1.0, std::abs(lo), std::abs(hi)});
  for (const Cell& cell : flat.cells) {
    std::optional<Prism> p = as_prism(flat, cell, axis);
    if (!p) return std::nullopt;
    const bool same = std::abs(p->lo - lo) <= tolerance && std::abs(p->hi - hi) <= tolerance;
    const bool pierces = p->lo <= lo + tolerance && p->hi >= hi - tolerance;
    const bool beside = p->hi <= lo + tolerance || p->lo >= hi - tolerance;
    if (through && beside) continue;
    if (!(same || (through && pierces))) return std::nullopt;
    out.push_back(std::move(p->section));
  }
  return out;
}

std::optional<kernel::Mesh> along(const std::vector<FlatComplex>& operands, kernel::BooleanOp op,
                                  bool exclusive, int axis) {
  const FlatComplex& first = operands.front();
  if (first.cells.empty() || first.dim != 3) return std::nullopt;
  const std::optional<Prism> probe = as_prism(first, first.cells.front(), axis);
  if (!probe) return std::nullopt;
  const bool through = op == kernel::BooleanOp::kDifference;
  std::optional<std::vector<kernel::Polygon>> acc =
      sections(first, axis, probe->lo, probe->hi, false);
  if (!acc) return std::nullopt;
  std::vector<kernel::Polygon> result = kernel::union_all(*acc);
  for (std::size_t i = 1; i < operands.size(); ++i) {
    std::optional<std::vector<kernel::Polygon>> next =
        sections(operands[i], axis, probe->lo, probe->hi, through);
    if (!next) return std::nullopt;
    const std::vector<kernel::Polygon> b = kernel::union_all(*next);
    kernel::BooleanResult r;
    if (exclusive) {
      r = kernel::exclusive_or(result, b);
    } else if (op == kernel::BooleanOp::kUnion) {
      r = kernel::unite(result, b);
    } else if (op == kernel::BooleanOp::kIntersection) {
      r = kernel::intersect(result, b);
    } else {
      r = kernel::subtract(result, b);
    }
    if (!r.ok()) return std::nullopt;
    result = std::move(r.polygons);
  }
  kernel::ExtrudeOptions untagged;
  untagged.bottom = untagged.top = untagged.side = kernel::FaceTag{};
  kernel::Mesh mesh;
  for (const kernel::Polygon& polygon : result) {
    if (kernel::extrude_between_append(mesh, polygon, probe->lo, probe->hi, untagged) !=
        kernel::ExtrudeStatus::kOk)
      return std::nullopt;
  }
  // From the section frame (u, v, axis) back to x, y, z: a cyclic permutation, so faces stay
  // outward.
  const auto [u, w] = section_axes(axis);
  for (Vec3& p : mesh.positions()) {
    double xyz[3];
    xyz[u] = p.x;
    xyz[w] = p.y;
    xyz[axis] = p.z;
    p = {xyz[0], xyz[1], xyz[2]};
  }
  return mesh;
}

}  // namespace

std::optional<kernel::Mesh> prism_boolean(const std::vector<FlatComplex>& operands,
                                          kernel::BooleanOp op, bool exclusive) {
  if (operands.size() < 2) return std::nullopt;
  for (int axis = 0; axis < 3; ++axis)
    if (std::optional<kernel::Mesh> mesh = along(operands, op, exclusive, axis)) return mesh;
  return std::nullopt;
}

}  // namespace insula::lang::plasm
