// Stochastic generation (seed 000, §4.3): the rooms are arranged by priority, the connected
// divisions' graph is set up, and the rooms are placed in a treemap-like node structure that is
// a Building model (and, through print_building, grammar rules).
//
// Steps: (1) a building-part skeleton for the requested shape, with disposable parts cutting the
// L, U, T and H notches (§3.2 "fake-concave"), and extra parts made by splitting real ones;
// (2) a room program (the given room list, or a default domestic one) sorted by priority;
// (3) a nominal treemap of rectangles from the size labels' growth factors (Eqs. 1-2 on a
// rectangular outline, where the intersection of Eq. 3 is the rectangle itself) used to order the
// parts from the entrance inwards and to know which rooms share a wall; (4) a door tree grown
// from the entrance room (Prim-like, doors preferably leave public rooms), plus a few extra
// doors between public rooms; (5) windows on rooms with exterior wall length.
#include "lang/bldg/stochastic.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numeric>
#include <span>
#include <string_view>
#include <tuple>

#include "shape/rng.h"

namespace insula::lang::bldg {
namespace {

using shape::Rng;

struct Rect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// Growth factors of the default restriction rules (§3.3): room weights are proportional to them.
double growth(SizeLabel size) {
  static const Restrictions defaults;  // built once: a Restrictions holds maps and strings
  return defaults.growth[static_cast<std::size_t>(size)];
}

// Nominal floor area per unit of weight, m² (a medium room ~16 m²).
constexpr double kAreaPerWeight = 8.0;
// Fraction of the outline left to rooms once walls are raised.
constexpr double kUsableFraction = 0.85;
// Generated doors state their width (door(a, b, 1)), so the grammar keeps it whatever rules it is
// built with (a door_width_fraction rule gives 2 m doors in a 35 m building).
constexpr double kDoorWidth = 1.0;
constexpr double kEntranceWidth = 1.2;
// A door needs this much shared wall in the nominal layout: its width, the floor-plan engine's
// clearance at both ends (half a wall and a jamb, 0.25 m each with the default rules) and slack
// for the engine's weight adjustments; the later passes accept less rather than leave a room out.
constexpr double kDoorOverlap[] = {kDoorWidth + 0.5 + 0.6, kDoorWidth + 0.5 + 0.2, 0.01};

struct GenRoom {
  // A view into the generator's spec (its room list) or a string literal: both outlive the
  // generator's rooms, and a view costs no copy per room.
  std::string_view type;
  SizeLabel size = SizeLabel::kMedium;
  int priority = 2;
  std::string symbol;
  Rect rect;
  bool disposable = false;
  bool dead_end = false;  // dead_end(type), asked for every door the room could give
  int windows = 0;
};

// A node of the part skeleton: a container of cells or a building part (leaf).
struct Cell {
  bool leaf = true;
  bool disposable = false;
  Orientation orientation = Orientation::kHorizontal;
  std::vector<Cell> children;
  int room_count = 0;
  std::vector<int> rooms;  // leaf: indices into the room list, in priority order
  Rect rect;
  std::size_t division = 0;  // leaf: the root of its division tree in Generator::divisions_
};

// A node of a part's division tree. The nodes of every part live in one list (no vector per
// node); a node's children are the `count` nodes from `first`.
struct DivNode {
  int room = -1;  // leaf when >= 0
  Orientation orientation = Orientation::kHorizontal;
  std::size_t first = 0;
  std::size_t count = 0;
  // The growth factors of its rooms: a leaf's own, a container's the sum of its children's in
  // order (the weight place_rooms slices by).
  double weight = 0;
};

Orientation along_longer(const Rect& r) {
  return r.width() >= r.height() ? Orientation::kHorizontal : Orientation::kVertical;
}
Orientation perpendicular(Orientation o) {
  return o == Orientation::kHorizontal ? Orientation::kVertical : Orientation::kHorizontal;
}

// ---- room program and priorities ----

struct TypeInfo {
  std::string_view type;  // a view: comparing lengths first rejects most names at once
  int priority;           // 0 public (near the entrance), 1 service, 2 private
  SizeLabel size;
};
constexpr TypeInfo kTypes[] = {
    {"atrium", 0, SizeLabel::kBig},     {"hall", 0, SizeLabel::kSmall},
    {"living", 0, SizeLabel::kBig},     {"lobby", 0, SizeLabel::kMedium},
    {"corridor", 0, SizeLabel::kSmall}, {"vestibule", 0, SizeLabel::kSmall},
    {"shop", 0, SizeLabel::kMedium},    {"taberna", 0, SizeLabel::kMedium},
    {"fauces", 0, SizeLabel::kSmall},   {"peristylium", 0, SizeLabel::kBig},
    {"kitchen", 1, SizeLabel::kMedium}, {"dining", 1, SizeLabel::kMedium},
    {"culina", 1, SizeLabel::kSmall},   {"triclinium", 1, SizeLabel::kMedium},
    {"pantry", 1, SizeLabel::kSmall},   {"storage", 1, SizeLabel::kSmall},
    {"laundry", 1, SizeLabel::kSmall},  {"tablinum", 1, SizeLabel::kMedium},
    {"bedroom", 2, SizeLabel::kMedium}, {"bathroom", 2, SizeLabel::kSmall},
    {"study", 2, SizeLabel::kSmall},    {"cubiculum", 2, SizeLabel::kSmall},
    {"office", 2, SizeLabel::kMedium},  {"guest", 2, SizeLabel::kMedium},
};

const TypeInfo* type_info(std::string_view type) {
  for (const TypeInfo& info : kTypes) {
    if (type == info.type) return &info;
  }
  return nullptr;
}

// Rooms that should end a walk, not be passed through (a door tree through a bathroom is odd).
bool dead_end(std::string_view type) {
  return type == "bathroom" || type == "storage" || type == "pantry" || type == "laundry" ||
         type == "void";
}

// `info` is type_info(type), looked up by the caller.
GenRoom make_room(std::string_view type, const TypeInfo* info, Rng& rng) {
  GenRoom room;
  room.type = type;
  room.dead_end = dead_end(type);
  if (info) {
    room.priority = info->priority;
    room.size = info->size;
    if (type == "bedroom" && rng.unit() < 0.4) room.size = SizeLabel::kBig;
  }
  return room;
}

// A default domestic program of n rooms: a hall, a living room and a kitchen first, then a
// bathroom per six rooms and a mix of private and service rooms.
// The program's types are entries of kTypes, looked up once.
std::vector<const TypeInfo*> default_program(int n, Rng& rng) {
  static const std::array<const TypeInfo*, 4> firsts = {
      type_info("hall"), type_info("living"), type_info("kitchen"), type_info("bathroom")};
  static const std::array<const TypeInfo*, 7> rest = {
      type_info("bedroom"), type_info("bedroom"), type_info("bedroom"), type_info("dining"),
      type_info("study"),   type_info("storage"), type_info("bathroom")};
  std::vector<const TypeInfo*> out;
  out.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int i = 0; i < n && i < 4; ++i) out.push_back(firsts[static_cast<std::size_t>(i)]);
  const double weights[] = {3, 3, 3, 1, 1, 1, 1};
  while (static_cast<int>(out.size()) < n) {
    out.push_back(rest[rng.choice(weights)]);
  }
  return out;
}

// Appends the decimal digits of `n`, as std::to_string writes them, without a temporary string.
void append_number(std::string& out, std::size_t n) {
  std::array<char, 24> digits;
  char* end = std::to_chars(digits.data(), digits.data() + digits.size(), n).ptr;
  out.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

// ---- skeleton ----

Cell leaf(bool disposable = false) {
  Cell c;
  c.disposable = disposable;
  return c;
}
Cell container(Orientation o, std::vector<Cell> children) {
  Cell c;
  c.leaf = false;
  c.orientation = o;
  c.children = std::move(children);
  return c;
}

// The fake-concave skeletons (§3.2, Fig. 7): children are placed from low to high coordinate,
// so the front (y = 0) is the first child of a vertical container.
Cell skeleton(RandomShape shape, bool wide) {
  const auto H = Orientation::kHorizontal;
  const auto V = Orientation::kVertical;
  switch (shape) {
    case RandomShape::kConvex:
      return container(wide ? H : V, {leaf()});
    case RandomShape::kL:
      return container(H, {leaf(), container(V, {leaf(), leaf(true)})});
    case RandomShape::kU:
      return container(H, {leaf(), container(V, {leaf(), leaf(true)}), leaf()});
    case RandomShape::kT:
      return container(V, {container(H, {leaf(true), leaf(), leaf(true)}), leaf()});
    case RandomShape::kH:
      return container(H, {leaf(), container(V, {leaf(true), leaf(), leaf(true)}), leaf()});
  }
  return container(H, {leaf()});
}

int min_parts(RandomShape shape) {
  switch (shape) {
    case RandomShape::kConvex:
      return 1;
    case RandomShape::kL:
    case RandomShape::kT:
      return 2;
    case RandomShape::kU:
    case RandomShape::kH:
      return 3;
  }
  return 1;
}

void collect_leaves(Cell& cell, std::vector<Cell*>& out, bool real_only) {
  if (cell.leaf) {
    if (!real_only || !cell.disposable) out.push_back(&cell);
    return;
  }
  for (Cell& child : cell.children) collect_leaves(child, out, real_only);
}

// Adds one real part by splitting a real leaf: a new sibling when the parent has room (fewer
// than 3 children), else the leaf becomes a perpendicular container of two parts.
bool split_one(Cell& parent, Rng& rng, int& budget) {
  std::vector<std::size_t> real;
  for (std::size_t i = 0; i < parent.children.size(); ++i) {
    if (parent.children[i].leaf && !parent.children[i].disposable) real.push_back(i);
  }
  std::vector<std::size_t> inner;
  for (std::size_t i = 0; i < parent.children.size(); ++i) {
    if (!parent.children[i].leaf) inner.push_back(i);
  }
  if (!real.empty() && (inner.empty() || rng.unit() < 0.5)) {
    const std::size_t i =
        real[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(real.size()) - 1))];
    const bool has_disposable = std::any_of(parent.children.begin(), parent.children.end(),
                                            [](const Cell& c) { return c.disposable; });
    if (parent.children.size() < 3 && !has_disposable) {
      parent.children.insert(parent.children.begin() + static_cast<std::ptrdiff_t>(i) + 1, leaf());
    } else {
      parent.children[i] = container(perpendicular(parent.orientation), {leaf(), leaf()});
    }
    --budget;
    return true;
  }
  if (inner.empty()) return false;
  const std::size_t i =
      inner[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(inner.size()) - 1))];
  return split_one(parent.children[i], rng, budget);
}

