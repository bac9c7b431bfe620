#!/usr/bin/env bash
# The farm on a real Slurm cluster of its own (slurm_cluster.sh, inside in_netns.sh: loopback
# only): a plan of a real EXR sequence with a cut goes through `spt farm slurm --wait`; one task
# is killed mid-shot and must be retried; the joined file must be byte for byte
# `spt paint --plan` in one process; `spt farm status` must say every shot is done; a second
# submission must keep every shot and paint none; a shot that keeps failing must fail the job
# (and cancel the join) with a message naming it. Every daemon started is stopped, by pid.
#   farm_slurm_test.sh SPT MEDIA_DIR
set -euo pipefail
spt="$1"; media="$2"
here="$(cd "$(dirname "$0")" && pwd)"
tmp="$(mktemp -d /tmp/spt_farm_test.XXXXXX)"
cluster="$tmp/cluster"; mkdir -p "$cluster"
ok=0
finish() {
  "$here/slurm_cluster.sh" stop "$cluster" || true
  if [ "$ok" = 1 ]; then rm -rf "$tmp"; else
    echo "farm test: FAILED; logs kept in $tmp" >&2
    for f in "$tmp"/*.farm/logs/*.log; do [ -f "$f" ] && { echo "== $f" >&2; tail -n 20 "$f" >&2; }; done
  fi
}
trap finish EXIT
die() { echo "farm test: $*" >&2; exit 1; }

[ -f "$media/exr/orbit/orbit.0010.exr" ] || die "the shared media are needed: $media"
command -v slurmctld >/dev/null || die "slurm-wlm is not installed (./setup.sh test installs it)"
command -v munged >/dev/null || die "munge is not installed (./setup.sh test installs it)"

"$here/slurm_cluster.sh" start "$cluster" 2 > "$cluster/env"
. "$cluster/env"
sinfo >&2

# 22 frames numbered 101-122: earth 1-12, a hard cut, orbit 1-10.
mkdir -p "$tmp/seq"
for i in $(seq 1 12); do ln -s "$media/exr/earth/earth.$(printf %04d "$i").exr" "$tmp/seq/s.$(printf %04d $((100 + i))).exr"; done
for i in $(seq 1 10); do ln -s "$media/exr/orbit/orbit.$(printf %04d "$i").exr" "$tmp/seq/s.$(printf %04d $((112 + i))).exr"; done
cd "$tmp"
"$spt" plan 'seq/s.####.exr' -o shot.plan.json --max-strokes 4000 --keyframe-interval 4 --max-task-frames 8 \
  --seed 5 --progress none
"$spt" paint --plan shot.plan.json -o ref.spt --progress none
shots=$(grep -c '"starts_at_cut"' shot.plan.json)
[ "$shots" = 4 ] || die "expected a plan of 4 shots, got $shots"

# Kill shot 1's painter mid-shot, once, by its pid (the task wrapper writes it): as soon as its
# output holds a finished frame (the header alone is a few hundred bytes; a key frame of 4,000
# strokes several KB), so the kill lands inside the shot on any machine. spt writes outputs to an
# unnamed file (O_TMPFILE) linked into place when complete, so the bytes written so far are read
# through the painter's open descriptors; a named fallback (.partial) counts too.
written() {
  local pid="$1" part="$2" best=0 s fd
  [ -f "$part" ] && best=$(stat -c %s "$part" 2>/dev/null || echo 0)
  for fd in /proc/"$pid"/fd/*; do
    case "$(readlink "$fd" 2>/dev/null)" in
      *"/shot.plan.farm/shots/"*) s=$(stat -L -c %s "$fd" 2>/dev/null || echo 0); [ "$s" -gt "$best" ] && best=$s ;;
    esac
  done
  echo "$best"
}
killer() {
  local pidf="$tmp/shot.plan.farm/run/shot-1.pid" part="$tmp/shot.plan.farm/shots/shot-00001.spt.partial" pid=""
  for _ in $(seq 1200); do
    pid="$(cat "$pidf" 2>/dev/null || true)"
    [ -n "$pid" ] && [ "$(written "$pid" "$part")" -gt 3000 ] && break
    sleep 0.05
  done
  [ -s "$pidf" ] || { echo "killer: shot 1 never started" > "$tmp/killer.txt"; return; }
  pid="$(cat "$pidf" 2>/dev/null || true)"
  if [ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; then echo "killed $pid" > "$tmp/killer.txt"
  else echo "killer: shot 1 ended before it could be killed" > "$tmp/killer.txt"; fi
}
killer & killer_pid=$!
start=$(date +%s.%N)
"$spt" farm slurm shot.plan.json -o out.spt --wait --retries 2 -- --time=30 > submit.txt 2> wait.txt ||
  { cat wait.txt >&2; die "spt farm slurm --wait failed"; }
end=$(date +%s.%N)
wait "$killer_pid" || true
cat submit.txt wait.txt >&2
grep -q '^tasks [0-9]' submit.txt || die "no task job id printed"
grep -q '^join [0-9]' submit.txt || die "no join job id printed"
grep -q '^killed ' killer.txt || die "$(cat killer.txt)"
grep -q 'frames/s over the farm' wait.txt || die "no progress line"
attempts="$(cat shot.plan.farm/run/shot-1.attempts)"
echo "shot 1 attempts: $attempts" >&2
[ "$(echo "$attempts" | head -1 | cut -d' ' -f2)" != 0 ] || die "the killed attempt did not fail"
[ "$(echo "$attempts" | tail -1 | cut -d' ' -f2)" = 0 ] || die "shot 1 was not retried to success"
cmp out.spt ref.spt || die "the farm's file differs from spt paint --plan"
"$spt" verify out.spt >&2
"$spt" farm status shot.plan.json > status.txt
cat status.txt >&2
[ "$(grep -c '  done  ' status.txt)" = 4 ] || die "spt farm status does not say 4 shots done"
awk -v a="$start" -v b="$end" 'BEGIN { printf "farm wall time: %.1f s\n", b - a }' >&2

# Again: every shot verifies, none is painted; the join alone runs.
"$spt" farm slurm shot.plan.json -o out2.spt --wait > submit2.txt 2> wait2.txt ||
  { cat wait2.txt >&2; die "resubmission failed"; }
grep -q '0 shots to paint, 4 kept' wait2.txt || { cat wait2.txt >&2; die "the resubmission painted shots again"; }
grep -q '^tasks -' submit2.txt || die "the resubmission queued tasks"
cmp out2.spt ref.spt || die "the resubmission's join differs"

# A shot that keeps failing (its frames are gone) fails the job, names the shot, cancels the join.
mkdir -p "$tmp/seq2"; cp -P "$tmp"/seq/s.010[1-8].exr "$tmp/seq2/"
"$spt" plan 'seq2/s.####.exr' -o bad.plan.json --max-strokes 300 --keyframe-interval 4 --max-task-frames 4 --progress none
rm "$tmp/seq2/s.0107.exr"
if "$spt" farm slurm bad.plan.json -o bad.spt --wait --retries 1 > bad_submit.txt 2> bad_wait.txt; then
  die "a job with a shot whose frames are gone succeeded"
fi
cat bad_wait.txt >&2
grep -q 'shot 1 failed after 2 attempts' bad_wait.txt || die "the failure does not name shot 1 and its 2 attempts"
[ ! -e bad.spt ] || die "a failed job left an output"
for _ in $(seq 50); do [ -z "$(squeue -h)" ] && break; sleep 0.2; done
[ -z "$(squeue -h)" ] || { squeue >&2; die "jobs left in the queue after the failure"; }
ok=1
echo "farm test: OK" >&2
