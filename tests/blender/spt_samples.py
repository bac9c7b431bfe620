"""Synthetic stored .spt files for the add-on tests and bench (written with the add-on's own
Python writer). Deterministic: a seed gives the same file."""

import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ADDON = os.path.join(HERE, "..", "..", "blender_addon")
try:  # inside Blender the installed add-on is used; elsewhere the source tree
    import spt_grease_pencil  # noqa: F401
except ImportError:
    sys.path.insert(0, ADDON)

from spt_grease_pencil.io import model, writer  # noqa: E402
from spt_grease_pencil.io.model import (AFFINE, INTER, KEY, POLYGON, STAMP, Frame, Header,  # noqa: E402
                                        Motion, StreamInfo, Template)


def templates():
    # A soft round bitmap (24x16, not square: catches row/column swaps) and two analytic kinds.
    w, h = 24, 16
    px = bytearray()
    for j in range(h):
        for i in range(w):
            u, v = (i + 0.5) / w * 2 - 1, (j + 0.5) / h * 2 - 1
            r = math.sqrt(u * u + v * v)
            px.append(max(0, min(255, int(255 * (1.2 - r) / 0.4))) if r < 1.2 else 0)
    return [Template(model.TEMPLATE_BITMAP, w, h, bytes(px), "soft"),
            Template(model.TEMPLATE_ELLIPSE, 0, 0, b"", "ellipse", 4),  # 4x4 supersampled
            Template(model.TEMPLATE_TRIANGLE, 0, 0, b"", "triangle")]


def info(width=160, height=120, sets=((40, 20), (20, 10), (8, 4)), fps=(24, 1)):
    h = Header(width=width, height=height, fps_num=fps[0], fps_den=fps[1], background=(250, 245, 230),
               sets=list(sets), orientations=model.default_orientations(8))
    return StreamInfo(header=h, templates=templates(), metadata=[("software", "spt tests")])


def random_stamp(rng, inf, set_index=None):
    h = inf.header
    s = rng.randrange(len(h.sets)) if set_index is None else set_index
    return (STAMP, s, rng.randrange(len(inf.templates)), rng.randrange(len(h.orientations)),
            rng.randrange(0, 16 * h.width), rng.randrange(0, 16 * h.height),
            rng.randrange(256), rng.randrange(256), rng.randrange(256), 255)


def random_affine(rng, inf):
    h = inf.header
    while True:
        a, b, c, d = (rng.randrange(-300, 300) for _ in range(4))
        if a * d - b * c != 0:
            break
    return (AFFINE, rng.randrange(len(inf.templates)), rng.randrange(16 * h.width), rng.randrange(16 * h.height),
            a, b, c, d, rng.randrange(256), rng.randrange(256), rng.randrange(256), rng.choice((255, 128)))


def random_curve(rng, inf):
    """A curve of 1..5 points; in a file with the curve_grid flag (format 1.4) with a grid N of
    0, 2, 4 or 16 (model.py: the tuple holds N only when it is not 0)."""
    h = inf.header
    n = rng.randrange(1, 6)
    pts = tuple((rng.randrange(16 * h.width), rng.randrange(16 * h.height), rng.randrange(8, 80)) for _ in range(n))
    rgb = (rng.randrange(256), rng.randrange(256), rng.randrange(256))
    grid = rng.choice((0, 2, 4, 16)) if h.curve_grid else 0
    return model.curve_tuple(*rgb, 255, pts, grid)


def random_polygon(rng, inf):
    """A polygon (format 1.2): a jittered 3..12-gon (integer-pixel vertices like geometrize's,
    sometimes sub-pixel), or now and then a self-intersecting star; grid N 0 or 2..16."""
    h = inf.header
    n = rng.randrange(3, 13)
    cx, cy = rng.randrange(16 * h.width), rng.randrange(16 * h.height)
    rad = rng.randrange(40, 400)
    step = 2 if (n % 2 and n >= 5 and rng.random() < 0.2) else 1  # {n/2} star
    pts = []
    for k in range(n):
        t = 2 * math.pi * ((k * step) % n) / n
        x = cx + int(rad * math.cos(t)) + rng.randrange(-8, 9)
        y = cy + int(rad * math.sin(t)) + rng.randrange(-8, 9)
        if rng.random() < 0.7:
            x, y = x & ~15, y & ~15
        pts.append((x, y))
    return (POLYGON, rng.randrange(256), rng.randrange(256), rng.randrange(256), rng.choice((255, 128)),
            rng.choice((0, 2, 4, 16)), tuple(pts))


def animation(frames=4, per_set=(6, 10, 14), seed=7, affines=3, curves=2, motion=True, inf=None, polygons=0,
              curve_grids=False):
    """A key frame (stamps coarse to fine, affine strokes, polygons, curves), then inter frames
    that remove some strokes, move the rest (motion field) and add strokes of every kind,
    interleaved. polygons > 0 makes a format 1.2 file (one more polygon added per inter frame);
    curve_grids a format 1.4 file whose curves carry grids (HEAD flag curve_grid)."""
    rng = random.Random(seed)
    inf = inf or info()
    h = inf.header
    h.curve_grid = h.curve_grid or curve_grids
    out = []
    key = []
    for si, n in enumerate(per_set):
        key += [random_stamp(rng, inf, si) for _ in range(n)]
    key += [random_affine(rng, inf) for _ in range(affines)]
    if polygons:  # interleaved with affine strokes: they share the "shapes" layer
        key[-1:-1] = [random_polygon(rng, inf) for _ in range(polygons)]
    key += [random_curve(rng, inf) for _ in range(curves)]
    out.append(Frame(0, KEY, added=key))
    live = len(key)
    for fi in range(1, frames):
        removed = sorted(rng.sample(range(live), min(live, 3)))
        mv = None
        if motion:
            bs = 32
            cols, rows = -(-h.width // bs), -(-h.height // bs)
            mv = Motion(bs, cols, rows, [(rng.randrange(-20, 21), rng.randrange(-20, 21)) for _ in range(cols * rows)])
        added = [random_stamp(rng, inf), random_stamp(rng, inf, 0), random_affine(rng, inf),
                 random_stamp(rng, inf, 2), random_curve(rng, inf)]
        if polygons:
            added.insert(2, random_polygon(rng, inf))
        out.append(Frame(fi, INTER, removed=removed, motion=mv, added=added))
        live += len(added) - len(removed)
    return inf, out


def linear_animation(alpha=True, **kw):
    """animation() as a format 1.3 file of colour encoding 1 (and an alpha canvas): every colour
    value becomes a 16-bit half code spread over the whole range, about half of them above 1.0
    (HDR), some subnormal, low bytes set. Deterministic like animation()."""
    inf, frames = animation(**kw)
    h = inf.header
    h.alpha, h.color_encoding = alpha, model.LINEAR_HALF
    h.set_background_values((0x3C00, 0x2E66, 0x0001))  # 1.0, about 0.1, the smallest subnormal

    def code(v, k):
        return ((v << 7) ^ (k * 0x1D3B)) % 0x7C00

    for fr in frames:
        fr.added = [model.with_color(s, tuple(code(c, k) for k, c in enumerate(model.stroke_color(s)[:3]))
                                     + (model.stroke_color(s)[3],)) for s in fr.added]
    return inf, frames


def write_animation(path, **kw):
    inf, frames = animation(**kw)
    writer.write_stored(path, inf, frames)
    return path


if __name__ == "__main__":
    write_animation(sys.argv[1])
