// Disjoint sets over the integers 0..size()-1 (union-find with path halving; Tarjan 1975). Used
// wherever things are grouped by pairwise links: mesh components, coplanar hull faces, rooms
// joined by doors, touching roof parts, rings touching in loops.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace insula::base {

class UnionFind {
 public:
  explicit UnionFind(std::size_t size = 0) : parent_(size) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }

  std::size_t size() const { return parent_.size(); }

  // Adds a set of its own; returns its element.
  std::uint32_t add() {
    const auto element = static_cast<std::uint32_t>(parent_.size());
    parent_.push_back(element);
    return element;
  }

  // The representative of x's set. Halves the path it walks, so a sequence of m operations on n
  // elements costs O(m log n) without union by rank.
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  // Joins the sets of a and b; b's representative represents the union. False when a and b were
  // already in one set.
  bool unite(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ra = find(a);
    const std::uint32_t rb = find(b);
    if (ra == rb) return false;
    parent_[ra] = rb;
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace insula::base
