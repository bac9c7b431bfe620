#!/usr/bin/env python3
"""Cartoon bench: `spt paint --style cartoon` against the default painter and x265 on the
flat-colour clips (python3 standard library, ffmpeg with libx265).

usage: python3 bench/cartoon_bench.py [--spt build/bin/spt] [--media ../shared/media]
                                      [--target 36] [--frames 24] [--threads 2]
                                      [--out /tmp/spt-cartoon-bench] [--stills-only]

Clips: cartoon/star and cartoon/taffy (RGBA, flattened over white) and video/butterfly-cartoon.avi,
the first FRAMES frames of each. For each clip, once on one still (frame 30 of star and taffy,
40 of the butterfly) and once on the sequence: bytes, PSNR and SSIM against the source
(`spt compare`: sequences give the PSNR of the mean MSE and the mean SSIM) and painting time
per frame for --style cartoon and the default painter at --target-psnr TARGET, and for x265
(-preset slow, yuv420p and yuv444p) at the CRF whose PSNR is closest to the cartoon's from
above, searched by bisection. x265 bytes are the raw HEVC stream (no container), spt bytes the
whole .spt file (header, templates and metadata included). Recorded results: the commit
messages of this file (git log bench/cartoon_bench.py).
"""
import argparse
import json
import os
import shutil
import subprocess
import time


def run(cmd):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def ff(*args):
    r = run(["ffmpeg", "-loglevel", "error", "-y"] + list(args))
    if r.returncode:
        raise SystemExit("ffmpeg failed: " + r.stderr)


def compare(spt, a, b):
    d = json.loads(run([spt, "compare", a, b, "--json"]).stdout)
    if "mean_psnr" in d:
        return d["mean_psnr"] or 99.0, d["mean_ssim"]
    return d["psnr"] or 99.0, d["ssim"]


def prepare(media, out, frames):
    """Each clip as a folder of flattened RGB PNGs d/f.0000.png ..., and its still."""
    clips = []
    for name, still in (("star", 30), ("taffy", 30)):
        d = os.path.join(out, name)
        os.makedirs(d, exist_ok=True)
        src = os.path.join(media, "cartoon", name)
        for i in range(frames):
            dst = os.path.join(d, f"f.{i:04d}.png")
            if not os.path.exists(dst):
                ff("-i", os.path.join(src, f"f.{i:04d}.png"), "-filter_complex",
                   "color=white,format=rgb24[b];[b][0]scale2ref[b][f];[b][f]overlay=format=auto:shortest=1,format=rgb24",
                   "-frames:v", "1", dst)
        s = os.path.join(out, f"{name}-still.png")
        if not os.path.exists(s):
            ff("-i", os.path.join(src, f"f.{still:04d}.png"), "-filter_complex",
               "color=white,format=rgb24[b];[b][0]scale2ref[b][f];[b][f]overlay=format=auto:shortest=1,format=rgb24",
               "-frames:v", "1", s)
        clips.append((name, d, s))
    d = os.path.join(out, "butterfly")
    os.makedirs(d, exist_ok=True)
    avi = os.path.join(media, "video", "butterfly-cartoon.avi")
    if not os.path.exists(os.path.join(d, "f.0000.png")):
        ff("-i", avi, "-frames:v", str(frames), "-pix_fmt", "rgb24", "-start_number", "0", os.path.join(d, "f.%04d.png"))
    s = os.path.join(out, "butterfly-still.png")
    if not os.path.exists(s):
        ff("-i", avi, "-vf", "select=eq(n\\,40)", "-frames:v", "1", "-pix_fmt", "rgb24", s)
    clips.append(("butterfly", d, s))
    return clips


