// One glTF mesh assembled from the faces of one or more parts (a building's parts, or one part):
// faces triangulated (concave faces stay right) and shaded flat, grouped into a primitive per
// material; the primitives share one set of vertex attributes. At the end, vertices alike in every
// written attribute are merged (a hash table of their written bytes), triangles reordered for the
// vertex cache (meshoptimizer, where a 16-vertex FIFO would load a vertex twice) and vertices for
// fetch, and positions quantized (KHR_mesh_quantization) to the grid kQuantizationStep where the
// mesh's extent fits 16 bits, so no vertex moves more than half a step (under 1 mm); the mesh's
// node then carries the offset and scale that undo it. Normals become normalized bytes. Each
// vertex may carry the feature id of its part (EXT_mesh_features).
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
  bool quantize = true;
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

  void clear();
  // Room for meshes of `vertices`, `corners` (face loop entries) and `faces` more in all, to be
  // added before the next emit: a 3D Tiles tile's one mesh grew by copying megabytes otherwise.
  void reserve(std::size_t vertices, std::size_t corners, std::size_t faces);
  // Adds the faces of `mesh`, each vertex carrying `feature` (when features are written). `mesh`
  // is `part`'s geometry where it stands, or with `instance_frame` the mesh `part` instances
  // (before its placement; the part's uv map is then evaluated at placed positions).
  // `quantize`: vertices are welded on the quantization grid rather than float32's.
  void add(const kernel::Mesh& mesh, const shape::Part& part, std::uint32_t feature, bool quantize,
           bool instance_frame);
  bool empty() const { return indices_by_material_.empty(); }

  // Writes the mesh's vertices and indices to the views; `with_features`: a _FEATURE_ID_0
  // attribute. Leaves the assembler empty.
  MeshRecord emit(Buffers& buffers, const MeshViews& views, const MeshOptions& options,
                  bool with_features);

 private:
  // A vertex of an added mesh, placed: computed once however many corners use it.
  struct Source {
    std::array<double, 3> position;    // Y-up
    std::array<std::int64_t, 3> grid;  // the nearest quantization grid point, when on_grid
    bool on_grid;
  };
  // The grid and float32 bounds of the vertices added, kept as they are added (a pass over a
  // tile's vertices at the end missed the cache on most of them).
  struct Bounds {
    bool on_grid = true;  // every vertex has a grid point (low and high are meaningful)
    std::array<std::int64_t, 3> low{INT64_MAX, INT64_MAX, INT64_MAX};
    std::array<std::int64_t, 3> high{INT64_MIN, INT64_MIN, INT64_MIN};
    std::array<double, 3> min{DBL_MAX, DBL_MAX, DBL_MAX};
    std::array<double, 3> max{-DBL_MAX, -DBL_MAX, -DBL_MAX};
    void add(const Source& source);
  };
  // A face's unit normal (Y-up), and as normalized bytes (the fourth is padding).
  struct FaceNormal {
    std::array<float, 3> normal;
    std::array<std::int8_t, 4> bytes;
  };
  // A corner of a face, flat shaded.
  struct Vertex {
    std::uint32_t source;  // into sources_
    std::uint32_t face;    // into face_normals_
    std::array<float, 2> uv;
    std::uint32_t feature;
  };

  std::vector<std::uint32_t> spare_list();
  void add_face(const kernel::Mesh& mesh, std::size_t face, std::vector<std::uint32_t>& indices);
  void add_corners(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop,
                   kernel::Vec3 newell, std::vector<std::uint32_t>& indices);
  void fit_uvs(const kernel::Mesh& mesh, std::span<const std::uint32_t> loop, kernel::Vec3 newell);

  // Where each written attribute lies in a vertex's row (rows_): bytes from the row's start and
  // bytes long (0: not written).
  struct RowLayout {
    std::uint32_t stride = 0;
    std::array<std::uint32_t, 4> offset{};  // position, normal, uv, feature
    std::array<std::uint32_t, 4> size{};
    bool float_features = false;  // written as FLOAT, else UNSIGNED_SHORT
  };

  // The steps of emit().
  void gather_indices();
  void quantize(bool wanted, MeshRecord& record);
  void lay_out(const MeshRecord& record, const MeshOptions& options, bool with_features);
  void pack_rows(std::size_t begin, std::size_t end);
  void merge_rows();
  void find_representatives(std::size_t begin, std::size_t end);
  std::size_t merge_and_order();
  void number_for_fetch();
  bool order_by_feature(std::span<unsigned int> indices);
  bool loads_each_once(std::span<const unsigned int> run);
  bool optimize_run(std::span<unsigned int> run);
  void write_attributes(Buffers& buffers, const MeshViews& views, const MeshOptions& options,
                        std::size_t count, MeshRecord& record);
  void write_primitives(Buffers& buffers, const MeshViews& views, std::size_t count,
                        MeshRecord& record);

  const MaterialTable& materials_;
  std::vector<bool> material_textured_;
  std::vector<Source> sources_;
  std::vector<FaceNormal> face_normals_;
  std::vector<Vertex> vertices_;
  // Triangles by table material, in the order materials are first met (sorted at emit).
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> indices_by_material_;
  std::vector<std::vector<std::uint32_t>> spare_lists_;  // emptied lists, kept for their room
  bool has_uv_ = false;
  Bounds bounds_;

  // The part being added.
  const shape::Part* part_ = nullptr;
  bool instance_frame_ = false;
  std::uint32_t first_source_ = 0;   // the part's vertex 0 in sources_
  std::vector<unsigned char> used_;  // by the part's vertex: some corner uses it
  double uv_scale_ = 0;              // solid_geometry's texture size, 0: none
  bool fit_uv_ = false;              // the face shows an image: UVs fit each face
  std::uint32_t feature_ = 0;

  // Scratch reused from face to face.
  FaceTriangulator triangulator_;
  std::vector<CornerTriangle> triangles_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> faces_by_material_;
  Float32Weld weld_;
  std::vector<std::uint32_t> corners_;
  std::vector<kernel::Vec2> face_uvs_;
  std::vector<std::array<float, 2>> corner_uvs_;
  // Scratch of emit(), kept from mesh to mesh.
  std::vector<unsigned int> indices_;
  std::vector<std::size_t> ends_;           // end of each material's run in indices_
  std::array<std::int64_t, 3> grid_low_{};  // the quantized mesh's grid origin
  RowLayout layout_;
  // Each vertex's written attributes, layout_.stride bytes; never zeroed (pack writes every
  // byte), so a tile's megabytes of rows are written once.
  std::unique_ptr<unsigned char[]> rows_;
  std::size_t rows_capacity_ = 0;
  std::vector<std::uint32_t> slots_;            // merge_rows()'s hash table of vertices (~0: free)
  std::vector<std::uint32_t> representative_;   // vertex -> the first vertex alike
  std::vector<std::uint32_t> feature_of_;       // vertex -> its feature
  std::vector<unsigned int> class_of_;          // representative -> merged vertex (~0: none yet)
  std::vector<unsigned int> fetch_;             // merged vertex -> written vertex
  std::vector<std::uint32_t> row_of_;           // merged, then written vertex -> a vertex alike
  std::vector<std::uint32_t> vertex_features_;  // by merged, then written vertex
  std::vector<std::uint32_t> moved_features_;
  std::vector<std::uint32_t> moved_rows_;
  std::vector<std::array<unsigned int, 3>> sorted_triangles_;
  std::vector<unsigned int> local_of_;  // order_by_feature: merged vertex -> run's own numbering
  std::vector<unsigned int> global_of_;
  std::vector<unsigned int> loaded_at_;  // merged vertex -> its load in the run checked
};

}  // namespace insula::io::gltf
