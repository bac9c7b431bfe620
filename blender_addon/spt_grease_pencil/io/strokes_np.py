"""Stroke lists as numpy tables: the file layer's fast path (Blender's Python has numpy).

The reference code (tests/blender/reference/) keeps one Python tuple per stroke, which
is simple and needs only the standard library, but costs microseconds per stroke; a 2-million
stroke animation needs the vectorised form. A StrokeTable holds one int32 row per stroke:

    KIND SET TMPL ORIENT X Y MA MB MC MD R G B A CURVE GRID

stamp:   SET TMPL ORIENT, X Y = position (Q4); MA..MD = 0
affine:  TMPL, X Y = translation (Q4), MA MB MC MD = matrix (a b c d, Q4); SET = ORIENT = 0
curve:   CURVE = index into a pool (a list of int32 arrays) shared by the tables of one file:
         (n, 3) x, y, width in Q4; GRID = supersampling N (format 1.4: a file with the HEAD flag
         curve_grid stores it in every curve record; 0 otherwise); every other geometry column 0.
polygon: X Y = the first vertex P0 (Q4), GRID = supersampling N, CURVE = pool entry (n, 2) of
         every vertex RELATIVE to P0 (so its first row is 0, 0).

A polygon keeps its outline relative to P0 because it moves rigidly by P0's motion block
(SPEC.md 5): moving it changes X Y only, exactly like a stamp, so motion is vectorised, the pool
entry is shared by every frame the polygon lives in, and the exporter's motion search
(state_np.find_motion) finds polygon motion with no extra code.

R G B are the colour values: 8-bit in colour encoding 0, 16-bit half codes in colour encoding 1
(format 1.3), whose stored records carry the low bytes after r, g, b, a (SPEC.md 6): `linear`
below says which, from the header.

Unused columns are always 0, so two rows are equal exactly when the strokes are (curves and
polygons: when their pool entries are the same entry; writers that compare strokes dedupe the
pool by content and shape).
tests/blender/test_io.py checks this module against that oracle on the same files.
"""

import struct

import numpy as np

from .model import (AFFINE, CURVE, MAX_CURVE_WIDTH, MAX_HALF_CODE, MAX_MATRIX, MAX_POS, POLYGON, STAMP, SptError,
                    curve_grid_of, curve_tuple)

KIND, SET, TMPL, ORIENT, X, Y, MA, MB, MC, MD, R, G, B, A, CURVE_ID, GRID = range(16)
NCOL = 16

STAMP_DT = np.dtype([("k", "u1"), ("s", "u1"), ("t", "u1"), ("o", "u1"), ("x", "<i4"), ("y", "<i4"),
                     ("r", "u1"), ("g", "u1"), ("b", "u1"), ("a", "u1")])
AFFINE_DT = np.dtype([("k", "u1"), ("t", "u1"), ("x", "<i4"), ("y", "<i4"), ("ma", "<i4"), ("mb", "<i4"),
                      ("mc", "<i4"), ("md", "<i4"), ("r", "u1"), ("g", "u1"), ("b", "u1"), ("a", "u1")])
_LO = [("rl", "u1"), ("gl", "u1"), ("bl", "u1")]  # colour encoding 1: the codes' low bytes
STAMP_LIN_DT = np.dtype(STAMP_DT.descr + _LO)
AFFINE_LIN_DT = np.dtype(AFFINE_DT.descr + _LO)
assert STAMP_DT.itemsize == 16 and AFFINE_DT.itemsize == 30
assert STAMP_LIN_DT.itemsize == 19 and AFFINE_LIN_DT.itemsize == 33
_CURVE_HEAD = struct.Struct("<BBBBBI")
_CURVE_LIN_HEAD = struct.Struct("<BBBBBBBBI")      # kind, r, g, b, a, r_lo, g_lo, b_lo, n
_POINT_DT = np.dtype([("x", "<i4"), ("y", "<i4"), ("w", "<u4")])
_POLYGON_HEAD = struct.Struct("<BBBBBBI")  # kind, r, g, b, a, grid N, n
_POLYGON_LIN_HEAD = struct.Struct("<BBBBBBBBBI")   # kind, r, g, b, a, r_lo, g_lo, b_lo, grid N, n
# Format 1.4, files with the curve_grid flag: a curve's head holds its grid N where a polygon's does.
_CURVE_GRID_HEAD, _CURVE_GRID_LIN_HEAD = _POLYGON_HEAD, _POLYGON_LIN_HEAD


