// libFuzzer harness: GNN tracker step on arbitrary measurement lists and
// timestamps (docs/reliability.md). Differential twin check, see
// tracker_harness.h.
#include <cstddef>
#include <cstdint>

#include "mptrack/gnn/gnn_tracker.h"
#include "tracker_harness.h"

namespace {
using Tracker = mptrack::GnnTracker<float, mptrack::SmallBoardCaps>;
Tracker g_a;
Tracker g_b;
Tracker::ScanType g_scan;
Tracker::ScanType g_prev;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mptrack::fuzz::FuzzReader in(data, size);
  Tracker::Params p;
  p.report_tentative = (in.u8() & 1u) != 0;
  FUZZ_CHECK(g_a.init(p) == mptrack::Status::kOk);
  FUZZ_CHECK(g_b.init(p) == mptrack::Status::kOk);
  const mptrack::fuzz::Region reg{p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad, p.region.azimuth_max_rad};
  mptrack::fuzz::run_twin(in, reg, g_a, g_b, 256, g_scan, g_prev);
  for (const auto& t : g_a.tracks()) FUZZ_CHECK(mptrack::fuzz::is_spd(t.P));
  return 0;
}
