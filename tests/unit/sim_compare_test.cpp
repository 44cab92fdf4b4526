// `mptrack-sim compare`: one row per tracker with the documented keys, the
// same measurements for every tracker (checksum against an independent
// regeneration), metrics that agree with the single-tracker runner, and the
// option parsing.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "compare.h"
#include "mptrack/adc/adc_json.h"
#include "stream/adc_compare.h"
#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"
#include "runner.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;

namespace {

sc::ScenarioSpec builtin(const std::string& name, std::uint32_t scans) {
  sc::ScenarioSpec s;
  REQUIRE(sc::builtin_scenario(name, s));
  s.num_scans = scans;
  s.eval_first_scan = 1;
  s.eval_last_scan = scans;
  std::vector<sc::TargetSpec> targets;
  for (auto t : s.targets) {
    if (t.birth_scan > scans) continue;
    t.death_scan = std::min(t.death_scan, scans);
    targets.push_back(t);
  }
  s.targets = targets;
  std::vector<sc::ClutterSpec> clutter;
  for (auto c : s.clutter) {
    if (c.birth_scan > scans) continue;
    c.death_scan = std::min(c.death_scan, scans);
    clutter.push_back(c);
  }
  s.clutter = clutter;
  return s;
}

}  // namespace

TEST_CASE("compare: a tiny seed001 run gives one row per tracker, in order, with the expected JSON keys") {
  CompareConfig cfg;
  cfg.spec = builtin("seed001-s1", 6);
  cfg.trackers = {"oracle", "gmphd", "gmphd-known", "cbmember"};
  cfg.runs = 2;
  cfg.progress = false;
  cfg.out_dir = (std::filesystem::temp_directory_path() / "mptrack_sim_compare_test").string();
  std::filesystem::remove_all(cfg.out_dir);
  const CompareResult r = run_compare(cfg);
  REQUIRE(r.rows.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) CHECK(r.rows[i].tracker == cfg.trackers[i]);
  CHECK(r.ospa_order == 1.0);       // seed 001 Sec. 5
  CHECK(r.ospa_cutoff_m == 300.0);

  std::ifstream in(cfg.out_dir + "/compare.json");
  REQUIRE(in);
  const auto doc = nlohmann::ordered_json::parse(in);
  CHECK(doc["scenario"] == "seed001-s1");
  CHECK(doc["runs"] == 2);
  REQUIRE(doc["rows"].size() == 4);
  for (const auto& row : doc["rows"]) {
    for (const char* key : {"tracker", "mean_ospa", "mean_gospa", "gospa_localisation", "gospa_missed",
                            "gospa_false", "cardinality_error", "nft", "latency_us", "measurement_checksum",
                            "track_scores", "ospa_per_scan"}) {
      CAPTURE(key);
      CHECK(row.contains(key));
    }
    for (const char* key : {"amota", "ids", "frag", "rmse_range_m", "rmse_velocity_mps", "mospa_mahalanobis",
                            "mospa"}) {
      CAPTURE(key);
      CHECK(row["seed003_metrics"].contains(key));
    }
    CHECK(row["latency_us"].contains("p50"));
    CHECK(row["latency_us"].contains("p99"));
    CHECK(row["latency_us"].contains("max"));
    CHECK(row["latency_us"]["samples"] == 12);  // 2 runs x 6 scans
    CHECK(row["ospa_per_scan"].size() == 6);
  }
  // Each of the four markdown tables (metrics, track scores, track scores per target (<= 8 targets), seed 003
  // metrics) has exactly one line per tracker;
  // the paired-difference table has one per tracker after the first (the reference).
  std::ifstream md(cfg.out_dir + "/compare.md");
  std::string line;
  int rows = 0;
  while (std::getline(md, line)) {
    for (const auto& t : cfg.trackers) rows += line.rfind("| " + t + " |", 0) == 0 ? 1 : 0;
  }
  CHECK(rows == 4 * 4 + (4 - 1));
  CHECK(std::filesystem::exists(cfg.out_dir + "/ospa.svg"));
}

