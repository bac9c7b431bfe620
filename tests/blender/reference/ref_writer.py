"""The reference (oracle) of the add-on's record packing and frame coding: one Python tuple per
stroke (model.py), standard library only. test_io.py checks that the add-on's vectorised versions
(strokes_np.records_bytes, state_np.frames_from_tables) give the same bytes and frames."""

import struct
from typing import Iterable, List

from spt_grease_pencil.io.model import AFFINE, CURVE, INTER, KEY, POLYGON, STAMP, Frame, SptError

_STAMP = struct.Struct("<BBBBiiBBBB")
_AFFINE = struct.Struct("<BBiiiiiiBBBB")


def _split(s, at):
    """The tuple with the codes r, g, b at `at` split as a colour encoding 1 record stores them:
    high bytes, a, low bytes."""
    r, g, b, a = s[at:at + 4]
    return s[:at] + (r >> 8, g >> 8, b >> 8, a, r & 255, g & 255, b & 255) + s[at + 4:]


def _curve_grid(s):
    """A curve tuple's grid N (model.py: it trails the points when it is not 0)."""
    return s[6] if len(s) > 6 else 0


def strokes_bytes(strokes: Iterable, linear: bool = False, curve_grid: bool = False) -> bytes:
    """The records of `strokes`; with `curve_grid` (the format 1.4 HEAD flag) a curve's grid N
    follows its colour, without it a curve with a grid cannot be written."""
    for s in strokes:
        if s[0] == CURVE and _curve_grid(s) and not curve_grid:
            raise SptError(f"curve with grid {_curve_grid(s)} in a file without the curve_grid flag")
    if linear:
        return b"".join(_linear_record(s, curve_grid) for s in strokes)
    out = []
    append = out.append
    sp, ap = _STAMP.pack, _AFFINE.pack
    for s in strokes:
        k = s[0]
        if k == STAMP:
            append(sp(*s))
        elif k == AFFINE:
            append(ap(*s))
        elif k == CURVE:
            pts = s[5]
            grid = (_curve_grid(s),) if curve_grid else ()
            append(struct.pack("<BBBBB" + "B" * len(grid) + "I", CURVE, s[1], s[2], s[3], s[4], *grid, len(pts)))
            append(b"".join(struct.pack("<iiI", *p) for p in pts))
        elif k == POLYGON:
            pts = s[6]
            append(struct.pack("<BBBBBBI", POLYGON, s[1], s[2], s[3], s[4], s[5], len(pts)))
            append(b"".join(struct.pack("<ii", *p) for p in pts))
        else:
            raise SptError(f"unknown stroke kind {k}")
    return b"".join(out)



def _linear_record(s, curve_grid) -> bytes:
    k = s[0]
    if k == STAMP:
        return struct.pack("<BBBBiiBBBBBBB", *_split(s, 6))
    if k == AFFINE:
        return struct.pack("<BBiiiiiiBBBBBBB", *_split(s, 8))
    if k == CURVE:
        t = _split(s, 1)
        grid = (_curve_grid(s),) if curve_grid else ()
        return struct.pack("<BBBBBBBB" + "B" * len(grid) + "I", *t[:8], *grid, len(s[5])) + \
            b"".join(struct.pack("<iiI", *p) for p in s[5])
    if k == POLYGON:
        t = _split(s, 1)
        return struct.pack("<BBBBBBBBBI", *t[:8], s[5], len(s[6])) + b"".join(struct.pack("<ii", *p) for p in s[6])
    raise SptError(f"unknown stroke kind {k}")


def frames_from_lists(live_lists: Iterable[list]) -> List[Frame]:
    """Codes a sequence of live lists as key and inter frames (section 5, without motion).

    An inter frame keeps the longest prefix of the new list that is a subsequence of the previous
    one (greedy earliest matching is optimal for that), removes the rest and appends the tail. A
    key frame is used when that would not be smaller."""
    frames: List[Frame] = []
    prev = None
    for i, cur in enumerate(live_lists):
        cur = list(cur)
        if prev is None:
            frames.append(Frame(index=i, type=KEY, added=cur))
        else:
            kept = []   # indices into prev of strokes kept, in order
            j = 0
            n = len(prev)
            for s in cur:
                while j < n and prev[j] != s:
                    j += 1
                if j == n:
                    break
                kept.append(j)
                j += 1
            keptset = set(kept)
            removed = [k for k in range(n) if k not in keptset]
            added = cur[len(kept):]
            # Stored sizes: a removal costs 4 bytes, a record at least 16; key re-sends all.
            if 4 * len(removed) + 16 * len(added) < 16 * len(cur):
                frames.append(Frame(index=i, type=INTER, removed=removed, added=added))
            else:
                frames.append(Frame(index=i, type=KEY, added=cur))
        prev = cur
    return frames
