"""File > Import > Stroke animation (.spt): builds one Grease Pencil object from a file.

Layering: one layer per stroke set, coarse (bottom) to fine (top), then "shapes" (affine strokes)
and "curves": an artist can hide, lock or retouch the detail pass apart from the under-painting.
The file's exact drawing order is kept per stroke (its ordinal, see gp_v2.py), so export restores
it even though inter frames interleave sets. layering='SINGLE' puts everything in one layer, whose
viewport order is then exactly the file's.
"""

import os

import numpy as np

from ..io import colors, geometry_np, stream_json
from ..io.model import AFFINE, CURVE, STAMP, NeedsPack, SptError
from ..io.reader import read_file
from . import gp
from .spt_tool import SptToolError, pack_stored, temp_path

LINEAR = np.array(colors.LINEAR, dtype=np.float32)


def load_stored(path: str, spt_path: str):
    """Reads `path`; a range-coded file goes through `spt pack --stored` first."""
    if not os.path.isfile(path):
        raise SptError(f"{path}: no such file")
    try:
        return read_file(path)
    except NeedsPack:
        pass
    tmp = temp_path()
    try:
        pack_stored(spt_path, path, tmp)
        f = read_file(tmp)
        f.path = path
        return f
    finally:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def template_coverage(t, size: int = 128) -> np.ndarray:
    """(rows top first) coverage 0..255 of a template; analytic kinds sampled at pixel centres."""
    if t.kind == 0:
        return np.frombuffer(t.pixels, dtype=np.uint8).reshape(t.height, t.width)
    c = (np.arange(size) + 0.5) / size * 2.0 - 1.0
    u, v = np.meshgrid(c, c)  # v grows downward with the row
    if t.kind == 1:
        inside = u * u + v * v <= 1.0
    elif t.kind == 2:
        inside = np.ones_like(u, dtype=bool)
    else:
        inside = (u >= -1) & (v >= -1) & (u + v <= 0)
    return np.where(inside, 255, 0).astype(np.uint8)


def _scene_setup(context, info, count):
    scene = context.scene
    h = info.header
    scene.render.resolution_x = h.width
    scene.render.resolution_y = h.height
    scene.render.resolution_percentage = 100
    fps = h.fps_num / h.fps_den
    scene.render.fps = max(1, min(32767, round(fps)))
    scene.render.fps_base = scene.render.fps / fps
    scene.frame_end = scene.frame_start + max(count, 1) - 1
    world = scene.world
    if world is None:
        import bpy
        world = scene.world = bpy.data.worlds.new("spt background")
    world.color = tuple(float(LINEAR[c]) for c in h.background)


def import_file(context, path: str, spt_path: str = "", layering: str = 'SETS', progress=None):
    """Returns (object, summary dict). Raises SptError / SptToolError with a readable message."""
    f = load_stored(path, spt_path)
    info = f.info
    h = info.header
    if not f.frames:
        raise SptError(f"{path}: the file holds no frames")
    lists = list(f.live_lists())
    name = os.path.splitext(os.path.basename(path))[0] or "strokes"
    obj = gp.new_object(context, name)
    gpd = obj.data

    tmat = []
    for ti, t in enumerate(info.templates):
        img = gp.stencil_image(f"{name} template {ti} {t.name}".strip(), template_coverage(t))
        mat = gp.template_material(f"{name} {t.name or 'template'} {ti}", img)
        mat["spt_template"] = ti
        tmat.append(gp.add_material(obj, mat))
    cmat = gp.curve_material(f"{name} curve")
    cmat["spt_curve"] = 1
    cmat_index = gp.add_material(obj, cmat)

    kinds_used = set()
    sets_used = set()
    for lst in lists:
        for s in lst:
            kinds_used.add(s[0])
            if s[0] == STAMP:
                sets_used.add(s[1])
    # Layers bottom to top. Key: ('set', i) / 'shapes' / 'curves', or 'all'.
    layer_of = {}
    if layering == 'SINGLE':
        layer_of['all'] = gp.new_layer(obj, "strokes")
    else:
        for si, (sw, sh) in enumerate(h.sets):
            if si in sets_used:
                layer_of[('set', si)] = gp.new_layer(obj, f"set {si} ({sw}x{sh})")
        if AFFINE in kinds_used:
            layer_of['shapes'] = gp.new_layer(obj, "shapes")
        if CURVE in kinds_used or not layer_of:
            layer_of['curves'] = gp.new_layer(obj, "curves")

    start = context.scene.frame_start
    sets_arr, orients = h.sets, h.orientations
    tmat_arr = np.array(tmat + [0], dtype=np.int32)
    total_strokes = 0
    for fi, lst in enumerate(lists):
        number = start + fi
        frames = {k: gp.new_frame(layer, number) for k, layer in layer_of.items()}
        groups = {}
        for i, s in enumerate(lst):
            k = s[0]
            key = 'all' if layering == 'SINGLE' else (('set', s[1]) if k == STAMP else
                                                      ('shapes' if k == AFFINE else 'curves'))
            groups.setdefault((key, k), []).append(i)
        # Quads first per layer in drawing order: within a layer, kinds do not interleave
        # except in SINGLE mode, where we build the layer stroke by stroke runs.
        for key, frame in frames.items():
            idx = sorted(i for (gk, _k), ids in groups.items() if gk == key for i in ids)
            _fill_frame(frame, lst, idx, sets_arr, orients, tmat_arr, cmat_index)
        total_strokes += len(lst)
        if progress:
            progress(fi + 1, len(lists))

    gpd["spt_stream"] = stream_json.to_json(info)
    gpd["spt_frame_start"] = start
    gpd["spt_frame_count"] = len(lists)
    gpd["spt_source"] = path
    _scene_setup(context, info, len(lists))
    cam = gp.new_camera(context, f"{name} camera", h.width, h.height)
    context.scene.camera = cam
    summary = {"frames": len(lists), "strokes": total_strokes, "layers": len(layer_of),
               "templates": len(info.templates), "complete": f.complete, "problem": f.problem}
    return obj, summary


