// Flattening of the building model and the treemap subdivision of parts and floors (seed 000,
// §3.2 and Fig. 2): weights back-propagate from rooms to their containers and parts, and every
// container's region is cut among its children by plan_treemap.h.
#include <algorithm>
#include <cstdio>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_state.h"
#include "lang/bldg/plan_treemap.h"
#include "lang/bldg/plan_weights.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

base::Span span_of(const Work& work, Location where) {
  return base::Span::at(work.file, where.line, where.column);
}

// Nodes and rooms (leaves) of a division tree, for sizing the lists add_division fills.
struct TreeSize {
  std::size_t nodes = 0;
  std::size_t rooms = 0;
};
void count_division(const Division& division, TreeSize& size) {
  ++size.nodes;
  if (division.room.has_value()) {
    ++size.rooms;
    return;
  }
  for (const Division& child : division.children) count_division(child, size);
}

// Parts, floors and rooms (the stand-in of a part without rooms included) of a part tree.
struct PartTreeSize {
  std::size_t nodes = 0;
  std::size_t parts = 0;
  std::size_t floors = 0;
  std::size_t rooms = 0;
};
void count_parts(const PartNode& node, PartTreeSize& size) {
  ++size.nodes;
  if (!node.part.has_value()) {
    for (const PartNode& child : node.children) count_parts(child, size);
    return;
  }
  ++size.parts;
  size.floors += node.part->floors.size();
  std::size_t rooms = 0;
  for (const Floor& f : node.part->floors) {
    TreeSize t;
    count_division(f.layout, t);
    rooms += t.rooms;
  }
  size.rooms += std::max<std::size_t>(rooms, 1);
}

// Adds the division tree under `division` to the floor's tree; returns the node index.
int add_division(Work& work, int floor_index, const Division& division, int parent, int depth) {
  WorkFloor& floor = work.floors[floor_index];
  const int index = static_cast<int>(floor.tree.size());
  floor.tree.push_back({});
  floor.tree[index].parent = parent;
  floor.tree[index].orientation = division.orientation;
  floor.tree[index].depth = depth;
  if (division.room.has_value()) {
    WorkRoom room;
    room.division = &division;
    room.part = floor.part;
    room.level = floor.level;
    room.floor = floor_index;
    const int room_index = static_cast<int>(work.rooms.size());
    work.rooms.push_back(room);
    work.floors[floor_index].rooms.push_back(room_index);
    work.floors[floor_index].tree[index].leaf = room_index;
    return index;
  }
  work.floors[floor_index].tree[index].children.reserve(division.children.size());
  for (const Division& child : division.children) {
    const int c = add_division(work, floor_index, child, index, depth + 1);
    work.floors[floor_index].tree[index].children.push_back(c);
  }
  return index;
}

void add_part(Work& work, const PartNode& node, int parent, int depth,
              std::vector<base::Diagnostic>& errors) {
  const int index = static_cast<int>(work.part_tree.size());
  work.part_tree.push_back({});
  work.part_tree[index].parent = parent;
  work.part_tree[index].orientation = node.orientation;
  work.part_tree[index].depth = depth;
  if (parent >= 0) work.part_tree[parent].children.push_back(index);
  if (!node.part.has_value()) {
    work.part_tree[index].children.reserve(node.children.size());
    for (const PartNode& child : node.children) add_part(work, child, index, depth + 1, errors);
    return;
  }
  const int part_index = static_cast<int>(work.parts.size());
  work.part_tree[index].leaf = part_index;
  WorkPart part;
  part.node = &node;
  part.tree_node = index;
  work.parts.push_back(part);
  const BuildingPart& bp = *node.part;
  if (bp.floors.empty() && !bp.disposable) {
    errors.push_back(base::Diagnostic::error(
        "PLAN001", "building part '" + node.symbol + "' has no floor", span_of(work, node.where)));
  }
  for (std::size_t level = 0; level < bp.floors.size(); ++level) {
    const Floor& f = bp.floors[level];
    WorkFloor floor;
    floor.part = part_index;
    floor.level = static_cast<int>(level);
    floor.height = f.height > 0 ? f.height : work.restrictions->storey_height;
    TreeSize size;
    count_division(f.layout, size);
    floor.tree.reserve(size.nodes);
    floor.rooms.reserve(size.rooms);
    const int floor_index = static_cast<int>(work.floors.size());
    work.floors.push_back(std::move(floor));
    work.parts[part_index].floors.push_back(floor_index);
    add_division(work, floor_index, f.layout, -1, 0);
    if (work.floors[floor_index].rooms.empty() && !bp.disposable) {
      errors.push_back(base::Diagnostic::error(
          "PLAN002", "floor '" + f.symbol + "' of part '" + node.symbol + "' holds no room",
          span_of(work, f.where)));
    }
  }
}

