#!/bin/sh
# Fuzzes every parser target for SECONDS each (default 60) with libFuzzer, ASan and UBSan (UB is
# fatal), over instrumented builds of libspt, the importers and the converter's ROI parser, and
# prints one line per target: executions, coverage (edges, features), corpus size and findings.
#   tests/fuzz/fuzz_all.sh [seconds] [build_dir] [target...]
# Environment: RUNS=N stops a target after N executions (whichever comes first with SECONDS);
# MERGE=1 merges the inputs that reached new coverage into the committed corpus (tests/...).
# REPLAY=1 runs each committed corpus once through the instrumented target (no fuzzing; what
# ./setup.sh test does): the exit status is 1 when any input fails.
# Findings (crash-, leak-, timeout-, oom- reproducers) are left in BUILD/findings/.
set -eu
secs=${1:-60}
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$src/build-fuzz}
[ $# -ge 2 ] && shift 2 || shift $#
CC=clang CXX=clang++ cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSPT_BUILD_FUZZERS=ON -DSPT_BUILD_CONVERTER=OFF -DSPT_BUILD_TESTS=ON >/dev/null

# target  binary (under BUILD/tests)  corpus (under tests/)  -max_len  -timeout (s)
table="template fuzz/fuzz_template fuzz/corpus/template 4096 10
roi fuzz/fuzz_roi fuzz/corpus/roi 8192 10
motion fuzz/fuzz_motion fuzz/corpus/motion 4096 10
json fuzz_importers/fuzz_importers_json fuzz_importers/corpus/json 65536 10
geometrize fuzz_importers/fuzz_importers_geometrize fuzz_importers/corpus/geometrize 8192 10
strokes fuzz/fuzz_strokes fuzz/corpus/strokes 4096 10
svg fuzz_importers/fuzz_importers_svg fuzz_importers/corpus/svg 65536 10
container fuzz/fuzz_container fuzz/corpus/container 32768 10"

mkdir -p "$build/findings"
rm -f "$build/findings/.failed"
[ "${REPLAY:-0}" = 1 ] || printf '%-11s %12s %8s %8s %7s %9s\n' target execs cov ft corpus findings
echo "$table" | while read -r t bin corpus maxlen timeout; do
  if [ $# -gt 0 ]; then
    case " $* " in *" $t "*) ;; *) continue ;; esac
  fi
  cmake --build "$build" --target "$(basename "$bin")" -j2 >"$build/build.log" 2>&1 ||
    { tail -20 "$build/build.log" >&2; echo "fuzz_all.sh: building $(basename "$bin") failed ($build/build.log)" >&2; exit 1; }
  log="$build/findings/$t.log"
  if [ "${REPLAY:-0}" = 1 ]; then
    n=$(ls "$src/tests/$corpus" | wc -l)
    if "$build/tests/$bin" -runs=0 -max_len="$maxlen" -timeout="$timeout" -rss_limit_mb=2048 \
        -artifact_prefix="$build/findings/$t-" "$src/tests/$corpus" >"$log" 2>&1; then
      printf '%-11s replayed %s inputs, 0 findings\n' "$t" "$n"
    else
      printf '%-11s replayed %s inputs: FAILED (%s)\n' "$t" "$n" "$log"
      grep -E "ERROR|SUMMARY|runtime error" "$log" | head -5 | sed 's/^/    /'
      touch "$build/findings/.failed"
    fi
    continue
  fi
  work=$(mktemp -d)
  cp "$src/tests/$corpus/"* "$work/"
  before=$(ls "$build/findings" | grep -c "^$t-" || true)
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    "$build/tests/$bin" -max_total_time="$secs" ${RUNS:+-runs=$RUNS} -max_len="$maxlen" -timeout="$timeout" \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/findings/$t-" "$work" >"$log" 2>&1 || true
  after=$(ls "$build/findings" | grep -c "^$t-" || true)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
  ft=$(echo "$last" | sed -n 's/.*ft: \([0-9]*\).*/\1/p')
  corp=$(echo "$last" | sed -n 's/.*corp: \([0-9]*\).*/\1/p')
  found=$((after - before))
  grep -q -E "ERROR: (libFuzzer|AddressSanitizer|LeakSanitizer)|runtime error:" "$log" && [ "$found" -eq 0 ] && found=1
  printf '%-11s %12s %8s %8s %7s %9s\n' "$t" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$found"
  [ "$found" -eq 0 ] || grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" | head -5 | sed 's/^/    /'
  if [ "${MERGE:-0}" = 1 ] && [ "$found" -eq 0 ]; then
    "$build/tests/$bin" -merge=1 -max_len="$maxlen" -timeout="$timeout" -artifact_prefix="$build/findings/$t-merge-" \
      "$src/tests/$corpus" "$work" >/dev/null 2>&1 || true
  fi
  rm -rf "$work"
done
[ ! -e "$build/findings/.failed" ]
