"""Strokes <-> Grease Pencil shapes, in pixel units, vectorised with numpy (millions of strokes).

A stamp or affine stroke becomes a quad: the images of the template corners
(u, v) = (-1,-1), (1,-1), (1,1), (-1,1) in pixel coordinates (x right, y down). Stamps are
centred on their exact Q4 position x/16, y/16 (the renderer snaps to the pixel centre; the quad
keeps the sub-pixel position so it survives a round trip). Float32 holds every Q4/16 value with
|v| < 2^20 px exactly, and the centre is recovered by rounding, so unedited strokes come back
bit-exact.

Stamp geometry (same convention as libspt): the template is scaled to the set's w x h and rotated
by the table entry (cos, sin): u axis = (w/2)(cos, sin), v axis = (h/2)(-sin, cos).

tests/blender/reference/ref_geometry.py is the one-stroke-at-a-time oracle these maps are tested
against."""

import numpy as np

from .model import AFFINE, MAX_MATRIX, MAX_POS, STAMP, curve_tuple
from .strokes_np import A, KIND, MA, MB, MC, MD, NCOL, ORIENT, R, SET, TMPL, X, Y, StrokeTable

CORNERS_UV = ((-1, -1), (1, -1), (1, 1), (-1, 1))
# How far (in pixels) a quad's axes may be from a stamp's to still count as that stamp.
STAMP_TOLERANCE_PX = 0.02
_CUV = np.array(CORNERS_UV, dtype=np.float64)  # (4, 2)


def stamp_axes_table(sets, orients):
    """(S, O, 2, 2) array: [set, orient] -> (u axis, v axis) in pixels."""
    wh = np.asarray(sets, dtype=np.float64).reshape(-1, 2)
    cs = np.asarray(orients, dtype=np.float64).reshape(-1, 2) / 16384.0
    c, s = cs[:, 0][None, :], cs[:, 1][None, :]
    w, h = wh[:, 0][:, None], wh[:, 1][:, None]
    ua = np.stack([0.5 * w * c, 0.5 * w * s], axis=-1)
    va = np.stack([-0.5 * h * s, 0.5 * h * c], axis=-1)
    return np.stack([ua, va], axis=-2)


def corners_from_frames(centre, ua, va):
    """(N, 4, 2) corners from (N, 2) centres and axes."""
    return centre[:, None, :] + _CUV[None, :, 0:1] * ua[:, None, :] + _CUV[None, :, 1:2] * va[:, None, :]


def stamps_to_corners(stamps, sets, orients):
    """stamps: (N, 10) int array of stamp tuples. Returns (N, 4, 2) pixel corners."""
    st = np.asarray(stamps, dtype=np.int64).reshape(-1, 10)
    table = stamp_axes_table(sets, orients)
    axes = table[st[:, 1], st[:, 3]]  # (N, 2, 2)
    centre = st[:, 4:6].astype(np.float64) / 16.0
    return corners_from_frames(centre, axes[:, 0], axes[:, 1])


def affines_to_corners(affines):
    """affines: (N, 12) int array of affine tuples. Returns (N, 4, 2) pixel corners."""
    af = np.asarray(affines, dtype=np.int64).reshape(-1, 12).astype(np.float64) / 16.0
    centre = af[:, 2:4]
    ua = np.stack([af[:, 4], af[:, 6]], axis=-1)
    va = np.stack([af[:, 5], af[:, 7]], axis=-1)
    return corners_from_frames(centre, ua, va)


def _q4(v):
    return np.floor(v * 16.0 + 0.5).astype(np.int64)


def table_corners(rows, sets, orients):
    """(N, 4, 2) pixel corners of the stamp and affine rows of a StrokeTable (curve rows: 0)."""
    r = np.asarray(rows)
    table = stamp_axes_table(sets, orients)
    is_stamp = r[:, KIND] == STAMP
    si = np.where(is_stamp, r[:, SET], 0)
    oi = np.where(is_stamp, r[:, ORIENT], 0)
    axes = table[si, oi]  # (N, 2, 2)
    m = r[:, MA:MD + 1].astype(np.float64) / 16.0  # a b c d
    ua = np.where(is_stamp[:, None], axes[:, 0], np.stack([m[:, 0], m[:, 2]], axis=-1))
    va = np.where(is_stamp[:, None], axes[:, 1], np.stack([m[:, 1], m[:, 3]], axis=-1))
    centre = r[:, X:Y + 1].astype(np.float64) / 16.0
    return corners_from_frames(centre, ua, va)