// Fig. 3 for one group of rooms.
void distribute(Work& work, const std::vector<int>& rooms) {
  std::vector<SizeLabel> sizes;
  for (int r : rooms) {
    const Division* d = work.rooms[r].division;
    sizes.push_back(d != nullptr ? d->room->size : SizeLabel::kMedium);
  }
  const std::vector<double> w = distribute_weights(sizes, *work.restrictions);
  for (std::size_t i = 0; i < rooms.size(); ++i) work.rooms[rooms[i]].weight = w[i];
}

// Back-propagated weights of every node of a tree (§3.2): a leaf's own weight, a container's
// children's sum (in child order). Children come after their parent in the flattened tree, so one
// pass from the last node back computes each sum once (the recursion per cut summed each subtree
// again at every level above it).
template <typename LeafWeight>
std::vector<double> node_weights(const std::vector<TreeNode>& tree, const LeafWeight& leaf_weight) {
  std::vector<double> weight(tree.size(), 0);
  for (std::size_t k = tree.size(); k-- > 0;) {
    const TreeNode& n = tree[k];
    if (n.leaf >= 0) {
      weight[k] = leaf_weight(n.leaf);
      continue;
    }
    double sum = 0;
    for (int c : n.children) sum += weight[c];
    weight[k] = sum;
  }
  return weight;
}

// §3.2: the axis alternates per depth. Each tree (the parts', each floor's) starts across the
// longer side of the region it divides (x on a tie), so a long narrow part is cut into rooms
// across its length instead of into slivers along it.
bool along_x(const TreeNode& node, bool x_first) {
  if (node.orientation == Orientation::kHorizontal) return true;
  if (node.orientation == Orientation::kVertical) return false;
  return (node.depth % 2 == 0) == x_first;
}

// Of a one-polygon region (bounds_of's box: the outer ring's), without copying it into a list.
bool wider_than_tall(const Polygon& region) {
  kernel::Bounds2 b;
  for (const kernel::Vec2 v : region.outer) b.add(v);
  return b.max.x - b.min.x >= b.max.y - b.min.y;
}

// The axis a node cuts along. On a lot the grammar was not written for, the axis it states (or the
// alternation gives) can cut rooms into strips along a thin lot ("Rooms that fit"): when it
// leaves a child's slab thinner than `sliver` (0: never) and the other axis leaves every child
// thicker, the other axis is taken. Slabs are measured on the region's box: along the axis, the
// child's share of it; across, the box's other side.
bool cut_along_x(const TreeNode& n, bool x_first, const std::vector<Polygon>& region,
                 const std::vector<double>& weights, double sliver) {
  const bool stated = along_x(n, x_first);
  if (sliver <= 0 || weights.size() < 2) return stated;
  const kernel::Bounds2 box = bounds_of(region);
  const double w = box.max.x - box.min.x;
  const double h = box.max.y - box.min.y;
  double total = 0;
  for (double k : weights) total += k;
  auto thinnest = [&](bool x) {
    const double along = x ? w : h;
    double m = x ? h : w;
    for (double k : weights) m = std::min(m, along * k / total);
    return m;
  };
  const double kept = thinnest(stated);
  return kept < sliver && thinnest(!stated) > kept ? !stated : stated;
}

