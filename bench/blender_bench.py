"""Times the add-on's import and export inside Blender (run by blender_bench.sh).
args after --: ZIP FILE.spt WORKDIR [export]"""

import os
import sys
import time

import bpy

zip_path, path, work = sys.argv[sys.argv.index("--") + 1:][:3]
do_export = "export" in sys.argv[sys.argv.index("--") + 1:]
import addon_utils  # noqa: E402
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
addon_utils.enable("spt_grease_pencil", default_set=True)
from spt_grease_pencil.blender import exporter, importer  # noqa: E402
from spt_grease_pencil.io import read_file  # noqa: E402

t0 = time.time()
f = read_file(path)
lists = list(f.live_lists())
t1 = time.time()
print(f"BENCH read+state (python file layer): {t1 - t0:.2f} s for {sum(map(len, lists))} strokes")
del lists, f
t0 = time.time()
obj, summary = importer.import_file(bpy.context, path)
t1 = time.time()
print(f"BENCH import: {t1 - t0:.2f} s, {summary['strokes']} strokes, {summary['frames']} frames")
if do_export:
    out = os.path.join(work, "bench_export.stored.spt")
    t0 = time.time()
    s = exporter.export_file(bpy.context, obj, out, stored=True)
    t1 = time.time()
    print(f"BENCH export (stored, no pack): {t1 - t0:.2f} s, {s['strokes']} strokes")
    same = [len(x) for x in read_file(out).live_lists()] == [len(x) for x in read_file(path).live_lists()]
    print(f"BENCH export matches the input stroke counts: {same}")
