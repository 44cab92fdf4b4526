// Track scores (host-sim/src/eval/track_scoring.h) on hand-built runs: one
// behaviour per case, expected values counted by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "eval/track_scoring.h"
#include "sim_test_truth.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;
using sim_test::truth_at;

namespace {

TrackOut track_at(std::uint32_t id, double x, double y, bool confirmed = true) {
  TrackOut t;
  t.id = id;
  t.px = x;
  t.py = y;
  t.confirmed = confirmed;
  return t;
}

/// A run of n scans: truth and estimates filled in by the cases.
struct Run {
  std::vector<sc::SimScan> scans;
  std::vector<EstimateOut> est;
  explicit Run(std::size_t n) : scans(n), est(n) {
    for (std::size_t i = 0; i < n; ++i) scans[i].scan = est[i].scan = static_cast<std::uint32_t>(i + 1);
  }
  void target(std::uint32_t k, std::uint32_t id, double x, double y) { scans[k - 1].truth.push_back(truth_at(id, x, y, -1)); }
  void track(std::uint32_t k, std::uint32_t id, double x, double y, bool confirmed = true) {
    est[k - 1].tracks.push_back(track_at(id, x, y, confirmed));
  }
};

TrackScoringParams gate(double gate_m, std::uint32_t min_scans = 1) {
  TrackScoringParams p;
  p.gate_m = gate_m;
  p.min_track_scans = min_scans;
  return p;
}

}  // namespace

TEST_CASE("track scoring: a target tracked from its second scan has TPD 3/4 and a latency of 1 scan") {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 1000.0, 0.0);
  for (std::uint32_t k = 2; k <= 4; ++k) r.track(k, 7, 1001.0, 0.0);
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.tpd() == doctest::Approx(0.75));
  CHECK(t.ttl_scans() == doctest::Approx(1.0));
  CHECK(t.nvt() == doctest::Approx(1.0));
  CHECK(t.nft() == doctest::Approx(0.0));
  CHECK(t.id_switches == 0);
}

TEST_CASE("track scoring: a confirmed track far from every target is a false track") {
  Run r(3);
  for (std::uint32_t k = 1; k <= 3; ++k) {
    r.target(k, 1, 0.0, 0.0);
    r.track(k, 9, 5000.0, 0.0);
  }
  const RunTrackScore s = score_run(r.scans, r.est, gate(50.0));
  CHECK(s.false_tracks == 1);
  CHECK(s.valid_tracks == 0);
  CHECK(s.targets_with_valid_track == 0);
  REQUIRE(s.targets.size() == 1);
  CHECK(s.targets[0].covered_scans == 0);
  CHECK(s.targets[0].first_covered_scan == -1);
}

TEST_CASE("track scoring: tracks shorter than min_track_scans are not scored") {
  Run r(3);
  for (std::uint32_t k = 1; k <= 3; ++k) r.track(k, 9, 5000.0, 0.0);
  CHECK(score_run(r.scans, r.est, gate(50.0, 4)).scored_tracks == 0);
  CHECK(score_run(r.scans, r.est, gate(50.0, 3)).scored_tracks == 1);
}

TEST_CASE("track scoring: tentative tracks are ignored") {
  Run r(2);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    r.target(k, 1, 0.0, 0.0);
    r.track(k, 3, 0.0, 0.0, false);
  }
  const RunTrackScore s = score_run(r.scans, r.est, gate(50.0));
  CHECK(s.scored_tracks == 0);
  CHECK(s.targets[0].covered_scans == 0);
}

TEST_CASE("track scoring: a track at the gate distance does not cover its target") {
  Run r(1);
  r.target(1, 1, 0.0, 0.0);
  r.track(1, 3, 50.0, 0.0);
  CHECK(score_run(r.scans, r.est, gate(50.0)).targets[0].covered_scans == 0);
  CHECK(score_run(r.scans, r.est, gate(50.5)).targets[0].covered_scans == 1);
}

