#!/usr/bin/env bash
# The web player against native: ms a frame in order and at random seeks, WebAssembly in
# headless Chromium (bench/web_bench.mjs, through the page `spt export` writes) against
# Reader::render_frame (bench/play_bench.cpp), at 640x360 and 1280x720, default coding and
# stored mode; the frames shown when the page plays the clip once at its fps; and the sizes
# of the page and of the WebAssembly module (gzip -9 too).
#   bench/web_bench.sh [BUILD_DIR] [passes]      (needs npm ci in tests/web; ./setup.sh test)
# Clips: 48 frames of city.mpg scaled with ffmpeg, painted with the defaults and key frames
# every 24 frames; made once into BUILD_DIR/bench_web/.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-$here/../build}" && pwd)"
passes="${2:-5}"
media="${SPT_MEDIA_DIR:-$here/../../shared/media}"
spt="$build/bin/spt"
work="$build/bench_web"
mkdir -p "$work"
for t in "$spt" "$build/bench/play_bench" "$build/web/player/spt_core.wasm"; do
  [ -e "$t" ] || { echo "web_bench: $t is missing (build spt_cli, play_bench and spt_web)" >&2; exit 1; }
done

for size in 640x360 1280x720; do
  clip="$work/city-$size.spt"
  if [ ! -f "$clip" ]; then
    mkdir -p "$work/f$size"
    ffmpeg -loglevel error -y -i "$media/video/city.mpg" -frames:v 48 -vf "scale=${size/x/:}:flags=bicubic" "$work/f$size/f.%04d.png"
    "$spt" paint "$work/f$size/f.####.png" -o "$clip" --keyframe-interval 24 --fps 25 --seed 1 --progress none
  fi
  [ -f "$work/city-$size-stored.spt" ] || "$spt" pack "$clip" -o "$work/city-$size-stored.spt" --stored >/dev/null
done

field() { python3 -c "import json,sys; print(json.loads(sys.argv[1])[sys.argv[2]])" "$1" "$2"; }
gz() { gzip -9c "$1" | wc -c; }

echo "| clip | frames | native in order | wasm in order | ratio | native random | wasm random | ratio | frames shown playing once |"
echo "|---|---|---|---|---|---|---|---|---|"
for size in 640x360 1280x720; do
  for mode in "" -stored; do
    clip="$work/city-$size$mode.spt"
    page="$work/city-$size$mode.html"
    "$spt" export "$clip" -o "$page"
    n=$("$build/bench/play_bench" "$clip" "$passes")
    w=$(node "$here/web_bench.mjs" "$page" "$passes")
    python3 - "$size${mode:- default}" "$n" "$w" <<'PY'
import json, sys
name, n, w = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
print(f"| {name.replace('-stored', ' stored')} | {n['frames']} | {n['in_order_ms']:.2f} ms | {w['in_order_ms']:.2f} ms | "
      f"{w['in_order_ms'] / n['in_order_ms']:.1f} | {n['random_ms']:.2f} ms | {w['random_ms']:.2f} ms | "
      f"{w['random_ms'] / n['random_ms']:.1f} | {w['played']} of {w['frames']} |")
PY
  done
done

echo
echo "| file | bytes | gzip -9 |"
echo "|---|---|---|"
wasm="$build/web/player/spt_core.wasm"
echo "| spt_core.wasm | $(stat -c %s "$wasm") | $(gz "$wasm") |"
for f in spt-core.js spt-player.js; do
  echo "| $f | $(stat -c %s "$build/web/player/$f") | $(gz "$build/web/player/$f") |"
done
for size in 640x360 1280x720; do
  for mode in "" -stored; do
    clip="$work/city-$size$mode.spt"
    page="$work/city-$size$mode.html"
    echo "| city-$size$mode.spt | $(stat -c %s "$clip") | $(gz "$clip") |"
    echo "| city-$size$mode.html (page) | $(stat -c %s "$page") | $(gz "$page") |"
  done
done
