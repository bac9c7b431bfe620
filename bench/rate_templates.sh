#!/usr/bin/env bash
# Template header cost against painting quality: builds template sets with
# converter/tools/make_templates.py (--size N) and paints every image to 28 dB with each,
# printing total coding-2 bytes (templates included) and the templates' share. A file named
# *rectangle* / *ellipse* becomes the analytic kind (bench/rate_codec --templates).
# Usage: bench/rate_templates.sh [BUILD_DIR] [LAMBDA] [STEP]   (defaults build-rate 32 8)
set -euo pipefail
BUILD=${1:-build-rate}
LAMBDA=${2:-32}
STEP=${3:-8}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MEDIA=${SPT_MEDIA:-$ROOT/../shared/media}
CODEC=$BUILD/bench/rate_codec
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for n in 60 32 16; do python3 "$ROOT/converter/tools/make_templates.py" --size $n --out "$TMP/g$n" >/dev/null; done
mk() { mkdir -p "$TMP/$1"; shift; }
# name: files (source set/file:target name)
set_of() { local d=$TMP/$1; shift; mkdir -p "$d"; for f in "$@"; do cp "$TMP/${f%%:*}" "$d/${f##*:}"; done; }
set_of four60  g60/0-rectangle.png:0-rectangle.png g60/1-soft-round.png:1-soft-round.png g60/2-bristle.png:2-bristle.png g60/3-dry-brush.png:3-dry-brush.png
set_of four32  g32/0-rectangle.png:0-rectangle.png g32/1-soft-round.png:1-soft-round.png g32/2-bristle.png:2-bristle.png g32/3-dry-brush.png:3-dry-brush.png
set_of four16  g16/0-rectangle.png:0-rectangle.png g16/1-soft-round.png:1-soft-round.png g16/2-bristle.png:2-bristle.png g16/3-dry-brush.png:3-dry-brush.png
set_of analytic g16/0-rectangle.png:0-rectangle.png g16/1-soft-round.png:1-ellipse.png
set_of rse16   g16/0-rectangle.png:0-rectangle.png g16/1-soft-round.png:1-soft-round.png g16/1-soft-round.png:2-ellipse.png
set_of rseb16  g16/0-rectangle.png:0-rectangle.png g16/1-soft-round.png:1-soft-round.png g16/1-soft-round.png:2-ellipse.png g16/2-bristle.png:3-bristle.png
set_of rsbd16  g16/0-rectangle.png:0-rectangle.png g16/1-soft-round.png:1-soft-round.png g16/2-bristle.png:2-bristle.png g16/3-dry-brush.png:3-dry-brush.png
SETS=${SETS:-"four60 four32 four16 analytic rse16 rseb16"}
source "$ROOT/bench/tools/rate_images.sh" "$TMP"
echo "command: $CODEC IMAGE --target-psnr 28 --lambda $LAMBDA --color-step $STEP --templates SET"
for img in "${IMAGES[@]}"; do
  for s in $SETS; do
    "$CODEC" "$img" --target-psnr 28 --lambda "$LAMBDA" --color-step "$STEP" --templates "$TMP/$s" --tmp "$TMP" | sed "s/^/set $s /" | tee -a "$TMP/t.txt"
  done
done
python3 - "$TMP/t.txt" <<'PY'
import sys, statistics, collections
by = collections.defaultdict(dict)
for line in open(sys.argv[1]):
    t = line.split(); kv = {t[i]: t[i + 1] for i in range(len(t) - 1)}
    by[t[2]][t[1]] = (float(kv["bytes_c2"]), float(kv["header_bytes"]), float(kv["strokes"]), t[3])
sets = list(dict.fromkeys(s for d in by.values() for s in d))
print("\ntotal bytes at 28 dB relative to the image's best set (median; small = at most 256x256 px)")
print("set        header  rel_all  rel_small  rel_large  strokes_rel")
for s in sets:
    rel = {im: d[s][0] / min(v[0] for v in d.values()) for im, d in by.items() if s in d}
    srel = [by[im][s][2] / min(v[2] for v in by[im].values()) for im in by if s in by[im]]
    small = [r for im, r in rel.items() if eval(by[im][s][3].replace("x", "*")) <= 65536]
    large = [r for im, r in rel.items() if eval(by[im][s][3].replace("x", "*")) > 65536]
    hdr = statistics.median(by[im][s][1] for im in by if s in by[im])
    med = lambda v: statistics.median(v) if v else float("nan")
    print(f"{s:10s} {hdr:6.0f} {med(list(rel.values())):8.3f} {med(small):10.3f} {med(large):10.3f} {med(srel):12.3f}")
PY
