# Run after a script from `skinlayer export --format blender --scene`, in the same Blender call:
#   blender -b --factory-startup --python MATERIAL.py --python blender_lighting.py -- MODE SIZE SAMPLES OUT [X Y Z]
# Relights the preview scene for the Blender comparison test (tests/app/export/blender_render_test.cpp) and renders
# it in Cycles on the CPU: MODE "furnace" is a white world of radiance 1 and no light; MODE "sun" is a black world and
# a sun of irradiance 1 (W/m^2, delta: angle 0) shining from the direction X Y Z (toward the light, world space).
# Nothing between the BSDF and the pixel: no denoising, adaptive sampling, clamping, glossy filter or film filter
# wider than Cycles' minimum. Writes OUT as text: "SIZE SIZE" then one "R G B" line per pixel, rows from the bottom,
# linear radiance.
import sys

import bpy
import mathutils

arguments = sys.argv[sys.argv.index("--") + 1:]
mode, size, samples, out = arguments[0], int(arguments[1]), int(arguments[2]), arguments[3]
scene = bpy.context.scene

for obj in list(scene.objects):
    if obj.type == "LIGHT":
        bpy.data.objects.remove(obj, do_unlink=True)
background = scene.world.node_tree.nodes["Background"]
background.inputs["Strength"].default_value = 1.0
if mode == "furnace":
    background.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
elif mode == "sun":
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    toward_light = mathutils.Vector([float(v) for v in arguments[4:7]]).normalized()
    sun = bpy.data.objects.new("test sun", bpy.data.lights.new("test sun", type="SUN"))
    sun.data.energy = 1.0
    sun.data.angle = 0.0
    # A sun shines along its local -z: turn +z toward the light.
    sun.rotation_euler = toward_light.to_track_quat("Z", "Y").to_euler()
    scene.collection.objects.link(sun)
else:
    raise SystemExit("MODE must be furnace or sun")

cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = samples
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.sample_clamp_direct = 0.0
cycles.sample_clamp_indirect = 0.0
cycles.blur_glossy = 0.0
cycles.filter_width = 0.01
cycles.seed = 1
scene.render.resolution_x = scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out + ".exr"
bpy.ops.render.render(write_still=True)

image = bpy.data.images.load(out + ".exr")
pixels = list(image.pixels)
with open(out, "w") as text:
    text.write(f"{image.size[0]} {image.size[1]}\n")
    for k in range(0, len(pixels), 4):
        text.write(f"{pixels[k]:.7g} {pixels[k + 1]:.7g} {pixels[k + 2]:.7g}\n")
