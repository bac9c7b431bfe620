"""A Cycles shot for the alpha and highlight tests (issue 34): a transparent film, a grey box
that turns, and a small emissive lamp (strength 12, scene-linear values far above 1) that
crosses the frame and passes behind the box for a few frames. 12 frames of 320x180 as RGBA half
EXR. Run by Blender 3.4 or later:

    blender -b --factory-startup -noaudio -P tests/scene/emissive_shot.py -- OUT_DIR

writes OUT_DIR/shot.0001.exr ... shot.0012.exr.
"""

import math
import os
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else "/tmp/spt-emissive-shot"
os.makedirs(out, exist_ok=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.samples = 16
scene.cycles.device = "CPU"
if hasattr(scene.cycles, "use_denoising"):
    scene.cycles.use_denoising = False
scene.cycles.seed = 1
scene.render.resolution_x, scene.render.resolution_y = 320, 180
scene.render.resolution_percentage = 100
scene.render.film_transparent = True
scene.frame_start, scene.frame_end = 1, 12
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "16"
scene.render.image_settings.color_mode = "RGBA"
scene.render.image_settings.exr_codec = "ZIP"
scene.view_settings.view_transform = "Standard"

cam_data = bpy.data.cameras.new("camera")
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
cam.location = (0, -9, 1.2)
cam.rotation_euler = (math.radians(84), 0, 0)
scene.camera = cam

sun_data = bpy.data.lights.new("sun", "SUN")
sun_data.energy = 3
sun = bpy.data.objects.new("sun", sun_data)
sun.rotation_euler = (math.radians(40), math.radians(20), 0)
scene.collection.objects.link(sun)


def material(name, color, emission=0.0):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = color
    if emission > 0:
        key = "Emission Color" if "Emission Color" in bsdf.inputs else "Emission"
        bsdf.inputs[key].default_value = color
        bsdf.inputs["Emission Strength"].default_value = emission
    return m


bpy.ops.mesh.primitive_cube_add(size=1.6, location=(0.2, 0, 1.0))
box = bpy.context.active_object
box.data.materials.append(material("box", (0.5, 0.45, 0.4, 1)))
box.rotation_euler = (0, 0, 0)
box.keyframe_insert("rotation_euler", frame=1)
box.rotation_euler = (0, 0, math.radians(40))
box.keyframe_insert("rotation_euler", frame=12)

bpy.ops.mesh.primitive_uv_sphere_add(radius=0.28, location=(-3.2, 1.5, 1.5))
lamp = bpy.context.active_object
lamp.data.materials.append(material("lamp", (1.0, 0.85, 0.6, 1), emission=12.0))
lamp.keyframe_insert("location", frame=1)
lamp.location = (3.2, 1.5, 2.1)  # behind the box halfway through, its top showing over it
lamp.keyframe_insert("location", frame=12)
for fc in lamp.animation_data.action.fcurves:
    for k in fc.keyframe_points:
        k.interpolation = "LINEAR"

scene.render.filepath = os.path.join(out, "shot.####")
bpy.ops.render.render(animation=True)
