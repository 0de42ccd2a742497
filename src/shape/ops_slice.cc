// Slicing with left-over policies (seed 001 §3.4.3 "Slicing") and constraints that snap or repel
// the boundaries of splits and slices (§3.5), reduced to 1D along the operation's axis.
#include <algorithm>
#include <cmath>

#include "shape/component_ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

constexpr double kMinPiece = 1e-9;  // meters: thinner pieces are left out (as split does)
constexpr double kTouch = 1e-6;     // meters: boxes this close across the axis still act

std::array<Axis, 2> other_axes(Axis axis) {
  switch (axis) {
    case Axis::kX:
      return {Axis::kY, Axis::kZ};
    case Axis::kY:
      return {Axis::kX, Axis::kZ};
    case Axis::kZ:
      break;
  }
  return {Axis::kX, Axis::kY};
}

// Bounds of the constraint box's corners in `scope`'s frame.
void box_bounds(const Scope& scope, const Scope& box, Vec3& lo, Vec3& hi) {
  lo = {1e300, 1e300, 1e300};
  hi = {-1e300, -1e300, -1e300};
  for (const Vec3& corner : box.corners()) {
    const Vec3 p = scope.to_local(corner);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
}

// Boundaries (piece ends but the last) as positions.
std::vector<double> boundaries(const std::vector<Piece>& pieces) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i)
    out.push_back(pieces[i].start + pieces[i].size);
  return out;
}

double snap(double b, std::span<const std::pair<Interval, double>> targets) {
  double best = b;
  double best_distance = 1e300;
  for (const auto& [iv, reach] : targets) {
    for (double t : {iv.lo, iv.hi}) {
      const double d = std::fabs(t - b);
      if (d <= reach + 1e-12 && d < best_distance) {
        best = t;
        best_distance = d;
      }
    }
  }
  return best;
}

double repel(double b, std::span<const std::pair<Interval, double>> zones) {
  // Repeat until no zone holds the boundary (zones may overlap; bounded by their count).
  for (std::size_t round = 0; round <= zones.size(); ++round) {
    bool moved = false;
    for (const auto& [iv, margin] : zones) {
      const double lo = iv.lo - margin;
      const double hi = iv.hi + margin;
      if (b > lo + 1e-12 && b < hi - 1e-12) {
        b = (b - lo <= hi - b) ? lo : hi;  // the nearer end; ties go down
        moved = true;
      }
    }
    if (!moved) break;
  }
  return b;
}

// Pieces from boundaries (clamped to [0, total] and kept ordered); empty pieces dropped.
std::vector<Piece> rebuild(const std::vector<Piece>& pieces, std::vector<double> bounds,
                           double total) {
  std::vector<Piece> out;
  double at = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    double end = i < bounds.size() ? std::clamp(bounds[i], at, total) : total;
    if (i + 1 == pieces.size()) end = total;
    if (end - at > kMinPiece) out.push_back({at, end - at, pieces[i].entry});
    at = std::max(at, end);
  }
  return out;
}

OpResult split_pieces(ShapeTree& tree, ShapeId id, Axis axis, const std::vector<Piece>& pieces) {
  std::vector<SizeSpec> sizes;
  for (const Piece& p : pieces) sizes.push_back({p.size, SizeMode::kAbsolute});
  // The last piece absorbs rounding: a floating size fills exactly to the scope's end.
  if (!sizes.empty()) sizes.back() = {1, SizeMode::kFloating};
  OpResult result = split(tree, id, axis, sizes);
  for (std::uint32_t& piece : result.pieces) piece = pieces[piece].entry;
  return result;
}

}  // namespace

std::optional<Interval> constraint_interval(const Scope& scope, Axis axis, const Constraint& c) {
  Vec3 lo;
  Vec3 hi;
  box_bounds(scope, c.box, lo, hi);
  for (Axis other : other_axes(axis)) {
    const double extent = scope.extent(other);
    if (component(hi, other) < -kTouch || component(lo, other) > extent + kTouch) return {};
  }
  return Interval{component(lo, axis), component(hi, axis)};
}

