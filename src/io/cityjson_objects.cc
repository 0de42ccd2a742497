#include "io/cityjson_objects.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "io/decimal_text.h"
#include "io/triangulated.h"
#include "kernel/semantic.h"
#include "shape/part_mesh.h"

namespace insula::io::cityjson {
namespace {

constexpr double kPerMeter = 1000.0;  // 1 / kScale

// CityObjects::pool_index_'s values for a mesh vertex not pooled yet, and for one that cannot be
// written (not finite, or too far to quantise).
constexpr std::uint32_t kUnset = UINT32_MAX;
constexpr std::uint32_t kUnwritable = UINT32_MAX - 1;

// An empty slot of the solid test's edge table (a key is a pair of different numbers).
constexpr std::uint64_t kNoEdge = UINT64_MAX;

bool finite(kernel::Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Quantised offsets must stay exact integers in a double and in JSON readers (|q| < 2^53).
bool quantisable(kernel::Vec3 offset) {
  constexpr double kLimit = 9.0e15 / kPerMeter;
  return std::abs(offset.x) < kLimit && std::abs(offset.y) < kLimit && std::abs(offset.z) < kLimit;
}

// a == b, inline (std::array's == calls memcmp).
bool same(const Quantised& a, const Quantised& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

const shape::AttributeMap* attributes_of(const shape::AttributeMap& attributes) {
  return attributes.empty() ? nullptr : &attributes;
}

// Starts loading every cache line of `bytes` from `data` on, up to 1 kB (a larger part's rings
// have time to come in while its first are written). The lines are counted from the one `data` is
// in: counted from `data`, the last line of an array that does not start a line was left out.
void prefetch_lines(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kLine = 64;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t end = begin + std::min<std::size_t>(bytes, 1024);
  for (std::uintptr_t line = begin & ~(kLine - 1); line < end; line += kLine) {
    __builtin_prefetch(reinterpret_cast<const void*>(line));
  }
}

// An object's place in id order: the first 8 bytes of its id (see CityObjects::write_objects()).
struct IdKey {
  std::uint64_t prefix;
  std::uint32_t object;
};

// Sorts `keys` by prefix, least significant byte first (a radix sort: a comparison sort of a city's
// ids cost as much as all the rest of ordering them); a byte the same in every key is skipped.
void sort_by_prefix(std::vector<IdKey>& keys) {
  constexpr std::size_t kBytes = 8;
  std::array<std::array<std::uint32_t, 256>, kBytes> counts{};
  for (const IdKey& key : keys) {
    for (std::size_t b = 0; b < kBytes; ++b) ++counts[b][(key.prefix >> (8 * b)) & 0xFFU];
  }
  std::vector<IdKey> sorted(keys.size());
  for (std::size_t b = 0; b < kBytes; ++b) {
    if (keys.empty() || counts[b][(keys[0].prefix >> (8 * b)) & 0xFFU] == keys.size()) continue;
    std::uint32_t offset = 0;
    for (std::uint32_t& count : counts[b]) offset += std::exchange(count, offset);
    for (const IdKey& key : keys) sorted[counts[b][(key.prefix >> (8 * b)) & 0xFFU]++] = key;
    keys.swap(sorted);
  }
}

// The part's mesh; for a shared-mesh instance its placed copy, made in `placed`.
const kernel::Mesh& part_mesh(const shape::Part& part, std::optional<kernel::Mesh>& placed) {
  if (!part.instance_of) return part.mesh;
  placed = shape::part_world_mesh(part);
  return *placed;
}

std::string_view object_type(shape::PartKind kind) {
  switch (kind) {
    case shape::PartKind::kStorey:
      return "BuildingStorey";
    case shape::PartKind::kRoom:
      return "BuildingRoom";
    case shape::PartKind::kInstallation:
      return "BuildingInstallation";
    case shape::PartKind::kFurniture:
      return "BuildingFurniture";
    case shape::PartKind::kBuildingPart:
    case shape::PartKind::kOther:
      break;
  }
  return "BuildingPart";
}

}  // namespace

std::size_t QuantisedHash::operator()(const Quantised& q) const {
  std::uint64_t h = 0;
  for (std::int64_t c : q) {
    h = (h ^ static_cast<std::uint64_t>(c)) * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 29U;
  }
  return static_cast<std::size_t>(h);
}

void VertexPool::begin_part(std::size_t vertices) {
  std::size_t slots = 16;
  while (slots < 2 * vertices) slots *= 2;
  part_slots_.assign(slots, kFreeNumber);
}

// The part's points lie at the end of the list, in cache: a slot holds just a number, and probing
// compares the points.
std::uint32_t VertexPool::add(const Quantised& q, std::uint64_t hash) {
  const std::size_t mask = part_slots_.size() - 1;
  for (std::size_t slot = hash & mask;; slot = (slot + 1) & mask) {
    std::uint32_t& entry = part_slots_[slot];
    if (entry == kFreeNumber) {
      entry = static_cast<std::uint32_t>(vertices_.size());
      vertices_.push_back(q);
      return entry;
    }
    if (same(vertices_[entry], q)) return entry;
  }
}

// Linear probing: a slot freed in the reverse order the points were added leaves the table as it
// was before they came (no later point probed past them).
void VertexPool::truncate(std::size_t size) {
  const std::size_t mask = part_slots_.size() - 1;
  while (vertices_.size() > size) {
    const auto last = static_cast<std::uint32_t>(vertices_.size() - 1);
    std::size_t slot = QuantisedHash{}(vertices_.back()) & mask;
    while (part_slots_[slot] != last) slot = (slot + 1) & mask;
    part_slots_[slot] = kFreeNumber;
    vertices_.pop_back();
  }
}

// The number of `q` in merge()'s table, or `next` when it is not there (then it is added with it).
// A slot holds the high half of the point's hash too: probing reads a point (far back in the list,
// a cache miss) only when they match.
inline std::uint32_t VertexPool::number(const Quantised& q, std::uint64_t hash,
                                        std::uint32_t next) {
  const std::uint64_t tag = hash & ~std::uint64_t{UINT32_MAX};
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = hash & mask;; slot = (slot + 1) & mask) {
    const std::uint64_t entry = slots_[slot];
    if (entry == kFree) {
      slots_[slot] = tag | next;
      return next;
    }
    const auto index = static_cast<std::uint32_t>(entry);
    if ((entry & ~std::uint64_t{UINT32_MAX}) == tag && same(vertices_[index], q)) return index;
  }
}

// Points are numbered again in list order, each found in the table (kAhead points ahead its slot
// is prefetched, 2 kAhead ahead the point itself); a point seen before takes its first number, a
// new one the next, and moves down to it. Every number stays the same as long as no point comes
// twice.
const std::vector<std::uint32_t>& VertexPool::merge() {
  constexpr std::size_t kAhead = 16;
  const std::size_t n = vertices_.size();
  std::size_t slots = 16;
  while (3 * slots < 4 * n) slots *= 2;
  slots_.assign(slots, kFree);
  const std::size_t mask = slots - 1;
  renumber_.clear();
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i + kAhead < n) __builtin_prefetch(&slots_[QuantisedHash{}(vertices_[i + kAhead]) & mask]);
    if (i + 2 * kAhead < n) __builtin_prefetch(&vertices_[i + 2 * kAhead]);
    const Quantised q = vertices_[i];
    const std::uint32_t number = this->number(q, QuantisedHash{}(q), next);
    if (number == next) {
      vertices_[next++] = q;
      for (std::size_t k = 0; k < 3; ++k) {
        low_[k] = std::min(low_[k], q[k]);
        high_[k] = std::max(high_[k], q[k]);
      }
    }
    if (number != i && renumber_.empty()) {  // the first point seen before: numbers change
      renumber_.reserve(n);
      for (std::uint32_t j = 0; j < i; ++j) renumber_.push_back(j);
    }
    if (!renumber_.empty()) renumber_.push_back(number);
  }
  vertices_.resize(next);
  return renumber_;
}

