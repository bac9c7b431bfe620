"""The reference (oracle) of the add-on's frame decoding: one Python tuple per stroke (model.py),
standard library only, slow and plain. It runs through the add-on's own container parser
(reader.read_bytes with decoding=TupleDecoding()), so tests/blender/test_io.py compares exactly
the part that differs: record parsing and the live-list update (section 5) against strokes_np.py
and state_np.py. The add-on itself ships only those."""

import struct
from typing import List

from spt_grease_pencil.io import reader
from spt_grease_pencil.io.model import (AFFINE, CURVE, INTER, KEY, MAX_CURVE_WIDTH, MAX_MATRIX,  # noqa: F401
                                        MAX_POS, POLYGON, STAMP, Frame, Header, Limits, Motion, SptError,
                                        StreamInfo)

_STAMP = struct.Struct("<BBBBiiBBBB")          # kind included: the tuple is the stroke
_AFFINE = struct.Struct("<BBiiiiiiBBBB")
_CURVE_HEAD = struct.Struct("<BBBBBI")
_POLYGON_HEAD = struct.Struct("<BBBBBBI")   # kind, r, g, b, a, grid N, n (format 1.2)
# Colour encoding 1 (format 1.3): r, g, b, a, then the low bytes r_lo, g_lo, b_lo of the codes.
_STAMP_LIN = struct.Struct("<BBBBiiBBBBBBB")
_AFFINE_LIN = struct.Struct("<BBiiiiiiBBBBBBB")
_CURVE_LIN_HEAD = struct.Struct("<BBBBBBBBI")
_POLYGON_LIN_HEAD = struct.Struct("<BBBBBBBBBI")
# Format 1.4, a file with the HEAD flag curve_grid: a curve's grid N follows its colour.
_CURVE_GRID_HEAD = struct.Struct("<BBBBBBI")        # kind, r, g, b, a, grid N, n
_CURVE_GRID_LIN_HEAD = struct.Struct("<BBBBBBBBBI")  # kind, r, g, b, a, r_lo, g_lo, b_lo, grid N, n
MAX_HALF_CODE = 0x7BFF


def _codes(fields, at):
    """fields with r, g, b at `at` as 16-bit codes (high bytes there, low bytes after a)."""
    r, g, b, a, rl, gl, bl = fields[at:at + 7]
    return fields[:at] + (256 * r + rl, 256 * g + gl, 256 * b + bl, a) + fields[at + 7:]


class TupleDecoding:
    """Frame contents as lists and tuples."""

    def removed(self, body, offset, count):
        return list(struct.unpack_from(f"<{count}I", body, offset))

    def vectors(self, body, offset, count):
        flat = struct.unpack_from(f"<{2 * count}h", body, offset)
        return list(zip(flat[0::2], flat[1::2]))

    def records(self, body, pos, count, path, base, info, limits):
        return parse_strokes(body, pos, count, path, base, info, limits)

    def live_lists(self, header, frames, limits, path):
        return apply_frames(header, frames, limits, path)


def read_bytes(data, path="<memory>", limits=None):
    return reader.read_bytes(data, path, limits, decoding=TupleDecoding())


def read_file(path, limits=None):
    return reader.read_file(path, limits, decoding=TupleDecoding())


def _err(path, offset, what):
    return SptError(f"{path}: byte {offset}: {what}")


def _check_stroke(s, path, off, ntemplates, nsets, norients, limits):
    k = s[0]
    if k == STAMP:
        if s[1] >= nsets or s[2] >= ntemplates or s[3] >= norients:
            raise _err(path, off, f"stamp stroke refers to set {s[1]}, template {s[2]}, orientation {s[3]} "
                                  f"(file has {nsets} sets, {ntemplates} templates, {norients} orientations)")
        if abs(s[4]) > MAX_POS or abs(s[5]) > MAX_POS:
            raise _err(path, off, "stamp position out of range")
    elif k == AFFINE:
        if s[1] >= ntemplates:
            raise _err(path, off, f"affine stroke refers to template {s[1]} (file has {ntemplates})")
        if abs(s[2]) > MAX_POS or abs(s[3]) > MAX_POS:
            raise _err(path, off, "affine translation out of range")
        if max(abs(s[4]), abs(s[5]), abs(s[6]), abs(s[7])) > MAX_MATRIX:
            raise _err(path, off, "affine matrix entry out of range")
        if s[4] * s[7] - s[5] * s[6] == 0:
            raise _err(path, off, "affine matrix is singular")


