#!/bin/sh
# Add-on bench: import and export of 20,000 strokes a frame over 100 frames (1920x1080).
# Prints times and peak memory (/usr/bin/time -v). Targets: import < 15 s, export < 15 s.
# usage: bench/blender_bench.sh [BUILD_DIR] [frames] [strokes]
set -e
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
frames=${2:-100}
strokes=${3:-20000}
zip=$build/spt_grease_pencil.zip
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -f "$zip" ] || { echo "no $zip: build the default target first" >&2; exit 1; }
python3 "$here/blender_bench_make.py" "$work/bench.spt" "$frames" "$strokes"
run() {
  HOME=$work/home /usr/bin/time -v blender -b --factory-startup --python-exit-code 1 \
    --python "$here/blender_bench.py" -- "$zip" "$work/bench.spt" "$work" "$@" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
  grep BENCH "$work/log"
  grep -E "Maximum resident|Elapsed \(wall" "$work/log"
}
echo "== import only"; run
echo "== import + export"; run export
