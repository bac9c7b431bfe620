"""Rendering (SPEC.md 8): coverage of each stroke kind, compositing, a whole frame.

A canvas holds width * height pixels, row-major, top row first: three colour values each
(8-bit values in colour encoding 0, 16-bit half codes in colour encoding 1) and, on an alpha
canvas, an 8-bit alpha value each."""
from .container import BITMAP, ELLIPSE, RECTANGLE
from .strokes import AFFINE, CURVE, STAMP, codes


# ---- 8.6 colour encoding 1: half codes and linear values ----

def lin(h):
    """A half code's linear value in units of 2^-24."""
    e, m = h >> 10, h & 1023
    return m if e == 0 else (1024 + m) << (e - 1)


def code(L):
    """The code whose lin() is nearest to L, the even one of two equally near."""
    if L < 2048:
        return L
    s = L.bit_length() - 11
    q = L >> s
    r = L - (q << s)
    if r > 1 << (s - 1) or (r == 1 << (s - 1) and q % 2 == 1):
        q += 1
    if q == 2048:
        q, s = 1024, s + 1
    return ((s + 1) << 10) | (q - 1024)


class Canvas:
    """The canvas of SPEC.md 8: `rgb` holds 3 values a pixel (bytes, or codes in colour
    encoding 1), `alpha` one byte a pixel on an alpha canvas, else None."""

    def __init__(self, header):
        self.width, self.height = header.width, header.height
        self.linear = header.color_encoding == 1
        n = self.width * self.height
        if header.alpha:
            start = (0, 0, 0)  # an alpha canvas starts transparent, all planes 0
            self.alpha = bytearray(n)
        else:
            start = tuple(header.background)
            if self.linear:
                start = tuple(256 * hi + lo for hi, lo in zip(header.background, header.background_lo))
            self.alpha = None
        self.rgb = list(start) * n if self.linear else bytearray(bytes(start) * n)

    def pixel(self, x, y):
        i = 3 * (y * self.width + x)
        return self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]

    def blend(self, x, y, cov, rgba, src):
        """8.6: composites a stroke's colour with coverage cov onto pixel (x, y); `rgba` holds
        the opacity A, `src` the three source values (bytes, or codes in colour encoding 1)."""
        alpha = (cov * rgba[3] + 127) // 255
        if alpha == 0:
            return
        p = y * self.width + x
        i = 3 * p
        for k in range(3):
            if self.linear:
                L = (lin(self.rgb[i + k]) * (255 - alpha) + lin(src[k]) * alpha + 127) // 255
                self.rgb[i + k] = code(L)
            else:
                self.rgb[i + k] = (self.rgb[i + k] * (255 - alpha) + src[k] * alpha + 127) // 255
        if self.alpha is not None:  # the alpha channel: a colour channel whose source is 255
            self.alpha[p] = (self.alpha[p] * (255 - alpha) + 255 * alpha + 127) // 255

    def frame_bytes(self):
        """The bytes render_fnv1a64 hashes (SPEC.md 9.4): R, G, B of every pixel (each code a
        little-endian u16 in colour encoding 1), then the alpha plane on an alpha canvas."""
        out = b"".join(v.to_bytes(2, "little") for v in self.rgb) if self.linear else bytes(self.rgb)
        return out + (bytes(self.alpha) if self.alpha is not None else b"")


