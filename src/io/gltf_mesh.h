// One glTF mesh assembled from the faces of one or more parts (a building's parts, or one part):
// faces triangulated (concave faces stay right) and shaded flat, grouped into a primitive per
// material; the primitives share one set of vertex attributes. Corners alike in every written
// attribute become one vertex as they are added (the same position on the quantization grid, or
// the same float32 position where positions are not quantized, with the same normal, uv and
// feature). At the end, triangles are reordered for the vertex cache (meshoptimizer, where a
// 16-vertex FIFO would load a vertex twice) and vertices for fetch, and positions quantized
// (KHR_mesh_quantization) to the grid kQuantizationStep where the mesh's extent fits 16 bits, so no
// vertex moves more than half a step (under 1 mm); the mesh's node then carries the offset and
// scale that undo it. Normals become normalized bytes. Each vertex may carry the feature id of its
// part (EXT_mesh_features).
#pragma once

#include <array>
#include <cfloat>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/float32_weld.h"
#include "io/gltf_buffers.h"
#include "io/triangulated.h"
#include "kernel/mesh.h"
#include "shape/scene.h"

namespace insula::io::gltf {

// 1/1024 m: a quantized position moves at most half a step along each axis, 0.85 mm in all (the
// issue asks under 1 mm); 16 bits then span 64 m.
inline constexpr double kQuantizationStep = 1.0 / 1024;

// The views every mesh of an asset appends to (created once per asset, see Buffers).
struct MeshViews {
  std::uint32_t quantized_positions;  // UNSIGNED_SHORT VEC3, 8 bytes a vertex
  std::uint32_t float_positions;      // FLOAT VEC3
  std::uint32_t quantized_normals;    // BYTE normalized VEC3, 4 bytes a vertex
  std::uint32_t float_normals;        // FLOAT VEC3
  std::uint32_t uvs;                  // FLOAT VEC2
  std::uint32_t features;             // SCALAR, 4 bytes a vertex (see MeshOptions)
  std::uint32_t short_indices;        // UNSIGNED_SHORT
  std::uint32_t int_indices;          // UNSIGNED_INT

  static MeshViews create(Buffers& buffers);
};

struct MeshOptions {
  // Positions on the quantization grid where the mesh's extent allows, normals as bytes, and
  // vertices welded on the grid (float32_weld.h); else floats throughout.
  bool quantize = true;
  // A _FEATURE_ID_0 attribute: vertices of different features are then never one.
  bool with_features = false;
  // Vertices numbered in the order the primitives first use them, material after material (the
  // order EXT_meshopt_compression's index codec stores in the fewest bytes), rather than in the
  // order they were made, part after part (one pass less over a tile's vertices).
  bool first_use_order = false;
  // The feature id attribute's type: UNSIGNED_SHORT while every id fits, else FLOAT (exact to
  // 2^24; EXT_mesh_features' note on 32-bit ids).
  Component feature_component = Component::kUnsignedShort;
};

// A primitive as written: its material, index accessor and the number of distinct feature ids.
struct PrimitiveRecord {
  std::uint32_t material = 0;
  std::uint32_t indices = 0;
  std::uint32_t feature_count = 0;
};

struct MeshRecord {
  std::uint32_t position = 0;
  std::uint32_t normal = 0;
  std::optional<std::uint32_t> uv;
  std::optional<std::uint32_t> feature;
  std::vector<PrimitiveRecord> primitives;
  // Positions are stored as (p - offset) / scale (Y-up) when quantized; else offset 0, scale 1.
  bool quantized = false;
  std::array<double, 3> offset{0, 0, 0};
  double scale = 1;
  // POSITION's bounds (glTF requires them) in the stored units: grid steps or float32 meters.
  std::array<double, 3> min{0, 0, 0};
  std::array<double, 3> max{0, 0, 0};
};

class MeshAssembler {
 public:
  // `material_texture`: per table material, whether it shows an image (its faces then get
  // texture coordinates fitted to each face).
  MeshAssembler(const MaterialTable& materials, std::vector<bool> material_textured);