const std::string* IdSet::insert(std::string_view id) {
  if (2 * (ids_.size() + 1) > slots_.size()) reserve(2 * ids_.size() + 1);
  const std::uint64_t hash = std::hash<std::string_view>{}(id);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = hash & mask; slots_[slot] != kFree; slot = (slot + 1) & mask) {
    const std::uint64_t entry = slots_[slot];
    if ((entry >> 32U) == (hash >> 32U) && ids_[static_cast<std::uint32_t>(entry)] == id) {
      return nullptr;
    }
  }
  ids_.emplace_back(id);
  place(hash, static_cast<std::uint32_t>(ids_.size() - 1));
  return &ids_.back();
}

void IdSet::prefetch(std::string_view id) const {
  if (!slots_.empty()) {
    __builtin_prefetch(&slots_[std::hash<std::string_view>{}(id) & (slots_.size() - 1)]);
  }
}

void IdSet::reserve(std::size_t n) {
  std::size_t slots = 16;
  while (slots < 2 * (n + 1)) slots *= 2;
  if (slots <= slots_.size()) return;
  slots_.assign(slots, kFree);
  for (std::uint32_t index = 0; index < ids_.size(); ++index) {
    place(std::hash<std::string_view>{}(ids_[index]), index);
  }
}

void IdSet::place(std::uint64_t hash, std::uint32_t index) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t slot = hash & mask;
  while (slots_[slot] != kFree) slot = (slot + 1) & mask;
  slots_[slot] = (hash & ~std::uint64_t{UINT32_MAX}) | index;
}

