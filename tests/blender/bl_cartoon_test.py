"""Blender test: a cartoon painting (`spt paint --style cartoon`) as editable Grease Pencil.

Five frames of the flat-colour clip cartoon/star, reduced to 96x72 (Blender's own image scaling:
the 4.3 and 5.2 roots have no OpenImageIO tools), painted with --style cartoon: polygons and
residual stamps, inter frames that keep, remove and add both (the first five frames, from 28,
20, 36, ... on, in which polygons are added over kept stamps: the file's order crosses the
layers). The add-on's default (Automatic) layering must give one layer per kind, "fills" (every
polygon, as a closed fill-only stroke, in drawing order) below "lines" (the thin regions the
painter draws as anti-aliased curves, format 1.4: open line strokes with widths) below "paint"
(the stamps); an
unedited export must give the same live lists stroke for stroke and, range coded, render the
same pixels as the painting; a recoloured fill and a hidden layer export as edited, everything
else in the file's order. The synthetic animation with curves adds "lines"; layering 'SETS'
keeps today's layers."""

import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402
import bl_gp as G  # noqa: E402

zip_path, spt, work, media = C.args()
C.install(zip_path, spt)
import spt_samples  # noqa: E402  (after install: uses the installed add-on)
from spt_grease_pencil.io import colors, read_file  # noqa: E402
from spt_grease_pencil.io.model import AFFINE, CURVE, POLYGON, STAMP, curve_grid_of  # noqa: E402

star = os.path.join(media, "cartoon", "star")
C.check(os.path.isdir(star), f"no cartoon clip at {star} (the test needs the shared media)")
C.check(C.spt_works(spt, "paint") and C.spt_works(spt, "render"), f"spt paint/render do not work: {spt!r}")


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    C.check(r.returncode == 0, f"{' '.join(cmd)}: {r.stderr}")


def renders_identically(a, b, frames):
    for name in (a, b):
        run([spt, "render", name, "-o", name + ".####.png"])
    for fi in range(frames):
        pa = open(f"{a}.{fi:04d}.png", "rb").read()
        pb = open(f"{b}.{fi:04d}.png", "rb").read()
        C.check(pa == pb, f"frame {fi} of {b} renders as {a}")


# ------------------------------------------------------------------ the painting
FRAMES = 5


def crossings(lists):
    """Polygons an inter frame draws after a stamp (the file's order crosses the layers)."""
    n = 0
    for lst in lists[1:]:
        stamps = [k for k, s in enumerate(lst) if s[0] in (STAMP, AFFINE)]
        n += sum(1 for k, s in enumerate(lst) if s[0] == POLYGON and stamps and k > stamps[0])
    return n


def paint_star(first):
    """FRAMES frames of the star from `first` at 96x72, painted, and their live lists."""
    for i in range(FRAMES):
        img = bpy.data.images.load(os.path.join(star, f"f.{first + i:04d}.png"))
        img.scale(96, 72)
        img.filepath_raw = os.path.join(work, f"star.{i:04d}.png")
        img.file_format = 'PNG'
        img.save()
        bpy.data.images.remove(img)
    run([spt, "paint", os.path.join(work, "star.####.png"), "--style", "cartoon", "--alpha", "off", "--target-psnr", "36",
         "--threads", "1", "--progress", "none", "-o", painted])
    run([spt, "pack", painted, "--stored", "-o", stored])
    return list(read_file(stored).live_lists())


# The first stretch of the clip whose painting draws polygons over kept stamps (which frames do
# depends on the painter's keep rules; the import must handle the crossing wherever it is).
# With lines too (the star's thin outlines, before it morphs into a circle).
painted = os.path.join(work, "star.spt")
stored = os.path.join(work, "star.stored.spt")
for first in (28, 20, 36, 12, 44, 4, 52, 8, 16, 24, 32, 40):
    orig_lists = paint_star(first)
    if crossings(orig_lists) and any(s[0] == CURVE for l in orig_lists for s in l):
        break
print(f"star frames {first}-{first + FRAMES - 1}")
C.check(len(orig_lists) == FRAMES, f"{len(orig_lists)} frames painted")
C.check(all(any(s[0] == POLYGON for s in l) and any(s[0] == STAMP for s in l) for l in orig_lists),
        "every frame holds polygons and residual stamps")
# Thin regions whose centreline curves are as close as their outlines are lines: anti-aliased
# curves (format 1.4), a GP line stroke each, in a layer of their own.
lines_drawn = sum(1 for l in orig_lists for s in l if s[0] == CURVE)
print(f"{lines_drawn} lines")
C.check(lines_drawn > 0, "the cartoon painter draws the star's thin outlines as lines")
C.check(all(curve_grid_of(s) >= 2 for l in orig_lists for s in l if s[0] == CURVE), "every line is anti-aliased (a grid)")
KINDS = ["fills", "lines", "paint"]

