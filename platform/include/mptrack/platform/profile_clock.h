// Binds the platform cycle counter to core's per-stage profiles
// (core/include/mptrack/profile.h). Core knows no clock; a profile-enabled
// build (CMake -DMPTRACK_PROFILE=ON) calls bind_profile_clocks() once at
// start-up, after which every FrontEnd::process and MfbpTracker::step
// records per-stage ticks in mptrack::profile::g_frontend / g_mfbp.
#pragma once

#include <cstdint>

#include "mptrack/profile.h"

namespace mptrack::platform {

/// Low 32 bits of CycleCounter::now(): cycles (DWT/PMU) or nanoseconds
/// (steady_clock). Deltas modulo 2^32 are exact for stages < one wrap.
std::uint32_t profile_ticks();

/// Enables the counter and binds profile_ticks() to every core profile.
/// Returns false (and binds nothing) when core was built without
/// MPTRACK_PROFILE, so a harness can say why it has no stage table.
bool bind_profile_clocks();

/// Microseconds per tick of profile_ticks() (cpu_hz: core clock, for cycle counters).
double profile_tick_us(double cpu_hz = 0.0);

}  // namespace mptrack::platform