void VertexPool::reserve(std::size_t n) {
  vertices_.reserve(n);
}

void VertexPool::clear() {
  vertices_.clear();
  low_ = kNoLow;
  high_ = kNoHigh;
}

void CityObjects::reserve_rings(std::size_t rings, std::size_t indices) {
  rings_.indices.reserve(indices);
  rings_.ends.reserve(rings);
  rings_.classes.reserve(rings);
}

// Inline: a call, its point passed and returned through memory, cost as much as the rounding.
inline Quantised CityObjects::quantise(kernel::Vec3 local) const {
  const kernel::Vec3 d = (local - base_) * kPerMeter;
  return {round_half_away(d.x), round_half_away(d.y), round_half_away(d.z)};
}

// Quantises every vertex of the mesh and hashes it; pool_index_ marks the vertices that cannot be
// written. The pool numbers the points later, in the order the faces use them.
void CityObjects::pool_vertices(const kernel::Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  pool_.begin_part(n);
  pool_index_.assign(n, kUnset);
  points_.resize(n);
  hashes_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    const kernel::Vec3 p = mesh.position(v);
    if (!finite(p) || !quantisable(p - base_)) {
      pool_index_[v] = kUnwritable;
      continue;
    }
    points_[v] = quantise(p);
    hashes_[v] = QuantisedHash{}(points_[v]);
  }
}

// After pool_vertices(mesh): appends the mesh's faces to rings_, each mesh vertex pooled once (at
// its first use), however many faces use it. A face that collapses on the grid (fewer than three
// distinct points) is dropped with the points it alone brought, so every point listed is used.
void CityObjects::collect_surfaces(const kernel::Mesh& mesh) {
  std::vector<std::uint32_t>& indices = rings_.indices;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t begin = indices.size();
    const std::size_t pooled = pool_.vertices().size();
    bool ok = true;
    for (std::uint32_t vertex : mesh.face(f)) {
      std::uint32_t& index = pool_index_[vertex];
      if (index == kUnset) index = pool_.add(points_[vertex], hashes_[vertex]);
      if (index == kUnwritable) {
        ok = false;
        break;
      }
      if (indices.size() == begin || indices.back() != index) indices.push_back(index);
    }
    while (indices.size() > begin + 1 && indices.back() == indices[begin]) indices.pop_back();
    if (!ok || indices.size() < begin + 3) {
      indices.resize(begin);
      unpool_since(mesh.face(f), pooled);
      continue;
    }
    rings_.ends.push_back(indices.size());
    rings_.classes.push_back(mesh.tag(f).semantic);
  }
}

// Takes back from the pool the points numbered `pooled` and later, which the face `loop` brought:
// its vertices go back to unpooled (a later face may bring them again).
void CityObjects::unpool_since(std::span<const std::uint32_t> loop, std::size_t pooled) {
  if (pool_.vertices().size() == pooled) return;
  for (std::uint32_t vertex : loop) {
    std::uint32_t& index = pool_index_[vertex];
    if (index != kUnwritable && index != kUnset && index >= pooled) index = kUnset;
  }
  pool_.truncate(pooled);
}

// Numbers the distinct vertices of `corners` 0, 1, ... in first-use order into local_ (one
// number a corner), their pool vertices into local_vertex_; returns how many there are. A stamp per
// pool vertex, in the same word as its number, tells this call's numbers from older ones without
// clearing anything.
std::uint32_t CityObjects::number_locally(std::span<const std::uint32_t> corners) const {
  ++stamp_;
  if (local_number_.size() < pool_.vertices().size()) {
    local_number_.resize(pool_.vertices().size(), 0);
  }
  const std::uint64_t stamp = std::uint64_t{stamp_} << 32U;
  std::uint32_t locals = 0;
  local_.resize(corners.size());
  local_vertex_.clear();
  for (std::size_t c = 0; c < corners.size(); ++c) {
    std::uint64_t& number = local_number_[corners[c]];
    if ((number & ~std::uint64_t{UINT32_MAX}) != stamp) {
      number = stamp | locals++;
      local_vertex_.push_back(corners[c]);
    }
    local_[c] = static_cast<std::uint32_t>(number);
  }
  return locals;
}

