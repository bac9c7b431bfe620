#!/usr/bin/env python3
"""An educational decoder of .spt (format/SPEC.md), written from the specification alone.

    python3 educational_decoder.py [--render] FILE.spt

prints one line per frame, `frame live_strokes live_fnv1a64`, as tests/format/golden/MANIFEST.txt
lists them; with --render it also renders each frame (SPEC.md 8) and adds `render_fnv1a64`, the
FNV-1a 64 of its width * height * 3 RGB values (bytes, or little-endian u16 codes in colour
encoding 1), followed on an alpha canvas by its alpha bytes. It is slow and plain on purpose: Python's standard library only, one function per
section of SPEC.md, no caches. It decodes frame codings 0, 1 and 2. The modules live in
educational_decoder/ next to this script.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from educational_decoder.decoder import decode_frames  # noqa: E402
from educational_decoder.errors import DecodeError  # noqa: E402
from educational_decoder.render import render  # noqa: E402
from educational_decoder.strokes import fnv1a64, live_hash  # noqa: E402


def main(argv):
    args = argv[1:]
    with_render = "--render" in args
    if with_render:
        args.remove("--render")
    if len(args) != 1:
        print("usage: educational_decoder.py [--render] FILE.spt", file=sys.stderr)
        return 2
    path = args[0]
    try:
        with open(path, "rb") as f:
            data = f.read()
        decoded = decode_frames(data)
        for index, live in decoded:
            h = decoded.header
            line = f"{index} {len(live)} {live_hash(live, h.color_encoding == 1, h.curve_grid):016x}"
            if with_render:
                canvas = render(decoded.header, decoded.templates, live)
                line += f" {fnv1a64(canvas.frame_bytes()):016x}"
            print(line, flush=True)
        if decoded.problem:
            print(f"{path}: incomplete: {decoded.problem}", file=sys.stderr)
    except (OSError, DecodeError) as e:
        print(f"{path}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
