// libFuzzer harness: GM-PHD, GM-CPHD and CBMeMBer steps on arbitrary scans
// (docs/reliability.md); the first byte picks the filter and clutter mode.
#include <cstddef>
#include <cstdint>

#include "mptrack/cbmember/cbmember_filter.h"
#include "mptrack/phd/phd_filter.h"
#include "tracker_harness.h"

namespace {
struct FuzzIggmCaps {
  static constexpr std::size_t kMaxTargets = 6;
  static constexpr std::size_t kMaxMeasurements = 16;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 1;
};
using Phd = mptrack::GmPhdFilter<float, FuzzIggmCaps>;
using Cphd = mptrack::GmCphdFilter<float, FuzzIggmCaps>;
using Cbm = mptrack::CbMemberFilter<float, FuzzIggmCaps>;
Phd g_phd_a, g_phd_b;
Cphd g_cphd_a, g_cphd_b;
Cbm g_cbm_a, g_cbm_b;
Phd::ScanType g_scan, g_prev;

template <class Filter>
void run(mptrack::fuzz::FuzzReader& in, const mptrack::RfsFilterParams<float>& p, Filter& a,
         Filter& b) {
  FUZZ_CHECK(a.init(p) == mptrack::Status::kOk);
  FUZZ_CHECK(b.init(p) == mptrack::Status::kOk);
  const mptrack::fuzz::Region reg = p.space == mptrack::MeasurementSpace::kPolar
      ? mptrack::fuzz::Region{p.region.range_min_m, p.region.range_max_m, p.region.azimuth_min_rad,
                              p.region.azimuth_max_rad}
      : mptrack::fuzz::Region{p.cartesian_region.x_min_m, p.cartesian_region.x_max_m,
                              p.cartesian_region.y_min_m, p.cartesian_region.y_max_m};
  mptrack::fuzz::run_twin(in, reg, a, b, 48, g_scan, g_prev);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mptrack::fuzz::FuzzReader in(data, size);
  mptrack::RfsFilterParams<float> p;
  const std::uint8_t cfg = in.u8();
  // The three modes the IGGM filters implement, in the corpus' order.
  constexpr mptrack::ClutterMode kModes[3] = {mptrack::ClutterMode::kKnownUniform,
                                              mptrack::ClutterMode::kEstimatedUniform,
                                              mptrack::ClutterMode::kEstimatedMap};
  p.clutter_mode = kModes[(cfg >> 2) % 3u];
  p.amplitude.use_amplitude = (cfg & 0x20u) == 0;
  if ((cfg & 0x40u) != 0) {  // polar measurement space
    p.space = mptrack::MeasurementSpace::kPolar;
    p.region.range_min_m = 10.0f;
    p.region.range_max_m = 2000.0f;
    p.region.azimuth_min_rad = -1.5f;
    p.region.azimuth_max_rad = 1.5f;
  }
  switch (cfg % 3u) {
    case 0: run(in, p, g_phd_a, g_phd_b); break;
    case 1: run(in, p, g_cphd_a, g_cphd_b); break;
    default: run(in, p, g_cbm_a, g_cbm_b); break;
  }
  return 0;
}
