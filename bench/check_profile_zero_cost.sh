#!/usr/bin/env bash
# Proves the per-stage profile hooks cost nothing when MPTRACK_PROFILE is 0:
# compiles core/src/instantiations.cpp (the whole of mptrack_core_static:
# every tracker and the front end, float) twice with the core_static flags
# of the given build tree -- once against core/include as it is, once
# against a copy with every MPTRACK_PROFILE_* hook line and the profile.h
# include removed -- and compares the disassembly and section sizes.
# Exit 0 if identical.
#   bench/check_profile_zero_cost.sh [BUILD_DIR]   (default build/host)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build/host}
NINJA=$BUILD/build.ninja
[ -f "$NINJA" ] || { echo "no $NINJA (configure a host tree first)" >&2; exit 2; }
rule=$(grep -A8 'build core/CMakeFiles/mptrack_core_static.dir/src/instantiations.cpp.o' "$NINJA")
defines=$(sed -n 's/^ *DEFINES = //p' <<<"$rule")
flags=$(sed -n 's/^ *FLAGS = //p' <<<"$rule")
includes=$(sed -n 's/^ *INCLUDES = //p' <<<"$rule")
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$BUILD/CMakeCache.txt")
case "$flags $defines" in *MPTRACK_PROFILE=1*) echo "tree $BUILD has MPTRACK_PROFILE on" >&2; exit 2 ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r "$ROOT/core/include" "$tmp/stripped"
grep -rlE 'MPTRACK_PROFILE_(STEP|STAGE)\(|include "mptrack/profile.h"' "$tmp/stripped" | while read -r f; do
  sed -i -E '/^\s*MPTRACK_PROFILE_(STEP|STAGE)\(.*\);\s*$/d; /^#include "mptrack\/profile.h"$/d' "$f"
done
hooks=$(grep -rE '^\s*MPTRACK_PROFILE_(STEP|STAGE)\(' "$ROOT/core/include" | wc -l)
left=$(grep -rE 'MPTRACK_PROFILE_(STEP|STAGE)\(' "$tmp/stripped" --include='*.h' | grep -v 'mptrack/profile.h' | wc -l || true)
[ "$left" -eq 0 ] || { echo "could not strip every hook line" >&2; exit 2; }
inc_stripped=${includes//$ROOT\/core\/include/$tmp/stripped}
# shellcheck disable=SC2086
"$cxx" $defines $includes $flags -c "$ROOT/core/src/instantiations.cpp" -o "$tmp/with_hooks.o"
# shellcheck disable=SC2086
"$cxx" $defines $inc_stripped $flags -c "$ROOT/core/src/instantiations.cpp" -o "$tmp/without.o"
objdump -d --no-show-raw-insn "$tmp/with_hooks.o" | tail -n +3 > "$tmp/a.s"
objdump -d --no-show-raw-insn "$tmp/without.o" | tail -n +3 > "$tmp/b.s"
size -A "$tmp/with_hooks.o" | tail -n +2 > "$tmp/a.size"
size -A "$tmp/without.o" | tail -n +2 > "$tmp/b.size"
n=$(grep -cE '^\s+[0-9a-f]+:' "$tmp/a.s" || true)
if cmp -s "$tmp/a.s" "$tmp/b.s" && cmp -s "$tmp/a.size" "$tmp/b.size"; then
  echo "profile hooks off: mptrack_core_static object identical ($hooks hook lines, $n instructions, same sections)"
else
  echo "profile hooks off: object code DIFFERS" >&2
  diff "$tmp/a.s" "$tmp/b.s" | head -n 20 >&2
  exit 1
fi
