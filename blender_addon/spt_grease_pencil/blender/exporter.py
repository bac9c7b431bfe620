"""File > Export > Stroke animation (.spt): the active Grease Pencil object to a .spt file.

Per scene frame, the strokes of the visible layers are gathered and put back in drawing order by
their ordinal (gp_v2.py); strokes drawn by hand have none and go right after the stroke before
them in their layer (or above the layers below theirs). Quads become stamps when they still match
a stamp of their set size and a table orientation, affine strokes otherwise; strokes of a polygon
material (importer.polygon_materials) are polygons of that material's alpha and grid N, with their
points as vertices (so an edited outline exports as edited, rounded to Q4); everything else is a
curve, of the grid N of its material's spt_curve_grid (importer.curve_materials; 0 without one),
and the file has the HEAD flag curve_grid (format 1.4) when a curve has a grid N (or the imported
file had it). All of it on numpy StrokeTables (io/strokes_np.py): the live lists are coded as key/inter
frames (state_np.frames_from_tables: strokes that all moved with a block motion field, as in the
painter's inter frames, are coded with that field again), written in stored mode by the Python
writer, then range-coded by `spt pack`.
"""

import os
import time

import numpy as np

from ..io import colors, geometry, state_np, stream_json
from ..io.geometry import points_to_curve
from ..io.model import CURVE, MAX_POS, POLYGON
from ..io.model import Header, SptError, StreamInfo, default_orientations
from ..io.strokes_np import A, B, CURVE_ID, G, GRID, KIND, NCOL, R, X, Y, StrokeTable
from ..io.writer import write_stored
from ..spt_tool import pack_coded, temp_path
from . import gp

def file_values(lin, h) -> np.ndarray:
    """Scene-linear floats to the file's colour values: 8-bit sRGB codes (the exact inverse of
    the import table) in colour encoding 0, the nearest half codes in colour encoding 1 (an
    imported colour returns to its own code)."""
    return colors.linear_to_values(lin, h.linear)


def stream_info(obj, scene) -> StreamInfo:
    text = obj.data.get("spt_stream")
    if text:
        info = stream_json.from_json(text)
    else:  # a Grease Pencil object not imported from .spt: curves only
        info = StreamInfo(header=Header(width=scene.render.resolution_x, height=scene.render.resolution_y,
                                        sets=[(16, 16)], orientations=default_orientations(8)))
    fps = scene.render.fps / scene.render.fps_base
    h = info.header
    if abs(h.fps_num / h.fps_den - fps) > 1e-6:
        from fractions import Fraction
        fr = Fraction(fps).limit_denominator(1001)
        h.fps_num, h.fps_den = fr.numerator, fr.denominator
    return info


def _material_tables(obj):
    mats = list(obj.data.materials)
    tmpl = np.full(len(mats) + 1, -1, dtype=np.int64)   # last entry: stroke without material
    grid = np.full(len(mats) + 1, -1, dtype=np.int64)   # polygon materials: their grid N
    curve_grid = np.zeros(len(mats) + 1, dtype=np.int64)  # curves: their material's grid N, else 0
    fill_base = np.ones((len(mats) + 1, 4), dtype=np.float64)
    line_base = np.zeros((len(mats) + 1, 4), dtype=np.float64)
    line_base[:, 3] = 1.0
    for i, m in enumerate(mats):
        if m is not None and "spt_template" in m:
            tmpl[i] = int(m["spt_template"])
        elif m is not None and "spt_polygon_grid" in m:
            grid[i] = int(m["spt_polygon_grid"])
        if m is not None and "spt_curve_grid" in m:
            curve_grid[i] = int(m["spt_curve_grid"])
        fill_base[i] = gp.material_color(m, True)
        line_base[i] = gp.material_color(m, False)
    return tmpl, fill_base, line_base, grid, curve_grid


class CurvePool:
    """The curve pool of the exported tables (curves, and polygon outlines relative to their
    first vertex), deduplicated by shape and content so that equal strokes have equal rows (the
    frame coder matches strokes by row)."""

    def __init__(self):
        self.curves = []
        self._ids = {}

    def add(self, pts, columns: int = 3) -> int:
        arr = np.asarray(pts, dtype=np.int32).reshape(-1, columns)
        key = (columns, arr.tobytes())
        i = self._ids.get(key)
        if i is None:
            i = self._ids[key] = len(self.curves)
            self.curves.append(arr)
        return i