// ---- nominal treemap (Eqs. 1-2 on rectangles) ----

double cell_weight(const Cell& cell, const std::vector<GenRoom>& rooms) {
  if (cell.leaf) {
    if (cell.rooms.empty()) return 2.0 * std::max(1, cell.room_count);
    double w = 0;
    for (const int r : cell.rooms) w += growth(rooms[static_cast<std::size_t>(r)].size);
    return w;
  }
  double w = 0;
  for (const Cell& child : cell.children) w += cell_weight(child, rooms);
  return w;
}

// Splits `rect` along `o` into pieces proportional to `weights`, the last taking the remainder
// (§3.2: "last index sub-BLSEs ... the remaining space is directly allocated to them"); piece i
// goes to out[i] (`out` holds weights.size() rects).
void slice(const Rect& rect, Orientation o, std::span<const double> weights, std::span<Rect> out) {
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double at = o == Orientation::kHorizontal ? rect.x0 : rect.y0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    Rect r = rect;
    const double extent = o == Orientation::kHorizontal ? rect.width() : rect.height();
    const double next = i + 1 == weights.size()
                            ? (o == Orientation::kHorizontal ? rect.x1 : rect.y1)
                            : at + extent * weights[i] / total;
    if (o == Orientation::kHorizontal) {
      r.x0 = at;
      r.x1 = next;
    } else {
      r.y0 = at;
      r.y1 = next;
    }
    out[i] = r;
    at = next;
  }
}