def sample_offsets(grid):
    """The sample offsets o_k in 1/256 pixel of an N x N grid (8.2), or the centre alone."""
    if grid < 2:
        return [128]
    return [(2 * k + 1) * 128 // grid for k in range(grid)]


def share(inside, samples):
    """Coverage of a pixel with `inside` of `samples` sample points inside."""
    return (255 * inside + samples // 2) // samples


# ---- 8.4 template coverage ----

def template_coverage(t, U, V):
    if abs(U) > 131072 or abs(V) > 131072:
        return 0
    if t.kind == ELLIPSE:
        return 255 if U * U + V * V <= 1 << 32 else 0
    if t.kind == RECTANGLE:
        return 255 if abs(U) <= 65536 and abs(V) <= 65536 else 0
    if t.kind != BITMAP:  # triangle
        return 255 if U >= -65536 and V >= -65536 and U + V <= 0 else 0
    tw, th = t.width, t.height
    sx = (U + 65536) * tw // 512
    sy = (V + 65536) * th // 512
    if sx < 0 or sx >= 256 * tw or sy < 0 or sy >= 256 * th:
        return 0
    qx, qy = sx - 128, sy - 128
    ix, iy = qx // 256, qy // 256
    fx, fy = qx - 256 * ix, qy - 256 * iy

    def p(i, j):
        return t.samples[min(max(j, 0), th - 1) * tw + min(max(i, 0), tw - 1)]

    top = p(ix, iy) * (256 - fx) + p(ix + 1, iy) * fx
    bot = p(ix, iy + 1) * (256 - fx) + p(ix + 1, iy + 1) * fx
    return (top * (256 - fy) + bot * fy + 32768) // 65536


# ---- 8.2 coverage of stamps and affine strokes ----

def stamp_coverage(header, templates, s):
    """Yields (x, y, coverage) over the stamp's evaluation box clipped to the canvas."""
    sw, sh = header.sets[s.set]
    C, S = header.orientations[s.orient]
    t = templates[s.template]
    grid = t.grid if t.kind != BITMAP else 0
    offsets = sample_offsets(grid)
    cx, cy = s.x >> 4, s.y >> 4
    RX = (sw * abs(C) + sh * abs(S)) // 32768 + 1
    RY = (sw * abs(S) + sh * abs(C)) // 32768 + 1
    for y in range(max(cy - RY, 0), min(cy + RY, header.height - 1) + 1):
        for x in range(max(cx - RX, 0), min(cx + RX, header.width - 1) + 1):
            i, j = x - cx, y - cy
            if grid < 2:
                cov = template_coverage(t, 8 * (i * C + j * S) // sw, 8 * (j * C - i * S) // sh)
            else:
                inside = 0
                for oq in offsets:
                    for op in offsets:
                        i2, j2 = 256 * i + op - 128, 256 * j + oq - 128
                        U = 8 * (i2 * C + j2 * S) // (256 * sw)
                        V = 8 * (j2 * C - i2 * S) // (256 * sh)
                        inside += template_coverage(t, U, V) == 255
                cov = share(inside, grid * grid)
            yield x, y, cov


def affine_coverage(header, templates, s):
    det = s.a * s.d - s.b * s.c
    if det == 0:
        return
    t = templates[s.template]
    grid = t.grid if t.kind != BITMAP else 0
    offsets = sample_offsets(grid)
    grow = 8 if grid >= 2 else 0
    rx, ry = abs(s.a) + abs(s.b) + grow, abs(s.c) + abs(s.d) + grow
    # pixels whose centre X = 16x + 8 satisfies |X - tx| <= rx (and likewise y)
    x0, x1 = max(-((8 - s.tx + rx) // 16), 0), min((s.tx + rx - 8) // 16, header.width - 1)
    y0, y1 = max(-((8 - s.ty + ry) // 16), 0), min((s.ty + ry - 8) // 16, header.height - 1)
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            dx, dy = 16 * x + 8 - s.tx, 16 * y + 8 - s.ty
            if grid < 2:
                cov = template_coverage(t, 65536 * (s.d * dx - s.b * dy) // det,
                                        65536 * (s.a * dy - s.c * dx) // det)
            else:
                inside = 0
                for oq in offsets:
                    for op in offsets:
                        dx2, dy2 = 256 * x + op - 16 * s.tx, 256 * y + oq - 16 * s.ty
                        U = 4096 * (s.d * dx2 - s.b * dy2) // det
                        V = 4096 * (s.a * dy2 - s.c * dx2) // det
                        inside += template_coverage(t, U, V) == 255
                cov = share(inside, grid * grid)
            yield x, y, cov


# ---- 8.5 curves ----

def segment_covers(Xs, Ys, p0, p1):
    """Whether segment (p0, p1) covers the sample (Xs, Ys), in 1/256 pixel (1/16 of a Q4 unit)."""
    (x0, y0, w0), (x1, y1, w1) = p0, p1
    ex, ey = x1 - x0, y1 - y0
    L = ex * ex + ey * ey
    qx, qy = Xs - 16 * x0, Ys - 16 * y0
    t = qx * ex + qy * ey
    if L == 0 or t <= 0:
        T = 0
    elif t >= 16 * L:
        T = 1 << 24
    else:
        T = (t << 20) // L  # Python's integers are exact: t * 2^20 needs no long division
    Ex = 16 * qx - (T * ex) // 65536
    Ey = 16 * qy - (T * ey) // 65536
    hw = (w0 * (1 << 24) + T * (w1 - w0)) // (1 << 17)
    return Ex * Ex + Ey * Ey <= hw * hw


def curve_coverage(header, s):
    """The samples of 8.8 (the pixel centre alone for grid 0), each inside when a segment covers
    it; a pixel's coverage counts its samples inside the union of the segments."""
    pts = s.points
    segments = [(pts[0], pts[0])] if len(pts) == 1 else list(zip(pts, pts[1:]))
    offsets = sample_offsets(s.grid)  # side = len(offsets)
    grow = 8 if s.grid >= 2 else 0    # a pixel's samples lie within 8 Q4 units of its centre
    inside = {}  # (x, y) -> the samples (p, q) some segment covers
    for p0, p1 in segments:
        m = -(-max(p0[2], p1[2]) // 2) + 1 + grow
        lo_x, hi_x = min(p0[0], p1[0]) - m, max(p0[0], p1[0]) + m
        lo_y, hi_y = min(p0[1], p1[1]) - m, max(p0[1], p1[1]) + m
        for y in range(max(-((8 - lo_y) // 16), 0), min((hi_y - 8) // 16, header.height - 1) + 1):
            for x in range(max(-((8 - lo_x) // 16), 0), min((hi_x - 8) // 16, header.width - 1) + 1):
                covered = inside.setdefault((x, y), set())
                for q, oq in enumerate(offsets):
                    for p, op in enumerate(offsets):
                        if (p, q) not in covered and segment_covers(256 * x + op, 256 * y + oq, p0, p1):
                            covered.add((p, q))
    for (x, y), covered in sorted(inside.items()):
        if covered:
            yield x, y, share(len(covered), len(offsets) ** 2)


# ---- 8.8 polygons ----

def polygon_coverage(header, s):
    V = [(16 * x, 16 * y) for x, y in s.vertices]
    edges = []
    for k in range(len(V)):
        (Xk, Yk), (Xn, Yn) = V[k], V[(k + 1) % len(V)]
        if Yk == Yn:
            continue
        if Yk < Yn:
            edges.append((Xk, Yk, Xn, Yn, 1))
        else:
            edges.append((Xn, Yn, Xk, Yk, -1))
    offsets = sample_offsets(s.grid)  # side = len(offsets)
    xs = [v[0] for v in s.vertices]
    ys = [v[1] for v in s.vertices]
    for y in range(max(min(ys) // 16, 0), min(max(ys) // 16, header.height - 1) + 1):
        for x in range(max(min(xs) // 16, 0), min(max(xs) // 16, header.width - 1) + 1):
            inside = 0
            for oq in offsets:
                Y = 256 * y + oq
                for op in offsets:
                    X = 256 * x + op
                    w = 0
                    for xa, ya, xb, yb, d in edges:
                        if ya <= Y < yb and (X - xa) * (yb - ya) >= (xb - xa) * (Y - ya):
                            w += d
                    inside += w != 0
            yield x, y, share(inside, len(offsets) ** 2)


def coverage(header, templates, s):
    if s.kind == STAMP:
        return stamp_coverage(header, templates, s)
    if s.kind == AFFINE:
        return affine_coverage(header, templates, s)
    if s.kind == CURVE:
        return curve_coverage(header, s)
    return polygon_coverage(header, s)


def draw(canvas, header, templates, s):
    src = codes(s) if canvas.linear else s.rgba[:3]
    for x, y, cov in coverage(header, templates, s):
        canvas.blend(x, y, cov, s.rgba, src)


def render(header, templates, live):
    canvas = Canvas(header)
    for s in live:
        draw(canvas, header, templates, s)
    return canvas