def parse_strokes(body, pos: int, count: int, path: str, base: int, info: StreamInfo, limits: Limits):
    """Parses `count` stroke records from body[pos:]; returns (strokes, new_pos)."""
    n = len(body)
    ntemplates = len(info.templates)
    nsets = len(info.header.sets)
    norients = len(info.header.orientations)
    out = []
    append = out.append
    linear = info.header.color_encoding == 1
    if linear:
        return _parse_linear(body, pos, count, path, base, info, limits)
    grid_byte = 1 if info.header.curve_grid else 0
    stamp_unpack = _STAMP.unpack_from
    for _ in range(count):
        if pos >= n:
            raise _err(path, base + pos, f"frame body ends inside its stroke list ({len(out)} of {count} strokes)")
        kind = body[pos]
        if kind == STAMP:
            if pos + 16 > n:
                raise _err(path, base + pos, "truncated stamp stroke")
            s = stamp_unpack(body, pos)
            # Inline range checks: this loop runs millions of times.
            if s[1] >= nsets or s[2] >= ntemplates or s[3] >= norients or \
                    not (-MAX_POS <= s[4] <= MAX_POS and -MAX_POS <= s[5] <= MAX_POS):
                _check_stroke(s, path, base + pos, ntemplates, nsets, norients, limits)
            pos += 16
        elif kind == AFFINE:
            if pos + 30 > n:
                raise _err(path, base + pos, "truncated affine stroke")
            s = _AFFINE.unpack_from(body, pos)
            _check_stroke(s, path, base + pos, ntemplates, nsets, norients, limits)
            pos += 30
        elif kind == CURVE:
            hs = 9 + grid_byte
            if pos + hs > n:
                raise _err(path, base + pos, "truncated curve stroke")
            if grid_byte:
                _, r, g, b, a, grid, npts = _CURVE_GRID_HEAD.unpack_from(body, pos)
            else:
                (_, r, g, b, a, npts), grid = _CURVE_HEAD.unpack_from(body, pos), 0
            if grid == 1 or grid > 16:
                raise _err(path, base + pos, f"curve supersampling {grid} is reserved")
            if npts < 1 or npts > limits.max_curve_points:
                raise _err(path, base + pos, f"curve stroke has {npts} points (allowed 1..{limits.max_curve_points})")
            if pos + hs + 12 * npts > n:
                raise _err(path, base + pos, f"curve stroke of {npts} points runs past the frame body")
            pts = tuple(struct.iter_unpack("<iiI", body[pos + hs:pos + hs + 12 * npts]))
            for (x, y, w) in pts:
                if abs(x) > MAX_POS or abs(y) > MAX_POS or w > MAX_CURVE_WIDTH:
                    raise _err(path, base + pos, "curve point out of range")
            # model.py: the grid trails the points, and only when it is not 0
            s = (CURVE, r, g, b, a, pts) + ((grid,) if grid else ())
            pos += hs + 12 * npts
        elif kind == POLYGON:
            if pos + 10 > n:
                raise _err(path, base + pos, "truncated polygon stroke")
            _, r, g, b, a, grid, npts = _POLYGON_HEAD.unpack_from(body, pos)
            if grid == 1 or grid > 16:
                raise _err(path, base + pos, f"polygon supersampling {grid} is reserved")
            if npts < 3 or npts > limits.max_polygon_vertices:
                raise _err(path, base + pos, f"polygon stroke has {npts} vertices (allowed 3..{limits.max_polygon_vertices})")
            if pos + 10 + 8 * npts > n:
                raise _err(path, base + pos, f"polygon stroke of {npts} vertices runs past the frame body")
            pts = tuple(struct.iter_unpack("<ii", body[pos + 10:pos + 10 + 8 * npts]))
            for (x, y) in pts:
                if abs(x) > MAX_POS or abs(y) > MAX_POS:
                    raise _err(path, base + pos, "polygon vertex out of range")
            s = (POLYGON, r, g, b, a, grid, pts)
            pos += 10 + 8 * npts
        else:
            raise _err(path, base + pos, f"unknown stroke kind {kind}")
        append(s)
    return out, pos


def _parse_linear(body, pos, count, path, base, info, limits):
    """Colour encoding 1 records, plainly: read each as the encoding-0 record would be read with
    the three low bytes taken out after the opacity, then combine them into codes."""
    n = len(body)
    out = []
    curve_head = _CURVE_GRID_LIN_HEAD if info.header.curve_grid else _CURVE_LIN_HEAD
    heads = {STAMP: (_STAMP_LIN, 6), AFFINE: (_AFFINE_LIN, 8), CURVE: (curve_head, 1), POLYGON: (_POLYGON_LIN_HEAD, 1)}
    for _ in range(count):
        if pos >= n:
            raise _err(path, base + pos, f"frame body ends inside its stroke list ({len(out)} of {count} strokes)")
        kind = body[pos]
        if kind not in heads:
            raise _err(path, base + pos, f"unknown stroke kind {kind}")
        st, at = heads[kind]
        if pos + st.size > n:
            raise _err(path, base + pos, "truncated stroke")
        s = _codes(st.unpack_from(body, pos), at)
        if max(s[at:at + 3]) > MAX_HALF_CODE:
            raise _err(path, base + pos, "colour code is not a finite half float >= 0 (above 0x7BFF)")
        start, pos = pos, pos + st.size
        if kind in (STAMP, AFFINE):
            _check_stroke(s, path, base + start, len(info.templates), len(info.header.sets),
                          len(info.header.orientations), limits)
        elif kind == CURVE:
            grid, npts = (s[5], s[6]) if info.header.curve_grid else (0, s[5])
            if grid == 1 or grid > 16:
                raise _err(path, base + start, f"curve supersampling {grid} is reserved")
            if npts < 1 or npts > limits.max_curve_points or pos + 12 * npts > n:
                raise _err(path, base + start, f"curve stroke of {npts} points is out of range or runs past the body")
            pts = tuple(struct.iter_unpack("<iiI", body[pos:pos + 12 * npts]))
            pos += 12 * npts
            s = s[:5] + (pts,) + ((grid,) if grid else ())
        else:
            grid, npts = s[5], s[6]
            if grid == 1 or grid > 16 or npts < 3 or npts > limits.max_polygon_vertices or pos + 8 * npts > n:
                raise _err(path, base + start, "polygon stroke out of range or runs past the body")
            pts = tuple(struct.iter_unpack("<ii", body[pos:pos + 8 * npts]))
            pos += 8 * npts
            s = s[:6] + (pts,)
        out.append(s)
    return out, pos