void place_cells(Cell& cell, const Rect& rect, const std::vector<GenRoom>& rooms) {
  cell.rect = rect;
  if (cell.leaf) return;
  std::vector<double> weights;
  for (const Cell& child : cell.children) weights.push_back(cell_weight(child, rooms));
  std::vector<Rect> pieces(weights.size());
  slice(rect, cell.orientation, weights, pieces);
  for (std::size_t i = 0; i < cell.children.size(); ++i) {
    place_cells(cell.children[i], pieces[i], rooms);
  }
}

// Children of a division node: up to three groups of rooms (§4.3).
constexpr std::size_t kMaxGroups = 3;

void place_rooms(const std::vector<DivNode>& nodes, std::size_t at, const Rect& rect,
                 std::vector<GenRoom>& rooms) {
  const DivNode& node = nodes[at];
  if (node.room >= 0) {
    rooms[static_cast<std::size_t>(node.room)].rect = rect;
    return;
  }
  // divide() makes at most kMaxGroups children per node.
  std::array<double, kMaxGroups> weights{};
  std::array<Rect, kMaxGroups> pieces{};
  const std::size_t n = node.count;
  for (std::size_t i = 0; i < n; ++i) weights[i] = nodes[node.first + i].weight;
  slice(rect, node.orientation, std::span(weights).first(n), std::span(pieces).first(n));
  for (std::size_t i = 0; i < n; ++i) place_rooms(nodes, node.first + i, pieces[i], rooms);
}

// The treemap-like node structure of one part's rooms (§4.3): groups of up to three rooms in
// containers, the axis along the longer side of the space so rooms stay compact. Fills
// nodes[self] with the rooms ids[lo, hi); its children are appended to `nodes` as one block.
void divide(const std::vector<int>& ids, std::size_t lo, std::size_t hi, const Rect& rect,
            const std::vector<GenRoom>& rooms, Rng& rng, std::vector<DivNode>& nodes,
            std::size_t self) {
  if (hi - lo == 1) {
    nodes[self].room = ids[lo];
    nodes[self].weight = growth(rooms[static_cast<std::size_t>(ids[lo])].size);
    return;
  }
  const Orientation orientation = along_longer(rect);
  nodes[self].orientation = orientation;
  const std::size_t n = hi - lo;
  std::array<std::pair<std::size_t, std::size_t>, kMaxGroups> groups{};
  std::size_t count = 0;
  if (n <= kMaxGroups) {
    for (std::size_t i = lo; i < hi; ++i) groups[count++] = {i, i + 1};
  } else {
    const std::size_t k = (n >= 7 && rng.unit() < 0.4) ? 3 : 2;
    std::size_t at = lo;
    for (std::size_t g = 0; g < k; ++g) {
      const std::size_t left = hi - at, groups_left = k - g;
      std::size_t size = left / groups_left;
      if (groups_left > 1 && left > groups_left * 2 && rng.unit() < 0.5) size += 1;
      if (g + 1 == k) size = left;
      groups[count++] = {at, at + size};
      at += size;
    }
  }
  std::array<double, kMaxGroups> weights{};
  for (std::size_t g = 0; g < count; ++g) {
    double w = 0;
    for (std::size_t i = groups[g].first; i < groups[g].second; ++i) {
      w += growth(rooms[static_cast<std::size_t>(ids[i])].size);
    }
    weights[g] = w;
  }
  std::array<Rect, kMaxGroups> pieces{};
  slice(rect, orientation, std::span(weights).first(count), std::span(pieces).first(count));
  const std::size_t first = nodes.size();
  nodes[self].first = first;
  nodes[self].count = count;
  nodes.resize(first + count);  // invalidates references into `nodes`: indices only below
  double weight = 0;
  for (std::size_t g = 0; g < count; ++g) {
    divide(ids, groups[g].first, groups[g].second, pieces[g], rooms, rng, nodes, first + g);
    weight += nodes[first + g].weight;
  }
  nodes[self].weight = weight;
}

// Length of the wall two rectangles share (0 when they do not touch along a side).
double shared_length(const Rect& a, const Rect& b) {
  constexpr double kEps = 1e-6;
  // Apart by more than kEps along an axis: no side can touch (most pairs of a building's rooms).
  if (a.x1 < b.x0 - kEps || b.x1 < a.x0 - kEps || a.y1 < b.y0 - kEps || b.y1 < a.y0 - kEps) {
    return 0;
  }
  const auto overlap = [](double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
  };
  if (std::abs(a.x1 - b.x0) < kEps || std::abs(b.x1 - a.x0) < kEps) {
    return overlap(a.y0, a.y1, b.y0, b.y1);
  }
  if (std::abs(a.y1 - b.y0) < kEps || std::abs(b.y1 - a.y0) < kEps) {
    return overlap(a.x0, a.x1, b.x0, b.x1);
  }
  return 0;
}

double boundary_length(const Rect& r, const Rect& outline) {
  constexpr double kEps = 1e-6;
  double length = 0;
  if (std::abs(r.x0 - outline.x0) < kEps) length += r.height();
  if (std::abs(r.x1 - outline.x1) < kEps) length += r.height();
  if (std::abs(r.y0 - outline.y0) < kEps) length += r.width();
  if (std::abs(r.y1 - outline.y1) < kEps) length += r.width();
  return length;
}

// boundary_length of one side of a room (a rectangle of zero width or height) at coordinate
// `at`, `length` long, against the outline's sides at `lo` and `hi` on the same axis: the same
// sums, without the zero-length terms.
double side_run(double at, double length, double lo, double hi) {
  constexpr double kEps = 1e-6;
  double run = 0;
  if (std::abs(at - lo) < kEps) run += length;
  if (std::abs(at - hi) < kEps) run += length;
  return run;
}

std::string identifier(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    out += ok ? c : '_';
  }
  if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out = "r_" + out;
  return out;
}