// A Solid needs one closed, consistently outward-oriented 2-manifold shell: checked on the
// quantised rings [first, end), so the test sees exactly what a validator such as val3dity will
// see. What kernel::check calls closed, oriented and manifold with one component comes to: every
// edge {a, b} is used exactly once a -> b and once b -> a, and the edges join all the vertices;
// the volume is kernel::volume's, on the quantised points. The edges are counted in a small hash
// table of vertex pairs, the joins in a union-find over the part's own vertex numbers.
bool CityObjects::is_solid(std::size_t first, std::size_t end) const {
  if (end - first < 4) return false;
  const std::size_t corners_begin = first == 0 ? 0 : rings_.ends[first - 1];
  const std::uint32_t locals =
      number_locally(std::span<const std::uint32_t>(rings_.indices)
                         .subspan(corners_begin, rings_.ends[end - 1] - corners_begin));
  // The edge test reads nothing but the rings' local numbering: a part numbered as the last one
  // tested (the same mesh again, as a city's repeated houses and instances are) has its verdict.
  if (!numbered_as_last(first, end, corners_begin)) {
    last_closed_ = closed_shell(first, end, corners_begin, locals);
  }
  return last_closed_ && volume(first, end, locals) > 0;
}

// Whether local_ and the sizes of rings [first, end) are those of the last part tested; if not,
// they become the ones kept.
bool CityObjects::numbered_as_last(std::size_t first, std::size_t end,
                                   std::size_t corners_begin) const {
  bool same = end - first == last_ends_.size() && local_ == last_local_;
  for (std::size_t r = first; same && r < end; ++r) {
    same = rings_.ends[r] - corners_begin == last_ends_[r - first];
  }
  if (same) return true;
  last_local_ = local_;
  last_ends_.resize(end - first);
  for (std::size_t r = first; r < end; ++r) last_ends_[r - first] = rings_.ends[r] - corners_begin;
  return false;
}

// The edge test of is_solid(), on local_ (`locals` numbers) and the sizes of rings [first, end).
bool CityObjects::closed_shell(std::size_t first, std::size_t end, std::size_t corners_begin,
                               std::uint32_t locals) const {
  std::size_t slots = 16;
  while (slots < 2 * local_.size()) slots *= 2;
  edges_.assign(slots, kNoEdge);
  sides_.assign(slots, 0);
  parent_.resize(locals);
  for (std::uint32_t v = 0; v < locals; ++v) parent_[v] = v;
  const auto root = [this](std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  };
  std::size_t pairs = 0;  // distinct {a, b}
  std::uint32_t joins = 0;
  for (std::size_t r = first, begin = 0; r < end; ++r) {
    const std::size_t size = rings_.ends[r] - corners_begin - begin;
    for (std::size_t i = 0; i < size; ++i) {
      const std::uint32_t a = local_[begin + i];
      const std::uint32_t b = local_[begin + (i + 1 < size ? i + 1 : 0)];
      // Rings repeat no vertex consecutively (collect_surfaces), so a != b.
      const std::uint8_t side = a < b ? 1 : 2;
      const std::uint64_t key = std::uint64_t{std::min(a, b)} << 32U | std::max(a, b);
      std::size_t slot = (key * 0x9E3779B97F4A7C15ULL >> 32U) & (slots - 1);
      while (edges_[slot] != kNoEdge && edges_[slot] != key) slot = (slot + 1) & (slots - 1);
      if (edges_[slot] == kNoEdge) {
        edges_[slot] = key;
        ++pairs;
        const std::uint32_t ra = root(a);
        const std::uint32_t rb = root(b);
        if (ra != rb) {
          parent_[ra] = rb;
          ++joins;
        }
      } else if ((sides_[slot] & side) != 0) {
        return false;  // used twice the same way
      }
      sides_[slot] |= side;
    }
    begin += size;
  }
  // Every pair used both ways (each twice) and one component.
  return 2 * pairs == local_.size() && joins + 1 == locals;
}

