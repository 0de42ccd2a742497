#include "shape/shape_tree.h"

#include "kernel/extrude.h"

#include <algorithm>
#include <cmath>

namespace insula::shape {

using kernel::Mesh;
using kernel::Polygon;
using kernel::Vec2;
using kernel::Vec3;

namespace {

bool finite_ring(const kernel::Ring& ring) {
  return std::all_of(ring.begin(), ring.end(),
                     [](Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

// Index of the outer edge the root scope's x axis follows.
std::size_t alignment_edge(const kernel::Ring& ring, RootAlignment alignment) {
  if (alignment == RootAlignment::kFirstEdge) return 0;
  std::size_t best = 0;
  double best_length = -1;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double l = length(ring[(i + 1) % ring.size()] - ring[i]);
    if (l > best_length + 1e-12) {  // the first of equally long edges wins
      best = i;
      best_length = l;
    }
  }
  return best;
}

kernel::Ring ring_to_scope(const kernel::Ring& ring, const Scope& scope, double elevation) {
  kernel::Ring out;
  out.reserve(ring.size());
  for (Vec2 p : ring) out.push_back(kernel::drop(scope.to_local(kernel::lift(p, elevation))));
  return out;
}

}  // namespace

std::shared_ptr<const Mesh> flat_mesh(const Polygon& outline, kernel::FaceTag tag) {
  auto mesh = std::make_shared<Mesh>();
  std::vector<std::uint32_t> ids;
  for (Vec2 p : outline.outer) ids.push_back(mesh->add_vertex(kernel::lift(p, 0)));
  for (const auto& hole : outline.holes) {
    for (Vec2 p : hole) ids.push_back(mesh->add_vertex(kernel::lift(p, 0)));
  }
  // One n-gon without holes, the triangles of its triangulation with them (kernel extrude.h).
  if (outline.outer.size() >= 3 && !kernel::add_region_faces(*mesh, outline, ids, false, tag)) {
    mesh = std::make_shared<Mesh>();
  }
  return mesh;
}

ShapeId ShapeTree::push(Shape shape) {
  const auto id = static_cast<ShapeId>(shapes_.size());
  shape.id = id;
  shapes_.push_back(std::move(shape));
  return id;
}

RootResult ShapeTree::create_root(const Polygon& footprint, double elevation,
                                  RootAlignment alignment) {
  Polygon polygon = footprint;
  kernel::normalize(polygon);
  if (polygon.outer.size() < 3) return {kNoShape, "footprint has fewer than 3 vertices"};
  if (!finite_ring(polygon.outer) ||
      !std::all_of(polygon.holes.begin(), polygon.holes.end(), finite_ring) ||
      !std::isfinite(elevation)) {
    return {kNoShape, "footprint has a non-finite coordinate"};
  }
  if (!(kernel::area(polygon) > 1e-12)) return {kNoShape, "footprint has zero area"};
  const std::size_t edge = alignment_edge(polygon.outer, alignment);
  const Vec2 a = polygon.outer[edge];
  const Vec2 b = polygon.outer[(edge + 1) % polygon.outer.size()];
  Scope scope;
  if (!make_frame(kernel::lift(b - a, 0), {0, 0, 1}, scope.x, scope.y, scope.z)) {
    return {kNoShape, "footprint's alignment edge has zero length"};
  }
  // Fit the box around the outer ring in the chosen axes.
  std::vector<Vec3> points;
  for (Vec2 p : polygon.outer) points.push_back(kernel::lift(p, elevation));
  scope = fit_scope(points, scope.x, scope.y, scope.z);
  scope.size.z = 0;
  auto outline = std::make_shared<Polygon>();
  outline->outer = ring_to_scope(polygon.outer, scope, elevation);
  for (const auto& hole : polygon.holes) {
    outline->holes.push_back(ring_to_scope(hole, scope, elevation));
  }
  auto mesh = flat_mesh(*outline, {kernel::SemanticClass::kGroundSurface, 0, 0});
  return {add_root(scope, std::move(mesh), std::move(outline)), {}};
}

ShapeId ShapeTree::add_root(const Scope& scope, std::shared_ptr<const Mesh> mesh,
                            std::shared_ptr<const Polygon> outline) {
  Shape s;
  s.scope = scope;
  s.mesh = std::move(mesh);
  s.outline = std::move(outline);
  s.child_index = static_cast<std::uint32_t>(roots_.size());
  s.seed = child_seed(seed_, s.child_index);
  const ShapeId id = push(std::move(s));
  roots_.push_back(id);
  return id;
}

ShapeId ShapeTree::add_child(ShapeId parent, const Scope& scope, std::shared_ptr<const Mesh> mesh,
                             std::shared_ptr<const Polygon> outline) {
  Shape s;
  s.parent = parent;
  s.scope = scope;
  s.mesh = std::move(mesh);
  s.outline = std::move(outline);
  s.child_index = static_cast<std::uint32_t>(shapes_[parent].children.size());
  s.seed = child_seed(shapes_[parent].seed, s.child_index);
  const ShapeId id = push(std::move(s));
  shapes_[parent].children.push_back(id);
  return id;
}

void ShapeTree::truncate(std::size_t size) {
  while (shapes_.size() > size) {
    const Shape& last = shapes_.back();
    if (last.parent == kNoShape) {
      roots_.pop_back();  // roots are pushed in id order, so the last root is this one
    } else {
      shapes_[last.parent].children.pop_back();
    }
    shapes_.pop_back();
  }
}

ShapeId ShapeTree::root_of(ShapeId id) const {
  while (shapes_[id].parent != kNoShape) id = shapes_[id].parent;
  return id;
}

std::vector<ShapeId> ShapeTree::subtree(ShapeId id) const {
  std::vector<ShapeId> out;
  std::vector<ShapeId> stack{id};
  while (!stack.empty()) {
    const ShapeId s = stack.back();
    stack.pop_back();
    out.push_back(s);
    const auto& kids = shapes_[s].children;
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return out;
}

std::vector<ShapeId> ShapeTree::leaves(ShapeId under) const {
  std::vector<ShapeId> out;
  if (under != kNoShape) {
    for (ShapeId s : subtree(under)) {
      if (shapes_[s].children.empty()) out.push_back(s);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  for (const Shape& s : shapes_) {
    if (s.children.empty()) out.push_back(s.id);
  }
  return out;
}

std::vector<ShapeId> ShapeTree::active() const {
  std::vector<ShapeId> out;
  for (const Shape& s : shapes_) {
    if (s.active) out.push_back(s.id);
  }
  return out;
}

std::vector<ShapeId> ShapeTree::all() const {
  std::vector<ShapeId> out(shapes_.size());
  for (ShapeId i = 0; i < out.size(); ++i) out[i] = i;
  return out;
}

SymbolId ShapeTree::intern(std::string_view text) {
  if (auto it = symbol_index_.find(text); it != symbol_index_.end()) return it->second;
  const auto id = static_cast<SymbolId>(symbols_.size());
  symbols_.emplace_back(text);
  symbol_index_.emplace(symbols_.back(), id);
  return id;
}

std::optional<SymbolId> ShapeTree::find_symbol(std::string_view text) const {
  if (auto it = symbol_index_.find(text); it != symbol_index_.end()) return it->second;
  return std::nullopt;
}

void ShapeTree::add_label(ShapeId id, std::string_view label) {
  const SymbolId symbol = intern(label);
  auto& labels = shapes_[id].labels;
  if (std::find(labels.begin(), labels.end(), symbol) == labels.end()) labels.push_back(symbol);
}

bool ShapeTree::has_label(ShapeId id, SymbolId label) const {
  const auto& labels = shapes_[id].labels;
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

bool ShapeTree::has_label(ShapeId id, std::string_view label) const {
  const auto symbol = find_symbol(label);
  return symbol && has_label(id, *symbol);
}

std::vector<std::string_view> ShapeTree::labels(ShapeId id) const {
  std::vector<std::string_view> out;
  for (SymbolId s : shapes_[id].labels) out.push_back(symbols_[s]);
  return out;
}

std::string_view ShapeTree::first_label(ShapeId id) const {
  const auto& labels = shapes_[id].labels;
  return labels.empty() ? std::string_view{} : std::string_view{symbols_[labels.front()]};
}

void ShapeTree::set_attribute(ShapeId id, std::string_view name, Value value) {
  const SymbolId symbol = intern(name);
  for (auto& [key, v] : shapes_[id].attributes) {
    if (key == symbol) {
      v = std::move(value);
      return;
    }
  }
  shapes_[id].attributes.emplace_back(symbol, std::move(value));
}

const Value* ShapeTree::attribute(ShapeId id, std::string_view name) const {
  const auto symbol = find_symbol(name);
  if (!symbol) return nullptr;
  // Inheritance by lookup up the parent chain: no shape copies its parent's map.
  for (ShapeId s = id; s != kNoShape; s = shapes_[s].parent) {
    for (const auto& [key, value] : shapes_[s].attributes) {
      if (key == *symbol) return &value;
    }
  }
  return nullptr;
}

AttributeMap ShapeTree::resolved_attributes(ShapeId id) const {
  AttributeMap out;
  for (ShapeId s = id; s != kNoShape; s = shapes_[s].parent) {
    for (const auto& [key, value] : shapes_[s].attributes) {
      out.emplace(symbols_[key], value);  // emplace keeps the nearer definition
    }
  }
  return out;
}

std::string_view ShapeTree::face_name(std::uint32_t face_id) const {
  if (face_id == 0 || face_id > symbols_.size()) return {};
  return symbols_[face_id - 1];
}

MemoryStats ShapeTree::memory_stats() const {
  MemoryStats m;
  m.shapes = shapes_.size();
  m.shape_bytes = sizeof(Shape) * shapes_.size();
  std::unordered_map<const void*, std::size_t> geometry;
  for (const Shape& s : shapes_) {
    m.heap_bytes += s.labels.capacity() * sizeof(SymbolId) +
                    s.attributes.capacity() * sizeof(s.attributes[0]) +
                    s.children.capacity() * sizeof(ShapeId) + s.regions.capacity() * sizeof(Region);
    if (s.mesh) {
      const Mesh& mesh = *s.mesh;
      std::size_t indices = 0;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) indices += mesh.face(f).size();
      geometry[s.mesh.get()] = sizeof(Mesh) + mesh.vertex_count() * sizeof(Vec3) +
                               indices * sizeof(std::uint32_t) +
                               mesh.face_count() * (sizeof(kernel::FaceTag) + 4);
    }
    if (s.outline) {
      std::size_t points = s.outline->outer.size();
      for (const auto& hole : s.outline->holes) points += hole.size();
      geometry[s.outline.get()] = sizeof(Polygon) + points * sizeof(Vec2);
    }
  }
  for (const auto& [pointer, bytes] : geometry) m.geometry_bytes += bytes;
  return m;
}

}  // namespace insula::shape
