"""Range-coded frame bodies, coding 1 (SPEC.md 7.1, 7.4, 7.5)."""
from .errors import ByteReader, fail
from .range_coder import Context, RangeDecoder, Res8, SInt, Tree, UInt, bits, contexts
from .strokes import AFFINE, CURVE, MATRIX_MAX, POLYGON, STAMP, Affine, Curve, Motion, Polygon, Stamp, check_coord
from .polygon import decode_grid, decode_polygon


class BodyPrefix:
    """The plain-byte fields that start a coding-1 (and coding-2) body (SPEC.md 7.1)."""

    def __init__(self, body, key, header, what):
        r = ByteReader(body, what)
        self.removed_count = 0
        self.bs = 0
        self.edits = b""
        if key:
            self.added_count = r.varint("added_count")
        else:
            self.removed_count = r.varint("removed_count")
            self.added_count = r.varint("added_count")
            present = r.u8("motion_present")
            if present > 1:
                fail("Unsupported", f"{what}: motion_present {present} is reserved")
            if present:
                self.bs = r.u16("block_size")
                if not 8 <= self.bs <= 256:
                    fail("Corrupt", f"{what}: motion block size {self.bs} outside 8..256")
            self.edits = r.take(r.varint("edit_length"), "edit stream")
            if self.removed_count == 0 and not self.bs and self.edits:
                fail("Corrupt", f"{what}: the edit stream of a frame without edits is not empty")
        self.rest = r  # the reader stands at the first byte after the prefix


# ---- 7.5 edit stream ----

def median(a, b, d):
    return max(min(a, b), min(max(a, b), d))


