#include "shape/rng.h"

#include <cmath>
#include <utility>

namespace insula::shape {

namespace {
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
}

std::uint64_t mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t child_seed(std::uint64_t parent_seed, std::uint32_t child_index) {
  // Mixing the index separately before combining keeps (seed, i) and (seed', i') pairs apart.
  return mix64(parent_seed + kGolden * (static_cast<std::uint64_t>(child_index) + 1) +
               mix64(child_index ^ 0x5851f42d4c957f2dULL));
}

std::uint64_t Rng::next() {
  state_ += kGolden;
  return mix64(state_);
}

double Rng::unit() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double a, double b) {
  if (a > b) std::swap(a, b);
  return a + (b - a) * unit();
}

std::int64_t Rng::integer(std::int64_t lo, std::int64_t hi) {
  if (lo > hi) std::swap(lo, hi);
  const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
  if (span == 0) return static_cast<std::int64_t>(next());  // the whole 64-bit range
  // Reject the top partial bucket so every value is equally likely.
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t r = next();
  while (r >= limit) r = next();
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + r % span);
}

std::size_t Rng::choice(std::span<const double> weights) {
  double total = 0;
  for (double w : weights) total += (w > 0) ? w : 0;  // NaN compares false: counts as 0
  if (!(total > 0) || !std::isfinite(total)) return weights.size();
  double r = unit() * total;
  std::size_t last = weights.size();
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0)) continue;
    last = i;
    if (r < weights[i]) return i;
    r -= weights[i];
  }
  return last;  // rounding left r just above the last positive weight
}

}  // namespace insula::shape
