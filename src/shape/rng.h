// Deterministic per-shape randomness (design.md, "Randomness"). Every shape carries a 64-bit seed
// derived from its parent's seed and its index among the parent's children, so a shape's random
// stream never depends on evaluation order or thread count. The generator is splitmix64 (Steele,
// Lea, Flood: "Fast splittable pseudorandom number generators", OOPSLA 2014): tiny state, good
// statistical quality, and ideal for deriving independent child seeds.
#pragma once

#include <cstdint>
#include <span>

namespace insula::shape {

// One splitmix64 finalisation step: a bijective mix of `x`.
std::uint64_t mix64(std::uint64_t x);
// Seed of the child with `child_index` (0-based) of a shape seeded `parent_seed`.
std::uint64_t child_seed(std::uint64_t parent_seed, std::uint32_t child_index);

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  // Next 64 random bits.
  std::uint64_t next();
  // Uniform in [0, 1) with 53 random bits.
  double unit();
  // Uniform in [a, b) (a == b gives a; a > b swaps them).
  double uniform(double a, double b);
  // Uniform integer in [lo, hi] inclusive (unbiased, by rejection); lo > hi swaps them.
  std::int64_t integer(std::int64_t lo, std::int64_t hi);
  // Index i with probability weights[i] / sum; negative and NaN weights count as 0. Returns
  // weights.size() when the list is empty or every weight is 0.
  std::size_t choice(std::span<const double> weights);

 private:
  std::uint64_t state_;
};

}  // namespace insula::shape
