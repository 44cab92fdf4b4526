#!/usr/bin/env bash
# Hexagon (Qualcomm DSP ISA) build of core with Debian's clang, and the
# golden runner under qemu-hexagon:
#   toolchains/hexagon-clang.sh [BUILD_DIR]     (default build/hexagon)
# Compiles one translation unit per core component (explicit instantiations,
# float, DefaultCaps, like core/src/instantiations.cpp) and every golden case
# (tests/golden/cases), freestanding: no Hexagon C library exists in Debian,
# so the C++ headers are libstdc++'s and newlib's from the arm-none-eabi
# packages (header-only use: core calls no libc function but memcpy/memset).
# Prints text/data/bss per component and the runtime symbols the objects
# still need (what a Hexagon runtime must provide: compiler-rt's
# __hexagon_* division/sqrt helpers and mem* functions); fails if a
# component does not compile or asks for heap or exception machinery.
# Flags are the bit-exactness set of cmake/MptrackFlags.cmake.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$ROOT/build/hexagon}
CPU=${MPTRACK_HEXAGON_CPU:-hexagonv67}  # the ISA version qemu-hexagon 7.2 models
CLANG=${MPTRACK_HEXAGON_CLANG:-clang++}
NM=$(command -v llvm-nm-14 || command -v llvm-nm)
SIZE=$(command -v llvm-size-14 || command -v llvm-size)
A=/usr/lib/arm-none-eabi/include
CXXV=$(ls "$A/c++" | sort -V | tail -n1)
RES=$("$CLANG" -print-resource-dir)
mkdir -p "$OUT/src" "$OUT/obj"

FLAGS=(--target=hexagon-unknown-none-elf -mcpu="$CPU" -std=c++17 -O2 -DNDEBUG
       -ffp-contract=off -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections
       -DEIGEN_DONT_VECTORIZE -DEIGEN_MPL2_ONLY -DEIGEN_NO_MALLOC
       -D__IEEE_LITTLE_ENDIAN   # newlib's headers know no Hexagon; it is little-endian
       -nostdinc -nostdinc++ -isystem "$A/c++/$CXXV" -isystem "$A/c++/$CXXV/arm-none-eabi/thumb/v7+fp/hard"
       -isystem "$A" -isystem "$RES/include" -I"$ROOT/core/include" -isystem /usr/include/eigen3
       -Wall -Wextra -Werror -Wno-unused-command-line-argument)
launcher=()
command -v ccache >/dev/null && launcher=(ccache)

# One translation unit per component.
component() {  # name includes... -- instantiations
  local name=$1; shift
  local f=$OUT/src/$name.cpp
  {
    while [ "$1" != "--" ]; do echo "#include \"$1\""; shift; done
    shift
    echo "namespace mptrack {"
    printf '%s\n' "$@"
    echo "}  // namespace mptrack"
  } >"$f.new"
  cmp -s "$f.new" "$f" 2>/dev/null && rm "$f.new" || mv "$f.new" "$f"
}
component gnn mptrack/caps.h mptrack/gnn/gnn_tracker.h -- \
  "template class GnnTracker<float, DefaultCaps>;"
component mfbp mptrack/caps.h mptrack/mfbp/mfbp_tracker.h -- \
  "template class MfbpTracker<float, DefaultCaps>;"
component phd mptrack/caps.h mptrack/phd/phd_filter.h -- \
  "template class phd::PhdFilter<float, DefaultCaps, false>;" "template class phd::PhdFilter<float, DefaultCaps, true>;"
component cbmember mptrack/caps.h mptrack/cbmember/cbmember_filter.h -- \
  "template class CbMemberFilter<float, DefaultCaps>;"
component frontend mptrack/frontend/front_end.h -- \
  "template class frontend::FrontEnd<frontend::Seed004RadarCaps>;" \
  "template Status frontend::FrontEnd<frontend::Seed004RadarCaps>::process(const frontend::RadarCubeInt16<frontend::Seed004RadarCaps>&, Scan<float, frontend::Seed004RadarCaps::kMaxDetections>&, frontend::FrontEndStageTimes*);"
component metrics mptrack/caps.h mptrack/metrics/assignment.h mptrack/metrics/ospa.h mptrack/metrics/gospa.h -- \
  "template class AssignmentSolver<float, DefaultCaps::kMaxTargets>;" \
  "template class OspaMetric<float, DefaultCaps::kMaxTargets>;" \
  "template class GospaMetric<float, DefaultCaps::kMaxTargets>;"
COMPONENTS=(gnn mfbp phd cbmember frontend metrics)

# Golden cases (the code the bare-metal runners run).
CASES=$(sed -n 's/^MPTRACK_GOLDEN_CASE([A-Za-z0-9_]*, *\([A-Za-z0-9_]*\))$/\1/p' \
  "$ROOT/tests/golden/cases/golden_cases.def" | sort -u)

