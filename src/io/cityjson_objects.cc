#include "io/cityjson_objects.h"

#include <algorithm>
#include <cmath>

#include "io/triangulated.h"
#include "shape/part_mesh.h"

namespace insula::io::cityjson {
namespace {

constexpr double kPerMeter = 1000.0;  // 1 / kScale

bool finite(kernel::Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Quantised offsets must stay exact integers in a double and in JSON readers (|q| < 2^53).
bool quantisable(kernel::Vec3 offset) {
  constexpr double kLimit = 9.0e15 / kPerMeter;
  return std::abs(offset.x) < kLimit && std::abs(offset.y) < kLimit && std::abs(offset.z) < kLimit;
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

// `base`, or `base-2`, `base-3`, ... when taken; records the result.
std::string unique_id(const std::string& base, IdSet& taken) {
  std::string id = base;
  for (int suffix = 2; !taken.insert(id); ++suffix) id = base + "-" + std::to_string(suffix);
  return id;
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

// A slot holds a point's number and the high half of its hash: probing compares those, and reads
// a point (a cache miss, as the points lie in first-use order) only when they match.
std::uint32_t VertexPool::add(const Quantised& q) {
  if (4 * (vertices_.size() + 1) > 3 * slots_.size()) {
    rehash(std::max<std::size_t>(16, 2 * slots_.size()));
  }
  const std::uint64_t hash = QuantisedHash{}(q);
  const std::uint64_t tag = hash & ~std::uint64_t{UINT32_MAX};
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = hash & mask;; slot = (slot + 1) & mask) {
    const std::uint64_t entry = slots_[slot];
    if (entry == kFree) {
      const auto index = static_cast<std::uint32_t>(vertices_.size());
      slots_[slot] = tag | index;
      vertices_.push_back(q);
      return index;
    }
    const auto index = static_cast<std::uint32_t>(entry);
    const Quantised& p = vertices_[index];
    if ((entry & ~std::uint64_t{UINT32_MAX}) == tag && p[0] == q[0] && p[1] == q[1] &&
        p[2] == q[2]) {
      return index;
    }
  }
}

void VertexPool::rehash(std::size_t slots) {
  slots_.assign(slots, kFree);
  const std::size_t mask = slots - 1;
  for (std::uint32_t index = 0; index < vertices_.size(); ++index) {
    const std::uint64_t hash = QuantisedHash{}(vertices_[index]);
    std::size_t slot = hash & mask;
    while (slots_[slot] != kFree) slot = (slot + 1) & mask;
    slots_[slot] = (hash & ~std::uint64_t{UINT32_MAX}) | index;
  }
}

bool IdSet::insert(std::string_view id) {
  if (2 * (ids_.size() + 1) > slots_.size()) {
    slots_.assign(std::max<std::size_t>(16, 2 * slots_.size()), kFree);
    for (std::uint32_t index = 0; index < ids_.size(); ++index) place(ids_[index], index);
  }
  const std::uint64_t hash = std::hash<std::string_view>{}(id);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = hash & mask; slots_[slot] != kFree; slot = (slot + 1) & mask) {
    const std::uint64_t entry = slots_[slot];
    if ((entry >> 32U) == (hash >> 32U) && ids_[static_cast<std::uint32_t>(entry)] == id) {
      return false;
    }
  }
  ids_.emplace_back(id);
  place(ids_.back(), static_cast<std::uint32_t>(ids_.size() - 1));
  return true;
}

void IdSet::place(std::string_view id, std::uint32_t index) {
  const std::uint64_t hash = std::hash<std::string_view>{}(id);
  const std::size_t mask = slots_.size() - 1;
  std::size_t slot = hash & mask;
  while (slots_[slot] != kFree) slot = (slot + 1) & mask;
  slots_[slot] = (hash & ~std::uint64_t{UINT32_MAX}) | index;
}

void VertexPool::reserve(std::size_t n) {
  std::size_t slots = 16;
  while (3 * slots < 4 * n) slots *= 2;
  if (slots > slots_.size()) rehash(slots);
  vertices_.reserve(n);
}

void VertexPool::clear() {
  std::fill(slots_.begin(), slots_.end(), kFree);
  vertices_.clear();
}

Quantised CityObjects::quantise(kernel::Vec3 local) const {
  const kernel::Vec3 d = (local - base_) * kPerMeter;
  return {round_half_away(d.x), round_half_away(d.y), round_half_away(d.z)};
}

// Each mesh vertex is quantised and pooled once, however many faces use it.
void CityObjects::collect_surfaces(const kernel::Mesh& mesh) {
  constexpr std::uint32_t kUnset = UINT32_MAX;
  constexpr std::uint32_t kUnwritable = UINT32_MAX - 1;  // not finite, or too far to quantise
  part_.clear();
  pool_index_.assign(mesh.vertex_count(), kUnset);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t begin = part_.indices.size();
    bool ok = true;
    for (std::uint32_t vertex : mesh.face(f)) {
      std::uint32_t& index = pool_index_[vertex];
      if (index == kUnset) {
        const kernel::Vec3 p = mesh.position(vertex);
        index = finite(p) && quantisable(p - base_) ? pool_.add(quantise(p)) : kUnwritable;
      }
      if (index == kUnwritable) {
        ok = false;
        break;
      }
      if (part_.indices.size() == begin || part_.indices.back() != index) {
        part_.indices.push_back(index);
      }
    }
    while (part_.indices.size() > begin + 1 && part_.indices.back() == part_.indices[begin]) {
      part_.indices.pop_back();
    }
    if (!ok || part_.indices.size() < begin + 3) {
      part_.indices.resize(begin);
      continue;
    }
    part_.ends.push_back(part_.indices.size());
    part_.types.push_back(kernel::citygml_surface(mesh.tag(f).semantic));
  }
}

// A Solid needs one closed, consistently outward-oriented 2-manifold shell: checked on the
// quantised rings, so the test sees exactly what a validator such as val3dity will see. What
// kernel::check calls closed, oriented and manifold with one component is tested on lists of
// each vertex's outgoing edges (a handful each): every edge used once and its reverse once, and
// every vertex reached from the first; the volume is kernel::volume's, on the quantised points.
bool CityObjects::is_solid() const {
  if (part_.size() < 4) return false;
  ++stamp_;
  if (local_index_.size() < pool_.vertices().size()) {
    local_index_.resize(pool_.vertices().size());
    local_stamp_.resize(pool_.vertices().size(), 0);
  }
  std::uint32_t locals = 0;
  const auto local = [this, &locals](std::uint32_t index) {
    if (local_stamp_[index] != stamp_) {
      local_stamp_[index] = stamp_;
      local_index_[index] = locals++;
    }
    return local_index_[index];
  };
  // The out-edges of local vertex v are to_[first_[v] .. first_[v + 1]).
  first_.assign(1, 0);
  const auto for_each_edge = [this](auto&& visit) {
    for (std::size_t r = 0; r < part_.size(); ++r) {
      const std::span<const std::uint32_t> ring = part_.ring(r);
      for (std::size_t i = 0; i < ring.size(); ++i) {
        visit(ring[i], ring[i + 1 < ring.size() ? i + 1 : 0]);
      }
    }
  };
  for_each_edge([&](std::uint32_t from, std::uint32_t /*to*/) {
    const std::uint32_t a = local(from);
    if (first_.size() < a + 2U) first_.resize(a + 2, 0);
    ++first_[a + 1];
  });
  // Every vertex of a ring begins one of its edges.
  for (std::size_t v = 0; v < locals; ++v) first_[v + 1] += first_[v];
  to_.resize(first_.back());
  cursor_.assign(first_.begin(), first_.end() - 1);
  for_each_edge([&](std::uint32_t from, std::uint32_t to) {
    to_[cursor_[local_index_[from]]++] = local_index_[to];
  });
  const auto out = [this](std::uint32_t v) {
    return std::span<const std::uint32_t>(to_).subspan(first_[v], first_[v + 1] - first_[v]);
  };
  for (std::uint32_t a = 0; a < locals; ++a) {
    const std::span<const std::uint32_t> edges = out(a);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const std::uint32_t b = edges[i];
      if (std::find(edges.begin() + static_cast<std::ptrdiff_t>(i) + 1, edges.end(), b) !=
          edges.end()) {
        return false;  // used twice
      }
      const std::span<const std::uint32_t> back = out(b);
      if (std::find(back.begin(), back.end(), a) == back.end()) return false;  // no reverse
    }
  }
  // One component: every vertex reached from the first along edges (each has its reverse).
  reached_.assign(locals, false);
  cursor_.assign(1, 0);
  reached_[0] = true;
  std::size_t count = 1;
  while (!cursor_.empty()) {
    const std::uint32_t v = cursor_.back();
    cursor_.pop_back();
    for (const std::uint32_t w : out(v)) {
      if (!reached_[w]) {
        reached_[w] = true;
        ++count;
        cursor_.push_back(w);
      }
    }
  }
  return count == locals && volume() > 0;
}

// kernel::volume of the part's quantised rings (the same sums in the same order).
double CityObjects::volume() const {
  const auto point = [this](std::uint32_t index) {
    const Quantised& q = pool_.vertices()[index];
    return kernel::Vec3{static_cast<double>(q[0]), static_cast<double>(q[1]),
                        static_cast<double>(q[2])};
  };
  double total = 0;
  for (std::size_t r = 0; r < part_.size(); ++r) {
    const std::span<const std::uint32_t> ring = part_.ring(r);
    kernel::Vec3 newell;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const kernel::Vec3 a = point(ring[i]);
      const kernel::Vec3 b = point(ring[i + 1 < ring.size() ? i + 1 : 0]);
      newell += kernel::Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                             (a.x - b.x) * (a.y + b.y)};
    }
    total += kernel::dot(point(ring[0]), newell / 2);
  }
  return total / 3;
}

