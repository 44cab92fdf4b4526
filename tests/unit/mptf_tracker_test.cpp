// Behaviour of the multipath track fusion baseline (MPTF, seed 002 Sec. IV):
// the M/N logic of one path track, deletion after empty gates, two paths of
// one target fused into one ground track, no allocation in step(), and the
// params checks. Detections are noise-free unless said otherwise, so each
// expected value follows from the logic by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/mptf/mptf_tracker.h"
#include "othr_scenario.h"

using mptrack::Status;
using Tracker = mptrack::MptfTracker<float, mptrack::SmallBoardCaps>;
using ScanF = Tracker::ScanType;
using mptrack::mptf::TrackStage;

namespace {

constexpr std::uint64_t kDtUs = 16000000;

mptrack::model::OthrState<double> truth(int k) {
  mptrack::model::OthrState<double> x;
  x << 1700.0 + 0.10 * 16.0 * k, 0.10, 0.48 + 8.7e-5 * 16.0 * k, 8.7e-5;  // seed 002 target 1
  return x;
}

/// Scan k with the noise-free detection of truth(k) on each listed path.
ScanF scan_at(int k, const std::vector<mptrack::model::OthrPath<double>>& paths) {
  ScanF s;
  s.time_us = 1000000ull + static_cast<std::uint64_t>(k) * kDtUs;
  s.has_doppler = true;
  for (const auto& p : paths) {
    const auto y = mptrack::model::othr_measure(truth(k), p, 100.0);
    mptrack::Measurement<float> m;
    m.range_m = static_cast<float>(y(0) * 1e3);
    m.doppler_mps = static_cast<float>(y(1) * 1e3);
    m.azimuth_rad = static_cast<float>(y(2));
    m.amplitude = 1.0f;
    REQUIRE(s.measurements.push_back(m) == Status::kOk);
  }
  return s;
}

const mptrack::model::OthrPath<double> kEE{100.0, 100.0};
const mptrack::model::OthrPath<double> kFF{260.0, 260.0};

/// One path (EE), a fused track from one path track.
Tracker::Params one_path() {
  Tracker::Params p;
  p.num_paths = 1;
  p.paths[0] = {100.0f, 100.0f};
  p.fuse_min_paths = 1;
  return p;
}

/// Two paths (EE, FF); a new fused track needs both.
Tracker::Params two_paths() {
  Tracker::Params p;
  p.num_paths = 2;
  p.paths[0] = {100.0f, 100.0f};
  p.paths[1] = {260.0f, 260.0f};
  return p;
}

}  // namespace

TEST_CASE("mptf: with stage 2 off, a path track is confirmed on 2/2 at its second scan") {
  auto t = std::make_unique<Tracker>();
  auto p = one_path();
  p.confirm_n2 = 0;
  p.confirm_m2 = 0;
  REQUIRE(t->init(p) == Status::kOk);
  REQUIRE(t->step(scan_at(0, {kEE})) == Status::kOk);
  REQUIRE(t->path_tracks().size() == 1);
  CHECK(t->path_tracks()[0].stage == TrackStage::kStage1);
  CHECK(t->counters().tracks_confirmed == 0);
  REQUIRE(t->step(scan_at(1, {kEE})) == Status::kOk);
  REQUIRE(t->path_tracks().size() == 1);
  CHECK(t->path_tracks()[0].stage == TrackStage::kConfirmed);
  CHECK(t->counters().tracks_confirmed == 1);
  CHECK(t->outputs()[0].tracks.size() == 1);
}

TEST_CASE("mptf: with 2/2 & 1/3 a path track seen on every scan is confirmed at its third scan") {
  auto t = std::make_unique<Tracker>();
  REQUIRE(t->init(one_path()) == Status::kOk);
  REQUIRE(t->step(scan_at(0, {kEE})) == Status::kOk);
  REQUIRE(t->step(scan_at(1, {kEE})) == Status::kOk);
  REQUIRE(t->path_tracks().size() == 1);
  CHECK(t->path_tracks()[0].stage == TrackStage::kStage2);  // 2/2 passed, 1/3 pending
  CHECK(t->outputs()[0].tracks.empty());
  REQUIRE(t->step(scan_at(2, {kEE})) == Status::kOk);
  CHECK(t->path_tracks()[0].stage == TrackStage::kConfirmed);
  CHECK(t->outputs()[0].tracks.size() == 1);
}

