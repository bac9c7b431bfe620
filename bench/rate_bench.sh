#!/usr/bin/env bash
# Rate bench: bytes per stroke per coding mode, rate-distortion curves with the JPEG XL lossless
# ratio, and spt at the byte sizes of primitive's and geometrize's outputs (xz -9).
# Usage: bench/rate_bench.sh [BUILD_DIR]   (needs bench/rate_codec, bin/spt, cjxl, xz)
set -euo pipefail
BUILD=${1:-build-rate}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MEDIA=${SPT_MEDIA:-$ROOT/../shared/media}
CODEC=$BUILD/bench/rate_codec
SPT=$BUILD/bin/spt
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

echo "== bytes per stroke and RD curve (lambda sweep, colour step 4, edges orientation)"
echo "   command: $CODEC IMAGE --lambda 8,16,32,64,128 --color-step 4 --jxl"
FR=()
for f in "$MEDIA"/foreign/coffee-256.png "$MEDIA"/stills/*; do
  "$CODEC" "$f" --lambda 8,16,32,64,128 --color-step 4 --jxl --tmp "$TMP" | tee -a "$TMP/rd.txt"
done
# 1280x720 frames from the clips
for v in "$MEDIA"/video/*; do
  ffmpeg -loglevel error -y -i "$v" -vf "select=eq(n\,30),scale=1280:720" -frames:v 1 "$TMP/frame_$(basename "$v").png"
  "$CODEC" "$TMP/frame_$(basename "$v").png" --lambda 16,64 --color-step 4 --jxl --tmp "$TMP" | tee -a "$TMP/rd.txt"
done
echo
echo "== medians over images (per lambda)"
python3 - "$TMP/rd.txt" <<'PY'
import sys, statistics, collections
rows = collections.defaultdict(list)
for line in open(sys.argv[1]):
    t = line.split()
    kv = {t[i]: t[i+1] for i in range(2, len(t) - 1) if t[i] in ("lambda","strokes","psnr","Bps_c1","Bps_c2","frameBps_c2","jxl_ratio","bytes_c2")}
    rows[float(kv["lambda"])].append(kv)
print("lambda  images  psnr   B/stroke c1  B/stroke c2  frame B/stroke c2  jxl/spt")
for l in sorted(rows):
    r = rows[l]; med = lambda k: statistics.median(float(x[k]) for x in r if k in x)
    print(f"{l:6g} {len(r):6d} {med('psnr'):6.2f} {med('Bps_c1'):12.3f} {med('Bps_c2'):12.3f} {med('frameBps_c2'):18.3f} {med('jxl_ratio'):8.2f}")
PY

echo
echo "== bytes at 28 dB (spt paint --target-psnr 28, coding 1 vs 2)"
for f in "$MEDIA"/foreign/coffee-256.png "$MEDIA"/stills/*.png; do
  for c in 1 2; do
    "$SPT" paint "$f" -o "$TMP/p.spt" --progress none --target-psnr 28 --coding $c 2>&1 | sed "s|^|coding $c: |"
  done
done

echo
echo "== equal bytes against primitive and geometrize (coffee-256; their SVG/JSON with xz -9)"
C=$MEDIA/foreign/coffee-256.png
for g in "$MEDIA"/foreign/coffee-*.svg "$MEDIA"/foreign/coffee-*.json; do
  [ -e "$g" ] || continue
  bytes=$(xz -9 -c "$g" | wc -c)
  png=${g%.*}.png
  theirs=$("$SPT" compare "$C" "$png" 2>/dev/null | grep -io 'psnr[^0-9]*[0-9.]*' | head -1 | grep -o '[0-9.]*$' || echo "?")
  out=$("$SPT" paint "$C" -o "$TMP/eq.spt" --progress none --target-bytes "$bytes" 2>&1 | tr '\n' ' ')
  ours=$(echo "$out" | grep -o '[0-9.]* dB PSNR' | head -1)
  echo "$(basename "$g"): xz ${bytes} B, their PSNR ${theirs} dB | spt: $(stat -c %s "$TMP/eq.spt") B, ${ours}"
done
