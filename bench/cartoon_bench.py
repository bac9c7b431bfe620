#!/usr/bin/env python3
"""Cartoon bench: `spt paint --style cartoon` against the default painter, x265, AV1 (libaom) and
potrace on the flat-colour clips (python3 standard library, ffmpeg with libx265, libaom-av1 and
librsvg, potrace).

usage: python3 bench/cartoon_bench.py [--spt build/bin/spt] [--media ../shared/media]
                                      [--target 36] [--frames 24] [--threads 2]
                                      [--out /tmp/spt-cartoon-bench] [--stills-only]
                                      [--clips star,taffy,butterfly] [--repeat 3]
                                      [--codecs x265,av1]

Clips: cartoon/star and cartoon/taffy (RGBA, flattened over white) and video/butterfly-cartoon.avi,
the first FRAMES frames of each. For each clip, once on one still (frame 30 of star and taffy,
40 of the butterfly) and once on the sequence: bytes, PSNR and SSIM against the source
(`spt compare`: sequences give the PSNR of the mean MSE and the mean SSIM) and painting time
per frame (the median of REPEAT paintings, which must be byte-identical) for --style cartoon and
the default painter at --target-psnr TARGET (the butterfly
sequence also painted from the .avi itself, --frames 0-(FRAMES-1)); for x265
(-preset slow) and AV1 (libaom, -cpu-used 4), yuv420p and yuv444p, the CRF whose PSNR is
closest to the cartoon's from above, and (yuv420p) the CRF whose stream is closest to the
cartoon's bytes from below, both searched by bisection; for potrace per colour layer
(bench/tools/potrace_layers.py: the frame quantized to the palette of the cartoon's polygons and lines
in that frame, stacked and not), the SVG bytes, plain and gzip'd, and its PSNR once rasterized by
librsvg (ffmpeg's svg decoder). x265 bytes are the raw HEVC stream, AV1 the raw OBU stream (no
container), spt the whole .spt file (header, templates and metadata included), potrace the sum
of one SVG per frame. Each clip's still also gives a contact sheet OUT/CLIP-contact.png:
source | cartoon | default painter | x265 420p at the cartoon's bytes, the quarter of the frame
with the most edges, at 2x. A still also gives its flat-colour layer ("cartoon fills only": the
cartoon's polygons and lines at its outline tolerance and smoothing, no stamps) and x265 444p at
that layer's PSNR: where the source's detail above the layer's PSNR is what the stamps chase
(blur, codec noise), this says whether the outlines alone already cost more than blocks. Every
encoder gets at most THREADS threads; --codecs narrows the codecs compared. Recorded results:
the commit messages of this file (git log bench/cartoon_bench.py) and
converter/src/cartoon/README.md.
"""
import argparse
import gzip
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "tools"))
import potrace_layers  # noqa: E402


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


def prepare(media, out, frames, wanted):
    """Each clip of `wanted` as a folder of flattened RGB PNGs d/f.0000.png ..., and its still. A
    folder per frame count (NAME-Nf): a sequence is every file of its folder."""
    clips = []
    for name, still in (("star", 30), ("taffy", 30)):
        if name not in wanted:
            continue
        src = os.path.join(media, "cartoon", name)
        have = len([f for f in os.listdir(src) if f.endswith(".png")])
        if frames > have:
            sys.exit(f"cartoon_bench: {src} has {have} frames; --frames {frames} asks for more")
        d = os.path.join(out, f"{name}-{frames}f")
        os.makedirs(d, exist_ok=True)
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
    if "butterfly" not in wanted:
        return clips
    d = os.path.join(out, f"butterfly-{frames}f")
    os.makedirs(d, exist_ok=True)
    avi = os.path.join(media, "video", "butterfly-cartoon.avi")
    if not os.path.exists(os.path.join(d, "f.0000.png")):
        ff("-i", avi, "-frames:v", str(frames), "-pix_fmt", "rgb24", "-start_number", "0", os.path.join(d, "f.%04d.png"))
    have = len([f for f in os.listdir(d) if f.endswith(".png")])
    if have < frames:
        sys.exit(f"cartoon_bench: {avi} has {have} frames; --frames {frames} asks for more")
    s = os.path.join(out, "butterfly-still.png")
    if not os.path.exists(s):
        ff("-i", avi, "-vf", "select=eq(n\\,40)", "-frames:v", "1", "-pix_fmt", "rgb24", s)
    clips.append(("butterfly", d, s))
    return clips