TEST_CASE("compare: every tracker is fed the same measurements (checksum equals an independent regeneration)") {
  CompareConfig cfg;
  cfg.spec = builtin("seed001-s2", 5);
  cfg.trackers = {"gmcphd", "cbmember-known", "oracle"};
  cfg.runs = 3;
  cfg.seed = 42;
  cfg.progress = false;
  const CompareResult r = run_compare(cfg);
  std::uint64_t h = kChecksumSeed;
  for (std::uint32_t run = 0; run < 3; ++run) {
    sc::Generator gen;
    REQUIRE(gen.init(cfg.spec, 42, run) == mptrack::Status::kOk);
    for (std::uint32_t k = 1; k <= 5; ++k) {
      sc::SimScan s;
      REQUIRE(gen.generate(k, s) == mptrack::Status::kOk);
      h = measurement_checksum(s, h);
    }
  }
  REQUIRE(r.rows.size() == 3);
  for (const CompareRow& row : r.rows) CHECK(row.measurement_checksum == h);
  // A different seed gives different measurements, so the checksum can fail.
  cfg.seed = 43;
  CHECK(run_compare(cfg).rows[0].measurement_checksum != h);
}

TEST_CASE("compare: OSPA, NFT and GOSPA of a tracker match the single-tracker runner (seed 000 metric)") {
  CompareConfig cfg;
  cfg.spec = builtin("seed000-s2", 8);
  cfg.trackers = {"oracle"};
  cfg.runs = 2;
  cfg.progress = false;
  const CompareResult r = run_compare(cfg);
  RunConfig rc;
  rc.spec = cfg.spec;
  rc.tracker = "oracle";
  rc.runs = 2;
  rc.progress = false;
  const Summary s = run_monte_carlo(rc);
  REQUIRE(r.rows.size() == 1);
  CHECK(r.ospa_order == 2.0);
  CHECK(r.ospa_cutoff_m == 631.0);
  CHECK(r.rows[0].mean_ospa == doctest::Approx(s.mean_ospa).epsilon(1e-12));
  CHECK(r.rows[0].mean_gospa == doctest::Approx(s.mean_gospa).epsilon(1e-12));
  CHECK(r.rows[0].nft == doctest::Approx(s.nft));
  CHECK(r.rows[0].mean_confirmed_tracks == doctest::Approx(s.mean_confirmed_tracks));
  CHECK(r.mean_truths == doctest::Approx(s.mean_truths));
  // Cardinality error by hand: the oracle reports exactly the detected in-region targets.
  CHECK(r.rows[0].cardinality_error == doctest::Approx(s.mean_truths - s.mean_confirmed_tracks));
}

TEST_CASE("compare: GOSPA components are c^p/2 per missed truth and add up to GOSPA^p") {
  CompareConfig cfg;
  cfg.spec = builtin("seed001-s1", 4);
  cfg.trackers = {"oracle"};
  cfg.runs = 1;
  cfg.progress = false;
  const CompareResult r = run_compare(cfg);
  const CompareRow& row = r.rows[0];
  CHECK(row.gospa_missed == doctest::Approx(150.0 * row.missed_per_scan));  // c^p / 2 = 300 / 2
  CHECK(row.gospa_false == doctest::Approx(150.0 * row.false_per_scan));
  // p = 1: GOSPA is the sum of the components, scan by scan, so the means add too.
  CHECK(row.mean_gospa == doctest::Approx(row.gospa_localisation + row.gospa_missed + row.gospa_false));
}

TEST_CASE("compare: tracker lists, defaults and errors") {
  CHECK(parse_tracker_list("gmphd,gmcphd-known,mfbp") ==
        std::vector<std::string>{"gmphd", "gmcphd-known", "mfbp"});
  CHECK_THROWS_AS(parse_tracker_list("gmphd,,mfbp"), std::runtime_error);
  CHECK_THROWS_AS(parse_tracker_list(""), std::runtime_error);
  sc::ScenarioSpec cart = builtin("seed001-s4", 50);
  for (const std::string& n : default_compare_trackers(cart)) CHECK(n.rfind("mfbp", 0) != 0);
  double c = 0.0, p = 0.0;
  default_ospa(cart, c, p);
  CHECK(c == 300.0);
  CHECK(p == 1.0);
  CompareConfig cfg;
  cfg.spec = cart;
  cfg.trackers = {"no-such-tracker"};
  cfg.progress = false;
  CHECK_THROWS_AS(run_compare(cfg), std::runtime_error);
}

