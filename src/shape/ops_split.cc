// Split and repeat along a scope axis (seed 004, "Basic Split Rule" and "Repeat Rule"; seed 001
// §3.4.3 "Splitting" and "Slicing"). Sizes resolve as in CGA (resolve_sizes); the geometry is cut
// three ways: boxes exactly (the common case of façades and floors), other closed meshes with the
// kernel's plane splitter, flat shapes in their plane.
#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/plane_split.h"
#include "shape/ops.h"
#include "shape/ops_fast.h"

namespace insula::shape {

using kernel::FaceTag;
using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec3;

namespace {

constexpr double kMinPiece = 1e-9;                 // meters: thinner pieces are left out
constexpr std::uint32_t kCapMarker = 0xfffffffeU;  // face id marking cut faces until retagged

Vec3 unit(Axis axis) {
  Vec3 v;
  set_component(v, axis, 1);
  return v;
}

Vec3 piece_size(Vec3 size, Axis axis, double extent) {
  set_component(size, axis, extent);
  return size;
}

void shift(Mesh& mesh, Axis axis, double by) {
  for (Vec3& p : mesh.positions()) set_component(p, axis, component(p, axis) - by);
}

// Box geometry: each piece is a box; outer sides keep the parent's tags, cut sides get
// cut_face_tag.
std::vector<std::shared_ptr<const Mesh>> split_box(const std::array<FaceTag, 6>& tags, Vec3 size,
                                                   Axis axis, const std::vector<Piece>& pieces) {
  const double total = component(size, axis);
  std::vector<std::shared_ptr<const Mesh>> out;
  for (const Piece& p : pieces) {
    out.push_back(box_mesh(piece_size(size, axis, p.size), split_box_tags(tags, axis, p, total)));
  }
  return out;
}

void retag_caps(Mesh& mesh, Axis axis) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).face_id != kCapMarker) continue;
    const double along = component(kernel::face_normal(mesh, f), axis);
    mesh.tag(f) = cut_face_tag(axis, along > 0);
  }
}

struct Cut {
  std::vector<std::shared_ptr<const Mesh>> meshes;
  std::string error;
};

// Any other mesh: kernel slabs, closed pieces for closed input (open ones for flat faces).
Cut split_mesh(const Mesh& mesh, Axis axis, const std::vector<Piece>& pieces, bool cap) {
  std::vector<double> positions{0.0};
  for (const Piece& p : pieces) positions.push_back(p.start + p.size);
  kernel::SplitOptions options;
  options.cap = cap;
  options.cap_tag = {SemanticClass::kNone, 0, kCapMarker};
  kernel::SlabResult slabs = kernel::split_into_slabs(mesh, unit(axis), positions, options);
  if (!slabs.ok()) return {{}, std::string(kernel::split_status_message(slabs.status))};
  Cut cut;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Mesh& m = slabs.pieces[i + 1];  // slab 0 lies below the first cut at 0
    retag_caps(m, axis);
    shift(m, axis, pieces[i].start);
    cut.meshes.push_back(std::make_shared<Mesh>(std::move(m)));
  }
  return cut;
}

// The outline of a flat piece: its single face as a polygon in the xy plane; null when the cut
// left several faces (a concave outline cut into disjoint parts, or a holed one triangulated).
std::shared_ptr<const kernel::Polygon> outline_of(const Mesh& mesh) {
  if (mesh.face_count() != 1) return nullptr;
  auto outline = std::make_shared<kernel::Polygon>();
  for (std::uint32_t v : mesh.face(0)) outline->outer.push_back(kernel::drop(mesh.position(v)));
  kernel::normalize(*outline);
  return outline;
}

FaceTag first_tag(const Shape& s) {
  return s.mesh && !s.mesh->empty() ? s.mesh->tag(0) : FaceTag{};
}

}  // namespace