def decode_edits(prefix, header, prev_live, what):
    """Returns (removed, motion) of an inter frame."""
    removed, motion = [], None
    if prefix.removed_count == 0 and not prefix.bs:
        return removed, motion  # nothing coded: the stream is empty (checked by BodyPrefix)
    rc = RangeDecoder(prefix.edits, what + " edit stream")
    gap, run, mvx, mvy = UInt(), UInt(), SInt(), SInt()
    prev = -1
    for _ in range(prefix.removed_count):
        index = prev + 1 + rc.uint(gap)
        if index >= prev_live:
            fail("Corrupt", f"{what}: removal index {index} is not below the live length {prev_live}")
        removed.append(index)
        prev = index
    if prefix.bs:
        bs = prefix.bs
        cols, rows = -(-header.width // bs), -(-header.height // bs)
        v = [None] * (cols * rows)

        def prediction(i):
            c, r = i % cols, i // cols
            if r == 0:
                return v[i - 1] if c > 0 else (0, 0)
            t = v[i - cols]
            left = v[i - 1] if c > 0 else t
            tr = v[i - cols + 1] if c + 1 < cols else t
            return (median(left[0], t[0], tr[0]), median(left[1], t[1], tr[1]))

        i = 0
        while i < cols * rows:
            n = rc.uint(run)
            if i + n > cols * rows:
                fail("Corrupt", f"{what}: motion run past the last block")
            for _ in range(n):
                v[i] = prediction(i)
                i += 1
            if i < cols * rows:
                p = prediction(i)
                ex, ey = rc.sint(mvx), rc.sint(mvy)
                if ex == 0 and ey == 0:
                    fail("Corrupt", f"{what}: a zero motion residual outside a run")
                dx, dy = p[0] + ex, p[1] + ey
                if not (-32768 <= dx <= 32767 and -32768 <= dy <= 32767):
                    fail("Corrupt", f"{what}: motion vector outside i16")
                v[i] = (dx, dy)
                i += 1
        motion = Motion(bs, cols, rows, v)
    rc.end()
    return removed, motion


# ---- 7.4 stroke stream ----

class Position:
    """pos[g][a]: the contexts of one axis of one stroke group."""

    def __init__(self, extent):
        self.extent = extent
        self.inside = Context()
        self.pix = Tree(bits(extent - 1))
        self.outside = SInt()
        self.frac8 = Context()
        self.frac = Tree(4)


class StrokeStream:
    """The coding-1 stroke stream (7.4). `rc` is given when the strokes are read from another
    stream's coder: the lead strokes of a coding-2 frame (7.7.5)."""

    def __init__(self, data, header, template_count, what, rc=None):
        self.rc = rc if rc is not None else RangeDecoder(data, what + " stroke stream")
        self.what = what
        self.header = header
        W, H = header.width, header.height
        self.n_sets, self.n_orients = len(header.sets), len(header.orientations)
        self.n_templates = template_count
        tb = bits(self.n_templates - 1) if self.n_templates > 1 else 0
        ob = bits(self.n_orients - 1)
        self.kind0, self.kind1, self.kind2 = contexts(4), contexts(4), contexts(4)
        self.same_set = Context()
        self.set_tree = Tree(4)
        self.tmpl = [Tree(tb) for _ in range(16)]
        self.affine_tmpl = Tree(tb)
        self.same_orient = contexts(16)
        self.orient = [Tree(ob) for _ in range(16)]
        self.pos = [[Position(W), Position(H)] for _ in range(4)]
        self.color = [[Res8() for _ in range(4)] for _ in range(3)]
        self.opaque = Context()
        self.alpha = Tree(8)
        self.color_lo = [Tree(8) for _ in range(3)]  # [G, R, B] low bytes, colour encoding 1
        self.matrix = [SInt() for _ in range(4)]
        self.axis_aligned, self.same_scale, self.similarity = Context(), Context(), Context()
        self.matrix_shift = Tree(3)
        self.points = UInt()
        self.width0, self.dx, self.dy, self.dw = SInt(), SInt(), SInt(), SInt()
        self.curve_same_aa, self.curve_aa = Context(), Tree(5)  # format 1.4, curve_grid files
        # predictors
        self.prev_kind = 0
        self.prev_set = 0
        self.prev_orient = [0] * 16
        self.prev_color = (128, 128, 128)
        self.prev_width0 = 0
        self.prev_curve_aa = 0
        self.grid_cols, self.grid_rows = -(-W // 8), -(-H // 8)
        self.grid = {}  # written colour cells: (col, row) -> (r, g, b)
        self.polygon_state = None  # contexts of 7.4 step 5, made by polygon.py on first use

    def fail(self, message):
        fail("Corrupt", f"{self.what}: {message}")

    def position(self, g, a):
        m, rc = self.pos[g][a], self.rc
        if rc.flag(m.inside) == 0:
            p = rc.tree(m.pix)
            if p >= m.extent:
                self.fail("pixel position past the canvas coded as inside")
        else:
            p = rc.sint(m.outside)
            if 0 <= p < m.extent:
                self.fail("pixel position inside the canvas coded as outside")
        f = 8
        if rc.flag(m.frac8):
            f = rc.tree(m.frac)
            if f == 8:
                self.fail("fraction 8 coded in full")
        v = 16 * p + f
        check_coord(v, self.what)
        return v

    def colour(self, q, x, y):
        rc = self.rc
        cell = (min(max((x >> 4) >> 3, 0), self.grid_cols - 1), min(max((y >> 4) >> 3, 0), self.grid_rows - 1))
        pr, pg, pb = self.grid.get(cell, self.prev_color)
        g = (pg + rc.res8(self.color[0][q])) % 256
        r = (g + (pr - pg) + rc.res8(self.color[1][q])) % 256
        b = (g + (pb - pg) + rc.res8(self.color[2][q])) % 256
        a = 255
        if rc.flag(self.opaque):
            a = rc.tree(self.alpha)
            if a == 255:
                self.fail("alpha 255 coded in full")
        lo = (0, 0, 0)
        if self.header.color_encoding == 1:
            g_lo = rc.tree(self.color_lo[0])
            r_lo = rc.tree(self.color_lo[1])
            b_lo = rc.tree(self.color_lo[2])
            lo = (r_lo, g_lo, b_lo)
        self.grid[cell] = self.prev_color = (r, g, b)  # the high bytes only
        return (r, g, b, a), lo

    def stroke(self):
        rc, prev = self.rc, self.prev_kind
        if rc.flag(self.kind0[prev]) == 0:
            kind = STAMP
        elif rc.flag(self.kind1[prev]) == 0:
            kind = AFFINE
        elif self.header.version_minor >= 2 and rc.flag(self.kind2[prev]) == 1:
            kind = POLYGON
        else:
            kind = CURVE
        self.prev_kind = kind
        return [self.stamp, self.affine, self.curve, self.polygon][kind]()

    def stamp(self):
        rc = self.rc
        s = self.prev_set
        if self.n_sets > 1 and rc.flag(self.same_set):
            s = rc.tree(self.set_tree)
            if s == self.prev_set or s >= self.n_sets:
                self.fail(f"set {s} coded in full")
        self.prev_set = s
        t = rc.tree(self.tmpl[s])
        if t >= self.n_templates:
            self.fail(f"template {t} of {self.n_templates}")
        o = self.prev_orient[s]
        if self.n_orients > 1 and rc.flag(self.same_orient[s]):
            o = rc.tree(self.orient[s])
            if o == self.prev_orient[s] or o >= self.n_orients:
                self.fail(f"orientation {o} coded in full")
        self.prev_orient[s] = o
        x, y = self.position(0, 0), self.position(0, 1)
        rgba, lo = self.colour(min(s, 3), x, y)
        return Stamp(s, t, o, x, y, rgba, lo=lo)

    def affine(self):
        rc = self.rc
        t = rc.tree(self.affine_tmpl)
        if t >= self.n_templates:
            self.fail(f"template {t} of {self.n_templates}")
        tx, ty = self.position(1, 0), self.position(1, 1)
        axis = rc.flag(self.axis_aligned)
        if axis:
            same = rc.flag(self.same_scale)
            coded = [0] if same else [0, 3]
        else:
            sim = rc.flag(self.similarity)
            coded = [0, 2] if sim else [0, 1, 2, 3]
        shift = rc.tree(self.matrix_shift)
        if shift > 4:
            self.fail(f"matrix shift {shift}")
        m = [0, 0, 0, 0]
        odd = False
        for i in coded:  # the context of entry i (0 a, 1 b, 2 c, 3 d) is matrix[i]
            v = rc.sint(self.matrix[i])
            odd = odd or v % 2 == 1
            m[i] = v << shift
            if abs(m[i]) > MATRIX_MAX:
                self.fail("matrix entry outside +-2^16")
        if shift < 4 and not odd:
            self.fail("matrix shift is not the largest")
        a, b, c, d = m
        if axis:
            b = c = 0
            if same:
                d = a
            elif a == d:
                self.fail("a = d coded in full")
        elif sim:
            d, b = a, -c
            if c == 0:
                self.fail("an axis-aligned matrix coded as a similarity")
        elif (b == 0 and c == 0) or (d == a and b == -c):
            self.fail("a special matrix form coded in full")
        if a * d - b * c == 0:
            self.fail("singular matrix")
        rgba, lo = self.colour(0, tx, ty)
        return Affine(t, tx, ty, a, b, c, d, rgba, lo=lo)

    def curve(self):
        rc = self.rc
        n = 1 + rc.uint(self.points)
        if n > 1 << 16:
            fail("LimitExceeded", f"{self.what}: curve of {n} points")
        grid = 0
        if self.header.curve_grid:  # format 1.4: coded only in a file with the HEAD flag
            grid = self.prev_curve_aa = decode_grid(rc, self.curve_same_aa, self.curve_aa, self.prev_curve_aa,
                                                    lambda g: self.fail(f"curve grid {g}"))
        x, y = self.position(2, 0), self.position(2, 1)
        w = self.prev_width0 + rc.sint(self.width0)
        if not 0 <= w <= 1 << 16:
            self.fail("curve width out of range")
        self.prev_width0 = w
        points = [[x, y, w]]
        for _ in range(n - 1):
            x += rc.sint(self.dx)
            y += rc.sint(self.dy)
            w += rc.sint(self.dw)
            check_coord(x, self.what)
            check_coord(y, self.what)
            if not 0 <= w <= 1 << 16:
                self.fail("curve width out of range")
            points.append([x, y, w])
        rgba, lo = self.colour(0, points[0][0], points[0][1])
        return Curve(rgba, points, lo=lo, grid=grid)

    def polygon(self):
        grid, vertices = decode_polygon(self)
        rgba, lo = self.colour(0, vertices[0][0], vertices[0][1])
        return Polygon(rgba, grid, vertices, lo=lo)


def decode_strokes(data, count, header, template_count, what):
    if count == 0:
        if data:
            fail("Corrupt", f"{what}: a stroke stream without strokes is not empty")
        return []
    if count > 1 << 24:
        fail("LimitExceeded", f"{what}: {count} strokes")
    ss = StrokeStream(data, header, template_count, what)
    added = [ss.stroke() for _ in range(count)]
    ss.rc.end()
    return added


def decode_ranged(body, key, header, template_count, prev_live, what):
    """Returns (removed, motion, added) of a coding-1 body."""
    prefix = BodyPrefix(body, key, header, what)
    if not key and prefix.removed_count > prev_live:
        fail("Corrupt", f"{what}: {prefix.removed_count} removals from {prev_live} strokes")
    removed, motion = decode_edits(prefix, header, prev_live, what) if not key else ([], None)
    r = prefix.rest
    added = decode_strokes(r.take(r.left(), "stroke stream"), prefix.added_count, header, template_count, what)
    return removed, motion, added