// Recursive treemap: `region` is cut among `node`'s children; leaves receive their pieces.
void split_tree(const std::vector<TreeNode>& tree, int node, std::vector<Polygon> region,
                const std::vector<double>& weight, double step, bool x_first, double sliver,
                std::vector<std::vector<Polygon>>& leaf_regions) {
  const TreeNode& n = tree[node];
  if (n.leaf >= 0) {
    leaf_regions[n.leaf] = std::move(region);
    return;
  }
  if (n.children.empty()) return;
  std::vector<double> weights;
  for (int c : n.children) weights.push_back(std::max(weight[c], 1e-12));
  std::vector<std::vector<Polygon>> cells =
      split_region(region, weights, cut_along_x(n, x_first, region, weights, sliver), step);
  for (std::size_t i = 0; i < n.children.size(); ++i)
    split_tree(tree, n.children[i], std::move(cells[i]), weight, step, x_first, sliver,
               leaf_regions);
}

// Keeps each leaf's largest piece and merges the others into the neighbouring leaf that shares
// the longest boundary with them. Returns the pieces no neighbour touches. `regions` is left
// with moved-from pieces.
std::vector<Polygon> settle_pieces(std::vector<std::vector<Polygon>>& regions,
                                   std::vector<Polygon>& cells, std::vector<bool>& has_cell) {
  std::vector<Polygon> orphans;
  cells.assign(regions.size(), Polygon{});
  has_cell.assign(regions.size(), false);
  for (std::size_t i = 0; i < regions.size(); ++i) {
    // A single piece (the usual case) is kept without measuring it; the pieces move (the caller's
    // lists are not read again).
    const int keep = regions[i].size() == 1 ? 0 : largest(regions[i]);
    if (keep < 0) continue;
    cells[i] = std::move(regions[i][keep]);
    has_cell[i] = true;
    for (std::size_t k = 0; k < regions[i].size(); ++k)
      if (static_cast<int>(k) != keep) orphans.push_back(std::move(regions[i][k]));
  }
  // Merging may make an orphan touch a cell it did not touch before; a few rounds settle chains.
  for (int round = 0; round < 4 && !orphans.empty(); ++round) {
    std::vector<Polygon> next;
    for (Polygon& piece : orphans) {
      int best = -1;
      double best_len = 0;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (!has_cell[i]) continue;
        const double len = shared_length(piece, cells[i]);
        if (len > best_len + kLineTolerance) {
          best_len = len;
          best = static_cast<int>(i);
        }
      }
      kernel::BooleanResult u;
      if (best >= 0) u = kernel::unite({cells[best]}, {piece});
      if (best >= 0 && u.ok() && u.polygons.size() == 1) {
        cells[best] = std::move(u.polygons[0]);
        simplify(cells[best]);
      } else {
        next.push_back(std::move(piece));
      }
    }
    const bool progress = next.size() < orphans.size();
    orphans = std::move(next);
    if (!progress) break;
  }
  return orphans;
}

}  // namespace

void warn(Work& work, std::string message, Location where, std::string code) {
  work.warnings.push_back({std::move(message), where, std::move(code)});
}

double door_width_between(const Work& work, int part_a, int part_b) {
  return std::min(work.door_widths[part_a], work.door_widths[part_b]);
}

