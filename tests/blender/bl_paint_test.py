"""Blender test: "Paint to strokes" through the operator (blocking path) on short clips made here:
the scene's rendered frame sequence (scene.render.filepath frames) and a chosen file pattern,
plus a still. Each result is imported and checked against `spt info --json --frames` (GP frames
follow the video frames, strokes per frame), then exported unedited and every frame rendered by
`spt render` from both files and compared byte for byte. Fails without a working spt paint.
Cancel is tested without Blender in test_paint_job.py."""

import json
import os
import subprocess
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402
import bl_gp as G  # noqa: E402

zip_path, spt, work, media = C.args()
if not C.spt_works(spt, "paint"):
    print(f"FAIL: needs a working 'spt paint' ({spt or 'not built'})")
    sys.exit(C.SKIP)
C.install(zip_path, spt)
scene = bpy.context.scene


def write_clip(pattern, frames, w, h, phase):
    """Frames first..last of a small animation (a disc and a bar moving over a gradient) as 8-bit
    PNGs at pattern % frame number (Blender's image writer, no colour transform)."""
    y, x = np.mgrid[0:h, 0:w].astype(np.float32)
    for k in frames:
        t = k + phase
        img = np.zeros((h, w, 4), dtype=np.float32)
        img[..., 0] = x / w
        img[..., 1] = 0.3 + 0.4 * y / h
        img[..., 2] = 0.6
        img[..., 3] = 1.0
        disc = (x - (20 + 5 * t)) ** 2 + (y - h / 2) ** 2 < (h / 4) ** 2
        img[disc] = (0.9, 0.2, 0.1, 1.0)
        bar = (np.abs(x - w / 2) < 4) & (np.abs(y - (10 + 3 * t) % h) < 12)
        img[bar] = (0.05, 0.05, 0.3, 1.0)
        im = bpy.data.images.new(f"clip{k}", width=w, height=h, alpha=True)
        im.pixels.foreach_set(img[::-1].ravel())  # Blender rows are bottom first
        im.filepath_raw = pattern % k
        im.file_format = 'PNG'
        im.save()
        bpy.data.images.remove(im)


def paint(label, output, **settings):
    st = scene.spt_paint
    for k, v in settings.items():
        setattr(st, k, v)
    st.output = output
    st.sets = 3
    st.max_strokes = 300
    st.seed = 3
    if os.path.exists(output):
        os.unlink(output)
    before = set(bpy.data.objects)
    t = time.time()
    r = bpy.ops.spt.paint_strokes(blocking=True)
    print(f"{label}: paint + import {time.time() - t:.1f} s")
    C.check(r == {'FINISHED'}, f"{label}: paint operator returned {r}")
    new = [o for o in bpy.data.objects if o not in before and o.type == G.OBJECT_TYPE]
    C.check(len(new) == 1, f"{label}: the painting was imported as one Grease Pencil object")
    C.check(os.path.isfile(output), f"{label}: the painting was written to {output}")
    return new[0]


def check_import(label, obj, path, want_frames):
    info = json.loads(subprocess.run([spt, "info", path, "--json", "--frames"], capture_output=True,
                                     text=True, check=True).stdout)
    frames = info["frame_list"]
    C.check(len(frames) == info["frames_found"] == want_frames,
            f"{label}: {info['frames_found']} frames in the file, expected {want_frames}")
    C.check((scene.render.resolution_x, scene.render.resolution_y) == (info["canvas"]["width"], info["canvas"]["height"]),
            f"{label}: canvas size")
    C.check(scene.frame_end - scene.frame_start + 1 == want_frames, f"{label}: scene frame range follows the file")
    fps = scene.render.fps / scene.render.fps_base
    C.check(abs(fps - info["fps"]["value"]) < 1e-6, f"{label}: scene fps {fps} vs file {info['fps']['value']}")
    C.check(len(obj.data.materials) == len(info["templates"]) + 1, f"{label}: one material per template (+ curves)")
    for layer in obj.data.layers:
        numbers = sorted(f.frame_number for f in layer.frames)
        C.check(numbers == list(range(scene.frame_start, scene.frame_start + want_frames)),
                f"{label}: layer '{G.layer_names(obj)}' has GP frames {numbers}: one per video frame")
    for fr in frames:
        number = scene.frame_start + fr["index"]
        n = sum(G.stroke_count(f) for l in obj.data.layers for f in l.frames if f.frame_number == number)
        C.check(n == fr["live"], f"{label}: frame {fr['index']}: {n} strokes, spt info says {fr['live']}")
    return info


def check_export_renders_identically(label, obj, path):
    exp = os.path.join(work, label + ".exported.spt")
    bpy.context.view_layer.objects.active = obj
    r = bpy.ops.export_scene.spt(filepath=exp)  # range-coded through spt pack
    C.check(r == {'FINISHED'}, f"{label}: export returned {r}")
    outs = []
    for name, p in (("orig", path), ("exp", exp)):
        pat = os.path.join(work, f"{label}.{name}.####.png")
        # --start 0: files named by position (painted sequences keep their source numbers).
        p = subprocess.run([spt, "render", p, "-o", pat, "--start", "0"], capture_output=True, text=True)
        C.check(p.returncode == 0, f"{label}: spt render {name}: {p.stderr}")
        outs.append(pat.replace("####", "%04d"))
    n = scene.frame_end - scene.frame_start + 1
    for k in range(n):
        a, b = (open(o % k, "rb").read() for o in outs)
        C.check(a == b, f"{label}: frame {k} of the unedited export renders differently")
    sizes = os.path.getsize(path), os.path.getsize(exp)
    print(f"{label}: {n} frames render bit-identically; file {sizes[0]} bytes, export {sizes[1]} bytes")


