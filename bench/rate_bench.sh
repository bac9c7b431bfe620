#!/usr/bin/env bash
# Rate bench: bytes per stroke and bytes at 28 dB per coding mode, rate-distortion curves with
# the JPEG XL lossless ratio, and spt at the byte sizes of primitive's and geometrize's outputs.
# Usage: bench/rate_bench.sh [BUILD_DIR]   (needs bench/rate_codec, bin/spt, cjxl, xz, ffmpeg)
# Images: foreign/coffee-256.png, stills/*, and frame 30 of each clip in video/ at 1280x720.
set -euo pipefail
BUILD=${1:-build-rate}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MEDIA=${SPT_MEDIA:-$ROOT/../shared/media}
CODEC=$BUILD/bench/rate_codec
SPT=$BUILD/bin/spt
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
source "$ROOT/bench/tools/rate_images.sh" "$TMP"
LAMBDAS=${LAMBDAS:-8,16,24,48,96}

echo "== 1. bytes at 28 dB, coding 1 and 2 (the painter's defaults at 28 dB: lambda 24, colour step 12)"
echo "   command: $CODEC IMAGE --target-psnr 28 --lambda 24 --color-step 12"
for f in "${STILLS[@]}" "${FRAMES[@]}"; do
  "$CODEC" "$f" --target-psnr 28 --lambda 24 --color-step 12 --tmp "$TMP" | tee -a "$TMP/at28.txt"
done

echo
echo "== 2. RD curve (lambda sweep, colour step 12, converged paints) with the JPEG XL lossless ratio"
echo "   command: $CODEC IMAGE --lambda $LAMBDAS --color-step 12 --jxl"
for f in "${STILLS[@]}" "${FRAMES[@]}"; do
  "$CODEC" "$f" --lambda "$LAMBDAS" --color-step 12 --jxl --tmp "$TMP" | tee -a "$TMP/rd.txt"
done

python3 - "$TMP/at28.txt" "$TMP/rd.txt" <<'PY'
import sys, statistics, collections
def rows(path):
    out = []
    for line in open(path):
        t = line.split()
        kv = {t[i]: t[i + 1] for i in range(2, len(t) - 1)}
        kv["image"], kv["size"] = t[0], t[1]
        out.append(kv)
    return out
med = lambda xs: statistics.median(xs) if xs else float("nan")
big = lambda r: r["size"] == "1280x720"
print("\n-- 28 dB: medians (stills = coffee-256 and stills/*; 720p = clip frames)")
print("group    images  strokes   bytes_c1   bytes_c2  B/stroke_c1  B/stroke_c2  frame B/stroke_c2")
at = rows(sys.argv[1])
for name, sel in (("stills", lambda r: not big(r)), ("720p", big), ("all", lambda r: True)):
    r = [x for x in at if sel(x)]
    f = lambda k: med([float(x[k]) for x in r])
    print(f"{name:8s} {len(r):6d} {f('strokes'):8.0f} {f('bytes_c1'):10.0f} {f('bytes_c2'):10.0f} {f('Bps_c1'):12.3f} {f('Bps_c2'):12.3f} {f('frameBps_c2'):18.3f}")
print("\n-- RD curve: medians per lambda (all images)")
print("lambda  images   psnr   bytes_c2  B/stroke_c1  B/stroke_c2  jxl_bytes  jxl/spt")
rd = collections.defaultdict(list)
for x in rows(sys.argv[2]): rd[float(x["lambda"])].append(x)
for l in sorted(rd):
    r = rd[l]; f = lambda k: med([float(x[k]) for x in r if k in x])
    print(f"{l:6g} {len(r):7d} {f('psnr'):6.2f} {f('bytes_c2'):10.0f} {f('Bps_c1'):12.3f} {f('Bps_c2'):12.3f} {f('jxl'):10.0f} {f('jxl_ratio'):8.2f}")
PY

echo
echo "== 3. equal bytes against primitive and geometrize (coffee-256; their SVG/JSON with xz -9)"
echo "   command: $SPT paint coffee-256.png -o OUT --target-bytes BYTES; $SPT compare coffee-256.png THEIR.png"
C=$MEDIA/foreign/coffee-256.png
for g in "$MEDIA"/foreign/coffee-*.svg "$MEDIA"/foreign/coffee-*.json; do
  [ -e "$g" ] || continue
  bytes=$(xz -9 -c "$g" | wc -c)
  png=${g%.*}.png
  theirs=$("$SPT" compare "$C" "$png" 2>/dev/null | grep -o 'PSNR [0-9.]*' | head -1 | cut -d' ' -f2)
  out=$("$SPT" paint "$C" -o "$TMP/eq.spt" --progress none --target-bytes "$bytes" 2>&1 | tr '\n' ' ')
  ours=$(echo "$out" | grep -o '[0-9.]* dB PSNR' | head -1 | cut -d' ' -f1)
  echo "$(basename "$g") xz_bytes $bytes their_psnr $theirs spt_bytes $(stat -c %s "$TMP/eq.spt") spt_psnr $ours" | tee -a "$TMP/eq.txt"
done
python3 - "$TMP/eq.txt" <<'PY'
import sys, statistics
r = [l.split() for l in open(sys.argv[1])]
d = [float(x[8]) - float(x[4]) for x in r]
print(f"-- median over {len(r)} outputs: spt PSNR - their PSNR at equal bytes = {statistics.median(d):+.2f} dB (min {min(d):+.2f})")
PY
