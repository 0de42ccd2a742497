// Shape (mesh) operations (graph-format.md §11): thin wrappers over the shared operation registry
// (docs/operations.md), so a graph reaches what CGA and Lua reach; actor transforms also move
// paths, points and lights.
#include <cmath>

#include "kernel/mesh.h"
#include "lang/graph/nodes.h"
#include "lang/graph/properties.h"
#include "lang/graph/shape_entities.h"
#include "shape/ops.h"
#include "shape/scope.h"

namespace insula::lang::graph {
namespace {

const shape::Operation& operation(std::string_view name) {
  return *shape::registry().find(name);
}

// A node that is one registry operation with one output port `out` (extrude, roof, insert).
template <const char* kOp>
void single_output(NodeContext& c) {
  const shape::Operation& op = operation(kOp);
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    std::vector<EntityId> children;
    if (!run_operation(c, in, kOp, registry_arguments(c, r, op), children)) continue;
    for (EntityId e : children) c.emit(c.output_port("out"), e);
  }
}
constexpr char kExtrude[] = "extrude";
constexpr char kRoof[] = "roof";
constexpr char kInsert[] = "insert";

void write_index(NodeContext& c, const std::vector<EntityId>& children) {
  for (std::size_t i = 0; i < children.size(); ++i) {
    c.write(children[i], "index", Value(static_cast<std::int64_t>(i)));
    c.write(children[i], "count", Value(static_cast<std::int64_t>(children.size())));
  }
}

void repeat(NodeContext& c) {
  const shape::Operation& op = operation("repeat");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    std::vector<EntityId> children;
    if (!run_operation(c, c.current(r), "repeat", registry_arguments(c, r, op), children)) continue;
    write_index(c, children);
    for (EntityId e : children) c.emit(c.output_port("out"), e);
  }
}

// Slices are the `slice` augmentations, in order; each piece leaves on its item's port.
void split(NodeContext& c) {
  const shape::Operation& op = operation("split");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    std::vector<shape::ArgInput> args = registry_arguments(c, r, op);
    std::vector<shape::SizeSpec> sizes;
    for (std::size_t i = 0; i < c.augment_count(); ++i) {
      const Value v = c.field(r, i, "size", in);
      shape::ParamDecl decl;
      decl.type = shape::ParamType::kSize;
      const std::optional<shape::ArgValue> size = to_argument(v, decl);
      if (!size || !std::holds_alternative<shape::SizeSpec>(*size)) {
        c.error("slice " + std::to_string(i) + ": a size is meters, 'r or ~w; got " + to_string(v));
      }
      sizes.push_back(std::get<shape::SizeSpec>(*size));
    }
    args.push_back({"sizes", sizes});
    std::vector<EntityId> children;
    std::vector<std::uint32_t> pieces;
    if (!run_operation(c, in, "split", args, children, &pieces)) continue;
    for (std::size_t k = 0; k < children.size(); ++k) {
      c.write(children[k], "index", Value(static_cast<std::int64_t>(pieces[k])));
      c.write(children[k], "count", Value(static_cast<std::int64_t>(sizes.size())));
      c.emit(c.augment_port(pieces[k]), children[k]);
    }
  }
}

// Every face goes to the first `select` item it matches; unmatched faces are dropped.
void comp(NodeContext& c) {
  static constexpr std::pair<std::string_view, shape::FaceSelector> kSelectors[] = {
      {"front", shape::FaceSelector::kFront}, {"back", shape::FaceSelector::kBack},
      {"left", shape::FaceSelector::kLeft},   {"right", shape::FaceSelector::kRight},
      {"top", shape::FaceSelector::kTop},     {"bottom", shape::FaceSelector::kBottom},
      {"side", shape::FaceSelector::kSide},   {"all", shape::FaceSelector::kAll}};
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    std::vector<shape::FaceSelector> selectors;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < c.augment_count(); ++i) {
      const std::string faces = c.field(r, i, "faces", in).text();
      names.push_back(faces);
      for (const auto& [name, selector] : kSelectors) {
        if (name == faces) selectors.push_back(selector);
      }
    }
    const shape::ShapeId id = c.entities()[in].shape;
    const std::shared_ptr<const kernel::Mesh> mesh = c.tree()[id].mesh;
    std::vector<EntityId> children;
    std::vector<std::uint32_t> pieces;
    if (!run_operation(c, in, "comp", {{"type", std::string("faces")}}, children, &pieces)) {
      continue;
    }
    std::vector<std::vector<EntityId>> chosen(selectors.size());
    for (std::size_t k = 0; k < children.size(); ++k) {
      const kernel::Vec3 n = kernel::face_normal(*mesh, pieces[k]);
      for (std::size_t i = 0; i < selectors.size(); ++i) {
        if (!shape::face_matches(selectors[i], n)) continue;
        chosen[i].push_back(children[k]);
        c.write(children[k], "face", Value(names[i]));
        break;
      }
    }
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      write_index(c, chosen[i]);
      for (EntityId e : chosen[i]) c.emit(c.augment_port(i), e);
    }
  }
}

