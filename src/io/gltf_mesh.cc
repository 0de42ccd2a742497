#include "io/gltf_mesh.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <variant>

#include "kernel/transform.h"
#include "kernel/uv.h"

namespace insula::io::gltf {
namespace {

// The texture size of a part in meters, or 0 for none (solid_geometry's attribute).
double uv_scale(const shape::Part& part) {
  auto it = part.attributes.find("uv_scale");
  if (it == part.attributes.end()) return 0;
  const auto* v = std::get_if<double>(&it->second);
  return v != nullptr && *v > 0 ? *v : 0;
}

std::array<double, 3> y_up(kernel::Vec3 p) {
  return {p.x, p.z, -p.y};
}

std::int8_t normal_byte(float c) {
  return static_cast<std::int8_t>(round_half_away(std::clamp(c, -1.0F, 1.0F) * 127.0F));
}

constexpr std::uint32_t kNone = ~0U;

}  // namespace

MeshViews MeshViews::create(Buffers& buffers) {
  MeshViews views{};
  views.quantized_positions = buffers.add_view(ViewKind::kVertices, 8);
  views.float_positions = buffers.add_view(ViewKind::kVertices, 12);
  views.quantized_normals = buffers.add_view(ViewKind::kVertices, 4);
  views.float_normals = buffers.add_view(ViewKind::kVertices, 12);
  views.uvs = buffers.add_view(ViewKind::kVertices, 8);
  views.features = buffers.add_view(ViewKind::kVertices, 4);
  views.short_indices = buffers.add_view(ViewKind::kIndices, 2);
  views.int_indices = buffers.add_view(ViewKind::kIndices, 4);
  return views;
}

MeshAssembler::MeshAssembler(const MaterialTable& materials, std::vector<bool> material_textured)
    : materials_(materials), material_textured_(std::move(material_textured)) {
  clear();
}

void MeshAssembler::start(const MeshOptions& options) {
  options_ = options;
  clear();
}

void MeshAssembler::clear() {
  positions_.clear();
  face_normals_.clear();
  vertices_.clear();
  for (auto& [material, list] : indices_by_material_) {
    list.clear();
    spare_lists_.push_back(std::move(list));
  }
  indices_by_material_.clear();
  has_uv_ = false;
  bounds_ = Bounds{};
  scope_feature_set_ = false;
  begin_scope();
}

void MeshAssembler::reserve(std::size_t vertices, std::size_t corners, std::size_t faces) {
  positions_.reserve(positions_.size() + vertices);
  vertices_.reserve(vertices_.size() + corners);
  face_normals_.reserve(face_normals_.size() + faces);
}

// A new scope for positions: no position entered before is found again.
void MeshAssembler::begin_scope() {
  if (scope_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(slots_.begin(), slots_.end(), Slot{0, 0});
    scope_ = 0;
  }
  ++scope_;
  scope_begin_ = static_cast<std::uint32_t>(positions_.size());
}

void MeshAssembler::add(const kernel::Mesh& mesh, const shape::Part& part, std::uint32_t feature,
                        bool instance_frame) {
  part_ = &part;
  instance_frame_ = instance_frame;
  uv_scale_ = uv_scale(part);
  // Vertices of different features are never one when features are written: each run of one
  // feature (a feature's parts come together) looks positions up in a scope of its own.
  if (options_.with_features && (!scope_feature_set_ || feature != scope_feature_)) {
    begin_scope();
    scope_feature_set_ = true;
    scope_feature_ = feature;
  }
  feature_ = feature;
  weld_.run(mesh, options_.quantize ? kQuantizationStep : 0);
  position_of_.assign(mesh.vertex_count(), kNone);
  // Faces grouped by material, in mesh order within each.
  faces_by_material_.clear();
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    faces_by_material_.emplace_back(materials_.index(mesh.tag(f)), f);
  }
  std::sort(faces_by_material_.begin(), faces_by_material_.end());  // (material, face): stable
  std::vector<std::uint32_t>* indices = nullptr;
  std::uint32_t current = std::numeric_limits<std::uint32_t>::max();
  for (const auto& [material, face] : faces_by_material_) {
    if (material != current) {
      current = material;
      auto it = std::find_if(indices_by_material_.begin(), indices_by_material_.end(),
                             [&current](const auto& entry) { return entry.first == current; });
      if (it == indices_by_material_.end()) {
        indices_by_material_.emplace_back(material, spare_list());
        it = indices_by_material_.end() - 1;
      }
      indices = &it->second;
      fit_uv_ = material_textured_[material];
    }
    add_face(mesh, face, *indices);
  }
  // A material all of whose faces were degenerate gets no primitive.
  std::erase_if(indices_by_material_, [this](auto& entry) {
    if (!entry.second.empty()) return false;
    spare_lists_.push_back(std::move(entry.second));
    return true;
  });
}