// kernel::volume of the quantised rings [first, end) (the same sums in the same order), after
// number_locally() on their corners: each point is converted to doubles once, not per corner.
double CityObjects::volume(std::size_t first, std::size_t end, std::uint32_t locals) const {
  const std::size_t corners_begin = first == 0 ? 0 : rings_.ends[first - 1];
  volume_points_.resize(locals);
  for (std::uint32_t v = 0; v < locals; ++v) {
    const Quantised& q = pool_.vertices()[local_vertex_[v]];
    volume_points_[v] = {static_cast<double>(q[0]), static_cast<double>(q[1]),
                         static_cast<double>(q[2])};
  }
  double total = 0;
  for (std::size_t r = first, begin = 0; r < end; ++r) {
    const std::size_t size = rings_.ends[r] - corners_begin - begin;
    kernel::Vec3 newell;
    for (std::size_t i = 0; i < size; ++i) {
      const kernel::Vec3 a = volume_points_[local_[begin + i]];
      const kernel::Vec3 b = volume_points_[local_[begin + (i + 1 < size ? i + 1 : 0)]];
      newell += kernel::Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                             (a.x - b.x) * (a.y + b.y)};
    }
    total += kernel::dot(volume_points_[local_[begin]], newell / 2);
    begin += size;
  }
  return total / 3;
}

// Not initialised: zero-filling room for a city's vertex list cost as much as writing it.
char* CityObjects::scratch(std::size_t size) {
  if (size > scratch_size_) {
    scratch_ = std::make_unique_for_overwrite<char[]>(size);
    scratch_size_ = size;
  }
  return scratch_.get();
}

// Rings [first, end) as surfaces of one ring each ("[[i,j,k]]"), in an array; in a Solid's, one
// array more (its single outer shell). Formatted here in one buffer rather than number by number
// through the stream: the corners are most of a city's text.
std::string_view CityObjects::boundaries_text(std::size_t first, std::size_t end, bool solid) {
  const std::size_t corners = rings_.ends[end - 1] - (first == 0 ? 0 : rings_.ends[first - 1]);
  // At most 10 digits and a comma a corner, 5 brackets and a comma a ring, 4 outer brackets.
  char* const text = scratch(11 * corners + 6 * (end - first) + 4);
  char* at = text;
  *at++ = '[';
  if (solid) *at++ = '[';
  for (std::size_t r = first; r < end; ++r) {
    if (r > first) *at++ = ',';
    *at++ = '[';
    *at++ = '[';
    const std::span<const std::uint32_t> ring = rings_.ring(r);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (i > 0) *at++ = ',';
      at = decimal::write(at, ring[i]);
    }
    *at++ = ']';
    *at++ = ']';
  }
  if (solid) *at++ = ']';
  *at++ = ']';
  return {text, static_cast<std::size_t>(at - text)};
}

// The distinct surface types of rings [first, end) into types_, in first-use order, and each
// ring's position among them (-1: none) into values_. A type is looked up once a semantic class,
// its value then read from a table by class (a search of the classes met cost a mispredicted
// branch or two a ring).
void CityObjects::collect_types(std::size_t first, std::size_t end) {
  constexpr int kUnseen = -2;
  std::array<int, kernel::kSemanticClassCount> value_of{};
  value_of.fill(kUnseen);
  types_.clear();
  values_.clear();
  for (std::size_t r = first; r < end; ++r) {
    const kernel::SemanticClass semantic = rings_.classes[r];
    const auto c = static_cast<std::size_t>(semantic);
    int value = c < value_of.size() ? value_of[c] : kUnseen;
    if (value == kUnseen) {
      value = -1;
      const std::string_view type = kernel::citygml_surface(semantic);
      if (!type.empty()) {
        value = static_cast<int>(std::find(types_.begin(), types_.end(), type) - types_.begin());
        if (value == static_cast<int>(types_.size())) types_.push_back(type);
      }
      if (c < value_of.size()) value_of[c] = value;
    }
    values_.push_back(value);
  }
}

// The "values" of collect_types(): an array of values_ (null for -1), in a Solid in one array more.
std::string_view CityObjects::values_text(bool solid) {
  char* const text = scratch(5 * values_.size() + 4);  // "null," at most a value
  char* at = text;
  *at++ = '[';
  if (solid) *at++ = '[';
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (i > 0) *at++ = ',';
    at = values_[i] < 0 ? std::copy_n("null", 4, at) : std::to_chars(at, at + 4, values_[i]).ptr;
  }
  if (solid) *at++ = ']';
  *at++ = ']';
  return {text, static_cast<std::size_t>(at - text)};
}

