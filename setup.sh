#!/usr/bin/env bash
# spt set-up: installs what is needed (Debian 12, as root), builds, then
#   ./setup.sh demo   paints the bundled sample and writes out/demo-side-by-side.png
#   ./setup.sh test   runs every test (CTest)
# Idempotent: packages already installed are not fetched again; the build is incremental.
set -euo pipefail
cd "$(dirname "$0")"
mode="${1:-demo}"
build="${SPT_BUILD_DIR:-build}"

core_pkgs=(build-essential cmake ninja-build pkg-config git python3
           libopenimageio-dev openimageio-tools libopencv-dev libopenexr-dev
           libavformat-dev libavcodec-dev libswscale-dev libavutil-dev
           libcli11-dev nlohmann-json3-dev libpugixml-dev libpng-dev zlib1g-dev libminizip-dev libyaml-dev
           help2man patchelf)           # the Debian package's man page; the relocatable bundle
test_pkgs=(libgtest-dev libgmock-dev clang python3-numpy ccache
           blender libegl1 libegl-mesa0 ffmpeg chromium inkscape xz-utils
           mmdebstrap time              # Blender 4.3 and 5.2 roots (tests/blender/blender_root.sh)
           emscripten node-acorn nodejs   # the web player (web/) and its Chromium test
           slurm-wlm munge iproute2     # the farm test's own Slurm cluster (tests/farm)
           libjxl-tools webp optipng potrace   # bench/ comparisons only
           python3-openimageio          # bench/color_bench.py (EXR sizes and errors)
           linux-perf)                  # bench/profile_stages.py

install_pkgs() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "setup: installing ${missing[*]}"
  local sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
}

build() {
  local tests="$1"; shift
  # ccache (when installed) makes a rebuild of an unchanged tree, in another clone too, a copy.
  local launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # Paths inside the checkout are hashed relative to it, so a clone in another folder (CI's)
  # hits the cache this one filled.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPT_BUILD_TESTS="$tests" "${launcher[@]}" "$@" >/dev/null
  cmake --build "$build" --parallel "$(nproc)"
}

case "$mode" in
  demo)
    install_pkgs "${core_pkgs[@]}"
    build OFF
    mkdir -p out
    "$build/bin/spt" paint samples/coffee-320.png -o out/demo.spt --seed 1 --target-psnr 28 \
        --preview out/demo.png --side-by-side out/demo-side-by-side.png --progress plain
    "$build/bin/spt" info out/demo.spt
    echo "setup: wrote out/demo.spt and out/demo-side-by-side.png (source | painting)"
    ;;
  test)
    install_pkgs "${core_pkgs[@]}" "${test_pkgs[@]}"
    # playwright-core drives Chromium in tests/web (versions pinned by its package-lock.json).
    # npm comes with nodejs from NodeSource; Debian's own nodejs needs the npm package.
    command -v npm >/dev/null || install_pkgs npm
    (cd tests/web && npm ci --no-audit --no-fund --loglevel=error)
    build ON -DSPT_BUILD_WEB=ON   # the tests include the WebAssembly player's
    ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 900
    # The fuzz corpora once more, through the instrumented targets (ASan, UBSan fatal): ctest
    # above replays them in the plain build, this one also sees memory errors and UB.
    REPLAY=1 tests/fuzz/fuzz_all.sh 0 "${build}-fuzz"
    ;;
  *)
    echo "usage: ./setup.sh demo|test" >&2; exit 2 ;;
esac