def match_stamps(ua, va, sets, orients, set_hint=None):
    """Per quad, set * O + orient of the stamp whose axes are ua, va (N, 2) within the tolerance,
    or -1: the hinted set first when it matches, else the first match in (set, orient) order
    (geometry.match_stamp). The hinted set is tried alone first (N x O work); only the quads it
    does not explain (edited or affine strokes: few) are compared with every (set, orient)."""
    table = stamp_axes_table(sets, orients)  # (S, O, 2, 2)
    S, O = table.shape[0], table.shape[1]
    flat = table.reshape(S, O, 4)
    mine = np.concatenate([ua, va], axis=1)  # (N, 4)
    n = mine.shape[0]
    first = np.full(n, -1, dtype=np.int64)
    todo = np.arange(n)
    if set_hint is not None:
        hint = np.asarray(set_hint, dtype=np.int64).reshape(-1)
        valid = (hint >= 0) & (hint < S)
        hint_c = np.clip(hint, 0, S - 1)
        ok = (np.abs(mine[:, None, :] - flat[hint_c]) <= STAMP_TOLERANCE_PX).all(axis=2)  # (N, O)
        hit = valid & ok.any(axis=1)
        first[hit] = hint_c[hit] * O + ok[hit].argmax(axis=1)
        todo = np.flatnonzero(~hit)
    step = 4096  # bounds the temporary (step x S*O x 4) array
    flat2 = flat.reshape(S * O, 4)
    for i in range(0, todo.shape[0], step):
        sel = todo[i:i + step]
        ok = (np.abs(mine[sel, None, :] - flat2[None, :, :]) <= STAMP_TOLERANCE_PX).all(axis=2)
        first[sel] = np.where(ok.any(axis=1), ok.argmax(axis=1), -1)
    return first


def quads_to_rows(corners, templates, rgba, sets, orients, set_hint=None):
    """Vectorised geometry.quad_to_stroke into StrokeTable rows. corners (N, 4, 2) pixels,
    templates (N,), rgba (N, 4) ints, set_hint (N,) or None. Returns (rows (N, NCOL) int32,
    valid (N,) bool); invalid rows (degenerate or out of range) are to be left out."""
    q = np.asarray(corners, dtype=np.float64).reshape(-1, 4, 2)
    n = q.shape[0]
    rows = np.zeros((n, NCOL), dtype=np.int32)
    if n == 0:
        return rows, np.zeros(0, dtype=bool)
    centre = q.mean(axis=1)
    ua = ((q[:, 1] - q[:, 0]) + (q[:, 2] - q[:, 3])) / 4.0
    va = ((q[:, 3] - q[:, 0]) + (q[:, 2] - q[:, 1])) / 4.0
    first = match_stamps(ua, va, sets, orients, set_hint)
    O = len(orients)
    x, y = _q4(centre[:, 0]), _q4(centre[:, 1])
    a, c, b, d = _q4(ua[:, 0]), _q4(ua[:, 1]), _q4(va[:, 0]), _q4(va[:, 1])
    pos_ok = (np.abs(x) <= MAX_POS) & (np.abs(y) <= MAX_POS)
    aff_ok = (np.maximum.reduce([np.abs(a), np.abs(b), np.abs(c), np.abs(d)]) <= MAX_MATRIX) & (a * d - b * c != 0)
    is_stamp = first >= 0
    valid = pos_ok & (is_stamp | aff_ok)
    x, y = np.where(valid, x, 0), np.where(valid, y, 0)
    rows[:, KIND] = np.where(is_stamp, STAMP, AFFINE)
    rows[:, SET] = np.where(is_stamp, first // O, 0)
    rows[:, ORIENT] = np.where(is_stamp, first % O, 0)
    rows[:, TMPL] = np.asarray(templates, dtype=np.int64)
    rows[:, X] = x
    rows[:, Y] = y
    aff = (~is_stamp) & valid
    for col, v in ((MA, a), (MB, b), (MC, c), (MD, d)):
        rows[:, col] = np.where(aff, v, 0)
    rows[:, R:A + 1] = np.asarray(rgba, dtype=np.int64).reshape(n, 4)
    return rows, valid


def quads_to_strokes(corners, templates, rgba, sets, orients, set_hint=None):
    """quads_to_rows as model tuples (None where invalid), for tests against the oracle."""
    rows, valid = quads_to_rows(corners, templates, rgba, sets, orients, set_hint)
    tup = StrokeTable(rows).to_tuples()
    return [t if v else None for t, v in zip(tup, valid.tolist())]


def points_to_curve(points, rgba, grid: int = 0):
    """A curve stroke (tuple) from (x px, y px, width px) points and its supersampling grid N
    (format 1.4; 0: pixel centres); None when empty, out of range or of a reserved grid (1,
    17..). One curve at a time: curves drawn by hand are few."""
    if grid == 1 or not 0 <= grid <= 16:
        return None
    pts = []
    for (x, y, w) in points:
        qx, qy, qw = (int(np.floor(v * 16.0 + 0.5)) for v in (x, y, w))
        qw = max(0, qw)
        if abs(qx) > MAX_POS or abs(qy) > MAX_POS or qw > (1 << 16):
            return None
        pts.append((qx, qy, qw))
    if not pts:
        return None
    return curve_tuple(*rgba, tuple(pts), grid)
