"""The Grease Pencil backend for the GPv3 data model (Blender 4.3 and later): object type
GREASEPENCIL, bpy.data.grease_pencils_v3 (4.3-4.5) or bpy.data.grease_pencils (5.x), and a
drawing per frame that is a curves geometry with generic attributes. Every stroke and point value
of a frame is read and written with one foreach_get / foreach_set per attribute: no Python loop
over strokes or points (drawing.strokes, the per-stroke objects, is not used at all).

Attributes the importer writes (CURVE domain unless said):
  position (POINT)        corners of quads, polygon outlines, curve points (metres, XZ plane)
  radius, opacity, vertex_color (POINT)
                          curves: width / 2 px in metres, alpha / 255, the scene-linear colour
  material_index, cyclic  the template, curve or polygon material; closed for quads and polygons
  fill_color, fill_opacity
                          quads and polygons: the scene-linear colour (A = 1: replaces the
                          material's); quads: alpha / 255 (shown in the viewport as in the file)
  uv_rotation, uv_translation, uv_scale
                          quads: the texture matrix that puts the template on the quad
                          (fill_texture_attributes); Blender keeps it attached to the points,
                          so the template follows moves, rotations and scales
  fill_id, hide_stroke    quads and polygons: a fill of their own (a distinct id) and no line, as
                          Blender 5.x decides per stroke (4.x by the material, as GPv2)
  spt_stroke (INT)        what the stroke was in the file: 1 quad (stamp or affine), 2 curve,
                          3 polygon; 0 (the default of strokes drawn in Blender): none
  spt_order (INT)         the stroke's index in the file frame's drawing order
  spt_set (INT)           the stroke set of a stamp (a hint: two sets may have one size)
Colours are FLOAT_COLOR attributes, which Blender 4.3 and 5.2 do not clamp (measured): the
scene-linear values of colour encoding 1 files, HDR included, are stored as they are.
Custom attributes travel with their strokes through Blender's edit operators (move, duplicate,
delete, join), which is what makes an edited export exact. Polygon alpha and grid N live in the
material, as in GPv2 (one material per (alpha, N): the exporter is shared by both backends), and
so does a curve's grid N (format 1.4: one curve material per N, spt_curve_grid = N for N > 0).
"""

import bpy
import numpy as np

from .gp_common import (add_material, curve_material, frame_at_sorted, frame_index,  # noqa: F401
                        material_color, new_camera, polygon_material, remove_since,
                        snapshot, stencil_image, template_material)
from .stroke_batch import FILL, LINE, QUAD, StrokeBatch, point_index  # noqa: F401

NAME = "GPv3"
OBJECT_TYPE = 'GREASEPENCIL'
KIND_NONE, KIND_QUAD, KIND_CURVE, KIND_POLYGON = 0, 1, 2, 3
FILL_RADIUS = 0.0005   # quads and polygons draw no line; any small radius will do

# (attribute, data_type, domain, foreach property, components)
_ATTRS = {
    "position": ('FLOAT_VECTOR', 'POINT', 'vector', 3),
    "radius": ('FLOAT', 'POINT', 'value', 1),
    "opacity": ('FLOAT', 'POINT', 'value', 1),
    "vertex_color": ('FLOAT_COLOR', 'POINT', 'color', 4),
    "material_index": ('INT', 'CURVE', 'value', 1),
    "cyclic": ('BOOLEAN', 'CURVE', 'value', 1),
    "fill_color": ('FLOAT_COLOR', 'CURVE', 'color', 4),
    "fill_opacity": ('FLOAT', 'CURVE', 'value', 1),
    "uv_rotation": ('FLOAT', 'CURVE', 'value', 1),
    "uv_translation": ('FLOAT2', 'CURVE', 'vector', 2),
    "uv_scale": ('FLOAT2', 'CURVE', 'vector', 2),
    "fill_id": ('INT', 'CURVE', 'value', 1),
    "hide_stroke": ('BOOLEAN', 'CURVE', 'value', 1),
    "spt_stroke": ('INT', 'CURVE', 'value', 1),
    "spt_order": ('INT', 'CURVE', 'value', 1),
    "spt_set": ('INT', 'CURVE', 'value', 1),
}
_DTYPE = {'FLOAT_VECTOR': np.float32, 'FLOAT': np.float32, 'FLOAT_COLOR': np.float32,
          'FLOAT2': np.float32, 'INT': np.int32, 'BOOLEAN': bool}


def _collection():
    return bpy.data.grease_pencils_v3 if hasattr(bpy.data, "grease_pencils_v3") else bpy.data.grease_pencils


def new_object(context, name: str):
    gpd = _collection().new(name)
    obj = bpy.data.objects.new(name, gpd)
    context.scene.collection.objects.link(obj)
    return obj


def remove_data(gpd):
    _collection().remove(gpd)


# ---------------------------------------------------------------- layers and frames

