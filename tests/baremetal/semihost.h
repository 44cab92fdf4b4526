// Arm semihosting (the debugger/emulator channel): text out and exit code.
// qemu-system-arm implements it with -semihosting-config enable=on; on a
// board under a debug probe the same calls go to the probe's console.
#pragma once

#include <cstdint>

namespace mptrack::baremetal {

/// Writes a NUL-terminated string (SYS_WRITE0).
void sh_write(const char* s);
/// Ends the program: exit status 0 if ok, 1 otherwise (SYS_EXIT with
/// ADP_Stopped_ApplicationExit / ADP_Stopped_RunTimeErrorUnknown).
[[noreturn]] void sh_exit(bool ok);

/// Writes v in decimal (no stdio on these images).
inline void sh_write_uint(std::uint64_t v) {
  char buf[24];
  char* p = buf + sizeof buf;
  *--p = '\0';
  do {
    *--p = static_cast<char>('0' + static_cast<int>(v % 10u));
    v /= 10u;
  } while (v != 0u);
  sh_write(p);
}

}  // namespace mptrack::baremetal
