#!/bin/sh
# Blender's render of an imported painting against spt render, in each Blender version:
#   bench/blender_render_compare.sh [BUILD_DIR] [IMAGE] [versions]
# paints IMAGE (default ../shared/media/stills/coffee.png, scaled by spt to its own size) with
# the default painter, imports it in each Blender and renders frame 0 with EEVEE.
set -e
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
image=${2:-$here/../../shared/media/stills/coffee.png}
versions=${3:-3.4 4.3 5.2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/spt" paint "$image" -o "$work/painting.spt" --seed 1 --progress plain >/dev/null
for v in $versions; do
  SPT_EXTRA_MOUNTS=$work SPT_BENCH_FILE=$work/painting.spt \
    "$here/../tests/blender/run_blender.sh" "$v" "$here/blender_render_compare.py" \
    "$build/spt_grease_pencil.zip" "$build/bin/spt" "$work/run-$v" >"$work/log" 2>&1 \
    || { cat "$work/log"; exit 1; }
  grep BENCH "$work/log"
done
