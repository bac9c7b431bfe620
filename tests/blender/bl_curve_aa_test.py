"""Blender test: anti-aliased curves (format 1.4) through Grease Pencil.

A synthetic animation whose curves carry supersampling grids 0, 2, 4 and 16 (HEAD flag curve_grid),
among stamps, affine strokes and polygons, moved by motion fields, is imported: each curve must be
a GP line of its points and widths in the curve material of its grid (grid 0: the one curve
material files of every version get; N > 0: one material per N, spt_curve_grid = N); an unedited
export gives the same live lists and the flag (range-coded too, and rendered identically by spt);
a line drawn by hand with an anti-aliased material, and a curve assigned another grid's material,
export with those grids. A file without the flag imports with the one curve material as before
and exports without it. Then libspt's golden curves_aa.spt through Blender and back."""

import os
import shutil
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402
import bl_gp as G  # noqa: E402

zip_path, spt, work, media = C.args()
C.install(zip_path, spt)
import spt_samples  # noqa: E402  (after install: uses the installed add-on)
from spt_grease_pencil.io import read_file  # noqa: E402
from spt_grease_pencil.io.model import CURVE, POLYGON, curve_grid_of  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
GOLDEN = os.path.join(HERE, "..", "format", "golden", "curves_aa")
C.check(C.spt_works(spt, "render") and C.spt_works(spt, "pack"), f"spt render and pack work ({spt!r})")

src = spt_samples.write_animation(os.path.join(work, "aa.stored.spt"), frames=4, polygons=2, curves=6,
                                  curve_grids=True)
orig = read_file(src)
orig_lists = list(orig.live_lists())
h = orig.info.header
C.check((h.curve_grid, h.version_minor) == (True, 4), "the sample is a format 1.4 file with curve_grid")
grids = {curve_grid_of(s) for lst in orig_lists for s in lst if s[0] == CURVE}
C.check(grids == {0, 2, 4, 16}, f"the sample's curves use grids 0, 2, 4 and 16: {grids}")
scene = bpy.context.scene


def curve_materials(gpd):
    """grid N -> material index of the object's curve materials."""
    out = {}
    for i, m in enumerate(gpd.materials):
        if m.get("spt_curve") == 1:
            g = int(m.get("spt_curve_grid", 0))
            C.check(g not in out, f"one curve material per grid: {g} twice")
            out[g] = i
    return out


# ------------------------------------------------------------------ structure after import
obj = C.import_spt(src)
gpd = obj.data
cmat = curve_materials(gpd)
C.check(sorted(cmat) == [0, 2, 4, 16], f"curve materials for grids {sorted(cmat)}")
C.check("spt_curve_grid" not in gpd.materials[cmat[0]], "grid 0 keeps the plain curve material")
for g, i in cmat.items():
    m = gpd.materials[i]
    C.check(m.grease_pencil.show_stroke and not m.grease_pencil.show_fill, f"grid {g}: a line material")
    C.check(m.name.startswith("aa.stored curve" + (f" grid {g}" if g else "")), f"grid {g}: named {m.name}")
curves = G.layer(obj, "curves")
for fi, lst in enumerate(orig_lists):
    got = G.strokes(G.frame(curves, scene.frame_start + fi))
    want = [(k, s) for k, s in enumerate(lst) if s[0] == CURVE]
    C.check([g.ordinal for g in got] == [k for k, _ in want], f"frame {fi}: the curves layer in drawing order")
    for g, (k, s) in zip(got, want):
        grid = curve_grid_of(s)
        C.check(g.material_index == cmat[grid], f"frame {fi} stroke {k}: the material of grid {grid}")
        co = tuple((round(c[0] * 16000), round(-c[2] * 16000), round(w * 16)) for c, w in zip(g.points, g.width_px))
        C.check(co == s[5], f"frame {fi} stroke {k}: points {co} != {s[5]}")

# ------------------------------------------------------------------ unedited export
got = C.export_spt(obj, os.path.join(work, "unedited.spt"))
C.check(got == orig_lists, "unedited export gives the same stroke lists, grids included")
back_h = read_file(os.path.join(work, "unedited.spt")).info.header
C.check((back_h.curve_grid, back_h.version_minor) == (True, 4), "export writes format 1.4 with curve_grid")
obj1 = C.import_spt(src, 'SINGLE')
C.check(C.export_spt(obj1, os.path.join(work, "unedited1.spt")) == orig_lists, "single-layer export is exact")
bpy.data.objects.remove(obj1)
coded = os.path.join(work, "unedited.coded.spt")
C.export_spt(obj, coded, stored=False)
C.check(C.stored_lists(spt, coded, os.path.join(work, "unedited.back.spt")) == orig_lists,
        "range-coded export: same stroke lists")
