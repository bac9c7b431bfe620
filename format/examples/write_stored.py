#!/usr/bin/env python3
"""A complete .spt writer in under 100 lines: the stored mode of format/SPEC.md (coding 0).

It shows what a painter in any language needs to write .spt: chunks with CRC-32, a HEAD, one
analytic template, key frames of stamp strokes, the index and IEND. `spt pack` then re-codes
the file with the range coder, `spt render` renders it, and educational_decoder.py (next to
this script, written from the spec alone) reads it back.

    python3 write_stored.py out.spt [frames]
"""
import math
import random
import struct
import sys
import zlib


def chunk(ctype: bytes, payload: bytes) -> bytes:
    # SPEC 2: u32 length, 4-byte type, payload, CRC-32 over type and payload.
    return struct.pack("<I", len(payload)) + ctype + payload + struct.pack("<I", zlib.crc32(ctype + payload))


def head(width, height, fps, frames, background, sets, orientations):
    p = struct.pack("<HHIIIIII", 1, 0, 0, width, height, fps, 1, frames)
    p += struct.pack("<B3BBBH", 0, *background, len(sets), len(orientations), 0)
    for w, h in sets:
        p += struct.pack("<HH", w, h)
    for c, s in orientations:
        p += struct.pack("<hh", c, s)
    return chunk(b"HEAD", p)


def template_ellipse(name=b"round"):
    # SPEC 3.2: kind 1 (ellipse), coding 0, width 0, height 0, name.
    return chunk(b"TMPL", struct.pack("<BBHHB", 1, 0, 0, 0, len(name)) + name)


def stamp(set_, tmpl, orient, px, py, rgba):
    # SPEC 6: u8 kind 0, u8 set, u8 template, u8 orient, i32 x, i32 y (Q4), u8 r, g, b, a.
    # Q4 position 16*p + 8 is the centre of pixel p.
    return struct.pack("<BBBBii4B", 0, set_, tmpl, orient, 16 * px + 8, 16 * py + 8, *rgba)


def key_frame(index, strokes):
    body = struct.pack("<I", len(strokes)) + b"".join(strokes)
    # SPEC 3.5: u32 frame_index, u8 frame_type (0 key), u8 coding (0 stored), u16 reserved.
    return chunk(b"FRAM", struct.pack("<IBBH", index, 0, 0, 0) + body)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "example.spt"
    frames = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    width, height = 160, 120
    sets = [(40, 16), (20, 8), (8, 4)]
    # The default orientation table (SPEC 3.1): k*pi/8 in Q14, computed once by the writer.
    orients = [(round(16384 * math.cos(k * math.pi / 8)), round(16384 * math.sin(k * math.pi / 8)))
               for k in range(8)]
    rng = random.Random(7)
    data = b"\x89SPT\r\n\x1a\n"
    data += head(width, height, 24, frames, (250, 245, 235), sets, orients)
    data += template_ellipse()
    index = []
    for f in range(frames):
        strokes = []
        for s, (w, h) in enumerate(sets):
            for _ in range(30 * (s + 1)):
                x, y = rng.randrange(width), rng.randrange(height)
                r = (x * 255 // width + 40 * f) % 256
                strokes.append(stamp(s, 0, rng.randrange(8), x, y, (r, y * 255 // height, 128, 255)))
        index.append((f, len(data)))
        data += key_frame(f, strokes)
    # SPEC 3.6: u32 count, then u32 frame_index, u8 frame_type, u8 0, u16 0, u64 offset.
    indx = struct.pack("<I", len(index)) + b"".join(struct.pack("<IBBHQ", f, 0, 0, 0, off) for f, off in index)
    index_offset = len(data)
    data += chunk(b"indx", indx)
    data += chunk(b"IEND", struct.pack("<IQ", frames, index_offset))  # SPEC 3.7
    with open(out, "wb") as fh:
        fh.write(data)
    print(f"wrote {out}: {frames} frames, {len(data)} bytes")


if __name__ == "__main__":
    main()
