// The spatial tree of a 3D Tiles tileset (docs/formats.md, "3D Tiles"): a quadtree over the
// buildings' plan boxes. A cell splits into its four quadrants while the buildings whose box
// centre lies in it weigh more than a tile may (their face count: what a viewer pays to load the
// tile); every building sits in exactly one leaf, so tiles never overlap in content, only in
// their bounding volumes where a building reaches past its cell. The tree depends on the items'
// boxes and order alone, never on threads or timing.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.h"

namespace insula::io {

struct TileItem {
  kernel::Vec2 min;  // plan box, local coordinates
  kernel::Vec2 max;
  std::size_t weight = 1;
};

struct TileNode {
  int level = 0;  // quadtree address: level, column x (west to east), row y (south to north)
  int x = 0;
  int y = 0;
  kernel::Vec2 cell_min;  // the square cell
  kernel::Vec2 cell_max;
  std::vector<std::size_t> children{};  // indices into TileTree::nodes, in quadrant order
  std::vector<std::size_t> items{};     // leaves only: the items, ascending
  std::size_t weight = 0;               // of every item below

  bool leaf() const { return children.empty(); }
  // "level-x-y", the tile's name and file stem.
  std::string name() const;
};

struct TileTree {
  std::vector<TileNode> nodes;  // nodes[0] is the root; empty when there are no items
};

// Splits a cell while it weighs more than `max_weight`, holds more than one item and is above
// `max_level`; a single heavy building stays one tile of its own.
TileTree plan_tiles(std::span<const TileItem> items, std::size_t max_weight, int max_level = 20);

}  // namespace insula::io
