// The entity types of §10 (a lattice under `entity`) and the value types of parameters and
// attributes (§5, §6), shared by the catalogue, the model and the checker.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insula::lang::graph {

// entity > actor > {shape, path, point, light, terrain}; entity > texture; entity > group.
// `terrain` (a heightfield) extends §10 (docs/graph-executor.md, "Terrain").
enum class EntityType : std::uint8_t {
  kEntity,
  kActor,
  kShape,
  kPath,
  kPoint,
  kLight,
  kTexture,
  kGroup,
  kTerrain
};

std::string_view entity_type_name(EntityType type);
std::optional<EntityType> entity_type_named(std::string_view name);
// True when every `sub` is a `super` (reflexive).
bool is_subtype(EntityType sub, EntityType super);
// The least common supertype.
EntityType common_supertype(EntityType a, EntityType b);

enum class ValueType : std::uint8_t {
  kNumber,
  kInteger,
  kBool,
  kString,
  kVec3,
  kList,
  kEnum,
  kAny
};

std::string_view value_type_name(ValueType type);
std::optional<ValueType> value_type_named(std::string_view name);

// The candidate within two edits of `word` (one for words of up to two letters), nearest first,
// then first listed; empty when none is that close. Behind every "did you mean" of the graph
// front-end (edit distance from base/format.h, as the CLI's verbs and PLaSM's names).
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace insula::lang::graph
