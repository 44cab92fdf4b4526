// Replay of recorded detections (replay/): the harness's own detections,
// written with --write-detections and read back (CSV and JSON), feed a
// tracker the same bits and give the same tracks bit for bit; malformed
// files are refused with file, line and column (CSV) or the JSON path.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mptrack/scenario/builtin.h"
#include "replay/detections_csv.h"
#include "replay/detections_json.h"
#include "replay/replay_source.h"
#include "run/truncate.h"
#include "runner.h"
#include "tracker_registry.h"

using namespace mptrack::sim;
namespace sc = mptrack::scenario;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("mptrack_replay_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

sc::ScenarioSpec small_spec() {
  sc::ScenarioSpec spec;
  REQUIRE(sc::builtin_scenario("seed000-s2", spec));
  truncate_scans(spec, 30);
  return spec;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The tracker's estimates of every scan `source` delivers (run 0).
RunRecord track(ScanSource& source, const sc::ScenarioSpec& spec, const std::string& tracker) {
  std::string error;
  auto t = make_tracker(tracker, error);
  REQUIRE(t != nullptr);
  TrackerSetup setup;
  setup.spec = spec;
  REQUIRE(t->init(setup).empty());
  source.begin_run(0);
  return run_tracker(source, *t, 0, nullptr);
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p;
}

std::string read_error(const fs::path& p) {
  try {
    (void)read_detections_csv(p.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string json_error(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  try {
    (void)read_detections_file(p.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("replay: --write-detections round-trips every detection bit for bit") {
  const sc::ScenarioSpec spec = small_spec();
  RunConfig cfg;
  cfg.spec = spec;
  cfg.tracker = "oracle";
  cfg.out_dir = (scratch() / "run").string();
  cfg.plot = false;
  cfg.progress = false;
  cfg.write_detections = true;
  (void)run_monte_carlo(cfg);
  const std::vector<sc::SimScan> replayed = read_detections_csv(cfg.out_dir + "/detections.csv");
  MeasurementSource gen(spec, cfg.seed, 1.0);
  gen.begin_run(0);
  REQUIRE(replayed.size() == gen.scans().size());
  for (std::size_t k = 0; k < replayed.size(); ++k) {
    const sc::SimScan& a = gen.scans()[k];
    const sc::SimScan& b = replayed[k];
    CHECK(a.time_us == b.time_us);
    REQUIRE(a.measurements.size() == b.measurements.size());
    for (std::size_t i = 0; i < a.measurements.size(); ++i) {
      CHECK(same_bits(a.measurements[i].range_m, b.measurements[i].range_m));
      CHECK(same_bits(a.measurements[i].azimuth_rad, b.measurements[i].azimuth_rad));
      CHECK(same_bits(a.measurements[i].amplitude, b.measurements[i].amplitude));
    }
  }
}

TEST_CASE("replay: mfbp on the replayed detections gives the run's tracks bit for bit") {
  const sc::ScenarioSpec spec = small_spec();
  MeasurementSource gen(spec, 1, 1.0);
  const RunRecord direct = track(gen, spec, "mfbp");
  const fs::path file = scratch() / "det.csv";
  write_detections_csv(file.string(), gen.scans());
  ReplaySource replay(spec, read_detections_csv(file.string()));
  const RunRecord replayed = track(replay, spec, "mfbp");
  REQUIRE(direct.by_scan.size() == replayed.by_scan.size());
  std::size_t tracks = 0;
  for (std::size_t k = 0; k < direct.by_scan.size(); ++k) {
    const auto& a = direct.by_scan[k].tracks;
    const auto& b = replayed.by_scan[k].tracks;
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(a[i].id == b[i].id);
      CHECK(a[i].confirmed == b[i].confirmed);
      CHECK(same_bits(a[i].px, b[i].px));
      CHECK(same_bits(a[i].py, b[i].py));
      CHECK(same_bits(a[i].vx, b[i].vx));
      CHECK(same_bits(a[i].vy, b[i].vy));
      CHECK(same_bits(a[i].existence, b[i].existence));
      ++tracks;
    }
  }
  CHECK(tracks > 30);  // the comparison saw real tracks
}

TEST_CASE("replay: the CLI outputs of a run and of its replay carry identical tracks.csv") {
  const sc::ScenarioSpec spec = small_spec();
  RunConfig run;
  run.spec = spec;
  run.tracker = "mfbp";
  run.out_dir = (scratch() / "cli_run").string();
  run.plot = false;
  run.progress = false;
  run.write_detections = true;
  (void)run_monte_carlo(run);
  RunConfig rep = run;
  rep.out_dir = (scratch() / "cli_replay").string();
  rep.write_detections = false;
  ReplaySource source(spec, read_detections_csv(run.out_dir + "/detections.csv"));
  (void)run_on_source(source, rep);
  const std::string a = slurp(fs::path(run.out_dir) / "tracks.csv");
  CHECK(a.size() > 1000);
  CHECK(a == slurp(fs::path(rep.out_dir) / "tracks.csv"));
}

TEST_CASE("replay: degrees or radians as the header says; empty scans kept") {
  const fs::path p = write_file("deg.csv", "time_s,range_m,azimuth_deg,amplitude\n1.25,1000,90,2\n2.5,,,\n3.75,2000,-45,3\n");
  const auto scans = read_detections_csv(p.string());
  REQUIRE(scans.size() == 3);
  CHECK(scans[0].time_us == 1250000);
  CHECK(scans[0].measurements[0].azimuth_rad == doctest::Approx(1.5707963267948966));
  CHECK(scans[1].measurements.empty());
  CHECK(scans[2].scan == 3);
}

TEST_CASE("replay: malformed files name line and column, nothing accepted silently") {
  CHECK(read_error(write_file("h.csv", "t,r,a,amp\n1,2,3,4\n")).find("h.csv:1: expected the header") != std::string::npos);
  CHECK(read_error(write_file("n.csv", "time_s,range_m,azimuth_rad,amplitude\n1,100,0.1,2\n2,abc,0.1,2\n"))
            .find("n.csv:3: column 2 (range_m): 'abc' is not a number") != std::string::npos);
  CHECK(read_error(write_file("c.csv", "time_s,range_m,azimuth_rad,amplitude\n1,100,0.1\n"))
            .find("c.csv:2: expected 4 columns, got 3") != std::string::npos);
  CHECK(read_error(write_file("o.csv", "time_s,range_m,azimuth_rad,amplitude\n2,100,0.1,2\n1,100,0.1,2\n"))
            .find("o.csv:3: column 1 (time_s): times must not decrease") != std::string::npos);
  CHECK(read_error(write_file("a.csv", "time_s,range_m,azimuth_rad,amplitude\n1,100,0.1,0\n"))
            .find("a.csv:2: column 4 (amplitude): must be > 0") != std::string::npos);
  CHECK(read_error(write_file("z.csv", "time_s,range_m,azimuth_deg,amplitude\n1,100,200,1\n"))
            .find("z.csv:2: column 3 (azimuth_deg)") != std::string::npos);
  CHECK(read_error(write_file("f.csv", "time_s,range_m,azimuth_rad,amplitude\n1,inf,0.1,1\n"))
            .find("column 2 (range_m): 'inf' is not finite") != std::string::npos);
}

TEST_CASE("replay json: --write-detections writes detections.json with the CSV's content, bit for bit") {
  sc::ScenarioSpec spec;
  REQUIRE(sc::builtin_scenario("seed000-s2", spec));
  truncate_scans(spec, 30);
  RunConfig run;
  run.spec = spec;
  run.tracker = "mfbp";
  run.out_dir = (scratch() / "run").string();
  run.plot = false;
  run.progress = false;
  run.write_detections = true;
  (void)run_monte_carlo(run);
  const auto csv = read_detections_csv(run.out_dir + "/detections.csv");
  const auto js = read_detections_file(run.out_dir + "/detections.json");
  REQUIRE(csv.size() == js.size());
  std::size_t n = 0;
  for (std::size_t k = 0; k < csv.size(); ++k) {
    CHECK(csv[k].time_us == js[k].time_us);
    CHECK(csv[k].scan == js[k].scan);
    REQUIRE(csv[k].measurements.size() == js[k].measurements.size());
    for (std::size_t i = 0; i < csv[k].measurements.size(); ++i, ++n) {
      CHECK(same_bits(csv[k].measurements[i].range_m, js[k].measurements[i].range_m));
      CHECK(same_bits(csv[k].measurements[i].azimuth_rad, js[k].measurements[i].azimuth_rad));
      CHECK(same_bits(csv[k].measurements[i].amplitude, js[k].measurements[i].amplitude));
    }
  }
  CHECK(n > 100);
  // The replay of the JSON gives the run's tracks.csv byte for byte.
  RunConfig rep = run;
  rep.out_dir = (scratch() / "replay").string();
  rep.write_detections = false;
  ReplaySource source(spec, js);
  (void)run_on_source(source, rep);
  const std::string a = slurp(fs::path(run.out_dir) / "tracks.csv");
  CHECK(a.size() > 1000);
  CHECK(a == slurp(fs::path(rep.out_dir) / "tracks.csv"));
}

TEST_CASE("replay json: degrees, an empty scan, equal times merge") {
  const fs::path p = scratch() / "ok.json";
  std::ofstream(p) << R"({"schema": "mptrack-detections/1", "scans": [
    {"time_s": 1.25, "detections": [{"range_m": 1000, "azimuth_deg": 90, "amplitude": 2}]},
    {"time_s": 2.5, "detections": []},
    {"time_s": 2.5, "detections": [{"range_m": 2000, "azimuth_rad": -0.5, "amplitude": 3}]}]})";
  const auto scans = read_detections_file(p.string());
  REQUIRE(scans.size() == 2);
  CHECK(scans[0].time_us == 1250000);
  CHECK(scans[0].measurements[0].azimuth_rad == doctest::Approx(1.5707963267948966));
  REQUIRE(scans[1].measurements.size() == 1);
  CHECK(scans[1].measurements[0].azimuth_rad == -0.5);
}

TEST_CASE("replay json: malformed files name the field's JSON path") {
  const std::string head = R"({"schema": "mptrack-detections/1", "scans": [)";
  CHECK(json_error("s.json", R"({"schema": "x", "scans": []})").find("s.json: schema: expected") != std::string::npos);
  CHECK(json_error("a.json", head + R"({"time_s": 1, "detections": [{"range_m": 1, "azimuth_rad": 0, "amplitude": 0}]}]})")
            .find("a.json: scans[0].detections[0].amplitude: must be > 0") != std::string::npos);
  CHECK(json_error("t.json", head + R"({"time_s": 2, "detections": []}, {"time_s": 1, "detections": []}]})")
            .find("scans[1].time_s: times must not decrease") != std::string::npos);
  CHECK(json_error("b.json", head + R"({"time_s": 1, "detections": [{"range_m": 1, "amplitude": 1}]}]})")
            .find("scans[0].detections[0]: expected exactly one of azimuth_rad and azimuth_deg") != std::string::npos);
  CHECK(json_error("u.json", head + R"({"time_s": 1, "detections": [], "gain": 2}]})")
            .find("scans[0].gain: unknown field") != std::string::npos);
  CHECK(json_error("r.json", head + R"({"time_s": 1, "detections": [{"range_m": "far", "azimuth_rad": 0, "amplitude": 1}]}]})")
            .find("scans[0].detections[0].range_m: expected a number") != std::string::npos);
  CHECK(json_error("p.json", "{not json").find("p.json: ") != std::string::npos);
}

TEST_CASE("replay: cleanup") { fs::remove_all(scratch()); }
