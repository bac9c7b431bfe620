"""The Grease Pencil backend for the GPv2 data model (Blender 3.x .. 4.2): object type GPENCIL,
bpy.data.grease_pencils, frame.strokes with per-stroke Python objects. gp.py picks this module or
gp_v3.py by bpy.app.version; nothing outside the two backends (and gp_common.py, which they share)
touches Grease Pencil data.

Hidden per-stroke data of imported quads (stroke-level, so it is written in bulk and survives
moving, rotating and recolouring; none of it affects a fill-only material):
  hardness  = 0.5 + ordinal * 2^-24  the stroke's index in the frame's drawing order (< 2^23);
                                     a stroke drawn by hand has hardness 1.0
  line_width = set + 1               stroke set hint (ambiguous when two sets have one size)
  aspect[0] = 0.5 + alpha / 512      the colour's alpha (fills have no per-stroke opacity)
Curves (GP lines, material without fill): uv_translation = (ordinal, 1); point pressure = width
in px with line_width 1; point strength = alpha / 255. A curve's supersampling grid N (format 1.4)
is its material's: one curve material per N used, spt_curve_grid = N (none for N = 0).
Polygons (format 1.2; closed, cyclic, solid fill, no line): hardness = 0.5 + ordinal * 2^-24 as
quads, line_width 1, aspect 1; vertex_color_fill = colour. A GPv2 stroke has no fill opacity of
its own (the shader takes the fill's alpha from the material only), so the alpha and the grid N
live in the material: one per (alpha, N) used (polygon_material), fill_color = (1, 1, 1, alpha).
HDR fills (format 1.3, colour encoding 1): GPv2 clamps vertex_color_fill to 0..1 (measured in
Blender 3.4; point vertex colours are not clamped), so a quad or polygon whose colour exceeds 1
also keeps its exact scene-linear colour in its points' vertex_color, alpha 1 (the line of a
fill-only material is never drawn). Export takes it back while the fill still equals its clamp,
i.e. while nobody recoloured the stroke (FrameData).
"""

import bpy
import numpy as np

from .gp_common import (add_material, curve_material, frame_at_sorted, frame_index,  # noqa: F401
                        material_color, new_camera, polygon_material, remove_since,
                        snapshot, stencil_image, template_material)
from .stroke_batch import FILL, LINE, QUAD, StrokeBatch  # noqa: F401

NAME = "GPv2"
OBJECT_TYPE = 'GPENCIL'
ORDINAL_SCALE = 2.0 ** -24
MAX_ORDINAL = 1 << 23
UV_FILL = np.array([0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0], dtype=np.float32)


def new_object(context, name: str):
    gpd = bpy.data.grease_pencils.new(name)
    obj = bpy.data.objects.new(name, gpd)
    context.scene.collection.objects.link(obj)
    return obj


def remove_data(gpd):
    bpy.data.grease_pencils.remove(gpd)


# ---------------------------------------------------------------- layers and frames

def new_layer(obj, name: str):
    return obj.data.layers.new(name, set_active=False)


def layers(obj):
    """Bottom to top."""
    return list(obj.data.layers)


def layer_name(layer) -> str:
    return layer.info


def layer_hidden(layer) -> bool:
    return bool(layer.hide)


def new_frame(layer, number: int):
    return layer.frames.new(number)


def remove_frame(layer, frame):
    layer.frames.remove(frame)


def frame_stroke_count(frame) -> int:
    return len(frame.strokes)


# ---------------------------------------------------------------- writing strokes
#
# Measured on Blender 3.4 (see the README): strokes.new() then points.add() in one loop is slower
# than all strokes.new() first, then points.add() over the collection; per stroke only new(),
# points.add() and the point coordinates (+ uv_fill) cross into Blender, every stroke-level value
# is one foreach_set per frame. GPv2 has no bulk access to the points of several strokes.