// An empty index list, one that served an earlier mesh when there is one: growing a list anew
// for every material of every building cost more than filling it.
std::vector<std::uint32_t> MeshAssembler::spare_list() {
  if (spare_lists_.empty()) return {};
  std::vector<std::uint32_t> list = std::move(spare_lists_.back());
  spare_lists_.pop_back();
  return list;
}

// Flat shading: the face's corners become vertices of their own, all carrying the face normal.
// Where the weld merges vertices (float32_weld.h) the face's triangles and corners come from it.
void MeshAssembler::add_face(const kernel::Mesh& mesh, std::size_t face,
                             std::vector<std::uint32_t>& indices) {
  const kernel::Vec3 newell = kernel::face_normal(mesh, face);
  triangles_.clear();
  if (!weld_.active()) {
    if (!triangulator_.triangulate(mesh, face, newell, triangles_)) return;
    add_corners(mesh, mesh.face(face), newell, indices);
    return;
  }
  corners_.clear();
  for (const auto& triangle : weld_.triangles(face)) {
    CornerTriangle t{};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto it = std::find(corners_.begin(), corners_.end(), triangle[k]);
      t[k] = static_cast<std::uint32_t>(it - corners_.begin());
      if (it == corners_.end()) corners_.push_back(triangle[k]);
    }
    triangles_.push_back(t);
  }
  add_corners(mesh, corners_, newell, indices);
}

void MeshAssembler::add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                                kernel::Vec3 newell, std::vector<std::uint32_t>& indices) {
  const std::array<double, 3> n = y_up(kernel::normalized(newell));
  const auto face = static_cast<std::uint32_t>(face_normals_.size());
  // Written in place (zeroed, so the padding byte is 0): built apart, its bytes written one by
  // one and copied in as a whole stalled the copy.
  FaceNormal& normal = face_normals_.emplace_back();
  for (std::size_t k = 0; k < 3; ++k) {
    normal.normal[k] = static_cast<float>(n[k]);
    normal.bytes[k] = normal_byte(normal.normal[k]);
  }
  corner_uvs_.assign(loop.size(), {0.0F, 0.0F});
  if (part_->uv) {
    // The part's map is over world positions; an instance's mesh is placed first. glTF's v runs
    // down the image, CityEngine's up.
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const kernel::Vec3 p = mesh.position(loop[i]);
      const kernel::Vec2 t =
          part_->uv->at(instance_frame_ ? kernel::apply_point(part_->instance_transform, p) : p);
      corner_uvs_[i] = {static_cast<float>(t.x), static_cast<float>(1 - t.y)};
    }
    has_uv_ = true;
  } else if (fit_uv_) {
    fit_uvs(mesh, loop, newell);
    has_uv_ = true;
  } else if (uv_scale_ > 0) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const kernel::Vec2 t = kernel::planar_uv(mesh.position(loop[i]), newell, uv_scale_);
      corner_uvs_[i] = {static_cast<float>(t.x), static_cast<float>(t.y)};
    }
    has_uv_ = true;
  }
  corner_vertices_.resize(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::uint32_t position = position_of(mesh, weld_.representative(loop[i]));
    corner_vertices_[i] = vertex_at(position, face, corner_uvs_[i]);
  }
  for (const CornerTriangle& triangle : triangles_) {
    for (std::uint32_t corner : triangle) indices.push_back(corner_vertices_[corner]);
  }
}