  // Starts a mesh written with `options`; what was added and not emitted is dropped.
  void start(const MeshOptions& options);
  const MeshOptions& options() const { return options_; }
  // Drops what was added and not emitted; the options stay.
  void clear();
  // Room for meshes of `vertices`, `corners` (face loop entries) and `faces` more in all, to be
  // added before the next emit: a 3D Tiles tile's one mesh grew by copying megabytes otherwise.
  void reserve(std::size_t vertices, std::size_t corners, std::size_t faces);
  // Adds the faces of `mesh`, each vertex carrying `feature` (when features are written). `mesh`
  // is `part`'s geometry where it stands, or with `instance_frame` the mesh `part` instances
  // (before its placement; the part's uv map is then evaluated at placed positions). Returns
  // whether any triangle came of it: a part whose faces all collapse where they are written (on
  // the quantization grid, or in float32) adds nothing, and its `feature` may be given to the
  // next part.
  bool add(const kernel::Mesh& mesh, const shape::Part& part, std::uint32_t feature,
           bool instance_frame);
  bool empty() const { return lists_.empty(); }

  // Writes the mesh's vertices and indices to the views. Leaves the assembler empty, with the
  // options of start().
  MeshRecord emit(Buffers& buffers, const MeshViews& views);

 private:
  // A position corners use, once per scope (the feature's run when features are written, else
  // the mesh): its coordinates, Y-up, as float32 and as the nearest grid point (when on_grid), and
  // the first of the vertices at it (a chain through Vertex::next).
  struct Position {
    std::array<std::int64_t, 3> grid;
    Float3 coordinates;
    bool on_grid;
    std::uint32_t first_vertex;
    // The last part that looked the position up (its serial) and the first of its vertices here:
    // another of its vertices at a different place rounded to the same position (float32_weld.h).
    std::uint32_t part;
    std::uint32_t part_vertex;
  };
  // The grid and float32 bounds of the positions used, kept as they are added (a pass over a
  // tile's vertices at the end missed the cache on most of them).
  struct Bounds {
    bool on_grid = true;  // every position has a grid point (low and high are meaningful)
    std::array<std::int64_t, 3> low{INT64_MAX, INT64_MAX, INT64_MAX};
    std::array<std::int64_t, 3> high{INT64_MIN, INT64_MIN, INT64_MIN};
    std::array<double, 3> min{DBL_MAX, DBL_MAX, DBL_MAX};
    std::array<double, 3> max{-DBL_MAX, -DBL_MAX, -DBL_MAX};
    void add(const Position& position);
  };
  // A face's unit normal (Y-up), and as normalized bytes (the fourth is padding).
  struct FaceNormal {
    std::array<float, 3> normal;
    std::array<std::int8_t, 4> bytes;
  };
  // A vertex as it will be written: a position with one face's normal, a uv and a feature.
  struct Vertex {
    std::uint32_t position;  // into positions_
    std::uint32_t face;      // into face_normals_
    std::array<float, 2> uv;
    std::uint32_t feature;
    std::uint32_t next;  // the next vertex at the same position, ~0 for none
  };

  // A material's triangles (vertex numbers, three a triangle) and the runs of one feature in them
  // (a run ends at `end` in indices).
  struct FeatureRun {
    std::uint32_t feature;
    std::size_t end;
  };
  struct MaterialList {
    std::uint32_t material = 0;
    std::vector<std::uint32_t> indices;
    std::vector<FeatureRun> runs;
  };

  MaterialList& list_of(std::uint32_t material);
  void add_face(const kernel::Mesh& mesh, std::size_t face, MaterialList& list);
  void add_triangles(const kernel::Mesh& mesh,
                     std::span<const std::array<std::uint32_t, 3>> triangles, kernel::Vec3 newell,
                     std::vector<std::uint32_t>& indices);
  void contract_face(const kernel::Mesh& mesh, std::size_t face, kernel::Vec3 newell);
  bool enter_positions(const kernel::Mesh& mesh);
  void add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                   kernel::Vec3 newell, std::vector<std::uint32_t>& indices);
  void fit_uvs(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop, kernel::Vec3 newell);
  Position rounded_position(const kernel::Mesh& mesh, std::uint32_t vertex) const;
  std::uint32_t find_position(const Position& position);
  void grow_position_table();
  std::uint32_t vertex_at(std::uint32_t position, std::uint32_t face, std::array<float, 2> uv);
  bool same_normal(std::uint32_t face, std::uint32_t other) const;
  void begin_scope();

