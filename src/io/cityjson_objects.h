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

#include "base/numbered_names.h"
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

// A vertex list: every distinct quantised point once, numbered in first-use order. Points come
// part by part and are numbered as they come, each once within its part (found in a small table
// of the part's own points); merge() then merges the numbers of a point that several parts use into
// its first. Looking each point up in a table of the whole city as it came cost a cache miss or
// two a point, the most of writing a city: merge() looks them up in one loop over the list, where
// the misses are prefetched far enough ahead to overlap.
class VertexPool {
 public:
  // Starts a part of at most `vertices` distinct points.
  void begin_part(std::size_t vertices);
  // The point's number, the same for the same point within the part. `hash`: its QuantisedHash.
  std::uint32_t add(const Quantised& q, std::uint64_t hash);
  // Forgets the points numbered `size` and later: the last the part added, which no face kept
  // (they collapsed on the grid). The part's table is then as it was when the list had `size`.
  void truncate(std::size_t size);
  // Merges the numbers of every point into its first (the list keeps the first of each point).
  // Returns the new number of each old one, or an empty list when no point had two.
  const std::vector<std::uint32_t>& merge();
  void reserve(std::size_t n);
  void clear();
  const std::vector<Quantised>& vertices() const { return vertices_; }
  // The least and the greatest of the points' coordinates, axis by axis (when there are points),
  // found by merge().
  const Quantised& low() const { return low_; }
  const Quantised& high() const { return high_; }

 private:
  static constexpr std::uint32_t kFreeNumber = UINT32_MAX;
  static constexpr std::uint64_t kFree = UINT64_MAX;
  static constexpr Quantised kNoLow{INT64_MAX, INT64_MAX, INT64_MAX};
  static constexpr Quantised kNoHigh{INT64_MIN, INT64_MIN, INT64_MIN};
  std::uint32_t number(const Quantised& q, std::uint64_t hash, std::uint32_t next);

  // The part's points by hash (a power of two, at most half of them used): their numbers.
  std::vector<std::uint32_t> part_slots_;
  // merge()'s table of the whole list by hash (a power of two, at most three quarters used): the
  // high half of a point's hash and its number.
  std::vector<std::uint64_t> slots_;
  std::vector<std::uint32_t> renumber_;
  std::vector<Quantised> vertices_;
  Quantised low_ = kNoLow;
  Quantised high_ = kNoHigh;
};

// Object ids given so far, found by open addressing on their hashes (a node-based set of strings
// cost an allocation and a cache miss per object).
class IdSet {
 public:
  // Adds `id` and returns the set's copy of it (which stays where it is as long as the set does),
  // or null when `id` was there already.
  const std::string* insert(std::string_view id);
  // Starts loading the table slot where insert(id) looks first.
  void prefetch(std::string_view id) const;
  // Room for `n` ids in all, so that adding them does not rehash.
  void reserve(std::size_t n);

 private:
  static constexpr std::uint64_t kFree = UINT64_MAX;
  // Files entry `index` of ids_, whose hash is `hash`.
  void place(std::uint64_t hash, std::uint32_t index);

  std::deque<std::string> ids_;       // a deque: adding an id does not move the others
  std::vector<std::uint64_t> slots_;  // high half of the hash, index into ids_
};

// Faces as rings of vertex indices (ring r is indices[ends[r - 1] .. ends[r])), with their
// semantic classes. One list for every part added: a part's faces are a range of rings.
struct Rings {
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> ends;
  std::vector<kernel::SemanticClass> classes;

  std::size_t size() const { return ends.size(); }
  std::span<const std::uint32_t> ring(std::size_t r) const {
    const std::size_t begin = r == 0 ? 0 : ends[r - 1];
    return std::span<const std::uint32_t>(indices).subspan(begin, ends[r] - begin);
  }
  void clear() {
    indices.clear();
    ends.clear();
    classes.clear();
  }
};

