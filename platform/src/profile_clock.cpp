#include "mptrack/platform/profile_clock.h"

#include "mptrack/platform/cycle_counter.h"

namespace mptrack::platform {

std::uint32_t profile_ticks() {
  return static_cast<std::uint32_t>(CycleCounter::now() & 0xFFFFFFFFu);
}

bool bind_profile_clocks() {
#if MPTRACK_PROFILE
  CycleCounter::enable();
  mptrack::profile::g_frontend.set_clock(&profile_ticks);
  mptrack::profile::g_mfbp.set_clock(&profile_ticks);
  return true;
#else
  return false;
#endif
}

double profile_tick_us(double cpu_hz) { return CycleCounter::to_us(1, cpu_hz); }

}  // namespace mptrack::platform
