// MF-BP under pressure (issue 18): the full-track-table policy
// (track_spawn.h: a birth evicts the least likely tentative track, never a
// confirmed one; otherwise it is refused) and the amplitude test of birth
// inside clutter (track_birth.h, amplitude_tail).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/mfbp/track_birth.h"

using namespace mptrack;

namespace {

template <std::size_t N>
struct PressureCaps {
  static constexpr std::size_t kMaxTargets = N;
  static constexpr std::size_t kMaxMeasurements = 16;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 4;  // the filter keeps 3 scans of history for births
};

MfbpParams<float> filter_params() {
  MfbpParams<float> p = seed000_default_params<float>();
  p.window_length = 1;
  p.slide = 1;
  p.clutter_birth = false;
  return p;
}

/// Scan k: a strong static target at 30 km, 0.6 rad, detected every scan,
/// and one "junk" point of a pair: scans 2m and 2m+1 (m >= 5) put a point at
/// 20 km + 2 km m, 0.3 rad, 30 m apart, never seen again. Each pair is a
/// two-point birth that then misses: a tentative track of falling visibility.
template <std::size_t N>
void make_scan(int k, Scan<float, N>& scan) {
  scan.time_us = 1000000u + static_cast<std::uint64_t>(k) * 1250000u;
  scan.measurements.clear();
  Measurement<float> t;
  t.range_m = 30000.0f + (k % 2 == 0 ? 5.0f : -5.0f);
  t.azimuth_rad = 0.6f;
  t.amplitude = 8.0f;
  REQUIRE(scan.measurements.push_back(t) == Status::kOk);
  const int m = k / 2;
  if (m < 5) return;
  Measurement<float> j;
  j.range_m = 20000.0f + 2000.0f * static_cast<float>(m % 10) + (k % 2 == 0 ? 0.0f : 30.0f);
  j.azimuth_rad = 0.3f;
  j.amplitude = 3.0f;
  REQUIRE(scan.measurements.push_back(j) == Status::kOk);
}

/// Runs 40 scans; returns the id of the confirmed track on the target
/// (0 if its id ever changed after confirmation or it went unreported).
template <class Tracker>
std::uint32_t run_target_id(Tracker& trk) {
  Scan<float, Tracker::kMaxMeas> scan;
  std::uint32_t id = 0;
  for (int k = 0; k < 40; ++k) {
    make_scan(k, scan);
    (void)trk.step(scan);
    for (const auto& est : trk.outputs()) {
      bool seen = false;
      for (const auto& tr : est.tracks) {
        const float dx = tr.state(0) - 30000.0f * std::cos(0.6f);
        const float dy = tr.state(2) - 30000.0f * std::sin(0.6f);
        if (dx * dx + dy * dy > 200.0f * 200.0f) continue;
        seen = true;
        if (id == 0) id = tr.id;
        if (tr.id != id) return 0;
      }
      if (id != 0 && !seen) return 0;
    }
  }
  return id;
}

}  // namespace

TEST_CASE("mfbp pressure: a full table evicts the least likely tentative track, never the confirmed one") {
  static MfbpTracker<float, PressureCaps<2>> trk;  // the target and one tentative slot
  REQUIRE(trk.init(filter_params()) == Status::kOk);
  CHECK(run_target_id(trk) != 0);
  CHECK(trk.counters().tentative_evicted > 0);
  CHECK(trk.counters().tracks_confirmed >= 1);
}

TEST_CASE("mfbp pressure: with only confirmed tracks a birth is refused and counted as a cap hit") {
  static MfbpTracker<float, PressureCaps<1>> trk;  // the target fills the table
  REQUIRE(trk.init(filter_params()) == Status::kOk);
  CHECK(run_target_id(trk) != 0);
  CHECK(trk.counters().tentative_evicted == 0);
  CHECK(trk.counters().track_cap_hits > 0);
}

TEST_CASE("mfbp birth inside clutter: amplitude tail by hand") {
  // Swerling I (n = 1): exp(-(m^2 - d^2) / varsigma); m = 2, d = 1, varsigma = 5.
  CHECK(mfbp::amplitude_tail(2.0, 1.0, 5.0, 1) == doctest::Approx(std::exp(-0.6)).epsilon(1e-12));
  // n = 2: x_m = 2 * 4 / 5 = 1.6, x_d = 0.4: exp(-1.2) (1 + 1.6) / (1 + 0.4).
  CHECK(mfbp::amplitude_tail(2.0, 1.0, 5.0, 2) == doctest::Approx(std::exp(-1.2) * 2.6 / 1.4).epsilon(1e-12));
  // At the threshold the tail is 1.
  CHECK(mfbp::amplitude_tail(1.0, 1.0, 5.0, 1) == doctest::Approx(1.0));
}
