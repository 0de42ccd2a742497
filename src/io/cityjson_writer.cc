#include "io/cityjson_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <variant>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"

namespace insula::io {
namespace {

using nlohmann::json;
using Quantised = std::array<std::int64_t, 3>;
using RingIndices = std::vector<std::uint32_t>;

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

struct QuantisedHash {
  std::size_t operator()(const Quantised& q) const {
    std::size_t h = 0;
    for (std::int64_t c : q) h = h * 1000003U ^ std::hash<std::int64_t>()(c);
    return h;
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
  const std::vector<Quantised>& vertices() const { return vertices_; }

 private:
  std::unordered_map<Quantised, std::uint32_t, QuantisedHash> index_;
  std::vector<Quantised> vertices_;
};

json value_json(const shape::Value& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  if (const auto* d = std::get_if<double>(&value)) return std::isfinite(*d) ? json(*d) : json();
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  return nullptr;
}

json attributes_json(const shape::AttributeMap& attributes) {
  json out = json::object();
  for (const auto& [name, value] : attributes) out[name] = value_json(value);
  return out;
}

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
std::string unique_id(const std::string& base, std::set<std::string>& taken) {
  std::string id = base;
  for (int suffix = 2; taken.contains(id); ++suffix) id = base + "-" + std::to_string(suffix);
  taken.insert(id);
  return id;
}

// The faces of one part as rings of file vertex indices, with their surface type ("" = none).
struct PartSurfaces {
  std::vector<RingIndices> rings;
  std::vector<std::string_view> types;
};

class Writer {
 public:
  explicit Writer(const shape::Scene& scene);
  json build();

 private:
  Quantised quantise(kernel::Vec3 local) const;
  PartSurfaces surfaces(const kernel::Mesh& mesh);
  bool is_solid(const PartSurfaces& part) const;
  json geometry(const PartSurfaces& part) const;
  void add_building(const shape::Building& building, std::size_t index, json& objects);
  json metadata() const;

  const shape::Scene& scene_;
  kernel::Vec3 min_{};  // local minimum corner of every finite vertex
  VertexPool pool_;
  std::set<std::string> ids_;
};

Writer::Writer(const shape::Scene& scene) : scene_(scene) {
  kernel::Bounds3 bounds;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (const kernel::Vec3& p : part.mesh.positions()) {
        if (finite(p)) bounds.add(p);
      }
    }
  }
  if (!bounds.empty()) min_ = bounds.min;
}

Quantised Writer::quantise(kernel::Vec3 local) const {
  const kernel::Vec3 d = (local - min_) * kPerMeter;
  return {std::llround(d.x), std::llround(d.y), std::llround(d.z)};
}

PartSurfaces Writer::surfaces(const kernel::Mesh& mesh) {
  PartSurfaces out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    RingIndices ring;
    bool ok = true;
    for (std::uint32_t vertex : mesh.face(f)) {
      const kernel::Vec3 p = mesh.position(vertex);
      if (!finite(p) || !quantisable(p - min_)) ok = false;
      if (!ok) break;
      const std::uint32_t index = pool_.add(quantise(p));
      if (ring.empty() || ring.back() != index) ring.push_back(index);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (!ok || ring.size() < 3) continue;
    out.rings.push_back(std::move(ring));
    out.types.push_back(kernel::citygml_surface(mesh.tag(f).semantic));
  }
  return out;
}

// A Solid needs one closed, consistently outward-oriented 2-manifold shell: checked on the
// quantised rings, so the test sees exactly what a validator such as val3dity will see.
bool Writer::is_solid(const PartSurfaces& part) const {
  if (part.rings.size() < 4) return false;
  kernel::Mesh mesh;
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  for (const RingIndices& ring : part.rings) {
    RingIndices loop;
    for (std::uint32_t index : ring) {
      auto [it, inserted] = local.emplace(index, static_cast<std::uint32_t>(mesh.vertex_count()));
      if (inserted) {
        const Quantised& q = pool_.vertices()[index];
        mesh.add_vertex(
            {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])});
      }
      loop.push_back(it->second);
    }
    mesh.add_face(loop, {});
  }
  const kernel::MeshCheck check = kernel::check(mesh);
  return check.closed && check.oriented && check.non_manifold_edges == 0 && check.components == 1 &&
         kernel::volume(mesh) > 0;
}