TEST_CASE("track scoring: a track on its target for 1 of 3 scans is false, for 2 of 3 valid") {
  Run r(3);
  for (std::uint32_t k = 1; k <= 3; ++k) r.target(k, 1, 0.0, 0.0);
  r.track(1, 5, 0.0, 0.0);
  r.track(2, 5, 900.0, 0.0);
  r.track(3, 5, 900.0, 0.0);
  CHECK(score_run(r.scans, r.est, gate(50.0)).false_tracks == 1);
  r.est[1].tracks[0].px = 0.0;
  CHECK(score_run(r.scans, r.est, gate(50.0)).valid_tracks == 1);
}

TEST_CASE("track scoring: a track that ends and a new id that takes over is one switch and one break") {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 0.0, 0.0);
  r.track(1, 1, 0.0, 0.0);
  r.track(2, 1, 0.0, 0.0);
  r.track(3, 2, 0.0, 0.0);
  r.track(4, 2, 0.0, 0.0);
  const TargetScore t = score_run(r.scans, r.est, gate(50.0)).targets.at(0);
  CHECK(t.id_switches == 1);
  CHECK(t.track_breaks == 1);
  CHECK(t.fragmentations == 0);
  CHECK(t.covered_scans == 4);
}

TEST_CASE("track scoring: two tracks that swap targets are an identity switch on each, no break") {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) {
    r.target(k, 1, 0.0, 0.0);
    r.target(k, 2, 1000.0, 0.0);
    const bool swapped = k >= 4;  // 3 of 4 scans on the first target: both tracks stay valid
    r.track(k, 11, swapped ? 1000.0 : 0.0, 0.0);
    r.track(k, 12, swapped ? 0.0 : 1000.0, 0.0);
  }
  const RunTrackScore s = score_run(r.scans, r.est, gate(50.0));
  REQUIRE(s.targets.size() == 2);
  CHECK(s.targets[0].id_switches == 1);
  CHECK(s.targets[1].id_switches == 1);
  CHECK(s.targets[0].track_breaks == 0);
  CHECK(s.targets[1].track_breaks == 0);
  CHECK(s.valid_tracks == 2);
}

TEST_CASE("track scoring: coverage that resumes after a gap is one fragmentation") {
  Run r(3);
  for (std::uint32_t k = 1; k <= 3; ++k) r.target(k, 1, 0.0, 0.0);
  r.track(1, 4, 0.0, 0.0);
  r.track(2, 4, 0.0, 0.0, false);  // not confirmed at scan 2
  r.track(3, 4, 0.0, 0.0);
  const TargetScore t = score_run(r.scans, r.est, gate(50.0)).targets.at(0);
  CHECK(t.fragmentations == 1);
  CHECK(t.id_switches == 0);
  CHECK(t.covered_scans == 2);
}

TEST_CASE("track scoring: ground range and bearing errors are measured about the origin") {
  Run r(1);
  r.target(1, 1, 10000.0, 0.0);
  const double bearing = 0.002;  // rad
  r.track(1, 3, 10100.0 * std::cos(bearing), 10100.0 * std::sin(bearing));
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(500.0)));
  CHECK(t.aee_range_m() == doctest::Approx(100.0).epsilon(1e-9));
  CHECK(t.aee_bearing_rad() == doctest::Approx(bearing).epsilon(1e-9));
}

TEST_CASE("track scoring: bearing errors wrap across +-pi") {
  Run r(1);
  r.target(1, 1, -10000.0, 1e-9);   // bearing just below +pi
  r.track(1, 3, -10000.0, -1e-9);   // bearing just above -pi
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.aee_bearing_rad() == doctest::Approx(2e-13).epsilon(1e-3));
}

TEST_CASE("track scoring totals: NVT and NFT are per-run means, TPD pools target-scans") {
  Run a(2);
  Run b(2);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    a.target(k, 1, 0.0, 0.0);
    a.track(k, 1, 0.0, 0.0);  // run a: tracked both scans
    b.target(k, 1, 0.0, 0.0);
    b.track(k, 8, 700.0, 0.0);  // run b: one false track, target missed
  }
  TrackScoreTotals t;
  t.add(score_run(a.scans, a.est, gate(50.0)));
  t.add(score_run(b.scans, b.est, gate(50.0)));
  CHECK(t.nvt() == doctest::Approx(0.5));
  CHECK(t.nft() == doctest::Approx(0.5));
  CHECK(t.tpd() == doctest::Approx(0.5));
  CHECK(t.targets_tracked == 1);
}