TEST_CASE("mptf: a tentative track missed at its second scan fails 2/2 and is deleted") {
  auto t = std::make_unique<Tracker>();
  REQUIRE(t->init(one_path()) == Status::kOk);
  REQUIRE(t->step(scan_at(0, {kEE})) == Status::kOk);
  REQUIRE(t->step(scan_at(1, {})) == Status::kOk);
  CHECK(t->path_tracks().empty());
  CHECK(t->counters().tracks_deleted == 1);
}

TEST_CASE("mptf: a confirmed track is deleted after delete_misses scans with an empty gate, not before") {
  for (std::uint32_t misses : {3u, 5u}) {
    CAPTURE(misses);
    auto t = std::make_unique<Tracker>();
    auto p = one_path();
    p.delete_misses = misses;
    REQUIRE(t->init(p) == Status::kOk);
    int k = 0;
    for (; k < 3; ++k) REQUIRE(t->step(scan_at(k, {kEE})) == Status::kOk);
    REQUIRE(t->path_tracks().size() == 1);
    REQUIRE(t->path_tracks()[0].stage == TrackStage::kConfirmed);
    for (std::uint32_t m = 1; m < misses; ++m, ++k) {
      REQUIRE(t->step(scan_at(k, {})) == Status::kOk);
      CHECK(t->path_tracks().size() == 1);
      CHECK(t->outputs()[0].tracks.size() == 1);
    }
    REQUIRE(t->step(scan_at(k, {})) == Status::kOk);
    CHECK(t->path_tracks().empty());
    CHECK(t->outputs()[0].tracks.empty());
  }
}

TEST_CASE("mptf: the EE and FF path tracks of one target fuse into one ground track at the target") {
  auto t = std::make_unique<Tracker>();
  const Tracker::Params p = two_paths();
  REQUIRE(t->init(p) == Status::kOk);
  for (int k = 0; k < 6; ++k) REQUIRE(t->step(scan_at(k, {kEE, kFF})) == Status::kOk);
  REQUIRE(t->path_tracks().size() == 2);
  REQUIRE(t->fused_tracks().size() == 1);
  const auto& f = t->fused_tracks()[0];
  CHECK(f.members() == 2);
  // Noise-free detections: the fused ground state is the truth up to the
  // filter's lag on the unmodelled curvature (well inside 1 km, 0.5 mrad).
  CHECK(std::fabs(static_cast<double>(f.x(0)) - truth(5)(0)) < 1.0);
  CHECK(std::fabs(static_cast<double>(f.x(2)) - truth(5)(2)) < 5e-4);
  const auto& e = t->outputs()[0];
  REQUIRE(e.tracks.size() == 1);
  CHECK(e.tracks[0].id == f.id);
}

TEST_CASE("mptf: the fused covariance is the information sum, below either member's") {
  auto t = std::make_unique<Tracker>();
  const Tracker::Params p = two_paths();
  REQUIRE(t->init(p) == Status::kOk);
  for (int k = 0; k < 4; ++k) REQUIRE(t->step(scan_at(k, {kEE, kFF})) == Status::kOk);
  REQUIRE(t->fused_tracks().size() == 1);
  const auto& f = t->fused_tracks()[0];
  const auto& tr = t->path_tracks()[0];
  mptrack::model::OthrState<float> x;
  mptrack::model::OthrMat4<float> Px;
  REQUIRE(mptrack::model::othr_slant_to_ground(tr.s, tr.P, p.paths[0], p.baseline_km, x, Px));
  // Two members of similar accuracy: about half of one member's variance.
  CHECK(f.P(0, 0) < 0.75f * Px(0, 0));
  CHECK(f.P(2, 2) < 0.75f * Px(2, 2));
}

TEST_CASE("mptf: a fused track keeps its id while its path tracks live") {
  auto t = std::make_unique<Tracker>();
  const Tracker::Params p = two_paths();
  REQUIRE(t->init(p) == Status::kOk);
  std::vector<std::uint32_t> ids;
  for (int k = 0; k < 12; ++k) {
    REQUIRE(t->step(scan_at(k, {kEE, kFF})) == Status::kOk);
    for (const auto& r : t->outputs()[0].tracks) ids.push_back(r.id);
  }
  REQUIRE(ids.size() == 10);  // reported from scan 2 (2/2 & 1/3) on
  for (std::uint32_t id : ids) CHECK(id == ids[0]);
}