# ------------------------------------------------------------------ layers after import
opts = bpy.ops.import_scene.spt.get_rna_type().properties["layering"]
C.check(opts.default == 'AUTO', f"the import's default layering is AUTO, not {opts.default}")
before = set(bpy.data.objects)
C.check(bpy.ops.import_scene.spt(filepath=painted) == {'FINISHED'}, "import with the default layering")
obj = [o for o in bpy.data.objects if o not in before and o.type == G.OBJECT_TYPE][0]
gpd = obj.data
names = G.layer_names(obj)
C.check(names == KINDS, f"one layer per kind, fills below lines below paint: {names}")
scene = bpy.context.scene
fills, lines, paint = G.layer(obj, "fills"), G.layer(obj, "lines"), G.layer(obj, "paint")
interleaved = 0
for fi, lst in enumerate(orig_lists):
    got_f = G.strokes(G.frame(fills, scene.frame_start + fi))
    got_p = G.strokes(G.frame(paint, scene.frame_start + fi))
    want_f = [k for k, s in enumerate(lst) if s[0] == POLYGON]
    want_p = [k for k, s in enumerate(lst) if s[0] in (STAMP, AFFINE)]
    got_l = G.strokes(G.frame(lines, scene.frame_start + fi))
    want_l = [k for k, s in enumerate(lst) if s[0] == CURVE]
    C.check([g.ordinal for g in got_l] == want_l, f"frame {fi}: lines holds the curves in drawing order")
    for g in got_l:
        mat = gpd.materials[g.material_index]
        C.check(mat.get("spt_curve_grid", 0) == curve_grid_of(lst[g.ordinal]), "a line's material carries its grid")
        C.check(mat.grease_pencil.show_stroke and not g.cyclic, "a line is an open line stroke")
    C.check([g.ordinal for g in got_f] == want_f, f"frame {fi}: fills holds the polygons in drawing order")
    C.check([g.ordinal for g in got_p] == want_p, f"frame {fi}: paint holds the stamps in drawing order")
    interleaved += sum(1 for k in want_f if want_p and k > want_p[0])
    for g in got_f:
        mat = gpd.materials[g.material_index]
        gpm = mat.grease_pencil
        C.check("spt_polygon_grid" in mat and gpm.show_fill and not gpm.show_stroke, "a fill-only polygon material")
        C.check(g.cyclic, "a polygon is a closed stroke")
print(f"{sum(map(len, orig_lists))} strokes; {interleaved} polygons drawn after a stamp (inter frames)")
C.check(interleaved > 0, "some inter frame draws polygons over kept stamps (the order crosses the layers)")

# ------------------------------------------------------------------ unedited export
C.check(C.export_spt(obj, os.path.join(work, "unedited.spt")) == orig_lists,
        "unedited export: the same live lists, stroke for stroke, across the two layers")
coded = os.path.join(work, "unedited.coded.spt")
C.export_spt(obj, coded, stored=False)
renders_identically(painted, coded, FRAMES)

# ------------------------------------------------------------------ edits in frame 1
fi = 1
lst = orig_lists[fi]
frame = G.frame(fills, scene.frame_start + fi)
k_col = [k for k, s in enumerate(lst) if s[0] == POLYGON][-1]
G.by_ordinal(frame)[k_col].fill = (colors.to_linear(10), colors.to_linear(20), colors.to_linear(30), 1.0)
got = C.export_spt(obj, os.path.join(work, "recoloured.spt"))
want = list(lst)
want[k_col] = lst[k_col][:1] + (10, 20, 30) + lst[k_col][4:]
C.check(got[fi] == want, "a recoloured fill exports recoloured, in its place")
C.check(got[:fi] == orig_lists[:fi] and got[fi + 1:] == orig_lists[fi + 1:], "other frames unchanged")
G.hide_layer(obj, "paint")
got = C.export_spt(obj, os.path.join(work, "fills-only.spt"))
C.check(got[0] == [s for s in orig_lists[0] if s[0] in (POLYGON, CURVE)], "hiding paint leaves fills and lines alone")
G.hide_layer(obj, "paint", False)
bpy.data.objects.remove(obj)

# ------------------------------------------------------------------ curves: "lines"; SETS as before
src = spt_samples.write_animation(os.path.join(work, "poly.stored.spt"), frames=3, polygons=5)
sample = list(read_file(src).live_lists())
obj = C.import_spt(src, 'AUTO')
C.check(G.layer_names(obj) == ["fills", "lines", "paint"], f"polygons and curves: {G.layer_names(obj)}")
lines = G.layer(obj, "lines")
for fi, lst in enumerate(sample):
    C.check([g.ordinal for g in G.strokes(G.frame(lines, scene.frame_start + fi))]
            == [k for k, s in enumerate(lst) if s[0] == CURVE], f"frame {fi}: lines holds the curves")
C.check(C.export_spt(obj, os.path.join(work, "sample-kinds.spt")) == sample, "per-kind layers export exactly")
obj = C.import_spt(painted, 'SETS')
C.check(G.layer_names(obj)[-2:] == ["shapes", "curves"] and G.layer_names(obj)[0].startswith("set "),
        f"layering SETS keeps the per-set layers, then shapes and the lines' curves: {G.layer_names(obj)}")
C.check(C.export_spt(obj, os.path.join(work, "sets.spt")) == orig_lists, "per-set layers export exactly")
print("OK")