def new_layer(obj, name: str):
    """A new top layer, unlit: a painting's colours are its own, as spt renders them (GPv3 layers
    are lit by default, and a scene without lights then renders them black)."""
    layer = obj.data.layers.new(name, set_active=False)
    layer.use_lights = False
    return layer


def layers(obj):
    """Bottom to top."""
    return list(obj.data.layers)


def layer_name(layer) -> str:
    return layer.name


def layer_hidden(layer) -> bool:
    return bool(layer.hide)


def new_frame(layer, number: int):
    return layer.frames.new(number)


def remove_frame(layer, frame):
    layer.frames.remove(frame.frame_number)


def frame_stroke_count(frame) -> int:
    d = frame.drawing
    return max(len(d.curve_offsets) - 1, 0) if d is not None else 0


# ---------------------------------------------------------------- attributes in bulk

def _attribute(drawing, name):
    """The attribute `name` of the drawing with the type and domain spt writes, created if absent."""
    data_type, domain, _, _ = _ATTRS[name]
    a = drawing.attributes.get(name)
    if a is not None and (a.data_type != data_type or a.domain != domain):
        drawing.attributes.remove(a)
        a = None
    if a is None:
        a = drawing.attributes.new(name, data_type, domain)
    return a


def _set(drawing, name, values):
    data_type, _, prop, _ = _ATTRS[name]
    _attribute(drawing, name).data.foreach_set(prop, np.ascontiguousarray(values, dtype=_DTYPE[data_type]).ravel())


def _get(drawing, name, count, default):
    """(count, components) or (count,) values of attribute `name`; `default` where the drawing has
    no such attribute of the expected type and domain (strokes drawn by hand lack spt's own)."""
    data_type, domain, prop, comps = _ATTRS[name]
    shape = (count, comps) if comps > 1 else (count,)
    a = drawing.attributes.get(name)
    if a is None or a.data_type != data_type or a.domain != domain or count == 0:
        return np.broadcast_to(np.asarray(default, dtype=_DTYPE[data_type]), shape).copy()
    out = np.empty(count * comps, dtype=_DTYPE[data_type])
    a.data.foreach_get(prop, out)
    return out.reshape(shape)


def fill_texture_attributes(corners):
    """(uv_rotation, uv_translation, uv_scale) per quad such that Blender's texture matrix maps the
    corners c0..c3 (n, 4, 3) to UV (0, 1), (1, 1), (1, 0), (0, 0), the uv_fill the GPv2 backend
    gives each point. GPv3 (Drawing::texture_matrices) maps a point p of a stroke to
        UV = R(uv_rotation) diag(1 / uv_scale) (dot(p - c0, lx), dot(p - c0, ly)) + uv_translation
    with lx along c0 -> c1 and ly = normal x lx (Newell's normal of the outline). With lx along the
    quad's first edge the rotation is 0, the translation is c0's UV, and the scales are the edge
    lengths, signed by the winding. A rectangle (every stamp) maps exactly; a sheared affine quad
    cannot (the matrix has no shear) and gets its template unsheared, fitted to the first edge."""
    c = np.asarray(corners, dtype=np.float64)
    n = c.shape[0]
    e1 = c[:, 1] - c[:, 0]
    e3 = c[:, 3] - c[:, 0]
    nxt = np.roll(c, -1, axis=1)
    normal = np.cross(c, nxt).sum(axis=1)  # Newell: the sum of cross products of consecutive points
    length1 = np.linalg.norm(e1, axis=1)
    lx = e1 / np.maximum(length1, 1e-30)[:, None]
    ln = np.linalg.norm(normal, axis=1)
    nn = normal / np.maximum(ln, 1e-30)[:, None]
    ly = np.cross(nn, lx)
    ly /= np.maximum(np.linalg.norm(ly, axis=1), 1e-30)[:, None]
    b = np.einsum('ij,ij->i', e3, ly)
    scale = np.stack([length1, -b], axis=1)
    scale[np.abs(scale) < 1e-12] = 1.0  # degenerate quads: keep the texture finite
    translation = np.tile(np.array([0.0, 1.0]), (n, 1))
    return np.zeros(n), translation, scale


