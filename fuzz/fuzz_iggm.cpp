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
using Phd = mptrack::phd::GmPhdFilter<float, FuzzIggmCaps>;
using Cphd = mptrack::phd::GmCphdFilter<float, FuzzIggmCaps>;
using Cbm = mptrack::cbmember::CbMemberFilter<float, FuzzIggmCaps>;
Phd g_phd_a, g_phd_b;
Cphd g_cphd_a, g_cphd_b;
Cbm g_cbm_a, g_cbm_b;
Phd::ScanType g_scan, g_prev;

template <class Filter>
void run(mptrack::fuzz::FuzzReader& in, const mptrack::phd::FilterParams<float>& p, Filter& a,
         Filter& b) {
  FUZZ_CHECK(a.init(p) == mptrack::Status::kOk);
  FUZZ_CHECK(b.init(p) == mptrack::Status::kOk);
  const mptrack::fuzz::Region reg{p.region_min0, p.region_max0, p.region_min1, p.region_max1};
  mptrack::fuzz::run_twin(in, reg, a, b, 48, g_scan, g_prev);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mptrack::fuzz::FuzzReader in(data, size);
  mptrack::phd::FilterParams<float> p;
  const std::uint8_t cfg = in.u8();
  // The three modes the IGGM filters implement, in the corpus' order.
  constexpr mptrack::phd::ClutterMode kModes[3] = {mptrack::phd::ClutterMode::kKnownUniform,
                                                   mptrack::phd::ClutterMode::kEstimatedUniform,
                                                   mptrack::phd::ClutterMode::kEstimatedMap};
  p.clutter_mode = kModes[(cfg >> 2) % 3u];
  p.use_amplitude = (cfg & 0x20u) == 0;
  if ((cfg & 0x40u) != 0) {  // polar measurement space
    p.space = mptrack::phd::MeasurementSpace::kPolar;
    p.region_min0 = 10.0f;
    p.region_max0 = 2000.0f;
    p.region_min1 = -1.5f;
    p.region_max1 = 1.5f;
  }
  switch (cfg % 3u) {
    case 0: run(in, p, g_phd_a, g_phd_b); break;
    case 1: run(in, p, g_cphd_a, g_cphd_b); break;
    default: run(in, p, g_cbm_a, g_cbm_b); break;
  }
  return 0;
}
