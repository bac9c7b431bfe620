"""Reader of .spt files in stored mode (format/SPEC.md sections 2-6).

Range-coded frames (coding 1) are not decoded here on purpose: the add-on runs
`spt pack IN --stored -o TMP` and reads the result, so there is one entropy decoder (libspt).
Frame contents are decoded by a Decoding: the add-on's is ColumnarDecoding (numpy StrokeTables,
strokes_np.py and state_np.py); tests/blender/reference/ plugs in a one-tuple-per-stroke oracle
through the same container parser.
"""

import struct
from typing import Iterator, List

import numpy as np

from . import chunks, state_np, strokes_np
from .model import (INTER, KEY, LINEAR_HALF, MAX_HALF_CODE, Frame, Header, Limits, Motion, NeedsPack, Roi,
                    SptError, StreamInfo, Template)

_U32 = struct.Struct("<I")
_HEAD = struct.Struct("<HHIIIIIIB3BBBH")
_FRAM = struct.Struct("<IBBH")


class ColumnarDecoding:
    """Frame contents as numpy: removals and motion vectors as arrays, stroke records as one
    StrokeTable per frame over a curve pool shared by the file (strokes_np.py)."""

    def __init__(self):
        self.curves = []

    def removed(self, body, offset: int, count: int):
        return np.frombuffer(body, dtype="<u4", count=count, offset=offset).astype(np.int64)

    def vectors(self, body, offset: int, count: int):
        return np.frombuffer(body, dtype="<i2", count=2 * count, offset=offset).reshape(-1, 2).astype(np.int32)

    def records(self, body, pos: int, count: int, path: str, base: int, info: StreamInfo, limits: Limits):
        return strokes_np.parse_records(body, pos, count, path, base, len(info.templates),
                                        len(info.header.sets), len(info.header.orientations),
                                        limits.max_curve_points, self.curves, limits.max_polygon_vertices,
                                        info.header.linear, info.header.curve_grid)

    def live_lists(self, header: Header, frames: List[Frame], limits: Limits, path: str):
        return state_np.apply_frames(header, frames, limits, path, self.curves)


class SptFile:
    """Everything read from a file: stream info, frames as stored, completeness."""

    def __init__(self, path: str, info: StreamInfo, frames: List[Frame], complete: bool, problem: str,
                 decoding, tuples: bool):
        self.path = path
        self.decoding = decoding
        self.curves = getattr(decoding, "curves", None)   # the curve pool of the StrokeTables
        self.tuples = tuples        # live_lists gives tuple lists (model.py), not StrokeTables
        self.info = info
        self.frames = frames
        self.complete = complete    # False when IEND was missing (recovered frames only)
        self.problem = problem      # why the file is incomplete, "" otherwise

    def live_lists(self, limits: Limits = None) -> Iterator[list]:
        """Yields the live stroke list after each frame (section 5): StrokeTables when the file
        was read with columnar=True, else lists of model.py tuples (small files, tests)."""
        for live in self.decoding.live_lists(self.info.header, self.frames, limits or Limits(), self.path):
            yield live.to_tuples() if self.tuples and hasattr(live, "to_tuples") else live


def _err(path, offset, what):
    return SptError(f"{path}: byte {offset}: {what}")


