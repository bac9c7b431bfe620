#!/usr/bin/env python3
"""Importer bench: for each sample of other shape painters in <media>/foreign/, the size of the
imported .spt against the tool's own SVG and JSON (raw and xz -9), the PSNR of the imported
rendering against the tool's PNG, and the import time (median of 5).

usage: bench/import_bench.py [--spt build/bin/spt] [--media ../shared/media]
Targets: .spt >= 3x smaller than the xz-compressed SVG; PSNR >= 40 dB against the tool's PNG.

Column "H0 B" puts the size target in perspective for geometrize's samples, whose shapes are
integers that an exact import must keep: the order-0 empirical entropy of geometrize's own
numbers (each field of its JSON coded on its own with an ideal static model of the field's
values in this very file, a model that is free here), in bytes. It is not a lower bound for a
context coder, but a coder has to beat it by the factor shown to reach 3x. Primitive writes
six-decimal floats whose precision the rendering does not need, so it has no such column.
"""
import collections, json, os, re, statistics, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "tools"))  # foreign_samples
from foreign_samples import entropy_bits, parse_args, xz_bytes as xz

def order0_bytes(json_path):
    """Sum over the fields of geometrize's shape records (data values and colour) of the
    empirical order-0 entropy, in bytes; None when the file is not geometrize JSON."""
    try:
        with open(json_path) as f:
            shapes = json.load(f)["shapes"]
        fields = collections.defaultdict(list)
        for sh in shapes:
            for i, v in enumerate(list(sh["data"]) + list(sh["color"])):
                fields[(sh["type"], i)].append(v)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return sum(entropy_bits(v) for v in fields.values()) / 8

def main():
    a, folder = parse_args(__doc__)
    if not os.path.isdir(folder):
        print("no samples in", folder); return 1
    srcs = sorted(f for f in os.listdir(folder) if f.endswith((".svg", ".json")))
    print(f"{'sample':36} {'spt':>6} {'svg':>7} {'svg.xz':>7} {'json':>7} {'json.xz':>7} {'svg.xz/spt':>10} {'PSNR dB':>8} {'ms':>6} {'H0 B':>6} {'svg.xz/3':>8}")
    worst_ratio, worst_psnr, rows = 1e9, 1e9, 0
    with tempfile.TemporaryDirectory() as tmp:
        for f in srcs:
            src = os.path.join(folder, f)
            stem = os.path.splitext(f)[0]
            png = os.path.join(folder, stem + ".png")
            out = os.path.join(tmp, f + ".spt")
            times, psnr = [], None
            for _ in range(5):
                t0 = time.perf_counter()
                r = subprocess.run([a.spt, "import", src, "-o", out, "--reference", png], capture_output=True, text=True)
                times.append((time.perf_counter() - t0) * 1000)
                if r.returncode != 0:
                    print(f, "failed:", r.stderr.strip()); break
                m = re.search(r"PSNR against .*: ([0-9.]+|inf)", r.stdout)
                psnr = float(m.group(1)) if m else None
            else:
                size = os.path.getsize(out)
                svg = os.path.join(folder, stem + ".svg")
                js = os.path.join(folder, stem + ".json")
                svg_raw = os.path.getsize(svg) if os.path.exists(svg) else 0
                svg_xz = xz(svg) if svg_raw else 0
                js_raw = os.path.getsize(js) if os.path.exists(js) else 0
                js_xz = xz(js) if js_raw else 0
                ratio = svg_xz / size if svg_xz else float("nan")
                worst_ratio = min(worst_ratio, ratio)
                worst_psnr = min(worst_psnr, psnr if psnr is not None else 0)
                rows += 1
                h0 = order0_bytes(js) if js_raw else None
                print(f"{f:36} {size:6d} {svg_raw:7d} {svg_xz:7d} {js_raw or '-':>7} {js_xz or '-':>7} {ratio:10.2f} "
                      f"{psnr if psnr is not None else float('nan'):8.2f} {statistics.median(times):6.1f} "
                      f"{f'{h0:.0f}' if h0 else '-':>6} {svg_xz / 3 if svg_xz else float('nan'):8.0f}")
    print(f"\nworst svg.xz/spt ratio {worst_ratio:.2f} (target >= 3): {'met' if worst_ratio >= 3 else 'MISSED'}")
    print(f"worst PSNR {worst_psnr:.2f} dB (target >= 40): {'met' if worst_psnr >= 40 else 'MISSED'}")
    return 0 if rows else 1

if __name__ == "__main__":
    sys.exit(main())
