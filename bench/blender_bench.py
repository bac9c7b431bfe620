"""Times the add-on's import and export inside Blender (run by blender_bench.sh through
tests/blender/run_blender.sh, in each Blender version).
args after --: ZIP SPT WORKDIR [MEDIA]; the environment gives SPT_BENCH_FILE (the .spt to import)
and SPT_BENCH_MODE (import | export)."""

import os
import sys
import time

import bpy

zip_path, spt, work = sys.argv[sys.argv.index("--") + 1:][:3]
path, mode = os.environ["SPT_BENCH_FILE"], os.environ["SPT_BENCH_MODE"]
import addon_utils  # noqa: E402
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
addon_utils.enable("spt_grease_pencil", default_set=True)
from spt_grease_pencil.blender import exporter, importer  # noqa: E402


def fmt(d):
    return ", ".join(f"{k} {v:.2f} s" for k, v in d.items())


t0, c0 = time.perf_counter(), time.process_time()
obj, summary = importer.import_file(bpy.context, path, spt)
t1, c1 = time.perf_counter(), time.process_time()
print(f"BENCH import: {t1 - t0:.2f} s wall, {c1 - c0:.2f} s CPU in Blender ({fmt(summary['seconds'])}), "
      f"{summary['strokes']} strokes, {summary['frames']} frames, {summary['layers']} layers")
if mode == "export":
    out = os.path.join(work, "bench_export.spt")
    t0, c0 = time.perf_counter(), time.process_time()
    s = exporter.export_file(bpy.context, obj, out, spt)
    t1, c1 = time.perf_counter(), time.process_time()
    print(f"BENCH export: {t1 - t0:.2f} s wall, {c1 - c0:.2f} s CPU in Blender ({fmt(s['seconds'])}), "
          f"{s['strokes']} strokes, {os.path.getsize(out)} bytes (input {os.path.getsize(path)})")
    # Check: the export holds the imported strokes (stroke lists, through spt pack --stored).
    from spt_grease_pencil.io import read_file  # noqa: E402
    from spt_grease_pencil.spt_tool import pack_stored  # noqa: E402
    a, b = os.path.join(work, "a.stored.spt"), os.path.join(work, "b.stored.spt")
    pack_stored(spt, path, a)
    pack_stored(spt, out, b)
    la = list(read_file(a, columnar=True).live_lists())
    lb = list(read_file(b, columnar=True).live_lists())
    same = len(la) == len(lb) and all(x.rows.shape == y.rows.shape and (x.rows == y.rows).all() for x, y in zip(la, lb))
    print(f"BENCH export holds the same stroke lists as the input: {same}")
