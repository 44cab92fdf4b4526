// MF-BP tracker end to end on a small deterministic scenario (two parallel
// targets 2 km apart, 10 uniform clutter points per scan): online filter,
// smoother, ablations, input validation, no allocation, float vs double.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mfbp_scenario.h"
#include "mptrack/mfbp/mfbp_tracker.h"

using namespace mptrack;

using mfbp_test::TestCaps;

namespace {

constexpr std::size_t kClutter = 10;

struct Report {
  int scan;
  std::uint32_t id;
  double x, y, existence, snr;
};

// Runs `scans` scans and collects every finalised confirmed report.
template <class T, class Caps>
std::vector<Report> run(MfbpTracker<T, Caps>& trk, int scans, std::uint64_t seed = 0x853c49e6748fea9bULL) {
  mfbp_test::Lcg rng;
  rng.s = seed;
  auto scan = std::make_unique<Scan<T, Caps::kMaxMeasurements>>();
  std::vector<Report> out;
  auto collect = [&]() {
    for (const auto& est : trk.outputs()) {
      for (const auto& tr : est.tracks) {
        out.push_back({static_cast<int>(est.scan_index), tr.id, static_cast<double>(tr.state(0)),
                       static_cast<double>(tr.state(2)), static_cast<double>(tr.existence),
                       static_cast<double>(tr.snr)});
      }
    }
  };
  for (int k = 0; k < scans; ++k) {
    mfbp_test::make_scan(rng, k, kClutter, *scan);
    const Status s = trk.step(*scan);
    CHECK((s == Status::kOk || s == Status::kPartial));
    collect();
  }
  CHECK(trk.flush() == Status::kOk);
  collect();
  return out;
}

double distance_to_truth(const Report& r, std::size_t i) {
  double p[2];
  mfbp_test::truth_at(r.scan, i, p);
  return std::hypot(r.x - p[0], r.y - p[1]);
}

// 3 sigma of the measurement noise in Cartesian at ~23 km (cross-range dominates).
constexpr double kThreeSigma = 3.0 * 250.0;

// After `settle` scans: each truth has exactly one confirmed report within
// 3 sigma on most scans, and no report is farther than 3 sigma from a truth.
void check_tracking(const std::vector<Report>& reps, int settle, int scans) {
  int false_reports = 0;
  int covered[2] = {0, 0};
  for (int k = settle; k < scans; ++k) {
    int near[2] = {0, 0};
    for (const auto& r : reps) {
      if (r.scan != k) continue;
      const double d0 = distance_to_truth(r, 0), d1 = distance_to_truth(r, 1);
      if (d0 < kThreeSigma) {
        ++near[0];
      } else if (d1 < kThreeSigma) {
        ++near[1];
      } else {
        ++false_reports;
      }
    }
    for (int i = 0; i < 2; ++i) {
      CHECK(near[i] <= 1);  // no duplicate confirmed track on a target
      covered[i] += near[i] == 1 ? 1 : 0;
    }
  }
  CHECK(false_reports == 0);
  const int window = scans - settle;
  CHECK(covered[0] >= window * 9 / 10);
  CHECK(covered[1] >= window * 9 / 10);
}

template <class T, class Caps>
std::unique_ptr<MfbpTracker<T, Caps>> make_tracker(std::size_t window, std::size_t slide,
                                                   T accel_var_m2ps4 = T(0)) {
  auto trk = std::make_unique<MfbpTracker<T, Caps>>();
  MfbpParams<T> p = seed000_default_params<T>();
  if (accel_var_m2ps4 > T(0)) p.accel_var_m2ps4 = accel_var_m2ps4;
  p.window_length = window;
  p.slide = slide;
  p.uniform_rate_per_scan = T(kClutter);
  REQUIRE(trk->init(p) == Status::kOk);
  return trk;
}

}  // namespace

