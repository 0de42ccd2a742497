// Entity creation (graph-format.md §11 "Entity creation"): one round as a source, or one round
// per impulse entity (what is made then descends from the impulse and inherits its attributes).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/tag_numbers.h"
#include "lang/graph/executor.h"
#include "lang/graph/nodes.h"
#include "lang/graph/shape_entities.h"

namespace insula::lang::graph {
namespace {

kernel::Vec3 vec(const Value& v) {
  return v.type() == ValueType::kVec3 ? v.vec() : kernel::Vec3{};
}

void emit_footprint(NodeContext& c, std::size_t round, std::uint32_t position,
                    const kernel::Polygon& footprint, double elevation) {
  std::string error;
  const std::optional<EntityId> e =
      footprint_entity(c, round, position, footprint, elevation, error);
  if (!e) c.error("cannot make a shape: " + error);
  c.emit(c.output_port("out"), *e);
}

void rectangle(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const double w = c.param(r, "width").number();
    const double d = c.param(r, "depth").number();
    const kernel::Vec3 o = vec(c.param(r, "origin"));
    emit_footprint(c, r, 0, {{{o.x, o.y}, {o.x + w, o.y}, {o.x + w, o.y + d}, {o.x, o.y + d}}, {}},
                   o.z);
  }
}

void circle(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const double radius = c.param(r, "radius").number();
    const std::int64_t segments = std::max<std::int64_t>(3, c.param(r, "segments").integer());
    const kernel::Vec3 center = vec(c.param(r, "center"));
    kernel::Polygon p;
    for (std::int64_t i = 0; i < segments; ++i) {
      const double a =
          2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(segments);
      p.outer.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
    }
    emit_footprint(c, r, 0, p, center.z);
  }
}

void polygon(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const Value vertices = c.param(r, "vertices");
    kernel::Polygon p;
    double z = 0;
    for (const Value& v : vertices.list()) {
      std::vector<double> xyz;
      if (v.type() == ValueType::kVec3) xyz = {v.vec().x, v.vec().y, v.vec().z};
      if (v.type() == ValueType::kList) {
        for (const Value& k : v.list()) {
          if (k.is_number()) xyz.push_back(k.number());
        }
      }
      if (xyz.size() < 2 || xyz.size() > 3) c.error("a vertex must be [x, y] or [x, y, z]");
      p.outer.push_back({xyz[0], xyz[1]});
      if (xyz.size() == 3) z = xyz[2];
    }
    if (p.outer.size() < 3) c.error("a polygon needs at least 3 vertices");
    emit_footprint(c, r, 0, p, z);
  }
}

void grid(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::int64_t columns = c.param(r, "columns").integer();
    const std::int64_t rows = c.param(r, "rows").integer();
    const double w = c.param(r, "cell_width").number();
    const double d = c.param(r, "cell_depth").number();
    const double gap = c.param(r, "gap").number();
    const kernel::Vec3 o = vec(c.param(r, "origin"));
    std::uint32_t index = 0;
    for (std::int64_t iy = 0; iy < rows; ++iy) {
      for (std::int64_t ix = 0; ix < columns; ++ix) {
        const double x = o.x + static_cast<double>(ix) * (w + gap);
        const double y = o.y + static_cast<double>(iy) * (d + gap);
        std::string error;
        const std::optional<EntityId> e = footprint_entity(
            c, r, index, {{{x, y}, {x + w, y}, {x + w, y + d}, {x, y + d}}, {}}, o.z, error);
        if (!e) c.error("cannot make a grid cell: " + error);
        c.write(*e, "index", Value(std::int64_t{index}));
        c.write(*e, "ix", Value(ix));
        c.write(*e, "iy", Value(iy));
        c.emit(c.output_port("out"), *e);
        ++index;
      }
    }
  }
}

void points(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const Value list = c.param(r, "points");
    std::uint32_t index = 0;
    for (const Value& v : list.list()) {
      const std::optional<Value> p = convert(v, ValueType::kVec3);
      if (!p) c.error("a point must be [x, y, z]; got " + to_string(v));
      const EntityId e = c.create(r, EntityType::kPoint, index);
      c.entities()[e].position = p->vec();
      c.write(e, "index", Value(std::int64_t{index}));
      c.emit(c.output_port("out"), e);
      ++index;
    }
  }
}

