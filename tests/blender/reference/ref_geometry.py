"""The reference (oracle) of the add-on's io/geometry.py: strokes <-> Grease Pencil shapes, one
Python tuple at a time, in pixel units. Kept with the tests; the add-on ships only the vectorised
version, and tests/blender/test_io.py checks that both give identical results.

The conventions (corners, Q4 centres, stamp axes) are those io/geometry.py states.
"""

import math
from typing import List, Optional, Sequence, Tuple

from spt_grease_pencil.io.geometry import CORNERS_UV, STAMP_TOLERANCE_PX  # noqa: F401
from spt_grease_pencil.io.model import AFFINE, CURVE, MAX_CURVE_WIDTH, MAX_MATRIX, MAX_POS, STAMP

# uv_fill of the corners: template row 0 (v = -1) is the image's top row (Blender v = 1).
UV_FILL = (0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0)



def stamp_axes(w: int, h: int, cos_q14: int, sin_q14: int):
    c, s = cos_q14 / 16384.0, sin_q14 / 16384.0
    return (0.5 * w * c, 0.5 * w * s), (-0.5 * h * s, 0.5 * h * c)


def stroke_frame(stroke, sets, orients):
    """(centre, u axis, v axis) of a stamp or affine stroke in pixels."""
    if stroke[0] == STAMP:
        w, h = sets[stroke[1]]
        c, s = orients[stroke[3]]
        ua, va = stamp_axes(w, h, c, s)
        return (stroke[4] / 16.0, stroke[5] / 16.0), ua, va
    _, _t, tx, ty, a, b, c, d = stroke[:8]
    return (tx / 16.0, ty / 16.0), (a / 16.0, c / 16.0), (b / 16.0, d / 16.0)


def quad_corners(stroke, sets, orients) -> List[Tuple[float, float]]:
    (cx, cy), (ux, uy), (vx, vy) = stroke_frame(stroke, sets, orients)
    return [(cx + u * ux + v * vx, cy + u * uy + v * vy) for (u, v) in CORNERS_UV]


def quad_frame(corners: Sequence[Tuple[float, float]]):
    """Centre and axes of a quad; averages opposite edges so a slightly skewed quad still works."""
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = corners
    cx, cy = (x0 + x1 + x2 + x3) / 4.0, (y0 + y1 + y2 + y3) / 4.0
    ux, uy = ((x1 - x0) + (x2 - x3)) / 4.0, ((y1 - y0) + (y2 - y3)) / 4.0
    vx, vy = ((x3 - x0) + (x2 - x1)) / 4.0, ((y3 - y0) + (y2 - y1)) / 4.0
    return (cx, cy), (ux, uy), (vx, vy)


def match_stamp(ua, va, sets, orients, set_hint: Optional[int] = None):
    """(set, orient) of the stamp whose axes are `ua`, `va`, or None."""
    tol = STAMP_TOLERANCE_PX
    order = list(range(len(sets)))
    if set_hint is not None and 0 <= set_hint < len(sets):
        order.remove(set_hint)
        order.insert(0, set_hint)
    for si in order:
        w, h = sets[si]
        for oi, (c, s) in enumerate(orients):
            (eux, euy), (evx, evy) = stamp_axes(w, h, c, s)
            if abs(ua[0] - eux) <= tol and abs(ua[1] - euy) <= tol and \
                    abs(va[0] - evx) <= tol and abs(va[1] - evy) <= tol:
                return si, oi
    return None


def _q4(v: float) -> int:
    return int(math.floor(v * 16.0 + 0.5))


def quad_to_stroke(corners, template: int, rgba, sets, orients, set_hint=None):
    """The stroke a quad stands for: a stamp when it matches one of its set size and a table
    orientation, otherwise an affine stroke. None when it cannot be one (degenerate or out of
    the format's ranges)."""
    (cx, cy), ua, va = quad_frame(corners)
    x, y = _q4(cx), _q4(cy)
    if abs(x) > MAX_POS or abs(y) > MAX_POS:
        return None
    m = match_stamp(ua, va, sets, orients, set_hint)
    if m is not None:
        return (STAMP, m[0], template, m[1], x, y) + tuple(rgba)
    a, c, b, d = _q4(ua[0]), _q4(ua[1]), _q4(va[0]), _q4(va[1])
    if max(abs(a), abs(b), abs(c), abs(d)) > MAX_MATRIX or a * d - b * c == 0:
        return None
    return (AFFINE, template, x, y, a, b, c, d) + tuple(rgba)


def curve_points(stroke) -> List[Tuple[float, float, float]]:
    """(x px, y px, width px) per point of a curve stroke."""
    return [(x / 16.0, y / 16.0, w / 16.0) for (x, y, w) in stroke[5]]


def points_to_curve(points, rgba, grid: int = 0):
    """A curve stroke from (x px, y px, width px) points rounded to Q4 (a negative width to 0)
    and its grid N (format 1.4), which model.py appends only when it is not 0; None when it has
    no point, one out of range, or a reserved grid N."""
    pts = []
    for (x, y, w) in points:
        qx, qy, qw = _q4(x), _q4(y), max(0, _q4(w))
        if abs(qx) > MAX_POS or abs(qy) > MAX_POS or qw > MAX_CURVE_WIDTH:
            return None
        pts.append((qx, qy, qw))
    if not pts or grid == 1 or not 0 <= grid <= 16:
        return None
    return (CURVE,) + tuple(rgba) + (tuple(pts),) + ((grid,) if grid else ())


def polygon_points(stroke) -> List[Tuple[float, float]]:
    """(x px, y px) per vertex of a polygon stroke."""
    return [(x / 16.0, y / 16.0) for (x, y) in stroke[6]]


def points_to_polygon(points, rgba, grid: int):
    """A polygon stroke (format 1.2) from (x px, y px) vertices rounded to Q4; None when it has
    fewer than 3 vertices, one out of range, or a reserved grid N."""
    pts = []
    for (x, y) in points:
        qx, qy = _q4(x), _q4(y)
        if abs(qx) > MAX_POS or abs(qy) > MAX_POS:
            return None
        pts.append((qx, qy))
    if len(pts) < 3 or grid == 1 or not 0 <= grid <= 16:
        return None
    return (3,) + tuple(rgba) + (grid, tuple(pts))
