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

TEST_CASE("mfbp one-point birth: state at the point, zero velocity under the v_max box prior") {
  mfbp::Vec4<double> x;
  mfbp::Mat4<double> P;
  // On the x axis (az 0): J = diag(1, r), so P_pos = diag(sigma_r^2, (r sigma_az)^2).
  mfbp::one_point_state(30000.0, 0.0, 20.0, 0.01, 120.0, 60.0, x, P);
  CHECK(x(0) == doctest::Approx(30000.0));
  CHECK(x(1) == 0.0);
  CHECK(x(2) == doctest::Approx(0.0));
  CHECK(x(3) == 0.0);
  CHECK(P(0, 0) == doctest::Approx(400.0));
  CHECK(P(2, 2) == doctest::Approx(90000.0));
  CHECK(P(1, 1) == doctest::Approx(120.0 * 120.0 / 3.0));
  CHECK(P(3, 3) == doctest::Approx(60.0 * 60.0 / 3.0));
  CHECK(P(0, 1) == 0.0);
  CHECK(P(1, 2) == 0.0);
  CHECK(P(0, 2) == doctest::Approx(0.0).epsilon(1e-9));
}

namespace {

/// The filter on a known map with one dense component (30 per scan, CNR 4)
/// at 30 km, 0.6 rad and no uniform clutter beyond the floor.
MfbpParams<float> known_component_params(float single_point_tail, float max_cnr, float cnr = 4.0f) {
  MfbpParams<float> p = filter_params();
  p.clutter_mode = ClutterMode::kKnownMap;
  p.known_clutter.uniform_rate_per_scan = 0.0f;
  p.known_clutter.num_components = 1;
  auto& c = p.known_clutter.components[0];
  c.rate_per_scan = 30.0f;
  c.mean << 30000.0f, 0.6f;
  c.covariance << 500.0f * 500.0f, 0.0f, 0.0f, 0.05f * 0.05f;
  c.cnr = cnr;
  p.birth_single_point_tail = single_point_tail;
  p.birth_in_clutter_max_cnr = max_cnr;
  return p;
}

/// One scan: a single detection at the centre of a component of mean CNR
/// cnr, of amplitude m (birth_in_clutter_max_cnr: max_cnr, 0 = no limit).
std::uint64_t births_after_one_point(float single_point_tail, float m, float max_cnr = 0.0f, float cnr = 4.0f) {
  static MfbpTracker<float, PressureCaps<4>> trk;
  REQUIRE(trk.init(known_component_params(single_point_tail, max_cnr, cnr)) == Status::kOk);
  Scan<float, 16> scan;
  scan.time_us = 1000000u;
  Measurement<float> z;
  z.range_m = 30000.0f;
  z.azimuth_rad = 0.6f;
  z.amplitude = m;
  REQUIRE(scan.measurements.push_back(z) == Status::kOk);
  (void)trk.step(scan);
  return trk.counters().tracks_born;
}

}  // namespace

TEST_CASE("mfbp one-point birth inside clutter: a strong lone detection starts a track only when enabled") {
  // d = 0.715 (seed 000), varsigma = 1 + CNR = 5: m = 5 gives a tail of
  // exp(-(25 - 0.511) / 5) = 0.0075 < 0.1. Without a second point no pair
  // can form, so with the one-point birth off nothing is born.
  CHECK(births_after_one_point(0.1f, 5.0f) == 1);
  CHECK(births_after_one_point(0.0f, 5.0f) == 0);
  // m = 2: tail exp(-(4 - 0.511) / 5) = 0.50, not below 0.1 (nor below the
  // pair test's 0.2): no birth.
  CHECK(births_after_one_point(0.1f, 2.0f) == 0);
}

TEST_CASE("mfbp birth inside clutter: no amplitude birth under a component stronger than birth_in_clutter_max_cnr") {
  // The CNR-4 component of above and m = 5 (tail 0.0075): a cap of 5 or
  // exactly 4 leaves the birth, a cap of 3.9 makes the point explained.
  CHECK(births_after_one_point(0.1f, 5.0f, 5.0f) == 1);
  CHECK(births_after_one_point(0.1f, 5.0f, 4.0f) == 1);
  CHECK(births_after_one_point(0.1f, 5.0f, 3.9f) == 0);
}

TEST_CASE("mfbp-s1's CNR limit keeps amplitude births under CNR-4 clutter and drops them under S2's CNR-6.67 chaff") {
  const float limit = every_scan_smoother_params<float>().birth_in_clutter_max_cnr;
  // m = 5 under CNR 6.67 (varsigma 7.67): tail exp(-(25 - 0.511) / 7.67) =
  // 0.041 < 0.1, so without a limit the point starts a track alone.
  CHECK(births_after_one_point(0.1f, 5.0f, 0.0f, 6.67f) == 1);
  CHECK(births_after_one_point(0.1f, 5.0f, limit, 6.67f) == 0);
  // Under CNR 4 (tail 0.0075, as above) the limit leaves the birth.
  CHECK(births_after_one_point(0.1f, 5.0f, limit, 4.0f) == 1);
}
