// The public face of the derivation (derive.h): terminal storage, built-in assets, one lot's
// derivation (the engine is in derive_engine.h), default lots, totals, the derivation dump and the
// export scene.
#include "lang/cga/derive.h"

#include <bit>
#include <cmath>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "kernel/shared_meshes.h"
#include "lang/cga/derive_engine.h"
#include "shape/alike_parts.h"
#include "shape/ops.h"

namespace insula::lang::cga {

using kernel::Mesh;
using kernel::Vec3;

namespace {

constexpr std::size_t kFirstBlock = 32;   // records in block 0; block k < 7 holds 32 << k
constexpr std::size_t kLastBlock = 4096;  // records in every block from block 7 on
constexpr std::size_t kGrowing = 4064;    // records in blocks 0..6 (32 + 64 + ... + 2048)

// Block index and offset of record i.
std::pair<std::size_t, std::size_t> locate_record(std::size_t i) {
  if (i < kGrowing) {
    const std::size_t k = static_cast<std::size_t>(std::bit_width(i + kFirstBlock)) - 6;
    return {k, i + kFirstBlock - (kFirstBlock << k)};
  }
  return {7 + (i - kGrowing) / kLastBlock, (i - kGrowing) % kLastBlock};
}

}  // namespace

void TerminalStore::push(const Terminal& t) {
  if (size_ == capacity_) {
    const std::size_t k = blocks_.size();
    const std::size_t n = k < 7 ? kFirstBlock << k : kLastBlock;
    blocks_.emplace_back(static_cast<Terminal*>(::operator new(n * sizeof(Terminal))));
    capacity_ += n;
  }
  const auto [block, offset] = locate_record(size_);
  new (blocks_[block].get() + offset) Terminal(t);
  ++size_;
}

const Terminal& TerminalStore::operator[](std::size_t i) const {
  const auto [block, offset] = locate_record(i);
  return blocks_[block].get()[offset];
}

std::shared_ptr<const Mesh> BuiltinAssets::find(std::string_view name, std::string& error) const {
  if (name == "cube" || name == "builtin:cube") {
    static const std::shared_ptr<const Mesh> cube =
        shape::box_mesh({1, 1, 1}, shape::mass_box_tags());
    return cube;
  }
  if (next_ == nullptr) {
    error = "asset '" + std::string(name) + "' not found (no asset folder; \"cube\" is built in)";
    return nullptr;
  }
  return next_->find(name, error);
}

LotResult derive_lot(const Program& program, const Lot& lot, std::size_t lot_index,
                     const DeriveOptions& options) {
  LotResult out;
  if (!program.uses_occlusion_queries) {
    detail::Engine engine(program, lot, lot_index, options, out);
    engine.run();
    return out;
  }
  // CityEngine's occlusion queries: a first pass in which every query is false makes the shapes
  // the second pass asks about (CGA reference, "Context and occlusion queries").
  std::vector<detail::Occluder> occluders;
  {
    LotResult first;
    detail::Engine engine(program, lot, lot_index, options, first);
    engine.run();
    if (!first.ok) return first;
    occluders = engine.take_occluders();
  }
  detail::Engine engine(program, lot, lot_index, options, out);
  engine.set_occluders(&occluders);
  engine.run();
  return out;
}

Lot default_lot(const Program& program, const DeriveOptions& options) {
  const auto constant_attr = [&](std::string_view name) -> double {
    for (const auto& [n, v] : options.sets) {
      if (n == name && std::holds_alternative<double>(v)) return std::get<double>(v);
    }
    const CAttr* a = program.find_attr(name);
    if (a != nullptr && a->value != kNoExpr && program.nodes[a->value].code == ECode::kConst) {
      const Value& v = program.consts[program.nodes[a->value].a];
      if (std::holds_alternative<double>(v)) return std::get<double>(v);
    }
    return 20.0;
  };
  const double w = constant_attr("lotWidth");
  const double d = constant_attr("lotDepth");
  Lot lot;
  lot.id = "lot_0";
  lot.polygons.push_back({{{0, 0}, {w, 0}, {w, d}, {0, d}}, {}});
  return lot;
}

Totals totals(const Program& program, const std::vector<LotResult>& results) {
  Totals t;
  std::vector<std::uint64_t> counts(program.symbols.size(), 0);
  for (const LotResult& r : results) {
    t.shapes += r.shapes;
    t.terminals += r.terminals;
    t.rule_applications += r.rule_applications;
    for (std::size_t s = 0; s < r.symbol_counts.size() && s < counts.size(); ++s) {
      counts[s] += r.symbol_counts[s];
    }
    for (const auto& [name, e] : r.reports) {
      t.reports[name].sum += e.sum;
      t.reports[name].count += e.count;
    }
  }
  for (std::size_t s = 0; s < counts.size(); ++s) {
    if (counts[s] > 0) t.symbols[program.symbols[s]] = counts[s];
  }
  return t;
}

std::string dump_derivation(const Program& program, const std::vector<LotResult>& results) {
  const Totals t = totals(program, results);
  std::string out = "shapes " + std::to_string(t.shapes) + "\nterminals " +
                    std::to_string(t.terminals) + "\nrule_applications " +
                    std::to_string(t.rule_applications) + "\n";
  for (const auto& [name, count] : t.symbols) {
    out += "symbol " + name + " " + std::to_string(count) + "\n";
  }
  const auto num = [](double v) {
    char text[32];
    const double r = std::round(v * 1e6) / 1e6;
    std::snprintf(text, sizeof text, "%.6f", r == 0 ? 0.0 : r);
    std::string s = text;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
  };
  const auto vec = [&](Vec3 v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); };
  static constexpr const char* kKinds[] = {"none", "box", "rect", "mesh"};
  for (std::size_t i = 0; i < results.size(); ++i) {
    const LotResult& r = results[i];
    out += "lot " + std::to_string(i) + " shapes " + std::to_string(r.shapes) + " terminals " +
           std::to_string(r.terminals) + "\n";
    for (std::size_t k = 0; k < r.terminals_store.size(); ++k) {
      const Terminal& term = r.terminals_store[k];
      const Geometry& g = r.geometry[term.geometry];
      out += "  " + std::string(program.symbol_name(term.symbol)) + " " +
             kKinds[static_cast<int>(g.kind)] + " at " + vec(term.scope.origin) + " size " +
             vec(term.scope.size) + "\n";
    }
  }
  return out;
}