def _curve_head(linear: bool, curve_grid: bool):
    if curve_grid:
        return _CURVE_GRID_LIN_HEAD if linear else _CURVE_GRID_HEAD
    return _CURVE_LIN_HEAD if linear else _CURVE_HEAD


def _split_codes(rgb):
    """16-bit codes (.., 3) to their (high bytes, low bytes), as a record stores them."""
    rgb = np.asarray(rgb, dtype=np.int64)
    return rgb >> 8, rgb & 255


def check_colours(rows, linear: bool, what: str = "stroke") -> None:
    """Colour values a record can hold: 0..255 (encoding 0) or codes 0..0x7BFF (encoding 1); the
    writer checks before packing, so a value never wraps silently into another colour."""
    if rows.shape[0] == 0:
        return
    top = MAX_HALF_CODE if linear else 255
    rgb = rows[:, R:B + 1]
    a = rows[:, A]
    bad = (rgb < 0).any(axis=1) | (rgb > top).any(axis=1) | (a < 0) | (a > 255)
    if bad.any():
        i = int(np.argmax(bad))
        kind = "16-bit half code 0..0x7BFF" if linear else "8-bit value 0..255"
        raise SptError(f"{what} {i}: colour {tuple(rows[i, R:A + 1].tolist())} is not a {kind} "
                       f"(colour encoding {1 if linear else 0}) with opacity 0..255")
_VERTEX_DT = np.dtype([("x", "<i4"), ("y", "<i4")])


def polygon_vertices(rows, curves, i) -> np.ndarray:
    """(n, 2) int64 absolute Q4 vertices of polygon row i."""
    r = rows[i]
    v = curves[r[CURVE_ID]].astype(np.int64)
    return v + np.array([r[X], r[Y]], dtype=np.int64)


def polygon_row(r, g, b, a, grid, vertices, curves) -> np.ndarray:
    """One polygon row; appends the outline relative to its first vertex to the pool `curves`."""
    v = np.asarray(vertices, dtype=np.int64).reshape(-1, 2)
    row = np.zeros(NCOL, dtype=np.int32)
    row[[KIND, X, Y, R, G, B, A, GRID, CURVE_ID]] = (POLYGON, v[0, 0], v[0, 1], r, g, b, a, grid, len(curves))
    curves.append((v - v[0]).astype(np.int32))
    return row