TEST_CASE("track scoring params: OTHR scenarios count tracks from 5 scans, gate = OSPA c") {
  sc::ScenarioSpec spec;
  spec.space = sc::MeasurementSpace::kOthr;
  const TrackScoringParams p = track_scoring_params(spec, 20000.0);
  CHECK(p.min_track_scans == 5);
  CHECK(p.gate_m == 20000.0);
  spec.space = sc::MeasurementSpace::kPolar;
  CHECK(track_scoring_params(spec, 631.0).min_track_scans == 1);
}

TEST_CASE("track scoring: range and velocity RMSE over the covered scans are worked out by hand") {
  // Target at 1000 m moving +2 m/s along x. Scan 1: track 3 m long in range,
  // 1 m/s slow (|dv|^2 = 1); scan 2: 4 m short, 1 m/s of cross-range
  // velocity (|dv|^2 = 1). RMSE range = sqrt((9 + 16) / 2), velocity = 1.
  Run r(2);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    r.target(k, 1, 1000.0, 0.0);
    r.scans[k - 1].truth.back().x.vx = 2.0;
  }
  r.track(1, 7, 1003.0, 0.0);
  r.est[0].tracks.back().vx = 1.0;
  r.track(2, 7, 996.0, 0.0);
  r.est[1].tracks.back().vx = 2.0;
  r.est[1].tracks.back().vy = 1.0;
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.rmse_range_m() == doctest::Approx(std::sqrt(12.5)));
  CHECK(t.rmse_velocity_mps() == doctest::Approx(1.0));
}

TEST_CASE("track scoring: RMSE ignores scans where no valid track covers the target") {
  Run r(2);
  for (std::uint32_t k = 1; k <= 2; ++k) r.target(k, 1, 1000.0, 0.0);
  r.track(1, 7, 1002.0, 0.0);
  r.track(2, 7, 1400.0, 0.0);  // beyond the gate: scan 2 is not covered
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.covered_scans == 1);
  CHECK(t.rmse_range_m() == doctest::Approx(2.0));
}

TEST_CASE("track scoring: the AMOTA of every run is averaged over runs") {
  // Run 1 tracked perfectly (AMOTA 1); run 2 has one target-scan and no track (0).
  Run a(1), b(1);
  a.target(1, 1, 1000.0, 0.0);
  a.track(1, 7, 1000.0, 0.0);
  a.est[0].tracks.back().existence = 1.0;
  b.target(1, 1, 1000.0, 0.0);
  TrackScoreTotals t;
  t.add(score_run(a.scans, a.est, gate(50.0)));
  t.add(score_run(b.scans, b.est, gate(50.0)));
  CHECK(t.amota() == doctest::Approx(0.5));
}

TEST_CASE("track scoring: coverage from birth + 5 judges only the scans from 5 after the birth on") {
  // Target 1 alive scans 1..10, covered on 3..6 and 9..10: its settled scans
  // are 6..10 (5), covered 6, 9, 10 (3): 3/5. Target 2 born at scan 4, alive
  // 4..10, covered on every scan: settled 9..10, 2/2. Pooled 5/7, worst 0.6.
  Run r(10);
  for (std::uint32_t k = 1; k <= 10; ++k) r.target(k, 1, 0.0, 0.0);
  for (std::uint32_t k = 4; k <= 10; ++k) r.target(k, 2, 5000.0, 0.0);
  for (std::uint32_t k : {3u, 4u, 5u, 6u, 9u, 10u}) r.track(k, 7, 1.0, 0.0);
  for (std::uint32_t k = 4; k <= 10; ++k) r.track(k, 8, 5001.0, 0.0);
  const RunTrackScore s = score_run(r.scans, r.est, gate(50.0));
  REQUIRE(s.targets.size() == 2);
  CHECK(s.targets[0].settled_scans == 5);
  CHECK(s.targets[0].settled_covered_scans == 3);
  CHECK(s.targets[1].settled_scans == 2);
  CHECK(s.targets[1].settled_covered_scans == 2);
  TrackScoreTotals t;
  t.add(s);
  CHECK(t.settled_coverage() == doctest::Approx(5.0 / 7.0));
  CHECK(t.min_settled_coverage == doctest::Approx(0.6));
  CHECK(t.settled_coverage_of(1) == doctest::Approx(0.6));
  CHECK(t.settled_coverage_of(2) == doctest::Approx(1.0));
}

