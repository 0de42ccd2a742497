#include "lang/graph/entity.h"

#include <algorithm>

#include "shape/rng.h"

namespace insula::lang::graph {

EntityStore::EntityStore() {
  attribute_nodes_.emplace_back();
}

EntityId EntityStore::create(EntityType type, std::uint64_t seed) {
  Entity e;
  e.type = type;
  e.seed = seed;
  e.lineage = next_lineage_++;
  entities_.push_back(std::move(e));
  return static_cast<EntityId>(entities_.size() - 1);
}

EntityId EntityStore::derive(EntityId parent, EntityType type) {
  Entity& p = entities_[parent];
  Entity e;
  e.type = type;
  e.parent = parent;
  e.seed = shape::child_seed(p.seed, p.children++);
  e.lineage = next_lineage_++;
  e.attributes = p.attributes;
  entities_.push_back(std::move(e));
  return static_cast<EntityId>(entities_.size() - 1);
}

EntityId EntityStore::copy(EntityId original) {
  Entity e = entities_[original];
  e.children = 0;
  entities_.push_back(std::move(e));
  return static_cast<EntityId>(entities_.size() - 1);
}

const Value* EntityStore::attribute(EntityId id, AttributeKey key) const {
  for (std::uint32_t n = entities_[id].attributes; n != 0; n = attribute_nodes_[n].next) {
    if (attribute_nodes_[n].key == key) return &attribute_nodes_[n].value;
  }
  return nullptr;
}

void EntityStore::set_attribute(EntityId id, AttributeKey key, Value value) {
  attribute_nodes_.push_back({entities_[id].attributes, key, std::move(value)});
  entities_[id].attributes = static_cast<std::uint32_t>(attribute_nodes_.size() - 1);
}

std::vector<std::pair<AttributeKey, const Value*>> EntityStore::attributes(EntityId id) const {
  std::vector<std::pair<AttributeKey, const Value*>> out;
  for (std::uint32_t n = entities_[id].attributes; n != 0; n = attribute_nodes_[n].next) {
    const AttributeKey key = attribute_nodes_[n].key;
    const bool seen =
        std::any_of(out.begin(), out.end(), [&](const auto& kv) { return kv.first == key; });
    if (!seen) out.emplace_back(key, &attribute_nodes_[n].value);
  }
  return out;
}

bool EntityStore::descends_from(EntityId id, EntityId maybe_ancestor) const {
  const std::uint32_t lineage = entities_[maybe_ancestor].lineage;
  for (EntityId e = id; e != kNoEntity; e = entities_[e].parent) {
    if (entities_[e].lineage == lineage) return true;
  }
  return false;
}

}  // namespace insula::lang::graph