void resolve_sizes_into(double total, std::span<const SizeSpec> sizes, std::vector<Piece>& out) {
  out.clear();
  double fixed = 0;
  double weights = 0;
  for (const SizeSpec& s : sizes) {
    const double v = std::max(0.0, s.value);
    if (s.mode == SizeMode::kAbsolute) fixed += v;
    if (s.mode == SizeMode::kRelative) fixed += v * total;
    if (s.mode == SizeMode::kFloating) weights += v;
  }
  const double rest = std::max(0.0, total - fixed);
  double at = 0;
  for (std::uint32_t i = 0; i < sizes.size() && at < total - kMinPiece; ++i) {
    const SizeSpec& s = sizes[i];
    const double v = std::max(0.0, s.value);
    double size = s.mode == SizeMode::kAbsolute   ? v
                  : s.mode == SizeMode::kRelative ? v * total
                  : weights > 0                   ? rest * v / weights
                                                  : 0;
    size = std::min(size, total - at);  // CGA: the piece crossing the end is cut there
    if (size > kMinPiece) out.push_back({at, size, i});
    at += size;
  }
  // Floating pieces fill exactly: snap the last piece's end onto the total against rounding.
  if (weights > 0 && !out.empty() && std::fabs(at - total) < 1e-9 * std::max(1.0, total)) {
    out.back().size = total - out.back().start;
  }
}

std::vector<Piece> resolve_sizes(double total, std::span<const SizeSpec> sizes) {
  std::vector<Piece> out;
  resolve_sizes_into(total, sizes, out);
  return out;
}

OpResult split(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes) {
  const Shape& s = tree[id];
  const double total = component(s.scope.size, axis);
  if (!(total > 0)) return OpResult::failure("the scope has size 0 along the split axis");
  const std::vector<Piece> pieces = resolve_sizes(total, sizes);
  std::vector<std::shared_ptr<const Mesh>> meshes(pieces.size());
  std::vector<std::shared_ptr<const kernel::Polygon>> outlines(pieces.size());
  std::array<FaceTag, 6> tags;
  if (s.is_flat()) {
    const bool rect = is_rectangle(*s.outline, s.scope.size.x, s.scope.size.y);
    Cut cut;
    if (!rect) cut = split_mesh(*s.mesh, axis, pieces, false);
    if (!cut.error.empty()) return OpResult::failure(cut.error);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Vec3 size = piece_size(s.scope.size, axis, pieces[i].size);
      outlines[i] = rect ? std::make_shared<kernel::Polygon>(rectangle_outline(size.x, size.y))
                         : outline_of(*cut.meshes[i]);
      meshes[i] = rect ? flat_mesh(*outlines[i], first_tag(s)) : cut.meshes[i];
    }
  } else if (s.mesh && is_box(*s.mesh, s.scope.size, &tags)) {
    meshes = split_box(tags, s.scope.size, axis, pieces);
  } else if (s.mesh) {
    Cut cut = split_mesh(*s.mesh, axis, pieces, true);
    if (!cut.error.empty()) return OpResult::failure(cut.error);
    meshes = std::move(cut.meshes);
  }
  OpResult result;
  const Scope scope = s.scope;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Scope child = split_piece_scope(scope, axis, pieces[i]);
    result.add(tree.add_child(id, child, meshes[i], outlines[i]), pieces[i].entry);
  }
  return finish(tree, id, std::move(result));
}

OpResult repeat(ShapeTree& tree, ShapeId id, Axis axis, double size) {
  std::string error;
  const std::size_t count = repeat_count(component(tree[id].scope.size, axis), size, error);
  if (count == 0) return OpResult::failure(error);
  const std::vector<SizeSpec> sizes(count, SizeSpec{1, SizeMode::kFloating});
  OpResult result = split(tree, id, axis, sizes);
  std::fill(result.pieces.begin(), result.pieces.end(), 0U);  // every piece is the one pattern
  return result;
}

namespace {

ParamDecl axis_param() {
  return {"axis", ParamType::kEnum, "scope axis", std::nullopt, {"x", "y", "z"}, {}, {}};
}

Axis axis_of(const Arguments& a) {
  const std::string& s = a.string("axis");
  return s == "x" ? Axis::kX : s == "y" ? Axis::kY : Axis::kZ;
}

}  // namespace

