// The fixed-lag smoother of the multipath tracker
// (multipath/fixed_lag_smoother.h): its backward steps against hand values
// and an independent RTS computation, its ring, and the tracker's lagged
// output on the seed 002 scene.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "alloc_guard.h"
#include "mptrack/multipath/fixed_lag_smoother.h"
#include "mptrack/multipath/multipath_tracker.h"
#include "othr_scenario.h"

using mptrack::Status;
namespace mp = mptrack::multipath;
using Smoother = mp::FixedLagSmoother<double, 4, 2, 8>;
using Entry = mp::LagEntry<double>;
using Tracker = mptrack::MultipathMfbpTracker<float, mptrack::DefaultCaps>;

namespace {

Entry entry(std::uint32_t id, double q, double q_pred) {
  Entry e;
  e.id = id;
  e.q = q;
  e.q_pred = q_pred;
  e.x << 1700.0, 0.1, 0.48, 8.7e-5;
  e.P = mp::Mat4<double>::Identity();
  e.x_pred = e.x;
  e.P_pred = e.P;
  e.dt_s = 16.0;
  e.confirmed = true;
  return e;
}

const mp::LagModel<double> kModel{0.85, 0.15};

}  // namespace

TEST_CASE("fixed-lag smoother: a scan with no newer scan is returned as filtered") {
  Smoother s;
  REQUIRE(s.open_scan(10, 0));
  const Entry e = entry(3, 0.6, 0.5);
  CHECK(s.record(e));
  mp::SmoothedEntry<double> out;
  REQUIRE(s.smooth(0, kModel, out));
  CHECK(out.q == e.q);
  CHECK(out.x == e.x);
  CHECK(out.P == e.P);
  CHECK(out.max_later_q == 0.0);
}

TEST_CASE("fixed-lag smoother: a one-scan miss between detections is smoothed to 0.790") {
  // Filtered q 0.42 after a miss on every path; the next scan predicts 0.444
  // and its detections give 0.98. By hand: up = 0.98 / 0.444, down =
  // 0.02 / 0.556; g1 = 0.42 (0.85 up + 0.15 down) = 0.78834,
  // g0 = 0.58 (0.15 up + 0.85 down) = 0.20927; g1 / (g1 + g0) = 0.79024.
  Smoother s;
  REQUIRE(s.open_scan(10, 0));
  CHECK(s.record(entry(1, 0.42, 0.9)));
  REQUIRE(s.open_scan(20, 1));
  CHECK(s.record(entry(1, 0.98, 0.444)));
  mp::SmoothedEntry<double> out;
  REQUIRE(s.smooth(0, kModel, out));
  CHECK(out.q == doctest::Approx(0.79024).epsilon(1e-4));
  CHECK(out.max_later_q == 0.98);
}

TEST_CASE("fixed-lag smoother: a newer scan that only confirms its prediction leaves q unchanged") {
  Smoother s;
  REQUIRE(s.open_scan(10, 0));
  CHECK(s.record(entry(1, 0.3, 0.5)));
  REQUIRE(s.open_scan(20, 1));
  const double predicted = 0.85 * 0.3 + 0.15 * 0.7;
  CHECK(s.record(entry(1, predicted, predicted)));  // the update added nothing
  mp::SmoothedEntry<double> out;
  REQUIRE(s.smooth(0, kModel, out));
  CHECK(out.q == doctest::Approx(0.3).epsilon(1e-12));
}