TEST_CASE("mfbp online filter confirms both targets near truth and no false track") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  const auto reps = run(*trk, 40);
  check_tracking(reps, 10, 40);
  CHECK(trk->counters().scans == 40u);
  CHECK(trk->counters().tracks_confirmed >= 2u);
}

TEST_CASE("mfbp online filter estimates the target SNR within 50 percent") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  const auto reps = run(*trk, 40);
  int checked = 0;
  for (const auto& r : reps) {
    if (r.scan < 30) continue;
    for (std::size_t i = 0; i < 2; ++i) {
      if (distance_to_truth(r, i) < kThreeSigma) {
        CHECK(r.snr == doctest::Approx(mfbp_test::truth_snr(i)).epsilon(0.5));
        ++checked;
      }
    }
  }
  CHECK(checked >= 15);
}

TEST_CASE("mfbp smoother (window 7, slide 3) tracks both targets and finalises every scan") {
  auto trk = make_tracker<float, TestCaps>(7, 3);
  const auto reps = run(*trk, 40);
  check_tracking(reps, 10, 40);
}

TEST_CASE("mfbp smoother outputs each scan exactly once, in order") {
  auto trk = make_tracker<float, TestCaps>(7, 3);
  mfbp_test::Lcg rng;
  Scan<float, TestCaps::kMaxMeasurements> scan;
  std::vector<std::uint32_t> idx;
  for (int k = 0; k < 20; ++k) {
    mfbp_test::make_scan(rng, k, kClutter, scan);
    (void)trk->step(scan);
    // 7 scans held before the first window; then 3 per window
    if (k < 6) CHECK(trk->outputs().size() == 0u);
    for (const auto& e : trk->outputs()) idx.push_back(e.scan_index);
  }
  CHECK(trk->flush() == Status::kOk);
  for (const auto& e : trk->outputs()) idx.push_back(e.scan_index);
  REQUIRE(idx.size() == 20u);
  for (std::uint32_t k = 0; k < 20; ++k) CHECK(idx[k] == k);
}

TEST_CASE("mfbp step allocates nothing") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<Scan<float, TestCaps::kMaxMeasurements>>();
  std::size_t allocs = 0;
  for (int k = 0; k < 15; ++k) {
    mfbp_test::make_scan(rng, k, kClutter, *scan);
    test::NoAllocScope guard;
    const Status s = trk->step(*scan);
    allocs += guard.allocations();
    CHECK(s == Status::kOk);
  }
  CHECK(allocs == 0u);
}

TEST_CASE("mfbp rejects a non-increasing timestamp and leaves the state unchanged") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  mfbp_test::Lcg rng;
  Scan<float, TestCaps::kMaxMeasurements> scan;
  mfbp_test::make_scan(rng, 0, kClutter, scan);
  REQUIRE(trk->step(scan) == Status::kOk);
  const auto before = trk->counters();
  CHECK(trk->step(scan) == Status::kOutOfOrder);
  CHECK(trk->counters().scans == before.scans);
  CHECK(trk->counters().scans_rejected == before.scans_rejected + 1u);
  CHECK(trk->counters().measurements_in == before.measurements_in);
}

TEST_CASE("mfbp skips and counts invalid measurements with kPartial") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  Scan<float, TestCaps::kMaxMeasurements> scan;
  scan.time_us = 1000;
  Measurement<float> good{20000.0f, 0.5f, 2.0f, 0.0f};
  Measurement<float> nan_m{std::nanf(""), 0.5f, 2.0f, 0.0f};
  Measurement<float> weak{20000.0f, 0.5f, 0.5f, 0.0f};     // amplitude <= d
  Measurement<float> outside{60000.0f, 0.5f, 2.0f, 0.0f};  // beyond r_max
  REQUIRE(scan.measurements.push_back(good) == Status::kOk);
  REQUIRE(scan.measurements.push_back(nan_m) == Status::kOk);
  REQUIRE(scan.measurements.push_back(weak) == Status::kOk);
  REQUIRE(scan.measurements.push_back(outside) == Status::kOk);
  CHECK(trk->step(scan) == Status::kPartial);
  CHECK(trk->counters().measurements_in == 4u);
  CHECK(trk->counters().measurements_invalid == 3u);
}

