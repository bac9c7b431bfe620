"""The live stroke list over frames (format/SPEC.md section 5) on StrokeTables, vectorised.

apply_frames: remove, move (motion field), add. frames_from_tables: the inverse, coding a sequence
of live lists as key and inter frames with the same rule as writer.frames_from_lists (the
reference), matching strokes by a 64-bit row hash that is then verified exactly."""

import numpy as np

from .model import CURVE, INTER, KEY, MAX_POS, POLYGON, Frame, Motion, SptError
from .strokes_np import KIND, NCOL, X, Y, CURVE_ID, StrokeTable


def apply_frames(header, frames, limits, path="<memory>", curves=None):
    """Yields the live StrokeTable after each frame. Frames hold StrokeTables in `added`, numpy
    arrays in `removed` and Motion with an (n, 2) vector array (reader columnar mode)."""
    curves = [] if curves is None else curves
    rows = np.zeros((0, NCOL), dtype=np.int32)
    for fr in frames:
        if fr.type == KEY:
            rows = fr.added.rows
        else:
            rem = np.asarray(fr.removed, dtype=np.int64)
            if rem.size:
                if (rem[1:] <= rem[:-1]).any() or rem[-1] >= rows.shape[0]:
                    raise SptError(f"{path}: frame {fr.index}: removed indices are not increasing or reach past "
                                   f"the live list length {rows.shape[0]}")
                keep = np.ones(rows.shape[0], dtype=bool)
                keep[rem] = False
                rows = rows[keep]
            if fr.motion is not None:
                rows = move_rows(rows, fr.motion, curves, path, fr.index)
            if len(fr.added):
                rows = np.concatenate([rows, fr.added.rows])
        if rows.shape[0] > limits.max_live_strokes:
            raise SptError(f"{path}: frame {fr.index}: {rows.shape[0]} live strokes exceed the limit")
        yield StrokeTable(rows, curves)


def _block_vectors(m, x, y):
    bs16 = 16 * m.block_size
    vec = np.asarray(m.vectors, dtype=np.int32).reshape(-1, 2)
    bx = np.clip(np.floor_divide(x, bs16), 0, m.cols - 1)
    by = np.clip(np.floor_divide(y, bs16), 0, m.rows - 1)
    return vec[by * m.cols + bx]


def polygons_fit(rows, d, curves) -> bool:
    """True when every polygon row moved by d (n, 2) keeps all its vertices in range (SPEC.md 4).
    Its position X Y (= P0) is checked with the other strokes; here the rest of the outline."""
    moved = np.flatnonzero((rows[:, KIND] == POLYGON) & d.any(axis=1))
    for i in moved.tolist():
        v = curves[rows[i, CURVE_ID]]
        x0, y0 = int(rows[i, X]) + int(d[i, 0]), int(rows[i, Y]) + int(d[i, 1])
        if (max(abs(x0 + int(v[:, 0].min())), abs(x0 + int(v[:, 0].max()))) > MAX_POS
                or max(abs(y0 + int(v[:, 1].min())), abs(y0 + int(v[:, 1].max()))) > MAX_POS):
            return False
    return True


