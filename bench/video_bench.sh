#!/usr/bin/env bash
# Video painter bench: speed, size, quality, temporal coherence and cut detection.
#   bench/video_bench.sh [BUILD_DIR] [FRAMES]     (defaults: build-video, 60 frames a clip)
# Needs the targets video_encode and video_coherence, ffmpeg (ffv1, libx264rgb, libx265,
# libaom-av1) and oiiotool. Prints one block per measurement; work files go to $TMPDIR/spt_vb.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-video}"
frames="${2:-60}"
media="${SPT_MEDIA_DIR:-$root/../shared/media}"
enc="$build/bench/video_encode"
coh="$build/bench/video_coherence"
work="${TMPDIR:-/tmp}/spt_vb"
threads="${THREADS:-2}"
only="${ONLY:-joined clips cartoon}"   # sections to run
mkdir -p "$work"
last=$((frames - 1))
want() { [[ " $only " == *" $1 "* ]]; }

summary() {  # csv -> the two summary lines
  grep '^#' "$1" | tail -2
}

# --- the joined clip: three shots at 640x360, true cuts at $frames and 2*$frames -------------
joined="$work/joined"
if want joined; then
if [ ! -f "$joined/.done.$frames" ]; then
  rm -rf "$joined"; mkdir -p "$joined/tmp"
  ffmpeg -loglevel error -i "$media/video/city.mpg" -vf "select=lt(n\,$frames),scale=640:360" -vsync 0 "$joined/tmp/a_%04d.png"
  ffmpeg -loglevel error -i "$media/video/butterfly-cartoon.avi" -vf "select=lt(n\,$frames),scale=640:360" -vsync 0 "$joined/tmp/b_%04d.png"
  i=0
  for f in "$media"/exr/earth/earth.*.exr; do
    [ $i -ge "$frames" ] && break
    oiiotool "$f" --ch R,G,B --colorconvert linear sRGB --resize 640x360 -d uint8 -o "$joined/tmp/c_$(printf %04d $((i + 1))).png"
    i=$((i + 1))
  done
  n=0
  for f in "$joined"/tmp/a_*.png "$joined"/tmp/b_*.png "$joined"/tmp/c_*.png; do
    mv "$f" "$joined/joined.$(printf %04d $n).png"; n=$((n + 1))
  done
  rmdir "$joined/tmp"; touch "$joined/.done.$frames"
fi
earth_frames=$(ls "$media"/exr/earth/earth.*.exr | head -n "$frames" | wc -l)
echo "== joined clip: $((2 * frames + earth_frames)) frames, true cuts at $frames and $((2 * frames))"
"$enc" "$joined/joined.####.png" "$work/joined.spt" --threads "$threads" --keyframe-interval 1000 \
  --raw-source "$work/joined_src.rgb" --raw-paint "$work/joined_paint.rgb" > "$work/joined.csv"
summary "$work/joined.csv"
python3 - "$work/joined.csv" "$frames" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
n = int(sys.argv[2]); truth = {n, 2 * n}
found = {int(r['index']) for r in rows if r['cut'] == '1'}
tp = len(found & truth)
print(f"cuts: detected {sorted(found)}; recall {tp}/{len(truth)} = {100*tp/len(truth):.0f}%; "
      f"false positives {len(found - truth)} of {len(rows) - len(truth)} frames "
      f"({100*len(found - truth)/(len(rows) - len(truth)):.1f}%)")
PY
fi