def fill_frame(frame, batch: StrokeBatch):
    """Adds the batch's strokes to an EMPTY frame, in order."""
    strokes = frame.strokes
    n = len(batch)
    if n == 0:
        return
    if len(strokes):
        raise ValueError("fill_frame needs an empty frame")
    if np.max(batch.ordinal) >= MAX_ORDINAL:
        raise ValueError(f"a frame holds more than {MAX_ORDINAL} strokes")
    shape = batch.shape
    new = strokes.new
    for _ in range(n):
        new()
    pts = [s.points for s in strokes]
    uv = UV_FILL
    off = batch.offsets()
    co = np.ascontiguousarray(batch.co, dtype=np.float32)
    if (shape == QUAD).all():
        for p in pts:
            p.add(4)
        quad_co = co.reshape(n, 12)
        for p, r in zip(pts, quad_co):  # the hot loop of import
            p.foreach_set('co', r)
            p.foreach_set('uv_fill', uv)
    else:
        width = np.ascontiguousarray(batch.width, dtype=np.float32)
        opacity = np.ascontiguousarray(batch.opacity, dtype=np.float32)
        vcol = np.ascontiguousarray(batch.vcol, dtype=np.float32)
        for i, (p, k) in enumerate(zip(pts, shape.tolist())):
            s0, s1 = int(off[i]), int(off[i + 1])
            p.add(s1 - s0)
            p.foreach_set('co', co[s0:s1].ravel())
            if k == QUAD:
                p.foreach_set('uv_fill', uv)
            elif k == FILL:
                # points.add() triangulated the outline while its points were all at the origin:
                # right for convex quads only, so a polygon is triangulated again.
                p.update()
            else:
                p.foreach_set('pressure', width[s0:s1])
                p.foreach_set('strength', opacity[s0:s1])
                p.foreach_set('vertex_color', vcol[s0:s1].ravel())
    # The hidden per-stroke data (module docstring), one foreach_set per property.
    quad = shape == QUAD
    fill_like = shape != LINE
    ordinal = np.asarray(batch.ordinal, dtype=np.float64)
    hardness = np.where(fill_like, 0.5 + ordinal * ORDINAL_SCALE, 1.0)
    aspect = np.ones((n, 2), dtype=np.float32)
    aspect[:, 0] = np.where(quad, 0.5 + np.asarray(batch.alpha, dtype=np.float32) / 512.0, 1.0)
    uvt = np.zeros((n, 2), dtype=np.float32)
    uvt[~fill_like, 0] = ordinal[~fill_like]
    uvt[~fill_like, 1] = 1.0
    fill = np.where(fill_like[:, None], np.asarray(batch.fill, dtype=np.float32), 0.0)
    # HDR fills: the exact colour in the points' vertex_color (module docstring).
    for i in np.flatnonzero(fill_like & (fill[:, :3] > 1.0).any(axis=1)).tolist():
        exact = np.array([fill[i, 0], fill[i, 1], fill[i, 2], 1.0], dtype=np.float32)
        pts[i].foreach_set('vertex_color', np.tile(exact, int(off[i + 1] - off[i])))
    for name, values, dtype in (("material_index", batch.material, np.int32), ("use_cyclic", fill_like, bool),
                                ("vertex_color_fill", fill, np.float32), ("hardness", hardness, np.float32),
                                ("line_width", np.where(quad, np.asarray(batch.set_hint) + 1, 1), np.int32),
                                ("aspect", aspect, np.float32), ("uv_translation", uvt, np.float32)):
        strokes.foreach_set(name, np.ascontiguousarray(values, dtype=dtype).ravel())


# ---------------------------------------------------------------- reading strokes back

