"""Writer of .spt files in stored mode (coding 0).

The output goes to a temporary file beside the target and is renamed into place at the end, so
a failure never leaves a half-written file."""

import os
import struct
import tempfile
from typing import Iterable, List

from . import chunks, state_np, strokes_np
from .model import INTER, KEY, LINEAR_HALF, MAX_HALF_CODE, POLYGON, SRGB8, Frame, SptError, StreamInfo
from .strokes_np import StrokeTable

def head_payload(info: StreamInfo, frame_count: int, minor: int = 0) -> bytes:
    """HEAD; `minor` is the format's minor version: 2 when a frame holds a polygon, 3 for an
    alpha canvas or colour encoding 1, 4 for the curve_grid flag (SPEC.md 11)."""
    h = info.header
    if h.color_encoding not in (SRGB8, LINEAR_HALF):
        raise SptError(f"colour encoding {h.color_encoding} cannot be written (0 sRGB or 1 linear half)")
    top = MAX_HALF_CODE if h.linear else 255
    if not all(0 <= c <= top for c in h.background_values()):
        raise SptError(f"background {h.background_values()} is not a colour of encoding {h.color_encoding}")
    if not h.linear and any(h.background_lo):
        raise SptError("background low bytes are set in colour encoding 0")
    flags = (1 if h.alpha else 0) | (2 if h.curve_grid else 0)
    p = struct.pack("<HHIIIIIIB3BBBH", 1, minor, flags, h.width, h.height, h.fps_num, h.fps_den,
                    frame_count, h.color_encoding, *h.background, len(h.sets), len(h.orientations), 0)
    p += b"".join(struct.pack("<HH", w, hh) for (w, hh) in h.sets)
    p += b"".join(struct.pack("<hh", c, s) for (c, s) in h.orientations)
    if h.linear:
        p += struct.pack("<3BB", *h.background_lo, 0)
    return p


def tmpl_payload(t) -> bytes:
    name = t.name.encode("utf-8")[:255]
    if t.kind == 0:
        if len(t.pixels) != t.width * t.height:
            raise SptError(f"template '{t.name}': {len(t.pixels)} samples for {t.width}x{t.height}")
        return struct.pack("<BBHHB", 0, 0, t.width, t.height, len(name)) + name + bytes(t.pixels)
    ss = getattr(t, "supersample", 0)
    if ss == 1 or ss > 16:
        raise SptError(f"template '{t.name}': supersampling {ss} is not 0 or 2..16")
    return struct.pack("<BBHHB", t.kind, ss, 0, 0, len(name)) + name


def meta_payload(items) -> bytes:
    out = [struct.pack("<I", len(items))]
    for k, v in items:
        kb, vb = k.encode("utf-8"), v.encode("utf-8")
        out.append(struct.pack("<I", len(kb)) + kb + struct.pack("<I", len(vb)) + vb)
    return b"".join(out)


def _added_bytes(added, linear: bool, curve_grid: bool) -> bytes:
    # A StrokeTable (strokes_np.py) packs itself; a list of model.py tuples becomes one first.
    if not hasattr(added, "record_bytes"):
        added = StrokeTable.from_tuples(list(added))
    return added.record_bytes(linear, curve_grid)


