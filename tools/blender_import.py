# Imports a model into an empty Blender scene and prints what a user would see, as JSON on one line
# starting with "IMPORTED ": the mesh objects' names, the scene's bounding box in Blender's
# coordinates (Z up), the number of materials, and each object's custom properties (glTF extras
# arrive there; only values that are numbers or text). The check that an output opens upright and
# whole in the modelling tool users open it in (issue 21).
#   blender -b --factory-startup --python tools/blender_import.py -- MODEL.obj|MODEL.glb
import json
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still names numpy.bool, which numpy 1.24 removed (a
# packaging mismatch): give it the builtin back before the importer loads.
if "bool" not in numpy.__dict__:
    numpy.bool = bool


def main():
    path = sys.argv[sys.argv.index("--") + 1]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.lower().endswith(".obj"):
        # Blender's own defaults for OBJ: Y up, -Z forward (what Maya and three.js assume too).
        bpy.ops.wm.obj_import(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    lo = [float("inf")] * 3
    hi = [float("-inf")] * 3
    for obj in meshes:
        for corner in obj.bound_box:
            world = obj.matrix_world @ Vector(corner)
            for k in range(3):
                lo[k] = min(lo[k], world[k])
                hi[k] = max(hi[k], world[k])
    print("IMPORTED " + json.dumps({
        "objects": sorted(o.name for o in meshes),
        "min": lo,
        "max": hi,
        "materials": len(bpy.data.materials),
        "properties": {o.name: {k: o[k] for k in o.keys() if isinstance(o[k], (int, float, str))}
                       for o in meshes},
    }))


main()
