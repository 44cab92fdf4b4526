// MF-BP: a newly born clutter component deletes the young tracks it explains
// (retire_tracks_in_new_component, retire_in_new_clutter; docs/algorithms/
// mfbp.md §Birth, tracks a new component explains). One behaviour per case;
// distances worked out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "mfbp_scenario.h"
#include "mptrack/caps.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/mfbp/track_management.h"

using namespace mptrack;
using namespace mptrack::mfbp;

namespace {

using Table = TrackTable<double, DefaultCaps>;
using Comp = CompSlot<double, DefaultCaps>;
using Clutter = ClutterTable<double, DefaultCaps>;

/// A component centred at (25 km, 0.5 rad) with E[D^-1] = diag(1000 m, 0.02 rad)^2
/// on every window scan (nu = 4, so E[D^-1] = W^-1).
Comp component() {
  Comp c;
  c.alive = true;
  for (auto& nw : c.nws) {
    nw.mu = Vec2<double>(25000.0, 0.5);
    nw.nu = 4.0;
    nw.w_inv = Mat2<double>::Zero();
    nw.w_inv(0, 0) = 1000.0 * 1000.0;
    nw.w_inv(1, 1) = 0.02 * 0.02;
  }
  return c;
}

/// A clutter table whose slot 0 is component() (the new one).
std::unique_ptr<Clutter> table_with_new_component() {
  auto cl = std::make_unique<Clutter>();
  cl->comps[0] = component();
  return cl;
}

/// Track `id` in slot i born on window scan `born`, at range r and azimuth
/// 0.5 rad (at rest) on every window scan.
void put(Table& t, std::size_t i, std::uint32_t id, std::size_t born, double r) {
  t[i].start(id, born, 0.5);
  for (auto& x : t[i].xs) x = Vec4<double>(r * std::cos(0.5), 0.0, r * std::sin(0.5), 0.0);
}

/// retire_tracks_in_new_component on t for the component in `slot` of cl,
/// seeded from seed_scans scans, window of n scans; returns the deletions.
std::uint64_t retire(Table& t, const Clutter& cl, std::size_t slot = 0, std::size_t seed_scans = 4, std::size_t n = 7,
                     const MfbpParams<double>& p = MfbpParams<double>{}) {
  TrackerCounters counters;
  retire_tracks_in_new_component(t, cl, slot, seed_scans, n, p, counters);
  return counters.tracks_deleted;
}

// A cloud of 4 points per scan from scan 10 in the seed grid cell [24, 26)
// km x [30, 34) deg of the seed-000 region, at range offsets -750, -250,
// 250, 750 m; the cross-range offset steps by 200 m from scan to scan
// (period 4), so pairs form only at lag 3 (pair box 3 x 150 m): the online
// filter starts 4 tracks on scan 13, and the pool (7 scans, at least 14
// points) makes the cloud a component on scan 14.
void cloud_scan(int k, Scan<double, mfbp_test::TestCaps::kMaxMeasurements>& scan) {
  scan.time_us = static_cast<std::uint64_t>(k) * 1250000u + 1000000u;
  scan.has_doppler = false;
  scan.measurements.clear();
  if (k < 10) return;
  const double cross_m = -300.0 + 200.0 * static_cast<double>(k % 4);
  for (double dr : {-750.0, -250.0, 250.0, 750.0}) {
    Measurement<double> m;
    m.range_m = 25000.0 + dr;
    m.azimuth_rad = 0.5585053606381855 + cross_m / 25000.0;  // 32 deg
    m.amplitude = 1.5;
    (void)scan.measurements.push_back(m);
  }
}

using Online = MfbpTracker<double, mfbp_test::TestCaps>;

/// Online filter through scan 14; REQUIREs the premise above.
std::unique_ptr<Online> run_cloud(bool retire) {
  auto trk = std::make_unique<Online>();
  MfbpParams<double> p = seed000_default_params<double>();
  p.window_length = 1;
  p.slide = 1;
  p.retire_in_new_clutter = retire;
  REQUIRE(trk->init(p) == Status::kOk);
  auto scan = std::make_unique<Scan<double, mfbp_test::TestCaps::kMaxMeasurements>>();
  for (int k = 0; k <= 14; ++k) {
    cloud_scan(k, *scan);
    REQUIRE(trk->step(*scan) == Status::kOk);
    if (k == 13) {
      REQUIRE(trk->counters().tracks_born == 4u);
      REQUIRE(trk->counters().clutter_born == 0u);
    }
  }
  REQUIRE(trk->counters().clutter_born == 1u);
  return trk;
}

}  // namespace

