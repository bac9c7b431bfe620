#!/usr/bin/env bash
# Chooses the painter's default lambda and colour step by measurement: paints every image to
# 28 dB (--target-psnr 28) for each (lambda, colour step) and prints the coding-2 frame bytes
# (templates excluded: they do not depend on lambda), then the median over images of each
# point's bytes relative to the best point of its image (1.000 = best everywhere).
# Usage: bench/rate_sweep.sh [BUILD_DIR] [LAMBDAS] [STEPS]
#   defaults: build-rate, "4 8 16 32 64 128", "1 2 4 6 8"
set -euo pipefail
BUILD=${1:-build-rate}
LAMBDAS=${2:-"4 8 16 32 64 128"}
STEPS=${3:-"1 2 4 6 8"}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MEDIA=${SPT_MEDIA:-$ROOT/../shared/media}
CODEC=$BUILD/bench/rate_codec
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
source "$ROOT/bench/tools/rate_images.sh" "$TMP"
echo "command: $CODEC IMAGE --target-psnr 28 --lambda L --color-step Q"
for img in "${IMAGES[@]}"; do
  for q in $STEPS; do
    for l in $LAMBDAS; do
      "$CODEC" "$img" --target-psnr 28 --lambda "$l" --color-step "$q" --tmp "$TMP" | sed "s/^/step $q /" | tee -a "$TMP/sweep.txt"
    done
  done
done
python3 - "$TMP/sweep.txt" <<'PY'
import sys, statistics, collections
pts = collections.defaultdict(dict)   # image -> (lambda, step) -> (frame bytes, psnr, strokes)
for line in open(sys.argv[1]):
    t = line.split()
    kv = {t[i]: t[i + 1] for i in range(len(t) - 1)}
    n = float(kv["strokes"])
    fb = float(kv["frameBps_c2"]) * n
    pts[t[2]][(float(kv["lambda"]), int(kv["step"]))] = (fb, float(kv["psnr"]), n, float(kv["Bps_c2"]))
keys = sorted({k for p in pts.values() for k in p})
print("\nmedian over %d images of frame bytes at 28 dB relative to the image's best point" % len(pts))
print("lambda step  rel_bytes  B/stroke(frame)  strokes(median)")
for k in keys:
    rel = [p[k][0] / min(v[0] for v in p.values()) for p in pts.values() if k in p]
    bps = [p[k][0] / p[k][2] for p in pts.values() if k in p]
    st = [p[k][2] for p in pts.values() if k in p]
    print(f"{k[0]:6g} {k[1]:4d} {statistics.median(rel):10.3f} {statistics.median(bps):16.3f} {statistics.median(st):16.0f}")
PY