def spt_paint(spt, src, base, extra, threads, n, repeat=1):
    """Paints `repeat` times: the median time per frame, and every painting must be the same
    bytes (the seed fixes them, whatever the machine's load)."""
    times, first = [], None
    for _ in range(repeat):
        t0 = time.time()
        r = run([spt, "paint", src, "-o", base + ".spt", "--threads", str(threads), "--progress", "none"] + extra)
        times.append(time.time() - t0)
        if r.returncode:
            raise SystemExit(f"spt paint {src}: {r.stderr}")
        with open(base + ".spt", "rb") as fh:
            data = fh.read()
        if first is None:
            first = data
        elif data != first:
            raise SystemExit(f"spt paint {src} {' '.join(extra)}: two paintings differ (not deterministic)")
    secs = statistics.median(times)
    if n == 1:
        out = base + ".png"
    else:
        os.makedirs(base + "-r", exist_ok=True)
        out = os.path.join(base + "-r", "f.####.png")
    r = run([spt, "render", base + ".spt", "-o", out])
    if r.returncode:
        raise SystemExit(f"spt render {base}.spt: {r.stderr}")
    return os.path.getsize(base + ".spt"), out, secs / n


def encode(codec, src_pattern, still, base, crf, pix, threads):
    """Codes the source with x265 (-preset slow, raw HEVC stream) or libaom AV1 (-cpu-used 4,
    raw OBU stream) at `crf`; returns (bytes, decoded frames as spt reads them)."""
    inp = ["-i", src_pattern] if still else ["-framerate", "24", "-start_number", "0", "-i", src_pattern]
    if codec == "x265":
        ext, opts = ".hevc", ["-c:v", "libx265", "-preset", "slow", "-crf", str(crf),
                              "-x265-params", f"log-level=error:pools={threads}", "-f", "hevc"]
    else:
        ext, opts = ".obu", ["-c:v", "libaom-av1", "-crf", str(int(crf)), "-b:v", "0", "-cpu-used", "4",
                             "-row-mt", "1", "-threads", str(threads), "-f", "obu"]
    ff(*inp, *opts[:-2], "-pix_fmt", pix, *opts[-2:], base + ext)
    if still:
        dec = base + ".png"
        ff("-threads", str(threads), "-i", base + ext, "-pix_fmt", "rgb24", dec)
    else:
        shutil.rmtree(base + "-d", ignore_errors=True)
        os.makedirs(base + "-d")
        dec = os.path.join(base + "-d", "f.%04d.png")
        ff("-threads", str(threads), "-i", base + ext, "-pix_fmt", "rgb24", "-start_number", "0", dec)
        dec = dec.replace("%04d", "####")
    return os.path.getsize(base + ext), dec


CRF_MAX = {"x265": 51.0, "av1": 63.0}


def codec_at(spt, codec, src_pattern, ref, still, base, pix, threads, psnr=None, max_bytes=None):
    """Bisects the CRF: the largest whose PSNR is at least `psnr`, or the smallest whose stream is
    at most `max_bytes` (else CRF 0, or the largest CRF). Returns (bytes, PSNR, SSIM, crf, decoded)."""
    lo, hi, best, crf = 0.0, CRF_MAX[codec], None, None
    integer = codec == "av1"
    for _ in range(7):
        crf = round((lo + hi) / 2) if integer else round((lo + hi) / 2, 2)
        b, dec = encode(codec, src_pattern, still, base, crf, pix, threads)
        p, s = compare(spt, dec, ref)
        ok = p >= psnr if psnr is not None else b <= max_bytes
        if ok:
            best = (b, p, s, crf)
        if (ok and psnr is not None) or (not ok and psnr is None):
            lo = crf
        else:
            hi = crf
        if integer and hi - lo <= 1:
            break
    if best is None:
        crf = 0 if psnr is not None else CRF_MAX[codec]
        b, dec = encode(codec, src_pattern, still, base, crf, pix, threads)
        p, s = compare(spt, dec, ref)
        best = (b, p, s, crf)
    if crf != best[3]:  # the frames on disk are the last ones coded: those of the chosen CRF
        b, dec = encode(codec, src_pattern, still, base, best[3], pix, threads)
    return best + (dec,)


def painter_options(spt, path):
    """The `painter.options` of a .spt file as a dict (key=value words)."""
    info = json.loads(run([spt, "info", path, "--json", "--no-fields"]).stdout)
    opts = dict(w.split("=", 1) for w in info.get("metadata", {}).get("painter.options", "").split() if "=" in w)
    opts["stamps"] = "1" if info.get("templates") else "0"  # a still without stamps carries no templates
    return opts


