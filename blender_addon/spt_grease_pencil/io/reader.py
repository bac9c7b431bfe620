"""Reader of .spt files in stored mode (format/SPEC.md sections 2-6), standard library only.

Range-coded frames (coding 1) are not decoded here on purpose: the add-on runs
`spt pack IN --stored -o TMP` and reads the result, so there is one entropy decoder (libspt).
"""

import struct
from typing import Iterator, List

from . import chunks
from .model import (AFFINE, CURVE, POLYGON, INTER, KEY, MAX_CURVE_WIDTH, MAX_MATRIX, MAX_POS, STAMP,
                    Frame, Header, Limits, Motion, NeedsPack, Roi, SptError, StreamInfo, Template)

_STAMP = struct.Struct("<BBBBiiBBBB")          # kind included: the tuple is the stroke
_AFFINE = struct.Struct("<BBiiiiiiBBBB")
_CURVE_HEAD = struct.Struct("<BBBBBI")
_POLYGON_HEAD = struct.Struct("<BBBBBBI")   # kind, r, g, b, a, grid N, n (format 1.2)
_U32 = struct.Struct("<I")
_HEAD = struct.Struct("<HHIIIIIIB3BBBH")
_FRAM = struct.Struct("<IBBH")


class SptFile:
    """Everything read from a file: stream info, frames as stored, completeness."""

    def __init__(self, path: str, info: StreamInfo, frames: List[Frame], complete: bool, problem: str,
                 curves=None):
        self.path = path
        self.curves = curves        # columnar mode: the curve pool of the StrokeTables
        self.info = info
        self.frames = frames
        self.complete = complete    # False when IEND was missing (recovered frames only)
        self.problem = problem      # why the file is incomplete, "" otherwise

    def live_lists(self, limits: Limits = None) -> Iterator[list]:
        """Yields the live stroke list after each frame (section 5): tuple lists, or StrokeTables
        when the file was read with columnar=True."""
        if self.curves is not None:
            from . import state_np
            return state_np.apply_frames(self.info.header, self.frames, limits or Limits(), self.path, self.curves)
        return apply_frames(self.info.header, self.frames, limits or Limits(), self.path)


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
            if pos + 9 > n:
                raise _err(path, base + pos, "truncated curve stroke")
            _, r, g, b, a, npts = _CURVE_HEAD.unpack_from(body, pos)
            if npts < 1 or npts > limits.max_curve_points:
                raise _err(path, base + pos, f"curve stroke has {npts} points (allowed 1..{limits.max_curve_points})")
            if pos + 9 + 12 * npts > n:
                raise _err(path, base + pos, f"curve stroke of {npts} points runs past the frame body")
            pts = tuple(struct.iter_unpack("<iiI", body[pos + 9:pos + 9 + 12 * npts]))
            for (x, y, w) in pts:
                if abs(x) > MAX_POS or abs(y) > MAX_POS or w > MAX_CURVE_WIDTH:
                    raise _err(path, base + pos, "curve point out of range")
            s = (CURVE, r, g, b, a, pts)
            pos += 9 + 12 * npts
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


def _parse_head(p, path, off, limits) -> Header:
    if len(p) < _HEAD.size:
        raise _err(path, off, f"HEAD payload is {len(p)} bytes, needs at least {_HEAD.size}")
    (vmaj, vmin, flags, w, h, fnum, fden, fcount, cenc, br, bg, bb, nsets, norients, res) = _HEAD.unpack_from(p, 0)
    if vmaj != 1:
        raise _err(path, off, f"format version {vmaj}.{vmin} is not supported (this reader knows 1.x)")
    if flags != 0 or res != 0:
        raise _err(path, off, "reserved HEAD fields are not 0 (unsupported file)")
    if not (1 <= w <= limits.max_width and 1 <= h <= limits.max_height and w * h <= limits.max_pixels):
        raise _err(path, off, f"canvas {w}x{h} is outside the limits")
    if fnum == 0 or fden == 0:
        raise _err(path, off, "frame rate numerator and denominator must be > 0")
    if cenc != 0:
        raise _err(path, off, f"colour encoding {cenc} is not supported")
    if not (1 <= nsets <= 16) or not (1 <= norients <= 64):
        raise _err(path, off, f"{nsets} stroke sets / {norients} orientations (allowed 1..16 / 1..64)")
    need = _HEAD.size + 4 * nsets + 4 * norients
    if len(p) != need:
        raise _err(path, off, f"HEAD payload is {len(p)} bytes, expected {need}")
    sets = list(struct.iter_unpack("<HH", p[_HEAD.size:_HEAD.size + 4 * nsets]))
    for i, (sw, sh) in enumerate(sets):
        if not (1 <= sw <= 4096 and 1 <= sh <= 4096):
            raise _err(path, off, f"stroke set {i} size {sw}x{sh} outside 1..4096")
    orients = list(struct.iter_unpack("<hh", p[_HEAD.size + 4 * nsets:need]))
    for i, (c, s) in enumerate(orients):
        if c * c + s * s > (1 << 28) + (1 << 16):
            raise _err(path, off, f"orientation {i} ({c}, {s}) is longer than unit length")
    return Header(width=w, height=h, fps_num=fnum, fps_den=fden, frame_count=fcount, version_major=vmaj,
                  version_minor=vmin, background=(br, bg, bb), sets=sets, orientations=orients)


