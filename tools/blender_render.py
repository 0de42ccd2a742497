# Renders a model as Blender 3.4 shows it after import (issue 21: "screenshots from both, looked
# at"): imports a GLB or OBJ into an empty scene, points a camera at it from the south-west above,
# lights it with a sun and renders with Cycles on the CPU (16 samples, no denoiser: Debian's
# Blender is built without OpenImageDenoise).
#   blender -b --factory-startup --python tools/blender_render.py -- MODEL.glb|MODEL.obj OUT.png
import math
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 glTF importer still names numpy.bool (tools/blender_import.py).
if "bool" not in numpy.__dict__:
    numpy.bool = bool
from mathutils import Vector
args = sys.argv[sys.argv.index("--") + 1:]
path, out = args[0], args[1]
bpy.ops.wm.read_factory_settings(use_empty=True)
if path.lower().endswith(".obj"):
    bpy.ops.wm.obj_import(filepath=path)
else:
    bpy.ops.import_scene.gltf(filepath=path)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
lo = Vector((1e9,)*3); hi = Vector((-1e9,)*3)
for o in meshes:
    for c in o.bound_box:
        w = o.matrix_world @ Vector(c)
        lo = Vector(map(min, lo, w)); hi = Vector(map(max, hi, w))
centre = (lo + hi) / 2; size = max(hi - lo)
cam = bpy.data.objects.new("cam", bpy.data.cameras.new("cam"))
bpy.context.scene.collection.objects.link(cam)
cam.location = centre + Vector((-1.2, -1.6, 1.0)) * size
d = centre - cam.location
cam.rotation_euler = d.to_track_quat('-Z', 'Y').to_euler()
cam.data.lens = 35
cam.data.clip_end = 10 * size + 100  # the default 100 m would cut a district away
bpy.context.scene.camera = cam
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 4; sun.rotation_euler = (math.radians(50), 0, math.radians(-40))
bpy.context.scene.collection.objects.link(sun)
world = bpy.data.worlds.new("w"); bpy.context.scene.world = world
world.use_nodes = True; world.node_tree.nodes["Background"].inputs[1].default_value = 0.6
s = bpy.context.scene
s.render.engine = 'CYCLES'; s.cycles.samples = 16; s.cycles.device = 'CPU'; s.cycles.use_denoising = False
s.render.resolution_x = 640; s.render.resolution_y = 480
s.render.filepath = out
bpy.ops.render.render(write_still=True)
print("RENDERED", out, len(meshes))
