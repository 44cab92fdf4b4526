#include "mptrack/platform/cycle_counter.h"

#if defined(MPTRACK_CYCLES_DWT)
namespace {
// ARMv7-M architecture reference manual, C1.8 (DWT) and C1.6.5 (DEMCR).
volatile std::uint32_t* const kDemcr = reinterpret_cast<volatile std::uint32_t*>(0xE000EDFCu);
volatile std::uint32_t* const kDwtCtrl = reinterpret_cast<volatile std::uint32_t*>(0xE0001000u);
volatile std::uint32_t* const kDwtCyccnt = reinterpret_cast<volatile std::uint32_t*>(0xE0001004u);
std::uint32_t g_last = 0;
std::uint64_t g_high = 0;
}  // namespace
#elif !defined(MPTRACK_CYCLES_PMU)
#include <chrono>
#endif

namespace mptrack::platform {

#if defined(MPTRACK_CYCLES_DWT)
void CycleCounter::enable() {
  *kDemcr = *kDemcr | (1u << 24);  // TRCENA
  *kDwtCyccnt = 0u;
  *kDwtCtrl = *kDwtCtrl | 1u;  // CYCCNTENA
}
std::uint64_t CycleCounter::now() {
  // Extend the 32-bit counter (wraps every ~8 s at 500 MHz); call at least once per wrap.
  const std::uint32_t c = *kDwtCyccnt;
  if (c < g_last) g_high += (std::uint64_t{1} << 32);
  g_last = c;
  return g_high | c;
}
StampUnit CycleCounter::unit() { return StampUnit::kCycles; }
#elif defined(MPTRACK_CYCLES_PMU)
void CycleCounter::enable() {
#if defined(__aarch64__)
  asm volatile("msr pmcr_el0, %0" ::"r"(std::uint64_t{1}));           // E: enable counters
  asm volatile("msr pmcntenset_el0, %0" ::"r"(std::uint64_t{1} << 31));  // C: cycle counter
#else
  asm volatile("mcr p15, 0, %0, c9, c12, 0" ::"r"(1u));
  asm volatile("mcr p15, 0, %0, c9, c12, 1" ::"r"(1u << 31));
#endif
}
std::uint64_t CycleCounter::now() {
#if defined(__aarch64__)
  std::uint64_t v = 0;
  asm volatile("mrs %0, pmccntr_el0" : "=r"(v));
  return v;
#else
  std::uint32_t v = 0;
  asm volatile("mrc p15, 0, %0, c9, c13, 0" : "=r"(v));
  return v;
#endif
}
StampUnit CycleCounter::unit() { return StampUnit::kCycles; }
#else
void CycleCounter::enable() {}
std::uint64_t CycleCounter::now() {
  const auto t = std::chrono::steady_clock::now().time_since_epoch();
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(t).count());
}
StampUnit CycleCounter::unit() { return StampUnit::kNanoseconds; }
#endif

double CycleCounter::to_us(std::uint64_t ticks, double cpu_hz) {
  if (unit() == StampUnit::kNanoseconds) return static_cast<double>(ticks) * 1e-3;
  return cpu_hz > 0.0 ? static_cast<double>(ticks) * 1e6 / cpu_hz : 0.0;
}

}  // namespace mptrack::platform
