// Bare-metal smoke image: places core objects in .bss and exercises them so
// the linker keeps real core code (and the nm check sees what it needs).
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/status.h"

namespace {
mptrack::Scan<float, mptrack::DefaultCaps::kMaxMeasurements> g_scan;  // .bss
volatile std::uint32_t g_result = 0;  // observable by a debugger
}  // namespace

extern "C" int app_main() {
  std::uint32_t failures = 0;
  for (std::uint32_t j = 0; j < 300; ++j) {
    mptrack::Measurement<float> m;
    m.range_m = 100.0f + static_cast<float>(j);
    m.azimuth_rad = 0.01f * static_cast<float>(j);
    m.amplitude = 3.0f;
    if (g_scan.measurements.push_back(m) != mptrack::Status::kOk) ++failures;  // 44 overflow
  }
  g_result = failures;
  return 0;
}
