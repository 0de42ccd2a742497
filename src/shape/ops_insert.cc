// Insertion of an asset mesh fitted to the scope (seed 004, "I(objId)"; CGA i(), as CityEngine's
// reference describes it: docs/cityengine-dialect.md, "i (insert)"). The shape layer reads no
// files: assets come from the Context's AssetProvider, which the app backs with io's importer.
#include <array>
#include <cmath>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

namespace {

struct Fit {
  Vec3 factor{1, 1, 1};  // asset units -> scope meters, per axis
  Vec3 offset;           // the child scope's origin in the parent's scope space
  Vec3 size;             // the child scope's size
};

// CityEngine's fitting: see insert() in ops.h.
Fit fit_to_scope(Vec3 scope, const kernel::Bounds3& b, InsertMode mode) {
  const Vec3 extent = b.size();
  Fit fit;
  if (mode == InsertMode::kKeepSizeAndPosition) scope = {};
  if (mode == InsertMode::kKeepSizeAlignPosition) {
    fit.size = extent;
    fit.offset = {(scope.x - extent.x) / 2, 0, (scope.z - extent.z) / 2};
    return fit;
  }
  const std::array<double, 3> size = {scope.x, scope.y, scope.z};
  const std::array<double, 3> have = {extent.x, extent.y, extent.z};
  const std::array<double, 3> low = {b.min.x, b.min.y, b.min.z};
  std::array<double, 3> factor{};
  std::array<bool, 3> fitted{};
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    fitted[k] = size[k] > 0 && have[k] > 0;
    if (fitted[k]) {
      factor[k] = size[k] / have[k];
      sum += factor[k];
      ++count;
    }
  }
  const double keep = count > 0 ? sum / count : 1.0;
  std::array<double, 3> offset{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (fitted[k]) continue;
    factor[k] = keep;
    // With at most one fitted axis the asset keeps its position on the others (scaled); with
    // two, the scope does not move.
    if (count <= 1) offset[k] = keep * low[k];
  }
  fit.factor = {factor[0], factor[1], factor[2]};
  fit.offset = {offset[0], offset[1], offset[2]};
  fit.size = {have[0] * factor[0], have[1] * factor[1], have[2] * factor[2]};
  return fit;
}

// Whether numerical clean-up has anything to merge. Small assets (the built-in cube, most
// façade parts) are checked pair by pair, which costs a fraction of a weld; larger ones are
// welded anyway.
bool has_close_vertices(const kernel::Mesh& mesh, double tolerance) {
  constexpr std::size_t kPairwise = 64;
  const std::vector<Vec3>& p = mesh.positions();
  if (p.size() > kPairwise) return true;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (kernel::length(p[i] - p[j]) <= tolerance) return true;
    }
  }
  return false;
}

}  // namespace

OpResult insert(ShapeTree& tree, ShapeId id, const kernel::Mesh& asset,
                const InsertOptions& options) {
  const Shape& s = tree[id];
  OpResult result;
  if (asset.empty()) {
    // CityEngine inserts nothing for an asset it cannot have: a shape without geometry.
    result.add(tree.add_child(id, s.scope), 0);
    return finish(tree, id, std::move(result));
  }
  kernel::Mesh turned;
  const kernel::Mesh* source = &asset;
  if (options.z_up) {
    turned = kernel::transformed(asset, kernel::rotation({1, 0, 0}, -90));
    source = &turned;
  }
  const kernel::Bounds3 b = source->bounds();
  if (b.empty()) return OpResult::failure("the asset has no faces");
  const Fit fit = fit_to_scope(s.scope.size, b, options.mode);
  const kernel::Transform place =
      kernel::compose(kernel::scaling(fit.factor), kernel::translation(-b.min));
  kernel::Mesh placed = kernel::transformed(*source, place);
  const double tolerance = 1e-6 * kernel::length(fit.size);
  if (options.cleanup && has_close_vertices(placed, tolerance)) {
    placed = kernel::weld(placed, tolerance);
  }
  result.add(tree.add_child(id, s.scope.sub(fit.offset, fit.size),
                            std::make_shared<kernel::Mesh>(std::move(placed))),
             0);
  return finish(tree, id, std::move(result));
}

std::vector<Operation> insert_operations() {
  std::vector<Operation> ops;
  ops.push_back(
      {"insert",
       "Inserts an asset mesh fitted to the scope as CGA i() does: axes of size 0 keep the "
       "asset's proportions; a missing asset inserts nothing where the provider allows it.",
       {{"asset",
         ParamType::kString,
         "asset name, resolved by the asset provider",
         std::nullopt,
         {},
         {},
         {}},
        {"up",
         ParamType::kEnum,
         "the asset's up axis (zup: turned -90 degrees about x)",
         ArgValue{std::string("yup")},
         {"yup", "zup"},
         {},
         {}},
        {"mode",
         ParamType::kEnum,
         "fit to the scope, keep size and position, or keep size centred in xz on y = 0",
         ArgValue{std::string("alignsizeandposition")},
         {"alignsizeandposition", "keepsizeandposition", "keepsizealignposition"},
         {},
         {}},
        {"cleanup",
         ParamType::kEnum,
         "merge vertices closer than 1e-6 of the asset's diagonal, or keep them",
         ArgValue{std::string("numericalcleanup")},
         {"numericalcleanup", "nocleanup"},
         {},
         {}}},
       [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
         std::string error;
         const auto mesh = find_asset(context, a.string("asset"), error);
         if (!mesh) return OpResult::failure(error);
         InsertOptions options;
         options.z_up = a.string("up") == "zup";
         const std::string& mode = a.string("mode");
         options.mode = mode == "keepsizeandposition"     ? InsertMode::kKeepSizeAndPosition
                        : mode == "keepsizealignposition" ? InsertMode::kKeepSizeAlignPosition
                                                          : InsertMode::kFit;
         options.cleanup = a.string("cleanup") == "numericalcleanup";
         return insert(t, id, *mesh, options);
       }});
  return ops;
}

}  // namespace insula::shape