TEST_CASE("mptf: step() allocates nothing") {
  using Big = mptrack::MptfTracker<float, mptrack::DefaultCaps>;
  othr_scene::Scene scene;
  scene.targets = othr_scene::seed002_targets();
  scene.clutter_mean = 125.0;
  const auto scans = othr_scene::make_scans<Big::kMaxMeasurements>(scene, 15);
  auto trk = std::make_unique<Big>();
  REQUIRE(trk->init(Big::Params{}) == Status::kOk);
  std::size_t allocations = 0;
  for (const auto& s : scans) {
    mptrack::test::NoAllocScope guard;
    const Status st = trk->step(s);
    allocations += guard.allocations();
    CHECK((st == Status::kOk || st == Status::kPartial));
  }
  CHECK(allocations == 0);
  CHECK(trk->counters().tracks_born > 0);
}

struct TwoPaths : mptrack::SmallBoardCaps {
  static constexpr std::size_t kMaxPaths = 2;
};

TEST_CASE("mptf: validate() names the failing field") {
  using T2 = mptrack::MptfTracker<float, TwoPaths>;
  mptrack::ParamError where;
  auto expect = [&](const T2::Params& p, const char* field) {
    CAPTURE(field);
    CHECK(T2::validate(p, &where) == Status::kInvalidArgument);
    CHECK(std::string(where.field) == field);
  };
  T2::Params p;
  p.num_paths = 2;
  p.fuse_min_paths = 2;
  REQUIRE(T2::validate(p, &where) == Status::kOk);
  T2::Params q = p;
  q.num_paths = 3;  // Caps::kMaxPaths = 2
  expect(q, "num_paths");
  q = p;
  q.fuse_min_paths = 3;
  expect(q, "fuse_min_paths");
  q = p;
  q.confirm_m2 = 4;  // > confirm_n2 = 3
  expect(q, "confirm_m2");
  q = p;
  q.pd = 0.0f;
  expect(q, "pd");
  q = p;
  q.delete_misses = 0;
  expect(q, "delete_misses");
}

TEST_CASE("mptf: with fuse_defer_ambiguous, EF and FF alone (a ghost reading as EE and FE fits as well) start nothing") {
  const mptrack::model::OthrPath<double> kEF{100.0, 260.0};
  // The ghost: the EF detection read as EE and the FF detection read as FE
  // land within a few km of each other on the ground, as the true reading does.
  mptrack::model::OthrState<double> a, b;
  REQUIRE(mptrack::model::othr_invert(mptrack::model::othr_measure(truth(0), kEF, 100.0), kEE, 100.0, a));
  REQUIRE(mptrack::model::othr_invert(mptrack::model::othr_measure(truth(0), kFF, 100.0), {260.0, 100.0}, 100.0, b));
  REQUIRE(std::fabs(a(0) - b(0)) < 2.0);
  REQUIRE(std::fabs(a(2) - b(2)) < 1e-3);
  for (bool defer : {false, true}) {
    CAPTURE(defer);
    auto t = std::make_unique<Tracker>();
    Tracker::Params p;  // the four seed 002 paths
    p.fuse_defer_ambiguous = defer;
    REQUIRE(t->init(p) == Status::kOk);
    for (int k = 0; k < 6; ++k) REQUIRE(t->step(scan_at(k, {kEF, kFF})) == Status::kOk);
    CHECK(t->fused_tracks().size() == (defer ? 0u : 1u));
    // EE joins (confirmed 3 scans later): the true reading now has 3 paths.
    for (int k = 6; k < 9; ++k) REQUIRE(t->step(scan_at(k, {kEE, kEF, kFF})) == Status::kOk);
    if (defer) {
      REQUIRE(t->fused_tracks().size() == 1);
      CHECK(t->fused_tracks()[0].members() == 3);
      CHECK(std::fabs(static_cast<double>(t->fused_tracks()[0].x(0)) - truth(8)(0)) < 2.0);
    }
  }
}