def read_layer_frame(d, info: StreamInfo, tables, pool: CurvePool, where: str, warnings: list):
    """The strokes of one GP frame as (rows (n, NCOL), ordinal (n,) or -1), in the frame's order;
    strokes that cannot be stored are left out with a warning."""
    h = info.header
    tmpl_of, fill_base, line_base, grid_of, curve_grid_of = tables
    nmat = len(tmpl_of) - 1
    n = d.count
    mi = np.where((d.material_index >= 0) & (d.material_index < nmat), d.material_index, nmat)
    t = tmpl_of[mi]
    is_quad = (t >= 0) & (t < len(info.templates)) & (d.npoints == 4) & d.is_imported_fill
    rows = np.zeros((n, NCOL), dtype=np.int32)
    keep = np.ones(n, dtype=bool)
    q = np.flatnonzero(is_quad)
    if q.size:
        co = d.co4[q].reshape(-1, 4, 3).astype(np.float64) * 1000.0
        corners = np.stack([co[:, :, 0], -co[:, :, 2]], axis=-1)  # px, image y down
        base = fill_base[mi[q]]
        fc = d.fill[q].astype(np.float64)
        rgb = base[:, :3] * (1.0 - fc[:, 3:4]) + fc[:, :3] * fc[:, 3:4]
        rgba = np.concatenate([file_values(rgb, h), d.alpha[q, None]], axis=1)
        qrows, valid = geometry.quads_to_rows(corners, t[q], rgba, h.sets, h.orientations, d.set_hint[q])
        rows[q] = qrows
        keep[q[~valid]] = False
        if not valid.all():
            warnings.append(f"{where}: {int((~valid).sum())} degenerate quad(s) left out")
    poly = ~is_quad & (grid_of[mi] >= 0)
    if poly.any():
        _polygons(d, np.flatnonzero(poly), fill_base[mi], grid_of[mi], rows, keep, pool, where, warnings, h)
    for i in np.flatnonzero(~is_quad & ~poly).tolist():
        if d.npoints[i] == 0:
            keep[i] = False
            continue
        co, pr, st, vc = d.points(i)
        base = line_base[mi[i]]
        vcm = vc.astype(np.float64).mean(axis=0)
        rgb = base[:3] * (1.0 - vcm[3]) + vcm[:3] * vcm[3]
        alpha = int(np.clip(np.floor(255.0 * base[3] * float(st.astype(np.float64).mean()) + 0.5), 0, 255))
        xy = co.astype(np.float64) * 1000.0
        widths = pr.astype(np.float64) * float(d.line_width[i])
        s = points_to_curve(zip(xy[:, 0].tolist(), (-xy[:, 2]).tolist(), widths.tolist()),
                            tuple(file_values(rgb, h).tolist()) + (alpha,), int(curve_grid_of[mi[i]]))
        if s is None:
            keep[i] = False
            warnings.append(f"{where}: a stroke out of range (or of a material with a reserved "
                            f"spt_curve_grid {int(curve_grid_of[mi[i]])}) was left out")
            continue
        rows[i] = StrokeTable.from_tuples([s]).rows[0]
        rows[i, CURVE_ID] = pool.add(s[5])
    return rows[keep], d.ordinal[keep]


def _polygons(d, idx, base, grid, rows, keep, pool, where, warnings, h):
    """Strokes `idx` of polygon materials (importer.polygon_materials) as polygon rows, all at
    once: the points are the vertices rounded to Q4 (as geometry.points_to_polygon), the colour
    the material's fill colour mixed with vertex_color_fill (as quads), the alpha the
    material's (a GP fill has no alpha of its own). Thousands of polygons a frame: no per-point
    Python."""
    co, start = d.coords(idx)
    qx = np.floor(co[:, 0].astype(np.float64) * 1000.0 * 16.0 + 0.5).astype(np.int64)
    qy = np.floor(-(co[:, 2].astype(np.float64) * 1000.0) * 16.0 + 0.5).astype(np.int64)
    counts = np.diff(start)
    ok = (counts >= 3) & (grid[idx] != 1) & (grid[idx] >= 0) & (grid[idx] <= 16)
    if len(qx):
        far = np.maximum(np.abs(qx), np.abs(qy)) > MAX_POS
        bad = np.add.reduceat(far.astype(np.int64), np.minimum(start[:-1], len(qx) - 1)) * (counts > 0)
        ok &= bad == 0
    b = base[idx]
    fc = d.fill[idx].astype(np.float64)
    rgb = file_values(b[:, :3] * (1.0 - fc[:, 3:4]) + fc[:, :3] * fc[:, 3:4], h)
    alpha = np.clip(np.floor(255.0 * b[:, 3] + 0.5), 0, 255).astype(np.int64)
    for k, i in enumerate(idx.tolist()):
        if not ok[k]:
            keep[i] = False
            if counts[k] == 0:  # an empty stroke: nothing to keep, nothing to say (as other kinds)
                continue
            warnings.append(f"{where}: a polygon with fewer than 3 points or out of range was left out")
            continue
        s0, s1 = int(start[k]), int(start[k + 1])
        rows[i, [KIND, X, Y, R, G, B, A, GRID]] = (POLYGON, qx[s0], qy[s0], rgb[k, 0], rgb[k, 1], rgb[k, 2],
                                                   alpha[k], grid[i])
        rows[i, CURVE_ID] = pool.add(np.stack([qx[s0:s1] - qx[s0], qy[s0:s1] - qy[s0]], axis=1), 2)


