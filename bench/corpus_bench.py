#!/usr/bin/python3
"""Corpus bench: every painter change is judged here, on every still and clip we have, never on
one (python3 with numpy, ffmpeg with libx265, oiiotool; synfig to render the vector corpus).

usage: /usr/bin/python3 bench/corpus_bench.py [--spt build/bin/spt]
           [--synthetic build/bench/synthetic_clips] [--media ../shared/media]
           [--corpus DIR] [--target 30] [--frames 24] [--threads 2]
           [--out /tmp/spt-corpus-bench] [--only NAME,...] [--no-x265] [--json FILE]

The corpus: the stills, EXR renders, videos and cartoon clips of ../shared/media (EXR flattened
over white and converted to sRGB 8-bit), the 13 stills and 7 clips of the synfig vector corpus
(cartoon/render_corpus.sh, rendered into --corpus when missing), and the synthetic clips of
tests/video/change_clips.hpp (still, nearly still, pan, fade, cut, flicker, held). Clips are
their first FRAMES frames. For each entry, both styles at --target-psnr TARGET: bytes, PSNR
(`spt compare` of the render against the source: the PSNR of the mean MSE), painting seconds;
x265 (-preset slow, yuv420p, raw HEVC) at the default painter's PSNR, by CRF bisection; and per
inter frame the budget of issue 34, 2 p x key frame bytes + 64, where p is the share of pixels
whose source changed since the previous frame by more than the target's RMS error: the worst
frame's bytes / budget ("inter" columns: at most 1 holds the rule) and the mean p.

Summary line: entries where the cartoon style is larger than the default painter (goal 0),
entries with an inter frame over its budget (goal 0), and the medians against x265.
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cartoon_bench import compare, ff, run, spt_paint  # noqa: E402

WHITE_OVER = "color=white,format=rgb24[b];[b][0]scale2ref[b][f];[b][f]overlay=format=auto:shortest=1,format=rgb24"


def exr_to_png(src, dst):
    """Scene-linear EXR (RGB or RGBA) to sRGB 8-bit, over white where it has alpha."""
    tmp = dst + ".rgba.png"
    chans = run(["oiiotool", "--info", "-v", src]).stdout
    ch = "R,G,B,A" if "A" in chans.split("channel list:")[-1].split("\n")[0].replace(",", " ").split() else "R,G,B"
    r = run(["oiiotool", src, "--ch", ch, "--unpremult", "--colorconvert", "linear", "sRGB",
             "-d", "uint8", "-o", tmp])
    if r.returncode:
        raise SystemExit(f"oiiotool {src}: {r.stderr}")
    flatten(tmp, dst)
    os.remove(tmp)


def flatten(src, dst):
    ff("-i", src, "-filter_complex", WHITE_OVER, "-frames:v", "1", dst)


def prepare(args):
    """[(name, kind, folder or file)]: every entry as flattened RGB PNGs, d/f.0000.png ..."""
    m, out, n = args.media, os.path.join(args.out, "src"), args.frames
    os.makedirs(out, exist_ok=True)
    entries = []

    def still(name, src, conv):
        dst = os.path.join(out, name + ".png")
        if not os.path.exists(dst):
            conv(src, dst)
        entries.append((name, "still", dst))

    def clip(name, files, conv):
        d = os.path.join(out, name)
        if not os.path.exists(os.path.join(d, ".done")):
            os.makedirs(d, exist_ok=True)
            for i, f in enumerate(files[:n]):
                conv(f, os.path.join(d, f"f.{i:04d}.png"))
            open(os.path.join(d, ".done"), "w").close()
        entries.append((name, "clip", d))

    for f in sorted(os.listdir(os.path.join(m, "stills"))):
        still(os.path.splitext(f)[0], os.path.join(m, "stills", f), lambda s, d: ff("-i", s, "-pix_fmt", "rgb24", d))
    for f in ("GoldenGate.exr", "StillLife.exr"):
        still(os.path.splitext(f)[0], os.path.join(m, "exr", f), exr_to_png)
    for seq in ("earth", "orbit"):
        d = os.path.join(m, "exr", seq)
        clip(seq, [os.path.join(d, f) for f in sorted(os.listdir(d)) if f.endswith(".exr")], exr_to_png)
    for v in ("city.mpg", "butterfly-cartoon.avi"):
        name = os.path.splitext(v)[0]
        d = os.path.join(out, name)
        if not os.path.exists(os.path.join(d, ".done")):
            os.makedirs(d, exist_ok=True)
            ff("-i", os.path.join(m, "video", v), "-frames:v", str(n), "-pix_fmt", "rgb24", "-start_number", "0",
               os.path.join(d, "f.%04d.png"))
            open(os.path.join(d, ".done"), "w").close()
        entries.append((name, "clip", d))
    for c in ("star", "taffy"):
        d = os.path.join(m, "cartoon", c)
        clip(c, [os.path.join(d, f) for f in sorted(os.listdir(d)) if f.endswith(".png")], flatten)
    corpus = args.corpus
    if not os.path.isdir(os.path.join(corpus, "clips")):
        subprocess.run([os.path.join(m, "cartoon", "render_corpus.sh"), corpus], check=True)
    for f in sorted(os.listdir(os.path.join(corpus, "stills"))):
        still("synfig-" + os.path.splitext(f)[0], os.path.join(corpus, "stills", f), flatten)
    for c in sorted(os.listdir(os.path.join(corpus, "clips"))):
        if c in ("star", "preambletaffy"):  # the shared star and taffy above
            continue
        d = os.path.join(corpus, "clips", c)
        files = [os.path.join(d, f) for f in sorted(os.listdir(d)) if f.endswith(".png")]
        if files:
            clip("synfig-" + c, files, flatten)
    syn = os.path.join(out, "synthetic")
    if not os.path.exists(os.path.join(syn, ".done")):
        shutil.rmtree(syn, ignore_errors=True)
        subprocess.run([args.synthetic, syn, str(n)], check=True)
        open(os.path.join(syn, ".done"), "w").close()
    for c in sorted(os.listdir(syn)):
        if os.path.isdir(os.path.join(syn, c)):
            entries.append(("synthetic-" + c, "clip", os.path.join(syn, c)))
    if args.only:
        wanted = set(args.only.split(","))
        entries = [e for e in entries if e[0] in wanted]
    return entries


def frames_rgb(path, kind):
    """The entry's frames as an (n, h, w, 3) uint8 array."""
    src = path if kind == "still" else os.path.join(path, "f.%04d.png")
    pre = [] if kind == "still" else ["-start_number", "0"]
    probe = json.loads(run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries", "stream=width,height",
                            "-of", "json"] + pre + ["-i", src]).stdout)["streams"][0]
    w, h = probe["width"], probe["height"]
    raw = subprocess.run(["ffmpeg", "-loglevel", "error"] + pre + ["-i", src, "-f", "rawvideo", "-pix_fmt", "rgb24",
                          "pipe:"], stdout=subprocess.PIPE, check=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(-1, h, w, 3), w, h


def changed_shares(frames, target):
    """p of every frame after the first: the share of pixels whose colour changed from the
    previous frame by more than the target's RMS error (root mean square over the channels)."""
    rms = 255.0 / 10 ** (target / 20)
    out = []
    for a, b in zip(frames[:-1], frames[1:]):
        d = a.astype(np.int32) - b.astype(np.int32)
        out.append(float(np.mean((d * d).sum(axis=2) > 3 * rms * rms)))
    return out


def inter_budget(spt, path, shares):
    """(worst bytes / budget over the inter frames, frames over budget, inter bytes, key bytes)."""
    info = json.loads(run([spt, "info", path, "--json", "--frames"]).stdout)
    worst, over, inter, keys, key = 0.0, 0, 0, 0, 0
    for i, f in enumerate(info["frame_list"]):
        if f["type"] == "key":
            key = f["bytes"]
            keys += key
            continue
        inter += f["bytes"]
        budget = 2 * shares[i - 1] * key + 64
        worst = max(worst, f["bytes"] / budget)
        over += f["bytes"] > budget
    return worst, over, inter, keys


def x265_at(spt, path, kind, ref, w, h, base, threads, psnr):
    """x265 (-preset slow, yuv420p, raw HEVC) at the largest CRF whose PSNR is at least `psnr`,
    by bisection (7 encodes); odd sizes are padded for 4:2:0 and cropped back after decoding.
    Returns (bytes, PSNR, CRF)."""
    inp = ["-i", path] if kind == "still" else ["-framerate", "24", "-start_number", "0", "-i",
                                                os.path.join(path, "f.%04d.png")]
    pad = f"pad=ceil(iw/2)*2:ceil(ih/2)*2,format=yuv420p"
    dec = base + ("-x265.png" if kind == "still" else "-x265-d")

    def encode(crf):
        ff(*inp, "-vf", pad, "-c:v", "libx265", "-preset", "slow", "-crf", str(crf),
           "-x265-params", f"log-level=error:pools={threads}", "-f", "hevc", base + ".hevc")
        if kind == "still":
            ff("-i", base + ".hevc", "-vf", f"format=rgb24,crop={w}:{h}:0:0", "-pix_fmt", "rgb24", dec)
            out = dec
        else:
            shutil.rmtree(dec, ignore_errors=True)
            os.makedirs(dec)
            ff("-i", base + ".hevc", "-vf", f"format=rgb24,crop={w}:{h}:0:0", "-pix_fmt", "rgb24", "-start_number", "0",
               os.path.join(dec, "f.%04d.png"))
            out = os.path.join(dec, "f.####.png")
        return os.path.getsize(base + ".hevc"), compare(spt, out, ref)[0]

    lo, hi, best = 0.0, 51.0, None
    for _ in range(7):
        crf = round((lo + hi) / 2, 2)
        b, p = encode(crf)
        if p >= psnr:
            best, lo = (b, p, crf), crf
        else:
            hi = crf
    if best is None:
        b, p = encode(0)
        best = (b, p, 0)
    return best


def bench_entry(args, name, kind, path):
    frames, w, h = frames_rgb(path, kind)
    n = len(frames)
    src = path if kind == "still" else os.path.join(path, "f.####.png")
    base = os.path.join(args.out, "work", name)
    os.makedirs(os.path.dirname(base), exist_ok=True)
    shares = changed_shares(frames, args.target)
    row = {"name": name, "kind": kind, "size": f"{w}x{h}", "frames": n,
           "p_mean": statistics.mean(shares) if shares else 0.0}
    for style in args.styles.split(","):
        b = f"{base}-{style}"
        extra = ["--seed", "1", "--target-psnr", str(args.target), "--style", style]
        size, rendered, secs = spt_paint(args.spt, src, b, extra, args.threads, n)
        psnr, _ = compare(args.spt, rendered, src)
        worst, over, inter, keys = inter_budget(args.spt, b + ".spt", shares) if n > 1 else (0.0, 0, 0, size)
        row[style] = {"bytes": size, "psnr": psnr, "seconds": secs * n, "inter_worst": worst, "inter_over": over,
                      "inter_bytes": inter, "key_bytes": keys}
    if not args.no_x265:
        psnr = row["painterly"]["psnr"] if "painterly" in row else args.target
        xb, xp, crf = x265_at(args.spt, path, kind, src, w, h, base + "-x265", args.threads, psnr)
        row["x265"] = {"bytes": xb, "psnr": xp, "crf": crf}
    return row


def print_table(rows, target):
    print(f"corpus bench at --target-psnr {target}: bytes, PSNR dB, seconds; inter = worst inter frame's bytes "
          "/ (2 p key + 64) (<= 1 holds), over = frames above it; x265 at the default painter's PSNR")
    hdr = (f"{'entry':26} {'size':>9} {'n':>3} {'p':>6} | {'default':>9} {'dB':>6} {'s':>6} {'inter':>6} {'over':>4} | "
           f"{'cartoon':>9} {'dB':>6} {'s':>6} {'inter':>6} {'over':>4} | {'c/d':>5} | {'x265':>8} {'d/x':>6} {'c/x':>6}")
    print(hdr)
    print("-" * len(hdr))
    none = {"bytes": 0, "psnr": 0.0, "seconds": 0.0, "inter_worst": 0.0, "inter_over": 0}
    for r in rows:
        d, c, x = r.get("painterly", none), r.get("cartoon", none), r.get("x265")
        xs = f"{x['bytes']:>8} {d['bytes'] / x['bytes']:>6.2f} {c['bytes'] / x['bytes']:>6.2f}" if x else f"{'-':>8} {'-':>6} {'-':>6}"
        print(f"{r['name']:26} {r['size']:>9} {r['frames']:>3} {100 * r['p_mean']:>5.1f}% | "
              f"{d['bytes']:>9} {d['psnr']:>6.2f} {d['seconds']:>6.1f} {d['inter_worst']:>6.2f} {d['inter_over']:>4} | "
              f"{c['bytes']:>9} {c['psnr']:>6.2f} {c['seconds']:>6.1f} {c['inter_worst']:>6.2f} {c['inter_over']:>4} | "
              f"{(c['bytes'] / d['bytes']) if d['bytes'] else 0:>5.2f} | {xs}")
    larger = [r["name"] for r in rows if "cartoon" in r and "painterly" in r
              and r["cartoon"]["bytes"] > r["painterly"]["bytes"]]
    over = [r["name"] for r in rows if any(r.get(k, none)["inter_over"] for k in ("painterly", "cartoon"))]
    xr = [r for r in rows if "x265" in r]
    med = lambda k: (statistics.median(r[k]["bytes"] / r["x265"]["bytes"] for r in xr if k in r)  # noqa: E731
                     if any(k in r for r in xr) else float("nan"))
    print(f"summary: {len(rows)} entries; cartoon larger than default: {len(larger)} ({', '.join(larger) or 'none'}); "
          f"an inter frame over 2x what changed: {len(over)} ({', '.join(over) or 'none'}); "
          f"median bytes against x265: default {med('painterly'):.2f}, cartoon {med('cartoon'):.2f}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--spt", default=os.path.join(root, "build", "bin", "spt"))
    ap.add_argument("--synthetic", default=os.path.join(root, "build", "bench", "synthetic_clips"))
    ap.add_argument("--media", default=os.path.join(root, "..", "shared", "media"))
    ap.add_argument("--corpus", default="/var/cache/spt/corpus")
    ap.add_argument("--target", type=float, default=30)
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="/tmp/spt-corpus-bench")
    ap.add_argument("--only", default="")
    ap.add_argument("--no-x265", action="store_true")
    ap.add_argument("--styles", default="painterly,cartoon", help="painterly,cartoon or one of them")
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    rows = []
    for name, kind, path in prepare(args):
        print(f"corpus_bench: {name}", file=sys.stderr, flush=True)
        rows.append(bench_entry(args, name, kind, path))
    print_table(rows, args.target)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(rows, fh, indent=1)


if __name__ == "__main__":
    main()
