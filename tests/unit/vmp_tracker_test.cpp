// VmpTracker behaviours on synthetic raw frames (tests/unit/vmp_test_frames.h):
// births, tracking, deaths, no false births in noise, no allocation in step(),
// and the tracker contract's rules (tracker_contract.h) written for the raw
// frame type, which the Scan-based tests/unit/tracker_contract_test.cpp cannot feed.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/vmp/vmp_tracker.h"
#include "test_budget.h"
#include "vmp_test_frames.h"

using mptrack::Status;
using Tracker = mptrack::VmpTracker<float, mptrack::VmpSmallCaps>;
using vmp_test::Cube;

static_assert(mptrack::is_tracker_v<Tracker>);
static_assert(mptrack::is_tracker_v<mptrack::VmpTracker<double>>);

namespace {

constexpr std::uint64_t kDtUs = 100000;

struct Drone {
  double x0, y0, vx, vy;
  double x(std::uint64_t n) const { return x0 + vx * 0.1 * static_cast<double>(n); }
  double y(std::uint64_t n) const { return y0 + vy * 0.1 * static_cast<double>(n); }
};

std::unique_ptr<Tracker> make_tracker(const mptrack::VmpParams& p = {}) {
  auto t = std::make_unique<Tracker>();
  REQUIRE(t->init(p) == Status::kOk);
  return t;
}

/// Frame n (0-based, time n * 100 ms): the drones with unit amplitude gain,
/// plus noise when rng is given.
void frame(const std::vector<Drone>& ds, std::uint64_t n, vmp_test::Lcg* rng, Cube& cube,
           const mptrack::VmpParams& p = {}) {
  vmp_test::clear(cube, n * kDtUs);
  for (const Drone& d : ds) vmp_test::add_echo(p, d.x(n), d.y(n), 1.0, 0.0, cube);
  if (rng != nullptr) vmp_test::add_noise(p, *rng, cube);
}

double dist(const mptrack::TrackReport<float>& r, const Drone& d, std::uint64_t n) {
  const double dx = static_cast<double>(r.state(0)) - d.x(n);
  const double dy = static_cast<double>(r.state(2)) - d.y(n);
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

TEST_CASE("VMP: a noise-free drone is born at the first frame and tracked") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  const std::vector<Drone> ds = {{8.0, 25.0, 3.0, -1.0}};
  for (std::uint64_t n = 0; n < 30; ++n) {
    frame(ds, n, nullptr, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
    const auto& e = t->outputs()[0];
    REQUIRE(e.tracks.size() == 1);
    CHECK(e.tracks[0].id == 1);
    CHECK(e.tracks[0].confirmed);
    CHECK(e.tracks[0].existence > 0.999f);
    // The zero-mean birth velocity lags the first frames by a few cm.
    if (n >= 3) CHECK(dist(e.tracks[0], ds[0], n) < 0.05);
  }
  const auto& r = t->outputs()[0].tracks[0];
  CHECK(std::abs(static_cast<double>(r.state(1)) - 3.0) < 0.1);
  CHECK(std::abs(static_cast<double>(r.state(3)) + 1.0) < 0.1);
  // ||s||^2 at 26 m is the mean component SNR (about 21 dB): the reported SNR matches.
  CHECK(r.snr > 80.0f);
  CHECK(r.snr < 200.0f);
  CHECK(t->counters().tracks_born == 1);
}

TEST_CASE("VMP: a noisy drone is tracked at the Cramer-Rao scale") {
  // 22..38 m: mean component SNR 23..13 dB, per-frame range CRB
  // 1 / sqrt(2 ||s||^2 (4 pi / c)^2 F_2 / E_U) = 0.1..0.4 m.
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  vmp_test::Lcg rng{0x1234u};
  const std::vector<Drone> ds = {{10.0, 20.0, 4.0, 2.0}};
  double sum2 = 0.0;
  int n_err = 0;
  for (std::uint64_t n = 0; n < 40; ++n) {
    frame(ds, n, &rng, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
    const auto& e = t->outputs()[0];
    REQUIRE(e.tracks.size() == 1);
    if (n >= 10) {
      sum2 += dist(e.tracks[0], ds[0], n) * dist(e.tracks[0], ds[0], n);
      ++n_err;
    }
  }
  CHECK(std::sqrt(sum2 / n_err) < 0.5);
  CHECK(t->counters().tracks_born == 1);
}

TEST_CASE("VMP: a drone that disappears is deleted at once") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  vmp_test::Lcg rng{7u};
  const std::vector<Drone> ds = {{-5.0, 22.0, 2.0, 0.0}};
  for (std::uint64_t n = 0; n < 10; ++n) {
    frame(ds, n, &rng, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
  }
  REQUIRE(t->outputs()[0].tracks.size() == 1);
  frame({}, 10, &rng, *cube);
  REQUIRE(t->step(*cube) == Status::kOk);
  CHECK(t->outputs()[0].tracks.empty());
  CHECK(t->counters().tracks_deleted == 1);
}

TEST_CASE("VMP: noise alone gives no births") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  vmp_test::Lcg rng{99u};
  // 300 frames on the host; cross builds check the first 40 (test_budget.h).
  const std::uint64_t frames = mptrack::test::run_length(300, 40);
  for (std::uint64_t n = 0; n < frames; ++n) {
    frame({}, n, &rng, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
    REQUIRE(t->outputs()[0].tracks.empty());
  }
  CHECK(t->counters().tracks_born == 0);
}

TEST_CASE("VMP: two drones in one resolution cell are both tracked through the crossing") {
  auto t = std::make_unique<mptrack::VmpTracker<float>>();
  REQUIRE(t->init(mptrack::VmpParams{}) == Status::kOk);
  auto cube = std::make_unique<Cube>();
  vmp_test::Lcg rng{5u};
  // Seed 004's crossing geometry: 0.2 m apart at frame 10 (r = 29 m, theta = 45 deg),
  // 2.2 m at frames 8 and 12; 7 m at frame 0.
  const std::vector<Drone> ds = {{15.45, 15.45, 4.95, 4.95}, {15.45, 25.55, 4.95, -4.95}};
  for (std::uint64_t n = 0; n < 20; ++n) {
    frame(ds, n, &rng, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
    const auto& e = t->outputs()[0];
    if (n < 3) continue;  // drone 2 (15.6 dB) may need a few frames to be born
    REQUIRE(e.tracks.size() == 2);
    // Each drone has a track within 1 m (the pair is 0.2..2 m apart near frame 10).
    for (const Drone& d : ds) {
      const double best = std::min(dist(e.tracks[0], d, n), dist(e.tracks[1], d, n));
      CAPTURE(n);
      CHECK(best < 1.0);
    }
  }
  CHECK(t->counters().tracks_born == 2);
}

TEST_CASE("VMP: step allocates nothing") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  vmp_test::Lcg rng{3u};
  const std::vector<Drone> ds = {{10.0, 20.0, 4.0, 2.0}, {-10.0, 35.0, 1.0, -3.0}};
  std::size_t allocations = 0;
  for (std::uint64_t n = 0; n < 15; ++n) {
    frame(ds, n, &rng, *cube);
    mptrack::test::NoAllocScope guard;
    const Status st = t->step(*cube);
    allocations += guard.allocations();
    CHECK(st == Status::kOk);
  }
  CHECK(allocations == 0);
  CHECK(t->outputs()[0].tracks.size() == 2);
}

// --- the tracker contract (tracker_contract.h rules 1-4) for raw frames ---

TEST_CASE("VMP contract: validate() names the offending field") {
  mptrack::VmpParams p;
  mptrack::ParamError where;
  REQUIRE(Tracker::validate(p, &where) == Status::kOk);
  p.max_gap_s = -1.0;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "max_gap_s");
  p = mptrack::VmpParams{};
  p.max_births_per_frame = mptrack::VmpSmallCaps::kMaxBirthsPerFrame + 1;  // over the caps
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "max_births_per_frame");
  p = mptrack::VmpParams{};
  p.noise_variance_v2 = 0.0;
  CHECK(Tracker::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "noise_variance_v2");
  auto t = std::make_unique<Tracker>();
  CHECK(t->init(p) == Status::kInvalidArgument);
  auto cube = std::make_unique<Cube>();
  CHECK(t->step(*cube) == Status::kNotInitialized);
}

TEST_CASE("VMP contract: before init() step() and flush() are refused") {
  auto t = std::make_unique<Tracker>();
  auto cube = std::make_unique<Cube>();
  CHECK(t->step(*cube) == Status::kNotInitialized);
  CHECK(t->flush() == Status::kNotInitialized);
  CHECK(t->outputs().empty());
  CHECK(t->counters().scans_rejected == 1);
  CHECK(t->counters().scans == 0);
}

TEST_CASE("VMP contract: a refused frame empties outputs() and changes nothing") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  const std::vector<Drone> ds = {{10.0, 20.0, 4.0, 2.0}};
  for (std::uint64_t n = 0; n < 5; ++n) {
    frame(ds, n, nullptr, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
  }
  const auto before = t->outputs()[0].tracks[0];
  frame(ds, 4, nullptr, *cube);  // same time again
  CHECK(t->step(*cube) == Status::kOutOfOrder);
  CHECK(t->outputs().empty());
  CHECK(t->counters().scans_rejected == 1);
  CHECK(t->counters().scans == 5);
  frame(ds, 5, nullptr, *cube);
  REQUIRE(t->step(*cube) == Status::kOk);
  CHECK(t->outputs()[0].tracks[0].id == before.id);
}

TEST_CASE("VMP contract: every accepted frame is finalised once, in order; flush holds nothing") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  std::vector<std::uint64_t> accepted, finalised;
  for (std::uint64_t n = 0; n < 12; ++n) {
    frame({{5.0, 15.0, 1.0, 1.0}}, n, nullptr, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
    accepted.push_back(cube->time_us);
    REQUIRE(t->outputs().size() == 1);
    CHECK(t->outputs()[0].scan_index == n);
    finalised.push_back(t->outputs()[0].time_us);
    if (n == 6) {
      REQUIRE(t->flush() == Status::kOk);
      CHECK(t->outputs().empty());
    }
  }
  CHECK(finalised == accepted);
  CHECK(t->counters().scans == 12);
}

TEST_CASE("VMP contract: a frame with NaN samples is kPartial, counted, and the tracks coast") {
  auto t = make_tracker();
  auto cube = std::make_unique<Cube>();
  const std::vector<Drone> ds = {{10.0, 20.0, 4.0, 2.0}};
  for (std::uint64_t n = 0; n < 6; ++n) {
    frame(ds, n, nullptr, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
  }
  frame(ds, 6, nullptr, *cube);
  cube->iq[17] = std::numeric_limits<float>::quiet_NaN();
  CHECK(t->step(*cube) == Status::kPartial);
  CHECK(t->counters().measurements_invalid == 1);
  CHECK(t->counters().measurements_in == 7);
  REQUIRE(t->outputs()[0].tracks.size() == 1);
  CHECK(dist(t->outputs()[0].tracks[0], ds[0], 6) < 0.1);  // predicted
  frame(ds, 7, nullptr, *cube);
  CHECK(t->step(*cube) == Status::kOk);
  // Several unusable frames in a row with a full window (W = 8): the frozen
  // tail must stay the filtered state of the frame that left the window.
  for (std::uint64_t n = 8; n < 20; ++n) {
    frame(ds, n, nullptr, *cube);
    if (n >= 9 && n <= 11) cube->iq[3] = std::numeric_limits<float>::infinity();
    CHECK(t->step(*cube) == (n >= 9 && n <= 11 ? Status::kPartial : Status::kOk));
    REQUIRE(t->outputs()[0].tracks.size() == 1);
    CAPTURE(n);
    CHECK(dist(t->outputs()[0].tracks[0], ds[0], n) < 0.1);
  }
  const auto& r = t->outputs()[0].tracks[0];
  CHECK(std::abs(static_cast<double>(r.state(1)) - 4.0) < 0.2);
  CHECK(std::abs(static_cast<double>(r.state(3)) - 2.0) < 0.2);
}

TEST_CASE("VMP contract: a full track pool returns kCapacityExceeded and counts the refused birth") {
  mptrack::VmpParams p;
  p.max_births_per_frame = 2;
  auto t = make_tracker(p);
  auto cube = std::make_unique<Cube>();
  // Six strong, well-separated drones for four track slots.
  std::vector<Drone> ds;
  for (int i = 0; i < 6; ++i) ds.push_back({-24.0 + 10.0 * i, 12.0 + 3.0 * (i % 2), 0.0, 0.0});
  int capacity_steps = 0;
  for (std::uint64_t n = 0; n < 4; ++n) {
    frame(ds, n, nullptr, *cube, p);
    const std::uint64_t before = t->counters().track_cap_hits;
    const Status s = t->step(*cube);
    const bool hit = t->counters().track_cap_hits > before;
    CAPTURE(n);
    CHECK(hit == (s == Status::kCapacityExceeded));
    if (!hit) CHECK(s == Status::kOk);
    capacity_steps += hit ? 1 : 0;
  }
  CHECK(capacity_steps > 0);
  CHECK(t->outputs()[0].tracks.size() == 4);
}

TEST_CASE("VMP contract: a gap longer than max_gap_s drops every track") {
  mptrack::VmpParams p;
  p.max_gap_s = 1.0;
  auto t = make_tracker(p);
  auto cube = std::make_unique<Cube>();
  const std::vector<Drone> ds = {{10.0, 20.0, 0.0, 0.0}};
  for (std::uint64_t n = 0; n < 3; ++n) {
    frame(ds, n, nullptr, *cube);
    REQUIRE(t->step(*cube) == Status::kOk);
  }
  frame(ds, 30, nullptr, *cube);  // 2.7 s later
  REQUIRE(t->step(*cube) == Status::kOk);
  CHECK(t->counters().gap_resets == 1);
  CHECK(t->counters().tracks_deleted == 1);
  REQUIRE(t->outputs()[0].tracks.size() == 1);  // re-born from this frame
  CHECK(t->outputs()[0].tracks[0].id == 2);
}