  // The steps of emit().
  void sort_lists();
  void quantize(MeshRecord& record);
  std::size_t order_for_cache();
  // The vertex written as number `w`.
  const Vertex& written(std::size_t w) const { return vertices_[renumbered_ ? vertex_of_[w] : w]; }
  void number_for_fetch();
  bool order_by_feature(std::span<std::uint32_t> indices, std::vector<FeatureRun>& runs);
  void sort_runs(std::span<std::uint32_t> indices, std::vector<FeatureRun>& runs);
  bool loads_each_once(std::span<const unsigned int> run);
  bool optimize_run(std::span<unsigned int> run);
  void write_attributes(Buffers& buffers, const MeshViews& views, std::size_t count,
                        MeshRecord& record);
  void write_primitives(Buffers& buffers, const MeshViews& views, std::size_t count,
                        MeshRecord& record);

  const MaterialTable& materials_;
  std::vector<bool> material_textured_;
  MeshOptions options_;
  std::vector<Position> positions_;
  std::vector<FaceNormal> face_normals_;
  std::vector<Vertex> vertices_;
  // By table material, in the order materials are first met (sorted at emit).
  std::vector<MaterialList> lists_;
  std::vector<MaterialList> spare_lists_;  // emptied lists, kept for their room
  std::size_t reserved_indices_ = 0;       // room for each list, as reserve() was told
  bool has_uv_ = false;
  Bounds bounds_;

  // The scope positions are looked up in: an open-addressing table of positions_ entries, stamped
  // with the scope they were entered in, so a new scope (a feature's run: most are small) empties
  // it without touching it.
  struct Slot {
    std::uint32_t position;
    std::uint32_t scope;
  };
  std::vector<Slot> slots_;
  std::uint32_t scope_ = 0;
  std::uint32_t scope_begin_ = 0;  // the scope's first entry in positions_
  bool scope_feature_set_ = false;
  std::uint32_t scope_feature_ = 0;

  // The part being added.
  const shape::Part* part_ = nullptr;
  bool instance_frame_ = false;
  std::vector<std::uint32_t> position_of_;  // by the part's vertex: its entry in positions_
  std::uint32_t part_serial_ = 0;           // counts the parts added (Position::part)
  bool collapsed_ = false;       // two of the part's vertices at different places share a position
  bool part_triangles_ = false;  // some face of the part gave a triangle
  double uv_scale_ = 0;          // solid_geometry's texture size, 0: none
  bool fit_uv_ = false;          // the face shows an image: UVs fit each face
  std::uint32_t feature_ = 0;

  // Scratch reused from face to face.
  FaceTriangulator triangulator_;
  std::vector<CornerTriangle> triangles_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> faces_by_material_;
  std::vector<kernel::Vec3> face_units_;  // the part's faces' unit normals (kernel::face_normal)
  Float32Weld weld_;
  std::vector<std::uint32_t> corners_;
  std::vector<std::uint32_t> corner_positions_;  // a face's corners' entries in positions_
  std::vector<kernel::Vec3> corner_places_;      // and their places
  std::vector<CornerTriangle> face_triangles_;
  std::vector<std::array<std::uint32_t, 3>> contracted_;  // contract_face(): triangles of vertices
  std::vector<std::uint32_t> corner_vertices_;
  std::vector<kernel::Vec2> face_uvs_;
  std::vector<std::array<float, 2>> corner_uvs_;
  // Scratch of emit(), kept from mesh to mesh.
  std::array<std::int64_t, 3> grid_low_{};  // the quantized mesh's grid origin
  std::vector<unsigned int> fetch_;         // number_for_fetch(): vertex -> written number
  bool renumbered_ = false;                 // vertices are written in another order than made
  std::vector<std::uint32_t> vertex_of_;    // when renumbered_: written number -> its vertex
  std::vector<unsigned int> sorted_indices_;
  std::vector<FeatureRun> sorted_runs_;
  std::vector<std::size_t> run_order_;
  std::vector<unsigned int> local_of_;  // order_by_feature: numbered vertex -> run's own numbering
  std::vector<unsigned int> global_of_;
  std::vector<unsigned int> loaded_at_;  // numbered vertex -> its load in the run checked
};

}  // namespace insula::io::gltf
