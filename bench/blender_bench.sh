#!/bin/sh
# Add-on bench: import and export of 20,000 strokes a frame over 100 frames (1920x1080), each in
# its own Blender process so /usr/bin/time -v gives each one's peak memory, in every Blender the
# add-on supports (3.4 on the host; 4.3 and 5.2 in the roots of tests/blender/blender_root.sh).
# Targets (5.2): import < 15 s, export < 15 s, import memory < 3 GB (the operators' code paths:
# the import includes `spt pack --stored`, the export `spt pack`).
# usage: bench/blender_bench.sh [BUILD_DIR] [frames] [strokes] [polygon_share] [versions]
#   polygon_share (0..1, default 0): that share of the strokes are polygons (format 1.2), imported
#   as closed fill-only Grease Pencil strokes. versions: default "3.4 4.3 5.2".
set -e
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
frames=${2:-100}
strokes=${3:-20000}
share=${4:-0}
versions=${5:-3.4 4.3 5.2}
zip=$build/spt_grease_pencil.zip
spt=$build/bin/spt
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -f "$zip" ] || { echo "no $zip: build the default target first" >&2; exit 1; }
[ -x "$spt" ] || { echo "no $spt: build spt_cli first" >&2; exit 1; }
# The add-on's file layer needs numpy: Debian's python3 (python3-numpy) before any other on PATH.
py=python3; [ -x /usr/bin/python3 ] && py=/usr/bin/python3
"$py" "$here/tools/blender_bench_make.py" "$work/bench.stored.spt" "$frames" "$strokes" "$share"
# The file users have: range-coded by spt pack.
"$spt" pack "$work/bench.stored.spt" -o "$work/bench.spt" >/dev/null
ls -l "$work/bench.stored.spt" "$work/bench.spt" | awk '{print "file:", $NF, $5, "bytes"}'
run() {
  SPT_EXTRA_MOUNTS=$work SPT_BENCH_FILE=$work/bench.spt SPT_BENCH_MODE=$2 /usr/bin/time -v \
    "$here/../tests/blender/run_blender.sh" "$1" "$here/blender_bench.py" "$zip" "$spt" "$work/run" \
    >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
  grep BENCH "$work/log"
  grep -E "Maximum resident|Elapsed \(wall|User time|System time" "$work/log" | sed 's/^\s*/  /'
}
for v in $versions; do
  echo "== Blender $v: import (blender process: start-up + import)"; run "$v" import
  echo "== Blender $v: export (blender process: start-up + import + export)"; run "$v" export
done
