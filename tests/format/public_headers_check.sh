#!/bin/bash
# public_headers_check.sh CXX INCLUDE_DIR WORK_DIR: libspt's public headers are standard C++20.
# Compiles a file that includes spt/spt.hpp and then every header of spt/ on its own with
# `CXX -std=c++20 -Wpedantic -Werror` (plus -Wall -Wextra), looks for compiler extensions by
# name (__extension__ hides them from -Wpedantic), and checks that spt.hpp's map of the
# headers names every one of them. Fails, naming the compiler, when CXX cannot be run: the
# check never passes without its compiler.
set -u
cxx=$1 inc=$2 work=$3
if ! command -v "$cxx" >/dev/null 2>&1; then
    echo "public_headers_check: compiler '$cxx' not found (clang is in setup.sh's test packages)" >&2
    exit 1
fi
mkdir -p "$work"
tu="$work/public_headers_$(basename "$cxx").cpp"
{
    echo '#include <spt/spt.hpp>'
    for h in "$inc"/spt/*.hpp; do echo "#include <spt/$(basename "$h")>"; done
    echo 'int main() { return 0; }'
} > "$tu"
"$cxx" -std=c++20 -Wpedantic -Werror -Wall -Wextra -fsyntax-only -I "$inc" "$tu" || {
    echo "public_headers_check: $cxx -std=c++20 -Wpedantic -Werror rejects libspt's public headers" >&2
    exit 1
}
# __extension__ silences -Wpedantic, so extensions are also looked for by name.
if grep -nE '__int128|__extension__|__attribute__|__builtin_|__declspec|#pragma GCC' "$inc"/spt/*.hpp; then
    echo "public_headers_check: libspt's public headers use a compiler extension (above)" >&2
    exit 1
fi
missing=0
for h in "$inc"/spt/*.hpp; do
    n=spt/$(basename "$h")
    [ "$n" = spt/spt.hpp ] && continue
    if ! grep -q "^//   $n " "$inc/spt/spt.hpp"; then
        echo "public_headers_check: spt/spt.hpp's map of the headers does not name $n" >&2
        missing=1
    fi
done
[ $missing = 0 ] || exit 1
echo "public_headers_check: $("$cxx" --version | head -1): $(ls "$inc"/spt/*.hpp | wc -l) headers, -Wpedantic -Werror clean, all in spt.hpp's map"
