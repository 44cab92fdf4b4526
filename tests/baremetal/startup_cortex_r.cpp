// Minimal Cortex-R5F start-up: Arm-state exception vectors at address 0,
// stack, VFP enable (CPACR, then FPEXC.EN), .data/.bss set-up, static
// constructors, then app_main(). No OS, no semihosting, no heap; exceptions
// other than reset park in a loop. (R profile: the vectors are instructions,
// not the M profile's table of addresses.)
#include <cstdint>

extern "C" {
extern std::uint32_t _data_load, _data_start, _data_end, _bss_start, _bss_end;
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int app_main();
void reset_handler();
}

__asm__(
    ".section .vectors, \"ax\"\n"
    ".arm\n"
    ".global _vectors\n"
    "_vectors:\n"
    "  ldr pc, =_reset_entry\n"  // reset
    "  b .\n"                    // undefined instruction
    "  b .\n"                    // SVC
    "  b .\n"                    // prefetch abort
    "  b .\n"                    // data abort
    "  b .\n"                    // reserved
    "  b .\n"                    // IRQ
    "  b .\n"                    // FIQ
    ".ltorg\n"
    ".text\n"
    ".arm\n"
    "_reset_entry:\n"
    "  ldr sp, =_stack_top\n"
    "  mrc p15, 0, r0, c1, c0, 2\n"  // CPACR: full access to CP10/CP11
    "  orr r0, r0, #0x00F00000\n"
    "  mcr p15, 0, r0, c1, c0, 2\n"
    "  isb\n"
    "  mov r0, #0x40000000\n"  // FPEXC.EN
    "  vmsr fpexc, r0\n"
    "  ldr r0, =reset_handler\n"
    "  bx r0\n"
    ".ltorg\n");

extern "C" void reset_handler() {
  std::uint32_t* src = &_data_load;
  for (std::uint32_t* dst = &_data_start; dst < &_data_end;) *dst++ = *src++;
  for (std::uint32_t* dst = &_bss_start; dst < &_bss_end;) *dst++ = 0u;
  for (auto* ctor = __init_array_start; ctor < __init_array_end; ++ctor) (*ctor)();
  static_cast<void>(app_main());
  for (;;) {
  }
}
