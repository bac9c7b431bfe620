#!/usr/bin/env bash
# The Debian package as a user meets it (issue 37): `apt install ./spt_VERSION_amd64.deb` in a
# Debian 12 root that has only the base system and a compiler, then spt paints, renders and
# verifies there, the man page and the add-on zips are where Debian puts such files, and a
# 20-line program (program/) builds against libspt with find_package(spt).
#   deb_in_root.sh DEB SAMPLE.png
# The base root (mmdebstrap, about a minute once) and apt's downloads are kept between runs in
# $SPT_PACKAGE_ROOTS (default /var/cache/spt/package-roots); each run works in a copy of it.
set -euo pipefail
deb="$1"; sample="$2"
here="$(cd "$(dirname "$0")" && pwd)"
base="${SPT_PACKAGE_ROOTS:-/var/cache/spt/package-roots}"
mirror="${SPT_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
die() { echo "deb_in_root.sh: $*" >&2; exit 1; }
[ -f "$deb" ] || die "no package at '$deb' (cmake --build BUILD --target package)"
[ -f "$sample" ] || die "no sample image at '$sample'"
command -v mmdebstrap >/dev/null || die "mmdebstrap is not installed (apt-get install mmdebstrap)"

dev="$base/bookworm-dev"
if [ ! -f "$dev/.spt-root-complete" ]; then
  mkdir -p "$base"
  tmp="$(mktemp -d "$base/.making.XXXXXX")"
  echo "deb_in_root.sh: making the Debian 12 root in $dev (once)" >&2
  mmdebstrap --quiet --variant=apt --include=build-essential,cmake,ca-certificates bookworm "$tmp/root" "$mirror" >&2 \
    || { rm -rf "$tmp"; die "mmdebstrap of bookworm failed"; }
  touch "$tmp/root/.spt-root-complete"
  rm -rf "$dev"; mv "$tmp/root" "$dev"; rm -rf "$tmp"
fi

work="$(mktemp -d /var/tmp/spt-deb-root.XXXXXX)"
root="$work/root"
cleanup() { umount "$root/var/cache/apt/archives" 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
cp -a "$dev" "$root"
mkdir -p "$base/archives/partial" "$root/tmp/job"
mount --bind "$base/archives" "$root/var/cache/apt/archives"
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$deb" "$sample" "$root/tmp/job/"
cp -r "$here/program" "$root/tmp/job/program"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root DEBIAN_FRONTEND=noninteractive "$@"; }

in_root apt-get update -qq
in_root apt-get install -y -qq "/tmp/job/$(basename "$deb")" >"$work/apt.log" 2>&1 \
  || { tail -20 "$work/apt.log" >&2; die "apt install of the package failed"; }
in_root dpkg -s spt | grep -q '^Status: install ok installed' || die "spt is not installed in the root"
# Only Debian's packages came with it: every installed package is from the mirror, but spt.
foreign="$(in_root dpkg-query -W -f='${Package} ${Maintainer}\n' | grep -c 'spt project' || true)"
[ "$foreign" = 1 ] || die "expected spt alone from outside Debian, found $foreign"
in_root spt --version
in_root test -f /usr/share/man/man1/spt.1 || die "no man page"
in_root test -f /usr/share/spt/blender/spt_grease_pencil.zip || die "no add-on zip"
in_root test -f /usr/lib/cmake/spt/sptConfig.cmake || die "no CMake package"
img="/tmp/job/$(basename "$sample")"
in_root spt paint "$img" -o /tmp/job/out.spt --max-strokes 300 --progress none
in_root spt verify /tmp/job/out.spt
in_root spt render /tmp/job/out.spt -o /tmp/job/out.png
in_root test -s /tmp/job/out.png || die "spt render wrote nothing"
in_root cmake -S /tmp/job/program -B /tmp/job/program/build -DCMAKE_BUILD_TYPE=Release >/dev/null
in_root cmake --build /tmp/job/program/build >/dev/null
out="$(in_root /tmp/job/program/build/spt_frames /tmp/job/out.spt)"
echo "program: $out"
case "$out" in *"1 frames"*) ;; *) die "the program's output is unexpected: $out" ;; esac
echo "deb_in_root.sh: the package installs, runs and builds against in Debian 12"
