#!/usr/bin/env bash
# Farm figures (issue 16): spt plan's cost per frame against painting's; the same plan on this
# machine's own Slurm cluster with 1 CPU and with 2 CPUs (wall time, ratio); and from those, the
# nodes a 90-minute 1080p film (130,000 frames at 24 fps) needs to paint overnight (8 h).
# Input: 48 frames of ../shared/media/video/city.mpg (frames 92-139, one hard cut at 116) scaled
# to 1920x1080 PNG with ffmpeg; painted at the defaults. Run from the checkout, as root:
#   bench/farm_bench.sh [build/bin/spt]
# Needs ffmpeg, slurm-wlm, munge (./setup.sh test installs them). Prints medians of 3 plan runs;
# paint and farm runs are single (each takes tens of seconds).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
spt="$(realpath "${1:-build/bin/spt}")"
media="$(realpath "$here/../../shared/media" 2>/dev/null || echo /work/shared/media)"
[ -f "$media/video/city.mpg" ] || media=/work/shared/media
tests="$here/../tests/farm"

if [ "${2:-}" = "--slurm" ]; then
  # Inside the network namespace: one cluster per CPU count, the plan through spt farm.
  tmp="$3"; cd "$tmp"
  for cpus in 1 2; do
    c="$tmp/cluster$cpus"; mkdir -p "$c"
    "$tests/slurm_cluster.sh" start "$c" "$cpus" > "$c/env"
    ( . "$c/env"
      rm -rf plan.farm
      t0=$(date +%s.%N)
      "$spt" farm slurm plan.json -o "farm$cpus.spt" --wait -- --cpus-per-task=1 > /dev/null 2> "farm$cpus.log" ||
        { cat "farm$cpus.log" >&2; exit 1; }
      t1=$(date +%s.%N)
      awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f\n", b - a }' > "farm$cpus.time" ) || rc=1
    "$tests/slurm_cluster.sh" stop "$c"
    [ "${rc:-0}" = 0 ] || exit 1
  done
  exit 0
fi

tmp="$(mktemp -d /tmp/spt_farm_bench.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/seq"
ffmpeg -loglevel error -y -i "$media/video/city.mpg" -vf "select=between(n\,92\,139),scale=1920:1080" \
  -vsync 0 -start_number 92 "$tmp/seq/f.%04d.png"
cd "$tmp"
frames=48
now() { date +%s.%N; }
span() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
# CPU seconds (user + sys) of a command: the machine is shared, and wall time counts the others.
cpu_of() {
  local TIMEFORMAT='%U %S %R'
  { time "$@" >/dev/null 2>&1; } 2> "$tmp/cpu.txt"
  awk '{ printf "%.3f %.3f\n", $1 + $2, $3 }' "$tmp/cpu.txt"
}
load0=$(cut -d' ' -f1 /proc/loadavg)
plan_times=()
for r in 1 2 3; do
  plan_times+=("$(cpu_of "$spt" plan 'seq/f.####.png' -o plan.json --keyframe-interval 24 --max-task-frames 12 --progress none)")
done
plan_s=$(printf '%s\n' "${plan_times[@]}" | cut -d' ' -f1 | sort -n | sed -n 2p)
plan_wall=$(printf '%s\n' "${plan_times[@]}" | cut -d' ' -f2 | sort -n | sed -n 2p)
shots=$(grep -c '"starts_at_cut"' plan.json)
read -r paint_s paint_wall < <(cpu_of "$spt" paint --plan plan.json -o one.spt --threads 2 --progress none)

"$tests/in_netns.sh" bash "$here/farm_bench.sh" "$spt" --slurm "$tmp"
cmp farm1.spt one.spt && cmp farm2.spt one.spt || { echo "farm_bench: the farm's files differ from spt paint --plan" >&2; exit 1; }
f1=$(cat farm1.time); f2=$(cat farm2.time)
load1=$(cut -d' ' -f1 /proc/loadavg)

awk -v n="$frames" -v shots="$shots" -v plan="$plan_s" -v planw="$plan_wall" -v paint="$paint_s" -v pw="$paint_wall" -v f1="$f1" -v f2="$f2" \
    -v l0="$load0" -v l1="$load1" 'BEGIN {
  printf "input: %d frames 1920x1080 PNG (city.mpg 92-139 scaled), plan of %d tasks (--keyframe-interval 24 --max-task-frames 12)\n", n, shots
  printf "load average %s at the start, %s at the end (2 cores)\n", l0, l1
  printf "spt plan:             %.3f CPU-s, %.1f ms a frame; %.1f ms wall a frame (medians of 3; bench/plan_bench.sh splits it)\n", plan, 1000 * plan / n, 1000 * planw / n
  printf "spt paint --plan:     %.2f CPU-s, %.0f ms a frame (one process, --threads 2; %.1f s wall)\n", paint, 1000 * paint / n, pw
  printf "plan / paint:         %.2f%% of the painting (CPU), %.2f%% (wall)\n", 100 * plan / paint, 100 * planw / pw
  printf "Slurm, 1 CPU:         %.2f s wall (%.0f ms a frame)\n", f1, 1000 * f1 / n
  printf "Slurm, 2 CPUs:        %.2f s wall (%.0f ms a frame); 1 CPU / 2 CPUs = %.2fx\n", f2, 1000 * f2 / n, f1 / f2
  film = 130000; night = 8 * 3600
  per_cpu = paint / n               # CPU seconds a frame
  eff = (f1 / f2) / 2               # parallel efficiency measured on 2 CPUs (wall, shared machine)
  printf "film: 130,000 frames x %.2f CPU-s a frame = %.0f CPU-hours\n", per_cpu, film * per_cpu / 3600
  printf "overnight (8 h) at the measured 2-CPU efficiency %.0f%%: %.1f CPUs busy all night, i.e. %.1f nodes of 2 cores, %.2f of 32 cores\n",
         100 * eff, film * per_cpu / night / eff, film * per_cpu / night / eff / 2, film * per_cpu / night / eff / 32
}'
