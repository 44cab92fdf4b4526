// mptrack-sim refuses bad input: one TEST_CASE per bad-input class of
// issue 17, each run as a user would (the binary, a fresh output
// directory). Each must exit non-zero within seconds, name the flag or
// field (and its limit) on stderr, and leave no output directory behind.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "param_error_text.h"

namespace fs = std::filesystem;

namespace {

struct CliResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
  double seconds = 0.0;
};

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("mptrack_cli_input_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

/// Runs mptrack-sim with `args` (20 s at most), output into out_dir.
CliResult run_sim(const std::string& args, const fs::path& out_dir) {
  const std::string cmd = "timeout 20 " + std::string(MPTRACK_SIM_EXE) + " " + args + " --no-progress --out " +
                          out_dir.string() + " 2>&1";
  const auto t0 = std::chrono::steady_clock::now();
  FILE* p = ::popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  CliResult r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int status = ::pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// A 20-scan copy of seed000-s2 with `edit` applied, written to dir/name.json.
template <class Edit>
fs::path scenario_file(const fs::path& dir, const std::string& name, Edit edit) {
  std::ifstream in(std::string(MPTRACK_SCENARIO_DIR) + "/seed000-s2.json");
  nlohmann::json s = nlohmann::json::parse(in);
  s["scans"] = 20;
  s["evaluation"] = {{"first_scan", 1}, {"last_scan", 20}};
  for (auto& t : s["targets"]) {
    t["lifetime"] = {1, 20};
    t.erase("motion");
  }
  for (auto& c : s["clutter"]) c["lifetime"] = {1, 20};
  edit(s);
  const fs::path f = dir / (name + ".json");
  std::ofstream(f) << s.dump(1);
  return f;
}

/// The refusal contract: non-zero exit, quick, every `needles` on the
/// output, no output directory.
void expect_refused(const std::string& args, std::initializer_list<const char*> needles) {
  const fs::path out = scratch() / "out";
  fs::remove_all(out);
  const CliResult r = run_sim(args, out);
  INFO("args: " << args << "\noutput: " << r.output);
  CHECK(r.exit_code != 0);
  CHECK(r.exit_code != 124);  // not the timeout
  CHECK(r.seconds < 10.0);
  for (const char* n : needles) CHECK(r.output.find(n) != std::string::npos);
  CHECK(r.output.size() < 2000);  // a message, not 300 digits
  CHECK_FALSE(fs::exists(out));
  // No staging directory left next to it either.
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    CHECK(e.path().filename().string().find(".partial") == std::string::npos);
  }
}

}  // namespace

TEST_CASE("describe_param_error: field, value, bounds and the cap's name") {
  mptrack::ParamError e;
  e.field = "window_length";
  e.rule = "check_at_most(p.window_length, kMaxWindow)";
  e.result = mptrack::check_at_most(std::size_t{100}, std::size_t{7}, "Caps::kMaxWindow");
  CHECK(mptrack::sim::describe_param_error("mfbp", e) == "mfbp.window_length = 100: must be <= 7 (Caps::kMaxWindow)");
  e.field = "p_survive";
  e.result = mptrack::check_open_probability(2.0);
  CHECK(mptrack::sim::describe_param_error("", e) == "p_survive = 2: must be in (0, 1)");
  e.result = mptrack::check(false);
  CHECK(mptrack::sim::describe_param_error("mfbp", e) ==
        "mfbp.p_survive: must satisfy check_at_most(p.window_length, kMaxWindow)");
}

TEST_CASE("cli: a good run exits 0 and writes its directory (the contract below is not vacuous)") {
  const fs::path out = scratch() / "good";
  fs::remove_all(out);
  const CliResult r = run_sim("--scenario seed000-s2 --scans 5 --runs 1 --no-plot", out);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(out / "summary.json"));
  CHECK(fs::exists(out / "tracks.csv"));
}

TEST_CASE("cli: a huge clutter mean is refused with the figure, not sampled forever") {
  const fs::path f = scenario_file(scratch(), "clutter_huge", [](nlohmann::json& s) { s["clutter"][0]["mean_count"] = 1e308; });
  expect_refused("--scenario-file " + f.string(), {"clutter[0].mean_count = 1e+308", "1e+06"});
  expect_refused("--scenario seed000-s2 --scans 5 --clutter-scale 1e308", {"--clutter-scale", "1e308", "1e+06"});
}

TEST_CASE("cli: expected measurements per scan far above the caps are refused with the figure") {
  const fs::path f = scenario_file(scratch(), "clutter_1e5", [](nlohmann::json& s) { s["clutter"][0]["mean_count"] = 1e5; });
  expect_refused("--scenario-file " + f.string(), {"measurements per scan", "10240"});
}

TEST_CASE("cli: an output estimated above the limit is refused unless --force") {
  expect_refused("--scenario seed000-s2 --runs 4294967295 --scans 1", {"--runs 4294967295", "GB", "--force"});
}

TEST_CASE("cli: --runs 0 names the flag and its range in a short message") {
  expect_refused("--scenario seed000-s2 --runs 0", {"--runs", "0", "[1, 4294967295]"});
}

TEST_CASE("cli: --mfbp-param values out of type or range are refused, naming the field") {
  expect_refused("--scenario seed000-s2 --scans 5 --mfbp-param use_amplitude=2", {"amplitude.use_amplitude"});
  expect_refused("--scenario seed000-s2 --scans 5 --mfbp-param amplitude.use_amplitude=2", {"expected 0 or 1"});
  expect_refused("--scenario seed000-s2 --scans 5 --mfbp-param window_length=100",
                 {"mfbp.window_length = 100: must be <= 7 (Caps::kMaxWindow)"});
  expect_refused("--scenario seed000-s2 --scans 5 --mfbp-param p_survive=2", {"mfbp.p_survive = 2: must be in (0, 1)"});
  expect_refused("--scenario seed000-s2 --scans 5 --mfbp-param window_length=2.5", {"window_length = 2.5", "integer"});
}