def spt_paint(spt, src, base, extra, threads, n):
    t0 = time.time()
    r = run([spt, "paint", src, "-o", base + ".spt", "--threads", str(threads), "--progress", "none"] + extra)
    secs = time.time() - t0
    if r.returncode:
        raise SystemExit(f"spt paint {src}: {r.stderr}")
    if n == 1:
        out = base + ".png"
    else:
        os.makedirs(base + "-r", exist_ok=True)
        out = os.path.join(base + "-r", "f.####.png")
    r = run([spt, "render", base + ".spt", "-o", out])
    if r.returncode:
        raise SystemExit(f"spt render {base}.spt: {r.stderr}")
    return os.path.getsize(base + ".spt"), out, secs / n


def x265(src_pattern, still, base, crf, pix):
    inp = ["-i", src_pattern] if still else ["-framerate", "24", "-start_number", "0", "-i", src_pattern]
    ff(*inp, "-c:v", "libx265", "-preset", "slow", "-crf", str(crf), "-pix_fmt", pix,
       "-x265-params", "log-level=error", "-f", "hevc", base + ".hevc")
    if still:
        dec = base + ".png"
        ff("-i", base + ".hevc", "-pix_fmt", "rgb24", dec)
    else:
        shutil.rmtree(base + "-d", ignore_errors=True)
        os.makedirs(base + "-d")
        dec = os.path.join(base + "-d", "f.%04d.png")
        ff("-i", base + ".hevc", "-pix_fmt", "rgb24", "-start_number", "0", dec)
        dec = dec.replace("%04d", "####")
    return os.path.getsize(base + ".hevc"), dec


def x265_at(spt, src_pattern, ref, still, base, psnr, pix):
    lo, hi, best = 0.0, 51.0, None
    for _ in range(7):
        crf = round((lo + hi) / 2, 2)
        b, dec = x265(src_pattern, still, base, crf, pix)
        p, s = compare(spt, dec, ref)
        if p >= psnr:
            best, lo = (b, p, s, crf), crf
        else:
            hi = crf
    if best is None:
        b, dec = x265(src_pattern, still, base, 0, pix)
        p, s = compare(spt, dec, ref)
        best = (b, p, s, 0)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spt", default="build/bin/spt")
    ap.add_argument("--media", default="../shared/media")
    ap.add_argument("--target", type=float, default=36)
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="/tmp/spt-cartoon-bench")
    ap.add_argument("--stills-only", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    clips = prepare(a.media, a.out, a.frames)
    print(f"target {a.target} dB; spt: whole file, x265: raw HEVC stream; s/frame: painting time")
    print(f"{'clip':16} {'coder':24} {'bytes':>9} {'PSNR':>7} {'SSIM':>7} {'s/frame':>8}")
    for name, folder, still in clips:
        cases = [(f"{name} still", still, still, still, 1)]
        if not a.stills_only:
            pat = os.path.join(folder, "f.####.png")
            cases.append((f"{name} {a.frames}f", pat, pat, os.path.join(folder, "f.%04d.png"), a.frames))
        for label, src, ref, ffsrc, n in cases:
            base = os.path.join(a.out, label.replace(" ", "-"))
            rows = []
            b, out, t = spt_paint(a.spt, src, base + "-cartoon", ["--style", "cartoon", "--target-psnr", str(a.target)], a.threads, n)
            cp, cs = compare(a.spt, out, ref)
            rows.append(("spt --style cartoon", b, cp, cs, t))
            b, out, t = spt_paint(a.spt, src, base + "-default", ["--target-psnr", str(a.target)], a.threads, n)
            p, s = compare(a.spt, out, ref)
            rows.append(("spt default painter", b, p, s, t))
            for pix in ("yuv420p", "yuv444p"):
                b, p, s, crf = x265_at(a.spt, ffsrc, ref, n == 1, base + "-" + pix, cp, pix)
                rows.append((f"x265 {pix[3:]} crf {crf}", b, p, s, None))
            for coder, b, p, s, t in rows:
                ts = f"{t:8.3f}" if t is not None else "       -"
                print(f"{label:16} {coder:24} {b:9d} {p:7.2f} {s:7.4f} {ts}", flush=True)


if __name__ == "__main__":
    main()
