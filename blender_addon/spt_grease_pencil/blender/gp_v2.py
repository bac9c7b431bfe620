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


def frame_at(layer, number: int):
    """The layer's frame shown at scene frame `number` (its latest key at or before it)."""
    best = None
    for fr in layer.frames:
        if fr.frame_number <= number and (best is None or fr.frame_number > best.frame_number):
            best = fr
    return best


# ---------------------------------------------------------------- writing strokes in bulk

def add_quads(frame, corners_m: np.ndarray, material_index, fill_rgba, ordinal, set_hint, alpha):
    """Appends N textured quads. corners_m: (N, 4, 2) XY in metres (image y down, not negated)."""
    n = corners_m.shape[0]
    if n == 0:
        return
    co = np.zeros((n, 4, 3), dtype=np.float32)
    co[:, :, 0] = corners_m[:, :, 0]
    co[:, :, 2] = -corners_m[:, :, 1]
    rows = list(co.reshape(n, 12))
    strokes = frame.strokes
    first = len(strokes)
    new = strokes.new
    uv = UV_FILL
    for r in rows:  # the hot loop: one stroke per iteration, nothing else
        p = new().points
        p.add(4)
        p.foreach_set('co', r)
        p.foreach_set('uv_fill', uv)
    _bulk_set(frame, first, n, material_index, fill_rgba, ordinal, set_hint, alpha)


def _bulk_set(frame, first, n, material_index, fill_rgba, ordinal, set_hint, alpha):
    strokes = frame.strokes
    total = len(strokes)
    # foreach_set works on the whole collection: read, patch our slice, write back.
    def put(prop, values, dtype, width=1):
        arr = np.empty(total * width, dtype=dtype)
        strokes.foreach_get(prop, arr)
        arr[first * width:(first + n) * width] = np.asarray(values, dtype=dtype).ravel()
        strokes.foreach_set(prop, arr)
    put('material_index', material_index, np.int32)
    put('use_cyclic', np.ones(n, dtype=bool), bool)
    put('vertex_color_fill', fill_rgba, np.float32, 4)
    put('hardness', 0.5 + np.asarray(ordinal, dtype=np.float64) * ORDINAL_SCALE, np.float32)
    put('line_width', np.asarray(set_hint, dtype=np.int32) + 1, np.int32)
    asp = np.ones((n, 2), dtype=np.float32)
    asp[:, 0] = 0.5 + np.asarray(alpha, dtype=np.float32) / 512.0
    put('aspect', asp, np.float32, 2)


def add_curve(frame, points_m: np.ndarray, widths_px: np.ndarray, material_index: int, line_rgb, alpha: int,
              ordinal: int):
    """Appends one GP line stroke. points_m: (n, 2) XY metres (image y down)."""
    n = points_m.shape[0]
    s = frame.strokes.new()
    s.material_index = material_index
    s.line_width = 1
    s.uv_translation = (float(ordinal), 1.0)
    s.use_cyclic = False
    p = s.points
    p.add(n)
    co = np.zeros((n, 3), dtype=np.float32)
    co[:, 0] = points_m[:, 0]
    co[:, 2] = -points_m[:, 1]
    p.foreach_set('co', co.ravel())
    p.foreach_set('pressure', np.asarray(widths_px, dtype=np.float32))
    p.foreach_set('strength', np.full(n, alpha / 255.0, dtype=np.float32))
    vc = np.empty((n, 4), dtype=np.float32)
    vc[:, 0:3] = line_rgb
    vc[:, 3] = 1.0
    p.foreach_set('vertex_color', vc.ravel())


# ---------------------------------------------------------------- reading strokes back

class FrameData:
    """One GP frame read back in bulk. Per stroke: material index, point count, hardness,
    line width, aspect x, fill colour, uv translation; points concatenated."""

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
        self.aspect_x = aspect[0::2]
        self.fill = self.fill.reshape(n, 4)
        self.uv_translation = uvt.reshape(n, 2)
        self._strokes = strokes
        self._list = None
        self.npoints = np.fromiter((len(s.points) for s in strokes), dtype=np.int64, count=n)
        self.offsets = np.zeros(n + 1, dtype=np.int64)
        np.cumsum(self.npoints, out=self.offsets[1:])
        total = int(self.offsets[-1])
        co = np.empty(total * 3, dtype=np.float32)
        off = self.offsets
        for i, s in enumerate(strokes):  # the hot loop of export
            a, b = off[i], off[i + 1]
            if b > a:
                s.points.foreach_get('co', co[3 * a:3 * b])
        co = co.reshape(total, 3)
        # Back to image orientation, metres: x right, y down.
        self.xy = np.stack([co[:, 0], -co[:, 2]], axis=1).astype(np.float64)

    def point_attrs(self, i: int):
        """(pressure, strength, vertex_color (n, 4)) of stroke i (curves only: slow path)."""
        if self._list is None:
            self._list = list(self._strokes)  # indexing a GP stroke collection is O(i)
        p = self._list[i].points
        n = len(p)
        pr = np.empty(n, dtype=np.float32)
        st = np.empty(n, dtype=np.float32)
        vc = np.empty(4 * n, dtype=np.float32)
        p.foreach_get('pressure', pr)
        p.foreach_get('strength', st)
        p.foreach_get('vertex_color', vc)
        return pr, st, vc.reshape(n, 4)


def read_frame(frame) -> FrameData:
    return FrameData(frame)