// {"boundaries", "lod", "semantics" (when some face has a type), "type"}; a Solid wraps the
// surfaces and values in one more array (its single outer shell).
void CityObjects::write_geometry(JsonStream& json) const {
  const bool solid = is_solid();
  json.begin_object().key("boundaries").begin_array();
  if (solid) json.begin_array();
  for (std::size_t r = 0; r < part_.size(); ++r) {
    json.begin_array().integers(part_.ring(r)).end_array();
  }
  if (solid) json.end_array();
  json.end_array().key("lod").string("2");
  std::vector<std::string_view> seen;
  for (std::string_view type : part_.types) {
    if (!type.empty() && std::find(seen.begin(), seen.end(), type) == seen.end()) {
      seen.push_back(type);
    }
  }
  if (!seen.empty()) {
    json.key("semantics").begin_object().key("surfaces").begin_array();
    for (std::string_view type : seen) json.begin_object().key("type").string(type).end_object();
    json.end_array().key("values").begin_array();
    if (solid) json.begin_array();
    for (std::string_view type : part_.types) {
      if (type.empty()) {
        json.null();
      } else {
        json.integer(std::find(seen.begin(), seen.end(), type) - seen.begin());
      }
    }
    if (solid) json.end_array();
    json.end_array().end_object();
  }
  json.key("type").string(solid ? "Solid" : "MultiSurface").end_object();
}