// The city objects of buildings. add_building() numbers the vertices (in the order the buildings
// come, into a pool) and keeps each part's rings; write_objects() then writes the objects' text
// straight in id order. A point p (local coordinates) becomes round((p - base) / kScale), so the
// file's transform translate is origin + base.
class CityObjects {
 public:
  explicit CityObjects(kernel::Vec3 base) : base_(base) {}

  // Adds the building (`index`: its position, naming an unnamed building "building<index>") and
  // its parts; returns the building's object id, unique among every id this object has given. A
  // part none of whose faces is left on the grid is no object (no id, not among the children); a
  // building all of whose parts are so stays, with its attributes and no children, like one
  // with no parts.
  // Parts that are shared-mesh instances are expanded. The building's and its parts' attributes
  // are read again by write_objects(): they must outlive that call.
  std::string add_building(const shape::Building& building, std::size_t index);
  // The members of "CityObjects" (an object, sorted by id) added since the last clear().
  void write_objects(JsonStream& json);
  // About the length of what write_objects() will write, for reserving room for it.
  std::size_t text_size_estimate() const { return text_size_; }
  // The "vertices" array.
  void write_vertices(JsonStream& json);
  const VertexPool& pool() const { return pool_; }
  VertexPool& pool() { return pool_; }
  // Forgets the objects and vertices (the ids given stay taken).
  void clear();
  // The ids of buildings that other writers give (other lines of a CityJSONSeq written tile by
  // tile): part ids avoid them, so ids stay unique across the writers.
  void avoid(std::shared_ptr<const std::unordered_set<std::string>> building_ids) {
    avoided_ = std::move(building_ids);
  }
  // Room for `rings` faces of `indices` corners in all, so the lists are not copied as they grow.
  void reserve_rings(std::size_t rings, std::size_t indices);
  // Room for `n` object ids in all.
  void reserve_ids(std::size_t n) { ids_.reserve(n); }
  // Starts loading what adding a building will read, some buildings ahead of buildings[b]: a
  // city's meshes lie all over memory, and fetching them while the buildings before are added
  // overlaps their cache misses. The parts (names and meshes' array pointers) come kPartsAhead
  // buildings ahead; then those pointers are read and the arrays loaded kMeshesAhead ahead (only
  // the positions when `positions_only`). Distances that measured best on a district of 10,000
  // buildings.
  static constexpr std::size_t kPartsAhead = 8;
  static constexpr std::size_t kMeshesAhead = 4;
  static void prefetch_ahead(const std::vector<shape::Building>& buildings, std::size_t b,
                             bool positions_only = false);

 private:
  // A city object as added, its text written by write_objects(): what that needs is kept here, so
  // writing in id order does not go back to the scene's parts (scattered in memory) for it. A
  // part's geometry is rings [first, first + count) of rings_; a building's children are
  // objects_[first, first + count).
  struct Object {
    std::string_view id;      // ids_'s copy
    std::string_view parent;  // the building's id; empty for the building itself
    std::string_view type;    // "Building", "BuildingPart", ...
    const shape::AttributeMap* attributes = nullptr;  // null when there are none
    std::size_t first = 0;
    std::size_t count = 0;
    bool solid = false;
  };

  Quantised quantise(kernel::Vec3 local) const;
  void collect_surfaces(const kernel::Mesh& mesh);
  void pool_vertices(const kernel::Mesh& mesh);
  void unpool_since(std::span<const std::uint32_t> loop, std::size_t pooled);
  std::uint32_t number_locally(std::span<const std::uint32_t> corners) const;
  bool is_solid(std::size_t first, std::size_t end) const;
  bool numbered_as_last(std::size_t first, std::size_t end, std::size_t corners_begin) const;
  bool closed_shell(std::size_t first, std::size_t end, std::size_t corners_begin,
                    std::uint32_t locals) const;
  void number_vertices();
  double volume(std::size_t first, std::size_t end, std::uint32_t locals) const;
  static void prefetch_parts(const shape::Building& building);
  static void prefetch_meshes(const shape::Building& building, bool positions_only);
  void prefetch_object(const Object& object) const;
  void write_object(JsonStream& json, const Object& object);
  char* scratch(std::size_t size);
  std::string_view boundaries_text(std::size_t first, std::size_t end, bool solid);
  void collect_types(std::size_t first, std::size_t end);
  std::string_view values_text(bool solid);
  std::string_view surfaces_text();
  void write_geometry(JsonStream& json, const Object& part);

