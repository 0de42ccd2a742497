#include "io/gltf_mesh.h"

#include <meshoptimizer.h>

#include <algorithm>
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

// Copies the `size`-byte slice at `column` of each of `rows` in turn to `out`; each size is a
// case of its own so every copy is a fixed-size move.
void gather_column(char* out, const unsigned char* column, std::size_t stride, std::uint32_t size,
                   std::span<const std::uint32_t> rows) {
  // A tile's rows are megabytes read in the order of first use: the rows a few steps ahead are
  // asked for early (the order is known; the processor's prefetcher cannot guess it).
  constexpr std::size_t kAhead = 16;
  const auto gather = [&]<std::size_t Size>(std::integral_constant<std::size_t, Size>) {
    const std::size_t n = rows.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (i + kAhead < n) __builtin_prefetch(column + std::size_t{rows[i + kAhead]} * stride);
      std::memcpy(out, column + std::size_t{rows[i]} * stride, Size);
      out += Size;
    }
  };
  switch (size) {
    case 4:
      return gather(std::integral_constant<std::size_t, 4>{});
    case 8:
      return gather(std::integral_constant<std::size_t, 8>{});
    case 12:
      return gather(std::integral_constant<std::size_t, 12>{});
    default:
      for (std::uint32_t row : rows) {
        std::memcpy(out, column + row * stride, size);
        out += size;
      }
  }
}

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
    : materials_(materials), material_textured_(std::move(material_textured)) {}

void MeshAssembler::clear() {
  sources_.clear();
  face_normals_.clear();
  vertices_.clear();
  for (auto& [material, list] : indices_by_material_) {
    list.clear();
    spare_lists_.push_back(std::move(list));
  }
  indices_by_material_.clear();
  has_uv_ = false;
  bounds_ = Bounds{};
}

void MeshAssembler::reserve(std::size_t vertices, std::size_t corners, std::size_t faces) {
  sources_.reserve(sources_.size() + vertices);
  vertices_.reserve(vertices_.size() + corners);
  face_normals_.reserve(face_normals_.size() + faces);
}

