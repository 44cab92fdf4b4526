// Cycle/time stamps for per-stage profiling.
//
// Source chosen at compile time:
//   MPTRACK_CYCLES_DWT  Cortex-M DWT->CYCCNT (cycles; call enable() once)
//   MPTRACK_CYCLES_PMU  Cortex-A PMCCNTR (cycles; needs the PMU enabled for
//                       the running exception level, i.e. bare metal or a
//                       kernel that allows user access)
//   default             std::chrono::steady_clock (nanoseconds) on hosts and
//                       Linux targets
// Stamps are 64-bit and monotonic within a run; units() says what they count.
#pragma once

#include <cstdint>

namespace mptrack::platform {

enum class StampUnit : std::uint8_t { kCycles, kNanoseconds };

class CycleCounter {
 public:
  /// Prepares the counter (DWT/PMU enable); a no-op for steady_clock.
  static void enable();
  /// Current stamp.
  static std::uint64_t now();
  static StampUnit unit();
  /// Converts a stamp difference to microseconds; cpu_hz is used for cycle counters.
  static double to_us(std::uint64_t ticks, double cpu_hz = 0.0);
};

}  // namespace mptrack::platform
