#!/usr/bin/env bash
# Cortex-M7 footprint report -> OUT_JSON (run by `./run bench`: build/bench-results/footprint.json).
#   bench/footprint.sh [BUILD_DIR] [OUT_JSON]
# Builds the bare-metal tree (toolchains/arm-none-eabi-cortex-m7.cmake) in
# BUILD_DIR (default build/m7-footprint) with -fstack-usage and
# -fcallgraph-info=su, then records
#   * .text/.data/.bss of tests/baremetal's image (front end + GNN, MF-BP
#     with DefaultCaps and SmallBoardCaps, all float, statically placed),
#   * the .bss/.data size of each object placed in the image (nm -S),
#   * sizeof of every top-level core object per preset (bench/m7_sizeof.cpp,
#     compiled for the M7, not linked),
#   * worst-case stack of each step()/process() (bench/scripts/stack_depth.awk
#     over GCC's call graph; static frames, complete = no unsized call),
#   * the RAM budgets of bench/README.md and whether they hold.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build/m7-footprint}
OUT=${2:-$BUILD/footprint.json}
SMALL_BOARD_BUDGET=65536     # SmallBoard preset: tracker state in 64 KiB
DEFAULT_BUDGET=524288        # Default preset: everything in the 512 KiB SRAM of cortex_m7.ld

for t in arm-none-eabi-g++ arm-none-eabi-size arm-none-eabi-nm; do
  command -v $t >/dev/null || { echo "footprint: $t not found (gcc-arm-none-eabi)" >&2; exit 2; }
done
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
    -DCMAKE_TOOLCHAIN_FILE="$ROOT/toolchains/arm-none-eabi-cortex-m7.cmake" \
    -DCMAKE_CXX_FLAGS="-fstack-usage -fcallgraph-info=su" >/dev/null
fi
cmake --build "$BUILD" --target mptrack_m7_image >/dev/null
ELF=$BUILD/tests/baremetal/mptrack_m7_image.elf
CI=$BUILD/tests/baremetal/CMakeFiles/mptrack_m7_image.dir/main.cpp.ci

