// Insertion of an asset mesh fitted to the scope (seed 004, "I(objId)"; CGA i()). The shape layer
// reads no files: assets come from the Context's AssetProvider, which the app backs with io's OBJ
// reader.
#include <cmath>

#include "shape/ops.h"

namespace insula::shape {

using kernel::Vec3;

OpResult insert(ShapeTree& tree, ShapeId id, const kernel::Mesh& asset) {
  const kernel::Bounds3 b = asset.bounds();
  if (asset.empty() || b.empty()) return OpResult::failure("the asset has no faces");
  const Vec3 extent = b.size();
  const Shape& s = tree[id];
  const std::array<double, 3> size = {s.scope.size.x, s.scope.size.y, s.scope.size.z};
  const std::array<double, 3> have = {extent.x, extent.y, extent.z};
  std::array<double, 3> factor{};
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    if (size[k] > 0 && have[k] > 0) {
      factor[k] = size[k] / have[k];
      sum += factor[k];
      ++count;
    }
  }
  // Axes of size 0 (or a flat asset axis) keep proportions: the mean of the fitted factors.
  const double keep = count > 0 ? sum / count : 1.0;
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(size[k] > 0 && have[k] > 0)) factor[k] = keep;
  }
  const kernel::Transform fit = kernel::compose(kernel::scaling({factor[0], factor[1], factor[2]}),
                                                kernel::translation(-b.min));
  auto mesh = std::make_shared<kernel::Mesh>(kernel::transformed(asset, fit));
  Scope scope = s.scope;
  scope.size = {have[0] * factor[0], have[1] * factor[1], have[2] * factor[2]};
  OpResult result;
  result.add(tree.add_child(id, scope, std::move(mesh)), 0);
  return finish(tree, id, std::move(result));
}

std::vector<Operation> insert_operations() {
  std::vector<Operation> ops;
  ops.push_back({"insert",
                 "Inserts an asset mesh (y up) scaled to the scope; axes of size 0 keep the "
                 "asset's proportions (CGA i).",
                 {{"asset",
                   ParamType::kString,
                   "asset name, resolved by the asset provider",
                   std::nullopt,
                   {},
                   {},
                   {}}},
                 [](ShapeTree& t, ShapeId id, const Arguments& a, const Context& context) {
                   if (context.assets == nullptr) return OpResult::failure("no asset provider");
                   std::string error;
                   auto mesh = context.assets->find(a.string("asset"), error);
                   if (!mesh) {
                     return OpResult::failure(
                         error.empty() ? "asset '" + a.string("asset") + "' not found" : error);
                   }
                   return insert(t, id, *mesh);
                 }});
  return ops;
}

}  // namespace insula::shape
