"""Writes the add-on bench file: 1920x1080, 20,000 strokes a frame over 100 frames, stored mode,
made with the add-on's Python writer. Frame 0 is a key frame; each later frame removes 1,000
strokes, moves the rest with a block motion field (every stroke moves: the worst case for the
importer) and adds 1,000. With a polygon share P (0..1), that share of the strokes are polygons
(format 1.2, 3..12 vertices, spt_samples.random_polygon) instead of stamps.
usage: python3 blender_bench_make.py OUT.spt [frames] [strokes] [polygon_share]"""

import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "blender"))
import spt_samples  # noqa: E402
from spt_grease_pencil.io.model import INTER, KEY, Frame, Motion  # noqa: E402
from spt_grease_pencil.io.writer import write_stored  # noqa: E402

out = sys.argv[1]
nframes = int(sys.argv[2]) if len(sys.argv) > 2 else 100
per = int(sys.argv[3]) if len(sys.argv) > 3 else 20000
share = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
churn = per // 20
rng = random.Random(1)
inf = spt_samples.info(width=1920, height=1080, sets=((96, 48), (64, 32), (40, 20), (24, 12), (12, 6), (6, 3)))
W, H = inf.header.width, inf.header.height


def stamp(set_index):
    if share and rng.random() < share:
        return spt_samples.random_polygon(rng, inf)
    return (0, set_index, rng.randrange(3), rng.randrange(8), rng.randrange(16 * W), rng.randrange(16 * H),
            rng.randrange(256), rng.randrange(256), rng.randrange(256), 255)


frames = [Frame(0, KEY, added=[stamp(min(5, i * 6 // per)) for i in range(per)])]
bs = 32
cols, rows = -(-W // bs), -(-H // bs)
for fi in range(1, nframes):
    removed = sorted(rng.sample(range(per), churn))
    mv = Motion(bs, cols, rows, [(rng.randrange(-4, 5), rng.randrange(-4, 5)) for _ in range(cols * rows)])
    frames.append(Frame(fi, INTER, removed=removed, motion=mv, added=[stamp(rng.randrange(6)) for _ in range(churn)]))
if share:
    inf.header.version_minor = 2  # polygon strokes are format 1.2
n = write_stored(out, inf, frames)
print(f"wrote {out}: {nframes} frames x {per} strokes, {n / 1e6:.1f} MB stored")
