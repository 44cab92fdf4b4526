// Length of a unit test's long statistical run, per build.
//
// A few behaviour tests run a tracker for hundreds of scans to show that
// something does not happen (no birth from noise alone, ...). On the host
// they run in full. Cross builds (MPTRACK_TEST_SHORT_RUNS, on by default
// there: tests/CMakeLists.txt) run a shorter prefix of the same run: every
// target computes the host's bits, which the golden cases check bit for bit
// on each target, so repeating the whole run under qemu would only repeat
// the host's verdict at 20-50x the cost (docs/targets.md, "What each leg runs").
#pragma once

#include <cstdint>

namespace mptrack::test {

#ifdef MPTRACK_TEST_SHORT_RUNS
inline constexpr bool kShortRuns = true;
#else
inline constexpr bool kShortRuns = false;
#endif

/// `full` scans on the host, `short_run` where kShortRuns is set.
constexpr std::uint64_t run_length(std::uint64_t full, std::uint64_t short_run) {
  return kShortRuns ? short_run : full;
}

}  // namespace mptrack::test
