// 3D Tiles 1.1 writer (docs/formats.md, "3D Tiles"; issue 17): `DIR/tileset.json` and one GLB per
// leaf tile in `DIR/tiles/`. Buildings are grouped by location (io/tile_tree.h); a leaf tile's GLB
// holds its buildings in local coordinates around the tile's centre, placed on the globe by the
// tile's `transform` (io/crs.h ecef_frames: the scene's CRS to ECEF with PROJ, so the projection's
// grid convergence and scale are taken along), as one node and one mesh (a primitive per
// material: few draw calls) whose every part is a feature (EXT_mesh_features) with its row in the
// property table (io/gltf_metadata.h): its name and kind, `building` (its building's id) and its
// building's attributes where the part has none of its own. Every tile has a `region` bounding
// volume (radians and ellipsoidal heights); inner tiles are empty, refine REPLACE, and their
// geometric error is an eighth of their cell's diagonal, so a viewer loads a leaf when the camera
// comes within a few kilometres of it. The scene's z is taken as the height above the WGS 84
// ellipsoid. Output is deterministic, whatever the thread count.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/gltf_writer.h"
#include "io/tile_tree.h"
#include "shape/scene.h"

namespace insula::io {

struct TilesetOptions {
  std::size_t tile_faces = 50000;  // a tile splits while its buildings have more faces
  // Coarse parent tiles: an inner tile over at most this many buildings shows each as a block (its
  // bounding box), for views from afar; 0: inner tiles stay empty.
  std::size_t block_buildings = 0;
  // write_tileset(): a building's parts alike in name, kind, attributes and uv map are one feature
  // (shape::merge_alike_parts), as a CGA scene's tiles have them when written tile by tile.
  bool merge_alike_parts = false;
};

// The folder of the tiles of `tileset_json`: its sibling "tiles".
std::filesystem::path tiles_folder(const std::filesystem::path& tileset_json);

// Writes a tileset tile by tile, so that a city need not be in memory at once: plan() groups the
// buildings-to-be by their plan boxes, write_tile() takes each leaf's buildings when they are made
// (from any thread, each leaf once), finish() writes tileset.json.
class TilesetWriter {
 public:
  // `origin` and `crs`: the buildings' local coordinates are world - origin in `crs`.
  // The tiles' GLBs are written with `gltf` (its `nodes` is ignored: a tile is one node).
  TilesetWriter(std::filesystem::path tileset_json, std::string crs, kernel::Vec3 origin,
                std::vector<shape::Material> materials, GltfOptions gltf = {},
                TilesetOptions options = {});

  // Writes the tiles into `folder` instead of tiles_folder() (a staging folder the caller renames
  // before finish(): a run killed midway leaves the earlier tileset as it was). Before plan().
  void stage_tiles_in(std::filesystem::path folder) { tile_folder_ = std::move(folder); }

  // Plans the tiles of `items` (plan boxes in local coordinates, weights: faces) and places each
  // leaf on the globe. Empty string on success, else the reason (no CRS, PROJ cannot place it).
  std::string plan(std::span<const TileItem> items);
  std::size_t leaf_count() const { return leaves_.size(); }
  // The items of leaf `leaf`, ascending.
  const std::vector<std::size_t>& leaf_items(std::size_t leaf) const;
  // Writes leaf `leaf`'s GLB from its buildings (local coordinates). Thread-safe for distinct
  // leaves. `materials`, when given, is the table the buildings' faces index instead of the
  // writer's own (a front-end that finds its materials as it builds, tile by tile). Empty string
  // on success, else the reason naming the file.
  std::string write_tile(std::size_t leaf, const std::vector<const shape::Building*>& buildings,
                         const std::vector<shape::Material>* materials = nullptr);
  // The same with buildings the tile may take apart (no copy of their meshes).
  std::string write_tile(std::size_t leaf, std::vector<shape::Building>&& buildings,
                         const std::vector<shape::Material>* materials = nullptr);
  // The box of what write_tile() wrote for `leaf` (empty: nothing); a leaf written by another
  // process (MPI) is told here before finish().
  kernel::Bounds3 tile_box(std::size_t leaf) const { return leaves_[leaf].box; }
  void set_tile_box(std::size_t leaf, const kernel::Bounds3& box) { leaves_[leaf].box = box; }
  // The boxes of the leaf's buildings (kept only with TilesetOptions::block_buildings), likewise.
  const std::vector<kernel::Bounds3>& tile_blocks(std::size_t leaf) const {
    return leaves_[leaf].blocks;
  }
  void set_tile_blocks(std::size_t leaf, std::vector<kernel::Bounds3> blocks) {
    leaves_[leaf].blocks = std::move(blocks);
  }
  // Writes tileset.json once every leaf is written (a leaf without geometry is left out).
  std::string finish();

 private:
  struct Leaf {
    std::size_t node = 0;
    kernel::Vec3 centre;  // the tile's own origin, local coordinates
    kernel::Bounds3 box;  // of its written geometry, local coordinates
    std::array<double, 16> frame{};
    std::vector<kernel::Bounds3> blocks;  // its buildings' boxes, for coarse parents
  };
  // An inner tile's blocks, when it shows them: its own origin and frame.
  struct Parent {
    kernel::Vec3 centre;
    std::array<double, 16> frame{};
    bool written = false;
  };
  std::string plan_parents();
  std::string write_parents();

  std::filesystem::path path_;
  std::string crs_;
  kernel::Vec3 origin_;
  std::vector<shape::Material> materials_;
  GltfOptions gltf_;
  TilesetOptions options_;
  std::filesystem::path tile_folder_;
  TileTree tree_;
  std::vector<Leaf> leaves_;
  std::vector<Parent> parents_;  // by tree node (leaves unused), with block_buildings
};

// The faces a building shows (an instance counts its mesh's): a tile's weight.
std::size_t building_faces(const shape::Building& building);

// The whole scene at once. The scene needs a CRS. Empty string on success, else the reason, naming
// the file.
std::string write_tileset(const shape::Scene& scene, const std::filesystem::path& tileset_json,
                          const GltfOptions& gltf = {}, const TilesetOptions& options = {});

}  // namespace insula::io
