#!/usr/bin/python3
"""Alpha and highlights over a shot (issue 34): paints an RGBA scene-linear EXR sequence with the
defaults, renders it back to EXR and prints, per frame, what a compositor sees (python3 with
numpy and OpenImageIO's bindings).

usage: /usr/bin/python3 bench/alpha_hold.py [--spt build/bin/spt] [--seq ../shared/media/exr/orbit]
                                            [--out /tmp/spt-alpha-hold] [--frames N] [--check]
                                            [--max-clear 1] [--max-da 0.02] [--min-hi 75]
                                            [-- extra paint options]

Per frame: clear = mean painted alpha over the pixels the source has clear (alpha < 1/255),
as a percentage (goal <= 1%); |da| = mean |painted alpha - source alpha| over the frame (goal
<= 0.02); hi = mean painted value / mean source value over the pixels whose source exceeds 2.0
in some channel (goal >= 75%); PSNR of the 8-bit proxy as `spt compare` would not see it.
The last line: the worst frame of each, and whether every frame holds.
"""

import argparse
import glob
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio


def read(path):
    buf = oiio.ImageBuf(path)
    px = buf.get_pixels(oiio.FLOAT)
    spec = buf.spec()
    names = list(spec.channelnames)
    a = px[:, :, names.index("A")] if "A" in names else np.ones(px.shape[:2], np.float32)
    return px[:, :, :3], a


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--spt", default=os.path.join(root, "build", "bin", "spt"))
    ap.add_argument("--seq", default=os.path.join(root, "..", "shared", "media", "exr", "orbit"))
    ap.add_argument("--out", default="/tmp/spt-alpha-hold")
    ap.add_argument("--frames", type=int, default=0)
    ap.add_argument("--check", action="store_true", help="exit 1 unless every frame holds the goals below")
    ap.add_argument("--max-clear", type=float, default=1.0, help="percent (issue 34: 1)")
    ap.add_argument("--max-da", type=float, default=0.02, help="(issue 34: 0.02)")
    ap.add_argument("--min-hi", type=float, default=75.0, help="percent (issue 34: 75; 0: not checked)")
    ap.add_argument("extra", nargs="*")
    args = ap.parse_args()
    src = sorted(glob.glob(os.path.join(args.seq, "*.exr")))
    if not src:
        sys.exit(f"alpha_hold: no EXR frames in {args.seq}")
    if args.frames:
        src = src[:args.frames]
    os.makedirs(args.out, exist_ok=True)
    stem = os.path.basename(src[0]).split(".")[0]
    pattern = os.path.join(args.seq, stem + ".####.exr")
    first = int(os.path.basename(src[0]).split(".")[1])
    frames = f"{first}-{first + len(src) - 1}"
    out = os.path.join(args.out, stem + ".spt")
    subprocess.run([args.spt, "paint", pattern, "-o", out, "--seed", "1", "--frames", frames, "--progress", "none"]
                   + args.extra, check=True)
    rdir = os.path.join(args.out, "render")
    os.makedirs(rdir, exist_ok=True)
    subprocess.run([args.spt, "render", out, "-o", os.path.join(rdir, "f.####.exr")], check=True)
    rendered = sorted(glob.glob(os.path.join(rdir, "f.*.exr")))
    print(f"alpha_hold: {pattern} frames {frames}, {os.path.getsize(out)} bytes")
    print(f"{'frame':>5} {'clear%':>7} {'|da|':>6} {'hi%':>6}")
    worst = [0.0, 0.0, 100.0]
    for i, (s, r) in enumerate(zip(src, rendered)):
        sc, sa = read(s)
        pc, pa = read(r)
        clear = sa < 1.0 / 255
        c = 100 * float(pa[clear].mean()) if clear.any() else 0.0
        da = float(np.abs(pa - sa).mean())
        hot = (sc > 2.0).any(axis=2)
        hi = 100 * float(pc[hot].mean() / sc[hot].mean()) if hot.any() else float("nan")
        print(f"{i:>5} {c:>7.2f} {da:>6.3f} {hi:>6.1f}")
        worst = [max(worst[0], c), max(worst[1], da), min(worst[2], hi) if hot.any() else worst[2]]
    ok = worst[0] <= args.max_clear and worst[1] <= args.max_da and worst[2] >= args.min_hi
    print(f"worst: clear {worst[0]:.2f}% (<= {args.max_clear:g}), |da| {worst[1]:.3f} (<= {args.max_da:g}), "
          f"highlights {worst[2]:.1f}% (>= {args.min_hi:g}): {'holds' if ok else 'does not hold'}")
    if args.check and not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()
