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
           libcli11-dev nlohmann-json3-dev libpugixml-dev libpng-dev zlib1g-dev)
test_pkgs=(libgtest-dev libgmock-dev clang python3-numpy
           blender libegl1 libegl-mesa0 ffmpeg chromium xz-utils
           libjxl-tools webp optipng    # these three: bench/ comparisons only
           slurm-wlm munge iproute2)    # the farm test's own Slurm cluster (tests/farm)

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
  local tests="$1"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPT_BUILD_TESTS="$tests" >/dev/null
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
    build ON
    ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 900
    ;;
  *)
    echo "usage: ./setup.sh demo|test" >&2; exit 2 ;;
esac