// Rounds to 1 / `per_unit` (10: decimetres) without binary noise in the printed grammar.
double round_to(double v, double per_unit) {
  return std::round(v * per_unit) / per_unit;
}

class Generator {
 public:
  Generator(const RandomSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {}

  Building run() {
    make_skeleton();
    make_program();
    order_and_assign();
    make_divisions();
    connect();
    add_windows();
    return emit();
  }

 private:
  void make_skeleton() {
    const int minimum = min_parts(spec_.shape);
    int parts = spec_.parts > 0 ? std::max(spec_.parts, minimum)
                                : static_cast<int>(rng_.integer(minimum, minimum + 2));
    parts = std::min(parts, 24);
    wide_ = rng_.unit() < 0.5;
    root_ = skeleton(spec_.shape, wide_);
    int budget = parts - minimum;
    while (budget > 0) {
      if (!split_one(root_, rng_, budget)) break;
    }
    std::vector<Cell*> real;
    collect_leaves(root_, real, true);
    const int lo = std::max(1, std::min(spec_.rooms_min, spec_.rooms_max));
    const int hi = std::max(lo, std::max(spec_.rooms_min, spec_.rooms_max));
    for (Cell* cell : real) cell->room_count = static_cast<int>(rng_.integer(lo, hi));
  }

  // The room list: the one given (repeated when shorter than the parts need), or a default
  // program; then the rooms are sorted by priority (§4.3), ties in random order.
  void make_program() {
    std::vector<Cell*> real;
    collect_leaves(root_, real, true);
    int total = 0;
    for (Cell* cell : real) total += cell->room_count;
    if (!spec_.room_types.empty()) {
      std::vector<std::string_view> types(spec_.room_types.begin(), spec_.room_types.end());
      while (types.size() < real.size())
        types.push_back(spec_.room_types[types.size() % spec_.room_types.size()]);
      redistribute(real, static_cast<int>(types.size()));
      rooms_.reserve(types.size());
      for (const std::string_view type : types) {
        rooms_.push_back(make_room(type, type_info(type), rng_));
      }
    } else {
      const std::vector<const TypeInfo*> types = default_program(total, rng_);
      rooms_.reserve(types.size());
      for (const TypeInfo* info : types) rooms_.push_back(make_room(info->type, info, rng_));
    }
    // A stable sort by (priority, key) is a sort by (priority, key, index): no buffer needed.
    struct Rank {
      int priority;
      std::uint64_t key;
      int index;
    };
    std::vector<Rank> ranks(rooms_.size());
    for (std::size_t i = 0; i < ranks.size(); ++i) {
      ranks[i] = {rooms_[i].priority, rng_.next(), static_cast<int>(i)};
    }
    std::sort(ranks.begin(), ranks.end(), [](const Rank& a, const Rank& b) {
      if (a.priority != b.priority) return a.priority < b.priority;
      if (a.key != b.key) return a.key < b.key;
      return a.index < b.index;
    });
    order_.resize(ranks.size());
    for (std::size_t i = 0; i < ranks.size(); ++i) order_[i] = ranks[i].index;
  }

  // Spreads `n` rooms over the real parts as evenly as possible (at least one each).
  void redistribute(std::vector<Cell*>& real, int n) {
    const int parts = static_cast<int>(real.size());
    for (int i = 0; i < parts; ++i) real[static_cast<std::size_t>(i)]->room_count = n / parts;
    for (int i = 0; i < n % parts; ++i) ++real[static_cast<std::size_t>(i)]->room_count;
  }

  // Parts ordered from the entrance inwards (breadth first over parts that share a wall), and
  // the priority-sorted rooms dealt to them in that order: public rooms at the entrance.
  void order_and_assign() {
    std::vector<Cell*> real;
    collect_leaves(root_, real, true);
    std::vector<Cell*> disposable;
    collect_leaves(root_, disposable, false);
    disposable.erase(std::remove_if(disposable.begin(), disposable.end(),
                                    [](const Cell* c) { return !c->disposable; }),
                     disposable.end());
    size_disposables(root_);
    outline_ = outline_rect();
    place_cells(root_, outline_, rooms_);
    const std::size_t front = front_leaf(real);
    std::vector<std::size_t> queue{front};
    std::vector<bool> seen(real.size(), false);
    seen[front] = true;
    std::vector<std::pair<double, std::size_t>> next;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      next.clear();
      for (std::size_t j = 0; j < real.size(); ++j) {
        const double shared = shared_length(real[queue[q]]->rect, real[j]->rect);
        if (!seen[j] && shared > 0) next.emplace_back(-shared, j);
      }
      std::sort(next.begin(), next.end());
      for (const auto& [unused, j] : next) {
        seen[j] = true;
        queue.push_back(j);
      }
    }
    for (std::size_t j = 0; j < real.size(); ++j) {
      if (!seen[j]) queue.push_back(j);  // not expected: every skeleton is connected
    }
    std::size_t at = 0;
    for (const std::size_t j : queue) {
      real[j]->rooms.reserve(static_cast<std::size_t>(std::max(real[j]->room_count, 0)));
      for (int k = 0; k < real[j]->room_count && at < order_.size(); ++k) {
        real[j]->rooms.push_back(order_[at++]);
      }
    }
    // Disposable parts get medium "void" rooms weighing about as much as their real sibling,
    // so the notch is proportionate (it is removed after the subdivision, §3.2).
    for (Cell* cell : disposable) {
      cell->rooms.reserve(static_cast<std::size_t>(std::max(cell->room_count, 0)));
      for (int k = 0; k < cell->room_count; ++k) {
        GenRoom room;
        room.type = "void";
        room.disposable = true;
        room.dead_end = dead_end(room.type);
        room.priority = 3;
        cell->rooms.push_back(static_cast<int>(rooms_.size()));
        rooms_.push_back(room);
      }
    }
    outline_ = outline_rect();
    place_cells(root_, outline_, rooms_);
  }