// A part's id: unique among the ids given and none of the avoided buildings' ids.
std::string CityObjects::unique_part_id(const std::string& base) {
  std::string id = base;
  for (int suffix = 2; (avoided_ && avoided_->contains(id)) || !ids_.insert(id); ++suffix) {
    id = base + "-" + std::to_string(suffix);
  }
  return id;
}

std::string CityObjects::add_building(const shape::Building& building, std::size_t index) {
  const std::string id =
      unique_id(building.id.empty() ? "building" + std::to_string(index) : building.id, ids_);
  std::vector<std::string> children;
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    std::string part_id =
        unique_part_id(id + "-" + (part.name.empty() ? "part" + std::to_string(p) : part.name));
    const std::size_t begin = text_.size();
    JsonStream json(text_);
    json.begin_object();
    if (!part.attributes.empty()) json.key("attributes").attributes(part.attributes);
    if (part.instance_of) {
      collect_surfaces(shape::part_world_mesh(part));
    } else {
      collect_surfaces(part.mesh);
    }
    if (part_.size() > 0) {
      json.key("geometry").begin_array();
      write_geometry(json);
      json.end_array();
    }
    json.key("parents").begin_array().string(id).end_array();
    json.key("type").string(object_type(part.kind)).end_object();
    objects_.push_back({part_id, begin, text_.size()});
    children.push_back(std::move(part_id));
  }
  const std::size_t begin = text_.size();
  JsonStream json(text_);
  json.begin_object();
  if (!building.attributes.empty()) json.key("attributes").attributes(building.attributes);
  if (!children.empty()) {
    json.key("children").begin_array();
    for (const std::string& child : children) json.string(child);
    json.end_array();
  }
  json.key("type").string("Building").end_object();
  objects_.push_back({id, begin, text_.size()});
  return id;
}