class StrokeTable:
    """An ordered stroke list: rows (N, NCOL) int32 and the curve pool its CURVE column refers to."""

    __slots__ = ("rows", "curves")

    def __init__(self, rows=None, curves=None):
        self.rows = np.zeros((0, NCOL), dtype=np.int32) if rows is None else rows
        self.curves = [] if curves is None else curves

    def __len__(self):
        return self.rows.shape[0]

    def take(self, index) -> "StrokeTable":
        return StrokeTable(self.rows[index], self.curves)

    def to_tuples(self) -> list:
        """The reference form (model.py tuples), for tests and small lists."""
        out = []
        for r in self.rows.tolist():
            k = r[KIND]
            if k == STAMP:
                out.append((STAMP, r[SET], r[TMPL], r[ORIENT], r[X], r[Y], r[R], r[G], r[B], r[A]))
            elif k == AFFINE:
                out.append((AFFINE, r[TMPL], r[X], r[Y], r[MA], r[MB], r[MC], r[MD], r[R], r[G], r[B], r[A]))
            elif k == POLYGON:
                v = self.curves[r[CURVE_ID]].astype(np.int64) + np.array([r[X], r[Y]], dtype=np.int64)
                out.append((POLYGON, r[R], r[G], r[B], r[A], r[GRID], tuple(tuple(p) for p in v.tolist())))
            else:
                pts = tuple(tuple(p) for p in self.curves[r[CURVE_ID]].tolist())
                out.append(curve_tuple(r[R], r[G], r[B], r[A], pts, r[GRID]))
        return out

    @classmethod
    def from_tuples(cls, strokes, curves=None) -> "StrokeTable":
        curves = [] if curves is None else curves
        rows = np.zeros((len(strokes), NCOL), dtype=np.int32)
        for i, s in enumerate(strokes):
            k = s[0]
            if k == STAMP:
                rows[i, [KIND, SET, TMPL, ORIENT, X, Y, R, G, B, A]] = s
            elif k == AFFINE:
                rows[i, [KIND, TMPL, X, Y, MA, MB, MC, MD, R, G, B, A]] = s
            elif k == POLYGON:
                rows[i] = polygon_row(s[1], s[2], s[3], s[4], s[5], s[6], curves)
            else:
                rows[i, [KIND, R, G, B, A, GRID]] = s[:5] + (curve_grid_of(s),)
                rows[i, CURVE_ID] = len(curves)
                curves.append(np.asarray(s[5], dtype=np.int32).reshape(-1, 3))
        return cls(rows, curves)

    def record_bytes(self, linear: bool = False, curve_grid: bool = False) -> bytes:
        """The stroke records of a stored frame body (section 4), in order."""
        return records_bytes(self.rows, self.curves, linear, curve_grid)


def tables_from_lists(live_lists):
    """StrokeTables of tuple lists over one curve pool deduplicated by content and shape, so that
    a curve or polygon that lives on from frame to frame has equal rows in every table (the
    frame coder matches strokes by row). Returns (tables, pool)."""
    pool, ids, tables = [], {}, []
    for ls in live_lists:
        t = StrokeTable.from_tuples(list(ls))
        rows = t.rows
        for i in np.flatnonzero((rows[:, KIND] == CURVE) | (rows[:, KIND] == POLYGON)).tolist():
            arr = t.curves[rows[i, CURVE_ID]]
            key = (arr.shape[1], arr.tobytes())
            if key not in ids:
                ids[key] = len(pool)
                pool.append(arr)
            rows[i, CURVE_ID] = ids[key]
        tables.append(StrokeTable(rows, pool))
    return tables, pool


def concat(tables, curves) -> StrokeTable:
    rows = [t.rows for t in tables if len(t)]
    if not rows:
        return StrokeTable(None, curves)
    return StrokeTable(np.concatenate(rows) if len(rows) > 1 else rows[0], curves)


# ---------------------------------------------------------------- bytes -> table

def _run_length(buf, pos: int, stride: int, maxrun: int, kind: int) -> int:
    """How many records of `kind` follow at `pos` (fixed size `stride`), at most `maxrun`. Looks
    at a growing window so alternating kinds cost O(run), not O(rest of the frame)."""
    run, win = 0, 64
    while run < maxrun:
        m = min(win, maxrun - run)
        ks = buf[pos + stride * run:pos + stride * (run + m):stride]
        bad = np.flatnonzero(ks != kind)
        if bad.size:
            return run + int(bad[0])
        run += m
        win *= 4
    return run


def _err(path, offset, what):
    return SptError(f"{path}: byte {offset}: {what}")


def _colour_columns(rows, rec, linear):
    """R G B A of records `rec`: bytes, or codes from high and low bytes (colour encoding 1)."""
    for c, f in ((R, "r"), (G, "g"), (B, "b")):
        rows[:, c] = rec[f]
        if linear:
            rows[:, c] = rows[:, c] * 256 + rec[f[0] + "l"]
    rows[:, A] = rec["a"]


def _bad_codes(rows, linear):
    """Per row: a colour code above 0x7BFF (not a finite half float >= 0)."""
    if not linear:
        return np.zeros(rows.shape[0], dtype=bool)
    return (rows[:, R:B + 1] > MAX_HALF_CODE).any(axis=1)