  void estimate_text(const Object& object);
  static void part_id_base(std::string& base, std::string_view id, const shape::Part& part,
                           std::size_t p);
  std::string_view unique_id(const std::string& base);
  std::string_view unique_part_id(const std::string& base);

  kernel::Vec3 base_;
  VertexPool pool_;
  IdSet ids_;
  // Where the search for a free `base-N` resumes, per base: buildings and parts apart, since a
  // part also refuses the avoided ids.
  base::NumberedNames building_names_{"-"};
  base::NumberedNames part_names_{"-"};
  std::shared_ptr<const std::unordered_set<std::string>> avoided_;
  Rings rings_;
  std::vector<Object> objects_;
  std::size_t text_size_ = 2;  // text_size_estimate()

  // Scratch reused from part to part.
  std::vector<std::string> part_ids_;       // a building's parts' ids before made unique
  std::vector<std::size_t> written_parts_;  // a building's parts with a face left, by position
  std::vector<std::uint32_t> pool_index_;   // mesh vertex -> pool vertex (kUnset, kUnwritable)
  std::vector<std::uint64_t> hashes_;       // mesh vertex -> its quantised point's hash
  std::vector<Quantised> points_;           // mesh vertex -> its quantised point
  std::unique_ptr<char[]> scratch_;         // the text of a geometry's "boundaries" or "values", or
  std::size_t scratch_size_ = 0;            // of the vertices
  std::vector<std::string_view> types_;     // a geometry's surface types
  std::vector<int> values_;                 // its rings' positions in types_ (-1: none)
  std::vector<std::string_view> surfaces_types_;  // the types whose "surfaces" text is kept
  std::string surfaces_text_;
  // The solid test's numbering of a part's vertices: pool vertex -> the test that numbered it (high
  // half) and its number (low half); corner -> its vertex's number.
  mutable std::vector<std::uint64_t> local_number_;
  mutable std::uint32_t stamp_ = 0;
  mutable std::vector<std::uint32_t> local_;
  mutable std::vector<std::uint32_t> local_vertex_;  // local number -> pool vertex
  mutable std::vector<kernel::Vec3> volume_points_;  // the volume's points, by local number
  // The solid test's edges: pairs of local numbers (lower << 32 | higher), and the ways each was
  // used (1: lower to higher, 2: back); its union-find of the local numbers.
  mutable std::vector<std::uint64_t> edges_;
  mutable std::vector<std::uint8_t> sides_;
  mutable std::vector<std::uint32_t> parent_;
  // The last part's local numbering and ring ends (from its first corner) the edge test saw, and
  // its verdict (see is_solid()).
  mutable std::vector<std::uint32_t> last_local_;
  mutable std::vector<std::size_t> last_ends_;
  mutable bool last_closed_ = false;
};

// What the CityJSON writer needs to know of a scene before writing it: the minimum corner of its
// finite vertices (local coordinates; (0, 0, 0) when none) and its sizes, to reserve room with.
// Shared-mesh instances are measured placed, as CityObjects::add_building() writes them.
struct SceneSize {
  kernel::Vec3 minimum;
  std::size_t vertices = 0;  // the meshes' vertices
  std::size_t faces = 0;
  std::size_t objects = 0;  // buildings and parts
};
SceneSize measure(const shape::Scene& scene);

// measure(scene).minimum.
kernel::Vec3 local_minimum(const shape::Scene& scene);

// The "transform" member's value: scale kScale, `translate`.
void write_transform(JsonStream& json, kernel::Vec3 translate);

}  // namespace insula::io::cityjson