# 1. The scene's rendered frame sequence: frames 1-8 of render/f_####.png (what F12 > Render
#    Animation writes for this output path), key frames every 4 frames.
os.makedirs(os.path.join(work, "render"), exist_ok=True)
scene.frame_start, scene.frame_end = 1, 8
scene.render.fps, scene.render.fps_base = 12, 1.0
scene.render.filepath = os.path.join(work, "render", "f_")
scene.render.image_settings.file_format = 'PNG'
write_clip(os.path.join(work, "render", "f_%04d.png"), range(1, 9), 96, 64, 0)
out = os.path.join(work, "rendered.spt")
obj = paint("rendered frames", out, source='RENDER', keyframe_interval=4)
info = check_import("rendered frames", obj, out, 8)
C.check(info["key_frames"][:2] == [0, 4] and len(info["key_frames"]) == 2,
        f"key frames every 4 frames: {info['key_frames']}")
C.check(info["fps"]["value"] == 12, "the scene's frame rate was passed to spt paint")
check_export_renders_identically("rendered", obj, out)

# 2. A chosen file pattern (6 other frames), key frames by spt's default interval.
os.makedirs(os.path.join(work, "clip"), exist_ok=True)
write_clip(os.path.join(work, "clip", "c.%04d.png"), range(1, 7), 80, 48, 3)
out = os.path.join(work, "pattern.spt")
obj = paint("file pattern", out, source='FILE', filepath=os.path.join(work, "clip", "c.####.png"), keyframe_interval=0)
check_import("file pattern", obj, out, 6)
check_export_renders_identically("pattern", obj, out)

# The painted clip edited: one stroke of frame 3 moved by 3 px (+X) exports as exactly that
# change, and the inter frames keep their motion coding (spt info: the same frame codings).
from spt_grease_pencil.io import read_file  # noqa: E402
out_stored = os.path.join(work, "pattern.stored.spt")
subprocess.run([spt, "pack", out, "--stored", "-o", out_stored], check=True)
orig_lists = list(read_file(out_stored).live_lists())
fi = 3
moved = None
for l in obj.data.layers:
    for s in G.strokes(G.frame(l, scene.frame_start + fi)):
        if s.ordinal >= 0 and len(s.points) == 4:
            moved = s.ordinal
            G.move(s, 0.003, 0.0)
            break
    if moved is not None:
        break
C.check(moved is not None, "found an imported quad to move")
exp = os.path.join(work, "pattern.moved.spt")
bpy.context.view_layer.objects.active = obj
C.check(bpy.ops.export_scene.spt(filepath=exp, stored=True) == {'FINISHED'}, "export of the edit")
got = list(read_file(exp).live_lists())
C.check(len(got) == len(orig_lists), "same frame count after the edit")
for k, (a, b) in enumerate(zip(orig_lists, got)):
    if k != fi:
        C.check(a == b, f"frame {k} is untouched by an edit of frame {fi}")
        continue
    diff = [(i, x, y) for i, (x, y) in enumerate(zip(a, b)) if x != y]
    C.check(len(a) == len(b) and len(diff) == 1 and diff[0][0] == moved, f"one stroke changed: {diff}")
    _, x, y = diff[0]
    C.check(y[4] - x[4] == 48 and y[5] == x[5] and y[:4] == x[:4] and y[6:] == x[6:],
            f"the stroke moved by 3 px (48 Q4) and nothing else: {x} -> {y}")


def codings(path):
    inf = json.loads(subprocess.run([spt, "info", path, "--json", "--frames"], capture_output=True,
                                    text=True, check=True).stdout)
    return [(f["type"], f["motion_bytes"] > 0) for f in inf["frame_list"]]


unedited = os.path.join(work, "pattern.exported.spt")
C.check(any(m for _, m in codings(out)), "the painted clip has inter frames with motion")
C.check(codings(unedited) == codings(out), f"unedited export keeps the frame codings and motion: "
        f"{codings(unedited)} vs {codings(out)}")
print(f"edit of a painted clip: stroke {moved} of frame {fi} moved by 3 px, exported as exactly that")

# 3. A still: one frame.
out = os.path.join(work, "still.spt")
obj = paint("still", out, source='FILE', filepath=os.path.join(work, "clip", "c.0002.png"))
check_import("still", obj, out, 1)
check_export_renders_identically("still", obj, out)

# 4. Style Cartoon: the same frames as flat-colour art (spt paint --style cartoon), imported one
#    layer per kind: "fills" holds the polygons, and the unedited export renders identically.
out = os.path.join(work, "cartoon.spt")
obj = paint("cartoon", out, source='FILE', filepath=os.path.join(work, "clip", "c.####.png"), style='CARTOON',
            target_psnr=30.0)
info = json.loads(subprocess.run([spt, "info", out, "--json"], capture_output=True, text=True, check=True).stdout)
C.check("style=cartoon" in info["metadata"].get("painter.options", ""), f"cartoon: spt painted with --style cartoon: {info['metadata']}")
C.check(info["strokes"]["kinds"]["polygon"] > 0, f"cartoon: the painting holds polygons: {info['strokes']['kinds']}")
C.check("fills" in G.layer_names(obj), f"cartoon: a fills layer: {G.layer_names(obj)}")
check_export_renders_identically("cartoon", obj, out)
scene.spt_paint.style = 'PAINTERLY'
scene.spt_paint.target_psnr = 0.0
print("OK")
