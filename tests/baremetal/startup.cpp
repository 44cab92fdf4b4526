// Minimal Cortex-M7 start-up: vector table, .data/.bss set-up, FPU enable,
// static constructors, then app_main(). No OS, no semihosting, no heap.
#include <cstdint>

extern "C" {
extern std::uint32_t _data_load, _data_start, _data_end, _bss_start, _bss_end, _bss2_start, _bss2_end, _stack_top;
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int app_main();
void reset_handler();
void default_handler();
}

extern "C" void default_handler() {
  for (;;) {
  }
}

extern "C" void reset_handler() {
  // Enable CP10/CP11 (the FPU) before any floating-point instruction.
  volatile std::uint32_t* const cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88u);
  *cpacr = *cpacr | (0xFu << 20);
  std::uint32_t* src = &_data_load;
  for (std::uint32_t* dst = &_data_start; dst < &_data_end;) *dst++ = *src++;
  for (std::uint32_t* dst = &_bss_start; dst < &_bss_end;) *dst++ = 0u;
  // A second .bss range where a linker script splits it over two RAMs.
  for (std::uint32_t* dst = &_bss2_start; dst < &_bss2_end;) *dst++ = 0u;
  for (auto* ctor = __init_array_start; ctor < __init_array_end; ++ctor) (*ctor)();
  static_cast<void>(app_main());
  default_handler();
}

// Initial stack pointer, reset, then the 14 core exceptions (all parked).
using Vector = void (*)();
__attribute__((section(".isr_vector"), used)) const Vector kVectorTable[16] = {
    reinterpret_cast<Vector>(&_stack_top), reset_handler, default_handler, default_handler,
    default_handler, default_handler, default_handler, nullptr,
    nullptr, nullptr, nullptr, default_handler,
    default_handler, nullptr, default_handler, default_handler};