// The "surfaces" of collect_types(): [{"type": ...}, ...]. Kept from part to part, as most parts
// of a city have the same few types in the same order.
std::string_view CityObjects::surfaces_text() {
  if (types_ != surfaces_types_) {
    surfaces_types_ = types_;
    surfaces_text_.clear();
    JsonStream json(surfaces_text_);
    json.begin_array();
    for (std::string_view type : types_) json.begin_object().key("type").string(type).end_object();
    json.end_array();
  }
  return surfaces_text_;
}

// {"boundaries", "lod", "semantics" (when some face has a type), "type"}.
void CityObjects::write_geometry(JsonStream& json, const Object& part) {
  const std::size_t end = part.first + part.count;
  json.begin_object().key("boundaries").raw(boundaries_text(part.first, end, part.solid));
  json.key("lod").string("2");
  collect_types(part.first, end);
  if (!types_.empty()) {
    json.key("semantics").begin_object().key("surfaces").raw(surfaces_text());
    json.key("values").raw(values_text(part.solid)).end_object();
  }
  json.key("type").string(part.solid ? "Solid" : "MultiSurface").end_object();
}

// `base`, or `base-2`, `base-3`, ... when taken; records the result.
std::string_view CityObjects::unique_id(const std::string& base) {
  const std::string* id = nullptr;
  building_names_.next(base, [&](const std::string& name) {
    id = ids_.insert(name);
    return id != nullptr;
  });
  return *id;
}

// A part's id: unique among the ids given and none of the avoided buildings' ids.
std::string_view CityObjects::unique_part_id(const std::string& base) {
  const std::string* id = nullptr;
  part_names_.next(base, [&](const std::string& name) {
    if (avoided_ && avoided_->contains(name)) return false;
    id = ids_.insert(name);
    return id != nullptr;
  });
  return *id;
}

void CityObjects::prefetch_ahead(const std::vector<shape::Building>& buildings, std::size_t b,
                                 bool positions_only) {
  if (b + kPartsAhead < buildings.size()) prefetch_parts(buildings[b + kPartsAhead]);
  if (b + kMeshesAhead < buildings.size()) {
    prefetch_meshes(buildings[b + kMeshesAhead], positions_only);
  }
}

void CityObjects::prefetch_parts(const shape::Building& building) {
  for (const shape::Part& part : building.parts) {
    // From the name (read for the part's id) to the end of the mesh's array pointers.
    const auto* begin = reinterpret_cast<const char*>(&part);
    const auto* end = reinterpret_cast<const char*>(&part.mesh) + sizeof(kernel::Mesh);
    prefetch_lines(begin, static_cast<std::size_t>(end - begin));
  }
}

void CityObjects::prefetch_meshes(const shape::Building& building, bool positions_only) {
  for (const shape::Part& part : building.parts) {
    const kernel::Mesh& mesh = part.mesh;
    if (mesh.empty()) continue;
    // Whole arrays (up to prefetch_lines()'s limit): their first lines alone left the rest of a
    // small building's corners and tags to miss when its surfaces were collected.
    prefetch_lines(mesh.positions().data(), mesh.vertex_count() * sizeof(kernel::Vec3));
    if (positions_only) continue;
    constexpr std::size_t kCornersPerFace = 4;  // about: quads, triangles and a few larger faces
    prefetch_lines(mesh.face(0).data(),
                   kCornersPerFace * mesh.face_count() * sizeof(std::uint32_t));
    prefetch_lines(&mesh.tag(0), mesh.face_count() * sizeof(kernel::FaceTag));
  }
}

// About 8 bytes a corner ("123456," and a ring's brackets), 4 a face's semantic value, 200 an
// object and 32 an attribute: an estimate to reserve room with, as more than is used costs nothing
// (the pages are never touched).
void CityObjects::estimate_text(const Object& object) {
  text_size_ += 200 + 2 * object.id.size() + object.parent.size();
  if (object.attributes != nullptr) text_size_ += 32 * object.attributes->size();
  if (!object.parent.empty() && object.count > 0) {
    const std::size_t first = object.first == 0 ? 0 : rings_.ends[object.first - 1];
    text_size_ += 8 * (rings_.ends[object.first + object.count - 1] - first) + 4 * object.count;
  }
}

