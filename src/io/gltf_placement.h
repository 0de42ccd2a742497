// Placements of glTF nodes and GPU instances (glTF 2.0 §3.5.3 "Transformations",
// EXT_mesh_gpu_instancing): an Insula placement (local Z-up, kernel::Transform) seen in glTF's
// Y-up frame, moved into a node that undoes position quantization, and split into translation,
// rotation and scale where it has no shear.
#pragma once

#include <array>
#include <optional>

#include "kernel/transform.h"

namespace insula::io::gltf {

// An affine map in glTF's frame: x -> L x + t, L by columns.
struct Affine {
  std::array<std::array<double, 3>, 3> columns{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::array<double, 3> translation{0, 0, 0};
};

// `t` (Z-up) in glTF's Y-up frame: C t C^-1 with C: (x, y, z) -> (x, z, -y).
Affine y_up(const kernel::Transform& t);

// `a` as seen from inside a node placed at `offset` with uniform `scale` (the dequantization of
// the node's own mesh): S^-1 T^-1 a.
Affine relative_to(const Affine& a, const std::array<double, 3>& offset, double scale);

// The node transform that undoes position quantization: x -> scale x + offset.
Affine dequantization(const std::array<double, 3>& offset, double scale);
// a after b.
Affine compose(const Affine& a, const Affine& b);

// The 16 numbers of a node's "matrix", column-major.
std::array<double, 16> matrix(const Affine& a);

struct Trs {
  std::array<double, 3> translation{};
  std::array<double, 4> rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w
  std::array<double, 3> scale{1, 1, 1};
};

// `a` as translation, rotation and (possibly negative) scale, or nothing when its columns are not
// orthogonal (a shear) or one is zero.
std::optional<Trs> decompose(const Affine& a);

}  // namespace insula::io::gltf
