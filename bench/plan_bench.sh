#!/usr/bin/env bash
# spt plan's cost per frame (issue 16: well under 1% of painting), for two builds interleaved so
# that the machine's load falls on both alike, and each build's plans checked byte-identical.
# Inputs: bench/farm_bench.sh's 48 frames (city.mpg 92-139 scaled to 1920x1080; FRAMES=A-B
# picks others, FRAMES=0-189 is the whole clip) as PNG, as half-float ZIP EXR (oiiotool -d half;
# a renderer's output), and as H.264 (libx264 crf 18). city.mpg has one hard cut, at 116.
# Variants, interleaved: OLD as it plans by default, NEW with --cut-scan full, NEW with
# --cut-scan sampled (a sequence's default); these must find the same cuts and shots. And NEW
# with --cut-scan tasks (a video file's default: no scan, the tasks find the cuts as they paint).
# Figures per variant and input, medians of RUNS:
#   cpu   user+sys of the whole command, over the frames
#   -st   the same less the process start-up (CPU of `spt --version`: loading the libraries)
#   wall  wall time of the whole command, over the frames
#   pass  the time spt plan reports for its pass (no start-up), over the frames
# With --paint, one `spt paint --plan` of each input's plan with the NEW build gives the
# painting's time a frame, and the ratios of each variant's plan to it.
#   bench/plan_bench.sh OLD_SPT NEW_SPT [RUNS=5] [--paint]
set -euo pipefail
old="$(realpath "$1")"; new="$(realpath "$2")"; runs="${3:-5}"; paint="${4:-}"
here="$(cd "$(dirname "$0")" && pwd)"
media="$(realpath "$here/../../shared/media" 2>/dev/null || echo /work/shared/media)"
[ -f "$media/video/city.mpg" ] || media=/work/shared/media
tmp="$(mktemp -d /tmp/spt_plan_bench.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
range="${FRAMES:-92-139}"; fa="${range%-*}"; fb="${range#*-}"
mkdir -p "$tmp/seq"
ffmpeg -loglevel error -y -i "$media/video/city.mpg" -vf "select=between(n\,$fa\,$fb),scale=1920:1080" \
  -vsync 0 -start_number "$fa" "$tmp/seq/f.%04d.png"
mkdir -p "$tmp/exr"
for f in "$tmp"/seq/*.png; do oiiotool "$f" -d half --compression zip -o "$tmp/exr/$(basename "$f" .png).exr"; done
ffmpeg -loglevel error -y -framerate 24 -start_number "$fa" -i "$tmp/seq/f.%04d.png" -c:v libx264 -preset fast -crf 18 \
  -pix_fmt yuv420p "$tmp/clip.mp4"
cd "$tmp"
frames=$((fb - fa + 1))
opts=(--keyframe-interval 24 --max-task-frames 12 --progress none)
one() {  # build input tag [options] -> appends "cpu wall pass" (seconds) to tag.txt
  local TIMEFORMAT='%U %S %R' pass
  { time "$1" plan "$2" -o "$3.json" "${opts[@]}" "${@:4}" 2> "$3.err" >/dev/null; } 2> "$3.time"
  pass=$(sed -n 's/.*, \([0-9.]*\) s (.*/\1/p' "$3.err")
  awk -v p="$pass" '{ printf "%.3f %.3f %s\n", $1 + $2, $3, p }' "$3.time" >> "$3.txt"
}
for r in $(seq "$runs"); do
  for input in 'seq/f.####.png' 'exr/f.####.exr' clip.mp4; do
    kind=png; [ "$input" = clip.mp4 ] && kind=h264; [ "$input" = 'exr/f.####.exr' ] && kind=exr
    one "$old" "$input" "old_$kind"
    one "$new" "$input" "full_$kind" --cut-scan full
    one "$new" "$input" "new_$kind" --cut-scan sampled
    one "$new" "$input" "tasks_$kind" --cut-scan tasks
  done
