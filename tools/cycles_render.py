"""Renders a glTF file with Blender's Cycles, set up as tools/cycles_compare.py sets up our
render of it: run inside Blender (Debian's `blender`, 3.4), never by hand:

    blender -b --factory-startup -P tools/cycles_render.py -- --gltf F --out F.pfm
        --camera "x y z yaw pitch" [--sky R] [--sun "dx dy dz irradiance"] [--size WxH]
        [--spp N] [--bounces N] [--distribution GGX|MULTI_GGX] [--spec-absorption 0|1]

Our coordinates are glTF's (+y up); Blender's importer turns them into its own (+z up) as
(x, y, z) -> (x, -z, y), so the camera and the sun are placed through the same map. The
camera is ours: vertical field of view 45 degrees, looking along (-cos yaw cos pitch,
sin pitch, -sin yaw cos pitch) with +y up (docs/scene-format.md). The world is a constant
radiance `sky`; the sun a delta light of the given irradiance (Cycles' sun strength is
irradiance in W/m^2, its angle 0 makes it a delta light) travelling along (dx, dy, dz).
Film: box filter of one pixel (ours: a uniform point in the pixel), no denoising, no
clamping, caustics on, every bounce limit `bounces`. The result is written as linear
RGB, rows bottom to top (PFM's order and Blender's)."""
import math
import struct
import sys

import bpy
import numpy
from mathutils import Vector

# Debian's Blender 3.4 glTF importer uses numpy.bool, an alias that Debian's numpy (1.24)
# no longer has: give it back before the importer runs.
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def args():
    a = sys.argv[sys.argv.index("--") + 1:]
    o = {"sky": "0.5", "sun": "", "size": "160x120", "spp": "256", "bounces": "8", "distribution": "GGX", "spec-absorption": "0"}
    for i in range(0, len(a), 2):
        o[a[i].lstrip("-")] = a[i + 1]
    return o


def to_blender(v):
    return Vector((v[0], -v[2], v[1]))


def main():
    o = args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=o["gltf"])
    # Single-scattering GGX, as the glTF specification's BSDF is (--distribution GGX), or
    # Cycles' multiple-scattering GGX (MULTI_GGX: Heitz et al. 2016's random walk on the
    # microsurface), against our Kulla-Conty compensation.
    for m in bpy.data.materials:
        for n in (m.node_tree.nodes if m.use_nodes else []):
            if n.type == "BSDF_PRINCIPLED":
                n.distribution = o["distribution"]
            # KHR_materials_volume: Blender 3.4's importer sets a Volume Absorption node of
            # colour attenuationColor and density 1 / attenuationDistance, whose absorption
            # is (1 - colour) density; the extension's is -ln(attenuationColor) /
            # attenuationDistance. --spec-absorption 1 rewrites the node to the extension's:
            # density k = max(-ln c) / d, colour 1 - (-ln c) / (k d), so (1 - colour) k = -ln(c) / d.
            if n.bl_idname == "ShaderNodeVolumeAbsorption" and o["spec-absorption"] == "1":
                c, d = list(n.inputs["Color"].default_value)[:3], n.inputs["Density"].default_value
                if d > 0:
                    sig = [-math.log(max(v, 1e-6)) * d for v in c]  # -ln(c) / distance
                    k = max(max(sig), 1e-9)
                    n.inputs["Density"].default_value = k
                    n.inputs["Color"].default_value = [1.0 - v / k for v in sig] + [1.0]
                    print("cycles_render: %s: absorption per unit length %s (the extension's)" % (m.name, " ".join("%.4g" % v for v in sig)))
    scene = bpy.context.scene
    w, h = map(int, o["size"].split("x"))
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = w, h
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    c = scene.cycles
    c.device = "CPU"
    c.samples = int(o["spp"])
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.transparent_max_bounces = int(o["bounces"])
    c.volume_bounces = 0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.seed = 1
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0

    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    s = float(o["sky"])
    bg.inputs["Color"].default_value = (s, s, s, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    scene.world = world

    px, py, pz, yaw, pitch = map(float, o["camera"].split())
    yr, pr = math.radians(yaw), math.radians(pitch)
    d = (-math.cos(yr) * math.cos(pr), math.sin(pr), -math.sin(yr) * math.cos(pr))
    cam = bpy.data.cameras.new("cam")
    cam.sensor_fit = "VERTICAL"
    cam.angle_y = math.radians(45.0)
    cam.clip_start, cam.clip_end = 1e-4, 1e6
    ob = bpy.data.objects.new("cam", cam)
    scene.collection.objects.link(ob)
    ob.location = to_blender((px, py, pz))
    ob.rotation_mode = "QUATERNION"
    ob.rotation_quaternion = to_blender(d).to_track_quat("-Z", "Y")
    scene.camera = ob

    if o["sun"]:
        dx, dy, dz, e = map(float, o["sun"].split())
        sun = bpy.data.lights.new("sun", "SUN")
        sun.energy = e
        sun.angle = 0.0
        sob = bpy.data.objects.new("sun", sun)
        scene.collection.objects.link(sob)
        sob.rotation_mode = "QUATERNION"
        sob.rotation_quaternion = to_blender((dx, dy, dz)).normalized().to_track_quat("-Z", "Y")

    exr = o["out"] + ".exr"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = exr
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(exr)
    px = list(img.pixels)  # RGBA floats, rows bottom to top, linear (an EXR)
    rgb = [px[i * 4 + k] for i in range(w * h) for k in range(3)]
    with open(o["out"], "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(struct.pack("<%df" % len(rgb), *rgb))
    # What the importer made of each material (for the comparison's notes).
    for m in bpy.data.materials:
        if not m.use_nodes:
            continue
        for n in m.node_tree.nodes:
            if n.type == "BSDF_PRINCIPLED":
                vals = {k: n.inputs[k].default_value for k in ("Metallic", "Roughness", "Specular", "Clearcoat", "Clearcoat Roughness",
                                                              "Sheen", "Transmission", "IOR", "Emission Strength") if k in n.inputs}
                linked = [i.name for i in n.inputs if i.is_linked]
                print("cycles_render: material %s: %s; linked %s; distribution %s" % (
                    m.name, ", ".join("%s %.3g" % (k, v) for k, v in vals.items()), linked, n.distribution))


main()