// The entry in positions_ of the part's vertex `vertex` (a weld representative), looked up in
// the scope on its first use by a corner.
std::uint32_t MeshAssembler::position_of(const kernel::Mesh& mesh, std::uint32_t vertex) {
  std::uint32_t& entry = position_of_[vertex];
  if (entry != kNone) return entry;
  constexpr double kStepsPerMeter = 1 / kQuantizationStep;  // a power of two
  // Past 2^62 steps (or not finite) a position has no grid point: its mesh stays float.
  constexpr double kGridLimit = 4.6e18;
  const std::array<double, 3> p = y_up(mesh.position(vertex));
  Position position{};
  position.on_grid = options_.quantize;
  for (std::size_t k = 0; k < 3; ++k) {
    position.coordinates[k] = static_cast<float>(p[k]);
    const double steps = p[k] * kStepsPerMeter;  // exact, as the division
    position.on_grid = position.on_grid && std::abs(steps) < kGridLimit;
    if (position.on_grid) position.grid[k] = round_half_away(steps);
  }
  position.first_vertex = kNone;
  entry = find_position(position);
  return entry;
}

namespace {

// What makes two positions one: their grid point where positions may be quantized and both have
// one (the weld made vertices on one grid point one vertex, so they share their float32 too),
// else their float32 coordinates' bits.
bool same_position(const std::array<std::int64_t, 3>& grid, const Float3& coordinates, bool on_grid,
                   const std::array<std::int64_t, 3>& other_grid, const Float3& other_coordinates,
                   bool other_on_grid) {
  if (on_grid != other_on_grid) return false;
  if (on_grid) return grid == other_grid;
  return std::memcmp(coordinates.data(), other_coordinates.data(), sizeof coordinates) == 0;
}

std::uint64_t position_hash(const std::array<std::int64_t, 3>& grid, const Float3& coordinates,
                            bool on_grid) {
  std::array<std::uint64_t, 3> words{};
  if (on_grid) {
    for (std::size_t k = 0; k < 3; ++k) words[k] = static_cast<std::uint64_t>(grid[k]);
  } else {
    for (std::size_t k = 0; k < 3; ++k) words[k] = std::bit_cast<std::uint32_t>(coordinates[k]);
  }
  // Each word times a constant of its own, summed: the products do not wait for each other.
  std::uint64_t hash = (words[0] + 1) * 0x9E3779B97F4A7C15ULL +
                       (words[1] + 1) * 0xC2B2AE3D27D4EB4FULL +
                       (words[2] + 1) * 0x165667B19E3779F9ULL;
  return hash ^ (hash >> 29U);
}

}  // namespace

// The scope's entry alike `position`, entered (with its bounds) when there is none.
std::uint32_t MeshAssembler::find_position(const Position& position) {
  if (2 * (positions_.size() - scope_begin_ + 1) > slots_.size()) grow_position_table();
  const std::size_t mask = slots_.size() - 1;
  const std::uint64_t hash = position_hash(position.grid, position.coordinates, position.on_grid);
  for (std::size_t slot = (hash >> 32U) & mask;; slot = (slot + 1) & mask) {
    Slot& entry = slots_[slot];
    if (entry.scope != scope_) {
      entry = {static_cast<std::uint32_t>(positions_.size()), scope_};
      positions_.push_back(position);
      bounds_.add(position);
      return entry.position;
    }
    const Position& other = positions_[entry.position];
    if (same_position(position.grid, position.coordinates, position.on_grid, other.grid,
                      other.coordinates, other.on_grid)) {
      return entry.position;
    }
  }
}