namespace {

std::array<float, 4> rgba_of(const std::string& hex) {
  std::array<float, 4> c{0.8F, 0.8F, 0.8F, 1.0F};
  for (std::size_t k = 0; k * 2 + 1 < hex.size() && k < 4; ++k) {
    c[k] = static_cast<float>(std::stoul(hex.substr(1 + k * 2, 2), nullptr, 16)) / 255.0F;
  }
  return c;
}

}  // namespace

namespace {

// How many terminals of a lot show each shared mesh (i() results, DeriveOptions::share_inserts).
std::map<const Mesh*, int> mesh_uses(const LotResult& r) {
  std::map<const Mesh*, int> uses;
  for (std::size_t t = 0; t < r.terminals_store.size(); ++t) {
    const Geometry& g = r.geometry[r.terminals_store[t].geometry];
    if (g.kind == Geometry::Kind::kMesh && g.mesh && !g.outline) ++uses[g.mesh.get()];
  }
  return uses;
}

// What a terminal's attribute chain gives its part: the user attributes (the nearest setting
// wins), the colour (also an attribute), the colour map and uv set 0. The same for every
// terminal on the chain, so it is read once per chain (a facade's walls share theirs).
struct ChainLook {
  shape::AttributeMap attributes;
  std::optional<shape::UvMap> uv;
  std::string color;
  std::string texture;
  // The scene's material, found at first use (find_material). Plain fields, not an optional:
  // to_scene reads them for every terminal, and a one-byte flag read back with its value stalls.
  bool material_known = false;
  bool recolours = false;  // a colour or colour map: the faces take `material`
  kernel::MaterialId material = 0;
};

// Adds a rectangle terminal (most of a facade: walls, panes, frames) to `mesh` straight in world
// coordinates: the face mesh_to_world(flat_mesh(rectangle_outline(w, h)), scope) makes (turned
// over by a mirroring scope), without the two meshes in between.
void add_world_rectangle(Mesh& mesh, const shape::Scope& scope, kernel::FaceTag tag) {
  const kernel::Transform t = shape::scope_transform(scope);
  const double w = scope.size.x;
  const double h = scope.size.y;
  std::uint32_t v[4];
  std::size_t k = 0;
  for (const kernel::Vec2 p : {kernel::Vec2{0, 0}, {w, 0}, {w, h}, {0, h}}) {
    v[k++] = mesh.add_vertex(kernel::apply_point(t, kernel::lift(p, 0)));
  }
  if (kernel::determinant(t) < 0) {
    mesh.add_face({v[3], v[2], v[1], v[0]}, tag);
  } else {
    mesh.add_face({v[0], v[1], v[2], v[3]}, tag);
  }
}

// The scene's material for a chain's colour and colour map, added at first use; none when the
// chain has neither (its faces keep the geometry's own material).
void find_material(ChainLook& look,
                   std::map<std::pair<std::string, std::string>, kernel::MaterialId>& materials,
                   shape::Scene& scene) {
  if (look.material_known) return;
  look.material_known = true;
  if (look.color.empty() && look.texture.empty()) return;
  const std::string& color = look.color;
  const std::string& texture = look.texture;
  auto [it, inserted] = materials.emplace(std::pair{color, texture}, 0);
  if (inserted) {
    it->second = static_cast<kernel::MaterialId>(scene.materials.size());
    shape::Material material{color.empty() ? texture : color,
                             color.empty() ? std::array<float, 4>{1, 1, 1, 1} : rgba_of(color)};
    if (!texture.empty() && !color.empty()) material.name = color + "_" + texture;
    material.texture = texture;
    scene.materials.push_back(std::move(material));
  }
  look.recolours = true;
  look.material = it->second;
}

// The part of a lot's scene that takes a terminal of symbol `name` with `look`'s attributes when
// alike terminals merge: by attribute chain first, then by value (two chains can give equal
// attributes), shape::AlikeParts deciding.
class ChainParts {
 public:
  explicit ChainParts(std::vector<shape::Part>& parts) : parts_(parts) {}
  shape::Part& part(std::uint32_t symbol, std::uint32_t chain, std::string_view name,
                    const ChainLook& look) {
    const auto [known, added] =
        by_chain_.try_emplace((std::uint64_t{symbol} << 32) | std::uint64_t{chain}, 0);
    if (added) {
      known->second =
          alike_.index(parts_, name, shape::PartKind::kBuildingPart, look.attributes, look.uv);
    }
    return parts_[known->second];
  }

