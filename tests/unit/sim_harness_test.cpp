// Harness pieces: per-scan metrics on hand-computed geometry, latency
// percentiles, CSV headers, and the whole pipeline (generate, track with the
// truth oracle, evaluate, write) on a small scenario.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "eval/scan_evaluator.h"
#include "mptrack/scenario/builtin.h"
#include "runner.h"
#include "tracker_registry.h"
#include "sim_test_truth.h"
#include "writers.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;
using sim_test::truth_at;

namespace {

TrackOut track(std::uint32_t id, double x, double y, bool confirmed, std::int32_t meas) {
  TrackOut t;
  t.id = id;
  t.px = x;
  t.py = y;
  t.confirmed = confirmed;
  t.measurement_index = meas;
  return t;
}

std::string first_line(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}

std::size_t line_count(const std::string& path) {
  std::ifstream f(path);
  std::size_t n = 0;
  std::string line;
  while (std::getline(f, line)) ++n;
  return n;
}

}  // namespace

TEST_CASE("sim metrics: OSPA, GOSPA, NFT and CAR on hand-computed geometry") {
  sc::SimScan scan;
  scan.scan = 7;
  scan.truth = {truth_at(1, 0.0, 0.0, 0), truth_at(2, 1000.0, 0.0, 1)};
  EstimateOut est;
  est.scan = 7;
  est.tracks = {track(10, 3.0, 4.0, true, 0),          // 5 m from truth 1, its measurement
                track(11, 5000.0, 5000.0, true, 1),    // far from everything: false track
                track(12, 1000.0, 1.0, false, 1)};     // tentative: ignored
  ScanEvaluator ev;
  const ScanMetrics m = ev.evaluate(scan, est);
  const double c = 631.0;
  CHECK(m.ospa == doctest::Approx(std::sqrt((25.0 + c * c) / 2.0)).epsilon(1e-12));
  CHECK(m.gospa == doctest::Approx(std::sqrt(25.0 + c * c)).epsilon(1e-12));
  CHECK(m.truths == 2);
  CHECK(m.confirmed == 2);
  CHECK(m.false_tracks == 1);
  CHECK(m.car_total == 2);    // both truths have a measurement
  CHECK(m.car_correct == 1);  // only truth 1's matched track picked its measurement

  // A matched track that picked another measurement is not a correct association.
  est.tracks = {track(10, 3.0, 4.0, true, 1)};
  const ScanMetrics w = ev.evaluate(scan, est);
  CHECK(w.car_correct == 0);
  CHECK(w.false_tracks == 0);
  CHECK(w.ospa == doctest::Approx(std::sqrt((25.0 + c * c) / 2.0)).epsilon(1e-12));

  // No truth, no track: OSPA 0.
  const ScanMetrics e = ev.evaluate(sc::SimScan{}, EstimateOut{});
  CHECK(e.ospa == 0.0);
  CHECK(e.car_total == 0);
}

TEST_CASE("sim identity CAR: a track keeps the label of its first match; coincident tracks keep theirs") {
  sc::SimScan scan;
  scan.scan = 1;
  scan.truth = {truth_at(1, 0.0, 0.0, 0), truth_at(2, 1000.0, 0.0, 1)};
  EstimateOut est;
  est.scan = 1;
  // Resolved: track 10 on target 1, track 11 on target 2, each on its own measurement.
  est.tracks = {track(10, 0.0, 0.0, true, 0), track(11, 1000.0, 0.0, true, 1)};
  ScanEvaluator ev;
  ev.begin_run();
  const ScanMetrics first = ev.evaluate(scan, est);
  CHECK(first.car_correct == 2);
  CHECK(first.car_id_correct == 2);

  // Later the targets coincide (unresolved) and so do the tracks, each still on
  // its own target's measurement. The per-scan OSPA assignment of two tracks at
  // one point is arbitrary; the labels are not.
  scan.scan = 2;
  scan.truth = {truth_at(1, 500.0, 0.0, 0), truth_at(2, 500.0, 0.0, 1)};
  est.tracks = {track(11, 500.0, 0.0, true, 1), track(10, 500.0, 0.0, true, 0)};
  const ScanMetrics same = ev.evaluate(scan, est);
  CHECK(same.car_id_correct == 2);

  // Swapped measurements: each track took the other target's.
  est.tracks = {track(11, 500.0, 0.0, true, 0), track(10, 500.0, 0.0, true, 1)};
  const ScanMetrics swapped = ev.evaluate(scan, est);
  CHECK(swapped.car_id_correct == 0);

  // A new run forgets the labels: the first match labels again.
  ev.begin_run();
  const ScanMetrics relabelled = ev.evaluate(scan, est);
  CHECK(relabelled.car_total == 2);
  CHECK(relabelled.car_id_correct == relabelled.car_correct);
}

TEST_CASE("sim latency: nearest-rank percentiles") {
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);
  const LatencyStats s = latency_stats(v);
  CHECK(s.p50_us == 50.0);
  CHECK(s.p99_us == 99.0);
  CHECK(s.max_us == 100.0);
  CHECK(s.mean_us == doctest::Approx(50.5));
  CHECK(s.count == 100);
  CHECK(latency_stats({}).count == 0);
}