def frame_payload(fr: Frame, linear: bool = False, curve_grid: bool = False) -> bytes:
    """A stored FRAM payload; `linear`: colour encoding 1 (colours are 16-bit codes);
    `curve_grid`: the format 1.4 HEAD flag (curve records carry their grid N)."""
    head = struct.pack("<IBBH", fr.index, fr.type, 0, 0)
    if fr.type == KEY:
        return head + struct.pack("<I", len(fr.added)) + _added_bytes(fr.added, linear, curve_grid)
    nrem = len(fr.removed)
    if hasattr(fr.removed, "astype"):  # numpy array
        rem = fr.removed.astype("<u4").tobytes()
    else:
        rem = struct.pack(f"<{nrem}I", *fr.removed)
    body = [head, struct.pack("<I", nrem), rem]
    if fr.motion is None:
        body.append(b"\x00")
    else:
        m = fr.motion
        body.append(struct.pack("<BHHH", 1, m.block_size, m.cols, m.rows))
        if hasattr(m.vectors, "astype"):
            body.append(m.vectors.astype("<i2").tobytes())
        else:
            body.append(struct.pack(f"<{2 * len(m.vectors)}h", *[c for v in m.vectors for c in v]))
    body.append(struct.pack("<I", len(fr.added)))
    body.append(_added_bytes(fr.added, linear, curve_grid))
    return b"".join(body)


def _has_polygon(added) -> bool:
    if hasattr(added, "rows"):  # a StrokeTable (columnar mode): KIND is column 0
        return bool((added.rows[:, 0] == POLYGON).any())
    return any(st[0] == POLYGON for st in added)


def write_stored(path: str, info: StreamInfo, frames: List[Frame]) -> int:
    """Writes a complete stored-mode file (HEAD, TMPL*, meta, rois, FRAM*, indx, IEND).
    Returns the number of bytes written. A curve with a grid N other than 0 needs the header's
    curve_grid (the exporter sets it); the file is then format 1.4."""
    h = info.header
    minor = 4 if h.curve_grid else 3 if (h.alpha or h.linear) else \
        2 if any(_has_polygon(f.added) for f in frames) else 0
    try:
        head = head_payload(info, len(frames), minor)
    except SptError as e:
        raise SptError(f"{path}: {e}") from None
    parts = [chunks.SIGNATURE, chunks.chunk_bytes(b"HEAD", head)]
    for t in info.templates:
        parts.append(chunks.chunk_bytes(b"TMPL", tmpl_payload(t)))
    if info.metadata:
        parts.append(chunks.chunk_bytes(b"meta", meta_payload(info.metadata)))
    if info.rois:
        parts.append(chunks.chunk_bytes(b"rois", struct.pack("<I", len(info.rois)) + b"".join(
            struct.pack("<IIIIII", r.first_frame, r.last_frame, r.x, r.y, r.w, r.h) for r in info.rois)))
    for ctype, payload in info.extra_chunks:
        parts.append(chunks.chunk_bytes(ctype, payload))
    offset = sum(len(p) for p in parts)
    index = []
    for fr in frames:
        try:
            payload = frame_payload(fr, h.linear, h.curve_grid)
        except SptError as e:
            raise SptError(f"{path}: frame {fr.index}: {e}") from None
        c = chunks.chunk_bytes(b"FRAM", payload)
        index.append(struct.pack("<IBBHQ", fr.index, fr.type, 0, 0, offset))
        parts.append(c)
        offset += len(c)
    index_offset = offset
    indx = chunks.chunk_bytes(b"indx", struct.pack("<I", len(frames)) + b"".join(index))
    parts.append(indx)
    parts.append(chunks.chunk_bytes(b"IEND", struct.pack("<IQ", len(frames), index_offset)))
    data = b"".join(parts)
    atomic_write(path, data)
    return len(data)


def atomic_write(path: str, data: bytes) -> None:
    folder = os.path.dirname(os.path.abspath(path))
    try:
        fd, tmp = tempfile.mkstemp(prefix=".spt-", suffix=".part", dir=folder)
    except OSError as e:
        raise SptError(f"{path}: cannot write: {e.strerror or e}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise SptError(f"{path}: cannot write: {e.strerror or e}") from None


def frames_from_lists(live_lists: Iterable[list]) -> List[Frame]:
    """Codes a sequence of live lists (model.py tuples) as key and inter frames without motion
    (section 5), through the same coder as the exporter (state_np.frames_from_tables)."""
    tables, curves = strokes_np.tables_from_lists(live_lists)
    return state_np.frames_from_tables(tables, curves)
