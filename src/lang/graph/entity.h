// Entities of a graph run (graph-format.md §10) and their store. An entity is a small record:
// its type, the entity it descends from (lineage, §9.10), its random seed (§9.9), the head of a
// persistent attribute chain shared with its ancestors and copies (§7: "attributes are always
// copied from the ancestors to their descendants"; stored once, looked up along the chain), and
// its payload: a shape in the run's shape tree, a street network, a point, a light, a texture,
// a group's members or a terrain's heightfield (docs/graph-executor.md, "Entities").
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/heightfield.h"
#include "kernel/mesh.h"
#include "kernel/street_network.h"
#include "kernel/vec.h"
#include "lang/graph/types.h"
#include "lang/graph/value.h"
#include "shape/scene.h"
#include "shape/shape.h"

namespace insula::lang::graph {

using EntityId = std::uint32_t;
inline constexpr EntityId kNoEntity = 0xffffffffU;

// An attribute of one declaration in one graph execution: graph runs number their executions
// (the root is 0, each subgraph round a new one), so a subgraph's attributes are unreachable
// once its entities leave (§8: "every attribute declared in the subgraph is removed").
using AttributeKey = std::uint64_t;
inline AttributeKey attribute_key(std::uint64_t execution, std::size_t declaration) {
  return (execution << 16U) | declaration;
}

// A street network (§10 `path`): vertices and edges in world space (kernel/street_network.h).
using PathGeometry = kernel::StreetNetwork;

struct LightData {
  std::string kind = "point";  // point, spot
  double intensity = 100;      // candela
  kernel::Vec3 color{1, 1, 0.8};
  double range = 0;  // 0: unlimited
};

// An RGBA image with a name (§10 `texture`), 8 bits per channel, rows top to bottom.
struct Texture {
  std::string name;
  std::string text;  // what texture.text wrote, for reports
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

// Parts a rule node made from a shape (a CGA rule file, a .bldg grammar, a Lua program or a
// PLaSM function): world-space meshes whose face materials index `materials`.
struct Model {
  std::vector<shape::Part> parts;
  std::vector<shape::Material> materials;  // index 0 is the default
};

struct Entity {
  EntityType type = EntityType::kEntity;
  EntityId parent = kNoEntity;  // the entity it was made from (none for created ones)
  std::uint32_t lineage = 0;    // copies made by divergence share it (§9.10)
  std::uint64_t seed = 0;
  std::uint32_t attributes = 0;  // head of the attribute chain (0: none set)
  std::uint32_t children = 0;    // descendants made so far (their child index, §9.9)
  // shape
  shape::ShapeId shape = shape::kNoShape;
  std::uint16_t material = 0;  // index into the run's materials; 0: the faces' own
  std::shared_ptr<const Model> model;
  // path
  std::shared_ptr<const PathGeometry> path;
  // point, light
  kernel::Vec3 position;
  std::shared_ptr<const LightData> light;
  // texture
  std::shared_ptr<const Texture> texture;
  // group
  std::vector<EntityId> members;
  // terrain (world XY and z; docs/graph-executor.md, "Terrain")
  std::shared_ptr<const kernel::Heightfield> terrain;
};

// Every entity of a run, never freed during it (a run is a batch). Not thread-safe for writes.
class EntityStore {
 public:
  EntityStore();

  const Entity& operator[](EntityId id) const { return entities_[id]; }
  Entity& operator[](EntityId id) { return entities_[id]; }
  std::size_t size() const { return entities_.size(); }

  // A new entity with no parent: its own lineage, the given seed.
  EntityId create(EntityType type, std::uint64_t seed);
  // A descendant of `parent` (§9.9: its seed follows from the parent's and its child index; it
  // inherits the parent's attributes); the payload is the caller's to set.
  EntityId derive(EntityId parent, EntityType type);
  // A copy for a divergent edge: same lineage, seed, attributes and payload.
  EntityId copy(EntityId original);

  // The value of `key` on the entity or its nearest ancestor, or null.
  const Value* attribute(EntityId id, AttributeKey key) const;
  void set_attribute(EntityId id, AttributeKey key, Value value);
  // Every (key, value) visible from the entity, nearest first, each key once.
  std::vector<std::pair<AttributeKey, const Value*>> attributes(EntityId id) const;

  // True when `maybe_ancestor`'s lineage is the lineage of `id` or of one of its ancestors.
  bool descends_from(EntityId id, EntityId maybe_ancestor) const;
  // Either descends from the other (§9.10: queries skip an entity's own ancestors and
  // descendants).
  bool related(EntityId a, EntityId b) const { return descends_from(a, b) || descends_from(b, a); }

 private:
  struct AttributeNode {
    std::uint32_t next = 0;
    AttributeKey key = 0;
    Value value;
  };
  std::deque<Entity> entities_;
  std::deque<AttributeNode> attribute_nodes_;  // node 0: the empty chain
  std::uint32_t next_lineage_ = 0;
};

}  // namespace insula::lang::graph