def merge_layers(parts):
    """One frame's live list from its visible layers' (rows, ordinal) bottom to top. Strokes
    without an ordinal (drawn by hand) take the one of the stroke before them in their layer, or
    the largest of the layers below; then a stable sort by (ordinal, layer, position)."""
    all_rows, keys, layer_ix, pos = [], [], [], []
    max_key = -1
    for li, (rows, ordinal) in enumerate(parts):
        n = rows.shape[0]
        if n == 0:
            continue
        known = ordinal >= 0
        last = np.maximum.accumulate(np.where(known, np.arange(n), -1))
        k = np.where(last >= 0, ordinal[np.maximum(last, 0)], max_key)
        max_key = max(max_key, int(k.max()))
        all_rows.append(rows)
        keys.append(k)
        layer_ix.append(np.full(n, li))
        pos.append(np.arange(n))
    if not all_rows:
        return np.zeros((0, NCOL), dtype=np.int32)
    keys, layer_ix, pos = np.concatenate(keys), np.concatenate(layer_ix), np.concatenate(pos)
    order = np.lexsort((pos, layer_ix, keys))
    return np.concatenate(all_rows)[order]


def export_file(context, obj, path: str, spt_path: str = "", stored: bool = False, progress=None):
    """Writes `path`. Returns a summary dict; raises SptError / SptToolError. summary["seconds"]
    splits the time: gp_read (Grease Pencil data, foreach_get), strokes (quads -> strokes, layer
    merge), write (frame coding + stored file), pack (spt pack)."""
    t_start = time.perf_counter()
    gp_read = 0.0
    if obj is None or obj.type != gp.OBJECT_TYPE:
        raise SptError("select a Grease Pencil object to export")
    scene = context.scene
    info = stream_info(obj, scene)
    first, last = scene.frame_start, scene.frame_end
    # A file numbered by its source (source.first_frame) stays numbered by the scene frames it
    # is exported from; a file without the key keeps none (its bytes then stay as they were).
    info.metadata = [(k, str(first) if k == "source.first_frame" else v) for k, v in info.metadata]
    if last < first:
        raise SptError("the scene frame range is empty")
    tables = _material_tables(obj)
    warnings = []
    pool = CurvePool()
    visible = [(li, layer, gp.frame_index(layer)) for li, layer in enumerate(gp.layers(obj))
               if not gp.layer_hidden(layer)]
    held = {}   # layer index -> (GP frame number, (rows, ordinal)): a held frame is read once
    lists = []
    count = last - first + 1
    for k, number in enumerate(range(first, last + 1)):
        parts = []
        for li, layer, index in visible:
            fr = gp.frame_at_sorted(index, number)
            if fr is None:
                continue
            if li not in held or held[li][0] != fr.frame_number:
                where = f"frame {fr.frame_number}, layer '{gp.layer_name(layer)}'"
                t = time.perf_counter()
                d = gp.read_frame(fr)
                gp_read += time.perf_counter() - t
                held[li] = (fr.frame_number, read_layer_frame(d, info, tables, pool, where, warnings))
            parts.append(held[li][1])
        lists.append(StrokeTable(merge_layers(parts), pool.curves))
        if progress:
            progress(k + 1, count)
    held.clear()
    # Format 1.4 only when a curve has a grid N; an imported file's flag stays, so that its
    # unedited export keeps the file's records (a flagged file may hold grid-0 curves only).
    info.header.curve_grid = info.header.curve_grid or any(
        bool(((t.rows[:, KIND] == CURVE) & (t.rows[:, GRID] != 0)).any()) for t in lists)
    t_collect = time.perf_counter()
    blocks = [int(b) for b in obj.data.get("spt_motion_blocks", [])]
    blocks += [b for b in (16, 32) if b not in blocks]
    frames = state_np.frames_from_tables(lists, pool.curves, info.header.width, info.header.height, blocks)
    t_pack = None
    if stored:
        write_stored(path, info, frames)
    else:
        tmp = temp_path()
        try:
            write_stored(tmp, info, frames)
            t_pack = time.perf_counter()
            pack_coded(spt_path, tmp, path)
        finally:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    t_end = time.perf_counter()
    seconds = {"gp_read": gp_read, "strokes": t_collect - t_start - gp_read,
               "write": (t_pack or t_end) - t_collect, "pack": t_end - t_pack if t_pack else 0.0}
    return {"frames": len(frames), "strokes": sum(len(x) for x in lists), "warnings": warnings,
            "seconds": seconds}
