#!/bin/sh
# Add-on bench: import and export of 20,000 strokes a frame over 100 frames (1920x1080), each in
# its own Blender process so /usr/bin/time -v gives each one's peak memory.
# Targets: import < 15 s, export < 15 s (the operators' code paths: the import includes
# `spt pack --stored`, the export `spt pack`).
# usage: bench/blender_bench.sh [BUILD_DIR] [frames] [strokes] [polygon_share]
#   polygon_share (0..1, default 0): that share of the strokes are polygons (format 1.2), imported
#   as closed fill-only Grease Pencil strokes.
set -e
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
frames=${2:-100}
strokes=${3:-20000}
share=${4:-0}
zip=$build/spt_grease_pencil.zip
spt=$build/bin/spt
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -f "$zip" ] || { echo "no $zip: build the default target first" >&2; exit 1; }
[ -x "$spt" ] || { echo "no $spt: build spt_cli first" >&2; exit 1; }
python3 "$here/blender_bench_make.py" "$work/bench.stored.spt" "$frames" "$strokes" "$share"
# The file users have: range-coded by spt pack.
"$spt" pack "$work/bench.stored.spt" -o "$work/bench.spt" >/dev/null
ls -l "$work/bench.stored.spt" "$work/bench.spt" | awk '{print "file:", $NF, $5, "bytes"}'
run() {
  HOME=$work/home /usr/bin/time -v blender -b --factory-startup --python-exit-code 1 \
    --python "$here/blender_bench.py" -- "$zip" "$spt" "$work/bench.spt" "$work" "$@" >"$work/log" 2>&1 \
    || { cat "$work/log"; exit 1; }
  grep BENCH "$work/log"
  grep -E "Maximum resident|Elapsed \(wall|User time|System time" "$work/log" | sed 's/^\s*/  /'
}
echo "== import (blender process: start-up + import)"; run import
echo "== export (blender process: start-up + import + export)"; run export
