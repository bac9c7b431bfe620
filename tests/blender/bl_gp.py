"""The tests' own view of a Grease Pencil object in either data model (GPv2: Blender 3.x-4.2,
GPv3: 4.3 and later), written against bpy directly and not through the add-on's backends, so a
test checks what Blender holds rather than what the add-on believes it wrote.

Strokes are proxies with the same names in both models: points (list of (x, y, z) metres, get
and set), fill (scene-linear RGBA of the fill / vertex fill colour, get and set), material_index,
cyclic, ordinal (the file's drawing order the import hid in the stroke, or -1), width_px (per
point, curves); material_index can be set (the Material panel's Assign). Edits an artist makes are functions here: move, rotate, delete, draw a line (as
the Draw tool leaves it: no spt data), hide a layer, delete or insert a key frame."""

import math

import bpy
import numpy as np

V3 = bpy.app.version >= (4, 3, 0)
OBJECT_TYPE = 'GREASEPENCIL' if V3 else 'GPENCIL'


def layer_names(obj):
    return [(l.name if V3 else l.info) for l in obj.data.layers]


def layer(obj, name):
    for l in obj.data.layers:
        if (l.name if V3 else l.info) == name:
            return l
    raise KeyError(name)


def frame(l, number):
    """The key frame of layer l at exactly `number`, or None."""
    for f in l.frames:
        if f.frame_number == number:
            return f
    return None


def frame_numbers(l):
    return sorted(f.frame_number for f in l.frames)


def hide_layer(obj, name, hide=True):
    layer(obj, name).hide = hide


def delete_key(obj, number):
    """Deletes the key frame at `number` on every layer (the previous key then holds)."""
    for l in obj.data.layers:
        f = frame(l, number)
        if f is not None:
            l.frames.remove(number if V3 else f)


def copy_key(obj, src, dst):
    """Inserts a key at `dst` on every layer holding a copy of the key at `src`."""
    for l in obj.data.layers:
        f = frame(l, src)
        if f is None:
            continue
        if V3:
            l.frames.copy(src, dst)
        else:
            l.frames.copy(f).frame_number = dst


# ---------------------------------------------------------------- strokes

def strokes(f):
    """Proxies of the strokes of GP frame f, in order."""
    if not V3:
        return [_V2Stroke(s) for s in f.strokes]
    d = f.drawing
    return [_V3Stroke(d, i) for i in range(max(len(d.curve_offsets) - 1, 0))]


def stroke_count(f):
    return len(f.strokes) if not V3 else max(len(f.drawing.curve_offsets) - 1, 0)


class _V2Stroke:
    def __init__(self, s):
        self.s = s

    @property
    def points(self):
        return [tuple(p.co) for p in self.s.points]

    @points.setter
    def points(self, pts):
        for p, c in zip(self.s.points, pts):
            p.co = c

    @property
    def fill(self):
        return tuple(self.s.vertex_color_fill)

    @fill.setter
    def fill(self, rgba):
        self.s.vertex_color_fill = rgba

    @property
    def material_index(self):
        return self.s.material_index

    @material_index.setter
    def material_index(self, i):
        self.s.material_index = i

    @property
    def cyclic(self):
        return bool(self.s.use_cyclic)

    @property
    def ordinal(self):
        s = self.s
        if s.hardness < 1.0:
            return int(round((s.hardness - 0.5) * 2 ** 24))
        if s.uv_translation[1] == 1.0:
            return int(s.uv_translation[0])
        return -1

    @property
    def width_px(self):
        return [p.pressure * self.s.line_width for p in self.s.points]

    def delete(self, f):
        f.strokes.remove(self.s)

    def remove_last_point(self):
        self.s.points.pop(index=len(self.s.points) - 1)


