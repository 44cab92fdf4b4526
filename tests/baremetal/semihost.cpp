#include "semihost.h"

#include <cstdint>

namespace mptrack::baremetal {

namespace {
constexpr std::uint32_t kSysWrite0 = 0x04u;
constexpr std::uint32_t kSysExit = 0x18u;
constexpr std::uint32_t kApplicationExit = 0x20026u;   // ADP_Stopped_ApplicationExit
constexpr std::uint32_t kRunTimeErrorUnknown = 0x20023u;  // ADP_Stopped_RunTimeErrorUnknown

std::uint32_t semihost_call(std::uint32_t op, const void* arg) {
  register std::uint32_t r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
#if defined(__thumb__) && !defined(__thumb2__)
#error "semihosting: Thumb-1 only cores are not supported"
#elif defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");  // M profile
#elif defined(__thumb__)
  __asm__ volatile("svc 0xab" : "+r"(r0) : "r"(r1) : "memory");  // A/R profile, Thumb state
#else
  __asm__ volatile("svc 0x123456" : "+r"(r0) : "r"(r1) : "memory");  // A/R profile, Arm state
#endif
  return r0;
}
}  // namespace

void sh_write(const char* s) { static_cast<void>(semihost_call(kSysWrite0, s)); }

void sh_exit(bool ok) {
  // On AArch32 the reason code is passed directly in r1 (not a block).
  static_cast<void>(semihost_call(kSysExit, reinterpret_cast<const void*>(
                                                static_cast<std::uintptr_t>(ok ? kApplicationExit : kRunTimeErrorUnknown))));
  for (;;) {
  }
}

}  // namespace mptrack::baremetal