TEST_CASE("track scoring: a target that dies within 5 scans of its birth has no settled coverage") {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 0.0, 0.0);
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.settled_scans == 0);
  CHECK(t.settled_coverage() == doctest::Approx(0.0));
  CHECK(t.settled_by_target.empty());
  CHECK(t.min_settled_coverage == doctest::Approx(1.0));  // no pair judged
}

TEST_CASE("track scoring: two tracks on an unresolved pair keep their targets while within the gate") {
  // Targets 20 m apart; the two tracks sit between them and trade places
  // every scan (9 m / 11 m from target 1). Assigned afresh each scan, the
  // nearer track takes target 1: 3 switches per target over 4 scans. With
  // the previous scan's pairs kept (CLEAR MOT), both pairs stay within the
  // 50 m gate: no switch.
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) {
    r.target(k, 1, 0.0, 0.0);
    r.target(k, 2, 20.0, 0.0);
    const bool odd = k % 2 == 1;
    r.track(k, 11, odd ? 9.0 : 11.0, 0.0);
    r.track(k, 12, odd ? 11.0 : 9.0, 0.0);
  }
  const RunTrackScore kept = score_run(r.scans, r.est, gate(50.0));
  REQUIRE(kept.targets.size() == 2);
  CHECK(kept.targets[0].id_switches == 0);
  CHECK(kept.targets[1].id_switches == 0);
  TrackScoringParams fresh = gate(50.0);
  fresh.keep_pairs = false;
  const RunTrackScore s = score_run(r.scans, r.est, fresh);
  CHECK(s.targets[0].id_switches == 3);
  CHECK(s.targets[1].id_switches == 3);
  CHECK(s.targets[0].track_breaks == 0);
}

TEST_CASE("track scoring: a kept pair is released when its track ends, and the new id is one switch and one break") {
  // Track 11 follows target 1 on scans 1-2 and ends; track 12, already 5 m
  // away since scan 1 (unmatched: target 1 is taken), covers it from scan 3.
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) {
    r.target(k, 1, 0.0, 0.0);
    if (k <= 2) r.track(k, 11, 1.0, 0.0);
    r.track(k, 12, 5.0, 0.0);
  }
  const TargetScore t = score_run(r.scans, r.est, gate(50.0)).targets.at(0);
  CHECK(t.id_switches == 1);
  CHECK(t.track_breaks == 1);
  CHECK(t.covered_scans == 4);
}

TEST_CASE("track scoring totals: the confirmation delay per target id averages the runs it was tracked in") {
  // Run 1: target 1 (alive 1..8) first covered at scan 4 (delay 3), target 2
  // (alive 1..8) at scan 2 (delay 1). Run 2: target 1 at scan 8 (delay 7),
  // target 2 never. Target 1: (3 + 7) / 2 = 5, never 0; target 2: 1, never 1.
  // Pooled: (3 + 1 + 7) / 3 tracked.
  TrackScoreTotals t;
  for (const std::uint32_t first1 : {4u, 8u}) {
    Run r(8);
    for (std::uint32_t k = 1; k <= 8; ++k) {
      r.target(k, 1, 1000.0, 0.0);
      r.target(k, 2, 5000.0, 0.0);
    }
    for (std::uint32_t k = first1; k <= 8; ++k) r.track(k, 7, 1001.0, 0.0);
    if (first1 == 4) {
      for (std::uint32_t k = 2; k <= 8; ++k) r.track(k, 8, 5001.0, 0.0);
    }
    t.add(score_run(r.scans, r.est, gate(50.0)));
  }
  REQUIRE(t.delay_by_target.size() == 2);
  CHECK(t.ttl_scans_of(1) == doctest::Approx(5.0));
  CHECK(t.delay_by_target.at(1).never_tracked == 0);
  CHECK(t.ttl_scans_of(2) == doctest::Approx(1.0));
  CHECK(t.delay_by_target.at(2).never_tracked == 1);
  CHECK(t.ttl_scans() == doctest::Approx(11.0 / 3.0));
  CHECK(t.ttl_scans_of(3) == doctest::Approx(0.0));  // no such target
}