class FrameData:
    """One GP frame read back in bulk: per stroke material index, point count, fill colour, line
    width, the decoded hidden data (is_imported_fill: an imported quad or polygon; ordinal or -1,
    set_hint, alpha) and the corners (n, 12) of 4-point strokes. Other strokes' points are read
    one by one on request (hand-drawn strokes and polygons: few)."""

    def __init__(self, frame):
        strokes = frame.strokes
        n = len(strokes)
        self.count = n
        self.material_index = np.empty(n, dtype=np.int32)
        self.hardness = np.empty(n, dtype=np.float32)
        self.line_width = np.empty(n, dtype=np.int32)
        aspect = np.empty(2 * n, dtype=np.float32)
        self.fill = np.empty(4 * n, dtype=np.float32)
        uvt = np.empty(2 * n, dtype=np.float32)
        if n:
            strokes.foreach_get('material_index', self.material_index)
            strokes.foreach_get('hardness', self.hardness)
            strokes.foreach_get('line_width', self.line_width)
            strokes.foreach_get('aspect', aspect)
            strokes.foreach_get('vertex_color_fill', self.fill)
            strokes.foreach_get('uv_translation', uvt)
        self.fill = self.fill.reshape(n, 4)
        # The hidden per-stroke data (module docstring) decoded.
        self.is_imported_fill = self.hardness < 1.0
        ax = aspect[0::2].astype(np.float64)
        self.alpha = np.where(ax >= 0.999, 255, np.clip(np.floor((ax - 0.5) * 512 + 0.5), 0, 255)).astype(np.int64)
        self.set_hint = self.line_width.astype(np.int64) - 1
        uvt = uvt.reshape(n, 2)
        quad_ord = np.floor((self.hardness.astype(np.float64) - 0.5) * 2.0 ** 24 + 0.5)
        self.ordinal = np.where(self.is_imported_fill, quad_ord,
                                np.where(uvt[:, 1] == 1.0, uvt[:, 0], -1)).astype(np.int64)
        self._pts = pts = [s.points for s in strokes]
        self.npoints = np.fromiter(map(len, pts), dtype=np.int64, count=n)
        # HDR fills (module docstring): a fill clamped at 1 may hide its exact colour in its
        # first point's vertex_color; it counts while the fill is still that colour's clamp.
        for i in np.flatnonzero(self.is_imported_fill & (self.fill[:, :3] >= 1.0).any(axis=1)).tolist():
            if self.npoints[i] == 0:
                continue
            vc = np.empty(4 * int(self.npoints[i]), dtype=np.float32)
            pts[i].foreach_get('vertex_color', vc)
            exact = vc[:3]
            if vc[3] == 1.0 and (exact > 1.0).any() and (np.minimum(exact, 1.0) == self.fill[i, :3]).all():
                self.fill[i, :3] = exact
        self.co4 = np.zeros((n, 12), dtype=np.float32)
        four = self.npoints == 4
        if four.all():
            for p, r in zip(pts, self.co4):  # the hot loop of export
                p.foreach_get('co', r)
        else:
            co4 = self.co4
            for i in np.flatnonzero(four).tolist():
                pts[i].foreach_get('co', co4[i])

    def coords(self, idx):
        """The points of strokes `idx` (one foreach_get each): co (sum m, 3) float32 and the
        start of each stroke's points in it (len(idx) + 1 offsets)."""
        counts = self.npoints[idx]
        start = np.zeros(len(idx) + 1, dtype=np.int64)
        np.cumsum(counts, out=start[1:])
        co = np.empty(3 * int(start[-1]), dtype=np.float32)
        for k, i in enumerate(idx.tolist()):
            self._pts[i].foreach_get('co', co[3 * start[k]:3 * start[k + 1]])
        return co.reshape(-1, 3), start

    def points(self, i: int):
        """(co (m, 3), pressure, strength, vertex_color (m, 4)) of stroke i."""
        p = self._pts[i]
        m = len(p)
        co = np.empty(3 * m, dtype=np.float32)
        pr = np.empty(m, dtype=np.float32)
        st = np.empty(m, dtype=np.float32)
        vc = np.empty(4 * m, dtype=np.float32)
        p.foreach_get('co', co)
        p.foreach_get('pressure', pr)
        p.foreach_get('strength', st)
        p.foreach_get('vertex_color', vc)
        return co.reshape(m, 3), pr, st, vc.reshape(m, 4)


def read_frame(frame) -> FrameData:
    return FrameData(frame)
