#!/usr/bin/env bash
# Runs one Blender test script headless in a given Blender version, the way CTest calls it:
#   run_blender.sh VERSION SCRIPT ZIP SPT WORKDIR [MEDIA_DIR]
# VERSION 3.4 is the host's own blender (Debian 12). 4.3 and 5.2 run in root folders of their
# own (blender_root.sh: Debian 13 and unstable), made once and kept; the host-built spt is copied
# in with its libraries, and the source tree, the build tree and the media folder are bind-mounted
# at the same paths in a private mount namespace (gone with the process, nothing to unmount).
# A Blender that cannot be had is a failure, never a skip. SPT_EXTRA_MOUNTS (folders separated by
# ':') are bound too.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
version="$1" script="$2" zip="$3" spt="$4" work="$5" media="${6:-}"
src="$(cd "$here/../.." && pwd)"
build="$(cd "$(dirname "$zip")" && pwd)"
rm -rf "$work"
mkdir -p "$work/home"
args=(-b --factory-startup --python-exit-code 1 --python "$script" -- "$zip")

if [ "$version" = 3.4 ]; then
  command -v blender >/dev/null || { echo "FAIL: no blender on PATH (apt-get install blender)"; exit 1; }
  have="$(blender --version 2>/dev/null | head -1)"
  case "$have" in "Blender 3.4"*) ;; *) echo "FAIL: host blender is '$have', not 3.4"; exit 1 ;; esac
  exec env HOME="$work/home" blender "${args[@]}" "$spt" "$work" "$media"
fi

root="$(flock /tmp/spt-blender-root.lock "$here/blender_root.sh" ensure "$version")" \
  || { echo "FAIL: could not make the Blender $version root"; exit 1; }
inner_spt=""
if [ -n "$spt" ]; then
  flock /tmp/spt-blender-root.lock "$here/blender_root.sh" install-spt "$version" "$spt" \
    || { echo "FAIL: could not put spt into the Blender $version root"; exit 1; }
  inner_spt=/usr/local/bin/spt
fi
mounts=("$src" "$build" "$work")
IFS=: read -r -a extra <<< "${SPT_EXTRA_MOUNTS:-}"   # more folders to bind (bench/blender_bench.sh)
for d in "${extra[@]}"; do [ -n "$d" ] && mounts+=("$(cd "$d" && pwd)"); done
[ -n "$media" ] && [ -d "$media" ] && mounts+=("$(cd "$media" && pwd)")
script_cmd='set -e; root="$1"; shift; n="$1"; shift
for i in $(seq 1 "$n"); do d="$1"; shift; mkdir -p "$root$d"; mount --bind "$d" "$root$d"; done
mount -t proc proc "$root/proc" 2>/dev/null || true
mkdir -p "$root/dev/shm"; mount -t tmpfs tmpfs "$root/dev/shm" 2>/dev/null || true
exec chroot "$root" "$@"'
exec unshare --mount --propagation private sh -c "$script_cmd" sh "$root" "${#mounts[@]}" "${mounts[@]}" \
  env HOME="$work/home" PATH=/usr/local/bin:/usr/bin:/bin blender "${args[@]}" "$inner_spt" "$work" "$media"
