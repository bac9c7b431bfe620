#!/usr/bin/env bash
# Peak memory of `spt import` of a large primitive-style SVG (issue 20 item 5): writes an SVG
# of N ellipses (default 2,000,000, about 196 MB), imports it under /usr/bin/time -v and prints
# the peak resident set, the bytes of memory per input byte and per stroke (a Stroke is 120
# bytes). Usage: bench/import_memory.sh [SPT] [N]   (SPT default build/bin/spt)
set -euo pipefail
spt="${1:-build/bin/spt}"
n="${2:-2000000}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 - "$n" "$tmp/in.svg" <<'PY'
import random, sys
n = int(sys.argv[1]); r = random.Random(1); W, H = 1024, 768
with open(sys.argv[2], "w") as f:
    f.write('<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="%d" height="%d">\n' % (W, H))
    f.write('<rect x="0" y="0" width="%d" height="%d" fill="#7f8a90" />\n' % (W, H))
    f.write('<g transform="scale(4.000000) translate(0.5 0.5)">\n')
    for i in range(n):
        f.write('<ellipse fill="#%02x%02x%02x" fill-opacity="0.501961" cx="%.3f" cy="%.3f" rx="%.3f" ry="%.3f" />\n' % (
            r.randrange(256), r.randrange(256), r.randrange(256), r.uniform(0, W / 4), r.uniform(0, H / 4),
            r.uniform(0.5, 8), r.uniform(0.5, 8)))
    f.write('</g>\n</svg>\n')
PY
bytes=$(stat -c %s "$tmp/in.svg")
/usr/bin/time -v "$spt" import "$tmp/in.svg" -o "$tmp/out.spt" --quiet 2> "$tmp/time"
kb=$(awk '/Maximum resident set size/ {print $6}' "$tmp/time")
secs=$(awk '/Elapsed \(wall clock\)/ {print $8}' "$tmp/time")
python3 -c "
kb, b, n = $kb, $bytes, $n
print(f'{n} ellipses, {b} input bytes: peak RSS {kb * 1024 / 1e6:.0f} MB = {kb * 1024 / b:.2f} bytes per input byte, '
      f'{kb * 1024 / n:.0f} bytes per stroke ({kb * 1024 / (n * 120):.2f} x the 120-byte stroke list), wall $secs')"