namespace {

/// Polar clutter region on scan k: range 10 km, azimuth 0, sigma 100 m x 0.01 rad.
ClutterRegion polar_region(std::uint32_t k) { return ClutterRegion{k, true, 10000.0, 0.0, 1e4, 0.0, 1e-4}; }

/// Scores r with a 50 m gate and the polar region of scan k.
RunTrackScore score_with_region(const Run& r, std::uint32_t k) {
  TrackScoringParams p = gate(50.0);
  p.clutter_regions = {polar_region(k)};
  return score_run(r.scans, r.est, p);
}

}  // namespace

TEST_CASE("track scoring: a false track first confirmed inside a clutter region counts in clutter, one outside not") {
  Run r(2);
  // Range error 50 m: d^2 = 0.25. Azimuth 0.05 rad: d^2 = 25 > 5.991.
  r.track(1, 5, 10050.0, 0.0);
  r.track(1, 6, 10000.0 * std::cos(0.05), 10000.0 * std::sin(0.05));
  const RunTrackScore s = score_with_region(r, 1);
  CHECK(s.false_tracks == 2);
  CHECK(s.false_tracks_in_clutter == 1);
}

TEST_CASE("track scoring: the clutter region is judged on the scan the false track is first confirmed") {
  Run r(2);
  r.track(1, 5, 10050.0, 0.0);  // inside the region's ellipse, but on scan 1
  r.track(2, 5, 10050.0, 0.0);
  CHECK(score_with_region(r, 2).false_tracks_in_clutter == 0);
}

TEST_CASE("track scoring: a valid track inside a clutter region is not a false track in clutter") {
  Run r(1);
  r.target(1, 1, 10050.0, 0.0);
  r.track(1, 5, 10050.0, 0.0);
  const RunTrackScore s = score_with_region(r, 1);
  CHECK(s.valid_tracks == 1);
  CHECK(s.false_tracks_in_clutter == 0);
}

TEST_CASE("track scoring: a Cartesian clutter region is the 95 % ellipse in x/y") {
  const ClutterRegion c{1, false, 0.0, 0.0, 1e4, 0.0, 1e4};  // sigma 100 m per axis
  CHECK(inside_clutter_region(c, 150.0, 150.0));             // d^2 = 4.5
  CHECK_FALSE(inside_clutter_region(c, 200.0, 200.0));       // d^2 = 8
}

TEST_CASE("track scoring: the scenario's Gaussian component gives one region per scan of its lifetime") {
  sc::ScenarioSpec spec;
  sc::ClutterSpec u;
  u.uniform = true;
  sc::ClutterSpec g;
  g.mean_range_m = 30000.0;
  g.mean_azimuth_deg = 90.0;
  g.sigma_range_m = 2500.0;
  g.sigma_azimuth_deg = 5.0;
  g.birth_scan = 3;
  g.death_scan = 5;
  spec.clutter = {u, g};
  const TrackScoringParams p = track_scoring_params(spec, 631.0);
  REQUIRE(p.clutter_regions.size() == 3);
  CHECK(p.clutter_regions[0].scan == 3);
  CHECK(p.clutter_regions[2].scan == 5);
  CHECK(p.clutter_regions[0].mean1 == doctest::Approx(std::acos(0.0)));
  CHECK(p.clutter_regions[0].cov00 == doctest::Approx(2500.0 * 2500.0));
  // 2.4 sigma in range (d^2 = 5.76) is inside, 2.5 sigma (6.25) is not.
  CHECK(inside_clutter_region(p.clutter_regions[0], 0.0, 30000.0 + 2.4 * 2500.0));
  CHECK_FALSE(inside_clutter_region(p.clutter_regions[0], 0.0, 30000.0 + 2.5 * 2500.0));
}

