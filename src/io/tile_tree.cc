#include "io/tile_tree.h"

#include <algorithm>
#include <array>

namespace insula::io {
namespace {

kernel::Vec2 centre(const TileItem& item) {
  return (item.min + item.max) * 0.5;
}

struct Planner {
  std::span<const TileItem> items;
  std::size_t max_weight;
  int max_level;
  TileTree tree{};

  // Adds the node for a cell holding `members` and, when it must split, its children.
  std::size_t add(int level, int x, int y, kernel::Vec2 cell_min, double size,
                  std::vector<std::size_t> members) {
    const std::size_t index = tree.nodes.size();
    TileNode node;
    node.level = level;
    node.x = x;
    node.y = y;
    node.cell_min = cell_min;
    node.cell_max = cell_min + kernel::Vec2{size, size};
    for (const std::size_t i : members) node.weight += items[i].weight;
    tree.nodes.push_back(node);
    if (!must_split(members, level)) {
      tree.nodes[index].items = std::move(members);
      return index;
    }
    const double half = size / 2;
    std::array<std::vector<std::size_t>, 4> quadrants;
    for (const std::size_t i : members) {
      const kernel::Vec2 c = centre(items[i]);
      const int east = c.x >= cell_min.x + half ? 1 : 0;
      const int north = c.y >= cell_min.y + half ? 1 : 0;
      quadrants[static_cast<std::size_t>(2 * north + east)].push_back(i);
    }
    for (int q = 0; q < 4; ++q) {
      std::vector<std::size_t>& quadrant = quadrants[static_cast<std::size_t>(q)];
      if (quadrant.empty()) continue;
      const int east = q % 2;
      const int north = q / 2;
      const std::size_t child =
          add(level + 1, 2 * x + east, 2 * y + north,
              cell_min + kernel::Vec2{east * half, north * half}, half, std::move(quadrant));
      tree.nodes[index].children.push_back(child);
    }
    return index;
  }

  bool must_split(const std::vector<std::size_t>& members, int level) const {
    if (level >= max_level || members.size() < 2) return false;
    std::size_t weight = 0;
    for (const std::size_t i : members) weight += items[i].weight;
    if (weight <= max_weight) return false;
    // Items that all share one centre would only go down a single quadrant forever.
    const kernel::Vec2 first = centre(items[members.front()]);
    return std::any_of(members.begin(), members.end(), [&](std::size_t i) {
      const kernel::Vec2 c = centre(items[i]);
      return c.x != first.x || c.y != first.y;
    });
  }
};

}  // namespace

std::string TileNode::name() const {
  return std::to_string(level) + "-" + std::to_string(x) + "-" + std::to_string(y);
}

TileTree plan_tiles(std::span<const TileItem> items, std::size_t max_weight, int max_level) {
  Planner planner{items, std::max<std::size_t>(max_weight, 1), max_level};
  if (items.empty()) return {};
  kernel::Vec2 lo = centre(items.front());
  kernel::Vec2 hi = lo;
  for (const TileItem& item : items) {
    const kernel::Vec2 c = centre(item);
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
  }
  // A square root cell a little larger than the centres' extent, so the east and north edges
  // fall inside it.
  const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1.0}) * (1 + 1e-9) + 1e-6;
  std::vector<std::size_t> all(items.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  planner.add(0, 0, 0, lo, size, std::move(all));
  return std::move(planner.tree);
}

}  // namespace insula::io
