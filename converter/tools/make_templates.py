#!/usr/bin/env python3
"""Generates spt's default stroke templates (python3 standard library only).

Writes the built-in templates as 8-bit grayscale PNGs to converter/templates/ (for users to view,
copy and edit, and to pass back with `spt paint --templates DIR`), textured brushes (60x60) to
converter/templates/brushes/, and converter/src/paint/default_templates_data.cpp, which holds the
built-in samples so that the spt binary needs no file at run time.

The shapes are procedural and seeded, so re-running the script reproduces the same bytes:
    python3 converter/tools/make_templates.py
The template's long axis is u (left to right): stroke sets are wider than tall and the
painter turns u along the edge it follows.
"""
import math
import os
import struct
import sys
import zlib

SIZE = 60


class Lcg:
    """A tiny deterministic generator (no dependence on Python's random module version)."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFFFFFFFFFF

    def next(self):
        self.state = (self.state * 6364136223846793005 + 1442695040888963407) & 0xFFFFFFFFFFFFFFFF
        return (self.state >> 33) / float(1 << 31)


def clamp8(v):
    return max(0, min(255, int(round(v))))


def smoothstep(e0, e1, x):
    if e1 == e0:
        return 1.0 if x >= e1 else 0.0
    t = max(0.0, min(1.0, (x - e0) / (e1 - e0)))
    return t * t * (3 - 2 * t)


def coords(i, j):
    """Pixel (i, j) -> template coordinates (u, v) in [-1, 1], at the pixel centre."""
    return (2.0 * (i + 0.5) / SIZE - 1.0, 2.0 * (j + 0.5) / SIZE - 1.0)


def rectangle():
    return [[255] * SIZE for _ in range(SIZE)]


def soft_round():
    # An ellipse filling the square with a soft falloff over its outer 35%: blends like an
    # airbrush dab, so neighbouring strokes leave no hard seams.
    out = []
    for j in range(SIZE):
        row = []
        for i in range(SIZE):
            u, v = coords(i, j)
            r = math.sqrt(u * u + v * v)
            row.append(clamp8(255 * (1.0 - smoothstep(0.65, 1.0, r))))
        out.append(row)
    return out


def bristle():
    # Parallel hair streaks along u: each bristle row has its own density and length, with
    # tapered ends, as a loaded flat brush leaves.
    rng = Lcg(0x5B7157)
    rows = []
    for _ in range(SIZE):
        rows.append((0.55 + 0.45 * rng.next(), 0.75 + 0.25 * rng.next(), (rng.next() - 0.5) * 0.2))
    out = []
    for j in range(SIZE):
        density, length, shift = rows[j]
        row = []
        for i in range(SIZE):
            u, v = coords(i, j)
            along = 1.0 - smoothstep(length - 0.25, length, abs(u + shift))
            across = 1.0 - smoothstep(0.85, 1.0, abs(v))
            row.append(clamp8(255 * density * along * across))
        out.append(row)
    return out


def dry_brush():
    # A dry brush skips: streaks along u broken by gaps where the paper shows through, more
    # gaps towards the trailing end (u > 0) where the paint runs out.
    rng = Lcg(0xD12B)
    out = [[0] * SIZE for _ in range(SIZE)]
    for j in range(SIZE):
        v = coords(0, j)[1]
        across = 1.0 - smoothstep(0.8, 1.0, abs(v))
        i = 0
        while i < SIZE:
            u = coords(i, j)[0]
            run = 2 + int(rng.next() * 12)
            skip_p = 0.15 + 0.45 * max(0.0, u)
            paint = rng.next() >= skip_p
            level = 0.7 + 0.3 * rng.next()
            for k in range(i, min(SIZE, i + run)):
                uk = coords(k, j)[0]
                along = 1.0 - smoothstep(0.85, 1.0, abs(uk))
                out[j][k] = clamp8(255 * level * along * across) if paint else 0
            i += run
    return out


def ellipse():
    # The unit disc; built in as the analytic ellipse (these samples are only for viewing).
    out = []
    for j in range(SIZE):
        row = []
        for i in range(SIZE):
            u, v = coords(i, j)
            row.append(255 if u * u + v * v <= 1.0 else 0)
        out.append(row)
    return out


# The built-in set, chosen by measurement (bench/rate_templates.sh, converter/src/paint/README.md
# "Templates"): the rectangle and the ellipse are analytic (no samples in the file) and the soft
# round is a 16x16 bitmap; its smooth falloff survives the upscaling and codes in ~170 bytes.
# The textured brushes cost 150-1500 bytes each per file and painted no better per byte, so they
# are written only as PNGs in templates/brushes/ for `spt paint --templates`.
TEMPLATES = [
    ("rectangle", rectangle, 16),
    ("soft-round", soft_round, 16),
    ("ellipse", ellipse, 16),
]
BRUSHES = [
    ("bristle", bristle, 60),
    ("dry-brush", dry_brush, 60),
]


def png_gray8(rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    ihdr = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 8, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


def cpp_source(items):
    lines = [
        "// GENERATED by converter/tools/make_templates.py: do not edit; re-run the script.",
        "// The default stroke templates' samples (8-bit coverage, row-major).",
        '#include "paint/default_templates_data.hpp"',
        "",
        "namespace spt::paint::detail {",
        "",
    ]
    for idx, (name, rows) in enumerate(items):
        flat = [x for r in rows for x in r]
        lines.append("static const unsigned char kSamples%d[%d] = {" % (idx, len(flat)))
        for k in range(0, len(flat), 20):
            lines.append("    " + ", ".join(str(x) for x in flat[k:k + 20]) + ",")
        lines.append("};")
        lines.append("")
    lines.append("const TemplateData kDefaultTemplates[] = {")
    for idx, (name, _) in enumerate(items):
        lines.append('    {"%s", %d, %d, kSamples%d},' % (name, len(items[idx][1][0]), len(items[idx][1]), idx))
    lines.append("};")
    lines.append("const int kDefaultTemplateCount = %d;" % len(items))
    lines.append("")
    lines.append("}  // namespace spt::paint::detail")
    return "\n".join(lines) + "\n"


def main():
    # Options for experiments (bench/rate_templates.sh): --size N draws every template, brushes
    # included, at N x N; --out DIR writes the PNGs and the C++ source to DIR instead of the
    # source tree.
    global SIZE
    args = sys.argv[1:]
    out_dir = None
    size = None
    while args:
        a = args.pop(0)
        if a == "--size" and args:
            size = int(args.pop(0))
        elif a == "--out" and args:
            out_dir = args.pop(0)
        else:
            print("usage: make_templates.py [--size N] [--out DIR]", file=sys.stderr)
            return 2
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    tdir = out_dir or os.path.join(root, "templates")
    os.makedirs(tdir, exist_ok=True)
    def draw(fn, n):
        global SIZE
        SIZE = size or n
        return fn()

    items = []
    for idx, (name, fn, n) in enumerate(TEMPLATES):
        rows = draw(fn, n)
        items.append((name, rows))
        with open(os.path.join(tdir, "%d-%s.png" % (idx, name)), "wb") as f:
            f.write(png_gray8(rows))
    bdir = os.path.join(tdir, "brushes")
    os.makedirs(bdir, exist_ok=True)
    for idx, (name, fn, n) in enumerate(BRUSHES):
        with open(os.path.join(bdir, "%d-%s.png" % (idx, name)), "wb") as f:
            f.write(png_gray8(draw(fn, n)))
    if out_dir:  # experiments: every shape, brushes too, in one folder
        for idx, (name, fn, n) in enumerate(BRUSHES):
            with open(os.path.join(tdir, "%d-%s.png" % (len(TEMPLATES) + idx, name)), "wb") as f:
                f.write(png_gray8(draw(fn, n)))
    out = os.path.join(out_dir or os.path.join(root, "src", "paint"), "default_templates_data.cpp")
    with open(out, "w") as f:
        f.write(cpp_source(items))
    print("wrote %d templates to %s and %s" % (len(items), tdir, out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
