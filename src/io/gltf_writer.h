// glTF 2.0 writer (docs/formats.md, "glTF"): binary .glb or .gltf JSON with an embedded buffer.
// One node per building (name = id, attributes in `extras`) with one child node per part (name,
// kind and attributes in `extras`, one mesh with a primitive per material). glTF is Y-up: a local
// Z-up point (x, y, z) is stored as (x, z, -y). Positions stay local (float32 keeps them exact to
// well under a millimetre near the origin); the scene origin that takes them back to the input CRS
// is kept as doubles in the scene's `extras` ("origin", "crs"). Faces are triangulated with
// kernel::triangulate (concave faces stay right) and shaded flat: each face has its own vertices
// carrying its normal; vertices float32 cannot tell apart are written as one, and faces
// contracted over them, so closed shells stay closed (io/float32_weld.h). Indices are
// UNSIGNED_INT. Scene lights become KHR_lights_punctual lights with a node each; material images
// become embedded PNG textures, their faces getting TEXCOORD_0 that fit the image to each face.
// Output is deterministic.
#pragma once

#include <filesystem>
#include <string>

#include "shape/scene.h"

namespace insula::io {

// The bytes of a .glb file for `scene` (12-byte header, JSON chunk, BIN chunk when non-empty).
std::string glb_bytes(const shape::Scene& scene);

// The text of a .gltf file for `scene`, its buffer embedded as a base64 data URI.
std::string gltf_text(const shape::Scene& scene);

// Writes `path` atomically: .gltf (any case) as JSON text, anything else as binary .glb. Returns an
// empty string on success, else a message naming the file.
std::string write_gltf(const shape::Scene& scene, const std::filesystem::path& path);

}  // namespace insula::io
