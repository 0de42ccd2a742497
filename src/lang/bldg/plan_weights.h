// Rooms' weight distribution (seed 000, §3.3 and Fig. 3): every final room starts at a small fixed
// weight and grows by the growth factor of its size label until the weights sum to one; the
// containers above then take the sum of their children (back-propagation, §3.2).
#pragma once

#include <vector>

#include "lang/bldg/model.h"

namespace insula::lang::bldg::plan {

// Fig. 3 loop: w_i = initial_weight, then w_i += initial_weight x growth[size_i] for every room
// per round until the sum reaches 1, then all are divided by the sum so they add up to exactly 1.
// The growth is additive ("grow with a rate of 1.5, 2 and 2.5 regarding a fixed value such as
// 0.001"): after k rounds w_i = initial_weight x (1 + k growth_i), so a big room ends about
// 2.5/1.5 times a small one whatever the number of rooms (a multiplicative reading would make the
// ratio depend on the room count). Non-positive restriction values fall back to the defaults.
// Empty input gives an empty result.
std::vector<double> distribute_weights(const std::vector<SizeLabel>& sizes,
                                       const Restrictions& restrictions);

}  // namespace insula::lang::bldg::plan
