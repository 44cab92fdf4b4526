// Behaviour of the GNN + CV-EKF baseline (seed 004 Sec. V-A; docs/algorithms/gnn.md) on small
// hand-built scenarios. Measurements are made from Cartesian truth with
// mptrack::dmath (so the inputs are the same bits on every target) and, where
// noisy, with a deterministic LCG + Irwin-Hall Gaussian written here.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/math/detmath.h"

using mptrack::Status;
using Tracker = mptrack::GnnTracker<float, mptrack::DefaultCaps>;
using ScanF = Tracker::ScanType;

namespace {

constexpr std::uint64_t kDtUs = 100000;  // 0.1 s, seed 004
constexpr float kDt = 0.1f;

struct Lcg {
  std::uint32_t state;
  float uniform() {  // [0, 1)
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
  }
  float gaussian() {  // Irwin-Hall(12) - 6: mean 0, variance 1, |x| <= 6
    float s = 0.0f;
    for (int k = 0; k < 12; ++k) s += uniform();
    return s - 6.0f;
  }
};

struct Point {
  float x;
  float y;
};

mptrack::Measurement<float> measure(Point p, float range_noise = 0.0f, float az_noise = 0.0f) {
  mptrack::Measurement<float> m;
  m.range_m = std::sqrt(p.x * p.x + p.y * p.y) + range_noise;
  m.azimuth_rad = mptrack::dmath::datan2(p.y, p.x) + az_noise;
  m.amplitude = 10.0f;
  return m;
}

ScanF make_scan(std::uint64_t k, const std::vector<mptrack::Measurement<float>>& ms) {
  ScanF s;
  s.time_us = 1000000 + k * kDtUs;
  for (const auto& m : ms) REQUIRE(s.measurements.push_back(m) == Status::kOk);
  return s;
}

std::unique_ptr<Tracker> make_tracker(const Tracker::Params& p = Tracker::Params{}) {
  auto t = std::make_unique<Tracker>();
  REQUIRE(t->init(p) == Status::kOk);
  return t;
}

const mptrack::TrackReport<float>* find_id(const Tracker& t, std::uint32_t id) {
  for (const auto& r : t.outputs()[0].tracks) {
    if (r.id == id) return &r;
  }
  return nullptr;
}

float pos_error(const mptrack::TrackReport<float>& r, Point p) {
  const float dx = r.state(0) - p.x;
  const float dy = r.state(2) - p.y;
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

TEST_CASE("GNN: a noise-free straight-line target is confirmed on scan 3 and its error goes to 0") {
  auto trk = make_tracker();
  const Point p0{20.0f, 5.0f};
  const Point v{3.0f, 4.0f};
  float err_scan10 = 0.0f;
  float err_last = 0.0f;
  float verr_last = 0.0f;
  for (std::uint64_t k = 0; k < 80; ++k) {
    const float t = static_cast<float>(k) * kDt;
    const Point p{p0.x + v.x * t, p0.y + v.y * t};
    REQUIRE(trk->step(make_scan(k, {measure(p)})) == Status::kOk);
    REQUIRE(trk->outputs().size() == 1);
    const auto& est = trk->outputs()[0];
    CHECK(est.scan_index == k);
    if (k < 2) {
      CHECK(est.tracks.size() == 0);  // tentative, not reported
      continue;
    }
    REQUIRE(est.tracks.size() == 1);
    const auto& r = est.tracks[0];
    CHECK(r.id == 1);
    CHECK(r.confirmed);
    CHECK(r.measurement_index == 0);
    if (k == 2) CHECK(trk->counters().tracks_confirmed == 1);
    if (k == 9) err_scan10 = pos_error(r, p);
    err_last = pos_error(r, p);
    verr_last = std::sqrt((r.state(1) - v.x) * (r.state(1) - v.x) + (r.state(3) - v.y) * (r.state(3) - v.y));
  }
  MESSAGE("position error at scan 10: " << err_scan10 << " m, at scan 80: " << err_last
                                       << " m; velocity error at scan 80: " << verr_last << " m/s");
  CHECK(err_last < 1e-4f);  // measured 7.6e-6 m (float)
  CHECK(verr_last < 1e-3f);  // measured 7.2e-6 m/s
  CHECK(err_last < 0.1f * err_scan10);
  CHECK(trk->counters().tracks_born == 1);
  CHECK(trk->counters().numerical_repairs == 0);
}

TEST_CASE("GNN: a confirmed target that disappears is deleted after exactly 5 misses") {
  auto trk = make_tracker();
  for (std::uint64_t k = 0; k < 10; ++k) {
    const Point p{30.0f + 2.0f * kDt * static_cast<float>(k), 10.0f};
    REQUIRE(trk->step(make_scan(k, {measure(p)})) == Status::kOk);
  }
  REQUIRE(trk->outputs()[0].tracks.size() == 1);
  for (std::uint64_t k = 10; k < 14; ++k) {  // misses 1..4: coasting
    REQUIRE(trk->step(make_scan(k, {})) == Status::kOk);
    REQUIRE(trk->outputs()[0].tracks.size() == 1);
    CHECK(trk->outputs()[0].tracks[0].measurement_index == -1);
    CHECK(trk->counters().tracks_deleted == 0);
  }
  REQUIRE(trk->step(make_scan(14, {})) == Status::kOk);  // miss 5
  CHECK(trk->outputs()[0].tracks.size() == 0);
  CHECK(trk->tracks().size() == 0);
  CHECK(trk->counters().tracks_deleted == 1);
}

TEST_CASE("GNN: a single clutter point lives as a tentative track for 3 scans") {
  Tracker::Params p;
  p.report_tentative = true;
  auto trk = make_tracker(p);
  REQUIRE(trk->step(make_scan(0, {measure(Point{40.0f, -12.0f})})) == Status::kOk);
  REQUIRE(trk->outputs()[0].tracks.size() == 1);
  const auto& r = trk->outputs()[0].tracks[0];
  CHECK_FALSE(r.confirmed);
  CHECK(r.existence == doctest::Approx(0.2));  // 1 hit of 5
  CHECK(r.state(1) == 0.0f);                    // velocity starts at 0
  for (std::uint64_t k = 1; k < 3; ++k) {
    REQUIRE(trk->step(make_scan(k, {})) == Status::kOk);
    CHECK(trk->outputs()[0].tracks.size() == 1);  // 1 hit + (5 - age) scans left >= 3
  }
  REQUIRE(trk->step(make_scan(3, {})) == Status::kOk);
  CHECK(trk->outputs()[0].tracks.size() == 0);
  CHECK(trk->counters().tracks_deleted == 1);
}

TEST_CASE("GNN: two crossing targets keep their IDs with moderate noise") {
  // Seed 004 tracks 1 and 2 (seed 004 Sec. V-A): they cross at scan ~21 with a
  // minimum separation of ~0.2 m, at right angles.
  Tracker::Params p;
  p.noise.range_std_m = 0.1f;
  p.noise.azimuth_std_rad = 0.003f;
  auto trk = make_tracker(p);
  Lcg rng{20240607u};
  const float vc = 4.95f;
  std::uint32_t id_of[2] = {0, 0};
  int checked = 0;
  for (std::uint64_t k = 0; k < 45; ++k) {
    const float t = static_cast<float>(k) * kDt;
    const Point truth[2] = {{10.0f + vc * t, 10.0f + vc * t}, {10.0f + vc * t, 31.0f - vc * t}};
    std::vector<mptrack::Measurement<float>> ms;
    for (const Point& q : truth) {
      const float nr = 0.1f * rng.gaussian();
      const float na = 0.003f * rng.gaussian();
      ms.push_back(measure(q, nr, na));
    }
    REQUIRE(trk->step(make_scan(k, ms)) == Status::kOk);
    const auto& tracks = trk->outputs()[0].tracks;
    if (k < 2) continue;
    REQUIRE(tracks.size() == 2);  // never a third confirmed track, never a loss
    if (k == 2) {
      for (int n = 0; n < 2; ++n) {
        id_of[n] = pos_error(tracks[0], truth[n]) < pos_error(tracks[1], truth[n]) ? tracks[0].id
                                                                                   : tracks[1].id;
      }
      REQUIRE(id_of[0] != id_of[1]);
      continue;
    }
    for (int n = 0; n < 2; ++n) {
      const auto* r = find_id(*trk, id_of[n]);
      REQUIRE(r != nullptr);
      // Away from the crossing each ID is the one near its own truth.
      if (k < 18 || k > 25) {
        CHECK(pos_error(*r, truth[n]) < 1.0f);
        ++checked;
      }
    }
  }
  CHECK(checked == 2 * (45 - 3 - 8));
  CHECK(trk->counters().tracks_born == 2);
}

TEST_CASE("GNN: sparse clutter alone never produces a confirmed track") {
  auto trk = make_tracker();
  Lcg rng{7u};
  std::size_t max_alive = 0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    std::vector<mptrack::Measurement<float>> ms;
    for (int c = 0; c < 4; ++c) {
      mptrack::Measurement<float> m;
      m.range_m = 1.0f + 149.0f * rng.uniform();
      m.azimuth_rad = -3.0f + 6.0f * rng.uniform();
      ms.push_back(m);
    }
    REQUIRE(trk->step(make_scan(k, ms)) == Status::kOk);
    CHECK(trk->outputs()[0].tracks.size() == 0);
    max_alive = std::max(max_alive, trk->tracks().size());
  }
  CHECK(trk->counters().tracks_confirmed == 0);
  // Each clutter track lives 3 scans, so at most 4 births x 3 scans are alive
  // after any step (fewer if a clutter point happened to fall in a gate).
  CHECK(max_alive <= 12);
  // Every clutter point either starts a track or updates a tentative one;
  // births and deletions balance with the live tracks.
  const auto& c = trk->counters();
  CHECK(c.tracks_born <= 800);
  CHECK(c.tracks_born >= 600);
  CHECK(c.tracks_born - c.tracks_deleted == trk->tracks().size());
}

TEST_CASE("GNN: NaN, Inf and out-of-region measurements are skipped and counted") {
  Tracker::Params p;
  p.report_tentative = true;
  p.region.range_max_m = 100.0f;
  auto trk = make_tracker(p);
  mptrack::Measurement<float> nan_m = measure(Point{10.0f, 10.0f});
  nan_m.range_m = std::numeric_limits<float>::quiet_NaN();
  mptrack::Measurement<float> inf_m = measure(Point{10.0f, 10.0f});
  inf_m.azimuth_rad = std::numeric_limits<float>::infinity();
  const auto far_m = measure(Point{150.0f, 0.0f});
  const auto good = measure(Point{20.0f, 20.0f});
  CHECK(trk->step(make_scan(0, {nan_m, good, inf_m, far_m})) == Status::kPartial);
  CHECK(trk->counters().measurements_in == 4);
  CHECK(trk->counters().measurements_invalid == 3);
  CHECK(trk->counters().tracks_born == 1);
  REQUIRE(trk->outputs()[0].tracks.size() == 1);
  CHECK(trk->outputs()[0].tracks[0].measurement_index == 1);  // index in the scan as given
  CHECK(trk->outputs()[0].tracks[0].state(0) == doctest::Approx(20.0).epsilon(1e-5));
  CHECK(trk->step(make_scan(1, {good})) == Status::kOk);
}

TEST_CASE("GNN: a scan that is not after the previous one is refused and changes nothing") {
  auto a = make_tracker();
  auto b = make_tracker();
  Lcg rng{11u};
  auto scan_at = [&](std::uint64_t k) {
    const float t = static_cast<float>(k) * kDt;
    return make_scan(k, {measure(Point{30.0f + 3.0f * t, 5.0f - 2.0f * t}, 0.1f * rng.gaussian(),
                                 0.005f * rng.gaussian())});
  };
  for (std::uint64_t k = 0; k < 6; ++k) {
    const ScanF s = scan_at(k);
    REQUIRE(a->step(s) == Status::kOk);
    REQUIRE(b->step(s) == Status::kOk);
  }
  ScanF same_time = scan_at(5);
  same_time.measurements[0].range_m += 3.0f;
  CHECK(a->step(same_time) == Status::kOutOfOrder);
  CHECK(a->outputs().size() == 0);
  ScanF earlier = scan_at(2);
  CHECK(a->step(earlier) == Status::kOutOfOrder);
  CHECK(a->counters().scans_rejected == 2);
  CHECK(a->counters().scans == 6);
  CHECK(a->counters().measurements_in == 6);
  for (std::uint64_t k = 6; k < 10; ++k) {
    const ScanF s = scan_at(k);
    REQUIRE(a->step(s) == Status::kOk);
    REQUIRE(b->step(s) == Status::kOk);
    REQUIRE(a->outputs()[0].tracks.size() == b->outputs()[0].tracks.size());
    for (std::size_t i = 0; i < a->outputs()[0].tracks.size(); ++i) {
      const auto& ra = a->outputs()[0].tracks[i];
      const auto& rb = b->outputs()[0].tracks[i];
      CHECK(ra.id == rb.id);
      CHECK(ra.state == rb.state);  // bit-identical: the refused scan left no trace
      CHECK(ra.covariance == rb.covariance);
    }
  }
}

TEST_CASE("GNN: init rejects bad parameters and step before init is refused") {
  auto trk = std::make_unique<Tracker>();
  CHECK(trk->step(make_scan(0, {})) == Status::kNotInitialized);
  CHECK(trk->flush() == Status::kNotInitialized);
  CHECK(trk->counters().scans_rejected == 1);
  Tracker::Params p;
  p.confirm_hits = 6;  // M > N
  CHECK(trk->init(p) == Status::kInvalidArgument);
  p = Tracker::Params{};
  p.noise.range_std_m = 0.0f;
  CHECK(trk->init(p) == Status::kInvalidArgument);
  p = Tracker::Params{};
  p.region.range_min_m = 300.0f;  // above region.range_max_m
  CHECK(trk->init(p) == Status::kInvalidArgument);
  p = Tracker::Params{};
  p.gate_chi2 = std::numeric_limits<float>::quiet_NaN();
  CHECK(trk->init(p) == Status::kInvalidArgument);
  p = Tracker::Params{};
  p.confirm_window = 33;
  CHECK(trk->init(p) == Status::kInvalidArgument);
  mptrack::ParamError where;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "confirm_window");
  CHECK(trk->step(make_scan(0, {})) == Status::kNotInitialized);
  CHECK(trk->init(Tracker::Params{}) == Status::kOk);
  CHECK(trk->step(make_scan(0, {})) == Status::kOk);
  CHECK(trk->flush() == Status::kOk);
  CHECK(trk->outputs().size() == 0);
}

TEST_CASE("GNN: step allocates nothing") {
  auto trk = make_tracker();
  Lcg rng{3u};
  std::size_t allocations = 0;
  for (std::uint64_t k = 0; k < 30; ++k) {
    const float t = static_cast<float>(k) * kDt;
    std::vector<mptrack::Measurement<float>> ms = {
        measure(Point{15.0f + 4.0f * t, 5.0f + 1.0f * t}, 0.1f * rng.gaussian(), 0.005f * rng.gaussian()),
        measure(Point{40.0f - 2.0f * t, 25.0f}, 0.1f * rng.gaussian(), 0.005f * rng.gaussian())};
    for (int c = 0; c < 3; ++c) {
      mptrack::Measurement<float> m;
      m.range_m = 1.0f + 99.0f * rng.uniform();
      m.azimuth_rad = -1.5f + 3.0f * rng.uniform();
      ms.push_back(m);
    }
    const ScanF s = make_scan(k, ms);
    mptrack::test::NoAllocScope guard;
    const Status st = trk->step(s);
    allocations += guard.allocations();
    CHECK(st == Status::kOk);
  }
  CHECK(allocations == 0);
  CHECK(trk->outputs()[0].tracks.size() >= 2);
}