TEST_CASE("mfbp init rejects bad params and step before init is refused") {
  MfbpTracker<float, TestCaps> trk;
  Scan<float, TestCaps::kMaxMeasurements> scan;
  CHECK(trk.step(scan) == Status::kNotInitialized);
  MfbpParams<float> p;
  p.window_length = 8;  // > kMaxWindow
  CHECK(trk.init(p) == Status::kInvalidArgument);
  p = MfbpParams<float>{};
  p.slide = 0;
  CHECK(trk.init(p) == Status::kInvalidArgument);
  p = MfbpParams<float>{};
  p.amplitude.swerling = 2;
  CHECK(trk.init(p) == Status::kInvalidArgument);
  p = MfbpParams<float>{};
  CHECK(trk.init(p) == Status::kOk);
}

TEST_CASE("mfbp ablations (KI, NCE, KCE, first iteration only) still track both targets") {
  for (int variant = 0; variant < 4; ++variant) {
    CAPTURE(variant);
    auto trk = std::make_unique<MfbpTracker<float, TestCaps>>();
    MfbpParams<float> p = seed000_default_params<float>();
    p.window_length = 1;
    p.slide = 1;
    p.uniform_rate_per_scan = float(kClutter);
    if (variant == 0) p.amplitude.use_amplitude = false;
    if (variant == 1) p.clutter_mode = ClutterMode::kUniformKnownRate;
    if (variant == 2) {
      p.clutter_mode = ClutterMode::kKnown;
      p.known_clutter.uniform_rate_per_scan = float(kClutter);
      p.known_clutter.uniform_cnr = 1.0f;
    }
    if (variant == 3) p.mp_max_iterations = 1;
    REQUIRE(trk->init(p) == Status::kOk);
    const auto reps = run(*trk, 40);
    check_tracking(reps, 12, 40);
  }
}

namespace {
// OSPA (p = 2, c = 631 m) between the truths and one scan's reports; brute
// force over the (<= 3) reports, enough for this scenario.
double ospa_scan(const std::vector<Report>& reps, int k) {
  std::vector<const Report*> est;
  for (const auto& r : reps) {
    if (r.scan == k) est.push_back(&r);
  }
  const double c = 631.0;
  const std::size_t m = 2, n_est = est.size();
  const std::size_t n = std::max(m, n_est);
  double best = 1e300;
  if (n_est == 0) return c;
  std::vector<std::size_t> perm(n_est);
  for (std::size_t i = 0; i < n_est; ++i) perm[i] = i;
  do {
    double cost = 0.0;
    const std::size_t pairs = std::min(m, n_est);
    for (std::size_t i = 0; i < pairs; ++i) {
      const double d = std::min(c, distance_to_truth(*est[perm[i]], i));
      cost += d * d;
    }
    best = std::min(best, cost);
  } while (std::next_permutation(perm.begin(), perm.end()));
  const double card = c * c * static_cast<double>(n - std::min(m, n_est));
  return std::sqrt((best + card) / static_cast<double>(n));
}
}  // namespace

TEST_CASE("mfbp float and double runs agree in OSPA") {
  auto tf = make_tracker<float, TestCaps>(1, 1);
  auto td = make_tracker<double, TestCaps>(1, 1);
  const auto rf = run(*tf, 40);
  const auto rd = run(*td, 40);
  double sum_f = 0, sum_d = 0;
  for (int k = 15; k < 40; ++k) {
    const double of = ospa_scan(rf, k), od = ospa_scan(rd, k);
    sum_f += of;
    sum_d += od;
    CHECK(std::fabs(of - od) < 60.0);
  }
  MESSAGE("mean OSPA float " << sum_f / 25.0 << " m, double " << sum_d / 25.0 << " m");
  CHECK(sum_f / 25.0 < 150.0);
  CHECK(std::fabs(sum_f - sum_d) / 25.0 < 10.0);
}