# Section sizes (the linker script keeps .rodata inside .text).
read -r text data bss < <(arm-none-eabi-size -A "$ELF" | awk '
  $1==".text"{t=$2} $1==".isr_vector"{v=$2} $1==".init_array"{i=$2} $1==".ARM.exidx"{x=$2}
  $1==".data"{d=$2} $1==".bss"{b=$2} END{print t+v+i+x, d, b}')

# Objects placed in the image (anonymous-namespace g_* symbols).
objects=$(arm-none-eabi-nm -S -C --radix=d "$ELF" | awk '$3 ~ /^[bBdD]$/ && $0 ~ /::g_/ {
  name=$NF; sub(/.*::/, "", name); printf "%s    \"%s\": {\"bytes\": %d, \"section\": \"%s\"}", sep, name, $2 + 0, ($3 ~ /[bB]/ ? ".bss" : ".data"); sep=",\n" }')

# sizeof per preset, as laid out for the M7.
cpu_flags=$(sed -n 's/^MPTRACK_CPU_FLAGS:STRING=//p' "$BUILD/CMakeCache.txt")
[ -n "$cpu_flags" ] || cpu_flags=$(sed -n 's/^set(MPTRACK_CPU_FLAGS_DEFAULT "\(.*\)")$/\1/p' \
  "$ROOT/toolchains/arm-none-eabi-cortex-m7.cmake")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086
arm-none-eabi-g++ -std=c++17 -O2 $cpu_flags -ffp-contract=off -fno-exceptions -fno-rtti \
  -DEIGEN_DONT_VECTORIZE -DEIGEN_MPL2_ONLY -I"$ROOT/core/include" -isystem /usr/include/eigen3 \
  -c "$ROOT/bench/m7_sizeof.cpp" -o "$tmp/sizeof.o"
sizes=$(arm-none-eabi-nm -S --radix=d "$tmp/sizeof.o" | awk '$4 ~ /^mptrack_sizeof__/ {
  name=$4; sub(/^mptrack_sizeof__/, "", name); printf "%s    \"%s\": %d", sep, name, $2 + 0; sep=",\n" }')
sizeof_of() { arm-none-eabi-nm -S --radix=d "$tmp/sizeof.o" | awk -v n="mptrack_sizeof__$1" '$4==n{print $2 + 0}'; }

# Worst-case stack per entry point.
stacks=$(awk -v ROOT_RE='stack_root_' -f "$ROOT/bench/scripts/stack_depth.awk" "$CI" | sort -k3 | awk '{
  name=$0; sub(/^[0-9]+ [01] /, "", name); sub(/.*stack_root_/, "", name); sub(/\(.*/, "", name);
  printf "%s    \"%s\": {\"bytes\": %d, \"complete\": %s}", sep, name, $1, ($2 == 1 ? "true" : "false"); sep=",\n" }')
stack_of() { awk -v ROOT_RE="stack_root_$1" -f "$ROOT/bench/scripts/stack_depth.awk" "$CI" | awk '{print $1}'; }

# Largest single frames in the image's translation unit (-fstack-usage).
frames=$(sort -t$'\t' -k2 -n -r "$BUILD/tests/baremetal/CMakeFiles/mptrack_m7_image.dir/main.cpp.su" | awk -F"\t" "NR <= 5" | awk -F"\t" '{
  f=$1; sub(/^.*:[0-9]+:[0-9]+:/, "", f); gsub(/"/, "\\\"", f); if (length(f) > 160) f=substr(f, 1, 157) "...";
  printf "%s    {\"function\": \"%s\", \"bytes\": %d}", sep, f, $2; sep=",\n" }')

small_state=$(sizeof_of MfbpTracker_float_SmallBoardCaps)
small_stack=$(stack_of mfbp_small_step)
small_total=$((small_state + small_stack))
ram=$((data + bss))
default_stack=$(stack_of mfbp_default_step)
default_total=$((ram + default_stack))
b() { [ "$1" -le "$2" ] && echo true || echo false; }

mkdir -p "$(dirname "$OUT")"
cat > "$OUT" <<JSON
{
  "schema": "mptrack-footprint/1",
  "target": "Cortex-M7 ($cpu_flags), $(arm-none-eabi-g++ --version | head -1), Release, -fno-exceptions -fno-rtti",
  "image": "tests/baremetal/mptrack_m7_image.elf: FrontEnd<Seed004RadarCaps> + GnnTracker<float, SmallBoardCaps> + MfbpTracker<float, DefaultCaps> + MfbpTracker<float, SmallBoardCaps>",
  "sections_bytes": {"text": $text, "data": $data, "bss": $bss, "flash": $((text + data)), "ram_static": $ram},
  "objects_in_image": {
$objects
  },
  "sizeof_m7": {
$sizes
  },
  "stack_worst_case": {
$stacks
  },
  "largest_frames": [
$frames
  ],
  "budgets": {
    "small_board": {"what": "MfbpTracker<float, SmallBoardCaps> state + worst-case step() stack", "bytes": $small_total,
                    "state_bytes": $small_state, "stack_bytes": $small_stack, "budget_bytes": $SMALL_BOARD_BUDGET,
                    "met": $(b $small_total $SMALL_BOARD_BUDGET)},
    "small_board_state_only": {"bytes": $small_state, "budget_bytes": $SMALL_BOARD_BUDGET, "met": $(b "$small_state" $SMALL_BOARD_BUDGET)},
    "default": {"what": "image .data + .bss + worst-case MF-BP DefaultCaps step() stack", "bytes": $default_total,
                "budget_bytes": $DEFAULT_BUDGET, "met": $(b $default_total $DEFAULT_BUDGET)}
  }
}
JSON
printf '\n== Cortex-M7 footprint (%s) ==\n' "$OUT"
printf 'image: .text %d  .data %d  .bss %d  (flash %d, static RAM %d)\n' "$text" "$data" "$bss" $((text + data)) "$ram"
printf 'stack worst case: MF-BP default step %d B, small step %d B, GNN small step %s B, front end %s B\n' \
  "$default_stack" "$small_stack" "$(stack_of gnn_small_step)" "$(stack_of frontend_process)"
printf 'SmallBoard MF-BP: state %d + stack %d = %d B (budget %d): %s\n' "$small_state" "$small_stack" "$small_total" \
  $SMALL_BOARD_BUDGET "$(b $small_total $SMALL_BOARD_BUDGET)"
printf 'Default image: %d B static + %d B stack = %d B (budget %d): %s\n' "$ram" "$default_stack" "$default_total" \
  $DEFAULT_BUDGET "$(b $default_total $DEFAULT_BUDGET)"
