// Instructions per scan of MultipathMfbpTracker<float, ...> on the emulated
// Cortex-M7 (systick_icount.h: SysTick ticks x 40 under -icount shift=0).
//
// Input: run 0 (seed 1) of seed002-othr at each Table IV cell, the file
// tests/golden/data/seed002_othr_run0.scans embedded in the image, with the
// Params the host harness's mfbp-multipath adapter uses (lag 3). Nc 125
// cells run on DefaultCaps (256 detections per scan); Nc 400 scans hold up to
// ~450 detections, beyond DefaultCaps, so those cells run on Nc400Caps
// (DefaultCaps with 512 detections and 128 tracks). Each cell prints the output hash of
// othr_file::hash_outputs(); the host prints the same for the same caps in
// seed002_scans_golden_test, so equal hashes show the M7 computed the host's
// tracks bit for bit. Instructions, not cycles (docs/targets.md).
#include "multipath_scan_cost.h"

#include <cstddef>
#include <cstdint>

#include "../support/othr_scan_file.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "semihost.h"
#include "systick_icount.h"

namespace mptrack::baremetal {

namespace {

using test::othr_file::Nc400Caps;
using SmallTracker = MultipathMfbpTracker<float, DefaultCaps>;
using BigTracker = MultipathMfbpTracker<float, Nc400Caps>;
SmallTracker g_small;  // .bss: init() sets it up
BigTracker g_big;
SmallTracker::ScanType g_small_scan;
BigTracker::ScanType g_big_scan;

constexpr std::uint32_t kMaxScans = 64;

/// Sorts the first n values ascending (insertion sort: n is 30).
void sort(std::uint32_t* v, std::uint32_t n) {
  for (std::uint32_t i = 1; i < n; ++i) {
    const std::uint32_t x = v[i];
    std::uint32_t j = i;
    for (; j > 0 && v[j - 1] > x; --j) v[j] = v[j - 1];
    v[j] = x;
  }
}

/// Nearest-rank percentile (q in percent) of n sorted values.
std::uint32_t percentile(const std::uint32_t* sorted, std::uint32_t n, std::uint32_t q) {
  std::uint32_t rank = (q * n + 99u) / 100u;  // ceil(q n / 100)
  if (rank < 1u) rank = 1u;
  return sorted[rank - 1u];
}

void write_milli(std::uint32_t v) {  // 750 -> "0.75", 3200 -> "3.2"
  sh_write_uint(v / 1000u);
  std::uint32_t frac = v % 1000u;
  if (frac == 0u) return;
  sh_write(".");
  if (frac < 100u) sh_write("0");
  while (frac % 10u == 0u) frac /= 10u;
  sh_write_uint(frac);
}

template <class Tracker>
bool run_cell(test::othr_file::Reader& r, const test::othr_file::Cell& cell, Tracker& trk,
              typename Tracker::ScanType& scan, const char* caps_name) {
  if (cell.num_scans > kMaxScans || trk.init(cell.params) != Status::kOk) return false;
  std::uint32_t insn[kMaxScans];
  std::uint32_t hash = test::othr_file::kHashSeed;
  std::size_t max_detections = 0;
  for (std::uint32_t k = 0; k < cell.num_scans; ++k) {
    if (!test::othr_file::read_scan(r, scan)) return false;
    if (scan.measurements.size() > max_detections) max_detections = scan.measurements.size();
    const std::uint32_t s = systick_now();
    const Status st = trk.step(scan);
    insn[k] = ticks_since(s) * kInsnPerTick;
    if (!test::othr_file::accepted(st)) return false;
    hash = test::othr_file::hash_outputs(trk, hash);
  }
  const std::uint32_t n = cell.num_scans;
  sort(insn, n);
  sh_write("multipath lag ");
  sh_write_uint(cell.params.smoothing_lag_scans);
  sh_write(" (float, ");
  sh_write(caps_name);
  sh_write(", ");
  sh_write_uint(sizeof(Tracker));
  sh_write(" B) seed002-othr run 0 pd ");
  write_milli(cell.pd_milli);
  sh_write(" clutter x");
  write_milli(cell.clutter_scale_milli);
  sh_write(": ");
  sh_write_uint(n);
  sh_write(" scans, <= ");
  sh_write_uint(max_detections);
  sh_write(" detections; instructions per step p50 ");
  sh_write_uint(percentile(insn, n, 50));
  sh_write(" p99 ");
  sh_write_uint(percentile(insn, n, 99));
  sh_write(" max ");
  sh_write_uint(insn[n - 1u]);
  sh_write(" min ");
  sh_write_uint(insn[0]);
  sh_write("; confirmed ");
  sh_write_uint(trk.counters().tracks_confirmed);
  sh_write(", cap hits ");
  sh_write_uint(total_cap_hits(trk.counters()));
  sh_write(" (association ");
  sh_write_uint(trk.counters().association_cap_hits);
  sh_write("), output hash ");
  sh_write_uint(hash);
  sh_write("\n");
  return true;
}

}  // namespace

bool report_multipath_scan_cost(const unsigned char* begin, const unsigned char* end) {
  systick_start();
  test::othr_file::Reader r(begin, end);
  if (r.u32() != test::othr_file::kMagic) return false;
  const std::uint32_t cells = r.u32();
  for (std::uint32_t c = 0; c < cells; ++c) {
    test::othr_file::Cell cell;
    if (!test::othr_file::read_cell(r, cell)) return false;
    const bool ok = cell.clutter_scale_milli <= 1000u
                        ? run_cell(r, cell, g_small, g_small_scan, "DefaultCaps")
                        : run_cell(r, cell, g_big, g_big_scan, "DefaultCaps with 512 detections, 128 tracks");
    if (!ok) return false;
  }
  return r.ok();
}

}  // namespace mptrack::baremetal