def _parse_head(p, path, off, limits) -> Header:
    if len(p) < _HEAD.size:
        raise _err(path, off, f"HEAD payload is {len(p)} bytes, needs at least {_HEAD.size}")
    (vmaj, vmin, flags, w, h, fnum, fden, fcount, cenc, br, bg, bb, nsets, norients, res) = _HEAD.unpack_from(p, 0)
    if vmaj != 1:
        raise _err(path, off, f"format version {vmaj}.{vmin} is not supported (this reader knows 1.x)")
    if flags & ~3 or res != 0:
        raise _err(path, off, "reserved HEAD fields are not 0 (unsupported file)")
    alpha = bool(flags & 1)
    curve_grid = bool(flags & 2)   # format 1.4: every curve record carries a grid byte
    if not (1 <= w <= limits.max_width and 1 <= h <= limits.max_height and w * h <= limits.max_pixels):
        raise _err(path, off, f"canvas {w}x{h} is outside the limits")
    if fnum == 0 or fden == 0:
        raise _err(path, off, "frame rate numerator and denominator must be > 0")
    if cenc > LINEAR_HALF:
        raise _err(path, off, f"colour encoding {cenc} is not supported (this reader knows 0, 8-bit sRGB, "
                              "and 1, scene-linear half floats)")
    if (alpha or cenc == LINEAR_HALF) and vmin < 3:
        raise _err(path, off, f"an alpha canvas or colour encoding 1 needs format 1.3, the file says 1.{vmin}")
    if curve_grid and vmin < 4:
        raise _err(path, off, f"anti-aliased curves (HEAD flag curve_grid) need format 1.4, the file says 1.{vmin}")
    if not (1 <= nsets <= 16) or not (1 <= norients <= 64):
        raise _err(path, off, f"{nsets} stroke sets / {norients} orientations (allowed 1..16 / 1..64)")
    need = _HEAD.size + 4 * nsets + 4 * norients
    tail = 4 if cenc == LINEAR_HALF else 0  # background_lo and a reserved byte (SPEC.md 3.1)
    if len(p) != need + tail:
        raise _err(path, off, f"HEAD payload is {len(p)} bytes, expected {need + tail}")
    background_lo = (0, 0, 0)
    if tail:
        background_lo = tuple(p[need:need + 3])
        if p[need + 3] != 0:
            raise _err(path, off, "reserved HEAD byte after background_lo is not 0 (unsupported file)")
        if any(256 * hi + lo > MAX_HALF_CODE for hi, lo in zip((br, bg, bb), background_lo)):
            raise _err(path, off, "background colour code is not a finite half float >= 0 (above 0x7BFF)")
    sets = list(struct.iter_unpack("<HH", p[_HEAD.size:_HEAD.size + 4 * nsets]))
    for i, (sw, sh) in enumerate(sets):
        if not (1 <= sw <= 4096 and 1 <= sh <= 4096):
            raise _err(path, off, f"stroke set {i} size {sw}x{sh} outside 1..4096")
    orients = list(struct.iter_unpack("<hh", p[_HEAD.size + 4 * nsets:need]))
    for i, (c, s) in enumerate(orients):
        if c * c + s * s > (1 << 28) + (1 << 16):
            raise _err(path, off, f"orientation {i} ({c}, {s}) is longer than unit length")
    return Header(width=w, height=h, fps_num=fnum, fps_den=fden, frame_count=fcount, version_major=vmaj,
                  version_minor=vmin, background=(br, bg, bb), sets=sets, orientations=orients,
                  alpha=alpha, color_encoding=cenc, background_lo=background_lo, curve_grid=curve_grid)


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


def _parse_frame(p, path, off, info, limits, decoding) -> Frame:
    """One FRAM chunk; its contents as the decoding makes them."""
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
        fr.removed = decoding.removed(body, 4, nrem)
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
            fr.motion = Motion(bs, cols, rows, decoding.vectors(body, pos, cols * rows))
            pos += 4 * cols * rows
        elif present != 0:
            raise _err(path, base + pos - 1, f"frame {index}: motion_present is {present}")
    if pos + 4 > n:
        raise _err(path, base + pos, f"frame {index}: body ends before the stroke count")
    (count,) = _U32.unpack_from(body, pos)
    pos += 4
    if count > limits.max_strokes_per_frame or count > (n - pos):  # each record is >= 1 byte
        raise _err(path, base + pos - 4, f"frame {index}: stroke count {count} is impossible for a {n}-byte body")
    fr.added, pos = decoding.records(body, pos, count, path, base, info, limits)
    if pos != n:
        raise _err(path, base + pos, f"frame {index}: {n - pos} bytes after the last stroke record")
    return fr


def read_bytes(data, path: str = "<memory>", limits: Limits = None, columnar: bool = False,
               decoding=None) -> SptFile:
    """Reads a stored-mode file. live_lists() gives StrokeTables with columnar=True (millions of
    strokes), tuple lists otherwise; decoding (default ColumnarDecoding) decodes frame contents."""
    limits = limits or Limits()
    decoding = decoding or ColumnarDecoding()
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
            fr = _parse_frame(p, path, off, info, limits, decoding)
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
    return SptFile(path, info, frames, ended, "" if ended else problem, decoding, not columnar)


def read_file(path: str, limits: Limits = None, columnar: bool = False, decoding=None) -> SptFile:
    limits = limits or Limits()
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SptError(f"{path}: cannot read: {e.strerror or e}") from None
    return read_bytes(data, path, limits, columnar, decoding)


def is_stored(path: str) -> bool:
    """True when every frame and template of the file is in stored coding (no pack needed)."""
    try:
        read_file(path)
        return True
    except NeedsPack:
        return False
