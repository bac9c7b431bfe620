#!/bin/sh
# include_arrows.sh REPO: fails, naming each file and line, where a part includes the headers of
# a part it must not see. Frame input (converter/src/frames) sits below the painters; the video
# encoder (converter/src/video), the cartoon painter (cartoon) and the planner (plan) each read
# frames through it and include none of each other's headers; farm/ sees only the plan model.
# One rule a line: the folder, then the include prefixes it must not use.
set -u
repo=${1:?usage: include_arrows.sh REPO}
status=0
check() {
    dir=$1
    shift
    [ -d "$repo/$dir" ] || { echo "include_arrows: $repo/$dir: no such folder"; exit 1; }
    for prefix in "$@"; do
        hits=$(grep -rnE "^[[:space:]]*#[[:space:]]*include[[:space:]]*\"$prefix/" "$repo/$dir" \
               --include='*.cpp' --include='*.hpp' --include='*.h')
        if [ -n "$hits" ]; then
            echo "$dir must not include $prefix/ headers:"
            echo "$hits" | sed "s|^$repo/||"
            status=1
        fi
    done
}
check converter/src/frames video cartoon plan job cli paint
check converter/src/video cartoon plan job cli
check converter/src/cartoon video plan job cli
check converter/src/plan video cartoon job cli
check farm video cartoon frames paint job cli
[ "$status" -eq 0 ] && echo "include arrows: one way"
exit $status