// Sorted by id through a list of (first 8 bytes, position): most comparisons are settled by the
// prefix, read as a big-endian number (a shorter id's missing bytes as 0, which orders it first
// as the full comparison would; equal prefixes go to the full comparison).
void CityObjects::write_objects(JsonStream& json) {
  struct Key {
    std::uint64_t prefix;
    std::uint32_t object;
  };
  std::vector<Key> order;
  order.reserve(objects_.size());
  for (std::uint32_t o = 0; o < objects_.size(); ++o) {
    std::uint64_t prefix = 0;
    const std::string& id = objects_[o].id;
    for (std::size_t i = 0; i < 8; ++i) {
      prefix = (prefix << 8U) | (i < id.size() ? static_cast<unsigned char>(id[i]) : 0U);
    }
    order.push_back({prefix, o});
  }
  std::sort(order.begin(), order.end(), [this](const Key& a, const Key& b) {
    if (a.prefix != b.prefix) return a.prefix < b.prefix;
    return std::string_view(objects_[a.object].id) < std::string_view(objects_[b.object].id);
  });
  json.begin_object();
  for (const Key& key : order) {
    const ObjectText& object = objects_[key.object];
    json.key(object.id).raw(
        std::string_view(text_).substr(object.begin, object.end - object.begin));
  }
  json.end_object();
}

std::size_t CityObjects::text_size() const {
  std::size_t size = text_.size() + 2;
  for (const ObjectText& object : objects_) size += object.id.size() + 4;  // "id": and a comma
  return size;
}

void CityObjects::write_vertices(JsonStream& json) const {
  json.begin_array();
  for (const Quantised& q : pool_.vertices()) json.integers(std::span<const std::int64_t>(q));
  json.end_array();
}

void CityObjects::clear() {
  pool_.clear();
  text_.clear();
  objects_.clear();
}

kernel::Vec3 local_minimum(const shape::Scene& scene) {
  kernel::Bounds3 bounds;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (const kernel::Vec3& p : part.mesh.positions()) {
        if (finite(p)) bounds.add(p);
      }
    }
  }
  return bounds.empty() ? kernel::Vec3{} : bounds.min;
}

void write_transform(JsonStream& json, kernel::Vec3 translate) {
  json.begin_object().key("scale").begin_array();
  json.number(kScale).number(kScale).number(kScale).end_array();
  json.key("translate").begin_array();
  json.number(translate.x).number(translate.y).number(translate.z).end_array().end_object();
}

}  // namespace insula::io::cityjson