// Two-port operations whose pieces name the port: offset (inside, border), setback (strip, rest).
template <const char* kOp>
void two_parts(NodeContext& c) {
  const shape::Operation& op = operation(kOp);
  const bool offset = std::string_view(kOp) == "offset";
  const std::size_t first = c.output_port(offset ? "inside" : "strip");
  const std::size_t second = c.output_port(offset ? "border" : "rest");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    std::vector<EntityId> children;
    std::vector<std::uint32_t> pieces;
    if (!run_operation(c, c.current(r), kOp, registry_arguments(c, r, op), children, &pieces)) {
      continue;
    }
    for (std::size_t k = 0; k < children.size(); ++k) {
      c.emit(pieces[k] == 0 ? first : second, children[k]);
    }
  }
}
constexpr char kOffset[] = "offset";
constexpr char kSetback[] = "setback";

// Any registry operation by name, its arguments an object (name -> value).
void op(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const std::string name = c.param(r, "op").text();
    const shape::Operation* operation = shape::registry().find(name);
    if (operation == nullptr) c.error("unknown operation '" + name + "'");
    std::vector<shape::ArgInput> args;
    const ParamValue* given = nullptr;
    for (const ParamValue& v : c.node().params) {
      if (v.name == "args") given = &v;
    }
    if (given != nullptr && given->value->kind == JsonValue::Kind::kObject) {
      for (const JsonMember& m : given->value->members) {
        const shape::ParamDecl* decl = operation->param(m.key);
        if (decl == nullptr) c.error(name + ": unknown parameter '" + m.key + "'");
        std::optional<Value> v = value_from_json(m.value);
        std::optional<shape::ArgValue> arg = v ? to_argument(*v, *decl) : std::nullopt;
        if (!arg) c.error(name + ": parameter '" + m.key + "' cannot take this value");
        args.push_back({m.key, *arg});
      }
    }
    std::vector<EntityId> children;
    if (!run_operation(c, in, name, args, children)) continue;
    write_index(c, children);
    for (EntityId e : children) c.emit(c.output_port("out"), e);
  }
}

std::array<float, 4> rgba(const Value& color) {
  const kernel::Vec3 v =
      color.type() == ValueType::kVec3 ? color.vec() : kernel::Vec3{0.8, 0.8, 0.8};
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 1.0F};
}

void set_material(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const std::uint16_t m = c.material(c.param(r, "material").text(), rgba(c.param(r, "color")));
    const EntityId out = c.entities().copy(in);
    c.entities()[out].material = m;
    c.emit(c.output_port("out"), out);
  }
}

void set_texture(NodeContext& c) {
  const std::size_t texture_port = c.input_port("texture");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const EntityId texture = c.input(r, texture_port).front();
    const std::shared_ptr<const Texture>& image = c.entities()[texture].texture;
    const EntityId out = c.entities().copy(in);
    c.entities()[out].material = c.textured_material(image);
    c.emit(c.output_port("out"), out);
  }
}

// Shapes through the registry; paths, points, lights and terrains moved directly (their scope
// is the world's axes, so scope and world spaces agree).
void move_other(NodeContext& c, EntityId out, kernel::Vec3 by) {
  Entity& e = c.entities()[out];
  e.position = e.position + by;
  if (e.path != nullptr) {
    auto path = std::make_shared<PathGeometry>(*e.path);
    for (kernel::Vec3& v : path->vertices) v = v + by;
    e.path = path;
  }
  if (e.terrain != nullptr) {
    auto field = std::make_shared<kernel::Heightfield>(*e.terrain);
    field->origin = field->origin + kernel::Vec2{by.x, by.y};
    for (double& z : field->z) z += by.z;
    e.terrain = field;
  }
}