void MeshAssembler::add(const kernel::Mesh& mesh, const shape::Part& part, std::uint32_t feature,
                        bool quantize, bool instance_frame) {
  part_ = &part;
  instance_frame_ = instance_frame;
  uv_scale_ = uv_scale(part);
  feature_ = feature;
  weld_.run(mesh, quantize ? kQuantizationStep : 0);
  first_source_ = static_cast<std::uint32_t>(sources_.size());
  constexpr double kStepsPerMeter = 1 / kQuantizationStep;  // a power of two
  // Past 2^62 steps (or not finite) a position has no grid point: its mesh stays float.
  constexpr double kGridLimit = 4.6e18;
  // Written in place: a Source built apart and copied in stalled on reloading its bytes.
  sources_.resize(first_source_ + mesh.vertex_count());
  Source* source = sources_.data() + first_source_;
  for (const kernel::Vec3& p : mesh.positions()) {
    source->position = y_up(p);
    source->on_grid = true;
    for (std::size_t k = 0; k < 3; ++k) {
      const double steps = source->position[k] * kStepsPerMeter;  // exact, as the division
      source->on_grid = source->on_grid && std::abs(steps) < kGridLimit;
      if (source->on_grid) source->grid[k] = round_half_away(steps);
    }
    ++source;
  }
  // Faces grouped by material, in mesh order within each.
  faces_by_material_.clear();
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    faces_by_material_.emplace_back(materials_.index(mesh.tag(f)), f);
  }
  std::sort(faces_by_material_.begin(), faces_by_material_.end());  // (material, face): stable
  std::vector<std::uint32_t>* indices = nullptr;
  std::uint32_t current = std::numeric_limits<std::uint32_t>::max();
  used_.assign(mesh.vertex_count(), 0);
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
  // The bounds of the vertices some corner uses, once each rather than once a corner.
  for (std::size_t v = 0; v < used_.size(); ++v) {
    if (used_[v] != 0) bounds_.add(sources_[first_source_ + v]);
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
  const auto base = static_cast<std::uint32_t>(vertices_.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::uint32_t source = first_source_ + weld_.representative(loop[i]);
    used_[source - first_source_] = 1;
    vertices_.push_back(Vertex{source, face, corner_uvs_[i], feature_});
  }
  for (const CornerTriangle& triangle : triangles_) {
    for (std::uint32_t corner : triangle) indices.push_back(base + corner);
  }
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

void MeshAssembler::Bounds::add(const Source& source) {
  on_grid = on_grid && source.on_grid;
  for (std::size_t k = 0; k < 3; ++k) {
    if (source.on_grid) {
      low[k] = std::min(low[k], source.grid[k]);
      high[k] = std::max(high[k], source.grid[k]);
    }
    const double c = static_cast<float>(source.position[k]);
    min[k] = std::min(min[k], c);
    max[k] = std::max(max[k], c);
  }
}

// Whether the mesh's extent on the quantization grid fits 16 bits; sets the record's offset and
// scale (and grid_low_) when it does, and its POSITION bounds either way. The bounds are those of
// every vertex added (each is used by a triangle, so merging and reordering keep them).
void MeshAssembler::quantize(bool wanted, MeshRecord& record) {
  record.quantized = wanted && bounds_.on_grid && !vertices_.empty();
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

// Every vertex's attributes as they will be written, side by side in one row (padding zero):
// positions, normals, then uvs and feature ids when written. Lays out the rows; merge_rows() packs
// them run by run.
void MeshAssembler::lay_out(const MeshRecord& record, const MeshOptions& options,
                            bool with_features) {
  const std::size_t n = vertices_.size();
  layout_.size = {record.quantized ? 8U : 12U,  // quantized: x, y, z, padding
                  options.quantize ? 4U : 12U, has_uv_ ? 8U : 0U, with_features ? 4U : 0U};
  layout_.stride = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    layout_.offset[k] = layout_.stride;
    layout_.stride += layout_.size[k];
  }
  layout_.float_features = options.feature_component == Component::kFloat;
  if (rows_capacity_ < n * layout_.stride) {
    rows_capacity_ = std::max(n * layout_.stride, 2 * rows_capacity_);
    rows_ = std::make_unique_for_overwrite<unsigned char[]>(rows_capacity_);
  }
}

// The rows of vertices [begin, end), every byte written (padding too), in one pass.
void MeshAssembler::pack_rows(std::size_t begin, std::size_t end) {
  const bool quantized = layout_.size[0] == 8;
  const bool byte_normals = layout_.size[1] == 4;
  const bool with_features = layout_.size[3] != 0;
  char* at = reinterpret_cast<char*>(rows_.get()) + begin * layout_.stride;
  for (std::size_t v = begin; v < end; ++v) {
    const Vertex& vertex = vertices_[v];
    const Source& source = sources_[vertex.source];
    if (quantized) {
      for (std::size_t k = 0; k < 3; ++k) {
        put_value(at, static_cast<std::uint16_t>(source.grid[k] - grid_low_[k]));
      }
      put_value(at, std::uint16_t{0});
    } else {
      for (double c : source.position) put_value(at, static_cast<float>(c));
    }
    const FaceNormal& normal = face_normals_[vertex.face];
    if (byte_normals) {
      for (std::int8_t c : normal.bytes) put_value(at, c);  // the fourth byte is 0
    } else {
      for (float c : normal.normal) put_value(at, c);
    }
    if (has_uv_) {
      for (float c : vertex.uv) put_value(at, c);
    }
    if (with_features && layout_.float_features) {
      put_value(at, static_cast<float>(vertex.feature));
    } else if (with_features) {
      put_value(at, static_cast<std::uint16_t>(vertex.feature));
      put_value(at, std::uint16_t{0});
    }
  }
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

// representative_[v]: the first vertex alike v in every written byte; feature_of_[v] its feature
// (the vertices' features side by side: numbering reads them in the indices' order, which jumps
// across a tile's vertices). When the feature id is
// written, vertices alike share a feature, and a feature's vertices were added together (part by
// part): each run of one feature is merged on its own, in a table that stays in cache (one table
// for a whole 3D Tiles tile missed it on most lookups).
void MeshAssembler::merge_rows() {
  const std::size_t n = vertices_.size();
  const bool by_feature = layout_.size[3] != 0;
  representative_.resize(n);
  feature_of_.resize(n);
  for (std::size_t v = 0; v < n; ++v) feature_of_[v] = vertices_[v].feature;
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = n;
    if (by_feature) {
      end = begin + 1;
      while (end < n && feature_of_[end] == feature_of_[begin]) ++end;
    }
    pack_rows(begin, end);  // hashed right away, while in cache
    find_representatives(begin, end);
    begin = end;
  }
}

// representative_[v] for the vertices [begin, end): the first of them alike in every written
// byte. Open addressing over the rows, with the table kept from run to run: most runs are small,
// and allocating a table for each cost more than the lookups.
void MeshAssembler::find_representatives(std::size_t begin, std::size_t end) {
  const std::size_t stride = layout_.stride;
  std::size_t capacity = 16;
  while (capacity < 2 * (end - begin)) capacity *= 2;
  slots_.assign(capacity, ~0U);
  const auto row = [&](std::size_t v) { return rows_.get() + v * stride; };
  // Rows are whole 4-byte words: compared word by word inline (memcmp was a call a lookup).
  const auto alike = [stride](const unsigned char* a, const unsigned char* b) {
    for (std::size_t i = 0; i < stride; i += 4) {
      std::uint32_t x;
      std::uint32_t y;
      std::memcpy(&x, a + i, 4);
      std::memcpy(&y, b + i, 4);
      if (x != y) return false;
    }
    return true;
  };
  // Each word times a constant of its own, summed: the products do not wait for each other as a
  // chain of multiplications did. Any hash finds the same representatives.
  static constexpr std::array<std::uint64_t, 4> kFactors{
      0x9E3779B97F4A7C15ULL, 0xC2B2AE3D27D4EB4FULL, 0x165667B19E3779F9ULL, 0xD6E8FEB86659FD93ULL};
  for (std::size_t v = begin; v < end; ++v) {
    std::uint64_t hash = 0;
    for (std::size_t i = 0; i < stride; i += 4) {
      std::uint32_t word;
      std::memcpy(&word, row(v) + i, 4);
      hash += (word + std::uint64_t{1}) * kFactors[(i / 4) % 4];
    }
    hash ^= hash >> 29U;
    for (std::size_t slot = (hash >> 32U) & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
      const std::uint32_t other = slots_[slot];
      if (other == ~0U) {
        slots_[slot] = static_cast<std::uint32_t>(v);
        representative_[v] = static_cast<std::uint32_t>(v);
        break;
      }
      if (alike(row(other), row(v))) {
        representative_[v] = other;
        break;
      }
    }
  }
}

// Vertices alike in every written attribute become one, numbered in order of first use by the
// indices (as meshopt_generateVertexRemap does); triangles part by part (a part's faces lie
// together, and the feature ids then come in runs, which EXT_meshopt_compression stores in almost
// nothing), each part's in the order that suits the vertex cache; then vertices in the order of
// first use, for fetch, which is already theirs unless a run was reordered. Leaves indices_ and
// vertex_features_ over the written vertices, and row_of_ naming the row each writes; returns
// their count.
std::size_t MeshAssembler::merge_and_order() {
  merge_rows();
  class_of_.assign(vertices_.size(), ~0U);
  row_of_.clear();
  vertex_features_.clear();
  unsigned int* out = indices_.data();
  for (const auto& [material, list] : indices_by_material_) {
    for (const std::uint32_t index : list) {
      const std::uint32_t representative = representative_[index];
      unsigned int& number = class_of_[representative];
      if (number == ~0U) {
        number = static_cast<unsigned int>(row_of_.size());
        row_of_.push_back(representative);
        vertex_features_.push_back(feature_of_[representative]);
      }
      *out++ = number;
    }
  }
  const std::size_t count = row_of_.size();
  local_of_.clear();  // sized by optimize_run when a run needs it
  loaded_at_.assign(count, ~0U);
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
  const std::size_t count = row_of_.size();
  fetch_.assign(count, ~0U);
  unsigned int next = 0;
  for (unsigned int& index : indices_) {
    if (fetch_[index] == ~0U) fetch_[index] = next++;
    index = fetch_[index];
  }
  moved_rows_.resize(count);
  moved_features_.resize(count);
  for (std::size_t w = 0; w < count; ++w) {
    moved_rows_[fetch_[w]] = row_of_[w];
    moved_features_[fetch_[w]] = vertex_features_[w];
  }
  std::swap(row_of_, moved_rows_);
  std::swap(vertex_features_, moved_features_);
}

// Each attribute's slice of the written vertices' rows, appended to its view.
void MeshAssembler::write_attributes(Buffers& buffers, const MeshViews& views,
                                     const MeshOptions& options, std::size_t count,
                                     MeshRecord& record) {
  const auto add = [&](std::size_t k, std::uint32_t view, Component component,
                       std::string_view type, bool normalized) {
    std::string& data = buffers.data(view);
    const std::size_t offset = data.size();
    const std::uint32_t size = layout_.size[k];
    data.resize(offset + count * size);
    gather_column(data.data() + offset, rows_.get() + layout_.offset[k], layout_.stride, size,
                  row_of_);
    return buffers.add_accessor(
        Accessor{view, offset, component, count, type, normalized, std::nullopt, std::nullopt});
  };
  record.position =
      add(0, record.quantized ? views.quantized_positions : views.float_positions,
          record.quantized ? Component::kUnsignedShort : Component::kFloat, "VEC3", false);
  buffers.set_bounds(record.position, {record.min, record.max});
  record.normal =
      add(1, options.quantize ? views.quantized_normals : views.float_normals,
          options.quantize ? Component::kByte : Component::kFloat, "VEC3", options.quantize);
  if (has_uv_) record.uv = add(2, views.uvs, Component::kFloat, "VEC2", false);
  if (layout_.size[3] > 0) {
    record.feature = add(3, views.features, options.feature_component, "SCALAR", false);
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

MeshRecord MeshAssembler::emit(Buffers& buffers, const MeshViews& views, const MeshOptions& options,
                               bool with_features) {
  MeshRecord record;
  gather_indices();
  quantize(options.quantize, record);
  lay_out(record, options, with_features);
  const std::size_t count = merge_and_order();
  write_attributes(buffers, views, options, count, record);
  write_primitives(buffers, views, count, record);
  clear();
  return record;
}

}  // namespace insula::io::gltf