def move_rows(rows, m, curves, path="<memory>", index=0):
    """Every stroke moved by the vector of the block holding its position (curves: per point;
    polygons: rigidly by P0's block, i.e. like a stamp, their outline being relative to P0).
    Moved curves get new pool entries; the input rows are not modified."""
    out = rows.copy()
    d = _block_vectors(m, rows[:, X].astype(np.int64), rows[:, Y].astype(np.int64))
    is_curve = rows[:, KIND] == CURVE
    d[is_curve] = 0
    nx = rows[:, X].astype(np.int64) + d[:, 0]
    ny = rows[:, Y].astype(np.int64) + d[:, 1]
    if (np.abs(nx) > MAX_POS).any() or (np.abs(ny) > MAX_POS).any() or not polygons_fit(rows, d, curves):
        raise SptError(f"{path}: frame {index}: motion moves a stroke out of range")
    out[:, X] = nx
    out[:, Y] = ny
    for i in np.flatnonzero(is_curve).tolist():
        pts = curves[rows[i, CURVE_ID]]
        dv = _block_vectors(m, pts[:, 0].astype(np.int64), pts[:, 1].astype(np.int64))
        moved = pts.copy()
        px = pts[:, 0].astype(np.int64) + dv[:, 0]
        py = pts[:, 1].astype(np.int64) + dv[:, 1]
        if (np.abs(px) > MAX_POS).any() or (np.abs(py) > MAX_POS).any():
            raise SptError(f"{path}: frame {index}: motion moves a stroke out of range")
        moved[:, 0] = px
        moved[:, 1] = py
        out[i, CURVE_ID] = len(curves)
        curves.append(moved)
    return out


# ---------------------------------------------------------------- live lists -> frames

_MULT = np.random.default_rng(0x5B7).integers(1, 2 ** 63, size=NCOL, dtype=np.uint64) | np.uint64(1)
_RANK_MULT = np.uint64(0x9E3779B97F4A7C15)


def row_hashes(rows):
    """(h, order): one uint64 per row (wrapping arithmetic) and the order that sorts h. Equal
    rows are told apart by their rank (the k-th copy of a stroke hashes differently from the
    first), so copies match copies in order."""
    h = (rows.astype(np.int64).view(np.uint64) * _MULT[None, :]).sum(axis=1, dtype=np.uint64)
    order = np.argsort(h)
    sh = h[order]
    if sh.shape[0] < 2 or (sh[1:] != sh[:-1]).all():
        return h, order
    order = np.argsort(h, kind="stable")  # copies are ranked in list order
    sh = h[order]
    new_group = np.empty(sh.shape[0], dtype=bool)
    new_group[0] = True
    new_group[1:] = sh[1:] != sh[:-1]
    starts = np.flatnonzero(new_group)
    rank = np.arange(sh.shape[0]) - starts[np.cumsum(new_group) - 1]
    out = h.copy()
    out[order] = sh + rank.astype(np.uint64) * _RANK_MULT
    return out, np.argsort(out)


def kept_prefix(prev_rows, cur_rows, prev_hashes=None, cur_hashes=None):
    """(L, positions): the longest prefix of cur that appears in prev in the same order, and the
    prev index of each of its strokes. Equal to the reference's greedy matching when prev has no
    duplicate strokes; with copies, copies match in order (still an exact coding). The hashes
    (row_hashes) may be passed in: a sequence coder reuses each frame's as the next one's prev."""
    n = cur_rows.shape[0]
    none = 0, np.zeros(0, dtype=np.int64)
    if n == 0 or prev_rows.shape[0] == 0:
        return none
    if not (prev_rows == cur_rows[0]).all(axis=1).any():
        return none  # common when everything moved: no hashing needed
    ph, order = prev_hashes or row_hashes(prev_rows)
    ch, corder = cur_hashes or row_hashes(cur_rows)
    sp = ph[order]
    if (sp[1:] == sp[:-1]).any():
        return none  # a hash collision: send a key frame, still exact
    j = np.empty(n, dtype=np.int64)
    j[corder] = np.searchsorted(sp, ch[corder])  # sorted needles: a merge, cache friendly
    np.minimum(j, sp.shape[0] - 1, out=j)
    pos = np.where(sp[j] == ch, order[j], -1)
    good = pos >= 0
    good[1:] &= pos[1:] > pos[:-1]
    L = n if good.all() else int(np.argmin(good))
    kept = pos[:L]
    if L and not (prev_rows[kept] == cur_rows[:L]).all():
        # A collision that matched different strokes: cut the prefix before the first mismatch.
        eq = (prev_rows[kept] == cur_rows[:L]).all(axis=1)
        L = int(np.argmin(eq))
        kept = kept[:L]
    return L, kept