namespace {

// The signed area of `ring` clipped to coordinate `axis` (0: x, 1: y) below `t`
// (Sutherland-Hodgman against one half-plane: exact for any ring, degenerate edges add nothing).
double area_below(const kernel::Ring& ring, int axis, double t) {
  const auto c = [axis](kernel::Vec2 p) { return axis == 0 ? p.x : p.y; };
  kernel::Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const kernel::Vec2 a = ring[i];
    const kernel::Vec2 b = ring[(i + 1) % ring.size()];
    const bool ina = c(a) <= t;
    const bool inb = c(b) <= t;
    if (ina) out.push_back(a);
    if (ina != inb) out.push_back(a + (b - a) * ((t - c(a)) / (c(b) - c(a))));
  }
  return out.size() < 3 ? 0 : kernel::signed_area(out);
}

double area_below(const kernel::Polygon& polygon, int axis, double t) {
  double area = area_below(polygon.outer, axis, t);
  for (const kernel::Ring& hole : polygon.holes) area += area_below(hole, axis, t);
  return area;
}

}  // namespace

OpResult split_area(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes) {
  const Shape& s = tree[id];
  if (!s.is_flat()) return OpResult::failure("needs a flat shape (a footprint or a face)");
  if (axis == Axis::kZ) return OpResult::failure("a flat shape splits along x or y only");
  const int k = axis == Axis::kX ? 0 : 1;
  const double extent = s.scope.extent(axis);
  const double total = area_below(*s.outline, k, extent + 1);
  if (!(total > 0)) return OpResult::failure("the shape has no area");
  // Pieces in area units, then each boundary where the area left of it reaches the running sum.
  const std::vector<Piece> pieces = resolve_sizes(total, sizes);
  if (pieces.empty()) return finish(tree, id, {});
  std::vector<SizeSpec> lengths;
  double previous = 0;
  for (const Piece& p : pieces) {
    const double target = p.start + p.size;
    double lo = previous;
    double hi = extent;
    if (target >= total * (1 - 1e-12)) {
      lo = hi;
    } else {
      for (int it = 0; it < 64; ++it) {
        const double mid = (lo + hi) / 2;
        (area_below(*s.outline, k, mid) < target ? lo : hi) = mid;
      }
    }
    lengths.push_back({lo - previous, SizeMode::kAbsolute});
    previous = lo;
  }
  OpResult r = split(tree, id, axis, lengths);
  for (std::uint32_t& piece : r.pieces) piece = pieces[piece].entry;  // length i is area piece i
  return r;
}

std::vector<Operation> split_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"split",
       "Splits along a scope axis into pieces of absolute, relative ('r) and floating "
       "(~) sizes (CGA split); piece i of the result is size entry pieces[i].",
       {axis_param(),
        {"sizes", ParamType::kSizeList, "piece sizes along the axis", std::nullopt, {}, 0.0, {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return split(t, id, axis_of(a), a.sizes("sizes"));
       }});
  ops.push_back(
      {"splitArea",
       "Splits a flat shape along a scope axis into pieces of the given areas: absolute (m²), "
       "relative ('r: a share of the area) and floating (~) (CGA splitArea); piece i of the "
       "result is size entry pieces[i].",
       {axis_param(), {"sizes", ParamType::kSizeList, "piece areas", std::nullopt, {}, 0.0, {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return split_area(t, id, axis_of(a), a.sizes("sizes"));
       }});
  ops.push_back(
      {"repeat",
       "Splits along a scope axis into as many equal pieces of about `size` as fit "
       "(at least one; CGA repeat).",
       {axis_param(),
        {"size", ParamType::kNumber, "approximate piece size (meters)", std::nullopt, {}, 0.0, {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
         return repeat(t, id, axis_of(a), a.number("size"));
       }});
  return ops;
}

}  // namespace insula::shape