namespace {
// The scenario plus a Gaussian clutter blob (20 points per scan around
// (24 km, 0.55 rad), sd (1 km, 3 deg), CNR 20/3): seed 000 Table III component shape.
template <class Caps>
void add_blob(mfbp_test::Lcg& rng, Scan<float, Caps::kMaxMeasurements>& scan, std::size_t count) {
  for (std::size_t b = 0; b < count; ++b) {
    Measurement<float> m;
    m.range_m = static_cast<float>(24000.0 + 1000.0 * rng.normal());
    m.azimuth_rad = static_cast<float>(0.55 + 0.05235987755982988 * rng.normal());
    m.amplitude = static_cast<float>(std::sqrt(mfbp_test::kD * mfbp_test::kD -
                                               (1.0 + 20.0 / 3.0) * dmath::dlog(rng.uniform())));
    (void)scan.measurements.push_back(m);
  }
}
}  // namespace

TEST_CASE("mfbp estimates a Gaussian clutter component: centroid, spread, count and CNR") {
  auto trk = make_tracker<float, DefaultCaps>(1, 1);
  mfbp_test::Lcg rng;
  auto scan = std::make_unique<Scan<float, DefaultCaps::kMaxMeasurements>>();
  for (int k = 0; k < 40; ++k) {
    mfbp_test::make_scan(rng, k, kClutter, *scan);
    add_blob<DefaultCaps>(rng, *scan, 20);
    (void)trk->step(*scan);
  }
  REQUIRE(trk->outputs().size() == 1u);
  const auto& est = trk->outputs()[0];
  REQUIRE(est.clutter.size() == 2u);  // uniform + one component
  CHECK(trk->counters().clutter_born == 1u);
  const auto& u = est.clutter[0];
  const auto& c = est.clutter[1];
  CHECK(u.uniform);
  CHECK(static_cast<double>(u.expected_count) == doctest::Approx(10.0).epsilon(0.3));
  CHECK(static_cast<double>(c.mean(0)) == doctest::Approx(24000.0).epsilon(0.01));  // +-240 m
  CHECK(static_cast<double>(c.mean(1)) == doctest::Approx(0.55).epsilon(0.03));
  CHECK(std::sqrt(static_cast<double>(c.covariance(0, 0))) == doctest::Approx(1000.0).epsilon(0.2));
  CHECK(std::sqrt(static_cast<double>(c.covariance(1, 1))) == doctest::Approx(0.0524).epsilon(0.2));
  CHECK(static_cast<double>(c.expected_count) == doctest::Approx(20.0).epsilon(0.2));
  CHECK(static_cast<double>(c.cnr) == doctest::Approx(20.0 / 3.0).epsilon(0.3));
}