def identity_rows(rows):
    """Rows without their position: what find_motion matches on."""
    ident = rows.copy()
    ident[:, X:Y + 1] = 0
    return ident


def find_motion(prev_rows, cur_rows, width, height, block_sizes, curves, prev_ident=None, cur_ident=None):
    """(L, kept, Motion) when cur starts with strokes of prev, in order, moved by a block motion
    field (section 5), else None. This lets an unedited export keep the painter's motion-coded
    inter frames instead of re-sending every moved stroke.

    1. Strokes are matched on everything but their position (copies in order); in a painting
       many strokes share set, template, orientation and colour, so some matches are wrong.
    2. Per block, the most common displacement of the matched strokes it holds is the field.
    3. The whole previous list moved by that field is matched exactly against cur (kept_prefix),
       so the result is exact whatever went wrong in 1 and 2; a worse field only costs bytes.
    Curves must stay in place (their points would move per point): a field that would move one
    is rejected. Polygons move rigidly by their first vertex's block, like stamps (strokes_np). prev_ident / cur_ident: (identity rows, their row_hashes), cached by the caller.
    """
    ip, iph = prev_ident or (identity_rows(prev_rows), None)
    ic, ich = cur_ident or (identity_rows(cur_rows), None)
    L0, kept0 = kept_prefix(ip, ic, iph, ich)
    if L0 < cur_rows.shape[0] // 2:
        # Copies matched in order go wrong once an earlier copy was removed: match greedily
        # (each stroke to the first copy after the previous match), as the reference coder does.
        L0, kept0 = _greedy_prefix(ip, ic)
    if L0 == 0:
        return None
    pk, ck = prev_rows[kept0], cur_rows[:L0]
    quad = pk[:, KIND] != CURVE
    px, py = pk[quad, X].astype(np.int64), pk[quad, Y].astype(np.int64)
    d = ck[quad, X:Y + 1].astype(np.int64) - pk[quad, X:Y + 1]
    ok = (np.abs(d) <= 32767).all(axis=1)
    if not d[ok].any():
        return None
    pquad = prev_rows[:, KIND] != CURVE
    best = None
    for bs in block_sizes:
        if not 8 <= bs <= 256:
            continue
        cols, nrows = -(-width // bs), -(-height // bs)
        b = np.clip(py // (16 * bs), 0, nrows - 1) * cols + np.clip(px // (16 * bs), 0, cols - 1)
        vec = _mode_per_block(b[ok], d[ok], cols * nrows)
        m = Motion(bs, cols, nrows, vec.astype(np.int32))
        if any(_block_vectors(m, curves[c][:, 0].astype(np.int64), curves[c][:, 1].astype(np.int64)).any()
               for c in prev_rows[~pquad, CURVE_ID].tolist()):
            continue  # the field would move a curve
        moved = prev_rows.copy()
        dv = _block_vectors(m, prev_rows[:, X].astype(np.int64), prev_rows[:, Y].astype(np.int64))
        dv[~pquad] = 0
        nx, ny = prev_rows[:, X] + dv[:, 0], prev_rows[:, Y] + dv[:, 1]
        if (np.abs(nx) > MAX_POS).any() or (np.abs(ny) > MAX_POS).any() or not polygons_fit(prev_rows, dv, curves):
            continue
        moved[:, X], moved[:, Y] = nx, ny
        L, kept = kept_prefix(moved, cur_rows)
        if L and (best is None or L > best[0]):
            best = (L, kept, m)
        if L >= L0:
            break  # as good as the identity match: no need to try other block sizes
    return best


def _greedy_prefix(prev_rows, cur_rows):
    """writer.frames_from_lists' greedy earliest matching on rows (Python loop over cur, bisect
    per stroke): slower than kept_prefix, used only when copies confuse the latter."""
    import bisect
    h = (prev_rows.astype(np.int64).view(np.uint64) * _MULT[None, :]).sum(axis=1, dtype=np.uint64).tolist()
    where = {}
    for i, v in enumerate(h):
        where.setdefault(v, []).append(i)
    ch = (cur_rows.astype(np.int64).view(np.uint64) * _MULT[None, :]).sum(axis=1, dtype=np.uint64).tolist()
    kept = []
    j = 0
    for v in ch:
        lst = where.get(v)
        if lst is None:
            break
        k = bisect.bisect_left(lst, j)
        if k == len(lst):
            break
        kept.append(lst[k])
        j = lst[k] + 1
    return len(kept), np.array(kept, dtype=np.int64)


def _mode_per_block(block, d, nblocks):
    """(nblocks, 2) int64: per block, the most common displacement among its strokes (0 where
    a block holds none)."""
    vec = np.zeros((nblocks, 2), dtype=np.int64)
    if block.shape[0] == 0:
        return vec
    key = (block * 65536 + (d[:, 0] + 32768)) * 65536 + (d[:, 1] + 32768)
    uniq, counts = np.unique(key, return_counts=True)
    ub = uniq // (65536 * 65536)
    order = np.lexsort((counts, ub))  # by block, then count: the last of each block wins
    last = np.ones(order.shape[0], dtype=bool)
    last[:-1] = ub[order][1:] != ub[order][:-1]
    win = uniq[order][last]
    wb = win // (65536 * 65536)
    vec[wb, 0] = (win // 65536) % 65536 - 32768
    vec[wb, 1] = win % 65536 - 32768
    return vec


def frames_from_tables(tables, curves, width=0, height=0, block_sizes=()):
    """Key/inter frames whose live lists are `tables`: the reference's rule (keep the longest
    prefix found in the previous list, remove the rest, append the tail; a key frame when that is
    not smaller), plus, when block sizes and the canvas are given, inter frames with a motion
    field when the strokes moved as one (find_motion) and that is smaller still."""
    frames = []
    prev = prev_h = prev_id = None
    for i, cur in enumerate(tables):
        rows = cur.rows
        cur_h = cur_id = None
        n = rows.shape[0]
        if block_sizes and width and n:
            ident = identity_rows(rows)
            cur_id = (ident, row_hashes(ident))
        if prev is None:
            frames.append(Frame(index=i, type=KEY, added=StrokeTable(rows, curves)))
            prev, prev_h, prev_id = rows, None, cur_id
            continue
        if prev.shape[0] and n and (prev == rows[0]).all(axis=1).any():
            prev_h = prev_h or row_hashes(prev)
            cur_h = row_hashes(rows)
        L, kept = kept_prefix(prev, rows, prev_h, cur_h)
        best = (16 * n, None)  # (stored bytes, frame); a key frame re-sends everything
        plain = 4 * (prev.shape[0] - L) + 16 * (n - L)
        if plain < best[0]:
            best = (plain, (L, kept, None))
        if block_sizes and width and L < n:
            found = find_motion(prev, rows, width, height, block_sizes, curves, prev_id, cur_id)
            if found is not None:
                Lm, keptm, m = found
                size = 4 * (prev.shape[0] - Lm) + 4 * m.cols * m.rows + 16 * (n - Lm)
                if size < best[0]:
                    best = (size, found)
        if best[1] is None:
            frames.append(Frame(index=i, type=KEY, added=StrokeTable(rows, curves)))
        else:
            L, kept, m = best[1]
            keep = np.zeros(prev.shape[0], dtype=bool)
            keep[kept] = True
            removed = np.flatnonzero(~keep).astype(np.uint32)
            frames.append(Frame(index=i, type=INTER, removed=removed, motion=m, added=StrokeTable(rows[L:], curves)))
        prev, prev_h, prev_id = rows, cur_h, cur_id
    return frames
