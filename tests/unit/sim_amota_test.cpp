// AMOTA (host-sim/src/eval/amota.h) on hand-built runs: one behaviour per
// case; TP/FP/FN/IDS counted by hand, MOTA = 1 - (FP + FN + IDS) / num_gt,
// MOTAR = 1 - (FP + IDS) / TP, and AMOTA = (1/L) sum over r = 1/L..1 of
// MOTAR_r (normalised) or MOTA_r (unscaled) (Weng et al., IROS 2020).
#include <doctest/doctest.h>

#include <memory>
#include <vector>

#include "eval/amota.h"
#include "sim_test_truth.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;
using sim_test::truth_at;

namespace {

struct Run {
  std::vector<sc::SimScan> scans;
  std::vector<EstimateOut> est;
  explicit Run(std::size_t n) : scans(n), est(n) {
    for (std::size_t i = 0; i < n; ++i) scans[i].scan = est[i].scan = static_cast<std::uint32_t>(i + 1);
  }
  void target(std::uint32_t k, std::uint32_t id, double x) { scans[k - 1].truth.push_back(truth_at(id, x, 0.0, -1)); }
  void track(std::uint32_t k, std::uint32_t id, double x, double existence, bool confirmed = true) {
    TrackOut t;
    t.id = id;
    t.px = x;
    t.existence = existence;
    t.confirmed = confirmed;
    est[k - 1].tracks.push_back(t);
  }
};

AmotaScore score(const Run& r, std::uint32_t recall_points) {
  auto solver = std::make_unique<ScoringSolver>();
  return run_amota(r.scans, r.est, AmotaParams{50.0, recall_points}, *solver);
}
double amota(const Run& r, std::uint32_t recall_points) { return score(r, recall_points).normalised; }
double amota_unscaled(const Run& r, std::uint32_t recall_points) { return score(r, recall_points).unscaled; }

/// Target 1 at x = 1000 m in each of 4 scans, track 7 on it at x = track_x
/// with existence existence0 - existence_step * k on scan k.
Run tracked_target(double track_x, double existence0, double existence_step) {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) {
    r.target(k, 1, 1000.0);
    r.track(k, 7, track_x, existence0 - existence_step * k);
  }
  return r;
}

/// Target 1 at x = 1000 m in each of 4 scans, covered by track 7 in the
/// first two only (existence 1).
Run half_covered_target() {
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 1000.0);
  r.track(1, 7, 1000.0, 1.0);
  r.track(2, 7, 1000.0, 1.0);
  return r;
}

MotCounts counts(const Run& r, double min_existence) {
  auto solver = std::make_unique<ScoringSolver>();
  return mot_counts(r.scans, r.est, 50.0, min_existence, *solver);
}

}  // namespace

TEST_CASE("AMOTA: a track on its target every scan and nothing else scores 1") {
  const Run r = tracked_target(1003.0, 0.9, 0.0);
  CHECK(amota(r, 40) == doctest::Approx(1.0));
}

TEST_CASE("MOT counts: a false track in two of four scans gives FP 2 and MOTA 1 - 2/4") {
  Run r = tracked_target(1003.0, 0.9, 0.0);
  r.track(1, 8, 5000.0, 0.3);
  r.track(2, 8, 5000.0, 0.3);
  const MotCounts c = counts(r, 0.0);
  CHECK(c.truths == 4);
  CHECK(c.tp == 4);
  CHECK(c.fp == 2);
  CHECK(c.fn == 0);
  CHECK(c.ids == 0);
  CHECK(c.mota() == doctest::Approx(0.5));
}

TEST_CASE("MOT counts: MOTAR charges false tracks and switches against true positives, not misses") {
  // 4 target-scans, 2 covered, one false track in scan 1: TP 2, FP 1, FN 2.
  // MOTA = 1 - (1 + 2) / 4; MOTAR = 1 - 1 / 2.
  Run r = half_covered_target();
  r.track(1, 8, 5000.0, 1.0);
  const MotCounts c = counts(r, 0.0);
  CHECK(c.mota() == doctest::Approx(0.25));
  CHECK(c.motar() == doctest::Approx(0.5));
}

TEST_CASE("AMOTA: a false track less confident than every true positive is thresholded away") {
  // TP scores {0.9 x 4}: every recall threshold sits at 0.9, above the false
  // track's 0.3, so MOTA_r = 1 for r = 1/4..1 although MOTA at 0 is 0.5.
  Run r = tracked_target(1003.0, 0.9, 0.0);
  r.track(1, 8, 5000.0, 0.3);
  r.track(2, 8, 5000.0, 0.3);
  CHECK(amota(r, 4) == doctest::Approx(1.0));
}

TEST_CASE("AMOTA: a recall the tracker never reaches contributes 0") {
  // 4 target-scans, covered in 2: recall 1/4 and 2/4 reach MOTAR 1 - 0/2;
  // 3/4 and 1 are unreached. AMOTA = (1 + 1 + 0 + 0) / 4.
  Run r = half_covered_target();
  CHECK(amota(r, 4) == doctest::Approx(0.5));
}