class _V3Stroke:
    def __init__(self, d, i):
        self.d, self.i = d, i

    def _range(self):
        off = [o.value for o in self.d.curve_offsets]
        return off[self.i], off[self.i + 1]

    @property
    def points(self):
        a, b = self._range()
        pos = self.d.attributes["position"].data
        return [tuple(pos[k].vector) for k in range(a, b)]

    @points.setter
    def points(self, pts):
        a, b = self._range()
        pos = self.d.attributes["position"].data
        for k, c in zip(range(a, b), pts):
            pos[k].vector = c
        self.d.tag_positions_changed()

    @property
    def fill(self):
        a = self.d.attributes.get("fill_color")
        return tuple(a.data[self.i].color) if a is not None else (0.0, 0.0, 0.0, 0.0)

    @fill.setter
    def fill(self, rgba):
        a = self.d.attributes.get("fill_color") or self.d.attributes.new("fill_color", 'FLOAT_COLOR', 'CURVE')
        a.data[self.i].color = rgba

    @property
    def material_index(self):
        a = self.d.attributes.get("material_index")
        return a.data[self.i].value if a is not None else 0

    @material_index.setter
    def material_index(self, i):
        a = self.d.attributes.get("material_index") or self.d.attributes.new("material_index", 'INT', 'CURVE')
        a.data[self.i].value = i

    @property
    def cyclic(self):
        a = self.d.attributes.get("cyclic")
        return bool(a.data[self.i].value) if a is not None else False

    @property
    def ordinal(self):
        k = self.d.attributes.get("spt_stroke")
        if k is None or k.data[self.i].value == 0:
            return -1
        return self.d.attributes["spt_order"].data[self.i].value

    @property
    def width_px(self):
        a, b = self._range()
        r = self.d.attributes.get("radius")
        return [(r.data[k].value if r is not None else 0.01) * 2000.0 for k in range(a, b)]

    def delete(self, f):
        self.d.remove_strokes(indices=[self.i])

    def remove_last_point(self):
        a, b = self._range()
        sizes = [o.value for o in self.d.curve_offsets]
        sizes = [sizes[k + 1] - sizes[k] for k in range(len(sizes) - 1)]
        sizes[self.i] -= 1
        self.d.resize_strokes(sizes=sizes)


def by_ordinal(f):
    return {s.ordinal: s for s in strokes(f) if s.ordinal >= 0}


def move(s, dx, dz):
    s.points = [(x + dx, y, z + dz) for x, y, z in s.points]


def rotate(s, angle):
    pts = s.points
    cx = sum(p[0] for p in pts) / len(pts)
    cz = sum(p[2] for p in pts) / len(pts)
    c, sn = math.cos(angle), math.sin(angle)
    s.points = [(cx + (x - cx) * c - (z - cz) * sn, y, cz + (x - cx) * sn + (z - cz) * c) for x, y, z in pts]


def scale(s, factor):
    pts = s.points
    cx = sum(p[0] for p in pts) / len(pts)
    cz = sum(p[2] for p in pts) / len(pts)
    s.points = [(cx + (x - cx) * factor, y, cz + (z - cz) * factor) for x, y, z in pts]


def draw_line(f, material_index, co, width_px, cyclic=False):
    """A stroke as the Draw tool leaves it (no spt data): points `co` (x, y, z metres),
    `width_px` wide. v2: line_width px with pressure 1; v3: radius = width / 2 in metres."""
    if not V3:
        ns = f.strokes.new()
        ns.material_index = material_index
        ns.line_width = int(width_px)
        ns.use_cyclic = cyclic
        ns.points.add(len(co))
        ns.points.foreach_set("co", [c for p in co for c in p])
        if cyclic:
            ns.points.update()
        return
    d = f.drawing
    n0 = max(len(d.curve_offsets) - 1, 0)
    d.add_strokes([len(co)])
    pos = d.attributes["position"].data
    m0 = len(pos) - len(co)
    for k, p in enumerate(co):
        pos[m0 + k].vector = p
    r = d.attributes.get("radius") or d.attributes.new("radius", 'FLOAT', 'POINT')
    for k in range(len(co)):
        r.data[m0 + k].value = width_px / 2000.0
    mi = d.attributes.get("material_index") or d.attributes.new("material_index", 'INT', 'CURVE')
    mi.data[n0].value = material_index
    if cyclic:
        cy = d.attributes.get("cyclic") or d.attributes.new("cyclic", 'BOOLEAN', 'CURVE')
        cy.data[n0].value = True
    d.tag_positions_changed()
