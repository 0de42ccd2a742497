// Contracting near-coincident vertices of a face loop, consistently across faces: used where
// vertices closer than a resolution become one (merged skeleton nodes in roof.cc, corners that
// round to one float32 position in the glTF writer).
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace insula::kernel {

// The simple loops a closed loop becomes when its corners with equal keys are contracted to one
// point: consecutive repeats merge, at a key the loop visits twice it splits in two, and pieces of
// fewer than three corners (an edge there and back) vanish. Each piece lists corner positions in
// `keys` (0 .. n-1) in loop order. Contracting every face of a closed, consistently oriented mesh
// by the same keys per vertex leaves it closed and consistently oriented: a contracted edge
// disappears from both faces that used it, and a vanished spike's two neighbours meet.
std::vector<std::vector<std::uint32_t>> contract_loop(std::span<const std::uint32_t> keys);

// Directed edge uses, to find where a contraction broke a closed, oriented surface: a contracted
// group whose vertices were not joined by an edge pinches it, and the edges to a common neighbour
// become one edge used four times (contracting that edge too removes the pinch).
class EdgeUses {
 public:
  void add(std::uint32_t a, std::uint32_t b) { ++uses_[std::uint64_t{a} << 32 | b]; }
  void add_loop(std::span<const std::uint32_t> loop);
  // The directed edges used more than once, or whose reverse is not used exactly once, sorted.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unpaired() const;

 private:
  std::unordered_map<std::uint64_t, int> uses_;
};

}  // namespace insula::kernel