def fills_rows(spt, cartoon_spt, src, base, threads):
    """A still's flat-colour layer: the cartoon painting's own outlines (its tolerance,
    smoothing, smallest region and palette share from painter.options), at a PSNR target every
    fill layer reaches, so without stamps; and x265 444p at that layer's PSNR. Where x265 needs
    fewer bytes even here, the source's edges and fills alone cost more as polygons than as
    blocks."""
    opts = painter_options(spt, cartoon_spt)
    extra = ["--style", "cartoon"] + ([] if opts.get("lines", "1") == "1" else ["--no-lines"])
    for name in ("min-region", "min-color-share"):
        if name in opts:
            extra += ["--" + name, opts[name]]
    if opts["stamps"] == "1":  # the polygons fell short: the outline it chose (0: the default 0.35 px)
        tolerance = opts["outline-tolerance"] if float(opts["outline-tolerance"]) > 0 else "0.35"
        extra += ["--target-psnr", "10", "--outline-tolerance", tolerance,
                  "--outline-smooth", opts.get("outline-smooth", "0")]
    else:  # the coarsest outline whose polygons reached the target
        extra += ["--target-psnr", opts["target-psnr"]]
    b, out, t = spt_paint(spt, src, base + "-fills", extra, threads, 1)
    p, s = compare(spt, out, src)
    xb, xp, xs, crf, _ = codec_at(spt, "x265", src, src, True, base + "-fills-x265", "yuv444p", threads, psnr=p)
    return [("cartoon fills only", b, p, s, t), (f"x265 444p =fills crf {crf}", xb, xp, xs, None)]


def potrace_rows(spt, cartoon_spt, src, ref, base, n):
    """potrace per colour layer (bench/tools/potrace_layers.py) on the source frames, with the palette
    of the cartoon's polygons and lines in the same frame; rasterized by librsvg (ffmpeg's svg decoder).
    Returns rows (label, SVG bytes, PSNR, SSIM) stacked and not, bytes gzip'd too."""
    shutil.rmtree(base + "-svg", ignore_errors=True)
    os.makedirs(base + "-svg")
    pattern = os.path.join(base + "-svg", "c.####.svg")
    r = run([spt, "export", cartoon_spt, "-o", pattern if n > 1 else pattern.replace("####", "0000")])
    if r.returncode:
        raise SystemExit(f"spt export {cartoon_spt}: {r.stderr}")
    rows = []
    for stacked in (True, False):
        tag = "stacked" if stacked else "per colour"
        total, gz, colours = 0, 0, 0
        for i in range(n):
            with open(os.path.join(base + "-svg", f"c.{i:04d}.svg")) as fh:
                palette = potrace_layers.svg_palette(fh.read())
            colours = max(colours, len(palette))
            frame = src if n == 1 else src.replace("####", f"{i:04d}")
            text = potrace_layers.trace(frame, palette, stacked).encode()
            out = os.path.join(base + "-svg", f"p{int(stacked)}.{i:04d}.svg")
            with open(out, "wb") as fh:
                fh.write(text)
            total += len(text)
            gz += len(gzip.compress(text, 9))
            ff("-i", out, "-pix_fmt", "rgb24", out[:-4] + ".png")
        dec = os.path.join(base + "-svg", f"p{int(stacked)}.0000.png" if n == 1 else f"p{int(stacked)}.####.png")
        p, s = compare(spt, dec, ref)
        rows.append((f"potrace {tag} ({colours} c)", total, p, s, None))
        rows.append((f"potrace {tag} svg.gz", gz, p, s, None))
    return rows


