"""File > Export > Stroke animation (.spt): the active Grease Pencil object to a .spt file.

Per scene frame, the strokes of the visible layers are gathered and put back in drawing order by
their ordinal (gp_v2.py); strokes drawn by hand have none and go right after the stroke before
them in their layer (or above the layers below theirs). Quads become stamps when they still match
a stamp of their set size and a table orientation, affine strokes otherwise; everything else is a
curve. The live lists are coded as key/inter frames (writer.frames_from_lists), written in stored
mode with the Python writer, then range-coded by `spt pack`.
"""

import os

import numpy as np

from ..io import colors, geometry_np, stream_json
from ..io.geometry import points_to_curve
from ..io.model import Header, SptError, StreamInfo, default_orientations
from ..io.writer import frames_from_lists, write_stored
from . import gp
from .spt_tool import pack_coded, temp_path

BOUNDS = np.array(colors.BOUNDS, dtype=np.float64)


def linear_to_codes(lin) -> np.ndarray:
    """Scene-linear floats to 8-bit sRGB codes (exact inverse of the import table)."""
    return np.searchsorted(BOUNDS, np.asarray(lin, dtype=np.float64), side='right').astype(np.int64)


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
    fill_base = np.ones((len(mats) + 1, 4), dtype=np.float64)
    line_base = np.zeros((len(mats) + 1, 4), dtype=np.float64)
    line_base[:, 3] = 1.0
    for i, m in enumerate(mats):
        if m is not None and "spt_template" in m:
            tmpl[i] = int(m["spt_template"])
        fill_base[i] = gp.material_color(m, True)
        line_base[i] = gp.material_color(m, False)
    return tmpl, fill_base, line_base


def collect_frame(obj, number: int, info: StreamInfo, tables, warnings: list):
    """The live stroke list the object shows at scene frame `number`."""
    h = info.header
    tmpl_of, fill_base, line_base = tables
    nmat = len(tmpl_of) - 1
    ntemplates = len(info.templates)
    entries = []   # (key, layer index, position, stroke)
    max_key = -1
    for li, layer in enumerate(gp.layers(obj)):
        if gp.layer_hidden(layer):
            continue
        fr = gp.frame_at(layer, number)
        if fr is None:
            continue
        d = gp.read_frame(fr)
        n = d.count
        if n == 0:
            continue
        mi = np.where((d.material_index >= 0) & (d.material_index < nmat), d.material_index, nmat)
        t = tmpl_of[mi]
        is_quad = (t >= 0) & (t < ntemplates) & (d.npoints == 4) & (d.hardness < 1.0)
        strokes = [None] * n
        keys = [None] * n
        q = np.nonzero(is_quad)[0]
        if q.size:
            starts = d.offsets[q]
            corners = d.xy[starts[:, None] + np.arange(4)[None, :]] * 1000.0  # (Nq, 4, 2) px
            base = fill_base[mi[q]]
            fc = d.fill[q].astype(np.float64)
            rgb = base[:, :3] * (1.0 - fc[:, 3:4]) + fc[:, :3] * fc[:, 3:4]
            alpha = np.where(d.aspect_x[q] >= 0.999, 255,
                             np.clip(np.floor((d.aspect_x[q].astype(np.float64) - 0.5) * 512 + 0.5), 0, 255))
            rgba = np.concatenate([linear_to_codes(rgb), alpha.astype(np.int64)[:, None]], axis=1)
            made = geometry_np.quads_to_strokes(corners, t[q], rgba, h.sets, h.orientations,
                                                d.line_width[q].astype(np.int64) - 1)
            ords = np.floor((d.hardness[q].astype(np.float64) - 0.5) * 2.0 ** 24 + 0.5).astype(np.int64).tolist()
            for j, i in enumerate(q.tolist()):
                strokes[i] = made[j]
                keys[i] = ords[j]
                if made[j] is None:
                    warnings.append(f"frame {number}, layer '{gp.layer_name(layer)}': a degenerate quad was left out")
        for i in np.nonzero(~is_quad)[0].tolist():
            a, b = int(d.offsets[i]), int(d.offsets[i + 1])
            if b <= a:
                continue
            pr, st, vc = d.point_attrs(i)
            base = line_base[mi[i]]
            vcm = vc.astype(np.float64).mean(axis=0)
            rgb = base[:3] * (1.0 - vcm[3]) + vcm[:3] * vcm[3]
            alpha = int(np.clip(np.floor(255.0 * base[3] * float(st.astype(np.float64).mean()) + 0.5), 0, 255))
            pts = d.xy[a:b] * 1000.0
            widths = pr.astype(np.float64) * float(d.line_width[i])
            s = points_to_curve(zip(pts[:, 0].tolist(), pts[:, 1].tolist(), widths.tolist()),
                                tuple(linear_to_codes(rgb).tolist()) + (alpha,))
            strokes[i] = s
            if s is None:
                warnings.append(f"frame {number}, layer '{gp.layer_name(layer)}': a stroke out of range was left out")
            if d.uv_translation[i, 1] == 1.0:
                keys[i] = int(d.uv_translation[i, 0])
        # Strokes without an ordinal follow the stroke before them in their layer, or sit
        # above the layers below.
        last = max_key
        for i in range(n):
            if keys[i] is None:
                keys[i] = last
            else:
                last = keys[i]
            if strokes[i] is not None:
                entries.append((keys[i], li, i, strokes[i]))
        if entries:
            max_key = max(max_key, max(e[0] for e in entries))
    entries.sort(key=lambda e: (e[0], e[1], e[2]))
    return [e[3] for e in entries]


def export_file(context, obj, path: str, spt_path: str = "", stored: bool = False, progress=None):
    """Writes `path`. Returns a summary dict; raises SptError / SptToolError."""
    if obj is None or obj.type != 'GPENCIL':
        raise SptError("select a Grease Pencil object to export")
    scene = context.scene
    info = stream_info(obj, scene)
    first, last = scene.frame_start, scene.frame_end
    if last < first:
        raise SptError("the scene frame range is empty")
    tables = _material_tables(obj)
    warnings = []
    lists = []
    count = last - first + 1
    for k, number in enumerate(range(first, last + 1)):
        lists.append(collect_frame(obj, number, info, tables, warnings))
        if progress:
            progress(k + 1, count)
    frames = frames_from_lists(lists)
    if stored:
        write_stored(path, info, frames)
    else:
        tmp = temp_path()
        try:
            write_stored(tmp, info, frames)
            pack_coded(spt_path, tmp, path)
        finally:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    return {"frames": len(frames), "strokes": sum(len(x) for x in lists), "warnings": warnings}