jobs=()
for c in "${COMPONENTS[@]}"; do jobs+=("$OUT/src/$c.cpp:$OUT/obj/$c.o"); done
for c in golden_sink $CASES; do jobs+=("$ROOT/tests/golden/cases/$c.cpp:$OUT/obj/case_$c.o"); done
printf '%s\n' "${jobs[@]}" | xargs -P "${MPTRACK_JOBS:-2}" -I{} sh -c '
  src=${1%%:*}; obj=${1#*:}; shift
  "$@" -c "$src" -o "$obj" || { echo "hexagon: $src failed" >&2; exit 255; }' _ {} "${launcher[@]}" "$CLANG" "${FLAGS[@]}"

echo "Hexagon ($CPU, clang $("$CLANG" -dumpversion), -O2, float, DefaultCaps): bytes per component"
printf '%-12s %9s %7s %7s\n' component text data bss
for c in "${COMPONENTS[@]}"; do
  "$SIZE" -A "$OUT/obj/$c.o" | awk -v n="$c" '
    $1 ~ /^\.text/ || $1 ~ /^\.rodata/ {t += $2} $1 ~ /^\.data/ || $1 ~ /^\.sdata/ {d += $2}
    $1 ~ /^\.bss/ || $1 ~ /^\.sbss/ {b += $2} END {printf "%-12s %9d %7d %7d\n", n, t, d, b}'
done
objs=()
for c in "${COMPONENTS[@]}"; do objs+=("$OUT/obj/$c.o"); done
for c in golden_sink $CASES; do objs+=("$OUT/obj/case_$c.o"); done
defined=$(for o in "${objs[@]}"; do "$NM" --defined-only "$o"; done | awk '{print $3}' | sort -u)
need=$(for o in "${objs[@]}"; do "$NM" -u "$o"; done | awk '{print $2}' | sort -u | comm -23 - <(echo "$defined"))
echo "runtime symbols the objects need: $(echo $need)"
bad=$(echo "$need" | grep -E '^(_Znw|_Zna|_Zdl|_Zda|malloc|calloc|realloc|free|__cxa_throw|__cxa_allocate_exception|__gxx_personality)' || true)
if [ -n "$bad" ]; then
  echo "hexagon: heap/exception symbols: $bad" >&2
  exit 1
fi
echo "hexagon: ${#COMPONENTS[@]} components and $(echo $CASES | wc -w) golden case files compiled, no heap or exception symbols"

# Golden runner: the cases above + tests/baremetal/golden_runner.cpp, the
# golden files embedded (.incbin), and tests/baremetal/hexagon_rt.cpp as the
# whole runtime (start-up, Linux write/exit, mem*, division and sqrt
# helpers); linked with ld.lld and run under qemu-hexagon when present.
{
  echo "// Generated by toolchains/hexagon-clang.sh: the golden files, embedded."
  for name in $(sed -n 's/^MPTRACK_GOLDEN_CASE(\([A-Za-z0-9_]*\),.*$/\1/p' "$ROOT/tests/golden/cases/golden_cases.def"); do
    printf '__asm__(".section .rodata.mptrack_golden_%s,\\"a\\"\\n.global mptrack_golden_%s\\nmptrack_golden_%s:\\n.incbin \\"%s\\"\\n.byte 0\\n.previous\\n");\n' \
      "$name" "$name" "$name" "$ROOT/tests/golden/data/$name.golden"
  done
} >"$OUT/src/golden_data.cpp"
"${launcher[@]}" "$CLANG" "${FLAGS[@]}" -I"$ROOT/tests/golden/cases" -c "$ROOT/tests/baremetal/golden_runner.cpp" -o "$OUT/obj/runner.o"
"$CLANG" "${FLAGS[@]}" -c "$OUT/src/golden_data.cpp" -o "$OUT/obj/runner_data.o"
"${launcher[@]}" "$CLANG" "${FLAGS[@]}" -ffreestanding -fno-builtin -c "$ROOT/tests/baremetal/hexagon_rt.cpp" -o "$OUT/obj/runner_rt.o"
LLD=$(command -v ld.lld-14 || command -v ld.lld)
"$LLD" -static -e _start --gc-sections -o "$OUT/mptrack_hexagon_goldens.elf" \
  "$OUT"/obj/case_*.o "$OUT/obj/runner.o" "$OUT/obj/runner_data.o" "$OUT/obj/runner_rt.o"
"$SIZE" -A "$OUT/mptrack_hexagon_goldens.elf" | awk '$1 ~ /^\.(text|rodata|data|bss|sdata|sbss)/'
if "$NM" "$OUT/mptrack_hexagon_goldens.elf" | grep -E ' (malloc|free|calloc|realloc|_Znw[jm]|_Zdl[Pv]|__cxa_throw)$'; then
  echo "hexagon: heap/exception symbols in the golden runner" >&2
  exit 1
fi
if command -v qemu-hexagon >/dev/null; then
  echo "running the goldens under qemu-hexagon"
  qemu-hexagon "$OUT/mptrack_hexagon_goldens.elf"
fi