 private:
  std::vector<shape::Part>& parts_;
  std::unordered_map<std::uint64_t, std::size_t> by_chain_;  // (symbol, chain) -> part
  shape::AlikeParts alike_;
};

ChainLook chain_look(const Program& program, const LotResult& r, std::uint32_t chain,
                     const std::string& uv0) {
  ChainLook look;
  for (std::uint32_t n = chain; n != 0; n = r.attr_nodes[n].parent) {
    const AttrNode& node = r.attr_nodes[n];
    if (node.attr == program.color_attr) {
      if (look.color.empty()) look.color = std::get<std::string>(node.value);
      continue;
    }
    const std::string& name = program.attrs[node.attr].name;
    if (name.starts_with("#uv")) {  // texture state, not a user attribute
      if (name == uv0 && !look.attributes.contains(name)) {
        look.uv = shape::decode_uv_map(to_shape(node.value));
        look.attributes.emplace(name, shape::Value{});  // seen: an older set stays hidden
      }
      continue;
    }
    look.attributes.emplace(name, to_shape(node.value));  // nearest wins
  }
  std::erase_if(look.attributes, [](const auto& a) { return a.first.starts_with("#uv"); });
  if (auto it = look.attributes.find(shape::kColormapAttribute); it != look.attributes.end()) {
    if (const auto* text = std::get_if<std::string>(&it->second)) look.texture = *text;
  }
  if (!look.color.empty()) look.attributes["color"] = look.color;
  return look;
}

// to_scene's work; with `consumed`, each lot's records are freed once its building is made.
shape::Scene make_scene(const Program& program, const std::vector<Lot>& lots,
                        const std::vector<LotResult>& results, bool instances, bool merge_alike,
                        std::vector<LotResult>* consumed) {
  shape::Scene scene;
  // By (colour, colour map): a textured material without a colour is white (CityEngine's).
  std::map<std::pair<std::string, std::string>, kernel::MaterialId> materials;
  const std::string uv0 = shape::uv_set_attribute(0);
  kernel::SharedMeshes across_lots;  // lots derive apart: alike meshes of different lots become one
  kernel::Mesh world;                // a terminal's mesh in world coordinates (its storage reused)
  constexpr std::size_t kRecordsAhead = 8;
  for (std::size_t i = 0; i < results.size() && i < lots.size(); ++i) {
    const LotResult& r = results[i];
    const std::map<const Mesh*, int> uses = instances ? mesh_uses(r) : std::map<const Mesh*, int>{};
    // The shared meshes coloured as their terminals show them, by (mesh, material).
    std::map<std::pair<const Mesh*, kernel::MaterialId>, std::shared_ptr<const Mesh>> shared;
    shape::Building building;
    building.id = lots[i].id;
    building.attributes = r.attributes;
    std::unordered_map<std::uint32_t, ChainLook> looks;  // by attribute chain
    ChainParts alike(building.parts);
    for (std::size_t t = 0; t < r.terminals_store.size(); ++t) {
      const Terminal& term = r.terminals_store[t];
      // The records were written while the tile's other lots derived and have left the cache:
      // ask for a later one's lines while this one is converted (perf: the record's load was
      // a tenth of to_scene).
      if (t + kRecordsAhead < r.terminals_store.size()) {
        const auto* ahead = reinterpret_cast<const char*>(&r.terminals_store[t + kRecordsAhead]);
        for (std::size_t line = 0; line < sizeof(Terminal); line += 64) {
          __builtin_prefetch(ahead + line);
        }
      }
      const Geometry& geometry = r.geometry[term.geometry];
      // Rectangles go straight into their part; a mesh is read where it is (no reference counted
      // copies per terminal), boxes are made in the scope first.
      const bool rectangle = geometry.kind == Geometry::Kind::kRect;
      detail::Materialized made;
      const Mesh* mesh = geometry.mesh.get();
      if (geometry.kind != Geometry::Kind::kMesh && !rectangle) {
        made = detail::Engine::materialize(geometry, term.scope.size);
        mesh = made.mesh.get();
      }
      if (!rectangle && (mesh == nullptr || mesh->empty())) continue;
      auto [known, added] = looks.try_emplace(term.attrs);
      if (added) known->second = chain_look(program, r, term.attrs, uv0);
      ChainLook& look = known->second;
      find_material(look, materials, scene);
      const bool recolours = look.recolours;
      const kernel::MaterialId material = look.material;  // 0 when it does not recolour
      const std::string_view name = program.symbol_name(term.symbol);
      const auto use = rectangle ? uses.end() : uses.find(mesh);
      if (use != uses.end() && use->second > 1 && !look.uv) {
        std::shared_ptr<const Mesh>& instanced = shared[{mesh, material}];
        if (!instanced) {
          auto coloured = std::make_shared<Mesh>(*mesh);
          for (std::size_t f = 0; material != 0 && f < coloured->face_count(); ++f) {
            coloured->tag(f).material = material;
          }
          instanced = across_lots.share(std::move(coloured));
        }
        shape::Part& part = building.parts.emplace_back();
        part.name = std::string(name);
        part.attributes = look.attributes;
        part.instance_of = instanced;
        part.instance_transform = shape::scope_transform(term.scope);
        continue;
      }
      shape::Part* part = nullptr;
      if (merge_alike) {
        part = &alike.part(term.symbol, term.attrs, name, look);
      } else {
        part = &building.parts.emplace_back();
        part->name = std::string(name);
        part->attributes = look.attributes;
        part->uv = look.uv;
      }
      const std::size_t first_face = part->mesh.face_count();
      if (rectangle) {
        add_world_rectangle(part->mesh, term.scope, geometry.tag);
      } else {
        shape::mesh_to_world(*mesh, term.scope, world);
        part->mesh.append(world);
      }
      for (std::size_t f = first_face; recolours && f < part->mesh.face_count(); ++f) {
        part->mesh.tag(f).material = material;
      }
    }
    if (!building.parts.empty()) scene.buildings.push_back(std::move(building));
    if (consumed != nullptr) (*consumed)[i] = LotResult();
  }
  return scene;
}

}  // namespace

shape::Scene to_scene(const Program& program, const std::vector<Lot>& lots,
                      const std::vector<LotResult>& results, bool instances, bool merge_alike) {
  return make_scene(program, lots, results, instances, merge_alike, nullptr);
}

shape::Scene to_scene(const Program& program, const std::vector<Lot>& lots,
                      std::vector<LotResult>&& results, bool instances, bool merge_alike) {
  shape::Scene scene = make_scene(program, lots, results, instances, merge_alike, &results);
  results.clear();
  return scene;
}

}  // namespace insula::lang::cga
