#!/usr/bin/env bash
# Root folders that hold a newer Blender than the host's, for the add-on's tests:
#   blender_root.sh path VERSION        prints the root's folder (made or not)
#   blender_root.sh ensure VERSION      makes it with mmdebstrap unless it is there (prints it)
#   blender_root.sh install-spt VERSION SPT
#                                       puts the host-built spt (and the shared libraries it
#                                       links, from the host) into ROOT/opt/spt, and a wrapper
#                                       ROOT/usr/local/bin/spt that sets LD_LIBRARY_PATH for spt
# VERSION: 4.3 (Debian 13 "trixie", Blender 4.3.2) or 5.2 (Debian unstable, Blender 5.2.2 LTS).
# Roots are kept between runs in $SPT_BLENDER_ROOTS (default /var/cache/spt/blender-roots):
# about 1 GB and 30-60 s each the first time. A root is made in a temporary folder and renamed
# when complete, so an interrupted run never leaves a half-made root that looks finished.
set -euo pipefail
base="${SPT_BLENDER_ROOTS:-/var/cache/spt/blender-roots}"
mirror="${SPT_DEBIAN_MIRROR:-http://deb.debian.org/debian}"

die() { echo "blender_root.sh: $*" >&2; exit 1; }

suite_of() {
  case "$1" in
    4.3) echo trixie ;;
    5.2) echo sid ;;
    *) die "unknown Blender version '$1' (4.3 or 5.2)" ;;
  esac
}

root_of() { echo "$base/blender-$1"; }

ensure() {
  local version="$1" suite root tmp
  suite="$(suite_of "$version")"
  root="$(root_of "$version")"
  if [ -x "$root/usr/bin/blender" ] && [ -f "$root/.spt-root-complete" ]; then
    echo "$root"; return 0
  fi
  command -v mmdebstrap >/dev/null || die "mmdebstrap is not installed (apt-get install mmdebstrap)"
  mkdir -p "$base"
  tmp="$(mktemp -d "$base/.making-$version.XXXXXX")"
  trap 'rm -rf "$tmp"' EXIT
  local pkgs="blender,python3-numpy,libegl1,libegl-mesa0,libgl1,libopengl0"
  local opts=()
  if [ "$suite" = sid ]; then
    opts+=(--aptopt='Acquire::Check-Valid-Until "false"')  # the served sid snapshot has expired
  fi
  echo "blender_root.sh: making the Blender $version root ($suite) in $root (once; about a minute)" >&2
  mmdebstrap --quiet --variant=apt "${opts[@]}" --include="$pkgs" "$suite" "$tmp/root" "$mirror" >&2 \
    || die "mmdebstrap of $suite failed (Blender $version root)"
  [ -x "$tmp/root/usr/bin/blender" ] || die "the $suite root has no /usr/bin/blender"
  touch "$tmp/root/.spt-root-complete"
  rm -rf "$root"
  mv "$tmp/root" "$root"
  rm -rf "$tmp"
  trap - EXIT
  echo "$root"
}

install_spt() {
  local version="$1" spt="$2" root dest lib
  root="$(root_of "$version")"
  [ -f "$root/.spt-root-complete" ] || die "no Blender $version root at $root (run: $0 ensure $version)"
  [ -x "$spt" ] || die "$spt: not an executable"
  dest="$root/opt/spt"
  mkdir -p "$dest/lib" "$root/usr/local/bin"
  # The libraries ldd resolves on the host, but the C library and the loader, which the root's
  # own glibc (newer) provides.
  while read -r lib; do
    case "$(basename "$lib")" in
      libc.so*|libm.so*|libpthread.so*|libdl.so*|librt.so*|ld-linux*|libresolv.so*) continue ;;
    esac
    # Copied beside and renamed into place: tests running in parallel may have the old one
    # mapped, and overwriting it in place would change it under them.
    target="$dest/lib/$(basename "$lib")"
    cmp -s "$lib" "$target" 2>/dev/null || { cp -L "$lib" "$target.new.$$" && mv -f "$target.new.$$" "$target"; }
  done < <(ldd "$spt" | awk '/=> \// {print $3}')
  if ! cmp -s "$spt" "$dest/spt" 2>/dev/null; then
    cp "$spt" "$dest/spt.new.$$" && mv -f "$dest/spt.new.$$" "$dest/spt"
  fi
  # The wrapper too is written beside and renamed: a test running it in parallel makes writing
  # it in place fail ("Text file busy").
  wrapper="$root/usr/local/bin/spt"
  cat > "$wrapper.new.$$" <<'EOF'
#!/bin/sh
# The host-built spt with the host's libraries beside it (tests/blender/blender_root.sh).
LD_LIBRARY_PATH=/opt/spt/lib exec /opt/spt/spt "$@"
EOF
  chmod +x "$wrapper.new.$$"
  if cmp -s "$wrapper.new.$$" "$wrapper" 2>/dev/null; then rm -f "$wrapper.new.$$"; else mv -f "$wrapper.new.$$" "$wrapper"; fi
  chroot "$root" /usr/local/bin/spt --version >/dev/null || die "spt does not run inside $root"
}

case "${1:-}" in
  path) root_of "${2:?VERSION}" ;;
  ensure) ensure "${2:?VERSION}" ;;
  install-spt) install_spt "${2:?VERSION}" "${3:?SPT}" ;;
  *) echo "usage: $0 path|ensure VERSION | install-spt VERSION SPT" >&2; exit 2 ;;
esac
