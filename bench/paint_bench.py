#!/usr/bin/env python3
"""Still-painter bench: speed, quality and size of `spt paint`, and the .spt size against
lossless coders of the same rendered painting (python3 standard library only).

usage: python3 bench/paint_bench.py [--spt build/bin/spt] [--media ../shared/media]
                                    [--target 28] [--threads 2] [--out /tmp/spt-paint-bench]
                                    [--quick]

Inputs: every still of MEDIA/stills and one frame of each clip of MEDIA/video (extracted with
ffmpeg), each at native size and resized to 1280x720. Each is painted to the --target PSNR with
edge-following orientation (the default) and with random orientation, at the same target, so
the size difference of edge following shows (the paper reports ~20% smaller).

Per image it prints wall time, PSNR/SSIM against the source (spt compare), strokes, .spt bytes,
bytes per stroke, and the bytes of the rendered painting coded losslessly by optipng -o2, cwebp
-lossless, cjxl -d 0 and JPEG-LS (ffmpeg's jpegls encoder), each where installed; then medians.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import time


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)


def prepare_inputs(media, out, quick):
    srcs = []
    stills = os.path.join(media, "stills")
    for name in sorted(os.listdir(stills)):
        srcs.append((os.path.splitext(name)[0], os.path.join(stills, name)))
    video = os.path.join(media, "video")
    if os.path.isdir(video) and shutil.which("ffmpeg"):
        for name in sorted(os.listdir(video)):
            frame = os.path.join(out, os.path.splitext(name)[0] + "-f40.png")
            if not os.path.exists(frame):
                run(["ffmpeg", "-loglevel", "error", "-y", "-i", os.path.join(video, name),
                     "-vf", "select=eq(n\\,40)", "-frames:v", "1", frame])
            if os.path.exists(frame):
                srcs.append((os.path.splitext(name)[0] + "-f40", frame))
    if quick:
        srcs = srcs[:2]
    inputs = []
    for label, path in srcs:
        native = os.path.join(out, label + "-native.png")
        if not os.path.exists(native):
            run(["ffmpeg", "-loglevel", "error", "-y", "-i", path, native])
        inputs.append((label + " native", native))
        hd = os.path.join(out, label + "-1280x720.png")
        if not os.path.exists(hd):
            run(["ffmpeg", "-loglevel", "error", "-y", "-i", path, "-vf", "scale=1280:720:flags=lanczos", hd])
        inputs.append((label + " 1280x720", hd))
    return [(l, p) for l, p in inputs if os.path.exists(p)]


def lossless_sizes(png, out):
    sizes = {}
    if shutil.which("optipng"):
        dst = os.path.join(out, "opt.png")
        shutil.copy(png, dst)
        run(["optipng", "-quiet", "-o2", dst])
        sizes["png"] = os.path.getsize(dst)
    if shutil.which("cwebp"):
        dst = os.path.join(out, "ll.webp")
        if run(["cwebp", "-quiet", "-lossless", "-z", "6", png, "-o", dst]).returncode == 0:
            sizes["webp"] = os.path.getsize(dst)
    if shutil.which("cjxl"):
        dst = os.path.join(out, "ll.jxl")
        if run(["cjxl", "-d", "0", "--quiet", png, dst]).returncode == 0:
            sizes["jxl"] = os.path.getsize(dst)
    if shutil.which("ffmpeg"):
        dst = os.path.join(out, "ll.jls")
        if run(["ffmpeg", "-loglevel", "error", "-y", "-i", png, "-c:v", "jpegls", dst]).returncode == 0:
            sizes["jpegls"] = os.path.getsize(dst)
    return sizes


def paint(spt, src, out, target, threads, orient):
    dst = os.path.join(out, "p.spt")
    prev = os.path.join(out, "p.png")
    t0 = time.monotonic()
    r = run([spt, "paint", src, "-o", dst, "--preview", prev, "--target-psnr", str(target),
             "--threads", str(threads), "--orient", orient, "--progress", "json", "--seed", "1"])
    wall = time.monotonic() - t0
    if r.returncode != 0:
        raise RuntimeError("spt paint failed on %s: %s" % (src, r.stderr.strip()))
    end = [json.loads(l) for l in r.stdout.splitlines() if l.startswith("{")][-1]
    c = run([spt, "compare", src, prev, "--json"])
    cmp = json.loads(c.stdout) if c.returncode == 0 else {"psnr": end["psnr"], "ssim": float("nan")}
    return {"wall": wall, "strokes": end["strokes"], "psnr": cmp["psnr"], "ssim": cmp["ssim"],
            "bytes": os.path.getsize(dst), "preview": prev}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--spt", default=os.path.join(here, "..", "build", "bin", "spt"))
    ap.add_argument("--media", default=os.path.join(here, "..", "..", "shared", "media"))
    ap.add_argument("--target", type=float, default=28.0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="/tmp/spt-paint-bench")
    ap.add_argument("--quick", action="store_true", help="two inputs only")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    inputs = prepare_inputs(a.media, a.out, a.quick)
    if not inputs:
        print("no inputs under %s" % a.media, file=sys.stderr)
        return 1

    hdr = ("%-24s %6s %6s %6s %7s %8s %6s | %8s %8s %8s %8s | %8s %6s" %
           ("image", "time s", "PSNR", "SSIM", "strokes", "spt B", "B/str", "png B", "webp B", "jxl B",
            "jls B", "random B", "edge%"))
    print("spt paint to %.1f dB, --threads %d, seed 1 (edge following unless noted)" % (a.target, a.threads))
    print(hdr)
    print("-" * len(hdr))
    rows = []
    for label, path in inputs:
        e = paint(a.spt, path, a.out, a.target, a.threads, "edges")
        ll = lossless_sizes(e["preview"], a.out)
        rnd = paint(a.spt, path, a.out, a.target, a.threads, "random")
        saving = 100.0 * (rnd["bytes"] - e["bytes"]) / rnd["bytes"]
        row = dict(e, **{k: ll.get(k) for k in ("png", "webp", "jxl", "jpegls")}, random=rnd["bytes"], saving=saving)
        rows.append(row)
        f = lambda v: "%8d" % v if v else "%8s" % "-"
        print("%-24s %6.2f %6.2f %6.3f %7d %8d %6.2f | %s %s %s %s | %8d %5.1f%%" %
              (label, e["wall"], e["psnr"], e["ssim"], e["strokes"], e["bytes"], e["bytes"] / max(1, e["strokes"]),
               f(row["png"]), f(row["webp"]), f(row["jxl"]), f(row["jpegls"]), rnd["bytes"], saving))
        sys.stdout.flush()

    def med(k, sel=rows):
        vals = [r[k] for r in sel if r.get(k) is not None]
        return statistics.median(vals) if vals else float("nan")

    print("-" * len(hdr))
    for name, sel in (("median, all", rows), ("median, 1280x720", [r for l, r in zip(inputs, rows) if "1280x720" in l[0]])):
        if not sel:
            continue
        print("%-24s %6.2f %6.2f %6.3f %7d %8d %6.2f | %8d %8d %8d %8d | %8d %5.1f%%" %
              (name, med("wall", sel), med("psnr", sel), med("ssim", sel), med("strokes", sel), med("bytes", sel),
               statistics.median([r["bytes"] / max(1, r["strokes"]) for r in sel]), med("png", sel), med("webp", sel),
               med("jxl", sel), med("jpegls", sel), med("random", sel), med("saving", sel)))
    ratios = [(k, statistics.median([r[k] / r["bytes"] for r in rows if r.get(k)])) for k in ("png", "webp", "jxl", "jpegls")
              if any(r.get(k) for r in rows)]
    print("lossless coder bytes / .spt bytes (median): " + ", ".join("%s %.2fx" % kv for kv in ratios))
    return 0


if __name__ == "__main__":
    sys.exit(main())
