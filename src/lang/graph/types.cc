#include "lang/graph/types.h"

#include <array>

#include "base/format.h"

namespace insula::lang::graph {
namespace {

constexpr std::array<std::string_view, 9> kEntityNames = {
    "entity", "actor", "shape", "path", "point", "light", "texture", "group", "terrain"};
constexpr std::array<std::string_view, 8> kValueNames = {"number", "integer", "bool", "string",
                                                         "vec3",   "list",    "enum", "any"};

EntityType parent(EntityType type) {
  switch (type) {
    case EntityType::kShape:
    case EntityType::kPath:
    case EntityType::kPoint:
    case EntityType::kLight:
    case EntityType::kTerrain:
      return EntityType::kActor;
    default:
      return EntityType::kEntity;
  }
}

}  // namespace

std::string_view entity_type_name(EntityType type) {
  return kEntityNames[static_cast<std::size_t>(type)];
}

std::optional<EntityType> entity_type_named(std::string_view name) {
  for (std::size_t i = 0; i < kEntityNames.size(); ++i) {
    if (kEntityNames[i] == name) return static_cast<EntityType>(i);
  }
  return std::nullopt;
}

bool is_subtype(EntityType sub, EntityType super) {
  for (EntityType t = sub;; t = parent(t)) {
    if (t == super) return true;
    if (t == EntityType::kEntity) return false;
  }
}

EntityType common_supertype(EntityType a, EntityType b) {
  for (EntityType t = a;; t = parent(t)) {
    if (is_subtype(b, t)) return t;
  }
}

std::string_view value_type_name(ValueType type) {
  return kValueNames[static_cast<std::size_t>(type)];
}

std::optional<ValueType> value_type_named(std::string_view name) {
  for (std::size_t i = 0; i + 1 < kValueNames.size(); ++i) {
    if (kValueNames[i] == name) return static_cast<ValueType>(i);
  }
  return std::nullopt;
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  const std::size_t limit = word.size() <= 2 ? 1 : 2;
  std::size_t best = limit + 1;
  std::string found;
  for (const std::string& c : candidates) {
    const std::size_t d = base::edit_distance(word, c);
    if (d < best && d > 0) {
      best = d;
      found = c;
    }
  }
  return found;
}

}  // namespace insula::lang::graph
