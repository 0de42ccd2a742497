// The CityJSON city objects of buildings, shared by the CityJSON writer (io/cityjson_writer.h, one
// vertex list for the file) and the CityJSONSeq writer (io/cityjsonseq_writer.h, one vertex list
// per line). A building becomes one "Building" with its attributes and one child per part
// ("BuildingPart", "BuildingStorey", "BuildingRoom" or "BuildingInstallation"), each with an LoD 2
// "Solid" or "MultiSurface" and semantic surfaces; vertices are integers on a 1 mm grid
// (docs/formats.md, "CityJSON").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "io/json_stream.h"
#include "kernel/mesh.h"
#include "shape/scene.h"

namespace insula::io::cityjson {

using Quantised = std::array<std::int64_t, 3>;

constexpr double kScale = 0.001;  // 1 mm, the precision of survey-grade city models

// Mixes the three components (splitmix64 finaliser) so nearby grid points spread over buckets.
struct QuantisedHash {
  std::size_t operator()(const Quantised& q) const;
};

// A vertex list: every distinct quantised point once, numbered in first-use order. The points are
// found by open addressing in a flat table of their numbers (a node-based map cost a cache miss
// or two per corner, the most of writing a city).
class VertexPool {
 public:
  std::uint32_t add(const Quantised& q);
  void reserve(std::size_t n);
  void clear();
  const std::vector<Quantised>& vertices() const { return vertices_; }

 private:
  static constexpr std::uint64_t kFree = UINT64_MAX;
  void rehash(std::size_t slots);

  // A power of two, at most three quarters of them used (small enough to stay in cache): the high
  // half of a point's hash and its number.
  std::vector<std::uint64_t> slots_;
  std::vector<Quantised> vertices_;
};

// Object ids given so far, found by open addressing on their hashes (a node-based set of strings
// cost an allocation and a cache miss per object).
class IdSet {
 public:
  // Adds `id`; false when it was there already.
  bool insert(std::string_view id);

 private:
  static constexpr std::uint64_t kFree = UINT64_MAX;
  void place(std::string_view id, std::uint32_t index);

  std::deque<std::string> ids_;
  std::vector<std::uint64_t> slots_;  // high half of the hash, index into ids_
};

// The faces of one part as rings of vertex indices (ring r is indices[ends[r - 1] .. ends[r])),
// with their surface type ("" = none).
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

// Builds the city objects of buildings, one after the other, into a text buffer and their
// vertices into a pool. A point p (local coordinates) becomes round((p - base) / kScale), so the
// file's transform translate is origin + base.
class CityObjects {
 public:
  explicit CityObjects(kernel::Vec3 base) : base_(base) {}

  // Adds the building (`index`: its position, naming an unnamed building "building<index>") and
  // its parts; returns the building's object id, unique among every id this object has given.
  // Parts that are shared-mesh instances are expanded.
  std::string add_building(const shape::Building& building, std::size_t index);
  // The members of "CityObjects" (an object, sorted by id) added since the last clear().
  void write_objects(JsonStream& json);
  // The length of what write_objects() will write.
  std::size_t text_size() const;
  // The "vertices" array.
  void write_vertices(JsonStream& json) const;
  const VertexPool& pool() const { return pool_; }
  VertexPool& pool() { return pool_; }
  // Forgets the objects and vertices (the ids given stay taken).
  void clear();
  // The ids of buildings that other writers give (other lines of a CityJSONSeq written tile by
  // tile): part ids avoid them, so ids stay unique across the writers.
  void avoid(std::shared_ptr<const std::unordered_set<std::string>> building_ids) {
    avoided_ = std::move(building_ids);
  }
  // Room for `bytes` of objects' text, so that it is not reallocated (and copied) as it grows.
  void reserve_text(std::size_t bytes) { text_.reserve(bytes); }

 private:
  // One city object's compact JSON text, kept in text_ until the objects are sorted by id.
  struct ObjectText {
    std::string id;
    std::size_t begin = 0;
    std::size_t end = 0;
  };

  Quantised quantise(kernel::Vec3 local) const;
  void collect_surfaces(const kernel::Mesh& mesh);
  bool is_solid() const;
  double volume() const;
  void write_geometry(JsonStream& json) const;

  std::string unique_part_id(const std::string& base);

  kernel::Vec3 base_;
  VertexPool pool_;
  IdSet ids_;
  std::shared_ptr<const std::unordered_set<std::string>> avoided_;
  std::string text_;
  std::vector<ObjectText> objects_;

  // Scratch reused from part to part.
  PartSurfaces part_;
  std::vector<std::uint32_t> pool_index_;  // mesh vertex -> pool vertex (kUnset, kUnwritable)
  mutable std::vector<std::uint32_t> local_index_;  // pool vertex -> solid test's numbering
  mutable std::vector<std::uint32_t> local_stamp_;  // which solid test set local_index_
  mutable std::uint32_t stamp_ = 0;
  // The solid test's edges: local vertex v's out-edges are to_[first_[v] .. first_[v + 1]).
  mutable std::vector<std::uint32_t> first_;
  mutable std::vector<std::uint32_t> to_;
  mutable std::vector<std::uint32_t> cursor_;
  mutable std::vector<bool> reached_;
};

// The minimum corner of the scene's finite vertices (local coordinates), (0, 0, 0) when none.
kernel::Vec3 local_minimum(const shape::Scene& scene);

// The "transform" member's value: scale kScale, `translate`.
void write_transform(JsonStream& json, kernel::Vec3 translate);

}  // namespace insula::io::cityjson
