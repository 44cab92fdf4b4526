// Instruction counting on the emulated Cortex-M7 (docs/targets.md
// §"Instructions per scan"): with qemu-system-arm -icount shift=0 every guest
// instruction advances the virtual clock by 1 ns and the SysTick, clocked
// from the MPS2's 25 MHz processor clock, ticks every 40 ns, so ticks x 40 =
// instructions (resolution 40). The 24-bit counter wraps after 671 million
// instructions: one step() must stay below that. Without -icount the ticks
// are host time and meaningless.
#pragma once

#include <cstdint>

namespace mptrack::baremetal {

inline constexpr std::uint32_t kInsnPerTick = 40u;  // 1 ns per insn (-icount 0) / 40 ns per 25 MHz tick

inline volatile std::uint32_t* systick_reg(std::uint32_t addr) {
  return reinterpret_cast<volatile std::uint32_t*>(addr);
}
/// Free-running, processor clock, no interrupt.
inline void systick_start() {
  *systick_reg(0xE000E014u) = 0x00FFFFFFu;  // SYST_RVR
  *systick_reg(0xE000E018u) = 0u;           // SYST_CVR
  *systick_reg(0xE000E010u) = 0x5u;         // SYST_CSR: enable, processor clock
}
inline std::uint32_t systick_now() { return *systick_reg(0xE000E018u); }  // counts down
inline std::uint32_t ticks_since(std::uint32_t start) { return (start - systick_now()) & 0x00FFFFFFu; }

}  // namespace mptrack::baremetal
