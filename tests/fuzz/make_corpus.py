#!/usr/bin/env python3
"""Builds the seed corpora of the fuzz targets from the golden files (tests/format/golden):
whole files for `container`, the harness inputs of `strokes`, `motion` and `template`, plus a
few malformed variants. Run from anywhere; rewrites tests/fuzz/corpus/."""
import os, pathlib, shutil, struct

here = pathlib.Path(__file__).resolve().parent
golden = here.parent / "format" / "golden"
out = here / "corpus"

def chunks(b):
    p = 8
    while p + 12 <= len(b):
        n = struct.unpack_from("<I", b, p)[0]
        yield b[p + 4:p + 8].decode("latin1"), b[p + 8:p + 8 + n]
        p += 12 + n

def varint(b, p):
    v, s = 0, 0
    while True:
        c = b[p]; p += 1
        v |= (c & 0x7F) << s; s += 7
        if not c & 0x80:
            return v, p

def put(target, name, data):
    d = out / target
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(bytes(data))

shutil.rmtree(out, ignore_errors=True)
for f in sorted(golden.glob("*.spt")):
    b = f.read_bytes()
    put("container", f.name, b)
    put("container", f.name + ".cut", b[: len(b) * 2 // 3])
    flipped = bytearray(b); flipped[len(b) // 2] ^= 0x20
    put("container", f.name + ".flip", flipped)
    head = None; ntmpl = 0
    for i, (t, p) in enumerate(chunks(b)):
        if t == "HEAD":
            w, h = struct.unpack_from("<II", p, 8)
            sets, orients = p[32], p[33]
            minor = struct.unpack_from("<H", p, 2)[0]
            curve_grid = bool(struct.unpack_from("<I", p, 4)[0] & 2)
            head = (sets, orients, w, h, minor, p[28] == 1, curve_grid)
        elif t == "TMPL":
            ntmpl += 1
            put("template", f"{f.stem}-{ntmpl}", p)
        elif t == "FRAM" and p[5] == 1 and head:
            sets, orients, w, h, minor, linear, curve_grid = head
            body = p[8:]
            if p[4] == 0:
                # Bit 7 of the first byte: a format 1.2 stream (polygon strokes, SPEC.md 7.4);
                # bit 6: colour encoding 1 (format 1.3, colour low bytes); bit 5: curves with a
                # grid (format 1.4).
                first = (sets - 1) | (0x40 if linear else 0x80 if minor >= 2 else 0) | (0x20 if curve_grid else 0)
                prefix = bytes([first, orients - 1, ntmpl]) + struct.pack("<HH", w - 1, h - 1)
                put("strokes", f"{f.stem}-{i}", prefix + body)
            else:
                removed, q = varint(body, 0)
                _, q = varint(body, q)
                motion = body[q]; q += 1
                block = 0
                if motion:
                    block = struct.unpack_from("<H", body, q)[0]; q += 2
                n, q = varint(body, q)
                prefix = struct.pack("<HHHHBH", w - 1, h - 1, 1000, removed, motion, block)
                put("motion", f"{f.stem}-{i}", prefix + body[q:q + n])
put("container", "empty", b"")
put("container", "signature-only", b"\x89SPT\r\n\x1a\n")
put("strokes", "huge-count", bytes([15, 63, 3, 0xFF, 0x0F, 0xFF, 0x0F, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F]))
put("motion", "huge-run", struct.pack("<HHHHBH", 4095, 4095, 65535, 65535, 1, 8) + b"\xFF" * 16)
put("template", "huge", bytes([0, 1, 0, 4, 0, 4, 0]) + b"\x00" * 8)