TEST_CASE("mfbp clutter estimation keeps false tracks near the known-clutter level, far below NCE") {
  std::size_t false_reports[3] = {0, 0, 0};
  for (int mode = 0; mode < 3; ++mode) {
    auto trk = std::make_unique<MfbpTracker<float, DefaultCaps>>();
    MfbpParams<float> p = seed000_default_params<float>();
    p.window_length = 1;
    p.slide = 1;
    p.uniform_rate_per_scan = float(kClutter);
    if (mode == 1) p.clutter_mode = ClutterMode::kUniformKnownRate;
    if (mode == 2) {
      p.clutter_mode = ClutterMode::kKnown;
      p.known_clutter.uniform_rate_per_scan = float(kClutter);
      p.known_clutter.num_components = 1;
      auto& kc = p.known_clutter.components[0];
      kc.rate_per_scan = 20.0f;
      kc.mean << 24000.0f, 0.55f;
      kc.covariance << 1e6f, 0.0f, 0.0f, 0.05235988f * 0.05235988f;
      kc.cnr = 20.0f / 3.0f;
    }
    REQUIRE(trk->init(p) == Status::kOk);
    mfbp_test::Lcg rng;
    auto scan = std::make_unique<Scan<float, DefaultCaps::kMaxMeasurements>>();
    for (int k = 0; k < 60; ++k) {
      mfbp_test::make_scan(rng, k, kClutter, *scan);
      add_blob<DefaultCaps>(rng, *scan, 20);
      (void)trk->step(*scan);
      for (const auto& e : trk->outputs()) {
        for (const auto& r : e.tracks) {
          const Report rep{k, r.id, double(r.state(0)), double(r.state(2)), 0.0, 0.0};
          if (std::min(distance_to_truth(rep, 0), distance_to_truth(rep, 1)) > kThreeSigma) ++false_reports[mode];
        }
      }
    }
  }
  MESSAGE("false reports in 60 scans: estimate " << false_reports[0] << ", NCE " << false_reports[1]
                                                 << ", KCE " << false_reports[2]);
  CHECK(false_reports[0] <= 2 * false_reports[2] + 10);
  CHECK(false_reports[1] > 3 * false_reports[0]);
}

TEST_CASE("mfbp Doppler, when present, is used: tracking holds and velocity error drops") {
  double vel_err[2] = {0.0, 0.0};
  int vel_n[2] = {0, 0};
  for (int use = 0; use < 2; ++use) {
    // The truth is exact CV: the paper's sigma_v^2 = 0.01 makes the velocity
    // error measure what Doppler adds, not how fast a noisier model settles.
    auto trk = make_tracker<float, TestCaps>(1, 1, 0.01f);
    mfbp_test::Lcg rng;
    mfbp_test::Lcg dop_rng;
    dop_rng.s = 12345u;
    auto scan = std::make_unique<Scan<float, TestCaps::kMaxMeasurements>>();
    std::vector<Report> reps;
    for (int k = 0; k < 30; ++k) {
      mfbp_test::make_scan(rng, k, kClutter, *scan);
      scan->has_doppler = use == 1;
      for (auto& m : scan->measurements) {
        // Target detections come first and lie within 200 m of a truth; the
        // others are clutter with a uniform radial velocity in [-150, 150].
        double best = 1e9, vr = 0.0;
        for (std::size_t i = 0; i < 2; ++i) {
          double p[2];
          mfbp_test::truth_at(k, i, p);
          const double px = double(m.range_m) * std::cos(double(m.azimuth_rad));
          const double py = double(m.range_m) * std::sin(double(m.azimuth_rad));
          const double d = std::hypot(px - p[0], py - p[1]);
          if (d < best) {
            best = d;
            vr = (p[0] * 40.0 + p[1] * -10.0) / std::hypot(p[0], p[1]);
          }
        }
        m.doppler_mps = static_cast<float>(best < 800.0 ? vr + dop_rng.normal() : 300.0 * dop_rng.uniform() - 150.0);
      }
      REQUIRE(trk->step(*scan) == Status::kOk);
      for (const auto& e : trk->outputs()) {
        for (const auto& t : e.tracks) {
          reps.push_back({k, t.id, double(t.state(0)), double(t.state(2)), 0.0, 0.0});
          if (k >= 10) {
            // radial component of the velocity error (what Doppler measures)
            const double r = std::hypot(double(t.state(0)), double(t.state(2)));
            const double ur = double(t.state(0)) / r, ua = double(t.state(2)) / r;
            vel_err[use] += std::fabs((double(t.state(1)) - 40.0) * ur + (double(t.state(3)) + 10.0) * ua);
            ++vel_n[use];
          }
        }
      }
    }
    check_tracking(reps, 10, 30);
  }
  REQUIRE(vel_n[0] > 0);
  REQUIRE(vel_n[1] > 0);
  const double e0 = vel_err[0] / vel_n[0], e1 = vel_err[1] / vel_n[1];
  MESSAGE("mean radial velocity error without Doppler " << e0 << " m/s, with " << e1 << " m/s");
  CHECK(e1 < 0.5 * e0);
}