def busiest_quarter(png):
    """(x, y, w, h) of the half-width, half-height window of `png` holding the most edges (pixels
    unlike their right or lower neighbour), on a grid of eighths: where the coders differ."""
    w, h, raw = potrace_layers.read_rgb(png)
    cw, ch = w // 2, h // 2
    step_x, step_y = max(1, w // 8), max(1, h // 8)
    col = [[0] * (w // step_x + 1) for _ in range(h // step_y + 1)]  # edges per grid cell
    for y in range(h - 1):
        row, below = y * w * 3, (y + 1) * w * 3
        for x in range(w - 1):
            i = row + 3 * x
            if raw[i:i + 3] != raw[i + 3:i + 6] or raw[i:i + 3] != raw[below + 3 * x:below + 3 * x + 3]:
                col[y // step_y][x // step_x] += 1
    best, at = -1, (0, 0)
    for gy in range(0, (h - ch) // step_y + 1):
        for gx in range(0, (w - cw) // step_x + 1):
            e = sum(col[gy + j][gx + i] for j in range(ch // step_y) for i in range(cw // step_x))
            if e > best:
                best, at = e, (gx * step_x, gy * step_y)
    return at[0], at[1], cw, ch


def contact_sheet(panels, out):
    """source | cartoon | default | x265 at equal bytes: the busiest quarter of each, 2x, nearest."""
    x, y, w, h = busiest_quarter(panels[0])
    args = []
    for p in panels:
        args += ["-i", p]
    crops = "".join(f"[{i}]format=rgb24,crop={w}:{h}:{x}:{y},scale=iw*2:ih*2:flags=neighbor"
                    f"{',pad=iw+4:ih:0:0:white' if i < len(panels) - 1 else ''}[c{i}];" for i in range(len(panels)))
    ff(*args, "-filter_complex", crops + "".join(f"[c{i}]" for i in range(len(panels)))
       + f"hstack=inputs={len(panels)}", "-frames:v", "1", out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spt", default="build/bin/spt")
    ap.add_argument("--media", default="../shared/media")
    ap.add_argument("--target", type=float, default=36)
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="/tmp/spt-cartoon-bench")
    ap.add_argument("--stills-only", action="store_true")
    ap.add_argument("--clips", default="star,taffy,butterfly")
    ap.add_argument("--repeat", type=int, default=3, help="paintings per case; the median time is printed")
    ap.add_argument("--codecs", default="x265,av1", help="the video codecs compared (x265, av1)")
    a = ap.parse_args()
    has_aom = "libaom-av1" in run(["ffmpeg", "-hide_banner", "-encoders"]).stdout
    if not has_aom and "av1" in a.codecs.split(","):
        print("AV1: this ffmpeg has no libaom-av1 encoder; AV1 rows left out")
    os.makedirs(a.out, exist_ok=True)
    clips = prepare(a.media, a.out, a.frames, a.clips.split(","))
    print(f"target {a.target} dB; spt: whole file, x265: raw HEVC stream, av1: raw OBU stream, potrace: SVG"
          f"; s/frame: painting time, median of {a.repeat}")
    print(f"{'clip':16} {'coder':26} {'bytes':>9} {'PSNR':>7} {'SSIM':>7} {'s/frame':>8}")
    for name, folder, still in clips:
        if name not in a.clips.split(","):
            continue
        cases = [(f"{name} still", still, still, still, 1)]
        if not a.stills_only:
            pat = os.path.join(folder, "f.####.png")
            cases.append((f"{name} {a.frames}f", pat, pat, os.path.join(folder, "f.%04d.png"), a.frames))
        for label, src, ref, ffsrc, n in cases:
            base = os.path.join(a.out, label.replace(" ", "-"))
            rows = []
            b, cartoon_out, t = spt_paint(a.spt, src, base + "-cartoon", ["--style", "cartoon", "--target-psnr", str(a.target)], a.threads, n, a.repeat)
            cartoon_bytes = b
            cp, cs = compare(a.spt, cartoon_out, ref)
            rows.append(("spt --style cartoon", b, cp, cs, t))
            if name == "butterfly" and n > 1:
                # The same frames painted from the video file itself (spt decodes the .avi).
                avi = os.path.join(a.media, "video", "butterfly-cartoon.avi")
                b, avi_out, t = spt_paint(a.spt, avi, base + "-cartoon-avi",
                                          ["--style", "cartoon", "--target-psnr", str(a.target), "--frames", f"0-{n - 1}"],
                                          a.threads, n, a.repeat)
                p, s = compare(a.spt, avi_out, ref)
                rows.append(("spt --style cartoon (.avi)", b, p, s, t))
            b, default_out, t = spt_paint(a.spt, src, base + "-default", ["--target-psnr", str(a.target)], a.threads, n, a.repeat)
            p, s = compare(a.spt, default_out, ref)
            rows.append(("spt default painter", b, p, s, t))
            codecs = [c for c in ("x265", "av1") if c in a.codecs.split(",") and (c != "av1" or has_aom)]
            for codec in codecs:
                for pix in ("yuv420p", "yuv444p"):
                    b, p, s, crf, _ = codec_at(a.spt, codec, ffsrc, ref, n == 1, f"{base}-{codec}-{pix}", pix, a.threads, psnr=cp)
                    rows.append((f"{codec} {pix[3:]} crf {crf}", b, p, s, None))
                b, p, s, crf, dec = codec_at(a.spt, codec, ffsrc, ref, n == 1, f"{base}-{codec}-bytes", "yuv420p", a.threads,
                                             max_bytes=cartoon_bytes)
                rows.append((f"{codec} 420p =bytes crf {crf}", b, p, s, None))
                if codec == "x265" and n == 1:
                    sheet = os.path.join(a.out, f"{name}-contact.png")
                    contact_sheet([src, cartoon_out, default_out, dec], sheet)
            if n == 1:
                rows += fills_rows(a.spt, base + "-cartoon.spt", src, base, a.threads)
            rows += potrace_rows(a.spt, base + "-cartoon.spt", src, ref, base + "-potrace", n)
            for coder, b, p, s, t in rows:
                ts = f"{t:8.3f}" if t is not None else "       -"
                print(f"{label:16} {coder:26} {b:9d} {p:7.2f} {s:7.4f} {ts}", flush=True)
    for name in a.clips.split(","):
        sheet = os.path.join(a.out, f"{name}-contact.png")
        if os.path.exists(sheet):
            print(f"contact sheet (source | cartoon | default painter | x265 420p at the cartoon's bytes; "
                  f"busiest quarter, 2x): {sheet}")


if __name__ == "__main__":
    main()