json Writer::geometry(const PartSurfaces& part) const {
  json surfaces = json::array();
  json values = json::array();
  std::vector<std::string_view> seen;
  for (std::string_view type : part.types) {
    if (type.empty()) {
      values.push_back(nullptr);
      continue;
    }
    auto it = std::find(seen.begin(), seen.end(), type);
    if (it == seen.end()) {
      seen.push_back(type);
      surfaces.push_back({{"type", type}});
      it = seen.end() - 1;
    }
    values.push_back(it - seen.begin());
  }
  json boundaries = json::array();
  for (const RingIndices& ring : part.rings) boundaries.push_back(json::array({ring}));
  const bool solid = is_solid(part);
  json geometry = {{"type", solid ? "Solid" : "MultiSurface"},
                   {"lod", "2"},
                   {"boundaries", solid ? json::array({boundaries}) : boundaries}};
  if (!seen.empty()) {
    geometry["semantics"] = {{"surfaces", surfaces},
                             {"values", solid ? json::array({values}) : values}};
  }
  return geometry;
}

void Writer::add_building(const shape::Building& building, std::size_t index, json& objects) {
  const std::string id =
      unique_id(building.id.empty() ? "building" + std::to_string(index) : building.id, ids_);
  json object = {{"type", "Building"}};
  if (!building.attributes.empty()) object["attributes"] = attributes_json(building.attributes);
  json children = json::array();
  for (std::size_t p = 0; p < building.parts.size(); ++p) {
    const shape::Part& part = building.parts[p];
    const std::string part_id =
        unique_id(id + "-" + (part.name.empty() ? "part" + std::to_string(p) : part.name), ids_);
    json child = {{"type", object_type(part.kind)}, {"parents", {id}}};
    if (!part.attributes.empty()) child["attributes"] = attributes_json(part.attributes);
    const PartSurfaces surfaces_of_part = surfaces(part.mesh);
    if (!surfaces_of_part.rings.empty()) child["geometry"] = {geometry(surfaces_of_part)};
    objects[part_id] = std::move(child);
    children.push_back(part_id);
  }
  if (!children.empty()) object["children"] = children;
  objects[id] = std::move(object);
}

json Writer::metadata() const {
  json metadata = json::object();
  const std::string reference_system = cityjson_reference_system(scene_.crs);
  if (!reference_system.empty()) metadata["referenceSystem"] = reference_system;
  if (pool_.vertices().empty()) return metadata;
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
  json extent = json::array();
  for (const Quantised* corner : {&lo, &hi}) {
    for (std::size_t k = 0; k < 3; ++k) {
      extent.push_back(translate[k] + static_cast<double>((*corner)[k]) * kScale);
    }
  }
  metadata["geographicalExtent"] = extent;
  return metadata;
}

json Writer::build() {
  json objects = json::object();
  for (std::size_t b = 0; b < scene_.buildings.size(); ++b) {
    add_building(scene_.buildings[b], b, objects);
  }
  const kernel::Vec3 translate = scene_.origin + min_;
  json vertices = json::array();
  for (const Quantised& q : pool_.vertices()) vertices.push_back(q);
  return {{"type", "CityJSON"},
          {"version", "2.0"},
          {"transform",
           {{"scale", {kScale, kScale, kScale}},
            {"translate", {translate.x, translate.y, translate.z}}}},
          {"metadata", metadata()},
          {"CityObjects", objects},
          {"vertices", vertices}};
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

std::string cityjson_text(const shape::Scene& scene) {
  Writer writer(scene);
  return writer.build().dump() + "\n";
}

std::string write_cityjson(const shape::Scene& scene, const std::filesystem::path& path) {
  return write_file_atomically(path, cityjson_text(scene));
}

}  // namespace insula::io