TEST_CASE("mfbp track IDs stay stable once both targets are confirmed") {
  auto trk = make_tracker<float, TestCaps>(1, 1);
  const auto reps = run(*trk, 40);
  std::vector<std::uint32_t> ids;
  for (const auto& r : reps) {
    if (r.scan >= 15) ids.push_back(r.id);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  CHECK(ids.size() == 2u);  // one ID per target over scans 15..39
}

TEST_CASE("mfbp track cap overflow is counted and reported, never a crash") {
  // 40 well-separated targets on a grid, no clutter: more than the 16 tracks
  // of TestCaps can hold.
  auto trk = make_tracker<float, TestCaps>(1, 1);
  Scan<float, TestCaps::kMaxMeasurements> scan;
  bool saw_cap = false;
  for (int k = 0; k < 8; ++k) {
    scan.time_us = 1000000u + static_cast<std::uint64_t>(k) * 1250000u;
    scan.measurements.clear();
    for (int t = 0; t < 40; ++t) {
      Measurement<float> m;
      m.range_m = 12000.0f + 900.0f * static_cast<float>(t) + 50.0f * static_cast<float>(k);
      m.azimuth_rad = 0.3f + 0.01f * static_cast<float>(t % 5);
      m.amplitude = 3.0f;
      REQUIRE(scan.measurements.push_back(m) == Status::kOk);
    }
    const Status s = trk->step(scan);
    CHECK((s == Status::kOk || s == Status::kCapacityExceeded));
    saw_cap = saw_cap || s == Status::kCapacityExceeded;
    CHECK(trk->live_tracks() <= TestCaps::kMaxTargets);
  }
  CHECK(saw_cap);
  CHECK(trk->counters().track_cap_hits > 0u);
  CHECK(trk->live_tracks() == TestCaps::kMaxTargets);
}

TEST_CASE("mfbp known clutter map can be replaced between scans and is validated") {
  MfbpTracker<float, TestCaps> trk;
  KnownClutter<float> kc;
  CHECK(trk.set_known_clutter(kc) == Status::kNotInitialized);
  MfbpParams<float> p = seed000_default_params<float>();
  p.clutter_mode = ClutterMode::kKnown;
  REQUIRE(trk.init(p) == Status::kOk);
  kc.uniform_rate_per_scan = 12.0f;
  kc.num_components = 1;
  kc.components[0].rate_per_scan = 5.0f;
  kc.components[0].mean << 20000.0f, 0.5f;
  kc.components[0].covariance << 1e6f, 0.0f, 0.0f, 0.003f;
  CHECK(trk.set_known_clutter(kc) == Status::kOk);
  CHECK(trk.params().known_clutter.uniform_rate_per_scan == 12.0f);
  kc.components[0].covariance << 1e6f, 0.0f, 0.0f, -1.0f;  // not positive definite
  CHECK(trk.set_known_clutter(kc) == Status::kInvalidArgument);
  CHECK(trk.params().known_clutter.components[0].covariance(1, 1) == 0.003f);  // unchanged
}

TEST_CASE("mfbp gate-pair cap: pairs beyond Caps::kMaxGatePairs are counted and reported") {
  // One target at 30 km tracked for 6 scans, then a scan in which 12
  // distinct detections fall inside its gate (within 10 m and 0.2 mrad of
  // the prediction; gate chi2 30 at sigma 20 m / 0.6 deg): the track keeps
  // its 8 most likely pairs, the other 4 are dropped and counted.
  auto trk = make_tracker<float, TestCaps>(1, 1);
  Scan<float, TestCaps::kMaxMeasurements> scan;
  for (int k = 0; k < 7; ++k) {
    scan.time_us = 1000000u + static_cast<std::uint64_t>(k) * 1250000u;
    scan.measurements.clear();
    const int n = k < 6 ? 1 : 12;
    for (int j = 0; j < n; ++j) {
      Measurement<float> m;
      m.range_m = 30000.0f + 1.0f * static_cast<float>(j);
      m.azimuth_rad = 0.6f + 0.00002f * static_cast<float>(j);
      m.amplitude = 6.0f;
      REQUIRE(scan.measurements.push_back(m) == Status::kOk);
    }
    const std::uint64_t before = trk->counters().association_cap_hits;
    const Status s = trk->step(scan);
    if (k < 6) {
      CHECK(s == Status::kOk);
      CHECK(trk->counters().association_cap_hits == before);
    } else {
      CHECK(s == Status::kCapacityExceeded);
      CHECK(trk->counters().association_cap_hits - before == 4u);
    }
  }
  static_assert(mfbp::kMaxGatePairs<TestCaps> == 8, "the test assumes the default 8 pairs");
}

namespace {

// 8 pairs per track from a pool of 10 per scan.
struct PoolCaps : TestCaps {
  static constexpr std::size_t kMaxTrackGatePairs = 8;
  static constexpr std::size_t kMaxGatePool = 10;
};

// Two targets at 30 km, azimuths 0.6 and 0.9 rad, tracked for 6 scans;
// on the 7th scan n_a and n_b distinct detections fall inside their gates
// (as in the test above). Returns the pairs dropped on that scan and its status.
template <class Caps>
std::uint64_t two_track_drops(std::size_t n_a, std::size_t n_b, Status& last) {
  auto trk = make_tracker<float, Caps>(1, 1);
  Scan<float, Caps::kMaxMeasurements> scan;
  std::uint64_t before = 0;
  for (int k = 0; k < 7; ++k) {
    scan.time_us = 1000000u + static_cast<std::uint64_t>(k) * 1250000u;
    scan.measurements.clear();
    const float az[2] = {0.6f, 0.9f};
    const std::size_t n[2] = {k < 6 ? 1u : n_a, k < 6 ? 1u : n_b};
    for (int t = 0; t < 2; ++t) {
      for (std::size_t j = 0; j < n[t]; ++j) {
        Measurement<float> m;
        m.range_m = 30000.0f + 1.0f * static_cast<float>(j);
        m.azimuth_rad = az[t] + 0.00002f * static_cast<float>(j);
        m.amplitude = 6.0f;
        REQUIRE(scan.measurements.push_back(m) == Status::kOk);
      }
    }
    before = trk->counters().association_cap_hits;
    last = trk->step(scan);
    if (k < 6) REQUIRE(trk->counters().association_cap_hits == before);
  }
  return trk->counters().association_cap_hits - before;
}

}  // namespace

TEST_CASE("mfbp gate pool: a short pool cuts the longest lists to a common quota, counted") {
  // Track A gates 3 detections, track B 12 (B's list holds 8). Their lists,
  // 3 + 8 = 11, overflow the pool of 10: the quota is the largest q with
  // min(3, q) + min(8, q) <= 10, q = 7, so A keeps its 3 and B 7 of its 12:
  // 5 pairs dropped (4 of them by the per-track list, 1 by the pool).
  Status st = Status::kOk;
  CHECK(two_track_drops<PoolCaps>(3, 12, st) == 5u);
  CHECK(st == Status::kCapacityExceeded);
  // Both at 12: q = 5 each, 2 x 7 = 14 dropped.
  CHECK(two_track_drops<PoolCaps>(12, 12, st) == 14u);
  // 3 + 7 fit exactly: nothing is dropped.
  CHECK(two_track_drops<PoolCaps>(3, 7, st) == 0u);
  CHECK(st == Status::kOk);
  // Without a pool member the pool holds every list: B's list alone drops 4.
  static_assert(mfbp::kMaxGatePool<TestCaps> == TestCaps::kMaxTargets * 8);
  CHECK(two_track_drops<TestCaps>(3, 12, st) == 4u);
}
