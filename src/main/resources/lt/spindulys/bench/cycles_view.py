# Written by `render bench` (bench/PeerInputs) into a scratch folder and run as
#   blender -b --factory-startup -noaudio -P cycles_view.py -- ARGS
# Renders one bench view with Cycles on the CPU: OBJ meshes in grey Lambert 0.8 with flat
# normals, a pinhole camera, one point light without radius (hard shadows), black background,
# 1 sample per pixel, direct light only. ARGS (coordinates as in the OBJ files, +Y up):
#   --mesh FILE (once per mesh)  --image OUT.tga  --threads N  --size W H
#   --eye X Y Z  --at X Y Z  --vfov DEGREES  --light X Y Z  --watts W
# Path tracing (all optional; the defaults are the view above):
#   --samples N  --bounces N  max_bounces and every kind's bounces N, caustics on, no clamp, no
#                glossy blur, 1-pixel box filter (as ours), light threshold 0
#   --mtl-colours  each imported material a diffuse BSDF of its own base colour (the MTL's Kd)
#                  instead of grey 0.8
#   --area X Y Z SX SY R G B  a one-sided rectangle light facing -Y (OBJ axes), SX along X, SY
#                  along Z, of radiance R G B; its power is radiance x 4 x area (--watts 0: no
#                  point light). Cycles' area lights do not show to camera rays.
#   --seed N  the sampling seed (default 0)
#   --pfm OUT.pfm  also write the linear image as a little-endian PFM (bottom row first)
# Blender is +Z up: the OBJ importer maps (x, y, z) to (x, -z, y), and so does to_blender().
# Prints "CYCLES_VIEW import_s A render_call_s B"; Cycles' own status lines give the sampling time.
import math
import sys
import time

import bpy
from mathutils import Vector


def options(argv):
    opts = {"mesh": [], "samples": [1], "bounces": None, "mtl-colours": False, "area": None, "pfm": None, "seed": [0]}
    i = 0
    counts = {"mesh": 1, "image": 1, "threads": 1, "size": 2, "eye": 3, "at": 3, "vfov": 1, "light": 3, "watts": 1,
              "samples": 1, "bounces": 1, "mtl-colours": 0, "area": 8, "pfm": 1, "seed": 1}
    while i < len(argv):
        key = argv[i][2:]
        if not argv[i].startswith("--") or key not in counts:
            raise SystemExit("cycles_view.py: unknown argument " + argv[i])
        values = argv[i + 1:i + 1 + counts[key]]
        i += 1 + counts[key]
        if key == "mesh":
            opts["mesh"].append(values[0])
        elif key == "mtl-colours":
            opts[key] = True
        elif key in ("image", "pfm"):
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



def diffuse_material(name, colour):
    """A material whose surface is one diffuse (Lambert, roughness 0) BSDF of the colour."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    for n in list(nodes):
        if n.type != "OUTPUT_MATERIAL":
            nodes.remove(n)
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (colour[0], colour[1], colour[2], 1.0)
    mat.node_tree.links.new(diffuse.outputs["BSDF"], nodes["Material Output"].inputs["Surface"])
    return mat


def base_colour(mat):
    """The imported material's base colour: the OBJ importer puts the MTL's Kd there."""
    if mat.use_nodes:
        for n in mat.node_tree.nodes:
            if n.type == "BSDF_PRINCIPLED":
                return tuple(n.inputs["Base Color"].default_value)[:3]
    return tuple(mat.diffuse_color)[:3]


grey = diffuse_material("bench_grey", (0.8, 0.8, 0.8))
for m in meshes:
    if o["mtl-colours"] and len(m.data.materials) > 0:
        for slot in range(len(m.data.materials)):
            old = m.data.materials[slot]
            m.data.materials[slot] = diffuse_material("bench_" + old.name, base_colour(old))
    else:
        m.data.materials.clear()
        m.data.materials.append(grey)
    m.data.polygons.foreach_set("use_smooth", [False] * len(m.data.polygons))

camera = bpy.data.cameras.new("bench_camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = math.radians(o["vfov"][0])
# Ours has no far clip; Blender's camera stops at 1000 units, less than the Cornell box's millimetres.
camera.clip_start, camera.clip_end = 1e-3, 1e7
camera_object = bpy.data.objects.new("bench_camera", camera)
scene.collection.objects.link(camera_object)
camera_object.location = to_blender(o["eye"])
camera_object.rotation_euler = (to_blender(o["at"]) - to_blender(o["eye"])).to_track_quat("-Z", "Y").to_euler()
scene.camera = camera_object

if o["watts"][0] > 0:
    light = bpy.data.lights.new("bench_light", "POINT")
    light.energy = o["watts"][0]
    light.shadow_soft_size = 0.0
    light_object = bpy.data.objects.new("bench_light", light)
    scene.collection.objects.link(light_object)
    light_object.location = to_blender(o["light"])

if o["area"] is not None:
    a = o["area"]
    radiance = a[5:8]
    peak = max(radiance)
    area = bpy.data.lights.new("bench_area", "AREA")
    area.shape = "RECTANGLE"
    area.size, area.size_y = a[3], a[4]
    # Cycles' area light of power P and area A emits the radiance P / (4 A) from its face (its
    # kernel's eval_fac is 0.25 / area), not the P / (pi A) of a Lambertian emitter of flux P; the
    # colour carries the hue, the power the brightest channel.
    area.color = tuple(c / peak for c in radiance)
    area.energy = peak * 4 * a[3] * a[4]
    area_object = bpy.data.objects.new("bench_area", area)
    scene.collection.objects.link(area_object)
    # A Blender area light faces its local -Z, which is the OBJ files' -Y (down) unrotated.
    area_object.location = to_blender(a[0:3])

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
cycles.samples = int(o["samples"][0])
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.max_bounces = 0
cycles.diffuse_bounces = cycles.glossy_bounces = cycles.transmission_bounces = 0
cycles.volume_bounces = cycles.transparent_max_bounces = 0
cycles.caustics_reflective = cycles.caustics_refractive = False
cycles.filter_width = 0.01
if o["bounces"] is not None:
    n = int(o["bounces"][0])
    cycles.max_bounces = n
    cycles.diffuse_bounces = cycles.glossy_bounces = cycles.transmission_bounces = n
    cycles.transparent_max_bounces = n
    cycles.caustics_reflective = cycles.caustics_refractive = True
    cycles.sample_clamp_direct = cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
cycles.seed = int(o["seed"][0])
cycles.use_auto_tile = False
scene.view_settings.view_transform = "Standard"

t2 = time.perf_counter()
bpy.ops.render.render(write_still=True)
t3 = time.perf_counter()
print("CYCLES_VIEW import_s %.3f render_call_s %.3f" % (t1 - t0, t3 - t2))

if o["pfm"] is not None:
    # The linear floats, read back from an uncompressed 32-bit EXR (a render result's pixels are not readable).
    settings = render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.exr_codec = "NONE"
    exr = o["pfm"] + ".exr"
    bpy.data.images["Render Result"].save_render(exr)
    img = bpy.data.images.load(exr)
    w, h = img.size
    px = img.pixels[:]
    import struct
    with open(o["pfm"], "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        rgb = [px[4 * i + c] for i in range(w * h) for c in range(3)]
        f.write(struct.pack("<%df" % len(rgb), *rgb))
    import os
    os.remove(exr)
