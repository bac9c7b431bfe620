"""Blender test: "Paint to strokes" through the operator (blocking path) on a real still, the
import checked against `spt info --json --frames`, the unedited export rendered bit-identically
by `spt render`, and Cancel of a running paint. Skips (77) until spt paint works."""

import json
import os
import subprocess
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402

zip_path, spt, work, media = C.args()
still = os.path.join(media, "stills", "chelsea.png")
if not C.spt_works(spt, "paint") or not os.path.isfile(still):
    print(f"SKIP: needs a working 'spt paint' ({spt or 'not built'}) and {still}")
    sys.exit(C.SKIP)
C.install(zip_path, spt)
from spt_grease_pencil.blender import spt_tool  # noqa: E402

scene = bpy.context.scene
st = scene.spt_paint
st.source = 'FILE'
st.filepath = still
out = os.path.join(work, "painted.spt")
if os.path.exists(out):
    os.unlink(out)
st.output = out
st.sets = 3
st.max_strokes = 600
st.seed = 3
t = time.time()
r = bpy.ops.spt.paint_strokes(blocking=True)
print(f"paint + import: {time.time() - t:.1f} s")
C.check(r == {'FINISHED'}, f"paint operator returned {r}")
obj = bpy.context.active_object
C.check(obj is not None and obj.type == 'GPENCIL', "the painting was imported")

info = json.loads(subprocess.run([spt, "info", out, "--json", "--frames"], capture_output=True,
                                 text=True, check=True).stdout)
C.check((scene.render.resolution_x, scene.render.resolution_y) == (info["canvas"]["width"], info["canvas"]["height"]),
        "canvas size")
C.check(len(obj.data.materials) == len(info["templates"]) + 1, "one material per template (+ curves)")
frames = info["frame_list"]
C.check(scene.frame_end - scene.frame_start + 1 == len(frames) == info["frames_found"], "frame count")
for fr in frames:
    number = scene.frame_start + fr["index"]
    n = sum(len(f.strokes) for l in obj.data.layers for f in l.frames if f.frame_number == number)
    C.check(n == fr["live"], f"frame {fr['index']}: {n} strokes, spt info says {fr['live']}")
C.check(all(l.info.startswith("set ") for l in obj.data.layers), "layers are stroke sets")

# Unedited export (range-coded through spt pack) renders bit-identically.
exp = os.path.join(work, "exported.spt")
r = bpy.ops.export_scene.spt(filepath=exp)
C.check(r == {'FINISHED'}, f"export returned {r}")
# Stroke lists first (independent of the renderer): both files through spt pack --stored.
from spt_grease_pencil.io import read_file  # noqa: E402
lists = []
for name in ("painted.spt", "exported.spt"):
    st_path = os.path.join(work, name + ".stored")
    subprocess.run([spt, "pack", os.path.join(work, name), "--stored", "-o", st_path], check=True)
    lists.append(list(read_file(st_path).live_lists()))
C.check(lists[0] == lists[1], "the exported painting holds the same strokes in the same order")
print(f"stroke lists identical: {sum(map(len, lists[0]))} strokes")
for name in ("painted.spt", "exported.spt"):
    p = subprocess.run([spt, "render", os.path.join(work, name), "-o", os.path.join(work, name + ".png")],
                       capture_output=True, text=True)
    C.check(p.returncode == 0, f"spt render {name}: {p.stderr}")
a = open(os.path.join(work, "painted.spt.png"), "rb").read()
b = open(os.path.join(work, "exported.spt.png"), "rb").read()
C.check(a == b, "the exported painting renders bit for bit like spt's")

# Cancel stops the subprocess and leaves no output file.
big = os.path.join(work, "cancelled.spt")
job = spt_tool.PaintJob(spt, still, big, {"max_strokes": 200000, "seed": 1})
time.sleep(1.0)
job.cancel()
C.check(job.poll() is not None, "spt paint stopped")
C.check(not os.path.exists(big), "no half-written output after Cancel")
print("OK")
