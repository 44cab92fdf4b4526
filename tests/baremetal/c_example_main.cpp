// Cortex-M7 entry point of the C API example (examples/c/tracker_example.c):
// the same C code as on the host, its lines written through semihosting;
// run under qemu-system-arm (MPS2 AN500) by the m7 leg (m7_c_example_qemu).
#include "semihost.h"
#include "tracker_example.h"

namespace {
void print_line(const char* line) {
  mptrack::baremetal::sh_write(line);
  mptrack::baremetal::sh_write("\n");
}
}  // namespace

extern "C" int app_main() {
  const int rc = mptrack_example_run(print_line);
  mptrack::baremetal::sh_exit(rc == 0);
}