def _run_rows(rec, columns, linear, path, at, size, code_error):
    """The table rows of a run of fixed-size records (`size` bytes each, the first at byte `at`):
    (column, values) pairs, then the colour; a colour code out of range names its record."""
    rows = np.zeros((rec.shape[0], NCOL), dtype=np.int32)
    for c, values in columns:
        rows[:, c] = values
    _colour_columns(rows, rec, linear)
    bad = _bad_codes(rows, linear)
    if bad.any():
        raise _err(path, at + size * int(np.argmax(bad)), code_error)
    return rows


def parse_records(body, pos: int, count: int, path: str, base: int, ntemplates: int, nsets: int,
                  norients: int, max_curve_points: int, curves: list, max_polygon_vertices: int = 1 << 16,
                  linear: bool = False, curve_grid: bool = False):
    """Parses `count` stroke records of a stored frame body from `pos`; returns (table, pos).
    `linear`: colour encoding 1, whose records carry three low bytes after r, g, b, a.
    `curve_grid`: the HEAD flag of format 1.4, whose curve records carry a grid N after those.
    Errors name the byte offset (base + position in the body) of the offending record."""
    stamp_dt, affine_dt = (STAMP_LIN_DT, AFFINE_LIN_DT) if linear else (STAMP_DT, AFFINE_DT)
    ssz, asz = stamp_dt.itemsize, affine_dt.itemsize
    curve_head = _curve_head(linear, curve_grid)
    polygon_head = _POLYGON_LIN_HEAD if linear else _POLYGON_HEAD
    code_error = "colour code is not a finite half float >= 0 (above 0x7BFF)"
    buf = np.frombuffer(body, dtype=np.uint8)
    n = buf.shape[0]
    pieces = []
    done = 0
    while done < count:
        if pos >= n:
            raise _err(path, base + pos, f"frame body ends inside its stroke list ({done} of {count} strokes)")
        kind = int(buf[pos])
        if kind == STAMP:
            run = _run_length(buf, pos, ssz, min(count - done, (n - pos) // ssz), STAMP)
            if run == 0:
                raise _err(path, base + pos, "truncated stamp stroke")
            rec = np.frombuffer(body, dtype=stamp_dt, count=run, offset=pos)
            bad = (rec["s"] >= nsets) | (rec["t"] >= ntemplates) | (rec["o"] >= norients)
            if bad.any():
                i = int(np.argmax(bad))
                r = rec[i]
                raise _err(path, base + pos + ssz * i,
                           f"stamp stroke refers to set {r['s']}, template {r['t']}, orientation {r['o']} "
                           f"(file has {nsets} sets, {ntemplates} templates, {norients} orientations)")
            bad = (np.abs(rec["x"]) > MAX_POS) | (np.abs(rec["y"]) > MAX_POS)
            if bad.any():
                raise _err(path, base + pos + ssz * int(np.argmax(bad)), "stamp position out of range")
            columns = ((SET, rec["s"]), (TMPL, rec["t"]), (ORIENT, rec["o"]), (X, rec["x"]), (Y, rec["y"]))
            pieces.append(_run_rows(rec, columns, linear, path, base + pos, ssz, code_error))
            pos += ssz * run
            done += run
        elif kind == AFFINE:
            run = _run_length(buf, pos, asz, min(count - done, (n - pos) // asz), AFFINE)
            if run == 0:
                raise _err(path, base + pos, "truncated affine stroke")
            rec = np.frombuffer(body, dtype=affine_dt, count=run, offset=pos)
            m = np.stack([rec["ma"], rec["mb"], rec["mc"], rec["md"]], axis=1).astype(np.int64)
            checks = ((rec["t"] >= ntemplates, "affine stroke refers to a template the file does not have"),
                      ((np.abs(rec["x"]) > MAX_POS) | (np.abs(rec["y"]) > MAX_POS), "affine translation out of range"),
                      (np.abs(m).max(axis=1) > MAX_MATRIX, "affine matrix entry out of range"),
                      (m[:, 0] * m[:, 3] - m[:, 1] * m[:, 2] == 0, "affine matrix is singular"))
            for bad, what in checks:
                if bad.any():
                    raise _err(path, base + pos + asz * int(np.argmax(bad)), what)
            columns = ((KIND, AFFINE), (TMPL, rec["t"]), (X, rec["x"]), (Y, rec["y"]), (slice(MA, MD + 1), m))
            pieces.append(_run_rows(rec, columns, linear, path, base + pos, asz, code_error))
            pos += asz * run
            done += run
        elif kind == CURVE:
            hs = curve_head.size
            if pos + hs > n:
                raise _err(path, base + pos, "truncated curve stroke")
            r, g, b, a, *grid, npts = _head_colour(curve_head.unpack_from(body, pos), linear)
            grid = grid[0] if grid else 0
            if max(r, g, b) > (MAX_HALF_CODE if linear else 255):
                raise _err(path, base + pos, code_error)
            if grid == 1 or grid > 16:
                raise _err(path, base + pos, f"curve supersampling {grid} is reserved")
            if npts < 1 or npts > max_curve_points:
                raise _err(path, base + pos, f"curve stroke has {npts} points (allowed 1..{max_curve_points})")
            if pos + hs + 12 * npts > n:
                raise _err(path, base + pos, f"curve stroke of {npts} points runs past the frame body")
            p = np.frombuffer(body, dtype=_POINT_DT, count=npts, offset=pos + hs)
            if (np.abs(p["x"]) > MAX_POS).any() or (np.abs(p["y"]) > MAX_POS).any() or (p["w"] > MAX_CURVE_WIDTH).any():
                raise _err(path, base + pos, "curve point out of range")
            row = np.zeros((1, NCOL), dtype=np.int32)
            row[0, [KIND, R, G, B, A, GRID, CURVE_ID]] = (CURVE, r, g, b, a, grid, len(curves))
            curves.append(np.stack([p["x"], p["y"], p["w"].astype(np.int32)], axis=1))
            pieces.append(row)
            pos += hs + 12 * npts
            done += 1
        elif kind == POLYGON:
            hs = polygon_head.size
            if pos + hs > n:
                raise _err(path, base + pos, "truncated polygon stroke")
            r, g, b, a, grid, npts = _head_colour(polygon_head.unpack_from(body, pos), linear)
            if max(r, g, b) > (MAX_HALF_CODE if linear else 255):
                raise _err(path, base + pos, code_error)
            if grid == 1 or grid > 16:
                raise _err(path, base + pos, f"polygon supersampling {grid} is reserved")
            if npts < 3 or npts > max_polygon_vertices:
                raise _err(path, base + pos, f"polygon stroke has {npts} vertices (allowed 3..{max_polygon_vertices})")
            if pos + hs + 8 * npts > n:
                raise _err(path, base + pos, f"polygon stroke of {npts} vertices runs past the frame body")
            v = np.frombuffer(body, dtype=_VERTEX_DT, count=npts, offset=pos + hs)
            if (np.abs(v["x"]) > MAX_POS).any() or (np.abs(v["y"]) > MAX_POS).any():
                raise _err(path, base + pos, "polygon vertex out of range")
            pieces.append(polygon_row(r, g, b, a, grid, np.stack([v["x"], v["y"]], axis=1), curves)[None, :])
            pos += hs + 8 * npts
            done += 1
        else:
            raise _err(path, base + pos, f"unknown stroke kind {kind}")
    rows = np.concatenate(pieces) if len(pieces) > 1 else (pieces[0] if pieces else np.zeros((0, NCOL), np.int32))
    return StrokeTable(rows, curves), pos


def _head_colour(fields, linear):
    """(r, g, b, a, rest...) of an unpacked curve or polygon head (kind first): codes from the
    high and low bytes in colour encoding 1."""
    if not linear:
        return fields[1:]
    r, g, b, a, rl, gl, bl = fields[1:8]
    return (256 * r + rl, 256 * g + gl, 256 * b + bl, a) + tuple(fields[8:])


# ---------------------------------------------------------------- table -> bytes

def _pack_colour(rec, r, linear):
    for f, c in (("r", R), ("g", G), ("b", B)):
        if linear:
            hi, lo = _split_codes(r[:, c])
            rec[f], rec[f[0] + "l"] = hi, lo
        else:
            rec[f] = r[:, c]
    rec["a"] = r[:, A]


def _head_bytes(head, kind, row, linear, *rest):
    if linear:
        rgb = [row[R], row[G], row[B]]
        return head.pack(kind, *[c >> 8 for c in rgb], row[A], *[c & 255 for c in rgb], *rest)
    return head.pack(kind, row[R], row[G], row[B], row[A], *rest)


def check_curve_grids(rows, curve_grid: bool) -> None:
    """Curve grids a record can hold: 0 or 2..16 with the HEAD flag curve_grid, 0 without it
    (a file without the flag has no byte for one)."""
    g = rows[(rows[:, KIND] == CURVE), GRID]
    bad = (g != 0) if not curve_grid else ((g == 1) | (g < 0) | (g > 16))
    if bad.any():
        i = int(np.flatnonzero(rows[:, KIND] == CURVE)[np.argmax(bad)])
        if curve_grid:
            raise SptError(f"curve {i}: supersampling grid {int(rows[i, GRID])} is not 0 or 2..16")
        raise SptError(f"curve {i}: supersampling grid {int(rows[i, GRID])} needs the HEAD flag curve_grid "
                       "(format 1.4)")


def records_bytes(rows, curves, linear: bool = False, curve_grid: bool = False) -> bytes:
    """Stroke records in order; runs of one kind are packed with one structured array each.
    `linear`: colour encoding 1 (R G B hold 16-bit codes; records carry their low bytes).
    `curve_grid`: the HEAD flag of format 1.4 (curve records carry their grid N)."""
    n = rows.shape[0]
    if n == 0:
        return b""
    check_colours(rows, linear)
    check_curve_grids(rows, curve_grid)
    curve_head = _curve_head(linear, curve_grid)
    stamp_dt, affine_dt = (STAMP_LIN_DT, AFFINE_LIN_DT) if linear else (STAMP_DT, AFFINE_DT)
    kinds = rows[:, KIND]
    cuts = np.flatnonzero(kinds[1:] != kinds[:-1]) + 1
    starts = [0] + cuts.tolist()
    ends = cuts.tolist() + [n]
    out = []
    for a, b in zip(starts, ends):
        k = int(kinds[a])
        r = rows[a:b]
        if k == STAMP:
            rec = np.empty(b - a, dtype=stamp_dt)
            rec["k"] = STAMP
            for f, c in (("s", SET), ("t", TMPL), ("o", ORIENT), ("x", X), ("y", Y)):
                rec[f] = r[:, c]
            _pack_colour(rec, r, linear)
            out.append(rec.tobytes())
        elif k == AFFINE:
            rec = np.empty(b - a, dtype=affine_dt)
            rec["k"] = AFFINE
            for f, c in (("t", TMPL), ("x", X), ("y", Y), ("ma", MA), ("mb", MB), ("mc", MC), ("md", MD)):
                rec[f] = r[:, c]
            _pack_colour(rec, r, linear)
            out.append(rec.tobytes())
        elif k == CURVE:
            for row in r.tolist():
                pts = curves[row[CURVE_ID]]
                grid = (row[GRID],) if curve_grid else ()
                out.append(_head_bytes(curve_head, CURVE, row, linear, *grid, pts.shape[0]))
                out.append(np.ascontiguousarray(pts, dtype="<i4").tobytes())
        elif k == POLYGON:
            for i in range(r.shape[0]):
                v = polygon_vertices(r, curves, i)
                row = r[i].tolist()
                out.append(_head_bytes(_POLYGON_LIN_HEAD if linear else _POLYGON_HEAD, POLYGON, row, linear,
                                       row[GRID], v.shape[0]))
                out.append(np.ascontiguousarray(v, dtype="<i4").tobytes())
        else:
            raise SptError(f"unknown stroke kind {k}")
    return b"".join(out)