TEST_CASE("mfbp new clutter: the tracks a cloud started end when it becomes a component") {
  const auto trk = run_cloud(true);
  CHECK(trk->live_tracks() == 0u);
  CHECK(trk->counters().tracks_deleted == 4u);
}

TEST_CASE("mfbp new clutter: with retire_in_new_clutter off those tracks live on") {
  const auto trk = run_cloud(false);
  CHECK(trk->live_tracks() == 4u);
}

TEST_CASE("mfbp new clutter: a track born on the component's scans inside its gate is deleted") {
  // Born on window scan 4 of 7: alive on scans 4..6, 3 <= 4 seed scans; at
  // the centre, d^2 = 0 < clutter_gate_chi2 (30).
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 4, 25000.0);
  CHECK(retire(*t, *table_with_new_component()) == 1u);
  CHECK_FALSE((*t)[0].alive);
}

TEST_CASE("mfbp new clutter: a track born before the component's scans is kept") {
  // Born on window scan 2 of 7: alive on 5 scans > 4 seed scans.
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 2, 25000.0);
  CHECK(retire(*t, *table_with_new_component()) == 0u);
  CHECK((*t)[0].alive);
}

TEST_CASE("mfbp new clutter: a young track already held to the in-clutter threshold is kept") {
  // It scored measurements with the predictive density inside a weaker
  // component (a component there died and is born again): the rules for
  // young tracks inside clutter decide it, not the new component.
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 4, 25000.0);
  (*t)[0].predictive_evidence = true;
  MfbpParams<double> p;
  REQUIRE(p.tentative_predictive_in_clutter);
  REQUIRE(p.confirm_threshold_in_clutter > p.confirm_threshold);
  CHECK(retire(*t, *table_with_new_component(), 0, 4, 7, p) == 0u);
  CHECK((*t)[0].alive);
}

TEST_CASE("mfbp new clutter: finalised scans count toward a track's life") {
  // Online filter (window of 1): a track with 3 finalised scans has lived 4
  // scans at the new one, within 7 seed scans; with 6 it has lived 7, and
  // with 7, 8 > 7 (kept).
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 0, 25000.0);
  put(*t, 1, 2, 0, 25000.0);
  put(*t, 2, 3, 0, 25000.0);
  (*t)[0].age = 3;
  (*t)[1].age = 6;
  (*t)[2].age = 7;
  CHECK(retire(*t, *table_with_new_component(), 0, 7, 1) == 2u);
  CHECK_FALSE((*t)[0].alive);
  CHECK_FALSE((*t)[1].alive);
  CHECK((*t)[2].alive);
}

TEST_CASE("mfbp new clutter: a young track inside an older component's gate is kept") {
  // The new component (slot 1) seeded in the tail of a live one (slot 0,
  // same centre): the track was already scored against clutter there.
  auto t = std::make_unique<Table>();
  put(*t, 0, 1, 4, 25000.0);
  auto cl = table_with_new_component();
  cl->comps[1] = component();
  CHECK(retire(*t, *cl, 1) == 0u);
  CHECK((*t)[0].alive);
}

TEST_CASE("mfbp new clutter: a young track just outside the component's gate is kept") {
  // Range offsets of 1000 sqrt(30) x 1.01 and x 0.99 m: d^2 = 30.6 and 29.4.
  auto t = std::make_unique<Table>();
  const double edge_m = 1000.0 * std::sqrt(30.0);
  put(*t, 0, 1, 4, 25000.0 + 1.01 * edge_m);
  put(*t, 1, 2, 4, 25000.0 + 0.99 * edge_m);
  CHECK(retire(*t, *table_with_new_component()) == 1u);
  CHECK((*t)[0].alive);
  CHECK_FALSE((*t)[1].alive);
}