def _parse_tmpl(p, path, off, limits) -> Template:
    if len(p) < 7:
        raise _err(path, off, "TMPL payload too short")
    kind, coding, w, h, nlen = struct.unpack_from("<BBHHB", p, 0)
    if 7 + nlen > len(p):
        raise _err(path, off, "TMPL name runs past the chunk")
    name = bytes(p[7:7 + nlen]).decode("utf-8", errors="replace")
    rest = p[7 + nlen:]
    if kind == 0:
        if not (1 <= w <= limits.max_template_side and 1 <= h <= limits.max_template_side):
            raise _err(path, off, f"bitmap template {w}x{h} outside 1..{limits.max_template_side}")
        if coding == 1:
            raise NeedsPack(f"{path}: byte {off}: template is range-coded; run 'spt pack --stored' first")
        if coding != 0:
            raise _err(path, off, f"template coding {coding} is not supported")
        if len(rest) != w * h:
            raise _err(path, off, f"bitmap template holds {len(rest)} samples, expected {w * h}")
        return Template(kind, w, h, bytes(rest), name)
    if kind in (1, 2, 3):
        if coding == 1 or coding > 16:
            raise _err(path, off, f"analytic template with reserved supersampling value {coding}")
        if w != 0 or h != 0 or len(rest) != 0:
            raise _err(path, off, "analytic template with non-zero size or samples")
        return Template(kind, 0, 0, b"", name, coding)
    raise _err(path, off, f"template kind {kind} is not supported")


def _parse_meta(p, path, off):
    out = []
    if len(p) < 4:
        raise _err(path, off, "meta chunk too short")
    (count,) = _U32.unpack_from(p, 0)
    pos = 4
    for _ in range(count):
        vals = []
        for _part in range(2):
            if pos + 4 > len(p):
                raise _err(path, off + 8 + pos, "meta entry runs past the chunk")
            (ln,) = _U32.unpack_from(p, pos)
            if pos + 4 + ln > len(p):
                raise _err(path, off + 8 + pos, "meta entry runs past the chunk")
            vals.append(bytes(p[pos + 4:pos + 4 + ln]).decode("utf-8", errors="replace"))
            pos += 4 + ln
        out.append((vals[0], vals[1]))
    return out


def _parse_rois(p, path, off):
    if len(p) < 4:
        raise _err(path, off, "rois chunk too short")
    (count,) = _U32.unpack_from(p, 0)
    if len(p) != 4 + 24 * count:
        raise _err(path, off, f"rois chunk is {len(p)} bytes, expected {4 + 24 * count}")
    return [Roi(*r) for r in struct.iter_unpack("<IIIIII", p[4:])]


