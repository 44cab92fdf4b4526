// Instruction counts on the emulated Cortex-M7 (docs/targets.md
// §"Instructions per scan"): QEMU has no guest-readable instruction counter
// on M profile, but under -icount shift=0 every instruction advances virtual
// time by 1 ns and the SysTick, clocked from the 25 MHz processor clock of
// the MPS2 board, ticks every 40 ns: ticks x 40 = instructions (resolution
// 40). Without -icount the counts are host time and meaningless.
#pragma once

#include <cstdint>

namespace mptrack::baremetal {

inline constexpr std::uint32_t kInsnPerTick = 40u;  // 1 ns per insn (-icount 0) / 40 ns per 25 MHz tick

inline volatile std::uint32_t* systick_reg(std::uint32_t addr) {
  return reinterpret_cast<volatile std::uint32_t*>(addr);
}

/// Starts the 24-bit SysTick down-counter from its maximum (671 M
/// instructions per wrap), processor clock, no interrupt.
inline void systick_start() {
  *systick_reg(0xE000E014u) = 0x00FFFFFFu;  // RVR
  *systick_reg(0xE000E018u) = 0u;           // CVR
  *systick_reg(0xE000E010u) = 0x5u;         // CSR: enable, processor clock
}
inline std::uint32_t systick_now() { return *systick_reg(0xE000E018u); }
inline std::uint32_t ticks_since(std::uint32_t start) { return (start - systick_now()) & 0x00FFFFFFu; }

/// SysTick ticks of a loop of exactly 2 000 000 instructions (subs + bne,
/// 10^6 iterations): 50 000 under -icount shift=0.
inline std::uint32_t icount_calibration_ticks() {
  std::uint32_t n = 1000000u;
  const std::uint32_t t0 = systick_now();
  __asm__ volatile("1: subs %0, %0, #1\n bne 1b" : "+r"(n) : : "cc");
  return ticks_since(t0);
}

}  // namespace mptrack::baremetal
