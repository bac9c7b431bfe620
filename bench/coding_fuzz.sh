#!/bin/sh
# Fuzzes each libspt sub-parser for N seconds (default 60) with libFuzzer + ASan + UBSan.
#   bench/coding_fuzz.sh [seconds] [build_dir]
set -eu
secs=${1:-60}
src=$(cd "$(dirname "$0")/.." && pwd)
build=${2:-$src/build-fuzz}
CC=clang CXX=clang++ cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSPT_BUILD_FUZZERS=ON -DSPT_BUILD_CONVERTER=OFF >/dev/null
for t in container strokes motion template; do
  cmake --build "$build" --target fuzz_$t -j2 >/dev/null
  work=$(mktemp -d)
  cp "$src/tests/fuzz/corpus/$t/"* "$work/"
  echo "== fuzz_$t for ${secs}s"
  "$build/tests/fuzz/fuzz_$t" -max_total_time="$secs" -rss_limit_mb=2048 -artifact_prefix="$build/crash-$t-" \
    "$work" 2>&1 | grep -E "^#[0-9]+.*DONE|ERROR|SUMMARY|crash-" || true
  rm -rf "$work"
done