// The id of part `p` of a building whose id is `id` (before it is made unique), into `base`: in
// place, as copies of short strings (each a library call) were a good part of adding a part.
void CityObjects::part_id_base(std::string& base, std::string_view id, const shape::Part& part,
                               std::size_t p) {
  base.assign(id).push_back('-');
  if (part.name.empty()) {
    base.append("part").append(std::to_string(p));
  } else {
    base.append(part.name);
  }
}

// Pools the parts' vertices and keeps their rings now, in the buildings' order (which numbers the
// vertices); the text comes in write_objects(). The ids are given after the geometry, in the same
// order as ever (the building's, then its parts'), so that their table slots, prefetched before it,
// are in cache by then (a city's ids do not stay there).
std::string CityObjects::add_building(const shape::Building& building, std::size_t index) {
  const std::string id_base =
      building.id.empty() ? "building" + std::to_string(index) : building.id;
  ids_.prefetch(id_base);
  part_ids_.resize(building.parts.size());
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    part_id_base(part_ids_[p], id_base, building.parts[p], p);
    ids_.prefetch(part_ids_[p]);
  }
  const std::size_t first_child = objects_.size();
  written_parts_.clear();
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    Object object{{}, {}, object_type(part.kind), attributes_of(part.attributes), rings_.size()};
    std::optional<kernel::Mesh> placed;  // (an empty Mesh would allocate)
    const kernel::Mesh& mesh = part_mesh(part, placed);
    pool_vertices(mesh);
    collect_surfaces(mesh);
    object.count = rings_.size() - object.first;
    if (object.count == 0) continue;
    object.solid = is_solid(object.first, rings_.size());
    objects_.push_back(object);
    written_parts_.push_back(p);
  }
  const std::string_view id = unique_id(id_base);
  const bool renamed = id.size() != id_base.size();  // "-2" or a later suffix added
  for (std::size_t c = 0; c < written_parts_.size(); ++c) {
    const std::size_t p = written_parts_[c];
    Object& object = objects_[first_child + c];
    if (renamed) part_id_base(part_ids_[p], id, building.parts[p], p);
    object.id = unique_part_id(part_ids_[p]);
    object.parent = id;
    estimate_text(object);
  }
  objects_.push_back({id,
                      {},
                      "Building",
                      attributes_of(building.attributes),
                      first_child,
                      objects_.size() - first_child});
  estimate_text(objects_.back());
  return std::string(id);
}

// A part: {"attributes", "geometry" (when it has faces), "parents", "type"}; a building:
// {"attributes", "children", "type"} (members in nlohmann's sorted order, empty ones left out).
void CityObjects::write_object(JsonStream& json, const Object& object) {
  json.begin_object();
  if (object.attributes != nullptr) json.key("attributes").attributes(*object.attributes);
  if (object.parent.empty()) {
    if (object.count > 0) {
      json.key("children").begin_array();
      for (std::size_t c = 0; c < object.count; ++c) json.string(objects_[object.first + c].id);
      json.end_array();
    }
  } else {
    if (object.count > 0) {
      json.key("geometry").begin_array();
      write_geometry(json, object);
      json.end_array();
    }
    json.key("parents").begin_array().string(object.parent).end_array();
  }
  json.key("type").string(object.type).end_object();
}

// The pool's numbers of points that several parts use merged, in the rings too (the solid tests,
// which need no more than a part's own numbers, are done).
void CityObjects::number_vertices() {
  const std::vector<std::uint32_t>& renumber = pool_.merge();
  if (renumber.empty()) return;
  for (std::uint32_t& index : rings_.indices) index = renumber[index];
}

// Starts loading what write_object() reads (in id order, objects far apart in memory).
void CityObjects::prefetch_object(const Object& object) const {
  __builtin_prefetch(object.id.data());
  if (object.parent.empty() || object.count == 0) return;
  const std::size_t corners_begin = object.first == 0 ? 0 : rings_.ends[object.first - 1];
  const std::size_t corners_end = rings_.ends[object.first + object.count - 1];
  prefetch_lines(&rings_.ends[object.first], object.count * sizeof(std::size_t));
  prefetch_lines(&rings_.classes[object.first], object.count);
  prefetch_lines(&rings_.indices[corners_begin],
                 (corners_end - corners_begin) * sizeof(std::uint32_t));
}