# --- per clip at 640x360: speed, bytes, PSNR, coherence, lossless coders --------------------
clip() {  # name input [extra args]
  local name="$1" input="$2"; shift 2
  "$enc" "$input" "$work/$name.spt" --threads "$threads" "$@" \
    --raw-source "$work/${name}_src.rgb" --raw-paint "$work/${name}_paint.rgb" > "$work/$name.csv"
  local size; size=$(sed -n 's/^# \([0-9]*\)x\([0-9]*\) .*/\1x\2/p' "$work/$name.csv")
  local w=${size%x*} h=${size#*x}
  local nf; nf=$(grep -c -E '^[0-9]+,' "$work/$name.csv")
  local keys; keys=$(awk -F, '$3=="key"{printf "%s%s", s, $1; s=","}' "$work/$name.csv")
  echo "== $name ${w}x${h}, $nf frames"
  summary "$work/$name.csv"
  awk -F, '/^[0-9]+,/ && $3=="inter" {f+=$12; r+=$13; p+=$14; c+=$15; n++}
    END { if (n) printf "inter frame ms: flow %.1f render %.1f paint %.1f cull %.1f\n", 1000*f/n, 1000*r/n, 1000*p/n, 1000*c/n }' "$work/$name.csv"
  "$coh" "$work/${name}_src.rgb" "$work/${name}_paint.rgb" "$w" "$h" "$keys" | sed 's/^/coherence: /'
  "$coh" "$work/${name}_src.rgb" "$work/${name}_src.rgb" "$w" "$h" "$keys" > /dev/null
  local spt_bytes; spt_bytes=$(stat -c %s "$work/$name.spt")
  ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s "${w}x${h}" -r 24 -i "$work/${name}_paint.rgb" \
    -c:v ffv1 -level 3 -pix_fmt bgr0 "$work/${name}_ffv1.mkv"
  ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s "${w}x${h}" -r 24 -i "$work/${name}_paint.rgb" \
    -c:v libx264rgb -qp 0 -preset medium "$work/${name}_x264.mkv"
  # Losslessness: the decoded frames' MD5s equal those of the raw painted frames.
  local ref; ref=$(ffmpeg -loglevel error -f rawvideo -pix_fmt rgb24 -s "${w}x${h}" -i "$work/${name}_paint.rgb" -f framemd5 -pix_fmt rgb24 - | grep -v '^#' | awk '{print $NF}' | md5sum)
  for c in ffv1 x264; do
    local got; got=$(ffmpeg -loglevel error -i "$work/${name}_$c.mkv" -f framemd5 -pix_fmt rgb24 - | grep -v '^#' | awk '{print $NF}' | md5sum)
    local b; b=$(stat -c %s "$work/${name}_$c.mkv")
    local ok=lossless; [ "$got" = "$ref" ] || ok=NOT-LOSSLESS
    python3 -c "print(f'$c: {$b} bytes ($ok), .spt is {$b/$spt_bytes:.1f}x smaller')"
  done
}

if want clips; then
  clip city "$media/video/city.mpg" --width 640 --frames "0-$last"
  # The quality setting: lower rate-distortion lambda, repaint at a lower error, more strokes.
  clip city_q "$media/video/city.mpg" --width 640 --frames "0-$last" --lambda 8 --repaint-error 10 \
    --max-inter-strokes 8000
  clip butterfly "$media/video/butterfly-cartoon.avi" --width 640 --frames "0-$last"
  clip earth "$media/exr/earth/earth.####.exr" --width 640
  clip city720 "$media/video/city.mpg" --width 1280 --frames "0-$((frames / 3))"
fi
want cartoon || exit 0

# --- cartoon archiving: the painting vs x265 and AV1 at the same bytes ------------------------
echo "== cartoon archiving: butterfly-cartoon.avi 520x380, frames 0-$last"
"$enc" "$media/video/butterfly-cartoon.avi" "$work/cartoon.spt" --threads "$threads" --frames "0-$last" \
  --raw-source "$work/cartoon_src.rgb" --raw-paint "$work/cartoon_paint.rgb" > "$work/cartoon.csv"
target=$(stat -c %s "$work/cartoon.spt")
raw_in=(-f rawvideo -pix_fmt rgb24 -s 520x380 -r 18)
metrics() {  # distorted.(rgb|mkv) -> "PSNR x SSIM y"
  local in=("$@")
  local p s
  p=$(ffmpeg -hide_banner "${in[@]}" "${raw_in[@]}" -i "$work/cartoon_src.rgb" -lavfi "[0:v]settb=1/18,setpts=N,format=rgb24[a];[1:v]settb=1/18,setpts=N,format=rgb24[b];[a][b]psnr" -f null - 2>&1 | sed -n 's/.*average:\([0-9.inf]*\).*/\1/p')
  s=$(ffmpeg -hide_banner "${in[@]}" "${raw_in[@]}" -i "$work/cartoon_src.rgb" -lavfi "[0:v]settb=1/18,setpts=N,format=rgb24[a];[1:v]settb=1/18,setpts=N,format=rgb24[b];[a][b]ssim" -f null - 2>&1 | sed -n 's/.*All:\([0-9.]*\).*/\1/p')
  echo "PSNR $p SSIM $s"
}
echo "spt painting: $target bytes, $(metrics "${raw_in[@]}" -i "$work/cartoon_paint.rgb")"
search() {  # codec lo hi -> encodes at the CRF whose size is closest to the target
  local codec="$1" lo="$2" hi="$3" best="" bestd=1000000000
  while [ "$lo" -le "$hi" ]; do
    local mid=$(((lo + hi) / 2)) out="$work/cartoon_$codec.mkv"
    if [ "$codec" = x265 ]; then
      ffmpeg -loglevel error -y "${raw_in[@]}" -i "$work/cartoon_src.rgb" -c:v libx265 -crf "$mid" -pix_fmt yuv444p -x265-params log-level=error "$out"
    else
      ffmpeg -loglevel error -y "${raw_in[@]}" -i "$work/cartoon_src.rgb" -c:v libaom-av1 -crf "$mid" -b:v 0 -cpu-used 6 -pix_fmt yuv444p "$out"
    fi
    local b; b=$(stat -c %s "$out"); local d=$((b > target ? b - target : target - b))
    [ "$d" -lt "$bestd" ] && bestd=$d && best=$mid
    if [ "$b" -gt "$target" ]; then lo=$((mid + 1)); else hi=$((mid - 1)); fi
  done
  echo "$best"
}
for codec in x265 aom; do
  if [ $codec = x265 ]; then crf=$(search x265 0 51); else crf=$(search aom 0 63); fi
  out="$work/cartoon_$codec.mkv"
  if [ "$codec" = x265 ]; then
    ffmpeg -loglevel error -y "${raw_in[@]}" -i "$work/cartoon_src.rgb" -c:v libx265 -crf "$crf" -pix_fmt yuv444p -x265-params log-level=error "$out"
  else
    ffmpeg -loglevel error -y "${raw_in[@]}" -i "$work/cartoon_src.rgb" -c:v libaom-av1 -crf "$crf" -b:v 0 -cpu-used 6 -pix_fmt yuv444p "$out"
  fi
  echo "$codec crf $crf: $(stat -c %s "$out") bytes, $(metrics -i "$out")"
done
# Side by side (source | painting | x265 | AV1), frame 30, a 200x150 crop.
mid=$((frames / 2))
# The crop: the 200x150 window of the source frame with the most detail (sum of luminance
# gradients), so the comparison shows lines and texture rather than flat background.
crop=$(python3 - "$work/cartoon_src.rgb" "$mid" <<'PY'
import sys
w, h, cw, ch = 520, 380, 200, 150
with open(sys.argv[1], 'rb') as f:
    f.seek(int(sys.argv[2]) * w * h * 3)
    px = f.read(w * h * 3)
lum = [(px[3*i] * 299 + px[3*i+1] * 587 + px[3*i+2] * 114) // 1000 for i in range(w * h)]
g = [[0] * (w + 1) for _ in range(h + 1)]  # integral image of |dx| + |dy|
for y in range(h):
    row, acc = g[y + 1], 0
    for x in range(w):
        i = y * w + x
        d = (abs(lum[i] - lum[i + 1]) if x + 1 < w else 0) + (abs(lum[i] - lum[i + w]) if y + 1 < h else 0)
        acc += d
        row[x + 1] = g[y][x + 1] + acc
best = max(((g[y + ch][x + cw] - g[y][x + cw] - g[y + ch][x] + g[y][x], x, y)
            for y in range(0, h - ch + 1, 10) for x in range(0, w - cw + 1, 10)))
print(f"crop={cw}:{ch}:{best[1]}:{best[2]}")
PY
)
echo "side-by-side crop (most detailed window of frame $mid): $crop"
ffmpeg -loglevel error -y "${raw_in[@]}" -i "$work/cartoon_src.rgb" "${raw_in[@]}" -i "$work/cartoon_paint.rgb" \
  -i "$work/cartoon_x265.mkv" -i "$work/cartoon_aom.mkv" \
  -lavfi "[0:v]select=eq(n\,$mid),$crop[a];[1:v]select=eq(n\,$mid),$crop[b];[2:v]select=eq(n\,$mid),$crop[c];[3:v]select=eq(n\,$mid),$crop,format=rgb24[d];[a][b][c][d]hstack=4" \
  -frames:v 1 "$work/cartoon_side_by_side.png"
echo "side by side (source | spt | x265 | AV1): $work/cartoon_side_by_side.png"
