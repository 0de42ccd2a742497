// 3D Tiles 1.1 writer (docs/formats.md, "3D Tiles"; issue 17): `DIR/tileset.json` and one GLB per
// leaf tile in `DIR/tiles/`. Buildings are grouped by location (io/tile_tree.h); a leaf tile's GLB
// holds its buildings in local coordinates around the tile's centre, placed on the globe by the
// tile's `transform` (io/crs.h ecef_frames: the scene's CRS to ECEF with PROJ, so the projection's
// grid convergence and scale are taken along), as one node and one mesh (a primitive per
// material: few draw calls) whose every part is a feature (EXT_mesh_features) with its row in the
// property table (io/gltf_metadata.h): its name and kind, `building` (its building's id) and its
// building's attributes where the part has none of its own.
// Every tile has a `region` bounding volume (radians and ellipsoidal heights); inner tiles are
// empty, refine REPLACE, and their geometric error is an eighth of their cell's diagonal, so a
// viewer loads a leaf when the camera comes within a few kilometres of it. The scene's z is taken
// as the height above the WGS 84 ellipsoid. Output is deterministic, whatever the thread count.
#pragma once

#include <filesystem>
#include <string>

#include "io/gltf_writer.h"
#include "shape/scene.h"

namespace insula::io {

struct TilesetOptions {
  GltfOptions gltf{};              // of the tiles (`nodes` is ignored)
  std::size_t tile_faces = 50000;  // a tile splits while its buildings have more faces
};

// The folder of the tiles of `tileset_json`: its sibling "tiles".
std::filesystem::path tiles_folder(const std::filesystem::path& tileset_json);

// Writes the tiles into tiles_folder(tileset_json) (which must not exist yet or be empty of
// anything else) and then tileset.json. The scene needs a CRS. Empty string on success, else the
// reason, naming the file.
std::string write_tileset(const shape::Scene& scene, const std::filesystem::path& tileset_json,
                          const TilesetOptions& options = {});

}  // namespace insula::io
