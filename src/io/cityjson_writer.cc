#include "io/cityjson_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "io/atomic_file.h"
#include "io/json_stream.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

using Quantised = std::array<std::int64_t, 3>;

constexpr double kScale = 0.001;  // 1 mm, the precision of survey-grade city models
constexpr double kPerMeter = 1000.0;

bool finite(kernel::Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Quantised offsets must stay exact integers in a double and in JSON readers (|q| < 2^53).
bool quantisable(kernel::Vec3 offset) {
  constexpr double kLimit = 9.0e15 / kPerMeter;
  return std::abs(offset.x) < kLimit && std::abs(offset.y) < kLimit && std::abs(offset.z) < kLimit;
}

// Mixes the three components (splitmix64 finaliser) so nearby grid points spread over buckets.
struct QuantisedHash {
  std::size_t operator()(const Quantised& q) const {
    std::uint64_t h = 0;
    for (std::int64_t c : q) {
      h = (h ^ static_cast<std::uint64_t>(c)) * 0x9E3779B97F4A7C15ULL;
      h ^= h >> 29U;
    }
    return static_cast<std::size_t>(h);
  }
};

// The file's vertex list: every distinct quantised point once, numbered in first-use order.
class VertexPool {
 public:
  std::uint32_t add(const Quantised& q) {
    const auto [it, inserted] = index_.emplace(q, static_cast<std::uint32_t>(vertices_.size()));
    if (inserted) vertices_.push_back(q);
    return it->second;
  }
  void reserve(std::size_t n) {
    index_.reserve(n);
    vertices_.reserve(n);
  }
  const std::vector<Quantised>& vertices() const { return vertices_; }

 private:
  std::unordered_map<Quantised, std::uint32_t, QuantisedHash> index_;
  std::vector<Quantised> vertices_;
};

std::string_view object_type(shape::PartKind kind) {
  switch (kind) {
    case shape::PartKind::kStorey:
      return "BuildingStorey";
    case shape::PartKind::kRoom:
      return "BuildingRoom";
    case shape::PartKind::kInstallation:
      return "BuildingInstallation";
    case shape::PartKind::kBuildingPart:
    case shape::PartKind::kOther:
      break;
  }
  return "BuildingPart";
}

// `base`, or `base-2`, `base-3`, ... when taken; records the result.
std::string unique_id(const std::string& base, std::unordered_set<std::string>& taken) {
  std::string id = base;
  for (int suffix = 2; taken.contains(id); ++suffix) id = base + "-" + std::to_string(suffix);
  taken.insert(id);
  return id;
}

// The faces of one part as rings of file vertex indices (ring r is
// indices[ends[r - 1] .. ends[r])), with their surface type ("" = none).
struct PartSurfaces {
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> ends;
  std::vector<std::string_view> types;

  std::size_t size() const { return ends.size(); }
  std::span<const std::uint32_t> ring(std::size_t r) const {
    const std::size_t begin = r == 0 ? 0 : ends[r - 1];
    return std::span<const std::uint32_t>(indices).subspan(begin, ends[r] - begin);
  }
  void clear() {
    indices.clear();
    ends.clear();
    types.clear();
  }
};

// One city object's compact JSON text, kept in a shared buffer until the objects are sorted by id
// (a JSON object's members in nlohmann's order).
struct ObjectText {
  std::string id;
  std::size_t begin = 0;
  std::size_t end = 0;
};

// Writes the CityJSON text directly (no document tree): the city objects first, each into a shared
// buffer, then the members in sorted order with the objects sorted by id, so the text is the
// one nlohmann::json would print for the same document.
class Writer {
 public:
  explicit Writer(const shape::Scene& scene);
  void write(std::string& out);

 private:
  Quantised quantise(kernel::Vec3 local) const;
  void collect_surfaces(const kernel::Mesh& mesh);
  bool is_solid() const;
  void write_geometry(JsonStream& json) const;
  void add_building(const shape::Building& building, std::size_t index);
  void write_metadata(JsonStream& json) const;

  const shape::Scene& scene_;
  kernel::Vec3 min_{};  // local minimum corner of every finite vertex
  VertexPool pool_;
  std::unordered_set<std::string> ids_;
  std::string objects_text_;
  std::vector<ObjectText> objects_;

  // Scratch reused from part to part.
  PartSurfaces part_;
  mutable std::vector<std::uint32_t> local_index_;  // file vertex -> solid-test mesh vertex
  mutable std::vector<std::uint32_t> local_stamp_;  // which solid test set local_index_
  mutable std::uint32_t stamp_ = 0;
};

Writer::Writer(const shape::Scene& scene) : scene_(scene) {
  kernel::Bounds3 bounds;
  std::size_t corners = 0;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (const kernel::Vec3& p : part.mesh.positions()) {
        if (finite(p)) bounds.add(p);
      }
      corners += part.mesh.vertex_count();
    }
  }
  if (!bounds.empty()) min_ = bounds.min;
  pool_.reserve(corners);
}

