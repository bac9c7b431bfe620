#!/usr/bin/env python3
"""How small can an exact import of geometrize's shapes be? An optimistic estimate per sample,
set against issue 6's size budget (the xz-compressed SVG / 3) and the size spt reaches.

usage: bench/import_bound.py [--spt build/bin/spt] [--media ../shared/media]
Needs numpy (Debian: python3-numpy; /usr/bin/python3 has it where blender is installed).

An exact import must keep every number geometrize wrote (its JSON is integers: any change
moves pixels). The estimate charges each number the least of several costs, each of them
free of model cost and therefore below what a real coder pays:
  - geometry and position: each field's empirical order-0 entropy in this very file (the
    decoder is handed the field's exact histogram for nothing; with 300 values a field of
    256 possible values looks less random than it is, so this is low);
  - colour: the least of (a) the order-0 entropy of r, g, b, (b) that of g, r - g, b - g,
    (c) that of the residual g, r - g, b - g against the mean colour of the canvas under the
    shape just before it is drawn (what a decoder knows: the canvas; geometrize picks the
    colour that moves that canvas towards the target), and (d) an adaptive Laplace model of
    that residual;
  - nothing for the container (header, templates, chunk framing, index).
The canvas under each shape comes from a float re-rendering of geometrize's shapes (27-33 dB
against the tool's own PNG): close enough to predict from.
"""
import collections, json, math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "tools"))  # foreign_samples
from foreign_samples import entropy_bits, parse_args, xz_bytes

try:
    import numpy as np
except ImportError:
    sys.exit("import_bound.py needs numpy (Debian: apt-get install python3-numpy; or run it with /usr/bin/python3)")

def laplace_bits(values):
    """Adaptive two-sided geometric model with a running mean |v| as its scale."""
    total, n, bits = 8.0, 1, 0.0
    for v in values:
        b = max(total / n, 0.3)
        p = (1 - math.exp(-1 / b)) / (1 + math.exp(-1 / b)) * math.exp(-abs(v) / b)
        bits -= math.log2(max(p, 1e-12))
        total += abs(v); n += 1
    return bits

def shape_mask(kind, d, xx, yy):
    """Pixels of one geometrize shape (type codes of geometrize's JSON export)."""
    if kind == 1:  # rectangle x1 y1 x2 y2
        return (xx >= min(d[0], d[2])) & (xx <= max(d[0], d[2])) & (yy >= min(d[1], d[3])) & (yy <= max(d[1], d[3]))
    if kind == 2:  # rotated rectangle x1 y1 x2 y2 angle(deg) about its centre
        a = math.radians(d[4]); dx = xx - (d[0] + d[2]) / 2; dy = yy - (d[1] + d[3]) / 2
        u = dx * math.cos(a) + dy * math.sin(a); v = -dx * math.sin(a) + dy * math.cos(a)
        return (abs(u) <= abs(d[2] - d[0]) / 2) & (abs(v) <= abs(d[3] - d[1]) / 2)
    if kind == 4:  # triangle x1 y1 x2 y2 x3 y3
        def side(px, py, qx, qy): return (xx - qx) * (py - qy) - (px - qx) * (yy - qy)
        s1 = side(d[0], d[1], d[2], d[3]); s2 = side(d[2], d[3], d[4], d[5]); s3 = side(d[4], d[5], d[0], d[1])
        return ~(((s1 < 0) | (s2 < 0) | (s3 < 0)) & ((s1 > 0) | (s2 > 0) | (s3 > 0)))
    if kind in (8, 16):  # ellipse x y rx ry [angle]
        a = math.radians(d[4]) if kind == 16 else 0.0; dx = xx - d[0]; dy = yy - d[1]
        u = (dx * math.cos(a) + dy * math.sin(a)) / max(d[2], 1); v = (-dx * math.sin(a) + dy * math.cos(a)) / max(d[3], 1)
        return u * u + v * v <= 1
    if kind == 32:  # circle x y r
        return (xx - d[0]) ** 2 + (yy - d[1]) ** 2 <= d[2] ** 2
    raise ValueError(f"geometrize shape type {kind}")

def analyse(shapes, background, height, width):
    yy, xx = np.mgrid[0:height, 0:width]
    canvas = np.zeros((height, width, 3)) + np.array(background, float)
    fields = collections.defaultdict(list)
    raw, resid = [[], [], []], [[], [], []]
    for sh in shapes:
        kind, d, col = sh["type"], sh["data"], sh["color"]
        for i, v in enumerate(d):
            fields[(kind, i)].append(v)
        m = shape_mask(kind, d, xx, yy)
        under = canvas[m].mean(0) if m.any() else canvas.reshape(-1, 3).mean(0)
        for k in range(3):
            raw[k].append(col[k]); resid[k].append(int(round(col[k] - under[k])))
        a = col[3] / 255
        canvas[m] = canvas[m] * (1 - a) + np.array(col[:3], float) * a
    fields[("alpha",)] = [sh["color"][3] for sh in shapes]
    n = len(shapes)
    def chroma(c): return [c[1], [c[0][i] - c[1][i] for i in range(n)], [c[2][i] - c[1][i] for i in range(n)]]
    colour = {
        "rgb": sum(entropy_bits(raw[k]) for k in range(3)),
        "g,r-g,b-g": sum(entropy_bits(v) for v in chroma(raw)),
        "canvas residual": sum(entropy_bits(v) for v in chroma(resid)),
        "canvas residual, Laplace": sum(laplace_bits(v) for v in chroma(resid)),
    }
    geometry = sum(entropy_bits(v) for v in fields.values())
    return geometry, colour, canvas

def main():
    a, folder = parse_args(__doc__)
    samples = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json")) if os.path.isdir(folder) else []
    if not samples:
        print("no geometrize JSON samples in", folder); return 1
    print(f"{'sample':32} {'shapes':>6} {'fields B':>8} {'colour b/shape (rgb / chroma / canvas / Laplace)':>50} "
          f"{'bound B':>7} {'svg.xz/3':>8} {'bound/budget':>12} {'spt B':>6}")
    over = 0
    with tempfile.TemporaryDirectory() as tmp:
        for stem in samples:
            js, svg, png = (os.path.join(folder, stem + e) for e in (".json", ".svg", ".png"))
            out = os.path.join(tmp, stem + ".spt")
            r = subprocess.run([a.spt, "import", js, "--reference", png, "-o", out, "-q"], capture_output=True, text=True)
            if r.returncode != 0:
                print(stem, "import failed:", r.stderr.strip()); return 1
            info = json.loads(subprocess.run([a.spt, "info", "--json", "--no-fields", out], capture_output=True, text=True).stdout)
            with open(js) as f:
                shapes = json.load(f)["shapes"]
            geometry, colour, _ = analyse(shapes, info["background"], info["canvas"]["height"], info["canvas"]["width"])
            n = len(shapes)
            best = min(colour.values())
            bound = (geometry + best) / 8
            budget = xz_bytes(svg) / 3
            over += bound > budget
            cols = " / ".join(f"{v / n:5.2f}" for v in colour.values())
            print(f"{stem:32} {n:6d} {geometry / 8:8.0f} {cols:>50} {bound:7.0f} {budget:8.0f} {bound / budget:12.2f} "
                  f"{os.path.getsize(out):6d}")
    print(f"\n{over} of {len(samples)} samples: even this estimate exceeds the 3x budget (bound/budget > 1), "
          "so no exact import of them can meet it")
    return 0

if __name__ == "__main__":
    sys.exit(main())