def apply_frames(header: Header, frames: List[Frame], limits: Limits, path: str = "<memory>"):
    """Yields the live list after each frame (remove, move, add: section 5)."""
    live: list = []
    for fr in frames:
        if fr.type == KEY:
            live = list(fr.added)
        else:
            if fr.removed:
                prev = -1
                for i in fr.removed:
                    if i <= prev or i >= len(live):
                        raise SptError(f"{path}: frame {fr.index}: removed index {i} is not increasing or "
                                       f">= the live list length {len(live)}")
                    prev = i
                drop = set(fr.removed)
                live = [s for i, s in enumerate(live) if i not in drop]
            else:
                live = list(live)
            if fr.motion is not None:
                live = move_all(live, fr.motion, path, fr.index)
            live.extend(fr.added)
        if len(live) > limits.max_live_strokes:
            raise SptError(f"{path}: frame {fr.index}: {len(live)} live strokes exceed the limit")
        yield live


def move_all(live: list, m: Motion, path="<memory>", index=0) -> list:
    """Moves every stroke of the live list (section 5). Stamps, by far the most common, take an
    inlined fast path: this runs for every stroke of every moving frame."""
    bs16 = 16 * m.block_size
    cols, rows = m.cols, m.rows
    cmax, rmax = cols - 1, rows - 1
    vec = m.vectors
    out = []
    append = out.append
    for s in live:
        if s[0] == STAMP:
            x, y = s[4], s[5]
            bx = x // bs16
            by = y // bs16
            if bx < 0:
                bx = 0
            elif bx > cmax:
                bx = cmax
            if by < 0:
                by = 0
            elif by > rmax:
                by = rmax
            dx, dy = vec[by * cols + bx]
            if dx or dy:
                x += dx
                y += dy
                if x > MAX_POS or x < -MAX_POS or y > MAX_POS or y < -MAX_POS:
                    raise SptError(f"{path}: frame {index}: motion moves a stroke out of range")
                s = (STAMP, s[1], s[2], s[3], x, y, s[6], s[7], s[8], s[9])
            append(s)
        else:
            append(move_stroke(s, m, path, index))
    return out


def _block_vector(m: Motion, px: int, py: int):
    bs16 = 16 * m.block_size
    bx = min(max(px // bs16, 0), m.cols - 1)
    by = min(max(py // bs16, 0), m.rows - 1)
    return m.vectors[by * m.cols + bx]


def move_stroke(s, m: Motion, path="<memory>", index=0):
    def chk(v):
        if abs(v) > MAX_POS:
            raise SptError(f"{path}: frame {index}: motion moves a stroke out of range")
        return v
    k = s[0]
    if k == STAMP:
        dx, dy = _block_vector(m, s[4], s[5])
        if dx == 0 and dy == 0:
            return s
        return s[:4] + (chk(s[4] + dx), chk(s[5] + dy)) + s[6:]
    if k == AFFINE:
        dx, dy = _block_vector(m, s[2], s[3])
        if dx == 0 and dy == 0:
            return s
        return s[:2] + (chk(s[2] + dx), chk(s[3] + dy)) + s[4:]
    if k == POLYGON:
        # Rigidly, by the vector of the block holding the first vertex (SPEC.md 5).
        dx, dy = _block_vector(m, s[6][0][0], s[6][0][1])
        if dx == 0 and dy == 0:
            return s
        return s[:6] + (tuple((chk(x + dx), chk(y + dy)) for (x, y) in s[6]),)
    pts = []
    for (x, y, w) in s[5]:
        dx, dy = _block_vector(m, x, y)
        pts.append((chk(x + dx), chk(y + dy), w))
    return s[:5] + (tuple(pts),) + s[6:]  # a curve's grid N (format 1.4) stays
