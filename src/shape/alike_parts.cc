#include "shape/alike_parts.h"

#include <set>
#include <utility>

#include "shape/uv_map.h"

namespace insula::shape {

std::size_t AlikeParts::index(std::vector<Part>& parts, std::string_view name, PartKind kind,
                              const AttributeMap& attributes, const std::optional<UvMap>& uv) {
  const auto [it, added] = index_.try_emplace(
      Key{std::string(name), kind, attributes, uv ? encode(*uv) : std::string()}, parts.size());
  if (added) {
    Part& made = parts.emplace_back();
    made.name = std::string(name);
    made.kind = kind;
    made.attributes = attributes;
    made.uv = uv;
  }
  return it->second;
}

void AlikeParts::add(std::vector<Part>& parts, Part&& part) {
  if (part.instance_of != nullptr) {
    parts.push_back(std::move(part));
    return;
  }
  const auto [it, added] = index_.try_emplace(
      Key{part.name, part.kind, part.attributes, part.uv ? encode(*part.uv) : std::string()},
      parts.size());
  if (added) {
    parts.push_back(std::move(part));
  } else {
    parts[it->second].mesh.append(part.mesh);
  }
}

bool has_alike_parts(const Building& building) {
  // Ordered by name, kind and attributes, then by uv map: compared by pointer, nothing copied.
  const auto less = [](const Part* a, const Part* b) {
    if (a->name != b->name) return a->name < b->name;
    if (a->kind != b->kind) return a->kind < b->kind;
    if (a->attributes != b->attributes) return a->attributes < b->attributes;
    if (a->uv.has_value() != b->uv.has_value()) return b->uv.has_value();
    return a->uv.has_value() && encode(*a->uv) < encode(*b->uv);
  };
  std::set<const Part*, decltype(less)> seen(less);
  for (const Part& part : building.parts) {
    if (part.instance_of == nullptr && !seen.insert(&part).second) return true;
  }
  return false;
}

Building merge_alike_parts(const Building& building) {
  Building merged;
  merged.id = building.id;
  merged.attributes = building.attributes;
  merged.plans = building.plans;
  AlikeParts alike;
  for (const Part& part : building.parts) alike.add(merged.parts, Part(part));
  return merged;
}

}  // namespace insula::shape