def _fill_frame(frame, lst, idx, sets, orients, tmat_arr, cmat_index):
    """Adds strokes lst[i] for i in idx (increasing) to one GP frame, in runs of one kind so
    quads go in bulk."""
    run = []
    run_kind = None
    for i in idx:
        k = 1 if lst[i][0] != CURVE else 2  # 1 = quad (stamp or affine), 2 = curve
        if run and k != run_kind:
            _flush(frame, lst, run, run_kind, sets, orients, tmat_arr, cmat_index)
            run = []
        run_kind = k
        run.append(i)
    if run:
        _flush(frame, lst, run, run_kind, sets, orients, tmat_arr, cmat_index)


def _flush(frame, lst, run, run_kind, sets, orients, tmat_arr, cmat_index):
    if run_kind == 2:
        for i in run:
            s = lst[i]
            pts = np.array(s[5], dtype=np.float64).reshape(-1, 3) / 16.0
            gp.add_curve(frame, pts[:, :2] / 1000.0, pts[:, 2], cmat_index,
                         LINEAR[[s[1], s[2], s[3]]], s[4], i)
        return
    n = len(run)
    corners = np.empty((n, 4, 2), dtype=np.float64)
    tmpl = np.empty(n, dtype=np.int64)
    rgba = np.empty((n, 4), dtype=np.int64)
    hint = np.zeros(n, dtype=np.int64)
    is_stamp = np.array([lst[i][0] == STAMP for i in run], dtype=bool)
    if is_stamp.any():
        st = np.array([lst[i] for i, m in zip(run, is_stamp) if m], dtype=np.int64)
        corners[is_stamp] = geometry_np.stamps_to_corners(st, sets, orients)
        tmpl[is_stamp] = st[:, 2]
        rgba[is_stamp] = st[:, 6:10]
        hint[is_stamp] = st[:, 1]
    if not is_stamp.all():
        af = np.array([lst[i] for i, m in zip(run, is_stamp) if not m], dtype=np.int64)
        corners[~is_stamp] = geometry_np.affines_to_corners(af)
        tmpl[~is_stamp] = af[:, 1]
        rgba[~is_stamp] = af[:, 8:12]
    fill = np.empty((n, 4), dtype=np.float32)
    fill[:, 0:3] = LINEAR[rgba[:, 0:3]]
    fill[:, 3] = 1.0
    ordinal = np.array(run, dtype=np.int64)
    if ordinal.size and ordinal.max() >= gp.backend.MAX_ORDINAL:
        raise SptError(f"a frame holds more than {gp.backend.MAX_ORDINAL} strokes")
    gp.add_quads(frame, corners / 1000.0, tmat_arr[tmpl], fill, ordinal, hint, rgba[:, 3])