done
shots() {  # the cuts and shots of a plan (the members every variant must agree on)
  python3 -c 'import json,sys; p=json.load(open(sys.argv[1])); print(p["cuts"], [(s["first"], s["last"], s["seed"]) for s in p["shots"]])' "$1"
}
cut_scan() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("cut_scan", "full"))' "$1"; }
for kind in png exr h264; do
  pairs="full:new"
  # OLD's default for a video file may be the tasks mode, whose plans hold no cuts.
  [ "$(cut_scan "old_$kind.json")" = tasks ] || pairs="$pairs old:new"
  for pair in $pairs; do
    a="${pair%:*}"; b="${pair#*:}"
    [ "$(shots "${a}_$kind.json")" = "$(shots "${b}_$kind.json")" ] ||
      { echo "plan_bench: the $kind plans of $a and $b differ: $(shots "${a}_$kind.json") / $(shots "${b}_$kind.json")" >&2; exit 1; }
  done
done
startup() {  # CPU seconds of a process that loads the same libraries and does nothing
  local TIMEFORMAT='%U %S'
  for i in 1 2 3; do { time "$1" --version >/dev/null; } 2>&1 | awk '{ print $1 + $2 }'; done | sort -n | sed -n 2p
}
med() { sort -n -k"$2" "$1" | awk -v k="$2" '{ v[NR] = $k } END { print v[int((NR + 1) / 2)] }'; }
echo "spt plan, $frames frames 1920x1080, ${opts[*]}; medians of $runs interleaved runs; load $(cut -d' ' -f1-3 /proc/loadavg)"
st_old=$(startup "$old"); st_new=$(startup "$new")
echo "old:  $old (start-up $st_old CPU-s)"
echo "full: $new --cut-scan full; new: the same --cut-scan sampled; tasks: --cut-scan tasks (start-up $st_new CPU-s)"
printf '%-5s %-4s %12s %12s %12s %12s %8s   (ms a frame)\n' input spt cpu -st wall pass read
for kind in png exr h264; do
  for b in old full new tasks; do
    f="${b}_$kind.txt"; st=$st_old; [ $b != old ] && st=$st_new
    rd=$(sed -n 's/.*(\([0-9]*\) read.*/\1/p' "${b}_$kind.err"); [ -n "$rd" ] || rd=$frames
    printf '%-5s %-4s %12.1f %12.1f %12.1f %12.1f %8s\n' "$kind" "$b" \
      "$(awk -v v="$(med "$f" 1)" -v n=$frames 'BEGIN { print 1000 * v / n }')" \
      "$(awk -v v="$(med "$f" 1)" -v s="$st" -v n=$frames 'BEGIN { print 1000 * (v - s) / n }')" \
      "$(awk -v v="$(med "$f" 2)" -v n=$frames 'BEGIN { print 1000 * v / n }')" \
      "$(awk -v v="$(med "$f" 3)" -v n=$frames 'BEGIN { print 1000 * v / n }')" "$rd/$frames"
  done
done
echo "old, full and new plans have the same cuts and shots (png, exr, h264): $(shots new_png.json | cut -c1-60)"
if [ "$paint" = --paint ]; then
  local_time() { local TIMEFORMAT='%U %S %R'; { time "$@" >/dev/null 2>&1; } 2>&1; }
  for kind in png exr h264; do
    read -r u s w < <(local_time "$new" paint --plan "new_$kind.json" -o "$kind.spt" --progress none)
    echo "$kind: spt paint --plan (new, default threads): $(awk -v u="$u" -v s="$s" -v w="$w" -v n=$frames \
      'BEGIN { printf "%.0f ms CPU, %.0f ms wall a frame", 1000 * (u + s) / n, 1000 * w / n }')"
    for b in old full new tasks; do
      st=$st_old; [ $b != old ] && st=$st_new
      awk -v b=$b -v u="$u" -v s="$s" -v w="$w" -v n=$frames -v st="$st" -v f="$(med "${b}_$kind.txt" 1)" \
          -v fw="$(med "${b}_$kind.txt" 2)" 'BEGIN {
        cpu = (u + s) / n
        printf "  plan %-4s / paint: CPU %.2f%% (%.2f%% less start-up), wall %.2f%%\n",
               b, 100 * f / n / cpu, 100 * (f - st) / n / cpu, 100 * fw / w
      }'
    done
  done
fi
