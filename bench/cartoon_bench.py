#!/usr/bin/env python3
"""Cartoon bench: `spt paint --style cartoon` against the default painter and x265 on flat-colour
frames (python3 standard library, ffmpeg with libx265).

usage: python3 bench/cartoon_bench.py [--spt build/bin/spt] [--media ../shared/media]
                                      [--target 36] [--threads 2] [--out /tmp/spt-cartoon-bench]

Per frame (star f.0030, taffy f.0030, butterfly-cartoon frame 40; RGBA frames flattened over
white): bytes, PSNR and SSIM against the source (spt compare) and painting time for
--style cartoon and the default painter at --target-psnr TARGET, and for x265 (-preset slow,
one intra frame, yuv420p and yuv444p) at the CRF whose PSNR is closest to the cartoon's from
above (CRF searched by bisection, decoded to RGB by ffmpeg). Stills only: the cartoon painter
does not code sequences yet, so x265 is given single frames too.
"""
import argparse
import json
import os
import re
import subprocess
import time


def run(cmd):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def compare(spt, a, b):
    r = run([spt, "compare", a, b, "--json"])
    d = json.loads(r.stdout)
    return d.get("psnr") or 99.0, d.get("ssim")


def flatten(src, dst):
    run(["ffmpeg", "-loglevel", "error", "-y", "-i", src, "-filter_complex",
         "color=white,format=rgb24[b];[b][0]scale2ref[b][f];[b][f]overlay=format=auto:shortest=1,format=rgb24",
         "-frames:v", "1", dst])


def paint(spt, src, out, extra, threads):
    t0 = time.time()
    r = run([spt, "paint", src, "-o", out + ".spt", "--threads", str(threads), "--preview", out + ".png",
             "--progress", "none"] + extra)
    secs = time.time() - t0
    if r.returncode:
        raise SystemExit(r.stderr)
    return os.path.getsize(out + ".spt"), secs


def x265(src, out, crf, pix):
    run(["ffmpeg", "-loglevel", "error", "-y", "-i", src, "-c:v", "libx265", "-preset", "slow", "-crf", str(crf),
         "-pix_fmt", pix, "-x265-params", "log-level=error", out + ".mkv"])
    run(["ffmpeg", "-loglevel", "error", "-y", "-i", out + ".mkv", "-pix_fmt", "rgb24", out + ".png"])
    # The stream alone (no container overhead) would be smaller still: quote the file.
    return os.path.getsize(out + ".mkv")


def x265_at(spt, src, out, psnr, pix):
    lo, hi, best = 0.0, 51.0, None
    for _ in range(8):
        crf = (lo + hi) / 2
        b = x265(src, out, round(crf, 2), pix)
        p, s = compare(spt, out + ".png", src)
        if p >= psnr:
            best = (b, p, s, round(crf, 2))
            lo = crf
        else:
            hi = crf
    if best is None:
        b = x265(src, out, 0, pix)
        p, s = compare(spt, out + ".png", src)
        best = (b, p, s, 0)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spt", default="build/bin/spt")
    ap.add_argument("--media", default="../shared/media")
    ap.add_argument("--target", type=float, default=36)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="/tmp/spt-cartoon-bench")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    frames = []
    for clip in ("star", "taffy"):
        dst = os.path.join(a.out, clip + "-f30.png")
        flatten(os.path.join(a.media, "cartoon", clip, "f.0030.png"), dst)
        frames.append((clip + " f30", dst))
    bf = os.path.join(a.out, "butterfly-f40.png")
    run(["ffmpeg", "-loglevel", "error", "-y", "-i", os.path.join(a.media, "video", "butterfly-cartoon.avi"),
         "-vf", "select=eq(n\\,40)", "-frames:v", "1", "-pix_fmt", "rgb24", bf])
    frames.append(("butterfly f40", bf))
    print(f"target {a.target} dB; bytes / PSNR dB / SSIM / seconds per frame")
    print(f"{'frame':14} {'coder':22} {'bytes':>8} {'PSNR':>7} {'SSIM':>7} {'s':>6}")
    for label, src in frames:
        base = os.path.join(a.out, re.sub(r"\W", "_", label))
        rows = []
        b, t = paint(a.spt, src, base + "-cartoon", ["--style", "cartoon", "--target-psnr", str(a.target)], a.threads)
        cp, cs = compare(a.spt, base + "-cartoon.png", src)
        rows.append(("spt --style cartoon", b, cp, cs, t))
        b, t = paint(a.spt, src, base + "-default", ["--target-psnr", str(a.target)], a.threads)
        p, s = compare(a.spt, base + "-default.png", src)
        rows.append(("spt default painter", b, p, s, t))
        for pix in ("yuv420p", "yuv444p"):
            b, p, s, crf = x265_at(a.spt, src, base + "-" + pix, cp, pix)
            rows.append((f"x265 {pix} crf {crf}", b, p, s, None))
        for name, b, p, s, t in rows:
            ts = f"{t:6.2f}" if t is not None else "     -"
            print(f"{label:14} {name:22} {b:8d} {p:7.2f} {s:7.4f} {ts}", flush=True)


if __name__ == "__main__":
    main()
