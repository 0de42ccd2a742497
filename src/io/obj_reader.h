// Wavefront OBJ reader for assets (docs/formats.md, "OBJ reader"). Reads `v` (x y z, an optional w
// or vertex colour is ignored), `f` (v, v/vt, v/vt/vn, v//vn; negative indices count back from the
// last vertex), `o`, `g` and `usemtl`. Ignores vt, vn, vp, s, l, p, mtllib and comments; warns on
// other statements. Faces keep their n-gon loops. Diagnostics are `file:line:col` with codes
// OBJ001.. (docs/formats.md lists them); bad input never crashes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/mesh.h"

namespace insula::io {

struct ObjModel {
  kernel::Mesh mesh;  // every `v` of the file in order; face ids number the faces from 0
  // `usemtl` names in order of first use; a face's FaceTag::material is its index + 1 (0: none).
  std::vector<std::string> materials;
};

// Parses OBJ text. A face's semantic class comes from the current group (`g`) when its name, or
// the last '.'-separated component of it, is a class name such as "RoofSurface" (what write_obj
// writes), else from the current material's name the same way, else kNone. Fails when there is
// any error or no face; warnings may accompany a value.
base::Result<ObjModel> parse_obj(std::string_view text, const std::string& source_name);

// parse_obj without the material names.
base::Result<kernel::Mesh> read_obj(std::string_view text, const std::string& source_name);

}  // namespace insula::io
