#include "lang/bldg/plan_weights.h"

#include <cmath>

namespace insula::lang::bldg::plan {

std::vector<double> distribute_weights(const std::vector<SizeLabel>& sizes,
                                       const Restrictions& restrictions) {
  const Restrictions defaults;
  const double w0 = restrictions.initial_weight > 0 && restrictions.initial_weight < 1
                        ? restrictions.initial_weight
                        : defaults.initial_weight;
  std::vector<double> growth(sizes.size());
  double rate = 0;  // sum of the per-round increments
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const auto label = static_cast<std::size_t>(sizes[i]);
    const double g = restrictions.growth[label] > 0 && std::isfinite(restrictions.growth[label])
                         ? restrictions.growth[label]
                         : defaults.growth[label];
    growth[i] = g * w0;
    rate += growth[i];
  }
  std::vector<double> weights(sizes.size(), w0);
  if (sizes.empty()) return weights;
  // Rounds needed for the sum to reach 1 (the loop of Fig. 3, counted instead of iterated: the
  // same k, without thousands of rounds for a single-room floor).
  const double start = w0 * static_cast<double>(sizes.size());
  const double rounds = start >= 1 ? 0 : std::ceil((1 - start) / rate);
  double sum = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    weights[i] = w0 + rounds * growth[i];
    sum += weights[i];
  }
  for (double& w : weights) w /= sum;
  return weights;
}

}  // namespace insula::lang::bldg::plan
