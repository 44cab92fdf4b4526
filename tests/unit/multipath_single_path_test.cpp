// The multipath tracker with one path reproduces MF-BP's behaviour (issue
// 14's single-path baseline): on MF-BP's own test scene (mfbp_scenario.h:
// two parallel targets 2 km apart at ~23 km, 10 uniform clutter detections
// per scan, 40 scans of 1.25 s, range and azimuth only), the multipath
// tracker configured with one path of zero heights and zero baseline
// (h(x) = [g, g_dot, theta]: a polar-state CV filter) and births from
// single detections is compared with the MF-BP online filter (window 1).
//
// What is compared, from scan 10 on (both have settled):
//  1. per tracker, each truth has exactly one counted (confirmed) track
//     within 3 sigma (750 m) on at least 90 % of the scans, and no counted
//     track is farther than 3 sigma from every truth: the same track
//     picture as MF-BP;
//  2. where both report a track on the same truth, the two position
//     estimates are within 250 m (one cross-range sigma) on every scan,
//     and their mean separation is under 100 m.
// Not compared: bits (different state coordinates and motion models:
// Cartesian CV in MF-BP, polar CV here), SNR (MF-BP estimates amplitude,
// the multipath tracker does not model it), latency of confirmation.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/multipath/multipath_tracker.h"

using namespace mptrack;

namespace {

constexpr int kScans = 40;
constexpr int kSettle = 10;
constexpr double kThreeSigma = 750.0;

struct Pos {
  bool ok = false;
  double x = 0.0, y = 0.0;
};

/// Per scan and truth: the counted track within 3 sigma (or none), and the
/// number of counted tracks near no truth.
template <class Estimate>
void tally(const Estimate& e, int k, std::vector<std::array<Pos, 2>>& near, int& duplicates, int& false_reports) {
  for (const auto& r : e.tracks) {
    if (!r.confirmed) continue;
    bool matched = false;
    for (std::size_t i = 0; i < 2; ++i) {
      double p[2];
      mfbp_test::truth_at(k, i, p);
      const double d = std::hypot(static_cast<double>(r.state(0)) - p[0], static_cast<double>(r.state(2)) - p[1]);
      if (d < kThreeSigma) {
        duplicates += near[static_cast<std::size_t>(k)][i].ok ? 1 : 0;
        near[static_cast<std::size_t>(k)][i] = {true, static_cast<double>(r.state(0)), static_cast<double>(r.state(2))};
        matched = true;
      }
    }
    false_reports += matched ? 0 : 1;
  }
}

/// MF-BP's test caps with room for the short-lived clutter-born tracks of
/// single-detection births (about 2 scans each, 10 per scan).
struct MultiCaps : mfbp_test::TestCaps {
  static constexpr std::size_t kMaxTargets = 64;
};

MultipathParams<float> single_path_params() {
  MultipathParams<float> p;
  p.num_paths = 1;
  p.paths[0] = {0.0f, 0.0f};
  p.baseline_km = 0.0f;
  p.pd[0] = 0.95f;  // Swerling I at SNR 10 and 16.7 over d = 0.715: 0.955, 0.970
  p.region = {10000.0f, 50000.0f, 0.17453292f, 1.0471976f};
  p.noise = {20.0f, 0.010471976f, 1.0f};
  p.range_rate_span_mps = 100.0f;
  p.clutter_mean_count = 10.0f;
  p.range_psd_m2ps3 = 1.0f;         // straight Cartesian lines curve slightly in (g, theta)
  p.bearing_psd_rad2ps3 = 1e-10f;
  p.min_group_size = 1;
  // With one path a single detection must not confirm a clutter-born
  // track: a dormant detection probability of 0.2 makes one hit worth a
  // likelihood ratio 0.95 / 0.2 instead of 0.95 / 0.01, so three hits
  // are needed from the birth existence 0.1 (with four paths the misses
  // on the other paths do this job).
  p.pd_dormant = 0.2f;
  p.birth_existence_scale = 0.1f;
  p.delete_existence = 0.05f;  // a clutter-born track goes at its first miss
  p.init_bearing_rate_std_radps = 3e-3f;  // 40 m/s across 23 km
  return p;
}

}  // namespace

TEST_CASE("multipath, one path, reproduces MF-BP's track picture and positions on MF-BP's scene") {
  using Mfbp = MfbpTracker<float, mfbp_test::TestCaps>;
  using Multi = MultipathMfbpTracker<float, MultiCaps>;
  auto mfbp = std::make_unique<Mfbp>();
  MfbpParams<float> mp = seed000_default_params<float>();
  mp.window_length = 1;
  mp.slide = 1;
  mp.uniform_rate_per_scan = 10.0f;
  REQUIRE(mfbp->init(mp) == Status::kOk);
  auto multi = std::make_unique<Multi>();
  REQUIRE(multi->init(single_path_params()) == Status::kOk);

  mfbp_test::Lcg rng;
  auto scan = std::make_unique<Scan<float, mfbp_test::TestCaps::kMaxMeasurements>>();
  std::vector<std::array<Pos, 2>> near_a(kScans), near_b(kScans);
  int dup_a = 0, dup_b = 0, false_a = 0, false_b = 0;
  for (int k = 0; k < kScans; ++k) {
    mfbp_test::make_scan(rng, k, 10, *scan);
    REQUIRE(mfbp->step(*scan) == Status::kOk);
    REQUIRE(multi->step(*scan) == Status::kOk);
    if (k < kSettle) continue;
    tally(mfbp->outputs()[0], k, near_a, dup_a, false_a);
    tally(multi->outputs()[0], k, near_b, dup_b, false_b);
  }
  int covered_a[2] = {0, 0}, covered_b[2] = {0, 0}, both = 0;
  double sum_sep = 0.0, max_sep = 0.0;
  for (int k = kSettle; k < kScans; ++k) {
    for (std::size_t i = 0; i < 2; ++i) {
      const Pos& a = near_a[static_cast<std::size_t>(k)][i];
      const Pos& b = near_b[static_cast<std::size_t>(k)][i];
      covered_a[i] += a.ok ? 1 : 0;
      covered_b[i] += b.ok ? 1 : 0;
      if (a.ok && b.ok) {
        const double sep = std::hypot(a.x - b.x, a.y - b.y);
        sum_sep += sep;
        max_sep = sep > max_sep ? sep : max_sep;
        ++both;
      }
    }
  }
  const int window = kScans - kSettle;
  MESSAGE("mfbp covered " << covered_a[0] << "/" << covered_a[1] << " multipath " << covered_b[0] << "/"
                          << covered_b[1] << " of " << window << "; separation mean " << sum_sep / both
                          << " m, max " << max_sep << " m");
  for (int i = 0; i < 2; ++i) {
    CHECK(covered_a[i] >= window * 9 / 10);
    CHECK(covered_b[i] >= window * 9 / 10);
  }
  CHECK(dup_a == 0);
  CHECK(dup_b == 0);
  CHECK(false_a == 0);
  CHECK(false_b == 0);
  REQUIRE(both > 0);
  CHECK(max_sep < 250.0);
  CHECK(sum_sep / both < 100.0);
}