TEST_CASE("AMOTA unscaled: a recall the tracker never reaches contributes 0") {
  // As above with MOTA: recall 1/4 and 2/4 reach MOTA 1 - 2/4. (0.5 + 0.5) / 4.
  Run r = half_covered_target();
  CHECK(amota_unscaled(r, 4) == doctest::Approx(0.25));
}

TEST_CASE("AMOTA: a perfect tracker whose confidences differ scores 1") {
  // One track on its target every scan, existence 0.9, 0.8, 0.7, 0.6. The
  // threshold of recall r = i/4 keeps the i most confident scans: TP i, no FP,
  // no IDS, so MOTAR_r = 1 for every r.
  const Run r = tracked_target(1000.0, 1.0, 0.1);
  CHECK(amota(r, 4) == doctest::Approx(1.0));
}

TEST_CASE("AMOTA unscaled: a perfect tracker whose confidences differ is held to MOTA_r = r") {
  // The same run: at r = i/4 FN = 4 - i, so MOTA_r = i/4 and the unscaled
  // AMOTA is (1 + 2 + 3 + 4) / 16 = (L + 1) / 2L.
  const Run r = tracked_target(1000.0, 1.0, 0.1);
  CHECK(amota_unscaled(r, 4) == doctest::Approx(0.625));
}

TEST_CASE("AMOTA: more false tracks than true positives makes it negative") {
  // 2 target-scans, 2 TP and 4 FP at the only threshold: MOTAR = 1 - 4/2 = -1.
  Run r(2);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    r.target(k, 1, 1000.0);
    r.track(k, 7, 1000.0, 1.0);
    r.track(k, 8, 3000.0, 1.0);
    r.track(k, 9, 4000.0, 1.0);
  }
  CHECK(amota(r, 2) == doctest::Approx(-1.0));
}

TEST_CASE("MOT counts: a target handed from one track id to another is one identity switch") {
  Run r = half_covered_target();
  r.track(3, 8, 1000.0, 1.0);
  r.track(4, 8, 1000.0, 1.0);
  const MotCounts c = counts(r, 0.0);
  CHECK(c.ids == 1);
  CHECK(c.mota() == doctest::Approx(0.75));
}

TEST_CASE("AMOTA: the threshold of recall r keeps the ceil(r num_gt) most confident true positives") {
  // Target seen 4 scans; track 7 (existence 0.9) covers scans 1-2, track 8
  // (existence 0.4) scans 3-4. TP scores {0.9, 0.9, 0.4, 0.4}, L = 4:
  //   r = 1/4, 2/4: threshold 0.9 -> TP 2, FN 2, IDS 0: MOTA 0.5, MOTAR 1
  //   r = 3/4, 1:   threshold 0.4 -> TP 4, FN 0, IDS 1: MOTA 0.75, MOTAR 1 - 1/4
  // AMOTA = (1 + 1 + 0.75 + 0.75) / 4 = 0.875; unscaled (0.5 + 0.5 + 0.75 + 0.75) / 4.
  Run r(4);
  for (std::uint32_t k = 1; k <= 4; ++k) r.target(k, 1, 1000.0);
  r.track(1, 7, 1000.0, 0.9);
  r.track(2, 7, 1000.0, 0.9);
  r.track(3, 8, 1000.0, 0.4);
  r.track(4, 8, 1000.0, 0.4);
  CHECK(counts(r, 0.9).mota() == doctest::Approx(0.5));
  CHECK(counts(r, 0.4).mota() == doctest::Approx(0.75));
  CHECK(amota(r, 4) == doctest::Approx(0.875));
  CHECK(amota_unscaled(r, 4) == doctest::Approx(0.625));
}

TEST_CASE("AMOTA: tentative tracks are not scored") {
  Run r(2);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    r.target(k, 1, 1000.0);
    r.track(k, 7, 1000.0, 1.0, false);
  }
  CHECK(counts(r, 0.0).tp == 0);
  CHECK(amota(r, 40) == doctest::Approx(0.0));
}

TEST_CASE("AMOTA: a run without targets scores 0") {
  Run r(2);
  r.track(1, 7, 1000.0, 1.0);
  CHECK(amota(r, 40) == doctest::Approx(0.0));
}

TEST_CASE("AMOTA totals: each run's AMOTA is kept in run order, the mean is theirs") {
  TrackScoreTotals totals;
  RunTrackScore a, b;
  a.amota = 0.25;
  b.amota = 0.75;
  totals.add(a);
  totals.add(b);
  REQUIRE(totals.amota_per_run.size() == 2);
  CHECK(totals.amota_per_run[0] == 0.25);
  CHECK(totals.amota_per_run[1] == 0.75);
  CHECK(totals.amota() == doctest::Approx(0.5));
}
