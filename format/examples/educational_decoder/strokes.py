"""The stroke model (SPEC.md 4), the live stroke list (SPEC.md 5) and the stored stroke records
(SPEC.md 6), which both coding 0 and the manifest's live_fnv1a64 hash use."""
import struct
from dataclasses import dataclass, field

from .errors import fail

STAMP, AFFINE, CURVE, POLYGON = 0, 1, 2, 3
COORD_MAX = 1 << 24   # |x|, |y|, |tx|, |ty| (Q4)
MATRIX_MAX = 1 << 16  # |a|, |b|, |c|, |d|
MAX_CODE = 0x7BFF     # colour encoding 1: the largest code, finite and not negative
WIDTH_MAX = 1 << 16   # curve width (Q4)


@dataclass
class Stamp:
    set: int
    template: int
    orient: int
    x: int
    y: int
    rgba: tuple
    kind: int = STAMP
    lo: tuple = (0, 0, 0)  # colour encoding 1: the low bytes R_lo, G_lo, B_lo (SPEC.md 4)


@dataclass
class Affine:
    template: int
    tx: int
    ty: int
    a: int
    b: int
    c: int
    d: int
    rgba: tuple
    kind: int = AFFINE
    lo: tuple = (0, 0, 0)


@dataclass
class Curve:
    rgba: tuple
    points: list = field(default_factory=list)  # [x, y, width] lists
    kind: int = CURVE
    lo: tuple = (0, 0, 0)
    grid: int = 0  # the supersampling grid N (format 1.4, curve_grid files): 0 or 2..16


@dataclass
class Polygon:
    rgba: tuple
    grid: int  # the supersampling grid N: 0 or 2..16
    vertices: list = field(default_factory=list)  # [x, y] lists
    kind: int = POLYGON
    lo: tuple = (0, 0, 0)


def check_coord(v, what):
    if not -COORD_MAX <= v <= COORD_MAX:
        fail("Corrupt", f"{what}: coordinate {v} is outside +-2^24")


def codes(s):
    """Colour encoding 1: the stroke's three 16-bit codes, 256 * high byte + low byte."""
    return tuple(256 * hi + lo for hi, lo in zip(s.rgba[:3], s.lo))


def check_stroke(s, header, template_count, what):
    """The value ranges of SPEC.md 4 (and the table sizes of HEAD)."""
    if header.color_encoding == 1 and max(codes(s)) > MAX_CODE:
        fail("Corrupt", f"{what}: colour code above 0x7BFF (not a finite half float >= 0)")
    if s.kind == STAMP:
        if s.set >= len(header.sets) or s.template >= template_count or s.orient >= len(header.orientations):
            fail("Corrupt", f"{what}: stamp set, template or orientation out of range")
        check_coord(s.x, what)
        check_coord(s.y, what)
    elif s.kind == AFFINE:
        if s.template >= template_count:
            fail("Corrupt", f"{what}: affine template out of range")
        check_coord(s.tx, what)
        check_coord(s.ty, what)
        if max(abs(s.a), abs(s.b), abs(s.c), abs(s.d)) > MATRIX_MAX:
            fail("Corrupt", f"{what}: affine matrix entry outside +-2^16")
        if s.a * s.d - s.b * s.c == 0:
            fail("Corrupt", f"{what}: affine matrix is singular")
    elif s.kind == CURVE:
        if not s.points:
            fail("Corrupt", f"{what}: curve without points")
        if s.grid == 1 or s.grid > 16:
            fail("Unsupported", f"{what}: curve grid {s.grid} is reserved")
        for x, y, w in s.points:
            check_coord(x, what)
            check_coord(y, what)
            if not 0 <= w <= WIDTH_MAX:
                fail("Corrupt", f"{what}: curve width {w} outside 0..2^16")
    else:
        if len(s.vertices) < 3:
            fail("Corrupt", f"{what}: polygon with fewer than 3 vertices")
        if s.grid == 1 or s.grid > 16:
            fail("Unsupported", f"{what}: polygon grid {s.grid} is reserved")
        for x, y in s.vertices:
            check_coord(x, what)
            check_coord(y, what)


