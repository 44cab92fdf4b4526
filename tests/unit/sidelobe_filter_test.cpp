// SidelobeFilter: envelopes from the range and angle processing, the
// grouping rule on candidate lists, and one strong target through FrontEnd.
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <memory>

#include "frontend_test_signals.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/frontend/sidelobe_filter.h"

namespace fe = mptrack::frontend;
using mptrack::Status;
using Small = fe::SmallDopplerRadarCaps;

namespace {

fe::PeakCandidate cand(std::size_t g, std::size_t d, std::size_t a, float power) {
  fe::PeakCandidate c;
  c.range_bin = static_cast<std::uint16_t>(g);
  c.doppler_bin = static_cast<std::uint16_t>(d);
  c.angle_bin = static_cast<std::uint16_t>(a);
  c.cell = static_cast<std::uint32_t>((d * Small::kNumAngleBins + a) * Small::kNumRangeBins + g);
  c.power = power;
  c.noise = 1.0f;
  return c;
}

}  // namespace

TEST_CASE("SidelobeFilter envelopes start at 1 and do not increase with distance; margin in dB") {
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.sidelobe_margin_db = 10.0;
  fe::SidelobeFilter<Small> f;
  REQUIRE(f.init(p) == Status::kOk);
  CHECK(f.margin() == doctest::Approx(10.0));
  CHECK(f.range_envelope_at(0) == 1.0f);
  CHECK(f.angle_envelope_at(0) == 1.0f);
  CHECK(f.doppler_envelope_at(0) == 1.0f);
  for (std::size_t k = 1; k <= fe::SidelobeFilter<Small>::kMaxRangeLag; ++k) {
    REQUIRE(f.range_envelope_at(k) <= f.range_envelope_at(k - 1));
  }
  for (std::size_t k = 1; k <= Small::kNumAngleBins / 2; ++k) {
    REQUIRE(f.angle_envelope_at(k) <= f.angle_envelope_at(k - 1));
  }
}

TEST_CASE("SidelobeFilter angle envelope: rectangular -13 dB sidelobes, Hann far lower") {
  // 8 virtual channels, 32 bins: the Dirichlet kernel's first sidelobe is
  // 1.5 resolution cells = 6 bins out, about -13 dB (up to ~1 dB more where
  // the sampled peak straddles two bins). Margin 0 dB.
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.sidelobe_margin_db = 0.0;
  fe::SidelobeFilter<Small> rect;
  REQUIRE(rect.init(p) == Status::kOk);
  CHECK(rect.angle_envelope_at(6) > 0.04f);
  CHECK(rect.angle_envelope_at(6) < 0.08f);
  p.angle_window = fe::WindowType::kHann;
  fe::SidelobeFilter<Small> hann;
  REQUIRE(hann.init(p) == Status::kOk);
  CHECK(hann.angle_envelope_at(12) < 0.1f * rect.angle_envelope_at(12));
}

TEST_CASE("SidelobeFilter drops a weaker candidate under a stronger one's range envelope only") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();  // margin 3 dB
  fe::SidelobeFilter<Small> f;
  REQUIRE(f.init(p) == Status::kOk);
  const float strong = 1e6f;
  const float env3 = f.margin() * f.range_envelope_at(3);
  fe::PeakList<8> peaks;
  peaks.reset(8);
  peaks.insert(cand(10, 4, 12, strong));
  peaks.insert(cand(13, 4, 12, 0.5f * strong * env3));   // under the envelope: sidelobe
  peaks.insert(cand(7, 5, 13, 2.0f * strong * env3));    // above it: a target
  peaks.insert(cand(13, 9, 12, 0.5f * strong * env3));   // 5 Doppler bins off: far above
                                                         // the product bound, a target
  std::array<bool, 8> keep{};
  CHECK(f.apply(peaks, keep) == 1);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    if (keep[i]) ++kept;
    if (!keep[i]) CHECK(peaks[i].range_bin == 13);
    if (!keep[i]) CHECK(peaks[i].doppler_bin == 4);
  }
  CHECK(kept == 3);
}

TEST_CASE("SidelobeFilter off keeps every candidate") {
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.sidelobe_grouping = false;
  fe::SidelobeFilter<Small> f;
  REQUIRE(f.init(p) == Status::kOk);
  fe::PeakList<4> peaks;
  peaks.reset(4);
  peaks.insert(cand(10, 4, 12, 1e6f));
  peaks.insert(cand(13, 4, 12, 1.0f));
  std::array<bool, 4> keep{};
  CHECK(f.apply(peaks, keep) == 0);
  CHECK(keep[0]);
  CHECK(keep[1]);
}

TEST_CASE("FrontEnd: a strong target's sidelobe detections are dropped, noise alarms elsewhere stay") {
  struct Rig {
    fe::FrontEnd<Small> fe;
    fe::RadarCube<Small> cube;
    mptrack::Scan<float, Small::kMaxDetections> scan;
  };
  auto rig = std::make_unique<Rig>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  mptrack::test::SynthTarget t;
  t.range_m = 61.0;  // between bins: sidelobes on both sides
  t.bearing_rad = 0.3;
  t.radial_mps = 7.0;
  t.amplitude = 1.0;
  // Per-sample SNR -3 dB; 32 samples x 16 chirps x 8 channels of
  // processing gain (36 dB) put the peak ~33 dB over the noise, as a strong
  // drone, so its sidelobes pass CFAR.
  mptrack::test::synthesize<Small>(p, &t, 1, 2.0, 3, rig->cube);
  // Detections within 2 m and 5 m/s of the strongest (a Doppler bin is
  // 9.4 m/s here): the target and its sidelobes (every azimuth).
  const auto near_strongest = [&]() {
    std::size_t n = 0;
    const mptrack::Measurement<float>& s = rig->scan.measurements[0];
    for (const mptrack::Measurement<float>& m : rig->scan.measurements) {
      const float dr = m.range_m - s.range_m;
      const float dv = m.doppler_mps - s.doppler_mps;
      if (dr < 2.0f && dr > -2.0f && dv < 5.0f && dv > -5.0f) ++n;
    }
    return n;
  };
  p.sidelobe_grouping = false;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  const std::size_t total_without = rig->scan.measurements.size();
  CHECK(near_strongest() >= 4);
  p.sidelobe_grouping = true;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  CHECK(near_strongest() == 1);
  CHECK(rig->fe.counters().detections_sidelobe == total_without - rig->scan.measurements.size());
  CHECK(rig->scan.measurements.size() >= 2);  // the noise alarms away from the target remain
}