// Twice the slots, the scope's positions entered again.
void MeshAssembler::grow_position_table() {
  slots_.assign(std::max<std::size_t>(64, 2 * slots_.size()), Slot{0, 0});
  if (scope_ == 0) scope_ = 1;  // 0 marks the new slots free
  const std::size_t mask = slots_.size() - 1;
  for (auto p = scope_begin_; p < positions_.size(); ++p) {
    const Position& position = positions_[p];
    const std::uint64_t hash = position_hash(position.grid, position.coordinates, position.on_grid);
    std::size_t slot = (hash >> 32U) & mask;
    while (slots_[slot].scope == scope_) slot = (slot + 1) & mask;
    slots_[slot] = {p, scope_};
  }
}

bool MeshAssembler::same_normal(std::uint32_t face, std::uint32_t other) const {
  const FaceNormal& a = face_normals_[face];
  const FaceNormal& b = face_normals_[other];
  if (options_.quantize) return std::memcmp(a.bytes.data(), b.bytes.data(), a.bytes.size()) == 0;
  return std::memcmp(a.normal.data(), b.normal.data(), sizeof a.normal) == 0;
}

// The vertex at `position` with face `face`'s normal and `uv`: one made by an earlier corner
// alike in all three (and so in every written byte), or a new one.
std::uint32_t MeshAssembler::vertex_at(std::uint32_t position, std::uint32_t face,
                                       std::array<float, 2> uv) {
  Position& at = positions_[position];
  for (std::uint32_t v = at.first_vertex; v != kNone; v = vertices_[v].next) {
    const Vertex& vertex = vertices_[v];
    if (std::bit_cast<std::uint64_t>(vertex.uv) == std::bit_cast<std::uint64_t>(uv) &&
        (vertex.face == face || same_normal(vertex.face, face))) {
      return v;
    }
  }
  const auto v = static_cast<std::uint32_t>(vertices_.size());
  vertices_.push_back(Vertex{position, face, uv, feature_, at.first_vertex});
  at.first_vertex = v;
  return v;
}
// A textured face shows its image once: the face's planar coordinates (kernel::planar_uv, u to the
// right and v up seen from outside) scaled to its extent, v flipped because glTF's (0, 0) is the
// image's top-left corner. So text reads the right way round on walls, roofs and floors.
void MeshAssembler::fit_uvs(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                            kernel::Vec3 newell) {
  kernel::Vec2 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  kernel::Vec2 high{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  face_uvs_.clear();
  for (std::uint32_t vertex : loop) {
    const kernel::Vec2 t = kernel::planar_uv(mesh.position(vertex), newell, 1);
    low = {std::min(low.x, t.x), std::min(low.y, t.y)};
    high = {std::max(high.x, t.x), std::max(high.y, t.y)};
    face_uvs_.push_back(t);
  }
  const auto unit = [](double v, double from, double to) {
    return to > from ? (v - from) / (to - from) : 0.0;
  };
  for (std::size_t i = 0; i < face_uvs_.size(); ++i) {
    corner_uvs_[i] = {static_cast<float>(unit(face_uvs_[i].x, low.x, high.x)),
                      static_cast<float>(1 - unit(face_uvs_[i].y, low.y, high.y))};
  }
}

// The materials' triangles one after the other (materials in table order): ends_ marks each
// run's end in indices_.
void MeshAssembler::gather_indices() {
  std::sort(indices_by_material_.begin(), indices_by_material_.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  ends_.clear();
  std::size_t end = 0;
  for (const auto& [material, list] : indices_by_material_) {
    end += list.size();
    ends_.push_back(end);
  }
  indices_.resize(end);  // filled by merge_and_order, numbered as they are copied
}

void MeshAssembler::Bounds::add(const Position& position) {
  on_grid = on_grid && position.on_grid;
  for (std::size_t k = 0; k < 3; ++k) {
    if (position.on_grid) {
      low[k] = std::min(low[k], position.grid[k]);
      high[k] = std::max(high[k], position.grid[k]);
    }
    const double c = position.coordinates[k];
    min[k] = std::min(min[k], c);
    max[k] = std::max(max[k], c);
  }
}

// Whether the mesh's extent on the quantization grid fits 16 bits; sets the record's offset and
// scale (and grid_low_) when it does, and its POSITION bounds either way. The bounds are those of
// every position a corner uses.
void MeshAssembler::quantize(MeshRecord& record) {
  record.quantized = options_.quantize && bounds_.on_grid && !vertices_.empty();
  for (std::size_t k = 0; k < 3 && record.quantized; ++k)
    record.quantized = bounds_.high[k] - bounds_.low[k] <= 65535;
  if (record.quantized) {
    record.scale = kQuantizationStep;
    grid_low_ = bounds_.low;
    for (std::size_t k = 0; k < 3; ++k) {
      record.offset[k] = static_cast<double>(bounds_.low[k]) * kQuantizationStep;
      record.min[k] = 0;
      record.max[k] = static_cast<double>(bounds_.high[k] - bounds_.low[k]);
    }
    return;
  }
  record.min = bounds_.min;
  record.max = bounds_.max;
}

// Whether a FIFO cache of kCacheSize vertices (meshopt's model of a GPU's) loads each vertex of
// `run` once: the usual case with flat shading, where a face's triangles come together and share
// only its corners. No order can do better, so the run is left as it is (and meshopt's optimiser,
// which costs more than the rest of a small mesh, is not run).
bool MeshAssembler::loads_each_once(std::span<const unsigned int> run) {
  constexpr unsigned int kCacheSize = 16;
  unsigned int loads = 0;
  bool once = true;
  for (unsigned int v : run) {
    if (loaded_at_[v] == ~0U) {
      loaded_at_[v] = loads++;
    } else if (loads - loaded_at_[v] > kCacheSize) {
      once = false;  // evicted, and loaded again
      break;
    }
  }
  for (unsigned int v : run) loaded_at_[v] = ~0U;  // a vertex may be in another material's run
  return once;
}

// Optimises one run of triangles for the vertex cache over the vertices it uses only: meshopt
// sizes its work by the vertex count it is given, so a building of thousands of parts would
// otherwise cost parts x vertices.
bool MeshAssembler::optimize_run(std::span<unsigned int> run) {
  if (loads_each_once(run)) return false;
  if (local_of_.empty()) local_of_.assign(loaded_at_.size(), ~0U);
  global_of_.clear();
  for (unsigned int& v : run) {
    if (local_of_[v] == ~0U) {
      local_of_[v] = static_cast<unsigned int>(global_of_.size());
      global_of_.push_back(v);
    }
    v = local_of_[v];
  }
  meshopt_optimizeVertexCache(run.data(), run.data(), run.size(), global_of_.size());
  for (unsigned int& v : run) v = global_of_[v];
  for (unsigned int v : global_of_) local_of_[v] = ~0U;
  return true;
}

// Sorts the triangles of `indices` by the feature of their first corner (stably; they usually
// come sorted, part after part), then optimises each feature's run for the vertex cache. Returns
// whether it changed the order of any triangle or index.
bool MeshAssembler::order_by_feature(std::span<unsigned int> indices) {
  const std::vector<std::uint32_t>& features = vertex_features_;
  const std::size_t triangles = indices.size() / 3;
  const auto feature = [&](std::size_t t) { return features[indices[3 * t]]; };
  bool sorted = true;
  for (std::size_t t = 1; t < triangles && sorted; ++t) sorted = feature(t - 1) <= feature(t);
  if (!sorted) {
    sorted_triangles_.resize(triangles);
    std::memcpy(sorted_triangles_.data(), indices.data(), indices.size() * sizeof(unsigned int));
    std::stable_sort(
        sorted_triangles_.begin(), sorted_triangles_.end(),
        [&features](const auto& a, const auto& b) { return features[a[0]] < features[b[0]]; });
    std::memcpy(indices.data(), sorted_triangles_.data(), indices.size() * sizeof(unsigned int));
  }
  bool reordered = !sorted;
  for (std::size_t begin = 0; begin < triangles;) {
    std::size_t end = begin + 1;
    while (end < triangles && feature(end) == feature(begin)) ++end;
    reordered = optimize_run(indices.subspan(3 * begin, 3 * (end - begin))) || reordered;
    begin = end;
  }
  return reordered;
}

// Vertices numbered in order of first use by the indices (as meshopt_generateVertexRemap does);
// triangles part by part (a part's faces lie together, and the feature ids then come in runs,
// which EXT_meshopt_compression stores in almost nothing), each part's in the order that suits the
// vertex cache; then vertices in the order of first use, for fetch, which is already theirs unless
// a run was reordered. Leaves indices_ and vertex_features_ over the written vertices, and
// vertex_of_ naming the Vertex each writes; returns their count.
std::size_t MeshAssembler::number_and_order() {
  number_of_.assign(vertices_.size(), kNone);
  vertex_of_.clear();
  vertex_features_.clear();
  unsigned int* out = indices_.data();
  for (const auto& [material, list] : indices_by_material_) {
    for (const std::uint32_t index : list) {
      unsigned int& number = number_of_[index];
      if (number == kNone) {
        number = static_cast<unsigned int>(vertex_of_.size());
        vertex_of_.push_back(index);
        vertex_features_.push_back(vertices_[index].feature);
      }
      *out++ = number;
    }
  }
  const std::size_t count = vertex_of_.size();
  local_of_.clear();  // sized by optimize_run when a run needs it
  loaded_at_.assign(count, kNone);
  bool reordered = false;
  std::size_t begin = 0;
  for (std::size_t end : ends_) {
    reordered = order_by_feature(std::span(indices_).subspan(begin, end - begin)) || reordered;
    begin = end;
  }
  if (reordered) number_for_fetch();
  return count;
}

// Renumbers the vertices in order of first use by the reordered indices. Every merged vertex is
// used (meshopt numbers only those the indices name).
void MeshAssembler::number_for_fetch() {
  const std::size_t count = vertex_of_.size();
  fetch_.assign(count, kNone);
  unsigned int next = 0;
  for (unsigned int& index : indices_) {
    if (fetch_[index] == kNone) fetch_[index] = next++;
    index = fetch_[index];
  }
  moved_vertices_.resize(count);
  moved_features_.resize(count);
  for (std::size_t w = 0; w < count; ++w) {
    moved_vertices_[fetch_[w]] = vertex_of_[w];
    moved_features_[fetch_[w]] = vertex_features_[w];
  }
  std::swap(vertex_of_, moved_vertices_);
  std::swap(vertex_features_, moved_features_);
}

// The written vertices' attributes, each appended to its view in one pass over the vertices:
// positions (grid steps from the mesh's low corner, or float32), normals (bytes, or float32),
// uvs when some face has them, feature ids when written.
void MeshAssembler::write_attributes(Buffers& buffers, const MeshViews& views, std::size_t count,
                                     MeshRecord& record) {
  const bool quantized = record.quantized;
  const bool byte_normals = options_.quantize;
  const bool with_features = options_.with_features;
  const bool float_features = options_.feature_component == Component::kFloat;
  // Room for `count` values of `size` bytes at the end of `view`; the accessor over them.
  const auto column = [&](std::uint32_t view, std::size_t size, Component component,
                          std::string_view type, bool normalized, std::uint32_t& accessor) {
    std::string& data = buffers.data(view);
    const std::size_t offset = data.size();
    data.resize(offset + count * size);
    accessor = buffers.add_accessor(
        Accessor{view, offset, component, count, type, normalized, std::nullopt, std::nullopt});
    return data.data() + offset;
  };
  char* positions = column(
      quantized ? views.quantized_positions : views.float_positions, quantized ? 8 : 12,
      quantized ? Component::kUnsignedShort : Component::kFloat, "VEC3", false, record.position);
  buffers.set_bounds(record.position, {record.min, record.max});
  char* normals = column(byte_normals ? views.quantized_normals : views.float_normals,
                         byte_normals ? 4 : 12, byte_normals ? Component::kByte : Component::kFloat,
                         "VEC3", byte_normals, record.normal);
  char* uvs = nullptr;
  if (has_uv_) uvs = column(views.uvs, 8, Component::kFloat, "VEC2", false, record.uv.emplace());
  char* features = nullptr;
  if (with_features) {
    features = column(views.features, 4, options_.feature_component, "SCALAR", false,
                      record.feature.emplace());
  }
  for (std::size_t w = 0; w < count; ++w) {
    const Vertex& vertex = vertices_[vertex_of_[w]];
    const Position& position = positions_[vertex.position];
    if (quantized) {
      for (std::size_t k = 0; k < 3; ++k) {
        put_value(positions, static_cast<std::uint16_t>(position.grid[k] - grid_low_[k]));
      }
      put_value(positions, std::uint16_t{0});
    } else {
      for (float c : position.coordinates) put_value(positions, c);
    }
    const FaceNormal& normal = face_normals_[vertex.face];
    if (byte_normals) {
      for (std::int8_t c : normal.bytes) put_value(normals, c);  // the fourth byte is 0
    } else {
      for (float c : normal.normal) put_value(normals, c);
    }
    if (uvs != nullptr) {
      for (float c : vertex.uv) put_value(uvs, c);
    }
    if (features != nullptr && float_features) {
      put_value(features, static_cast<float>(vertex.feature));
    } else if (features != nullptr) {
      put_value(features, static_cast<std::uint16_t>(vertex.feature));
      put_value(features, std::uint16_t{0});
    }
  }
}

// One primitive per material over the shared attributes, indices 16-bit when they fit.
void MeshAssembler::write_primitives(Buffers& buffers, const MeshViews& views, std::size_t count,
                                     MeshRecord& record) {
  const bool short_indices = count <= 65535;  // 65535 itself is not a valid index (glTF 3.7.2.1)
  const std::uint32_t view = short_indices ? views.short_indices : views.int_indices;
  std::string& data = buffers.data(view);
  const std::size_t first = data.size();
  data.resize(first + indices_.size() * (short_indices ? 2 : 4));
  char* at = data.data() + first;
  std::size_t begin = 0;
  for (std::size_t m = 0; m < ends_.size(); ++m) {
    const std::size_t offset = static_cast<std::size_t>(at - data.data());
    for (std::size_t i = begin; i < ends_[m]; ++i) {
      if (short_indices) {
        put_value(at, static_cast<std::uint16_t>(indices_[i]));
      } else {
        put_value(at, static_cast<std::uint32_t>(indices_[i]));
      }
    }
    // A triangle's corners come from one face, so share its feature, and the triangles are
    // sorted by it (order_by_feature): the distinct features are the runs.
    std::uint32_t distinct = 0;
    for (std::size_t i = begin; i < ends_[m]; i += 3) {
      if (i == begin || vertex_features_[indices_[i]] != vertex_features_[indices_[i - 3]])
        ++distinct;
    }
    const std::uint32_t accessor = buffers.add_accessor(
        Accessor{view, offset, short_indices ? Component::kUnsignedShort : Component::kUnsignedInt,
                 ends_[m] - begin, "SCALAR", false, std::nullopt, std::nullopt});
    record.primitives.push_back({indices_by_material_[m].first, accessor, distinct});
    begin = ends_[m];
  }
}

MeshRecord MeshAssembler::emit(Buffers& buffers, const MeshViews& views) {
  MeshRecord record;
  gather_indices();
  quantize(record);
  const std::size_t count = number_and_order();
  write_attributes(buffers, views, count, record);
  write_primitives(buffers, views, count, record);
  clear();
  return record;
}

}  // namespace insula::io::gltf
