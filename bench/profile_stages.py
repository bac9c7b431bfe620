#!/usr/bin/python3
"""Where a paint spends its time, by stage: `perf record` of one `spt paint` run, its samples
grouped by the function they fall in (issue 38's profile table).

  bench/profile_stages.py --spt build/bin/spt --input clip.mp4 --frames 0-23 [--threads 2]

Prints one table of stages (share of the samples, CPU ms a frame). Run it twice, --frames 0-0
(a key frame alone) and a whole range, to tell key frames from inter frames. Needs `perf`
(Debian linux-perf). About a minute for 24 frames of 720p."""

import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

# First match wins: a function's name (demangled) -> the stage it belongs to.
STAGES = [
    ("candidate scoring", r"colour_sums|new_error|best_colour|sse_over|score_stamp|CandidateDomain|paint::paint\(|"
                          r"_Function_handler<void \(unsigned long\), spt::paint::paint|stamp_error|score_"),
    ("acceptance and canvas", r"commit_stamp|Canvas::|raster::|RendererImpl|apply_frame|BandRenderer|copy_whole_rows"),
    ("error and change maps", r"changed_pixels|psnr|touched_area|visibly_wrong|hidden_strokes|strokes_touching|error_map"),
    ("motion (flow, blocks)", r"block_motion|Optical|DIS|calcOptical|motion|remap|warp|pyr|resize"),
    ("edges and orientation", r"multiscale_edges|atan|Sobel|Gaussian|structure|orient|distanceTransform|filter2D|sepFilter"),
    ("coding", r"encode_strokes|bit_cost|spt::detail|replay_info|range_|Writer"),
    ("video decode", r"libavcodec|libswscale|libavutil|cvtColor|VideoCapture|ff_|sws_"),
    ("OpenCV, unnamed (flow pyramids, filters, colour)", r"libopencv"),
    ("memory copies and fills", r"memmove|memset|memcpy"),
    ("start-up (dynamic linking)", r"do_lookup_x|_dl_|dl_relocate|strcmp"),
    ("kernel (page faults, scheduling)", r"^\[k\]"),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--spt", required=True)
    ap.add_argument("--input", required=True)
    ap.add_argument("--frames", default="0-23")
    ap.add_argument("--threads", default="2")
    ap.add_argument("--freq", default="999")
    ap.add_argument("extra", nargs="*", help="more spt paint options")
    a = ap.parse_args()
    first, last = (int(x) for x in a.frames.split("-"))
    frames = last - first + 1
    with tempfile.TemporaryDirectory() as d:
        data, out = os.path.join(d, "perf.data"), os.path.join(d, "out.spt")
        cmd = [a.spt, "paint", a.input, "-o", out, "--frames", a.frames, "--threads", a.threads, "--progress", "none"] + a.extra
        r = subprocess.run(["perf", "record", "-F", a.freq, "-o", data, "--"] + cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"perf record failed: {r.stderr.strip()[-400:]}")
        rep = subprocess.run(["perf", "report", "-i", data, "--no-children", "--sort", "dso,symbol", "--stdio", "-g", "none",
                              "-F", "overhead,sample,dso,symbol"], capture_output=True, text=True)
    shares, samples = collections.Counter(), 0
    for line in rep.stdout.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+(\d+)\s+(\S+)\s+(.*)", line)
        if not m:
            continue
        n, dso, sym = int(m.group(2)), m.group(3), m.group(4).strip()
        samples += n
        stage = next((s for s, rx in STAGES if re.search(rx, sym) or re.search(rx, dso)), "other")
        shares[stage] += n
    if samples == 0:
        sys.exit("no samples")
    hz = float(a.freq)
    print(f"# {' '.join(cmd)}  ({samples} samples at {a.freq} Hz, {frames} frames)")
    print("| stage | share | CPU ms a frame |")
    print("|---|---:|---:|")
    for stage, _ in STAGES + [("other", "")]:
        n = shares.get(stage, 0)
        print(f"| {stage} | {100.0 * n / samples:.1f}% | {1000.0 * n / hz / frames:.1f} |")
    print(f"| total | 100% | {1000.0 * samples / hz / frames:.1f} |")


if __name__ == "__main__":
    main()