Quantised Writer::quantise(kernel::Vec3 local) const {
  const kernel::Vec3 d = (local - min_) * kPerMeter;
  return {std::llround(d.x), std::llround(d.y), std::llround(d.z)};
}

void Writer::collect_surfaces(const kernel::Mesh& mesh) {
  part_.clear();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t begin = part_.indices.size();
    bool ok = true;
    for (std::uint32_t vertex : mesh.face(f)) {
      const kernel::Vec3 p = mesh.position(vertex);
      if (!finite(p) || !quantisable(p - min_)) {
        ok = false;
        break;
      }
      const std::uint32_t index = pool_.add(quantise(p));
      if (part_.indices.size() == begin || part_.indices.back() != index) {
        part_.indices.push_back(index);
      }
    }
    while (part_.indices.size() > begin + 1 && part_.indices.back() == part_.indices[begin]) {
      part_.indices.pop_back();
    }
    if (!ok || part_.indices.size() < begin + 3) {
      part_.indices.resize(begin);
      continue;
    }
    part_.ends.push_back(part_.indices.size());
    part_.types.push_back(kernel::citygml_surface(mesh.tag(f).semantic));
  }
}

// A Solid needs one closed, consistently outward-oriented 2-manifold shell: checked on the
// quantised rings, so the test sees exactly what a validator such as val3dity will see.
bool Writer::is_solid() const {
  if (part_.size() < 4) return false;
  ++stamp_;
  if (local_index_.size() < pool_.vertices().size()) {
    local_index_.resize(pool_.vertices().size());
    local_stamp_.resize(pool_.vertices().size(), 0);
  }
  kernel::Mesh mesh;
  std::vector<std::uint32_t> loop;
  for (std::size_t r = 0; r < part_.size(); ++r) {
    loop.clear();
    for (std::uint32_t index : part_.ring(r)) {
      if (local_stamp_[index] != stamp_) {
        local_stamp_[index] = stamp_;
        local_index_[index] = static_cast<std::uint32_t>(mesh.vertex_count());
        const Quantised& q = pool_.vertices()[index];
        mesh.add_vertex(
            {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])});
      }
      loop.push_back(local_index_[index]);
    }
    mesh.add_face(loop, {});
  }
  const kernel::MeshCheck check = kernel::check(mesh);
  return check.closed && check.oriented && check.non_manifold_edges == 0 && check.components == 1 &&
         kernel::volume(mesh) > 0;
}

// {"boundaries", "lod", "semantics" (when some face has a type), "type"}; a Solid wraps the
// surfaces and values in one more array (its single outer shell).
void Writer::write_geometry(JsonStream& json) const {
  const bool solid = is_solid();
  json.begin_object().key("boundaries").begin_array();
  if (solid) json.begin_array();
  for (std::size_t r = 0; r < part_.size(); ++r) {
    json.begin_array().begin_array();
    for (std::uint32_t index : part_.ring(r)) json.integer(index);
    json.end_array().end_array();
  }
  if (solid) json.end_array();
  json.end_array().key("lod").string("2");
  std::vector<std::string_view> seen;
  for (std::string_view type : part_.types) {
    if (!type.empty() && std::find(seen.begin(), seen.end(), type) == seen.end()) {
      seen.push_back(type);
    }
  }
  if (!seen.empty()) {
    json.key("semantics").begin_object().key("surfaces").begin_array();
    for (std::string_view type : seen) json.begin_object().key("type").string(type).end_object();
    json.end_array().key("values").begin_array();
    if (solid) json.begin_array();
    for (std::string_view type : part_.types) {
      if (type.empty()) {
        json.null();
      } else {
        json.integer(std::find(seen.begin(), seen.end(), type) - seen.begin());
      }
    }
    if (solid) json.end_array();
    json.end_array().end_object();
  }
  json.key("type").string(solid ? "Solid" : "MultiSurface").end_object();
}