def stored_record(s, linear=False, curve_grid=False):
    """A stroke's coding-0 record (SPEC.md 6), its kind byte first. In colour encoding 1
    (`linear`) the colour's r, g, b, a bytes are followed by r_lo, g_lo, b_lo; in a file with
    the curve_grid flag a curve's colour is followed by its grid, as a polygon's is."""
    colour = bytes(s.rgba) + (bytes(s.lo) if linear else b"")
    if s.kind == STAMP:
        return struct.pack("<BBBBii", STAMP, s.set, s.template, s.orient, s.x, s.y) + colour
    if s.kind == AFFINE:
        return struct.pack("<BBiiiiii", AFFINE, s.template, s.tx, s.ty, s.a, s.b, s.c, s.d) + colour
    if s.kind == CURVE:
        grid = bytes([s.grid]) if curve_grid else b""
        out = bytes([CURVE]) + colour + grid + struct.pack("<I", len(s.points))
        return out + b"".join(struct.pack("<iiI", x, y, w) for x, y, w in s.points)
    out = bytes([POLYGON]) + colour + struct.pack("<BI", s.grid, len(s.vertices))
    return out + b"".join(struct.pack("<ii", x, y) for x, y in s.vertices)


def fnv1a64(data):
    h = 0xCBF29CE484222325
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def live_hash(live, linear=False, curve_grid=False):
    """The manifest's live_fnv1a64: FNV-1a 64 of the live list as a coding-0 key frame body of
    the file (its records as that file stores them: low bytes, curve grids)."""
    return fnv1a64(struct.pack("<I", len(live)) + b"".join(stored_record(s, linear, curve_grid) for s in live))


# ---- SPEC.md 5: applying a frame ----

class Motion:
    """A motion field: block size bs and cols x rows vectors (dx, dy), row-major."""

    def __init__(self, bs, cols, rows, vectors):
        self.bs, self.cols, self.rows, self.vectors = bs, cols, rows, vectors

    def vector_at(self, px, py):
        bx = min(max(px // (16 * self.bs), 0), self.cols - 1)  # // floors, as floor_div
        by = min(max(py // (16 * self.bs), 0), self.rows - 1)
        return self.vectors[by * self.cols + bx]


def move(s, motion, what):
    """Moves a stroke's anchor points by the motion field (SPEC.md 5)."""
    if s.kind == STAMP:
        dx, dy = motion.vector_at(s.x, s.y)
        s.x, s.y = s.x + dx, s.y + dy
        check_coord(s.x, what)
        check_coord(s.y, what)
    elif s.kind == AFFINE:
        dx, dy = motion.vector_at(s.tx, s.ty)
        s.tx, s.ty = s.tx + dx, s.ty + dy
        check_coord(s.tx, what)
        check_coord(s.ty, what)
    elif s.kind == CURVE:
        for p in s.points:
            dx, dy = motion.vector_at(p[0], p[1])
            p[0] += dx
            p[1] += dy
            check_coord(p[0], what)
            check_coord(p[1], what)
    else:
        dx, dy = motion.vector_at(*s.vertices[0])  # rigidly, by the block of P_0
        for v in s.vertices:
            v[0] += dx
            v[1] += dy
            check_coord(v[0], what)
            check_coord(v[1], what)


def copy_stroke(s):
    if s.kind == CURVE:
        return Curve(s.rgba, [list(p) for p in s.points], lo=s.lo, grid=s.grid)
    if s.kind == POLYGON:
        return Polygon(s.rgba, s.grid, [list(v) for v in s.vertices], lo=s.lo)
    return type(s)(**{k: getattr(s, k) for k in s.__dataclass_fields__})


def remove_and_move(live, removed, motion, what):
    """Steps 1 and 2 of an inter frame: a new list, the previous one left as it was."""
    for i in removed:
        if i >= len(live):
            fail("Corrupt", f"{what}: removal index {i} is not below the live length {len(live)}")
    gone = set(removed)
    kept = [copy_stroke(s) for i, s in enumerate(live) if i not in gone]
    if motion is not None:
        for s in kept:
            move(s, motion, what)
    return kept
