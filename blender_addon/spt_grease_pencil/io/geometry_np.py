"""geometry.py vectorised with numpy, for millions of strokes in the Blender layer.

Same maps and tolerances as geometry.py (the reference); tests/blender/test_io.py checks that
both give identical results. Only imported when numpy exists (it does inside Blender)."""

import numpy as np

from .geometry import CORNERS_UV, STAMP_TOLERANCE_PX
from .model import AFFINE, MAX_MATRIX, MAX_POS, STAMP

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


def quads_to_strokes(corners, templates, rgba, sets, orients, set_hint=None):
    """Vectorised geometry.quad_to_stroke. corners (N, 4, 2) pixels, templates (N,), rgba (N, 4)
    ints, set_hint (N,) or None. Returns a list of N stroke tuples (None where invalid)."""
    q = np.asarray(corners, dtype=np.float64).reshape(-1, 4, 2)
    n = q.shape[0]
    if n == 0:
        return []
    centre = q.mean(axis=1)
    ua = ((q[:, 1] - q[:, 0]) + (q[:, 2] - q[:, 3])) / 4.0
    va = ((q[:, 3] - q[:, 0]) + (q[:, 2] - q[:, 1])) / 4.0
    table = stamp_axes_table(sets, orients)  # (S, O, 2, 2)
    S, O = table.shape[0], table.shape[1]
    flat = table.reshape(S * O, 4)
    mine = np.concatenate([ua, va], axis=1)  # (N, 4)
    ok = np.empty((n, S * O), dtype=bool)
    step = 4096  # bounds the temporary (step x S*O x 4) array
    for i in range(0, n, step):
        diff = np.abs(mine[i:i + step, None, :] - flat[None, :, :])
        ok[i:i + step] = (diff <= STAMP_TOLERANCE_PX).all(axis=2)
    # First match in (set, orient) order, but the hinted set first when it matches.
    first = np.where(ok.any(axis=1), ok.argmax(axis=1), -1)
    if set_hint is not None:
        hint = np.asarray(set_hint, dtype=np.int64)
        okr = ok.reshape(n, S, O)
        valid = (hint >= 0) & (hint < S)
        hint_c = np.clip(hint, 0, S - 1)
        hrow = okr[np.arange(n), hint_c]  # (n, O)
        use = valid & hrow.any(axis=1)
        first = np.where(use, hint_c * O + hrow.argmax(axis=1), first)
    x, y = _q4(centre[:, 0]), _q4(centre[:, 1])
    a, c, b, d = _q4(ua[:, 0]), _q4(ua[:, 1]), _q4(va[:, 0]), _q4(va[:, 1])
    pos_ok = (np.abs(x) <= MAX_POS) & (np.abs(y) <= MAX_POS)
    aff_ok = (np.maximum.reduce([np.abs(a), np.abs(b), np.abs(c), np.abs(d)]) <= MAX_MATRIX) & (a * d - b * c != 0)
    tmpl = np.asarray(templates, dtype=np.int64).tolist()
    col = [tuple(r) for r in np.asarray(rgba, dtype=np.int64).tolist()]
    out = []
    for i, (fi, xi, yi, ai, bi, ci, di, pk, ak) in enumerate(zip(
            first.tolist(), x.tolist(), y.tolist(), a.tolist(), b.tolist(), c.tolist(), d.tolist(),
            pos_ok.tolist(), aff_ok.tolist())):
        if not pk:
            out.append(None)
        elif fi >= 0:
            out.append((STAMP, fi // O, tmpl[i], fi % O, xi, yi) + col[i])
        elif ak:
            out.append((AFFINE, tmpl[i], xi, yi, ai, bi, ci, di) + col[i])
        else:
            out.append(None)
    return out
