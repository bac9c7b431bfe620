#!/usr/bin/env bash
# The relocatable bundle as a user meets it (issue 37): unpacked by a user who is not root into
# Debian 12, 13 and unstable roots that hold nothing but the minimal base system (mmdebstrap
# --variant=minbase), spt paints a PNG sequence, an EXR with alpha and a video file there, and
# renders, describes and verifies what it painted.
#   bundle_in_roots.sh BUNDLE.tar.xz MEDIA_DIR [SUITE...]     (default: bookworm trixie sid)
# The roots are made once and kept in $SPT_PACKAGE_ROOTS (default /var/cache/spt/package-roots);
# each run works in a copy.
set -euo pipefail
bundle="$1"; media="$2"; shift 2
suites=("$@"); [ ${#suites[@]} -gt 0 ] || suites=(bookworm trixie sid)
base="${SPT_PACKAGE_ROOTS:-/var/cache/spt/package-roots}"
mirror="${SPT_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
die() { echo "bundle_in_roots.sh: $*" >&2; exit 1; }
[ -f "$bundle" ] || die "no bundle at '$bundle' (cmake --build BUILD --target bundle)"
for f in cartoon/star/f.0000.png exr/orbit/orbit.0001.exr video/butterfly-cartoon.avi; do
  [ -f "$media/$f" ] || die "the shared media are needed: $media/$f"
done
command -v mmdebstrap >/dev/null || die "mmdebstrap is not installed (apt-get install mmdebstrap)"

ensure_root() {  # SUITE -> prints the cached minbase root
  local suite="$1" root="$base/$1-minbase" tmp opts=()
  if [ ! -f "$root/.spt-root-complete" ]; then
    mkdir -p "$base"
    tmp="$(mktemp -d "$base/.making.XXXXXX")"
    [ "$suite" = sid ] && opts+=(--aptopt='Acquire::Check-Valid-Until "false"')
    echo "bundle_in_roots.sh: making the $suite minbase root in $root (once)" >&2
    mmdebstrap --quiet --variant=minbase "${opts[@]}" "$suite" "$tmp/root" "$mirror" >&2 \
      || { rm -rf "$tmp"; die "mmdebstrap of $suite failed"; }
    touch "$tmp/root/.spt-root-complete"
    rm -rf "$root"; mv "$tmp/root" "$root"; rm -rf "$tmp"
  fi
  echo "$root"
}

work="$(mktemp -d /var/tmp/spt-bundle-roots.XXXXXX)"
cleanup() { for p in "$work"/*/proc; do umount "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
for suite in "${suites[@]}"; do
  root="$work/$suite"
  cp -a "$(ensure_root "$suite")" "$root"
  home="$root/home/user"
  mkdir -p "$home/in"
  tar -C "$home" -xJf "$bundle"
  for i in 0 1 2; do cp "$media/cartoon/star/f.000$i.png" "$home/in/"; done
  cp "$media/exr/orbit/orbit.0001.exr" "$media/video/butterfly-cartoon.avi" "$home/in/"
  chown -R 65534:65534 "$home"
  # The loader finds $ORIGIN through /proc/self/exe, as on any running system.
  mount -t proc proc "$root/proc"
  spt="$(cd "$home" && ls -d spt-*/bin/spt)"
  as_user() { chroot --userspec=65534:65534 "$root" env -i HOME=/home/user PATH=/usr/bin:/bin sh -c "cd /home/user && $1"; }
  echo "== $suite: $(as_user "./$spt --version")"
  as_user "./$spt paint 'in/f.####.png' -o seq.spt --max-strokes 400 --progress none"
  as_user "./$spt paint in/orbit.0001.exr -o exr.spt --max-strokes 400 --progress none"
  as_user "./$spt info exr.spt" | grep -qi 'alpha' || die "$suite: the EXR's painting has no alpha canvas"
  as_user "./$spt paint in/butterfly-cartoon.avi --frames 0-2 -o video.spt --max-strokes 400 --progress none"
  for f in seq exr video; do as_user "./$spt verify $f.spt" >/dev/null || die "$suite: $f.spt does not verify"; done
  as_user "./$spt render seq.spt -o 'seq.####.png'"
  [ -s "$home/seq.0002.png" ] || die "$suite: spt render wrote no frames"
  as_user "./$spt info video.spt" | grep -q 'frames      3 found' || die "$suite: the video's painting lacks its 3 frames"
  echo "== $suite: painted a PNG sequence, an EXR with alpha and a video, rendered, verified"
  umount "$root/proc"
  rm -rf "$root"
done
echo "bundle_in_roots.sh: the bundle runs in ${suites[*]}"
