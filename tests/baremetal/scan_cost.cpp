// Instructions per scan, measured on the emulated Cortex-M7.
//
// QEMU has no instruction counter a guest can read (no DWT CYCCNT, no PMU on
// M profile) and Debian ships no TCG plugins, but with -icount shift=0 every
// guest instruction advances the virtual clock by exactly 1 ns, and the
// SysTick, clocked from the 25 MHz processor clock of the MPS2 board, ticks
// every 40 ns of virtual time. So SysTick ticks x 40 = instructions executed
// (resolution 40). The runner calibrates this against a loop of known length
// first and prints the measured ratio. Without -icount the counts are host
// time and meaningless; the test passes -icount shift=0.
//
// Input: seed000-s2 (seed 1, run 0) scans 1..5 as float tracker input, i.e.
// tests/golden/data/scenario_s2_scans1to5.golden embedded in the image (its
// "k<k>.m<j>.r|az|amp" lines). The measurement is a spot check of one short
// run, not a benchmark.
#include "scan_cost.h"

#include <cstdint>
#include <cstring>

#include "mptrack/mfbp/mfbp_tracker.h"
#include "semihost.h"
#include "systick_icount.h"

namespace mptrack::baremetal {

namespace {

using Tracker = MfbpTracker<float, DefaultCaps>;
using S2Scan = Scan<float, DefaultCaps::kMaxMeasurements>;
Tracker g_tracker;  // .bss, no constructor needed beyond zero (init() sets it up)
S2Scan g_scan;

std::uint32_t parse_hex(const char* p) {
  std::uint32_t v = 0;
  for (; (*p >= '0' && *p <= '9') || (*p >= 'a' && *p <= 'f'); ++p) {
    v = v * 16u + static_cast<std::uint32_t>(*p <= '9' ? *p - '0' : *p - 'a' + 10);
  }
  return v;
}

float float_of(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Fills g_scan with scan k ("k<k>.m<j>.<field> f32 <hex>" lines); false if none.
bool load_scan(const char* text, std::uint32_t k) {
  g_scan.measurements.clear();
  g_scan.time_us = 1000000u * static_cast<std::uint64_t>(k);  // seed000-s2: T = 1 s
  char prefix[16] = "k";
  prefix[1] = static_cast<char>('0' + static_cast<int>(k));
  std::strcpy(prefix + 2, ".m");
  const std::size_t plen = std::strlen(prefix);
  Measurement<float> m;
  for (const char* line = text; *line != '\0';) {
    const char* end = std::strchr(line, '\n');
    if (end == nullptr) end = line + std::strlen(line);
    if (std::strncmp(line, prefix, plen) == 0) {
      const char* dot = std::strchr(line + plen, '.');
      const char* hex = std::strstr(line, " f32 ");
      if (dot != nullptr && hex != nullptr && hex < end) {
        const float v = float_of(parse_hex(hex + 5));
        if (std::strncmp(dot, ".r ", 3) == 0) m.range_m = v;
        if (std::strncmp(dot, ".az ", 4) == 0) m.azimuth_rad = v;
        if (std::strncmp(dot, ".amp ", 5) == 0) {
          m.amplitude = v;
          if (g_scan.measurements.push_back(m) != Status::kOk) return false;
        }
      }
    }
    line = *end == '\n' ? end + 1 : end;
  }
  return !g_scan.measurements.empty();
}

}  // namespace

bool report_mfbp_scan_cost(const char* s2_golden_text) {
  systick_start();
  const std::uint32_t cal = icount_calibration_ticks();
  sh_write("icount calibration: 2000000-instruction loop = ");
  sh_write_uint(cal);
  sh_write(" SysTick ticks (");
  sh_write_uint(cal == 0u ? 0u : 2000000u / cal);
  sh_write(" instructions per tick; 40 expected under -icount shift=0)\n");

  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = 1;  // online filter
  p.slide = 1;
  if (g_tracker.init(p) != Status::kOk) return false;
  for (std::uint32_t k = 1; k <= 5; ++k) {
    if (!load_scan(s2_golden_text, k)) return false;
    const std::uint32_t s = systick_now();
    const Status st = g_tracker.step(g_scan);
    const std::uint32_t ticks = ticks_since(s);
    if (st != Status::kOk) return false;
    sh_write("mfbp filter (float, DefaultCaps) seed000-s2 scan ");
    sh_write_uint(k);
    sh_write(": ");
    sh_write_uint(static_cast<std::uint32_t>(g_scan.measurements.size()));
    sh_write(" measurements, ");
    sh_write_uint(ticks * kInsnPerTick);
    sh_write(" instructions (SysTick resolution: 40)\n");
  }
  return true;
}

}  // namespace mptrack::baremetal
