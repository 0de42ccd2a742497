// The world mesh of an export part, expanding shared-mesh instances (seed 001 §3.6 / §4.5:
// decorations "can therefore take advantage of instancing"). glTF writes one mesh per distinct
// Part::instance_of and a node per instance; every other writer calls expand_instances() once at
// its entry and then sees plain parts.
#pragma once

#include "kernel/mesh.h"
#include "shape/scene.h"

namespace insula::shape {

// The part's mesh in the building's local coordinates: `part.mesh`, or `*part.instance_of`
// placed by `part.instance_transform`.
kernel::Mesh part_world_mesh(const Part& part);
bool has_instances(const Scene& scene);
// `scene` itself when no part is an instance (no copy, so outputs of scenes without instances
// are unchanged); otherwise `storage`, filled with a copy of `scene` whose instance parts carry
// their expanded meshes.
const Scene& expand_instances(const Scene& scene, Scene& storage);

}  // namespace insula::shape