def fill_frame(frame, batch: StrokeBatch):
    """Adds the batch's strokes to an EMPTY frame, in order: one add_strokes call and one
    foreach_set per attribute."""
    n = len(batch)
    if n == 0:
        return
    d = frame.drawing
    if frame_stroke_count(frame):
        raise ValueError("fill_frame needs an empty frame")
    shape = np.asarray(batch.shape)
    d.add_strokes([int(k) for k in batch.counts])
    line = shape == LINE
    quad = shape == QUAD
    off = batch.offsets()
    m = int(off[-1])
    on_line = np.repeat(line, batch.counts)
    _set(d, "position", batch.co)
    _set(d, "radius", np.where(on_line, np.asarray(batch.width, dtype=np.float64) / 2000.0, FILL_RADIUS))
    _set(d, "opacity", batch.opacity)
    _set(d, "vertex_color", batch.vcol)
    _set(d, "material_index", batch.material)
    _set(d, "cyclic", ~line)
    # Blender 5.x fills a stroke only when its fill_id is not 0 (strokes of one id fill as one
    # region) and hides its line by hide_stroke, not by the material: each quad and polygon is
    # its own filled region with no line. Earlier versions keep them as inert attributes.
    _set(d, "fill_id", np.where(line, 0, np.arange(1, n + 1)))
    _set(d, "hide_stroke", ~line)
    _set(d, "fill_color", np.where(line[:, None], 0.0, np.asarray(batch.fill, dtype=np.float32)))
    _set(d, "fill_opacity", np.where(quad, np.asarray(batch.alpha, dtype=np.float64) / 255.0, 1.0))
    rot = np.zeros(n)
    trans = np.zeros((n, 2))
    scale = np.ones((n, 2))
    q = np.flatnonzero(quad)
    if q.size:
        corners = np.asarray(batch.co, dtype=np.float64)[point_index(off[q], np.full(q.size, 4))].reshape(-1, 4, 3)
        rot[q], trans[q], scale[q] = fill_texture_attributes(corners)
    _set(d, "uv_rotation", rot)
    _set(d, "uv_translation", trans)
    _set(d, "uv_scale", scale)
    _set(d, "spt_stroke", np.where(quad, KIND_QUAD, np.where(line, KIND_CURVE, KIND_POLYGON)))
    _set(d, "spt_order", batch.ordinal)
    _set(d, "spt_set", np.where(quad, batch.set_hint, 0))
    assert m == len(d.attributes["position"].data)
    d.tag_positions_changed()


# ---------------------------------------------------------------- reading strokes back

class FrameData:
    """One GP frame read back in bulk, with the fields the exporter reads from either backend
    (gp_v2.FrameData): per stroke material_index, npoints, fill (n, 4), line_width (1: curve
    widths are in px already), is_imported_fill (an imported quad or polygon), ordinal (or -1),
    set_hint, alpha; co4 (n, 12) corners of 4-point strokes; coords(idx) and points(i)."""

    def __init__(self, frame):
        d = frame.drawing
        # An empty drawing reports one offset but holds none (foreach_get wants 0 values).
        off = np.zeros(len(d.curve_offsets), dtype=np.int32)
        if len(off) > 1:
            d.curve_offsets.foreach_get('value', off)
        off = off.astype(np.int64)
        n = max(len(off) - 1, 0)
        m = int(off[-1]) if n else 0
        self.count = n
        self._off = off if n else np.zeros(1, dtype=np.int64)
        self.npoints = np.diff(self._off)
        self._co = _get(d, "position", m, (0.0, 0.0, 0.0))
        self._radius = _get(d, "radius", m, 0.01)
        self._opacity = _get(d, "opacity", m, 1.0)
        self._vcol = _get(d, "vertex_color", m, (0.0, 0.0, 0.0, 0.0))
        self.material_index = _get(d, "material_index", n, 0).astype(np.int32)
        self.fill = _get(d, "fill_color", n, (0.0, 0.0, 0.0, 0.0))
        fill_opacity = _get(d, "fill_opacity", n, 1.0).astype(np.float64)
        kind = _get(d, "spt_stroke", n, KIND_NONE)
        self.line_width = np.ones(n, dtype=np.int32)
        self.is_imported_fill = (kind == KIND_QUAD) | (kind == KIND_POLYGON)
        self.ordinal = np.where(kind != KIND_NONE, _get(d, "spt_order", n, -1), -1).astype(np.int64)
        self.set_hint = _get(d, "spt_set", n, 0).astype(np.int64)
        self.alpha = np.clip(np.floor(fill_opacity * 255.0 + 0.5), 0, 255).astype(np.int64)
        self.co4 = np.zeros((n, 12), dtype=np.float32)
        four = np.flatnonzero(self.npoints == 4)
        if four.size:
            self.co4[four] = self._co[point_index(self._off[four], np.full(four.size, 4))].reshape(-1, 12)

    def coords(self, idx):
        """The points of strokes `idx`: co (sum m, 3) float32 and the start of each stroke's points
        in it (len(idx) + 1 offsets)."""
        idx = np.asarray(idx, dtype=np.int64)
        counts = self.npoints[idx]
        start = np.zeros(len(idx) + 1, dtype=np.int64)
        np.cumsum(counts, out=start[1:])
        return self._co[point_index(self._off[idx], counts)], start

    def points(self, i: int):
        """(co (m, 3), width px, opacity, vertex_color (m, 4)) of stroke i."""
        s0, s1 = int(self._off[i]), int(self._off[i + 1])
        return (self._co[s0:s1], self._radius[s0:s1] * 2000.0, self._opacity[s0:s1], self._vcol[s0:s1])


def read_frame(frame) -> FrameData:
    return FrameData(frame)