TEST_CASE("fixed-lag smoother: the state step matches RTS computed with an explicit inverse") {
  Smoother s;
  Entry e0 = entry(1, 0.9, 0.9);
  e0.x << 1700.0, 0.1, 0.48, 1e-4;
  e0.P << 4.0, 0.01, 0.0, 0.0, 0.01, 1e-4, 0.0, 0.0, 0.0, 0.0, 1e-6, 1e-9, 0.0, 0.0, 1e-9, 1e-10;
  Entry e1 = entry(1, 0.95, 0.9);
  e1.dt_s = 16.0;
  mp::Mat4<double> F = mp::Mat4<double>::Identity();
  F(0, 1) = F(2, 3) = 16.0;
  e1.x_pred = F * e0.x;
  e1.P_pred = F * e0.P * F.transpose() + mp::Mat4<double>::Identity() * 1e-3;
  e1.x = e1.x_pred + Eigen::Vector4d(0.5, 0.001, 1e-4, 0.0);  // after its update
  e1.P = e1.P_pred * 0.5;
  REQUIRE(s.open_scan(10, 0));
  CHECK(s.record(e0));
  REQUIRE(s.open_scan(26, 1));
  CHECK(s.record(e1));
  mp::SmoothedEntry<double> out;
  REQUIRE(s.smooth(0, kModel, out));
  const mp::Mat4<double> G = e0.P * F.transpose() * e1.P_pred.inverse();
  const Eigen::Vector4d xs = e0.x + G * (e1.x - e1.x_pred);
  const mp::Mat4<double> Ps = e0.P + G * (e1.P - e1.P_pred) * G.transpose();
  for (int r = 0; r < 4; ++r) {
    CHECK(out.x(r) == doctest::Approx(xs(r)).epsilon(1e-9));
    for (int c = 0; c < 4; ++c) CHECK(out.P(r, c) == doctest::Approx(Ps(r, c)).epsilon(1e-9).scale(1e-12));
  }
}

TEST_CASE("fixed-lag smoother: a track missing from the next scan (deleted) keeps its filtered values") {
  Smoother s;
  REQUIRE(s.open_scan(10, 0));
  CHECK(s.record(entry(1, 0.6, 0.5)));
  REQUIRE(s.open_scan(20, 1));
  CHECK(s.record(entry(2, 0.99, 0.5)));  // another track only
  mp::SmoothedEntry<double> out;
  REQUIRE(s.smooth(0, kModel, out));
  CHECK(out.q == 0.6);
  CHECK(out.max_later_q == 0.0);
}

TEST_CASE("fixed-lag smoother: the ring holds lag + 1 scans and pop frees the oldest") {
  Smoother s;  // lag 2: three scans
  CHECK(s.open_scan(1, 0));
  CHECK(s.open_scan(2, 1));
  CHECK(s.open_scan(3, 2));
  CHECK_FALSE(s.open_scan(4, 3));
  CHECK(s.pending() == 3);
  s.pop();
  CHECK(s.oldest().scan_index == 1);
  CHECK(s.open_scan(4, 3));
  CHECK(s.pending() == 3);
}

namespace {

/// Every estimate the tracker finalised, by scan index (flush included).
std::map<std::uint32_t, Tracker::Estimate> run_lagged(const othr_scene::Scene& scene, int num_scans,
                                                      std::uint32_t lag, std::vector<std::size_t>* per_step = nullptr) {
  Tracker::Params p;
  p.pd.fill(static_cast<float>(scene.pd));
  p.clutter_mean_count = static_cast<float>(scene.clutter_mean > 1.0 ? scene.clutter_mean : 1.0);
  p.smoothing_lag_scans = lag;
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, num_scans);
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(p) == Status::kOk);
  std::map<std::uint32_t, Tracker::Estimate> out;
  for (const auto& s : scans) {
    REQUIRE(trk->step(s) == Status::kOk);
    if (per_step != nullptr) per_step->push_back(trk->outputs().size());
    for (const auto& e : trk->outputs()) out[e.scan_index] = e;
  }
  REQUIRE(trk->flush() == Status::kOk);
  for (const auto& e : trk->outputs()) out[e.scan_index] = e;
  return out;
}

double ground_error_km(const mptrack::TrackReport<float>& r, const mptrack::model::OthrState<double>& x) {
  const double dx = static_cast<double>(r.state(0)) - x(0) * std::cos(x(2)) * 1e3;
  const double dy = static_cast<double>(r.state(2)) - x(0) * std::sin(x(2)) * 1e3;
  return std::sqrt(dx * dx + dy * dy) * 1e-3;
}