TEST_CASE("compare on raw ADC: every pipeline sees the same frames and agrees with the single-tracker runner") {
  AdcRunConfig cfg;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", cfg.scenario));
  cfg.frames = 12;
  cfg.runs = 2;
  cfg.progress = false;
  cfg.plot = false;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mptrack_adc_compare_test";
  std::filesystem::remove_all(dir);
  cfg.out_dir = dir.string();
  const std::vector<AdcSummary> rows = run_adc_compare(cfg, {"gnn", "mfbp-filter"});
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].base.tracker == "gnn");
  CHECK(rows[1].base.tracker == "mfbp-filter");
  // Both consumed the front end's detections of the same frames.
  CHECK(rows[0].base.measurement_checksum == rows[1].base.measurement_checksum);
  AdcRunConfig one = cfg;
  one.tracker = "mfbp-filter";
  one.out_dir.clear();
  const AdcSummary single = run_adc_monte_carlo(one);
  CHECK(rows[1].base.mean_ospa == doctest::Approx(single.base.mean_ospa).epsilon(1e-12));
  CHECK(rows[1].base.measurement_checksum == single.base.measurement_checksum);
  // Detection statistics are per tracker: the same as the single-tracker run's.
  CHECK(rows[1].drone_detection_rate == doctest::Approx(single.drone_detection_rate).epsilon(1e-12));
  CHECK(rows[1].ring.frames_processed == single.ring.frames_processed);
  // frames.csv: a header and one row per (tracker, frame).
  std::ifstream f(dir / "frames.csv");
  std::string line;
  std::size_t n = 0;
  while (std::getline(f, line)) ++n;
  CHECK(n == 1 + 2 * 12);
  CHECK(std::filesystem::exists(dir / "compare.md"));
  CHECK(std::filesystem::exists(dir / "rmse.csv"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("compare on raw ADC: vmp consumes the frame itself, sbl-gnn the SBL detector's detections") {
  AdcRunConfig cfg;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", cfg.scenario));
  cfg.frames = 6;
  cfg.runs = 1;
  cfg.progress = false;
  cfg.plot = false;
  const std::vector<AdcSummary> rows = run_adc_compare(cfg, {"vmp", "sbl-gnn", "gnn"});
  REQUIRE(rows.size() == 3);
  // No detection reaches the raw-frame tracker: its checksum is the empty chain's.
  CHECK(rows[0].base.measurement_checksum == kChecksumSeed);
  CHECK(rows[0].base.mean_measurements == 0.0);
  CHECK(rows[0].stages.frontend.max_us == 0.0);
  CHECK(rows[0].base.counters.scans == 6);
  CHECK(rows[0].drone_detection_rate == 0.0);  // no detector in its pipeline
  CHECK(rows[2].drone_detection_rate > 0.0);
  // The two detectors give different detections of the same frames.
  CHECK(rows[1].base.mean_measurements > 0.0);
  CHECK(rows[1].base.measurement_checksum != rows[2].base.measurement_checksum);
}

TEST_CASE("compare: the raw-frame trackers refuse a measurement-level scenario with a message") {
  CompareConfig cfg;
  cfg.spec = builtin("seed000-s2", 3);
  cfg.progress = false;
  cfg.trackers = {"vmp"};
  CHECK_THROWS_WITH_AS(run_compare(cfg), doctest::Contains("raw ADC"), std::runtime_error);
  cfg.trackers = {"sbl-gnn"};
  CHECK_THROWS_WITH_AS(run_compare(cfg), doctest::Contains("raw-ADC scenario"), std::runtime_error);
}
