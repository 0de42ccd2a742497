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

// Faces of up to this many corners (nearly all) keep their corners' vertices on the stack.
constexpr std::size_t kSmallFace = 16;

// The vertex cache triangles are ordered for: meshopt's FIFO model of a GPU's, 16 vertices.
constexpr unsigned int kCacheSize = 16;

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
  for (MaterialList& list : lists_) {
    list.indices.clear();
    list.runs.clear();
    spare_lists_.push_back(std::move(list));
  }
  lists_.clear();
  has_uv_ = false;
  bounds_ = Bounds{};
  reserved_indices_ = 0;
  scope_feature_set_ = false;
  begin_scope();
}

void MeshAssembler::reserve(std::size_t vertices, std::size_t corners, std::size_t faces) {
  positions_.reserve(positions_.size() + vertices);
  vertices_.reserve(vertices_.size() + corners);
  face_normals_.reserve(face_normals_.size() + faces);
  // A face of n corners has n - 2 triangles. Every material's list gets room for all of them:
  // room never written costs address space only, and a tile's lists grew by copying otherwise.
  reserved_indices_ = 3 * (corners > 2 * faces ? corners - 2 * faces : 0);
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

bool MeshAssembler::add(const kernel::Mesh& mesh, const shape::Part& part, std::uint32_t feature,
                        bool instance_frame) {
  part_ = &part;
  part_triangles_ = false;
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
  collapsed_ = enter_positions(mesh);
  // A closed shell is welded as a whole; an open mesh's faces are contracted one by one.
  if (!collapsed_ || !weld_.run(mesh, options_.quantize ? kQuantizationStep : 0)) weld_.clear();
  // Faces grouped by material, in mesh order within each.
  // Every face's unit normal first, in a loop of its own: each normal is a chain of dependent
  // sums, a square root and divisions, and faces computed side by side overlap those waits.
  face_units_.resize(mesh.face_count());
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f)
    face_units_[f] = kernel::face_normal(mesh, f);
  faces_by_material_.clear();
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    faces_by_material_.emplace_back(materials_.index(mesh.tag(f)), f);
  }
  std::sort(faces_by_material_.begin(), faces_by_material_.end());  // (material, face): stable
  MaterialList* list = nullptr;
  for (const auto& [material, face] : faces_by_material_) {
    if (list == nullptr || list->material != material) {
      list = &list_of(material);
      fit_uv_ = material_textured_[material];
    }
    add_face(mesh, face, *list);
  }
  // A material all of whose faces were degenerate gets no primitive.
  std::erase_if(lists_, [this](MaterialList& entry) {
    if (!entry.indices.empty()) return false;
    spare_lists_.push_back(std::move(entry));
    return true;
  });
  return part_triangles_;
}

// The list of `material`'s triangles, made (from one that served an earlier mesh when there is
// one: growing a list anew for every material of every building cost more than filling it) when
// the mesh has none yet.
MeshAssembler::MaterialList& MeshAssembler::list_of(std::uint32_t material) {
  for (MaterialList& list : lists_) {
    if (list.material == material) return list;
  }
  if (spare_lists_.empty()) {
    lists_.emplace_back();
  } else {
    lists_.push_back(std::move(spare_lists_.back()));
    spare_lists_.pop_back();
  }
  lists_.back().material = material;
  lists_.back().indices.reserve(reserved_indices_);
  return lists_.back();
}

// Flat shading: the face's corners become vertices of their own, all carrying the face normal.
// Where the weld merges vertices (float32_weld.h) the face's triangles and corners come from it.
void MeshAssembler::add_face(const kernel::Mesh& mesh, std::size_t face, MaterialList& list) {
  const kernel::Vec3 newell = face_units_[face];
  // A face whose corners all lie on one line has no area and no normal to shade it with (glTF
  // requires unit normals): it is not written. (face_normal is unit or zero; NaN fails too.)
  if (!(kernel::dot(newell, newell) > 0)) return;
  const std::size_t indices_before = list.indices.size();
  triangles_.clear();
  if (weld_.active()) {
    add_triangles(mesh, weld_.triangles(face), newell, list.indices);
  } else if (collapsed_) {
    contract_face(mesh, face, newell);
    add_triangles(mesh, contracted_, newell, list.indices);
  } else {
    if (!triangulator_.triangulate(mesh, face, newell, triangles_)) return;
    add_corners(mesh, mesh.face(face), newell, list.indices);
  }
  // A face that contracted away starts no run: a run counts a feature the primitive shows.
  if (list.indices.size() == indices_before) return;
  part_triangles_ = true;
  // The face's triangles belong to the part's feature.
  if (list.runs.empty() || list.runs.back().feature != feature_) {
    list.runs.push_back({feature_, list.indices.size()});
  } else {
    list.runs.back().end = list.indices.size();
  }
}