  void size_disposables(Cell& cell) {
    if (cell.leaf) return;
    double sibling = 0;
    int real_children = 0;
    for (const Cell& child : cell.children) {
      if (!child.disposable) {
        sibling += cell_weight(child, rooms_);
        ++real_children;
      }
    }
    for (Cell& child : cell.children) {
      if (child.disposable) {
        const double target = real_children > 0 ? sibling / real_children : 4.0;
        child.room_count =
            std::max(1, static_cast<int>(std::lround(target / growth(SizeLabel::kMedium))));
      }
      size_disposables(child);
    }
  }

  // A rectangle whose area holds every room's nominal area; its aspect depends on the shape.
  Rect outline_rect() {
    const double weight = cell_weight(root_, rooms_);
    const double area = weight * kAreaPerWeight / kUsableFraction;
    if (aspect_ == 0) {
      switch (spec_.shape) {
        case RandomShape::kConvex:
          aspect_ = rng_.uniform(1.0, 1.6);
          break;
        case RandomShape::kL:
          aspect_ = rng_.uniform(1.0, 1.3);
          break;
        case RandomShape::kU:
        case RandomShape::kH:
          aspect_ = rng_.uniform(1.2, 1.5);
          break;
        case RandomShape::kT:
          aspect_ = rng_.uniform(1.0, 1.3);
          break;
      }
      if (spec_.shape == RandomShape::kConvex && !wide_) aspect_ = 1 / aspect_;
    }
    const double width = std::max(4.0, round_to(std::sqrt(area * aspect_), 10));
    const double depth = std::max(4.0, round_to(area / width, 10));
    return Rect{0, 0, width, depth};
  }

  // The real part on the front edge (y = 0) nearest the middle: the entrance side.
  std::size_t front_leaf(const std::vector<Cell*>& real) const {
    std::size_t best = 0;
    double best_score = 1e300;
    const double mid = (outline_.x0 + outline_.x1) / 2;
    for (std::size_t j = 0; j < real.size(); ++j) {
      const Rect& r = real[j]->rect;
      if (r.y0 > outline_.y0 + 1e-6) continue;
      const double score = std::abs((r.x0 + r.x1) / 2 - mid);
      if (score < best_score) {
        best_score = score;
        best = j;
      }
    }
    return best;
  }

  void make_divisions() {
    std::vector<Cell*> leaves;
    collect_leaves(root_, leaves, false);
    // A tree of r rooms has fewer than 2r nodes.
    divisions_.reserve(2 * rooms_.size() + leaves.size());
    for (Cell* cell : leaves) {
      cell->division = divisions_.size();
      divisions_.emplace_back();
      divide(cell->rooms, 0, cell->rooms.size(), cell->rect, rooms_, rng_, divisions_,
             cell->division);
      place_rooms(divisions_, cell->division, cell->rect, rooms_);
    }
  }

  // §4.3 "sets up the connected divisions' graph": the entrance on the front room of highest
  // priority, then a tree of doors grown from it over rooms that share a wall, each step taking a
  // door from the most public room that can give one, then extra doors between public rooms.
  void connect() {
    entrance_ = choose_entrance();
    seed_salt_ = rng_.next();
    const std::size_t n = rooms_.size();
    set_neighbors(touching_pairs());
    std::vector<char> in_tree(n, 0);
    in_tree[static_cast<std::size_t>(entrance_)] = true;
    std::size_t reached = 1;
    std::size_t wanted = 0;
    for (const GenRoom& room : rooms_) wanted += room.disposable ? 0 : 1;
    for (const double threshold : kDoorOverlap) {
      if (reached < wanted) reached += grow_tree(threshold, in_tree);
    }
    // Not expected with the skeletons above; keeps the graph guarantee for any program.
    for (std::size_t v = 0; v < n && reached < wanted; ++v) {
      if (in_tree[v] || rooms_[v].disposable) continue;
      doors_.emplace_back(nearest_in_tree(v, in_tree), static_cast<int>(v));
      in_tree[v] = 1;
      ++reached;
    }
    add_extra_doors();
  }

  // Two rooms sharing a wall of positive length.
  struct Touch {
    int u, v;  // u < v
    double shared;
  };