// Sorted by id through a list of (first 8 bytes, position): most ids differ in the prefix, read
// as a big-endian number (a shorter id's missing bytes as 0, which orders it first as the full
// comparison would) and radix-sorted; ids of equal prefixes are then sorted by the full comparison.
void CityObjects::write_objects(JsonStream& json) {
  number_vertices();
  std::vector<IdKey> order;
  order.reserve(objects_.size());
  for (std::uint32_t o = 0; o < objects_.size(); ++o) {
    std::uint64_t prefix = 0;
    const std::string_view id = objects_[o].id;
    for (std::size_t i = 0; i < 8; ++i) {
      prefix = (prefix << 8U) | (i < id.size() ? static_cast<unsigned char>(id[i]) : 0U);
    }
    order.push_back({prefix, o});
  }
  sort_by_prefix(order);
  for (auto run = order.begin(); run != order.end();) {
    const auto run_end = std::find_if(run + 1, order.end(),
                                      [&](const IdKey& key) { return key.prefix != run->prefix; });
    if (run_end - run > 1) {
      std::sort(run, run_end, [this](const IdKey& a, const IdKey& b) {
        return objects_[a.object].id < objects_[b.object].id;
      });
    }
    run = run_end;
  }
  // Objects are prefetched kAhead ahead, their rings and ids half that (once the object is in).
  constexpr std::size_t kAhead = 8;
  json.begin_object();
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i + kAhead < order.size()) __builtin_prefetch(&objects_[order[i + kAhead].object]);
    if (i + kAhead / 2 < order.size()) prefetch_object(objects_[order[i + kAhead / 2].object]);
    const Object& object = objects_[order[i].object];
    json.key(object.id);
    write_object(json, object);
  }
  json.end_object();
}

// Formatted here a chunk of points at a time, as the boundaries are (a city has hundreds of
// thousands of points). The points are prefetched kAhead ahead: though read in order, they were
// waited for (the hardware's prefetching did not keep up on the 2-core test machine).
void CityObjects::write_vertices(JsonStream& json) {
  constexpr std::size_t kChunk = 256;
  constexpr std::size_t kAhead = 32;
  // At most 20 characters a coordinate, 4 brackets and commas a point.
  char* const text = scratch(64 * kChunk);
  const std::vector<Quantised>& vertices = pool_.vertices();
  json.begin_array();
  for (std::size_t chunk = 0; chunk < vertices.size(); chunk += kChunk) {
    char* at = text;
    const std::size_t chunk_end = std::min(chunk + kChunk, vertices.size());
    for (std::size_t v = chunk; v < chunk_end; ++v) {
      if (v + kAhead < vertices.size()) __builtin_prefetch(&vertices[v + kAhead]);
      if (v > chunk) *at++ = ',';
      *at++ = '[';
      for (std::size_t k = 0; k < 3; ++k) {
        if (k > 0) *at++ = ',';
        at = decimal::write(at, vertices[v][k]);
      }
      *at++ = ']';
    }
    json.elements({text, static_cast<std::size_t>(at - text)});
  }
  json.end_array();
}

void CityObjects::clear() {
  pool_.clear();
  rings_.clear();
  objects_.clear();
  text_size_ = 2;
}
// One pass over the meshes' positions, prefetched (see CityObjects::prefetch_ahead()).
SceneSize measure(const shape::Scene& scene) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  kernel::Vec3 low{kNone, kNone, kNone};
  SceneSize size;
  const std::vector<shape::Building>& buildings = scene.buildings;
  for (std::size_t b = 0; b < buildings.size(); ++b) {
    CityObjects::prefetch_ahead(buildings, b, true);
    size.objects += buildings[b].parts.size() + 1;
    for (const shape::Part& part : buildings[b].parts) {
      std::optional<kernel::Mesh> placed;
      const kernel::Mesh& mesh = part_mesh(part, placed);
      for (const kernel::Vec3& p : mesh.positions()) {
        if (finite(p)) low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      }
      size.vertices += mesh.vertex_count();
      size.faces += mesh.face_count();
    }
  }
  size.minimum = low.x == kNone ? kernel::Vec3{} : low;
  return size;
}

kernel::Vec3 local_minimum(const shape::Scene& scene) {
  return measure(scene).minimum;
}

void write_transform(JsonStream& json, kernel::Vec3 translate) {
  json.begin_object().key("scale").begin_array();
  json.number(kScale).number(kScale).number(kScale).end_array();
  json.key("translate").begin_array();
  json.number(translate.x).number(translate.y).number(translate.z).end_array().end_object();
}

}  // namespace insula::io::cityjson