TEST_CASE("sim csv: headers are exactly the documented columns") {
  CHECK(std::string(kTruthCsvHeader) == "run,scan,target_id,x,y,vx,vy,snr,eval");
  CHECK(std::string(kMeasurementsCsvHeader) == "run,scan,range,azimuth,amplitude,origin");
  CHECK(std::string(kTracksCsvHeader) == "run,scan,track_id,x,y,vx,vy,existence,snr,confirmed,eval");
  CHECK(origin_label(sc::Origin{sc::OriginKind::kTarget, 3}) == "target:3");
  CHECK(origin_label(sc::Origin{sc::OriginKind::kClutter, 0}) == "clutter:0");
}

TEST_CASE("sim pipeline: oracle on a clean one-target scenario gives noise-level OSPA, CAR 1, no false tracks") {
  sc::ScenarioSpec s;
  REQUIRE(sc::builtin_scenario("seed000-s1", s));
  s.name = "clean";
  s.num_scans = 20;
  s.eval_first_scan = 11;
  s.eval_last_scan = 20;
  s.targets.resize(1);
  s.targets[0].death_scan = 20;
  s.targets[0].snr = 1e6;  // Pd = exp(-0.51 / 1e6): always detected
  s.clutter.clear();
  s.sigma_range_m = 1.0;
  s.sigma_azimuth_deg = 0.001;
  RunConfig cfg;
  cfg.spec = s;
  cfg.tracker = "oracle";
  cfg.runs = 3;
  cfg.seed = 9;
  cfg.progress = false;
  cfg.out_dir = (std::filesystem::temp_directory_path() / "mptrack_sim_harness_test").string();
  std::filesystem::remove_all(cfg.out_dir);
  const Summary sum = run_monte_carlo(cfg);
  // Position error: sigma_r = 1 m, cross-range 0.001 deg * 16 km = 0.28 m.
  CHECK(sum.mean_ospa > 0.1);
  CHECK(sum.mean_ospa < 5.0);
  CHECK(sum.car == 1.0);
  CHECK(sum.car_total == 3 * 10);
  CHECK(sum.nft == 0.0);
  CHECK(sum.tracks_found_per_run == 1.0);
  CHECK(sum.latency.count == 3 * 20);
  CHECK(sum.ospa_per_scan.size() == 20);

  const std::string d = cfg.out_dir + "/";
  CHECK(first_line(d + "truth.csv") == kTruthCsvHeader);
  CHECK(first_line(d + "measurements.csv") == kMeasurementsCsvHeader);
  CHECK(first_line(d + "tracks.csv") == kTracksCsvHeader);
  CHECK(line_count(d + "truth.csv") == 1 + 3 * 20);
  CHECK(line_count(d + "measurements.csv") == 1 + 3 * 20);
  CHECK(line_count(d + "tracks.csv") == 1 + 3 * 20);
  CHECK(std::filesystem::exists(d + "plot.svg"));
  std::ifstream sj(d + "summary.json");
  const auto j = nlohmann::json::parse(sj);
  for (const char* key : {"mean_ospa", "mean_gospa", "car", "nft", "runs", "scans", "latency_us"}) {
    CAPTURE(key);
    CHECK(j.contains(key));
  }
  CHECK(j["runs"] == 3);
  CHECK(j["scans"] == 20);
  CHECK(j["latency_us"].contains("p50"));
  CHECK(j["latency_us"].contains("p99"));
  CHECK(j["latency_us"].contains("max"));
  // Scan 11 is the first evaluated one: its truth row carries eval = 1, scan 10's eval = 0.
  std::ifstream tf(d + "truth.csv");
  std::string line;
  std::getline(tf, line);
  int eval_rows = 0;
  while (std::getline(tf, line)) eval_rows += line.back() == '1' ? 1 : 0;
  CHECK(eval_rows == 3 * 10);
  std::filesystem::remove_all(cfg.out_dir);
}

TEST_CASE("sim pipeline: an unknown tracker is a clear error") {
  RunConfig cfg;
  REQUIRE(sc::builtin_scenario("seed000-s1", cfg.spec));
  cfg.tracker = "kalman9000";
  cfg.progress = false;
  std::string msg;
  try {
    (void)run_monte_carlo(cfg);
  } catch (const std::exception& e) {
    msg = e.what();
  }
  CHECK(msg == "unknown tracker 'kalman9000'");
}

TEST_CASE("sim tracker init: a refused parameter is named with the rule it broke") {
  // DefaultCaps::kMaxWindow = 7: window 100 is refused by MfbpTracker::validate.
  std::string error;
  auto trk = make_tracker("mfbp", error);
  REQUIRE(trk != nullptr);
  TrackerSetup setup;
  REQUIRE(sc::builtin_scenario("seed000-s1", setup.spec));
  setup.mfbp_params = {"window_length=100"};
  CHECK(trk->init(setup) == "mfbp.window_length = 100: must be <= 7 (Caps::kMaxWindow)");
  setup.mfbp_params = {"noise.range_std_m=-1"};
  CHECK(trk->init(setup) == "mfbp.noise.range_std_m = -1: must be in [0.001, 100000]");
  setup.mfbp_params = {"amplitude.use_amplitude=2"};
  CHECK(trk->init(setup) == "--mfbp-param amplitude.use_amplitude: expected 0 or 1, got '2'");
  setup.mfbp_params = {"process_noise_var=0.1"};  // the old name
  CHECK(trk->init(setup) == "--mfbp-param: unknown parameter 'process_noise_var' (see host-sim/README.md)");
  setup.mfbp_params = {};
  CHECK(trk->init(setup).empty());
}