std::vector<Piece> constrain_pieces(const Scope& scope, Axis axis, std::vector<Piece> pieces,
                                    std::span<const Constraint> constraints) {
  if (pieces.size() < 2 || constraints.empty()) return pieces;
  std::vector<std::pair<Interval, double>> snaps;
  std::vector<std::pair<Interval, double>> repels;
  for (const Constraint& c : constraints) {
    const auto iv = constraint_interval(scope, axis, c);
    if (!iv) continue;
    (c.kind == ConstraintKind::kSnap ? snaps : repels).emplace_back(*iv, std::max(0.0, c.distance));
  }
  const double total = scope.extent(axis);
  std::vector<double> bounds = boundaries(pieces);
  for (double& b : bounds) b = repel(snap(b, snaps), repels);
  return rebuild(pieces, std::move(bounds), total);
}

std::vector<Piece> slice_pieces(double total, double size, LeftOver policy) {
  std::vector<Piece> out;
  if (!(total > 0) || !(size > 0)) return out;
  const auto n = static_cast<std::size_t>(std::max(1.0, std::floor(total / size + 1e-9)));
  const double left = std::max(0.0, total - static_cast<double>(n) * size);
  std::vector<double> sizes(n, size);
  switch (policy) {
    case LeftOver::kFirst:
      sizes.front() += left;
      break;
    case LeftOver::kLast:
      sizes.back() += left;
      break;
    case LeftOver::kBoth:
      sizes.front() += left / 2;
      sizes.back() += left / 2;
      break;
    case LeftOver::kSpread:
      std::fill(sizes.begin(), sizes.end(), total / static_cast<double>(n));
      break;
  }
  if (n == 1) sizes.front() = total;  // a scope shorter than one slice is one piece
  double at = 0;
  for (double s : sizes) {
    out.push_back({at, s, 0});
    at += s;
  }
  out.back().size = total - out.back().start;
  return out;
}

OpResult slice(ShapeTree& tree, ShapeId id, Axis axis, double size, LeftOver policy,
               std::span<const Constraint> constraints) {
  if (!(size > 0) || !std::isfinite(size)) return OpResult::failure("size must be > 0");
  const double total = tree[id].scope.extent(axis);
  if (!(total > 0)) return OpResult::failure("the scope has size 0 along the slice axis");
  if (total / size > 1e6) return OpResult::failure("more than 1000000 pieces");
  const std::vector<Piece> pieces =
      constrain_pieces(tree[id].scope, axis, slice_pieces(total, size, policy), constraints);
  return split_pieces(tree, id, axis, pieces);
}

OpResult slice_at(ShapeTree& tree, ShapeId id, Axis axis, std::span<const Constraint> constraints) {
  const Scope scope = tree[id].scope;
  const double total = scope.extent(axis);
  if (!(total > 0)) return OpResult::failure("the scope has size 0 along the slice axis");
  std::vector<double> cuts;
  for (const Constraint& c : constraints) {
    const auto iv = constraint_interval(scope, axis, c);
    if (!iv) continue;
    for (double t : {iv->lo, iv->hi}) {
      if (t > kMinPiece && t < total - kMinPiece) cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [](double a, double b) { return std::fabs(a - b) <= kMinPiece; }),
             cuts.end());
  if (cuts.empty()) return OpResult::failure("no constraint crosses the component");
  std::vector<Piece> pieces;
  double at = 0;
  for (std::size_t i = 0; i <= cuts.size(); ++i) {
    const double end = i < cuts.size() ? cuts[i] : total;
    pieces.push_back({at, end - at, static_cast<std::uint32_t>(i)});
    at = end;
  }
  return split_pieces(tree, id, axis, pieces);
}

OpResult split_constrained(ShapeTree& tree, ShapeId id, Axis axis, std::span<const SizeSpec> sizes,
                           std::span<const Constraint> constraints) {
  const Scope scope = tree[id].scope;
  const double total = scope.extent(axis);
  if (!(total > 0)) return OpResult::failure("the scope has size 0 along the split axis");
  std::vector<Piece> pieces = resolve_sizes(total, sizes);
  // A split that does not fill the scope keeps its shortfall: constrain only the filled part.
  const double filled = pieces.empty() ? 0 : pieces.back().start + pieces.back().size;
  if (std::fabs(filled - total) > 1e-9 * std::max(1.0, total)) {
    return split(tree, id, axis, sizes);
  }
  return split_pieces(tree, id, axis,
                      constrain_pieces(scope, axis, std::move(pieces), constraints));
}

}  // namespace insula::shape