void entity(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::int64_t count = c.param(r, "count").integer();
    for (std::int64_t i = 0; i < count; ++i) {
      const EntityId e = c.create(r, EntityType::kEntity, static_cast<std::uint32_t>(i));
      c.write(e, "index", Value(i));
      c.emit(c.output_port("out"), e);
    }
  }
}

// GeoJSON lots: properties become the declared attributes of the same name (W030 for others).
void lots(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::string file = c.param(r, "file").text();
    std::vector<LotInput> lots;
    std::string error;
    if (!c.options().lots) c.error("no lots: give --lot LOTS.geojson or the parameter 'file'");
    if (!c.options().lots(file, lots, error)) c.error(error);
    // The attributes the node's `index` writes: a lot property of that name is overwritten by the
    // lot's number anyway, so it is left to it without a warning (a graph numbering its lots in
    // `building` would otherwise warn on every OpenStreetMap lot, whose tag `building=yes` it is).
    std::vector<std::string_view> numbered;
    for (const AttributeMapping& m : c.checked().node->attributes) {
      if (m.node_attribute == "index") numbered.push_back(m.to);
    }
    std::uint32_t index = 0;
    for (const LotInput& lot : lots) {
      const std::uint32_t number = lot.number.value_or(index);
      std::string why;
      const std::optional<EntityId> e = footprint_entity(c, r, number, lot.footprint, 0, why);
      if (!e) {
        c.warning("W030", "lot " + (lot.id.empty() ? std::to_string(number) : "'" + lot.id + "'") +
                              ": " + why + "; skipped");
        ++index;
        continue;
      }
      for (const auto& [property, value] : lot.properties) {
        // OpenStreetMap's `building:levels` is attribute building_levels when that is declared
        // and no property of that very name is given (docs/graph-executor.md, create.lots).
        std::string name = property;
        if (!c.declared_type(name)) {
          std::string spelled = base::identifier_spelling(property);
          if (c.declared_type(spelled) && !lot.properties.contains(spelled))
            name = std::move(spelled);
        }
        if (std::find(numbered.begin(), numbered.end(), name) != numbered.end()) continue;
        const std::optional<ValueType> type = c.declared_type(name);
        if (!type) {
          c.warning("W030", "GeoJSON property '" + name + "' is not a declared attribute; ignored");
          continue;
        }
        std::optional<Value> given;
        if (const auto* d = std::get_if<double>(&value)) given = Value(*d);
        if (const auto* b = std::get_if<bool>(&value)) given = Value(*b);
        if (const auto* s = std::get_if<std::string>(&value)) given = Value(*s);
        if (!given) continue;
        // OpenStreetMap tags are text: a number or integer attribute takes "12", "12 m" or "66'"
        // as that length in metres (base/tag_numbers.h), as mass models and CGA attrs do.
        if (given->type() == ValueType::kString &&
            (*type == ValueType::kNumber || *type == ValueType::kInteger)) {
          if (const std::optional<double> length = base::parse_length(given->text())) {
            given = Value(*length);
          }
        }
        // Real data does not follow the graph's types (OpenStreetMap's `building=kindergarten`
        // for an integer `building`): a value that does not fit is left out, not a failed run.
        if (!convert(*given, *type)) {
          c.warning("W030", "GeoJSON property '" + name + "' is not " +
                                std::string(value_type_name(*type)) + " (" + to_string(*given) +
                                "); ignored");
          continue;
        }
        c.set_attribute(*e, name, *given);
      }
      c.write(*e, "index", Value(std::int64_t{number}));
      c.record_lot(*e, lot.id.empty() ? "lot_" + std::to_string(number) : lot.id);
      c.emit(c.output_port("out"), *e);
      ++index;
    }
  }
}

constexpr NodeImpl kNodes[] = {
    {"create.rectangle", rectangle}, {"create.circle", circle}, {"create.polygon", polygon},
    {"create.grid", grid},           {"create.points", points}, {"create.entity", entity},
    {"create.lots", lots},
};

}  // namespace

std::span<const NodeImpl> creation_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