template <const char* kOp>
void actor(NodeContext& c) {
  const shape::Operation& op = operation(kOp);
  const std::string_view name = kOp;
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    if (c.entities()[in].type == EntityType::kShape) {
      std::vector<shape::ArgInput> args = registry_arguments(c, r, op);
      if (name == "translate" && c.param(r, "space").text() == "world") {
        // World offsets as scope offsets: project on the scope's axes.
        const shape::Scope& s = c.tree()[c.entities()[in].shape].scope;
        const kernel::Vec3 w{c.param(r, "x").number(), c.param(r, "y").number(),
                             c.param(r, "z").number()};
        args = {{"x", kernel::dot(w, s.x)}, {"y", kernel::dot(w, s.y)}, {"z", kernel::dot(w, s.z)}};
      }
      std::vector<EntityId> children;
      if (!run_operation(c, in, std::string(name), args, children)) continue;
      for (EntityId e : children) c.emit(c.output_port("out"), e);
      continue;
    }
    const EntityId out = c.entities().derive(in, c.entities()[in].type);
    Entity& e = c.entities()[out];
    const Entity& src = c.entities()[in];
    e.position = src.position;
    e.path = src.path;
    e.light = src.light;
    e.terrain = src.terrain;
    if (name == "translate") {
      move_other(c, out,
                 {c.param(r, "x").number(), c.param(r, "y").number(), c.param(r, "z").number()});
    } else if (name != "scale" || e.type != EntityType::kPoint) {
      // A point has no size, so scaling leaves it as it is; nothing else but a shape turns.
      c.fail(in, std::string(name) + " needs a shape; a " + std::string(entity_type_name(e.type)) +
                     " can only be translated");
      continue;
    }
    c.emit(c.output_port("out"), out);
  }
}
constexpr char kTranslate[] = "translate";
constexpr char kRotate[] = "rotate";
constexpr char kScale[] = "scale";

// All faces of the inputs in one shape (world axes, scope the bounds); the attributes every
// input shares are kept.
void merge(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::span<const EntityId> in = c.input(r, 0);
    if (in.empty()) continue;
    auto mesh = std::make_shared<kernel::Mesh>();
    for (EntityId e : in) {
      const shape::Shape& s = c.tree()[c.entities()[e].shape];
      if (s.mesh != nullptr) mesh->append(shape::mesh_to_world(*s.mesh, s.scope));
    }
    const EntityId out = merged_entity(c, r, 0, in, *mesh);
    c.emit(c.output_port("out"), out);
  }
}

// "Fit-to-scope" (Fig. 5): the shape placed in the target's scope, scaled to its size on the
// chosen axes.
void fit_scope(NodeContext& c) {
  const std::size_t target_port = c.input_port("target");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const EntityId target = c.input(r, target_port).front();
    const std::optional<shape::Scope> goal = entity_scope(c.entities(), c.tree(), target);
    const shape::Shape& s = c.tree()[c.entities()[in].shape];
    const std::string axes = c.param(r, "axes").text();
    shape::Scope placed = *goal;
    kernel::Vec3 factor{1, 1, 1};
    // An axis the target has no extent on (a point, a flat face's z) keeps the shape's size,
    // so fitting to a point places the shape there unscaled.
    const auto fit = [&](char axis, double own, double& want, double& f) {
      if (axes.find(axis) != std::string::npos && own > 0 && want > 0) {
        f = want / own;
      } else {
        want = own;
      }
    };
    fit('x', s.scope.size.x, placed.size.x, factor.x);
    fit('y', s.scope.size.y, placed.size.y, factor.y);
    fit('z', s.scope.size.z, placed.size.z, factor.z);
    std::shared_ptr<const kernel::Mesh> mesh = s.mesh;
    if (mesh != nullptr) {
      auto scaled = std::make_shared<kernel::Mesh>(*mesh);
      for (kernel::Vec3& p : scaled->positions())
        p = {p.x * factor.x, p.y * factor.y, p.z * factor.z};
      mesh = scaled;
    }
    const shape::ShapeId child = c.tree().add_child(c.entities()[in].shape, placed, mesh);
    c.emit(c.output_port("out"), shape_child(c, in, child));
  }
}

constexpr NodeImpl kNodes[] = {
    {"shape.extrude", single_output<kExtrude>},
    {"shape.split", split},
    {"shape.repeat", repeat},
    {"shape.comp", comp},
    {"shape.offset", two_parts<kOffset>},
    {"shape.setback", two_parts<kSetback>},
    {"shape.roof", single_output<kRoof>},
    {"shape.insert", single_output<kInsert>},
    {"shape.fit_scope", fit_scope},
    {"shape.merge", merge},
    {"shape.set_material", set_material},
    {"shape.set_texture", set_texture},
    {"shape.op", op},
    {"actor.translate", actor<kTranslate>},
    {"actor.rotate", actor<kRotate>},
    {"actor.scale", actor<kScale>},
};

}  // namespace

std::span<const NodeImpl> shape_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
