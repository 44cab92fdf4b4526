#!/usr/bin/env bash
# Instruction counts per scan (valgrind/callgrind) for the default scenario,
# against the recorded baseline bench/callgrind_baseline.json. Not in CI.
#
#   bench/check_callgrind.sh            compare; exit 1 if any tracker's
#                                       instructions per scan grew by more
#                                       than THRESHOLD percent (default 2)
#   bench/check_callgrind.sh --record   measure and write the baseline
# Options: --threshold PCT, --bin PATH (default build/host/bench/mptrack-bench-scan),
#          --scans N (default 60; the baseline records its own N).
#
# Workload: seed 000 S2 (run 0, seed 0), float, DefaultCaps, the first N scans,
# counted inside run_scans() only (--toggle-collect), so scenario generation
# and start-up are excluded. Instruction counts are deterministic for a given
# binary: unlike time, they do not move with machine load. They do move with
# the compiler and flags, so the baseline records the compiler; re-record
# after a toolchain change.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=$ROOT/build/host/bench/mptrack-bench-scan
BASELINE=$ROOT/bench/callgrind_baseline.json
THRESHOLD=2
SCANS=60
RECORD=0
TRACKERS=(mfbp-filter mfbp mfbp-s1 gmphd gmcphd gnn)
while [ $# -gt 0 ]; do
  case $1 in
    --record) RECORD=1 ;;
    --threshold) THRESHOLD=$2; shift ;;
    --bin) BIN=$2; shift ;;
    --scans) SCANS=$2; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
command -v valgrind >/dev/null || { echo "valgrind not installed" >&2; exit 2; }
[ -x "$BIN" ] || { echo "$BIN not built (cmake --build <dir> --target mptrack-bench-scan)" >&2; exit 2; }
if [ $RECORD -eq 0 ]; then
  [ -f "$BASELINE" ] || { echo "no baseline: run with --record first" >&2; exit 2; }
  SCANS=$(sed -n 's/.*"scans": \([0-9]*\).*/\1/p' "$BASELINE" | head -1)
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A ir
for t in "${TRACKERS[@]}"; do
  valgrind --tool=callgrind --callgrind-out-file="$tmp/$t.out" --toggle-collect='*run_scans*' \
    "$BIN" "$t" "$SCANS" >"$tmp/$t.log" 2>&1 || { cat "$tmp/$t.log" >&2; exit 2; }
  ir[$t]=$(sed -n 's/^totals: \([0-9]*\).*/\1/p' "$tmp/$t.out")
done

compiler=$(c++ --version | head -1)
if [ $RECORD -eq 1 ]; then
  {
    echo "{"
    echo "  \"schema\": \"mptrack-callgrind/1\","
    echo "  \"workload\": \"seed000-s2, run 0, seed 0, float, DefaultCaps, first N scans, inside run_scans()\","
    echo "  \"scans\": $SCANS,"
    echo "  \"compiler\": \"$compiler\","
    echo "  \"valgrind\": \"$(valgrind --version)\","
    echo "  \"instructions_per_scan\": {"
    sep=""
    for t in "${TRACKERS[@]}"; do
      printf '%s    "%s": %d' "$sep" "$t" $((ir[$t] / SCANS))
      sep=$',\n'
    done
    printf '\n  },\n  "instructions_total": {\n'
    sep=""
    for t in "${TRACKERS[@]}"; do
      printf '%s    "%s": %d' "$sep" "$t" "${ir[$t]}"
      sep=$',\n'
    done
    printf '\n  }\n}\n'
  } >"$BASELINE"
  echo "recorded $BASELINE"
  for t in "${TRACKERS[@]}"; do printf '%-12s %12d instructions/scan\n' "$t" $((ir[$t] / SCANS)); done
  exit 0
fi

base_compiler=$(sed -n 's/.*"compiler": "\(.*\)",/\1/p' "$BASELINE")
[ "$base_compiler" = "$compiler" ] || echo "note: baseline compiler '$base_compiler', now '$compiler'" >&2
fail=0
printf '%-12s %14s %14s %8s\n' tracker baseline now change
for t in "${TRACKERS[@]}"; do
  now=${ir[$t]}
  # The per-scan block comes first in the file, so the first match is it.
  base_per_scan=$(grep -m1 "\"$t\": " "$BASELINE" | sed 's/.*: \([0-9]*\).*/\1/' || true)
  if [ -z "$base_per_scan" ]; then  # a tracker added after the baseline was recorded
    printf '%-12s %14s %14d %8s  %s\n' "$t" "-" $((now / SCANS)) "-" "no baseline (--record)"
    continue
  fi
  base=$((base_per_scan * SCANS))
  pct=$(awk -v n="$now" -v b="$base" 'BEGIN { printf "%.2f", (n - b) * 100.0 / b }')
  verdict=ok
  if awk -v p="$pct" -v t="$THRESHOLD" 'BEGIN { exit !(p > t) }'; then verdict="REGRESSION (> ${THRESHOLD}%)"; fail=1; fi
  printf '%-12s %14d %14d %7s%%  %s\n' "$t" "$base_per_scan" $((now / SCANS)) "$pct" "$verdict"
done
exit $fail