void Writer::add_building(const shape::Building& building, std::size_t index) {
  const std::string id =
      unique_id(building.id.empty() ? "building" + std::to_string(index) : building.id, ids_);
  std::vector<std::string> children;
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    std::string part_id =
        unique_id(id + "-" + (part.name.empty() ? "part" + std::to_string(p) : part.name), ids_);
    const std::size_t begin = objects_text_.size();
    JsonStream json(objects_text_);
    json.begin_object();
    if (!part.attributes.empty()) json.key("attributes").attributes(part.attributes);
    collect_surfaces(part.mesh);
    if (part_.size() > 0) {
      json.key("geometry").begin_array();
      write_geometry(json);
      json.end_array();
    }
    json.key("parents").begin_array().string(id).end_array();
    json.key("type").string(object_type(part.kind)).end_object();
    objects_.push_back({part_id, begin, objects_text_.size()});
    children.push_back(std::move(part_id));
  }
  const std::size_t begin = objects_text_.size();
  JsonStream json(objects_text_);
  json.begin_object();
  if (!building.attributes.empty()) json.key("attributes").attributes(building.attributes);
  if (!children.empty()) {
    json.key("children").begin_array();
    for (const std::string& child : children) json.string(child);
    json.end_array();
  }
  json.key("type").string("Building").end_object();
  objects_.push_back({id, begin, objects_text_.size()});
}

void Writer::write_metadata(JsonStream& json) const {
  json.begin_object();
  if (!pool_.vertices().empty()) {
    Quantised lo = pool_.vertices().front();
    Quantised hi = lo;
    for (const Quantised& q : pool_.vertices()) {
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    }
    const kernel::Vec3 t = scene_.origin + min_;
    const std::array<double, 3> translate{t.x, t.y, t.z};
    json.key("geographicalExtent").begin_array();
    for (const Quantised* corner : {&lo, &hi}) {
      for (std::size_t k = 0; k < 3; ++k) {
        json.number(translate[k] + static_cast<double>((*corner)[k]) * kScale);
      }
    }
    json.end_array();
  }
  const std::string reference_system = cityjson_reference_system(scene_.crs);
  if (!reference_system.empty()) json.key("referenceSystem").string(reference_system);
  json.end_object();
}

void Writer::write(std::string& out) {
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) add_building(scene_.buildings[b], b);
  std::sort(objects_.begin(), objects_.end(),
            [](const ObjectText& a, const ObjectText& b) { return a.id < b.id; });
  // About 20 bytes per vertex ("[123456,234567,3456],"), plus the objects.
  out.reserve(out.size() + objects_text_.size() + 24 * pool_.vertices().size() + 512);
  JsonStream json(out);
  json.begin_object().key("CityObjects").begin_object();
  for (const ObjectText& object : objects_) {
    json.key(object.id).raw(
        std::string_view(objects_text_).substr(object.begin, object.end - object.begin));
  }
  json.end_object().key("metadata");
  write_metadata(json);
  const kernel::Vec3 translate = scene_.origin + min_;
  json.key("transform").begin_object().key("scale").begin_array();
  json.number(kScale).number(kScale).number(kScale).end_array();
  json.key("translate").begin_array();
  json.number(translate.x).number(translate.y).number(translate.z).end_array().end_object();
  json.key("type").string("CityJSON").key("version").string("2.0");
  json.key("vertices").begin_array();
  for (const Quantised& q : pool_.vertices()) {
    json.begin_array().integer(q[0]).integer(q[1]).integer(q[2]).end_array();
  }
  json.end_array().end_object();
}

}  // namespace

std::string cityjson_reference_system(const std::string& crs) {
  static constexpr std::string_view kPrefix = "https://www.opengis.net/def/crs/";
  if (crs.starts_with(kPrefix) || crs.starts_with("http://www.opengis.net/def/crs/")) return crs;
  std::string upper = crs;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  std::string_view rest = upper;
  if (!rest.starts_with("EPSG:")) return {};
  rest.remove_prefix(5);
  if (rest.starts_with(':')) rest.remove_prefix(1);
  if (rest.empty() || rest.size() > 9 ||
      !std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return {};
  }
  return std::string(kPrefix) + "EPSG/0/" + std::string(rest);
}

std::string cityjson_text(const shape::Scene& input) {
  shape::Scene expanded;  // shared-mesh instances written as plain geometry
  Writer writer(shape::expand_instances(input, expanded));
  std::string out;
  writer.write(out);
  out += '\n';
  return out;
}

std::string write_cityjson(const shape::Scene& scene, const std::filesystem::path& path) {
  return write_file_atomically(path, cityjson_text(scene));
}

}  // namespace insula::io
