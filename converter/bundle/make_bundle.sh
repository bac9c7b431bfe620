#!/usr/bin/env bash
# A relocatable spt for Linux x86-64 (issue 37): `cmake --build BUILD --target bundle` writes
# BUILD/spt-VERSION-linux-x86_64.tar.xz holding bin/spt with the shared libraries it loads
# beside it in lib/ (found through an $ORIGIN run path, so the folder works wherever it is
# unpacked, by any user), the add-on zips, the web player, the spec, the man page and the README.
# The C library and the loader are the system's (glibc is backward compatible: a bundle made on
# Debian 12 runs on 13 and unstable).
#   make_bundle.sh BUILD_DIR OUT.tar.xz README.md
set -euo pipefail
build="$1"; out="$2"; readme="$3"
die() { echo "make_bundle.sh: $*" >&2; exit 1; }
command -v patchelf >/dev/null || die "patchelf is not installed (apt-get install patchelf)"
name="$(basename "$out" .tar.xz)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
stage="$work/$name"
cmake --install "$build" --prefix "$stage" >/dev/null
[ -x "$stage/bin/spt" ] || die "no bin/spt after installing $build"
cp "$readme" "$stage/README.md"
mkdir -p "$stage/lib"
n=0
while read -r lib; do
  case "$(basename "$lib")" in
    libc.so*|libm.so*|libpthread.so*|libdl.so*|librt.so*|ld-linux*|libresolv.so*|libutil.so*) continue ;;
  esac
  cp -L "$lib" "$stage/lib/"
  n=$((n + 1))
done < <(ldd "$stage/bin/spt" | awk '/=> \// {print $3}')
# DT_RPATH (not RUNPATH) on the executable: the loader then searches lib/ for the libraries'
# own dependencies too; a library with a run path of its own gets $ORIGIN instead.
patchelf --force-rpath --set-rpath '$ORIGIN/../lib' "$stage/bin/spt"
for lib in "$stage"/lib/*.so*; do
  if [ -n "$(patchelf --print-rpath "$lib" 2>/dev/null)" ]; then patchelf --set-rpath '$ORIGIN' "$lib"; fi
done
missing="$(env -i "$stage/bin/spt" --version >/dev/null 2>&1 || echo x)"
[ -z "$missing" ] || die "the bundled spt does not start"
tar -C "$work" -cf - "$name" | xz -T0 -6 > "$out.partial"
mv "$out.partial" "$out"
echo "make_bundle.sh: $out: $n libraries, $(du -sb "$stage" | cut -f1) bytes unpacked, $(stat -c %s "$out") packed"
