"""Every Grease Pencil call of the add-on, for the GPv2 Python API (Blender 2.93 .. 4.2).

Blender 4.3 replaced the API (GPv3); a gp_v3.py with the same functions can sit beside this one
and gp.py picks by bpy.app.version. Nothing outside this module touches GP data directly.

Units: 1 px = 1 mm. Point coordinates are metres in the object's XZ plane: x_px / 1000 -> X,
y_px / 1000 -> -Z (image y grows downward). The object is not scaled, so brush sizes behave as
usual when an artist draws.

Hidden per-stroke data of imported quads (stroke-level, so it is written in bulk and survives
moving, rotating and recolouring; none of it affects a fill-only material):
  hardness  = 0.5 + ordinal * 2^-24  the stroke's index in the frame's drawing order (< 2^23);
                                     a stroke drawn by hand has hardness 1.0
  line_width = set + 1               stroke set hint (ambiguous when two sets have one size)
  aspect[0] = 0.5 + alpha / 512      the colour's alpha (fills have no per-stroke opacity)
Curves (GP lines, material without fill): uv_translation = (ordinal, 1); point pressure = width
in px with line_width 1; point strength = alpha / 255.
Polygons (format 1.2; closed, cyclic, solid fill, no line): hardness = 0.5 + ordinal * 2^-24 as
quads, line_width 1, aspect 1; vertex_color_fill = colour. A GPv2 stroke has no fill opacity of
its own (the shader takes the fill's alpha from the material only), so the alpha and the grid N
live in the material: one per (alpha, N) used (polygon_material), fill_color = (1, 1, 1, alpha).
"""

import bpy
import numpy as np

SUPPORTED = bpy.app.version < (4, 3, 0)

ORDINAL_SCALE = 2.0 ** -24
MAX_ORDINAL = 1 << 23
UV_FILL = np.array([0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0], dtype=np.float32)


# ---------------------------------------------------------------- objects, camera, materials

def new_object(context, name: str):
    gpd = bpy.data.grease_pencils.new(name)
    obj = bpy.data.objects.new(name, gpd)
    context.scene.collection.objects.link(obj)
    return obj


def new_camera(context, name: str, width: int, height: int):
    """An orthographic camera that frames the W x H mm canvas exactly."""
    cam = bpy.data.cameras.new(name)
    cam.type = 'ORTHO'
    cam.ortho_scale = max(width, height) / 1000.0
    cam.sensor_fit = 'AUTO'
    obj = bpy.data.objects.new(name, cam)
    obj.location = (width / 2000.0, -1.0, -height / 2000.0)
    obj.rotation_euler = (np.pi / 2, 0.0, 0.0)
    context.scene.collection.objects.link(obj)
    return obj


def stencil_image(name: str, coverage: np.ndarray):
    """An image whose alpha is the template coverage (rows top first, 0..255), rgb white."""
    h, w = coverage.shape
    img = bpy.data.images.new(name, width=w, height=h, alpha=True)
    px = np.ones((h, w, 4), dtype=np.float32)
    px[:, :, 3] = coverage[::-1, :].astype(np.float32) / 255.0  # Blender rows are bottom first
    img.pixels.foreach_set(px.ravel())
    img.pack()
    return img


def template_material(name: str, image):
    mat = bpy.data.materials.new(name)
    bpy.data.materials.create_gpencil_data(mat)
    gp = mat.grease_pencil
    gp.show_stroke = False
    gp.show_fill = True
    gp.fill_style = 'TEXTURE'
    gp.fill_image = image
    gp.mix_factor = 1.0
    gp.texture_clamp = True
    gp.texture_offset = (-0.5, -0.5)
    gp.fill_color = (1.0, 1.0, 1.0, 1.0)
    return mat


def curve_material(name: str):
    mat = bpy.data.materials.new(name)
    bpy.data.materials.create_gpencil_data(mat)
    gp = mat.grease_pencil
    gp.show_stroke = True
    gp.show_fill = False
    gp.color = (1.0, 1.0, 1.0, 1.0)
    return mat


def polygon_material(name: str, alpha: int):
    """Solid fill, no line: white with the polygons' alpha, tinted per stroke by
    vertex_color_fill (mix 1), so vertex paint recolours a polygon as it does a quad."""
    mat = bpy.data.materials.new(name)
    bpy.data.materials.create_gpencil_data(mat)
    gp = mat.grease_pencil
    gp.show_stroke = False
    gp.show_fill = True
    gp.fill_style = 'SOLID'
    gp.fill_color = (1.0, 1.0, 1.0, alpha / 255.0)
    return mat


def add_material(obj, mat) -> int:
    obj.data.materials.append(mat)
    return len(obj.data.materials) - 1


def material_color(mat, fill: bool):
    if mat is None or mat.grease_pencil is None:
        return (0.0, 0.0, 0.0, 1.0)
    gp = mat.grease_pencil
    return tuple(gp.fill_color if fill else gp.color)


