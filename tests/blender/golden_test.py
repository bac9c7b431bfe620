"""Cross-check of the spec: the add-on's bpy-free reader decodes every golden stored file of
tests/format/golden/ (written by libspt), and with numpy its fast path gives the same strokes
(CTest runs it with python3 and again inside Blender, whose Python has numpy). Exit 1
when there are none yet."""

import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "blender_addon"))
from spt_grease_pencil.io import SptError, read_file  # noqa: E402
sys.path.insert(0, HERE)
from reference import ref_reader  # noqa: E402  (the one-tuple-per-stroke oracle)

try:
    import numpy as np
except ImportError:  # the reference reader alone
    np = None

golden = sorted(glob.glob(os.path.join(HERE, "..", "format", "golden", "*.stored.spt")))
if not golden:
    print("FAIL: no tests/format/golden/*.stored.spt yet")
    sys.exit(1)
bad = 0
print("numpy fast path:", "checked" if np is not None else "not available (reference reader only)")
for p in golden:
    name = os.path.basename(p)
    expect_error = name.startswith(("bad", "corrupt", "invalid"))
    try:
        f = read_file(p)
        counts = [len(lst) for lst in f.live_lists()]
        ok = f.complete or "truncated" in name or "incomplete" in name
        print(f"{name}: {f.info.header.width}x{f.info.header.height}, {len(f.frames)} frames, "
              f"{sum(counts)} live strokes in all, complete={f.complete}")
        if expect_error or not ok:
            print(f"  FAIL: {name} should {'fail' if expect_error else 'be complete'}")
            bad += 1
        if np is not None:  # the numpy fast path (polygons included) must agree
            fc = read_file(p, columnar=True)
            if [t.to_tuples() for t in fc.live_lists()] != list(f.live_lists()):
                print(f"  FAIL: {name}: the numpy reader disagrees with the reference")
                bad += 1
        if list(ref_reader.read_file(p).live_lists()) != list(f.live_lists()):
            print(f"  FAIL: {name}: the reader disagrees with the tuple oracle (tests/blender/reference)")
            bad += 1
    except SptError as e:
        print(f"{name}: error: {e}")
        if not expect_error:
            bad += 1
sys.exit(1 if bad else 0)