TEST_CASE("cli: compare --ospa-c 0 / nan and --ospa-p 0 are refused, not replaced by defaults") {
  const std::string base = "compare --scenario seed000-s2 --scans 3 --runs 1 --trackers gnn";
  expect_refused(base + " --ospa-c 0", {"--ospa-c", "(0, 1e+09]"});
  expect_refused(base + " --ospa-c nan", {"--ospa-c", "finite"});
  expect_refused(base + " --ospa-p 0", {"--ospa-p", "[1, 64]"});
}

TEST_CASE("cli: --rate and --frames on a measurement-level scenario are refused") {
  expect_refused("--scenario seed000-s2 --scans 3 --rate 10", {"--rate", "raw-ADC", "--scans"});
  expect_refused("--scenario seed000-s2 --scans 3 --frames 10", {"--frames", "raw-ADC"});
}

TEST_CASE("cli: raw-ADC-only flags on measurement-level scenarios and the reverse are refused") {
  expect_refused("--scenario seed000-s2 --scans 3 --adc-format int16", {"--adc-format", "raw-ADC"});
  expect_refused("--scenario seed000-s2 --scans 3 --saturation-policy drop", {"--saturation-policy", "raw-ADC"});
  expect_refused("--scenario seed004-drones --frames 3 --write-detections", {"--write-detections", "measurement-level"});
}

TEST_CASE("cli: scenario values out of range name the field and the bounds") {
  const fs::path d = scratch();
  expect_refused("--scenario-file " + scenario_file(d, "p1", [](nlohmann::json& s) { s["scan_period_s"] = 1e-320; }).string(),
                 {"scan_period_s = ", "[0.0001, 3600]"});
  expect_refused("--scenario-file " + scenario_file(d, "p2", [](nlohmann::json& s) { s["scan_period_s"] = 1e308; }).string(),
                 {"scan_period_s = 1e+308", "[0.0001, 3600]"});
  expect_refused("--scenario-file " +
                     scenario_file(d, "s", [](nlohmann::json& s) { s["measurement_noise"]["sigma_range_m"] = 1e308; }).string(),
                 {"measurement_noise.sigma_range_m = 1e+308", "(0, 100000] m"});
  expect_refused("--scenario-file " + scenario_file(d, "t", [](nlohmann::json& s) { s["threshold"] = 1e308; }).string(),
                 {"threshold = 1e+308", "(0, 1000]"});
  expect_refused("--scenario-file " +
                     scenario_file(d, "v", [](nlohmann::json& s) { s["targets"][0]["initial_state"][1] = 1e308; }).string(),
                 {"targets[0].initial_state[1] = 1e+308", "m/s"});
}

TEST_CASE("cli: a target never inside the surveillance region is refused, not scored") {
  const fs::path f = scenario_file(scratch(), "outside", [](nlohmann::json& s) {
    s["targets"][0]["initial_state"] = {-90000.0, 40.0, -90000.0, -40.0};
  });
  expect_refused("--scenario-file " + f.string() + " --tracker oracle", {"targets[0] (id 1)", "never inside"});
}

TEST_CASE("cli: more clutter components than mfbp-kce's known map holds are refused, naming the cap") {
  const fs::path f = scenario_file(scratch(), "nine", [](nlohmann::json& s) {
    nlohmann::json g;
    for (const auto& c : s["clutter"]) {
      if (c["type"] == "gaussian") g = c;
    }
    for (int i = 0; i < 9; ++i) {
      g["id"] = 10 + i;
      s["clutter"].push_back(g);
    }
  });
  expect_refused("--scenario-file " + f.string() + " --tracker mfbp-kce",
                 {"mfbp.known_clutter.num_components = 12", "kMaxKnownClutterComponents"});
}

TEST_CASE("cli: gnn and mfbp refuse seed 001's Cartesian scenarios instead of running with every detection invalid") {
  // Before: both ran to the end with measurements_invalid = every detection
  // and OSPA = c on every scan, with no message.
  expect_refused("--scenario seed001-s1 --tracker gnn --runs 1", {"gnn models polar", "\"cartesian\"", "gmphd"});
  expect_refused("--scenario seed001-s1 --tracker mfbp-filter --runs 1", {"mfbp-filter models polar", "cbmember"});
}

TEST_CASE("cli: a top-level option a subcommand does not read is refused, not silently dropped") {
  // compare has its own --scenario (a name or a file); the default command's
  // --scenario-file reached it through the fallthrough and compare ran
  // seed000-s2 instead of the user's file.
  const fs::path f = scenario_file(scratch(), "plain", [](nlohmann::json&) {});
  expect_refused("compare --scenario-file " + f.string() + " --runs 1 --trackers gnn",
                 {"--scenario-file is not an option of `compare`", "--scenario takes"});
  expect_refused("table5 --runs 1 --tracker gnn", {"--tracker is not an option of `table5`"});
}

TEST_CASE("cli: compare reads a scenario file through --scenario") {
  const fs::path f = scenario_file(scratch(), "named", [](nlohmann::json& s) { s["name"] = "my-own-scene"; });
  const fs::path out = scratch() / "cmp";
  fs::remove_all(out);
  const CliResult r = run_sim("compare --scenario " + f.string() + " --runs 1 --trackers gnn --no-plot", out);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(out / "compare.json");
  CHECK(nlohmann::json::parse(in)["scenario"] == "my-own-scene");
}

TEST_CASE("cli: cleanup") { fs::remove_all(scratch()); }