// A face given as triangles of vertices: its corners are the vertices in the order the triangles
// first use them.
void MeshAssembler::add_triangles(const kernel::Mesh& mesh,
                                  std::span<const std::array<std::uint32_t, 3>> triangles,
                                  kernel::Vec3 newell, std::vector<std::uint32_t>& indices) {
  corners_.clear();
  for (const auto& triangle : triangles) {
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

// In a part where vertices at different places round to one written position (and no weld took
// the part as a whole: it is open), each face is contracted over its corners' positions, as
// Float32Weld does for a closed shell, into contracted_: triangles of the first vertex of the part
// at each position, triangulated at those vertices' places.
void MeshAssembler::contract_face(const kernel::Mesh& mesh, std::size_t face, kernel::Vec3 newell) {
  corner_positions_.clear();
  corners_.clear();
  corner_places_.clear();
  for (std::uint32_t vertex : mesh.face(face)) {
    const std::uint32_t entry = position_of_[vertex];
    const std::uint32_t first = positions_[entry].part_vertex;
    corner_positions_.push_back(entry);
    corners_.push_back(first);
    corner_places_.push_back(mesh.position(first));
  }
  face_triangles_.clear();
  triangulator_.triangulate_contracted(corner_positions_, corner_places_, newell, face_triangles_);
  contracted_.clear();
  for (const CornerTriangle& t : face_triangles_) {
    contracted_.push_back({corners_[t[0]], corners_[t[1]], corners_[t[2]]});
  }
}

void MeshAssembler::add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                                kernel::Vec3 newell, std::vector<std::uint32_t>& indices) {
  const std::array<double, 3> n = y_up(newell);  // add_face's unit normal
  const auto face = static_cast<std::uint32_t>(face_normals_.size());
  // Written in place (zeroed, so the padding byte is 0): built apart, its bytes written one by
  // one and copied in as a whole stalled the copy.
  FaceNormal& normal = face_normals_.emplace_back();
  for (std::size_t k = 0; k < 3; ++k) {
    normal.normal[k] = static_cast<float>(n[k]);
    normal.bytes[k] = normal_byte(normal.normal[k]);
  }
  // Most faces have no uv: their corners share one zero uv rather than a list filled with it.
  const bool with_uv = part_->uv || fit_uv_ || uv_scale_ > 0;
  if (with_uv) corner_uvs_.resize(loop.size());
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
  // Vertices made in the order the triangles first use them: the order they are written in.
  // A face of up to kSmallFace corners keeps them on the stack (memset's wide stores into the
  // list stalled the first read of each entry).
  std::array<std::uint32_t, kSmallFace> small{};
  if (loop.size() > kSmallFace) corner_vertices_.resize(loop.size());
  const std::span<std::uint32_t> corner_vertex =
      loop.size() <= kSmallFace ? std::span<std::uint32_t>(small).first(loop.size())
                                : std::span<std::uint32_t>(corner_vertices_);
  std::fill(corner_vertex.begin(), corner_vertex.end(), kNone);
  for (const CornerTriangle& triangle : triangles_) {
    for (std::uint32_t corner : triangle) {
      std::uint32_t& vertex = corner_vertex[corner];
      if (vertex == kNone) {
        const std::uint32_t position = position_of_[weld_.representative(loop[corner])];
        vertex = vertex_at(position, face,
                           with_uv ? corner_uvs_[corner] : std::array<float, 2>{0.0F, 0.0F});
      }
      indices.push_back(vertex);
    }
  }
}

// Looks every vertex of the part up in the scope (position_of_). Returns whether two of them at
// different places round to one written position: the float32 weld's question, answered by the
// lookups the corners need anyway.
bool MeshAssembler::enter_positions(const kernel::Mesh& mesh) {
  ++part_serial_;
  bool collapsed = false;
  position_of_.resize(mesh.vertex_count());
  for (std::uint32_t vertex = 0; vertex < mesh.vertex_count(); ++vertex) {
    const std::uint32_t entry = find_position(rounded_position(mesh, vertex));
    position_of_[vertex] = entry;
    Position& at = positions_[entry];
    if (at.part != part_serial_) {
      at.part = part_serial_;
      at.part_vertex = vertex;
    } else if (at.part_vertex != vertex &&
               !(mesh.position(at.part_vertex) == mesh.position(vertex))) {
      collapsed = true;
    }
  }
  return collapsed;
}

// The position the part's vertex `vertex` is written at: Y-up, float32, and the nearest grid
// point when positions may be quantized.
MeshAssembler::Position MeshAssembler::rounded_position(const kernel::Mesh& mesh,
                                                        std::uint32_t vertex) const {
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
  position.part = part_serial_;
  position.part_vertex = vertex;
  return position;
}

namespace {

// What makes two positions one: their grid point where positions may be quantized and both have
// one (the weld made vertices on one grid point one vertex, so they share their float32 too),
// else their float32 coordinates' bits.
bool same_position(const std::array<std::int64_t, 3>& grid, const Float3& coordinates, bool on_grid,
                   const std::array<std::int64_t, 3>& other_grid, const Float3& other_coordinates,
                   bool other_on_grid) {
  if (on_grid != other_on_grid) return false;
  // Compared word by word: std::array's == called memcmp, a tenth of the lookups' time.
  if (on_grid) {
    return grid[0] == other_grid[0] && grid[1] == other_grid[1] && grid[2] == other_grid[2];
  }
  const auto bits = [](float c) { return std::bit_cast<std::uint32_t>(c); };
  return bits(coordinates[0]) == bits(other_coordinates[0]) &&
         bits(coordinates[1]) == bits(other_coordinates[1]) &&
         bits(coordinates[2]) == bits(other_coordinates[2]);
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

// The scope's entry alike `position`, entered when there is none.
std::uint32_t MeshAssembler::find_position(const Position& position) {
  if (2 * (positions_.size() - scope_begin_ + 1) > slots_.size()) grow_position_table();
  const std::size_t mask = slots_.size() - 1;
  const std::uint64_t hash = position_hash(position.grid, position.coordinates, position.on_grid);
  for (std::size_t slot = (hash >> 32U) & mask;; slot = (slot + 1) & mask) {
    Slot& entry = slots_[slot];
    if (entry.scope != scope_) {
      entry = {static_cast<std::uint32_t>(positions_.size()), scope_};
      positions_.push_back(position);
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
  // The bounds are those of the positions written (a part's vertex no face uses has an entry).
  if (at.first_vertex == kNone) bounds_.add(at);
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

// The materials in table order: their primitives' order.
void MeshAssembler::sort_lists() {
  std::sort(lists_.begin(), lists_.end(),
            [](const MaterialList& a, const MaterialList& b) { return a.material < b.material; });
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
  meshopt_optimizeVertexCacheFifo(run.data(), run.data(), run.size(), global_of_.size(),
                                  kCacheSize);
  for (unsigned int& v : run) v = global_of_[v];
  for (unsigned int v : global_of_) local_of_[v] = ~0U;
  return true;
}

// Sorts the triangles of `indices` (one material's) by feature, keeping the order within a
// feature (they usually come sorted, part after part), merging `runs` to one a feature; then
// optimises each feature's run for the vertex cache. Returns whether it changed the order of any
// triangle or index.
bool MeshAssembler::order_by_feature(std::span<std::uint32_t> indices,
                                     std::vector<FeatureRun>& runs) {
  bool sorted = true;
  for (std::size_t r = 1; r < runs.size() && sorted; ++r)
    sorted = runs[r - 1].feature < runs[r].feature;
  if (!sorted) sort_runs(indices, runs);
  bool reordered = !sorted;
  std::size_t begin = 0;
  for (const FeatureRun& run : runs) {
    reordered = optimize_run(indices.subspan(begin, run.end - begin)) || reordered;
    begin = run.end;
  }
  return reordered;
}

// The runs of `indices` stably sorted by feature, runs of one feature merged.
void MeshAssembler::sort_runs(std::span<std::uint32_t> indices, std::vector<FeatureRun>& runs) {
  run_order_.resize(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) run_order_[r] = r;
  std::stable_sort(run_order_.begin(), run_order_.end(), [&runs](std::size_t a, std::size_t b) {
    return runs[a].feature < runs[b].feature;
  });
  sorted_indices_.resize(indices.size());
  sorted_runs_.clear();
  std::size_t end = 0;
  for (std::size_t r : run_order_) {
    const std::size_t begin = r == 0 ? 0 : runs[r - 1].end;
    std::copy(indices.begin() + static_cast<std::ptrdiff_t>(begin),
              indices.begin() + static_cast<std::ptrdiff_t>(runs[r].end),
              sorted_indices_.begin() + static_cast<std::ptrdiff_t>(end));
    end += runs[r].end - begin;
    if (!sorted_runs_.empty() && sorted_runs_.back().feature == runs[r].feature) {
      sorted_runs_.back().end = end;
    } else {
      sorted_runs_.push_back({runs[r].feature, end});
    }
  }
  std::copy(sorted_indices_.begin(), sorted_indices_.end(), indices.begin());
  runs.swap(sorted_runs_);
}

// Vertices are numbered as they were made: part by part, a face's in the order its triangles
// first use them, so a part's vertices lie together and are written in one pass. Triangles stay
// part by part (the feature ids then come in runs, which EXT_meshopt_compression stores in almost
// nothing), each part's in the order that suits the vertex cache. Where that moved a triangle, or
// where the options ask for it, vertices are numbered again in the order of first use (as
// meshopt_optimizeVertexFetch does). Returns the number of vertices written.
std::size_t MeshAssembler::order_for_cache() {
  renumbered_ = false;
  local_of_.clear();  // sized by optimize_run when a run needs it
  loaded_at_.assign(vertices_.size(), kNone);
  bool reordered = false;
  for (MaterialList& list : lists_) {
    reordered = order_by_feature(list.indices, list.runs) || reordered;
  }
  if (reordered || (options_.first_use_order && lists_.size() > 1)) number_for_fetch();
  return vertices_.size();
}

// Renumbers the vertices in order of first use by the reordered indices; vertex_of_ then names
// the vertex each number writes. Every vertex is used (each was made for a triangle's corner).
void MeshAssembler::number_for_fetch() {
  const std::size_t count = vertices_.size();
  fetch_.assign(count, kNone);
  unsigned int next = 0;
  for (MaterialList& list : lists_) {
    for (unsigned int& index : list.indices) {
      if (fetch_[index] == kNone) fetch_[index] = next++;
      index = fetch_[index];
    }
  }
  vertex_of_.resize(count);
  for (std::size_t v = 0; v < count; ++v) vertex_of_[fetch_[v]] = static_cast<std::uint32_t>(v);
  renumbered_ = true;
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
  // Room for `count` values of `size` bytes at the end of `view`, not zeroed (every byte is
  // written below, padding included); the accessor over them.
  const auto column = [&](std::uint32_t view, std::size_t size, Component component,
                          std::string_view type, bool normalized, std::uint32_t& accessor) {
    Bytes& data = buffers.data(view);
    const std::size_t offset = data.size();
    char* at = data.extend(count * size);
    accessor = buffers.add_accessor(
        Accessor{view, offset, component, count, type, normalized, std::nullopt, std::nullopt});
    return at;
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
    const Vertex& vertex = written(w);
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
  Bytes& data = buffers.data(view);
  std::size_t total = 0;
  for (const MaterialList& list : lists_) total += list.indices.size();
  char* at = data.extend(total * (short_indices ? 2 : 4));  // every byte written below
  for (const MaterialList& list : lists_) {
    const std::size_t offset = static_cast<std::size_t>(at - data.data());
    for (const std::uint32_t index : list.indices) {
      if (short_indices) {
        put_value(at, static_cast<std::uint16_t>(index));
      } else {
        put_value(at, index);
      }
    }
    // The triangles are sorted by feature, one run a feature (order_by_feature).
    const auto distinct = static_cast<std::uint32_t>(list.runs.size());
    const std::uint32_t accessor = buffers.add_accessor(
        Accessor{view, offset, short_indices ? Component::kUnsignedShort : Component::kUnsignedInt,
                 list.indices.size(), "SCALAR", false, std::nullopt, std::nullopt});
    record.primitives.push_back({list.material, accessor, distinct});
  }
}

MeshRecord MeshAssembler::emit(Buffers& buffers, const MeshViews& views) {
  MeshRecord record;
  sort_lists();
  quantize(record);
  const std::size_t count = order_for_cache();
  write_attributes(buffers, views, count, record);
  write_primitives(buffers, views, count, record);
  clear();
  return record;
}

}  // namespace insula::io::gltf