  // The pairs (u < v, in increasing order) of real rooms sharing a wall of positive length, with
  // its length. A sweep over the rooms sorted by left edge compares only rooms whose x ranges
  // meet, instead of all n² pairs; their rectangles are copied into the sorted list so the sweep
  // reads them in order, and pairs whose y ranges are apart (most of them) are skipped before
  // shared_length.
  std::vector<Touch> touching_pairs() const {
    constexpr double kEps = 1e-6;  // shared_length's tolerance
    struct Placed {
      Rect rect;
      int room;
    };
    std::vector<Placed> by_x;
    by_x.reserve(rooms_.size());
    for (std::size_t u = 0; u < rooms_.size(); ++u) {
      if (!rooms_[u].disposable) by_x.push_back({rooms_[u].rect, static_cast<int>(u)});
    }
    std::sort(by_x.begin(), by_x.end(), [](const Placed& a, const Placed& b) {
      return a.rect.x0 != b.rect.x0 ? a.rect.x0 < b.rect.x0 : a.room < b.room;
    });
    std::vector<Touch> pairs;
    for (std::size_t i = 0; i < by_x.size(); ++i) {
      const Rect& a = by_x[i].rect;
      const double reach = a.x1 + kEps;
      for (std::size_t j = i + 1; j < by_x.size() && by_x[j].rect.x0 <= reach; ++j) {
        const Rect& b = by_x[j].rect;
        if (b.y1 < a.y0 - kEps || a.y1 < b.y0 - kEps) continue;  // shared_length would be 0
        const double shared = shared_length(a, b);
        if (shared > 0) {
          const int u = by_x[i].room, v = by_x[j].room;
          pairs.push_back({std::min(u, v), std::max(u, v), shared});
        }
      }
    }
    // Each pair is found once, so ordering by (u, v) is the tuples' order.
    std::sort(pairs.begin(), pairs.end(),
              [](const Touch& a, const Touch& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
    return pairs;
  }

  // Rooms that share a wall in the nominal layout, with the shared length (computed once), as
  // one flat list sliced per room: room u's neighbours are neighbors_[neighbor_start_[u] ..
  // neighbor_start_[u + 1]), in the order of `pairs` (what pushing to per-room lists gives,
  // without a vector per room).
  void set_neighbors(const std::vector<Touch>& pairs) {
    const std::size_t n = rooms_.size();
    neighbor_start_.assign(n + 1, 0);
    for (const auto& [u, v, shared] : pairs) {
      ++neighbor_start_[static_cast<std::size_t>(u) + 1];
      ++neighbor_start_[static_cast<std::size_t>(v) + 1];
    }
    for (std::size_t u = 0; u < n; ++u) neighbor_start_[u + 1] += neighbor_start_[u];
    neighbors_.resize(neighbor_start_[n]);
    std::vector<std::size_t> next(neighbor_start_.begin(), neighbor_start_.end() - 1);
    for (const auto& [u, v, shared] : pairs) {
      neighbors_[next[static_cast<std::size_t>(u)]++] = {v, shared};
      neighbors_[next[static_cast<std::size_t>(v)]++] = {u, shared};
    }
  }

  std::span<const std::pair<int, double>> neighbors(std::size_t u) const {
    return std::span(neighbors_)
        .subspan(neighbor_start_[u], neighbor_start_[u + 1] - neighbor_start_[u]);
  }

  // Prim's algorithm over walls at least `threshold` long: the next door is the frontier edge of
  // smallest key (the source room's priority, dead ends last, then a seeded hash). Returns the
  // number of rooms added.
  // A room's edges enter the frontier at most once per call, so no two candidates have equal
  // keys and the order of doors depends only on the keys, not on the heap's layout. The heap's
  // storage (frontier_) is kept from call to call.
  std::size_t grow_tree(double threshold, std::vector<char>& in_tree) {
    std::vector<Candidate>& frontier = frontier_;
    frontier.clear();
    const auto push_edges = [&](int u) {
      const GenRoom& from = rooms_[static_cast<std::size_t>(u)];
      const int key = from.priority + (from.dead_end ? 3 : 0);
      for (const auto& [v, shared] : neighbors(static_cast<std::size_t>(u))) {
        if (in_tree[static_cast<std::size_t>(v)] || shared < threshold) continue;
        const std::uint64_t hash =
            shape::mix64(seed_salt_ ^ (static_cast<std::uint64_t>(u) * 1315423911U +
                                       static_cast<std::uint64_t>(v)));
        frontier.push_back({key, hash, u, v});
        std::push_heap(frontier.begin(), frontier.end(), CandidateAfter());
      }
    };
    for (std::size_t u = 0; u < in_tree.size(); ++u) {
      if (in_tree[u]) push_edges(static_cast<int>(u));
    }
    std::size_t added = 0;
    while (!frontier.empty()) {
      std::pop_heap(frontier.begin(), frontier.end(), CandidateAfter());
      const auto [key, hash, u, v] = frontier.back();
      frontier.pop_back();
      if (in_tree[static_cast<std::size_t>(v)]) continue;
      doors_.emplace_back(u, v);
      in_tree[static_cast<std::size_t>(v)] = 1;
      ++added;
      push_edges(v);
    }
    return added;
  }

  int nearest_in_tree(std::size_t v, const std::vector<char>& in_tree) const {
    int best = entrance_;
    double best_d = 1e300;
    const Rect& a = rooms_[v].rect;
    for (std::size_t u = 0; u < rooms_.size(); ++u) {
      if (!in_tree[u]) continue;
      const Rect& b = rooms_[u].rect;
      const double d = std::hypot((a.x0 + a.x1 - b.x0 - b.x1) / 2, (a.y0 + a.y1 - b.y0 - b.y1) / 2);
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(u);
      }
    }
    return best;
  }

  // Extra doors only join neighbours, each pair once (u < v), so a door already there is found
  // by marking the neighbour-list slot of every door's lower room.
  void add_extra_doors() {
    std::vector<char> has_door(neighbors_.size(), 0);
    for (const auto& [x, y] : doors_) {
      const auto a = static_cast<std::size_t>(std::min(x, y));
      const int b = std::max(x, y);
      for (std::size_t k = neighbor_start_[a]; k < neighbor_start_[a + 1]; ++k) {
        if (neighbors_[k].first == b) has_door[k] = 1;
      }
    }
    for (std::size_t u = 0; u < rooms_.size(); ++u) {
      const int a = static_cast<int>(u);
      for (std::size_t k = neighbor_start_[u]; k < neighbor_start_[u + 1]; ++k) {
        const auto& [v, shared] = neighbors_[k];
        if (v <= a || shared < kDoorOverlap[0]) continue;
        if (rooms_[u].priority > 1 || rooms_[static_cast<std::size_t>(v)].priority > 1) continue;
        if (!has_door[k] && rng_.unit() < 0.25) doors_.emplace_back(a, v);
      }
    }
  }

  int choose_entrance() const {
    int best = -1;
    std::pair<int, double> best_key{1 << 30, 0};
    const double mid = (outline_.x0 + outline_.x1) / 2;
    for (int pass = 0; pass < 2 && best < 0; ++pass) {
      for (std::size_t i = 0; i < rooms_.size(); ++i) {
        const GenRoom& room = rooms_[i];
        if (room.disposable) continue;
        const bool front = room.rect.y0 <= outline_.y0 + 1e-6;
        if (pass == 0 ? !front : boundary_length(room.rect, outline_) <= 0) continue;
        const std::pair<int, double> key{room.priority,
                                         std::abs((room.rect.x0 + room.rect.x1) / 2 - mid)};
        if (key < best_key) {
          best_key = key;
          best = static_cast<int>(i);
        }
      }
    }
    if (best >= 0) return best;
    for (std::size_t i = 0; i < rooms_.size(); ++i) {
      if (!rooms_[i].disposable) return static_cast<int>(i);
    }
    return 0;
  }

  // Windows where a room has exterior wall: the outline, or a disposable part's side (which is
  // exterior once the part is removed).
  void add_windows() {
    // A window needs window_width (1.2) plus the engine's clearance at both ends on one straight
    // exterior wall.
    constexpr double kWindowRun = 1.2 + 0.5 + 0.5;
    const std::vector<Notch> notches = gather_notches();
    std::vector<double> runs;
    for (std::size_t i = 0; i < rooms_.size(); ++i) {
      GenRoom& room = rooms_[i];
      if (room.disposable) continue;
      exterior_runs(room.rect, notches, runs);
      std::sort(runs.rbegin(), runs.rend());
      // The entrance room keeps its longest wall for the door (the engine puts no window beside
      // an entrance door).
      if (static_cast<int>(i) == entrance_ && !runs.empty()) runs.erase(runs.begin());
      int fit = 0;
      for (const double run : runs) fit += static_cast<int>(std::floor(run / kWindowRun));
      if (fit == 0) continue;
      room.windows = 1;
      const bool small = room.type == "bathroom" || room.type == "storage" ||
                         room.type == "corridor" || room.type == "hall" || room.type == "pantry";
      if (!small && fit >= 3 && rng_.unit() < 0.6) room.windows = 2;
    }
  }

  // A disposable part: its rectangle holds its void rooms' rectangles (they slice it), so a room
  // well apart from the part touches none of them.
  struct Notch {
    Rect part;
    std::vector<Rect> rooms;
  };

  std::vector<Notch> gather_notches() {
    std::vector<Cell*> leaves;
    collect_leaves(root_, leaves, false);
    std::vector<Notch> notches;
    for (const Cell* cell : leaves) {
      if (!cell->disposable) continue;
      Notch& notch = notches.emplace_back();
      notch.part = cell->rect;
      for (const int r : cell->rooms)
        notch.rooms.push_back(rooms_[static_cast<std::size_t>(r)].rect);
    }
    return notches;
  }

  // True when the rectangles are apart by more than `gap` along an axis.
  static bool apart(const Rect& a, const Rect& b, double gap) {
    return a.x1 < b.x0 - gap || b.x1 < a.x0 - gap || a.y1 < b.y0 - gap || b.y1 < a.y0 - gap;
  }

  // Straight exterior wall runs of a room, into `runs`: its sides on the outline, and the parts
  // of its sides along the disposable rooms of `notches` (exterior once the notch is removed,
  // §3.2). The order of the runs does not matter (add_windows sorts them).
  void exterior_runs(const Rect& r, const std::vector<Notch>& notches,
                     std::vector<double>& runs) const {
    runs.clear();
    const double sides[] = {side_run(r.x0, r.height(), outline_.x0, outline_.x1),
                            side_run(r.x1, r.height(), outline_.x0, outline_.x1),
                            side_run(r.y0, r.width(), outline_.y0, outline_.y1),
                            side_run(r.y1, r.width(), outline_.y0, outline_.y1)};
    for (const double side : sides) {
      if (side > 0) runs.push_back(side);
    }
    // shared_length's tolerance is 1e-6; twice that covers the void rooms' rounding inside
    // their part's rectangle.
    constexpr double kGap = 2e-6;
    for (const Notch& notch : notches) {
      if (apart(r, notch.part, kGap)) continue;
      for (const Rect& room : notch.rooms) {
        const double shared = shared_length(r, room);
        if (shared > 0) runs.push_back(shared);
      }
    }
  }

  // ---- the model ----
  Building emit() {
    name_rooms();
    Building building;
    building.symbol = "building";
    building.name = spec_.name;
    building.outline.outer = {{outline_.x0, outline_.y0},
                              {outline_.x1, outline_.y0},
                              {outline_.x1, outline_.y1},
                              {outline_.x0, outline_.y1}};
    // The transitions first: they copy the room symbols that the layout then takes over.
    emit_transitions(building);
    emit_cell(root_, true, building.layout);
    building.layout.symbol = building.symbol;
    choose_roofs(building.layout);
    return building;
  }

  void emit_transitions(Building& building) const {
    building.transitions.reserve(1 + doors_.size());
    Transition& entrance = building.transitions.emplace_back();
    entrance.symbol = "entrance0";
    entrance.kind = TransitionKind::kEntrance;
    entrance.from = rooms_[static_cast<std::size_t>(entrance_)].symbol;
    entrance.width = kEntranceWidth;
    for (std::size_t i = 0; i < doors_.size(); ++i) {
      Transition& door = building.transitions.emplace_back();
      door.symbol = "door";
      append_number(door.symbol, i);
      door.kind = TransitionKind::kDoor;
      door.from = rooms_[static_cast<std::size_t>(doors_[i].first)].symbol;
      door.to = rooms_[static_cast<std::size_t>(doors_[i].second)].symbol;
      door.width = kDoorWidth;
    }
  }

  // Symbols are the room type as an identifier and a per-identifier count ("bedroom3"). Few
  // distinct types per building: the identifiers are looked up in a short list, each type's
  // identifier made once.
  void name_rooms() {
    std::vector<std::pair<std::string, int>> counts;             // identifier, rooms so far
    std::vector<std::pair<std::string_view, std::size_t>> slot;  // type -> index in counts
    for (GenRoom& room : rooms_) {
      auto known = std::find_if(slot.begin(), slot.end(),
                                [&](const auto& entry) { return entry.first == room.type; });
      if (known == slot.end()) {
        std::string base = identifier(room.type);
        auto same = std::find_if(counts.begin(), counts.end(),
                                 [&](const auto& entry) { return entry.first == base; });
        if (same == counts.end()) same = counts.insert(same, {std::move(base), 0});
        known =
            slot.insert(slot.end(), {room.type, static_cast<std::size_t>(same - counts.begin())});
      }
      auto& [base, count] = counts[known->second];
      room.symbol = base;
      append_number(room.symbol, static_cast<std::size_t>(++count));
    }
  }

  // Fills `node` in place (a PartNode built and then moved into its parent costs a move of
  // every string and vector in it). Room symbols are moved out of rooms_: each room is emitted
  // once, after the transitions have copied them.
  void emit_cell(const Cell& cell, bool root, PartNode& node) {
    node.orientation = cell.orientation;
    if (!cell.leaf) {
      if (!root) {
        node.symbol = "parts";
        append_number(node.symbol, static_cast<std::size_t>(containers_++));
      }
      node.children.resize(cell.children.size());
      for (std::size_t i = 0; i < cell.children.size(); ++i) {
        emit_cell(cell.children[i], false, node.children[i]);
      }
      return;
    }
    const int index = parts_++;
    node.symbol = cell.disposable ? "notch" : "part";
    append_number(node.symbol, static_cast<std::size_t>(index));
    node.orientation = Orientation::kAlternate;
    BuildingPart& part = node.part.emplace();
    part.disposable = cell.disposable;
    Floor& floor = part.floors.emplace_back();
    floor.symbol = node.symbol;
    floor.symbol += "_ground";
    const DivNode& divisions = divisions_[cell.division];
    int counter = 0;  // numbers the part's division containers
    if (divisions.room >= 0) {
      floor.layout.orientation = along_longer(cell.rect);
      emit_division(divisions, node.symbol, counter, floor.layout.children.emplace_back());
    } else {
      floor.layout.orientation = divisions.orientation;
      floor.layout.children.resize(divisions.count);
      for (std::size_t i = 0; i < divisions.count; ++i) {
        emit_division(divisions_[divisions.first + i], node.symbol, counter,
                      floor.layout.children[i]);
      }
    }
    floor.layout.symbol = floor.symbol;
  }

  // Fills `out`; `counter` numbers the containers of `part`.
  void emit_division(const DivNode& div, const std::string& part, int& counter, Division& out) {
    if (div.room >= 0) {
      GenRoom& room = rooms_[static_cast<std::size_t>(div.room)];
      out.symbol = std::move(room.symbol);
      Room& r = out.room.emplace();
      r.type = room.type;
      r.size = room.disposable ? SizeLabel::kMedium : room.size;
      r.walls = room.disposable ? 0 : 4;
      r.windows = room.windows;
      return;
    }
    out.symbol = part;
    out.symbol += "_div";
    append_number(out.symbol, static_cast<std::size_t>(counter++));
    out.orientation = div.orientation;
    out.children.resize(div.count);
    for (std::size_t i = 0; i < div.count; ++i) {
      emit_division(divisions_[div.first + i], part, counter, out.children[i]);
    }
  }

  // Roofs (§4.1, §4.6): one kind and height for the whole building; L, U, T and H buildings, and
  // half of the multi-part convex ones, get HipGlued so the parts share one merged roof (Fig. 10).
  void choose_roofs(PartNode& layout) {
    const RoofKind kinds[] = {RoofKind::kHip, RoofKind::kGable, RoofKind::kFlat, RoofKind::kMansard,
                              RoofKind::kPyramid};
    RoofKind kind = kinds[rng_.integer(0, parts_ == 1 ? 4 : 3)];
    if (spec_.shape != RandomShape::kConvex || (parts_ > 1 && rng_.unit() < 0.5)) {
      kind = RoofKind::kHipGlued;
    }
    const double height = kind == RoofKind::kFlat ? 0.5 : round_to(rng_.uniform(2.0, 3.5), 10);
    set_roofs(layout, kind, height);
  }

  void set_roofs(PartNode& node, RoofKind kind, double height) {
    if (node.part) {
      node.part->roof = node.part->disposable ? RoofKind::kFlat : kind;
      node.part->height = node.part->disposable ? 0.0 : height;
    }
    for (PartNode& child : node.children) set_roofs(child, kind, height);
  }

  RandomSpec spec_;
  Rng rng_;
  std::uint64_t seed_salt_ = 0x5DEECE66DULL;
  Cell root_;
  bool wide_ = true;
  double aspect_ = 0;
  Rect outline_;
  std::vector<GenRoom> rooms_;
  std::vector<int> order_;
  std::vector<DivNode> divisions_;  // every part's division tree (Cell::division: its root)
  int entrance_ = 0;
  std::vector<std::pair<int, int>> doors_;
  std::vector<std::pair<int, double>> neighbors_;  // (room, shared wall), sliced per room
  std::vector<std::size_t> neighbor_start_;
  // A door candidate of grow_tree, ordered by (key, hash, u, v) as a tuple would be; the heap
  // is a min-heap, so its comparison is "comes after".
  struct Candidate {
    int key;
    std::uint64_t hash;
    int u, v;
  };
  struct CandidateAfter {  // a function object: inlined into the heap's loops
    bool operator()(const Candidate& a, const Candidate& b) const {
      if (a.key != b.key) return a.key > b.key;
      if (a.hash != b.hash) return a.hash > b.hash;
      if (a.u != b.u) return a.u > b.u;
      return a.v > b.v;
    }
  };
  std::vector<Candidate> frontier_;
  int parts_ = 0;
  int containers_ = 0;
};

}  // namespace

bool parse_random_shape(const std::string& text, RandomShape& shape) {
  std::string key;
  for (const char c : text) key += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (key == "convex") {
    shape = RandomShape::kConvex;
  } else if (key == "l") {
    shape = RandomShape::kL;
  } else if (key == "u") {
    shape = RandomShape::kU;
  } else if (key == "t") {
    shape = RandomShape::kT;
  } else if (key == "h") {
    shape = RandomShape::kH;
  } else {
    return false;
  }
  return true;
}

const char* random_shape_name(RandomShape shape) {
  switch (shape) {
    case RandomShape::kConvex:
      return "convex";
    case RandomShape::kL:
      return "L";
    case RandomShape::kU:
      return "U";
    case RandomShape::kT:
      return "T";
    case RandomShape::kH:
      return "H";
  }
  return "convex";
}

Building random_building(const RandomSpec& spec, std::uint64_t seed) {
  return Generator(spec, seed).run();
}

std::uint64_t batch_seed(std::uint64_t seed, std::uint64_t index) {
  return shape::mix64(seed ^ shape::mix64(index + 0x9E3779B97F4A7C15ULL));
}

}  // namespace insula::lang::bldg