/// Target-scans with a counted report within 10 km, over every target.
double coverage(const othr_scene::Scene& scene, const std::map<std::uint32_t, Tracker::Estimate>& est) {
  int alive = 0, covered = 0;
  for (const auto& t : scene.targets) {
    for (int k = t.first_scan; k <= t.last_scan; ++k) {
      ++alive;
      const auto it = est.find(static_cast<std::uint32_t>(k));
      if (it == est.end()) continue;
      bool near = false;
      for (const auto& r : it->second.tracks) near = near || (r.confirmed && ground_error_km(r, t.at(k, scene.dt_s)) < 10.0);
      covered += near ? 1 : 0;
    }
  }
  return static_cast<double>(covered) / alive;
}

}  // namespace

TEST_CASE("multipath, lag 2: scan k is reported at step k + 2 and flush() gives the last two") {
  othr_scene::Scene scene;
  scene.targets = othr_scene::seed002_targets();
  std::vector<std::size_t> per_step;
  const auto est = run_lagged(scene, 10, 2, &per_step);
  CHECK(per_step == std::vector<std::size_t>{0, 0, 1, 1, 1, 1, 1, 1, 1, 1});
  CHECK(est.size() == 10);  // scans 0..9, 8 from steps and 2 from flush()
}

TEST_CASE("multipath: a lag of 3 scans raises coverage at pd 0.4, Nc 125 (8 seeds) by at least 0.1") {
  double lag0 = 0.0, lag3 = 0.0;
  for (std::uint32_t seed = 0; seed < 8; ++seed) {
    othr_scene::Scene scene;
    scene.targets = othr_scene::seed002_targets();
    scene.pd = 0.4;
    scene.clutter_mean = 125.0;
    scene.seed = 0x5eed0002u + seed;
    lag0 += coverage(scene, run_lagged(scene, 30, 0)) / 8.0;
    lag3 += coverage(scene, run_lagged(scene, 30, 3)) / 8.0;
  }
  MESSAGE("coverage lag 0: " << lag0 << ", lag 3: " << lag3);
  CHECK(lag3 >= lag0 + 0.1);
}

TEST_CASE("multipath, lag 3: step() allocates nothing") {
  othr_scene::Scene scene;
  scene.targets = othr_scene::seed002_targets();
  scene.clutter_mean = 125.0;
  const auto scans = othr_scene::make_scans<Tracker::kMaxMeasurements>(scene, 15);
  Tracker::Params p;
  p.smoothing_lag_scans = 3;
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(p) == Status::kOk);
  std::size_t allocations = 0;
  for (const auto& s : scans) {
    mptrack::test::NoAllocScope guard;
    const Status st = trk->step(s);
    allocations += guard.allocations();
    CHECK(st == Status::kOk);
  }
  CHECK(allocations == 0);
}

TEST_CASE("multipath: validate() names smoothing_lag_scans above Caps::kMaxSmoothingLag") {
  Tracker::Params p;
  p.smoothing_lag_scans = static_cast<std::uint32_t>(Tracker::kMaxLag) + 1;
  mptrack::ParamError where;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "smoothing_lag_scans");
}

TEST_CASE("retrodiction: the backward CWNA step undoes the forward one in the mean, adds Q in the covariance") {
  mp::Mat4<double> P = mp::Mat4<double>::Identity() * 0.5;
  Eigen::Vector4d x(1700.0, 0.1, 0.48, 8.7e-5);
  Eigen::Vector4d fwd = x;
  mp::Mat4<double> Pf = P;
  mptrack::model::cwna_predict(fwd, Pf, 16.0, 1e-8, 1e-12);
  mp::Mat4<double> Pb = P;
  mp::cwna_retrodict(fwd, Pb, 16.0, 1e-8, 1e-12);
  for (int r = 0; r < 4; ++r) CHECK(fwd(r) == doctest::Approx(x(r)).epsilon(1e-12));
  // Independently: F^-1 (P + Q) F^-T with Q = Pf - F P F^T and F^-1 by Eigen.
  mp::Mat4<double> F = mp::Mat4<double>::Identity();
  F(0, 1) = F(2, 3) = 16.0;
  const mp::Mat4<double> Q = Pf - F * P * F.transpose();
  const mp::Mat4<double> expect = F.inverse() * (P + Q) * F.inverse().transpose();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) CHECK(Pb(r, c) == doctest::Approx(expect(r, c)).epsilon(1e-9).scale(1e-12));
  }
}

