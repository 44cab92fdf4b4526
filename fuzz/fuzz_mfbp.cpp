// libFuzzer harness: MF-BP measurement ingest and window processing on
// arbitrary scans (docs/reliability.md). Small caps keep one execution in
// the millisecond range; the first byte picks the online filter (K = 1),
// a short window (K = 3, slide 1), the paper's smoother (K = 7, slide 3) or,
// with bit 0x40, mfbp-s1's (K = 7, slide 1, confirm_lookahead_in_clutter 2).
#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/mfbp_tracker.h"
#include "tracker_harness.h"

namespace {
struct FuzzMfbpCaps {
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kMaxMeasurements = 12;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 7;
};
using Tracker = mptrack::MfbpTracker<float, FuzzMfbpCaps>;
Tracker g_a;
Tracker g_b;
Tracker::ScanType g_scan;
Tracker::ScanType g_prev;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mptrack::fuzz::FuzzReader in(data, size);
  Tracker::Params p;
  const std::uint8_t cfg = in.u8();
  switch (cfg % 3u) {
    case 0: p.window_length = 1; p.slide = 1; break;
    case 1: p.window_length = 3; p.slide = 1; break;
    default: p.window_length = 7; p.slide = 3; break;
  }
  if (p.window_length == 7 && (cfg & 0x40u) != 0) {
    p.slide = 1;
    p.confirm_lookahead_in_clutter = 2;
  }
  p.amplitude.use_amplitude = (cfg & 0x10u) == 0;
  p.clutter_mode = (cfg & 0x20u) == 0 ? mptrack::ClutterMode::kEstimate
                                       : mptrack::ClutterMode::kUniformKnownRate;
  p.bp_max_iterations = 50;  // bounded time per execution
  FUZZ_CHECK(g_a.init(p) == mptrack::Status::kOk);
  FUZZ_CHECK(g_b.init(p) == mptrack::Status::kOk);
  const mptrack::fuzz::Region reg{p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad,
                                  p.region.azimuth_max_rad};
  mptrack::fuzz::run_twin(in, reg, g_a, g_b, 40, g_scan, g_prev);
  FUZZ_CHECK(g_a.live_tracks() <= FuzzMfbpCaps::kMaxTargets);
  return 0;
}