def _parse_frame(p, path, off, info, limits, curves=None) -> Frame:
    """One FRAM chunk. With a curve pool (columnar mode) the strokes become a StrokeTable and
    removals / motion vectors numpy arrays (strokes_np.py); otherwise tuples and lists."""
    if len(p) < _FRAM.size:
        raise _err(path, off, "FRAM payload too short")
    index, ftype, coding, res = _FRAM.unpack_from(p, 0)
    if res != 0:
        raise _err(path, off, "reserved FRAM field is not 0")
    if ftype not in (KEY, INTER):
        raise _err(path, off, f"frame {index}: frame type {ftype} is not supported")
    if coding == 1:
        raise NeedsPack(f"{path}: frame {index} is range-coded; run 'spt pack --stored' first")
    if coding != 0:
        raise _err(path, off, f"frame {index}: coding {coding} is not supported")
    body = p[_FRAM.size:]
    base = off + 8 + _FRAM.size
    n = len(body)
    fr = Frame(index=index, type=ftype)
    pos = 0
    if ftype == INTER:
        if n < 4:
            raise _err(path, base, f"frame {index}: body too short")
        (nrem,) = _U32.unpack_from(body, 0)
        if 4 + 4 * nrem > n:
            raise _err(path, base, f"frame {index}: {nrem} removed indices run past the body")
        if curves is not None:
            import numpy as np
            fr.removed = np.frombuffer(body, dtype="<u4", count=nrem, offset=4).astype(np.int64)
        else:
            fr.removed = list(struct.unpack_from(f"<{nrem}I", body, 4))
        pos = 4 + 4 * nrem
        if pos >= n:
            raise _err(path, base + pos, f"frame {index}: body ends before motion_present")
        present = body[pos]
        pos += 1
        if present == 1:
            if pos + 6 > n:
                raise _err(path, base + pos, f"frame {index}: truncated motion field")
            bs, cols, rows = struct.unpack_from("<HHH", body, pos)
            hdr = info.header
            if not (8 <= bs <= 256) or cols != -(-hdr.width // bs) or rows != -(-hdr.height // bs):
                raise _err(path, base + pos, f"frame {index}: motion field {cols}x{rows} blocks of {bs} px does not fit the canvas")
            pos += 6
            if pos + 4 * cols * rows > n:
                raise _err(path, base + pos, f"frame {index}: motion vectors run past the body")
            if curves is not None:
                import numpy as np
                vec = np.frombuffer(body, dtype="<i2", count=2 * cols * rows, offset=pos).reshape(-1, 2)
                fr.motion = Motion(bs, cols, rows, vec.astype(np.int32))
            else:
                flat = struct.unpack_from(f"<{2 * cols * rows}h", body, pos)
                fr.motion = Motion(bs, cols, rows, list(zip(flat[0::2], flat[1::2])))
            pos += 4 * cols * rows
        elif present != 0:
            raise _err(path, base + pos - 1, f"frame {index}: motion_present is {present}")
    if pos + 4 > n:
        raise _err(path, base + pos, f"frame {index}: body ends before the stroke count")
    (count,) = _U32.unpack_from(body, pos)
    pos += 4
    if count > limits.max_strokes_per_frame or count > (n - pos):  # each record is >= 1 byte
        raise _err(path, base + pos - 4, f"frame {index}: stroke count {count} is impossible for a {n}-byte body")
    if curves is not None:
        from . import strokes_np
        fr.added, pos = strokes_np.parse_records(body, pos, count, path, base, len(info.templates),
                                                 len(info.header.sets), len(info.header.orientations),
                                                 limits.max_curve_points, curves, limits.max_polygon_vertices)
    else:
        fr.added, pos = parse_strokes(body, pos, count, path, base, info, limits)
    if pos != n:
        raise _err(path, base + pos, f"frame {index}: {n - pos} bytes after the last stroke record")
    return fr


def read_bytes(data, path: str = "<memory>", limits: Limits = None, columnar: bool = False) -> SptFile:
    """Reads a stored-mode file. columnar=True (needs numpy) gives StrokeTables instead of tuples:
    the fast path for millions of strokes."""
    limits = limits or Limits()
    curves = [] if columnar else None
    if len(data) < 8 or bytes(data[:8]) != chunks.SIGNATURE:
        raise SptError(f"{path}: byte 0: not a .spt file (bad signature)")
    info = StreamInfo()
    frames: List[Frame] = []
    seen_head = False
    ended = False
    problem = ""
    gen = chunks.scan(data, limits.max_chunk_bytes)
    while True:
        try:
            off, ctype, p = next(gen)
        except StopIteration as stop:
            problem = stop.value or ""
            break
        if ended:
            raise _err(path, off, "data after IEND")
        name = ctype.decode("latin-1")
        if not seen_head and ctype != b"HEAD":
            raise _err(path, off, f"first chunk is {name}, expected HEAD")
        if ctype == b"HEAD":
            if seen_head:
                raise _err(path, off, "second HEAD chunk")
            info.header = _parse_head(p, path, off, limits)
            seen_head = True
        elif ctype == b"TMPL":
            if frames:
                raise _err(path, off, "TMPL after the first FRAM")
            if len(info.templates) >= limits.max_templates:
                raise _err(path, off, "too many templates")
            info.templates.append(_parse_tmpl(p, path, off, limits))
        elif ctype == b"FRAM":
            fr = _parse_frame(p, path, off, info, limits, curves)
            if fr.index != len(frames):
                raise _err(path, off, f"frame index {fr.index}, expected {len(frames)}")
            if fr.index == 0 and fr.type != KEY:
                raise _err(path, off, "the first frame is not a key frame")
            if len(frames) >= limits.max_frames:
                raise _err(path, off, "too many frames")
            frames.append(fr)
        elif ctype == b"IEND":
            if len(p) != 12:
                raise _err(path, off, "IEND payload is not 12 bytes")
            (count,) = _U32.unpack_from(p, 0)
            if count != len(frames):
                raise _err(path, off, f"IEND says {count} frames, the file holds {len(frames)}")
            ended = True
        elif ctype == b"meta":
            info.metadata.extend(_parse_meta(p, path, off))
        elif ctype == b"rois":
            info.rois.extend(_parse_rois(p, path, off))
        elif ctype == b"indx":
            pass  # we scan sequentially; the index is rebuilt on write
        elif chunks.is_critical(ctype):
            raise _err(path, off, f"unknown critical chunk {name} (unsupported file)")
        else:
            info.extra_chunks.append((bytes(ctype), bytes(p)))
    if not seen_head:
        raise SptError(f"{path}: no HEAD chunk ({problem or 'empty file'})")
    if not ended:
        problem = problem or "file ends without IEND"
    return SptFile(path, info, frames, ended, "" if ended else problem, curves)


def read_file(path: str, limits: Limits = None, columnar: bool = False) -> SptFile:
    limits = limits or Limits()
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SptError(f"{path}: cannot read: {e.strerror or e}") from None
    return read_bytes(data, path, limits, columnar)


def is_stored(path: str) -> bool:
    """True when every frame and template of the file is in stored coding (no pack needed)."""
    try:
        read_file(path)
        return True
    except NeedsPack:
        return False




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
    return s[:5] + (tuple(pts),)