TEST_CASE("track scoring: the report delay adds the lag of the estimate that first covered the target") {
  // Target alive 1..8, covered from scan 3: TTL 2. Each scan's estimate was
  // handed out 4 scans later (a smoother's lag), the last ones by flush()
  // after scan 8: scan 3's after scan 7, so the report delay is 7 - 1 = 6.
  Run r(8);
  for (std::uint32_t k = 1; k <= 8; ++k) r.target(k, 1, 1000.0, 0.0);
  for (std::uint32_t k = 3; k <= 8; ++k) r.track(k, 7, 1001.0, 0.0);
  for (std::uint32_t k = 1; k <= 8; ++k) r.est[k - 1].reported_after_scan = k + 4 < 8 ? k + 4 : 8;
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.ttl_scans() == doctest::Approx(2.0));
  CHECK(t.report_delay_scans() == doctest::Approx(6.0));
  CHECK(t.report_delay_scans_of(1) == doctest::Approx(6.0));
}

TEST_CASE("track scoring: an estimate without a recorded report scan counts as reported at its own scan") {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 1000.0, 0.0);
  for (std::uint32_t k = 2; k <= 4; ++k) r.track(k, 7, 1001.0, 0.0);
  TrackScoreTotals t;  // reported_after_scan left 0, as a replay or a hand-built run leaves it
  t.add(score_run(r.scans, r.est, gate(50.0)));
  CHECK(t.report_delay_scans() == doctest::Approx(t.ttl_scans()));
  CHECK(t.report_delay_scans() == doctest::Approx(1.0));
}

TEST_CASE("track scoring: the real-time delay is the first scan whose own estimate covers the target") {
  // Final estimates cover target 1 (born at scan 1) from scan 3: TTL 2. The
  // real-time stream (each step's estimate of its own scan) first shows
  // track 7 on it at scan 6, so the real-time delay is 6 - 1 = 5.
  Run r(8);
  std::vector<EstimateOut> realtime(8);
  for (std::uint32_t k = 1; k <= 8; ++k) {
    r.target(k, 1, 1000.0, 0.0);
    realtime[k - 1].scan = k;
  }
  for (std::uint32_t k = 3; k <= 8; ++k) r.track(k, 7, 1001.0, 0.0);
  for (std::uint32_t k = 6; k <= 8; ++k) realtime[k - 1].tracks.push_back(track_at(7, 1002.0, 0.0));
  TrackScoreTotals t;
  t.add(score_run(r.scans, r.est, gate(50.0), &realtime));
  CHECK(t.ttl_scans() == doctest::Approx(2.0));
  CHECK(t.realtime_delay_scans() == doctest::Approx(5.0));
  CHECK(t.realtime_delay_scans_of(1) == doctest::Approx(5.0));
}

TEST_CASE("track scoring: a real-time track that no final estimate scores as valid does not count") {
  // Track 8 sits on the target in real time from scan 2 (nearer than track
  // 7 from scan 4) but never appears in the final estimates (deleted before
  // its scans were final): the first real-time coverage is track 7's, at scan 4.
  Run r(6);
  std::vector<EstimateOut> realtime(6);
  for (std::uint32_t k = 1; k <= 6; ++k) {
    r.target(k, 1, 1000.0, 0.0);
    r.track(k, 7, 1001.0, 0.0);
    realtime[k - 1].scan = k;
    if (k >= 2) realtime[k - 1].tracks.push_back(track_at(8, 1000.5, 0.0));  // 0.5 m off, track 7 1 m
    if (k >= 4) realtime[k - 1].tracks.push_back(track_at(7, 1001.0, 0.0));
  }
  const RunTrackScore s = score_run(r.scans, r.est, gate(50.0), &realtime);
  REQUIRE(s.targets.size() == 1);
  CHECK(s.targets[0].first_realtime_scan == 4);
}
