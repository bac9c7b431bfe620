#!/usr/bin/python3
"""Compositing-grade output (issue 17): the scene-linear / alpha encodings against bitmaps and
against the 8-bit sRGB encoding of the same painting.

    bench/color_bench.py BUILD [--media DIR] [--runs N] [--out DIR]

For each source (orbit frame 1, earth frame 1, GoldenGate, StillLife) it paints twice with the
same seed: `--color-encoding linear` (alpha follows the source) and `--color-encoding srgb8`
(same alpha; and once more with `--coding 1`, the coding linear files use, so that the cost of
the encoding itself shows apart from coding 2's), renders them to half-float EXR, and prints
- sizes: the .spt against the painted frame as EXR (PIZ, DWAA), as 16-bit PNG (sRGB view,
  straight alpha) and against the 8-bit encoding's .spt;
- error against the source: RMS in stops (log2 of straight linear colour where the source's and
  the painting's alpha are both >= 0.5, values below 2^-10 counted as 2^-10), PSNR in sRGB after the view transform (clipped, over
  black), and the alpha's mean absolute error overall, inside the matte (source alpha >= 0.5) and
  outside it;
- time: paint and render (medians of N runs, the two encodings interleaved).
Needs python3-openimageio and numpy (setup.sh test installs both) and oiiotool.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
import OpenImageIO as oiio


def read(path):
    buf = oiio.ImageBuf(path)
    spec = buf.spec()
    px = buf.get_pixels(oiio.FLOAT).reshape(spec.height, spec.width, spec.nchannels)
    if spec.nchannels == 3:
        px = np.concatenate([px, np.ones(px.shape[:2] + (1,), np.float32)], axis=2)
    return np.nan_to_num(px[..., :4], nan=0.0, posinf=65504.0).clip(0, None)


def srgb_view(lin):
    x = np.clip(lin, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def errors(src, out):
    """src, out: premultiplied linear RGBA."""
    a_s, a_o = src[..., 3], out[..., 3]
    eps = 2.0 ** -10
    straight = lambda p: p[..., :3] / np.maximum(p[..., 3:4], 1e-6)
    inside = (a_s >= 0.5) & (a_o >= 0.5)  # colour is defined where both are mostly opaque
    ls = np.log2(np.maximum(straight(src), eps))[inside]
    lo = np.log2(np.maximum(straight(out), eps))[inside]
    stops = float(np.sqrt(np.mean((ls - lo) ** 2))) if ls.size else 0.0
    mse = np.mean((srgb_view(src[..., :3]) - srgb_view(out[..., :3])) ** 2)
    psnr = 99.0 if mse == 0 else float(10 * np.log10(1.0 / mse))
    matte = a_s >= 0.5
    mae = lambda m: float(np.mean(np.abs(a_s - a_o)[m])) if m.any() else 0.0
    return stops, psnr, mae(np.ones_like(matte)), mae(matte), mae(~matte)


def run(cmd):
    t = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    return time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--media", default=os.path.join(os.path.dirname(__file__), "..", "..", "shared", "media"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--out", default=None, help="keep the outputs here (default: a temporary folder)")
    ap.add_argument("--paint-args", default="--seed 1", help="extra spt paint options")
    args = ap.parse_args()
    spt = os.path.join(args.build, "bin", "spt")
    exr = os.path.join(args.media, "exr")
    sources = [("orbit.0001", os.path.join(exr, "orbit", "orbit.0001.exr")),
               ("earth.0001", os.path.join(exr, "earth", "earth.0001.exr")),
               ("GoldenGate", os.path.join(exr, "GoldenGate.exr")),
               ("StillLife", os.path.join(exr, "StillLife.exr"))]
    out = args.out or tempfile.mkdtemp(prefix="spt_color_bench_")
    os.makedirs(out, exist_ok=True)
    extra = args.paint_args.split()
    print(f"# bench/color_bench.py {args.build} --runs {args.runs} --paint-args '{args.paint_args}'")
    print("| source | encoding | .spt bytes | EXR PIZ | EXR DWAA | PNG 16 | vs srgb8 .spt | "
          "log RMS (stops) | sRGB PSNR | alpha MAE all / in / out | paint s | render s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, path in sources:
        src = read(path)
        variants = {"linear": ["--color-encoding", "linear"], "srgb8": ["--color-encoding", "srgb8"],
                    "srgb8-c1": ["--color-encoding", "srgb8", "--coding", "1"]}
        times = {enc: ([], []) for enc in variants}
        for _ in range(args.runs):
            for enc, opts in variants.items():
                spt_file = os.path.join(out, f"{name}.{enc}.spt")
                times[enc][0].append(run([spt, "paint", path, "-o", spt_file, "--progress", "none"] + opts + extra))
                times[enc][1].append(run([spt, "render", spt_file, "-o", os.path.join(out, f"{name}.{enc}.exr")]))
        sizes = {enc: os.path.getsize(os.path.join(out, f"{name}.{enc}.spt")) for enc in times}
        for enc in variants:
            rendered = os.path.join(out, f"{name}.{enc}.exr")
            piz, dwaa, png = (os.path.join(out, f"{name}.{enc}.{s}") for s in ("piz.exr", "dwaa.exr", "16.png"))
            subprocess.run(["oiiotool", rendered, "--compression", "piz", "-d", "half", "-o", piz], check=True)
            subprocess.run(["oiiotool", rendered, "--compression", "dwaa", "-d", "half", "-o", dwaa], check=True)
            subprocess.run(["oiiotool", rendered, "--unpremult", "--colorconvert", "linear", "sRGB",
                            "-d", "uint16", "-o", png], check=True)
            stops, psnr, a_all, a_in, a_out = errors(src, read(rendered))
            print(f"| {name} | {enc} | {sizes[enc]} | {os.path.getsize(piz)} | {os.path.getsize(dwaa)} | "
                  f"{os.path.getsize(png)} | {sizes[enc] / sizes['srgb8']:.2f} | {stops:.3f} | {psnr:.2f} | "
                  f"{a_all:.4f} / {a_in:.4f} / {a_out:.4f} | {statistics.median(times[enc][0]):.2f} | "
                  f"{statistics.median(times[enc][1]):.3f} |")
        sys.stdout.flush()
    print(f"# outputs in {out}")


if __name__ == "__main__":
    main()
