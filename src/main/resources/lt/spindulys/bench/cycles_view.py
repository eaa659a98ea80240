# Written by `render bench` (bench/PeerInputs) into a scratch folder and run as
#   blender -b --factory-startup -noaudio -P cycles_view.py -- ARGS
# Renders one bench view with Cycles on the CPU: OBJ meshes in grey Lambert 0.8 with flat
# normals, a pinhole camera, one point light without radius (hard shadows), black background,
# 1 sample per pixel, direct light only. ARGS (coordinates as in the OBJ files, +Y up):
#   --mesh FILE (once per mesh)  --image OUT.tga  --threads N  --size W H
#   --eye X Y Z  --at X Y Z  --vfov DEGREES  --light X Y Z  --watts W
# Blender is +Z up: the OBJ importer maps (x, y, z) to (x, -z, y), and so does to_blender().
# Prints "CYCLES_VIEW import_s A render_call_s B"; Cycles' own status lines give the sampling time.
import math
import sys
import time

import bpy
from mathutils import Vector


def options(argv):
    opts = {"mesh": []}
    i = 0
    counts = {"mesh": 1, "image": 1, "threads": 1, "size": 2, "eye": 3, "at": 3, "vfov": 1, "light": 3, "watts": 1}
    while i < len(argv):
        key = argv[i][2:]
        if not argv[i].startswith("--") or key not in counts:
            raise SystemExit("cycles_view.py: unknown argument " + argv[i])
        values = argv[i + 1:i + 1 + counts[key]]
        i += 1 + counts[key]
        if key == "mesh":
            opts["mesh"].append(values[0])
        elif key == "image":
            opts[key] = values[0]
        else:
            opts[key] = [float(v) for v in values]
    return opts


def to_blender(p):
    return Vector((p[0], -p[2], p[1]))


o = options(sys.argv[sys.argv.index("--") + 1:])
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

t0 = time.perf_counter()
meshes = []
for path in o["mesh"]:
    known = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=path, forward_axis="NEGATIVE_Z", up_axis="Y")
    meshes.extend(x for x in bpy.data.objects if x not in known)
t1 = time.perf_counter()

grey = bpy.data.materials.new("bench_grey")
grey.use_nodes = True
nodes = grey.node_tree.nodes
for n in list(nodes):
    if n.type != "OUTPUT_MATERIAL":
        nodes.remove(n)
diffuse = nodes.new("ShaderNodeBsdfDiffuse")
diffuse.inputs["Color"].default_value = (0.8, 0.8, 0.8, 1.0)
grey.node_tree.links.new(diffuse.outputs["BSDF"], nodes["Material Output"].inputs["Surface"])
for m in meshes:
    m.data.materials.clear()
    m.data.materials.append(grey)
    m.data.polygons.foreach_set("use_smooth", [False] * len(m.data.polygons))

camera = bpy.data.cameras.new("bench_camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = math.radians(o["vfov"][0])
camera_object = bpy.data.objects.new("bench_camera", camera)
scene.collection.objects.link(camera_object)
camera_object.location = to_blender(o["eye"])
camera_object.rotation_euler = (to_blender(o["at"]) - to_blender(o["eye"])).to_track_quat("-Z", "Y").to_euler()
scene.camera = camera_object

light = bpy.data.lights.new("bench_light", "POINT")
light.energy = o["watts"][0]
light.shadow_soft_size = 0.0
light_object = bpy.data.objects.new("bench_light", light)
scene.collection.objects.link(light_object)
light_object.location = to_blender(o["light"])

world = bpy.data.worlds.new("bench_black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

render = scene.render
render.engine = "CYCLES"
render.resolution_x, render.resolution_y = (int(v) for v in o["size"])
render.resolution_percentage = 100
render.threads_mode = "FIXED"
render.threads = int(o["threads"][0])
render.image_settings.file_format = "TARGA_RAW"
render.filepath = o["image"]
cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = 1
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.max_bounces = 0
cycles.diffuse_bounces = cycles.glossy_bounces = cycles.transmission_bounces = 0
cycles.volume_bounces = cycles.transparent_max_bounces = 0
cycles.caustics_reflective = cycles.caustics_refractive = False
cycles.filter_width = 0.01
cycles.seed = 0
cycles.use_auto_tile = False
scene.view_settings.view_transform = "Standard"

t2 = time.perf_counter()
bpy.ops.render.render(write_still=True)
t3 = time.perf_counter()
print("CYCLES_VIEW import_s %.3f render_call_s %.3f" % (t1 - t0, t3 - t2))