# ---------------------------------------------------------------- layers and frames

def new_layer(obj, name: str):
    return obj.data.layers.new(name, set_active=False)


def layers(obj):
    return list(obj.data.layers)


def layer_name(layer) -> str:
    return layer.info


def layer_hidden(layer) -> bool:
    return bool(layer.hide)


def new_frame(layer, number: int):
    return layer.frames.new(number)


def frame_index(layer):
    """(sorted frame numbers, frames) of a layer, for frame_at_sorted."""
    frs = sorted(layer.frames, key=lambda f: f.frame_number)
    return [f.frame_number for f in frs], frs


def frame_at_sorted(index, number: int):
    """The frame shown at scene frame `number` (the latest key at or before it) or None."""
    import bisect
    numbers, frs = index
    k = bisect.bisect_right(numbers, number) - 1
    return frs[k] if k >= 0 else None


# ---------------------------------------------------------------- writing strokes in bulk
#
# Measured on Blender 3.4 (see the README): strokes.new() then points.add() in one loop is slower
# than all strokes.new() first, then points.add() over the collection; per stroke only new(),
# points.add() and the point coordinates (+ uv_fill) cross into Blender, every stroke-level value
# is one foreach_set per frame. GPv2 has no bulk access to the points of several strokes.

QUAD, LINE, FILL = 0, 1, 2   # fill_frame's stroke shapes: template quad, curve, polygon


def fill_frame(frame, shape, quad_co, paths, material_index, fill_rgba, ordinal, set_hint, alpha):
    """Adds n strokes to an EMPTY frame, in order.

    shape (n,) QUAD / LINE / FILL; quad_co (nq, 12) float32: XYZ of the 4 corners of each quad,
    in order; paths: per LINE or FILL stroke, in order: curves (co (m, 3) float32, pressure (m,),
    strength (m,), vertex_color (m, 4)), polygons (co (m, 3),); per stroke (n,): material_index,
    fill_rgba (n, 4) scene-linear, ordinal (drawing order in the file's frame), set_hint, alpha
    (0..255, quads only)."""
    strokes = frame.strokes
    shape = np.asarray(shape)
    n = shape.shape[0]
    if n == 0:
        return
    if len(strokes):
        raise ValueError("fill_frame needs an empty frame")
    if np.max(ordinal) >= MAX_ORDINAL:
        raise ValueError(f"a frame holds more than {MAX_ORDINAL} strokes")
    new = strokes.new
    for _ in range(n):
        new()
    pts = [s.points for s in strokes]
    uv = UV_FILL
    if (shape == QUAD).all():
        for p in pts:
            p.add(4)
        for p, r in zip(pts, quad_co):  # the hot loop of import
            p.foreach_set('co', r)
            p.foreach_set('uv_fill', uv)
    else:
        qi = ci = 0
        for p, k in zip(pts, shape.tolist()):
            if k == QUAD:
                p.add(4)
                p.foreach_set('co', quad_co[qi])
                p.foreach_set('uv_fill', uv)
                qi += 1
                continue
            path = paths[ci]
            ci += 1
            co = path[0]
            p.add(co.shape[0])
            p.foreach_set('co', np.ascontiguousarray(co, dtype=np.float32).ravel())
            if k == FILL:
                # points.add() triangulated the outline while its points were all at the origin:
                # right for convex quads only, so a polygon is triangulated again.
                p.update()
                continue
            pressure, strength, vcol = path[1:]
            p.foreach_set('pressure', np.ascontiguousarray(pressure, dtype=np.float32))
            p.foreach_set('strength', np.ascontiguousarray(strength, dtype=np.float32))
            p.foreach_set('vertex_color', np.ascontiguousarray(vcol, dtype=np.float32).ravel())
    # The hidden per-stroke data (module docstring), one foreach_set per property.
    quad = shape == QUAD
    fill_like = shape != LINE
    ordinal = np.asarray(ordinal, dtype=np.float64)
    hardness = np.where(fill_like, 0.5 + ordinal * ORDINAL_SCALE, 1.0)
    aspect = np.ones((n, 2), dtype=np.float32)
    aspect[:, 0] = np.where(quad, 0.5 + np.asarray(alpha, dtype=np.float32) / 512.0, 1.0)
    uvt = np.zeros((n, 2), dtype=np.float32)
    uvt[~fill_like, 0] = ordinal[~fill_like]
    uvt[~fill_like, 1] = 1.0
    fill = np.where(fill_like[:, None], np.asarray(fill_rgba, dtype=np.float32), 0.0)
    for name, values, dtype in (("material_index", material_index, np.int32), ("use_cyclic", fill_like, bool),
                                ("vertex_color_fill", fill, np.float32), ("hardness", hardness, np.float32),
                                ("line_width", np.where(quad, np.asarray(set_hint) + 1, 1), np.int32),
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