std::string meters(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string room_name(const Work& work, int room) {
  const WorkRoom& r = work.rooms[room];
  return r.division != nullptr ? r.division->symbol : work.parts[r.part].node->symbol;
}

void build_work(const Building& building, const Restrictions& restrictions, Work& work,
                std::vector<base::Diagnostic>& errors) {
  work.building = &building;
  work.restrictions = &restrictions;
  // The lists sized once: growing them moved every room (with its cell) and floor again and again.
  PartTreeSize size;
  count_parts(building.layout, size);
  work.part_tree.reserve(size.nodes);
  work.parts.reserve(size.parts);
  work.floors.reserve(size.floors);
  work.rooms.reserve(size.rooms);
  add_part(work, building.layout, -1, 0, errors);
  // Parts without rooms (disposable parts usually) weigh as one medium room.
  std::vector<int> ground;
  for (std::size_t p = 0; p < work.parts.size(); ++p) {
    WorkPart& part = work.parts[p];
    if (!part.floors.empty()) part.weight_rooms = work.floors[part.floors[0]].rooms;
    if (part.weight_rooms.empty()) {
      WorkRoom stand_in;
      stand_in.part = static_cast<int>(p);
      stand_in.floor = -1;
      part.weight_rooms.push_back(static_cast<int>(work.rooms.size()));
      work.rooms.push_back(stand_in);
    }
    ground.insert(ground.end(), part.weight_rooms.begin(), part.weight_rooms.end());
    if (!part.disposable())
      work.levels = std::max(work.levels, static_cast<int>(part.floors.size()));
  }
  // Fig. 3: the ground floor's rooms of the whole building share one distribution (it sizes the
  // parts); each upper floor distributes its own rooms inside its part.
  distribute(work, ground);
  for (const WorkFloor& floor : work.floors)
    if (floor.level > 0) distribute(work, floor.rooms);
}

bool subdivide_parts(Work& work) {
  const auto weight = [&](int part) {
    double sum = 0;
    for (int r : work.parts[part].weight_rooms) sum += work.rooms[r].weight;
    return sum;
  };
  std::vector<std::vector<Polygon>> regions(work.parts.size());
  // Parts keep their axes: fake-concave shapes (an L, a U) are made by them.
  split_tree(work.part_tree, 0, {work.outline}, node_weights(work.part_tree, weight),
             work.restrictions->step, wider_than_tall(work.outline), 0, regions);
  std::vector<Polygon> cells;
  std::vector<bool> has_cell;
  const std::vector<Polygon> left = settle_pieces(regions, cells, has_cell);
  bool changed = false;
  for (std::size_t p = 0; p < work.parts.size(); ++p) {
    WorkPart& part = work.parts[p];
    const bool same = part.has_cell == has_cell[p] && part.cell.outer == cells[p].outer &&
                      part.cell.holes == cells[p].holes;
    if (!same) changed = true;
    part.cell = std::move(cells[p]);
    part.has_cell = has_cell[p];
  }
  if (!left.empty() && changed) {
    warn(work, "the outline falls apart under the part arrangement; " +
                   std::to_string(left.size()) +
                   " piece(s) touching no part are left out of the footprint");
  }
  return changed;
}

void subdivide_floor(Work& work, int floor_index) {
  WorkFloor& floor = work.floors[floor_index];
  const WorkPart& part = work.parts[floor.part];
  // Leaf regions by room index (only this floor's entries are written).
  std::vector<std::vector<Polygon>> regions(work.rooms.size());
  const auto weight = [&](int room) { return work.rooms[room].weight; };
  if (part.has_cell)
    split_tree(floor.tree, 0, {part.cell}, node_weights(floor.tree, weight),
               work.restrictions->step, wider_than_tall(part.cell), work.sliver, regions);
  std::vector<std::vector<Polygon>> mine;
  mine.reserve(floor.rooms.size());
  for (int r : floor.rooms) mine.push_back(std::move(regions[r]));
  std::vector<Polygon> cells;
  std::vector<bool> has_cell;
  const std::vector<Polygon> left = settle_pieces(mine, cells, has_cell);
  for (std::size_t i = 0; i < floor.rooms.size(); ++i) {
    WorkRoom& room = work.rooms[floor.rooms[i]];
    room.cell = std::move(cells[i]);
    room.has_cell = has_cell[i];
  }
  floor.dead_zones.clear();
  for (const Polygon& piece : left)
    floor.dead_zones.push_back({piece, "a piece of the floor the treemap cut off from its room"});
}

void subdivide_all(Work& work) {
  subdivide_parts(work);
  for (std::size_t f = 0; f < work.floors.size(); ++f) subdivide_floor(work, static_cast<int>(f));
}

}  // namespace insula::lang::bldg::plan
