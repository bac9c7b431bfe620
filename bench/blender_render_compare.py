"""How close Blender's own render of an imported painting is to `spt render` (the viewport and
F12 show Grease Pencil, not spt's renderer). Run through tests/blender/run_blender.sh by
blender_render_compare.sh; args after --: ZIP SPT WORKDIR; SPT_BENCH_FILE is the painting.
Renders frame 0 with EEVEE at the canvas size and prints the PSNR against spt's render."""

import os
import subprocess
import sys

import bpy
import numpy as np

zip_path, spt, work = sys.argv[sys.argv.index("--") + 1:][:3]
path = os.environ["SPT_BENCH_FILE"]
import addon_utils  # noqa: E402
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
addon_utils.enable("spt_grease_pencil", default_set=True)
bpy.ops.wm.read_factory_settings(use_empty=True)
addon_utils.enable("spt_grease_pencil", default_set=True)
bpy.context.preferences.addons["spt_grease_pencil"].preferences.spt_path = spt
assert bpy.ops.import_scene.spt(filepath=path) == {'FINISHED'}
scene = bpy.context.scene
engines = [e.identifier for e in bpy.types.RenderSettings.bl_rna.properties['engine'].enum_items]
scene.render.engine = next(e for e in ("BLENDER_EEVEE_NEXT", "BLENDER_EEVEE") if e in engines)
scene.eevee.taa_render_samples = 16
scene.view_settings.view_transform = 'Standard'
scene.render.image_settings.file_format = 'PNG'
scene.render.filepath = os.path.join(work, "blender.png")
scene.frame_set(scene.frame_start)
bpy.ops.render.render(write_still=True)
ref = os.path.join(work, "spt.png")
subprocess.run([spt, "render", path, "-o", ref, "--frames", "0"], check=True, capture_output=True)


def load(p):
    img = bpy.data.images.load(p)
    w, h = img.size
    a = np.empty(w * h * 4, dtype=np.float32)
    img.pixels.foreach_get(a)
    return a.reshape(h, w, 4)[:, :, :3]


a, b = load(scene.render.filepath), load(ref)
mse = float(np.mean((a - b) ** 2))
psnr = 10 * np.log10(1.0 / mse) if mse > 0 else float("inf")
if os.environ.get("SPT_KEEP"):  # a folder to keep the render in, for a look
    import shutil
    shutil.copy(scene.render.filepath, os.path.join(os.environ["SPT_KEEP"], f"blender-{bpy.app.version_string[:3]}.png"))
print(f"BENCH render {bpy.app.version_string}: EEVEE against spt render: {psnr:.2f} dB PSNR")
