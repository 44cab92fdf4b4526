// Replay of recorded detections in JSON (replay/detections_json.h): the same
// content as the CSV, bit for bit, and every malformed field named by its
// JSON path.
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

using namespace mptrack::sim;
namespace sc = mptrack::scenario;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("mptrack_replay_json_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

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

TEST_CASE("replay json: cleanup") { fs::remove_all(scratch()); }