namespace {

/// One target seen on path 0 only for scans 0-2 (no birth: a group needs
/// two detections), then on all four paths; no clutter.
std::vector<Tracker::ScanType> late_birth_scans(othr_scene::Scene& four) {
  four.targets = othr_scene::seed002_targets();
  four.targets.resize(1);
  four.pd = 0.999;
  four.clutter_mean = 0.0;
  othr_scene::Scene one = four;
  one.geometry.num_paths = 1;
  auto a = othr_scene::make_scans<Tracker::kMaxMeasurements>(one, 8);
  auto b = othr_scene::make_scans<Tracker::kMaxMeasurements>(four, 8);
  for (std::size_t k = 0; k < 3; ++k) b[k] = a[k];
  return b;
}

/// Scans with a counted report (one target, no clutter: it is the
/// target's track), its largest ground error over them [km], and the first
/// step after which the tracker holds a confirmed track.
struct Coverage {
  std::vector<std::uint32_t> scans;
  double worst_error_km = 0.0;
  std::uint32_t confirmed_at = 99;
};

Coverage covered_scans(bool retrodict) {
  othr_scene::Scene scene;
  const auto scans = late_birth_scans(scene);
  Tracker::Params p;
  p.pd.fill(0.999f - 1e-3f);
  p.smoothing_lag_scans = 3;
  p.retrodict_births = retrodict;
  auto trk = std::make_unique<Tracker>();
  REQUIRE(trk->init(p) == Status::kOk);
  Coverage cov;
  const auto take = [&](const Tracker::OutputQueue& out) {
    for (const auto& e : out) {
      for (const auto& r : e.tracks) {
        if (!r.confirmed) continue;
        cov.scans.push_back(e.scan_index);
        const double err = ground_error_km(r, scene.targets[0].at(static_cast<int>(e.scan_index), scene.dt_s));
        cov.worst_error_km = err > cov.worst_error_km ? err : cov.worst_error_km;
      }
    }
  };
  for (std::uint32_t k = 0; k < scans.size(); ++k) {
    REQUIRE(trk->step(scans[k]) == Status::kOk);
    for (const auto& t : trk->tracks()) cov.confirmed_at = t.confirmed && cov.confirmed_at == 99 ? k : cov.confirmed_at;
    take(trk->outputs());
  }
  REQUIRE(trk->flush() == Status::kOk);
  take(trk->outputs());
  return cov;
}

}  // namespace

TEST_CASE("retrodiction: a track born at scan 3 is reported back to 3 scans before its confirmation") {
  // Scan s is output at step s + 3, counted if the track is confirmed by
  // then: with retrodiction every scan from max(0, c - 3) on, c the step
  // of confirmation; without, only from the birth scan 3.
  CHECK(covered_scans(false).scans == std::vector<std::uint32_t>{3, 4, 5, 6, 7});
  const Coverage retro = covered_scans(true);
  REQUIRE(retro.confirmed_at >= 3);
  REQUIRE(retro.confirmed_at <= 6);
  std::vector<std::uint32_t> expect;
  for (std::uint32_t k = retro.confirmed_at - 3; k < 8; ++k) expect.push_back(k);
  CHECK(retro.scans == expect);
}

TEST_CASE("retrodiction: the carried-back states stay within 3 azimuth sigmas (15 km) of the target") {
  // Each held-back scan adds one path-0 detection, azimuth sigma 3e-3 rad:
  // about 5.1 km across range at 1700 km.
  CHECK(covered_scans(true).worst_error_km < 15.0);
}