C.renders_identically(spt, src, coded, len(orig_lists))

# ------------------------------------------------------------------ edits in frame 1
fi = 1
frame = G.frame(curves, scene.frame_start + fi)
lst = list(orig_lists[fi])
by_ord = G.by_ordinal(frame)
k2 = next(k for k, s in enumerate(lst) if s[0] == CURVE and curve_grid_of(s) != 16)
by_ord[k2].material_index = cmat[16]            # the Material panel's Assign: now grid 16
G.draw_line(frame, cmat[4], [(0.01, 0, -0.01), (0.05, 0, -0.02), (0.09, 0, -0.01)], 10)
G.draw_line(frame, cmat[0], [(0.02, 0, -0.03), (0.06, 0, -0.04)], 6)
edited = os.path.join(work, "edited.spt")
got = C.export_spt(obj, edited)
C.check(got[0] == orig_lists[0] and got[2:] == orig_lists[2:], "other frames unchanged")
e = got[fi]
last_curve = max(k for k, s in enumerate(lst) if s[0] == CURVE)
want = list(lst)
want[k2] = lst[k2][:6] + (16,)
# Hand-drawn lines follow the last stroke of their layer; their colour and opacity are what the
# Draw tool left (not this test's subject): their points, widths and grids are.
drawn = e[last_curve + 1:last_curve + 3]
C.check(len(e) == len(lst) + 2 and e[:last_curve + 1] + e[last_curve + 3:] == want,
        "a curve assigned the grid-16 material exports with grid 16, the rest unchanged:\n"
        + "\n".join(f"  got {a}\n want {b}" for a, b in zip(e[:last_curve + 1] + e[last_curve + 3:], want) if a != b))
C.check([(s[0], s[5], curve_grid_of(s)) for s in drawn]
        == [(CURVE, ((160, 160, 160), (800, 320, 160), (1440, 160, 160)), 4), (CURVE, ((320, 480, 96), (960, 640, 96)), 0)],
        f"lines drawn with the grid-4 and the plain curve material are curves of grids 4 and 0: {drawn}")
C.check(len(drawn[1]) == 6, "a grid-0 curve keeps the tuple of format 1.3")
r = subprocess.run([spt, "render", edited, "-o", os.path.join(work, "edited.####.png")], capture_output=True, text=True)
C.check(r.returncode == 0, f"spt render edited.spt (a valid 1.4 file for libspt): {r.stderr}")

# ------------------------------------------------------------------ a file without the flag
plain = spt_samples.write_animation(os.path.join(work, "plain.stored.spt"), frames=3, polygons=2)
plain_lists = list(read_file(plain).live_lists())
C.check(read_file(plain).info.header.version_minor == 2, "the plain sample is a format 1.2 file")
pobj = C.import_spt(plain)
pmat = curve_materials(pobj.data)
C.check(list(pmat) == [0], f"one curve material, as before format 1.4: {[m.name for m in pobj.data.materials]}")
C.check(pobj.data.materials[pmat[0]].name.startswith("plain.stored curve")
        and "spt_curve_grid" not in pobj.data.materials[pmat[0]], "the plain curve material")
C.check(len(pobj.data.materials) == len(read_file(plain).info.templates) + 1 + len(
    {(s[4], s[5]) for lst_ in plain_lists for s in lst_ if s[0] == POLYGON}), "templates, curves, polygons")
out = os.path.join(work, "plain.exported.spt")
C.check(C.export_spt(pobj, out) == plain_lists, "the plain file exports its strokes")
ph = read_file(out).info.header
C.check((ph.curve_grid, ph.version_minor) == (False, 2), f"no curve_grid flag, format 1.{ph.version_minor}")

# ------------------------------------------------------------------ libspt's golden file
C.check(os.path.isfile(GOLDEN + ".spt"), f"{GOLDEN}.spt exists")
ref = list(read_file(GOLDEN + ".stored.spt").live_lists())
gin = os.path.join(work, "curves_aa.spt")   # a copy: the renders are written beside it
shutil.copyfile(GOLDEN + ".spt", gin)
gobj = C.import_spt(gin)                     # range-coded: spt pack --stored on the way in
gout = os.path.join(work, "curves_aa.back.spt")
C.export_spt(gobj, gout, stored=False)
C.check(C.stored_lists(spt, gout, os.path.join(work, "curves_aa.back.stored.spt")) == ref,
        "golden curves_aa.spt -> Blender -> export: same strokes")
C.renders_identically(spt, gin, gout, len(ref))
print(f"golden curves_aa: {len(ref)} frames, grids "
      f"{sorted({curve_grid_of(s) for l in ref for s in l if s[0] == CURVE})} round-tripped")
print("OK")
