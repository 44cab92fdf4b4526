// Scenario JSON: the shipped files are the built-in specs, round trips are
// exact, and every kind of bad input names the offending field.
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "mptrack/scenario/builtin.h"
#include "scenario_json.h"

using mptrack::scenario::ScenarioSpec;
using mptrack::sim::ScenarioError;
using json = nlohmann::ordered_json;

namespace {

ScenarioSpec builtin(const std::string& name) {
  ScenarioSpec s;
  REQUIRE(mptrack::scenario::builtin_scenario(name, s));
  return s;
}

std::string error_of(const json& doc) {
  try {
    (void)mptrack::sim::scenario_from_json(doc);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("sim json: every shipped scenario file loads to exactly the built-in spec") {
  for (const std::string& name : mptrack::scenario::builtin_scenario_names()) {
    CAPTURE(name);
    const ScenarioSpec file = mptrack::sim::load_scenario_file(std::string(MPTRACK_SCENARIO_DIR) + "/" + name + ".json");
    CHECK(file == builtin(name));
  }
}

TEST_CASE("sim json: to_json then from_json reproduces a spec exactly, and a change is seen") {
  ScenarioSpec s = builtin("seed000-s3");
  CHECK(mptrack::sim::scenario_from_json(mptrack::sim::scenario_to_json(s)) == s);
  ScenarioSpec t = s;
  t.clutter[2].variation.cov_scale_end = 1.3333333333333335;  // one ulp off
  CHECK_FALSE(t == s);
  CHECK(mptrack::sim::scenario_from_json(mptrack::sim::scenario_to_json(t)) == t);
}

TEST_CASE("sim json: a bad target SNR names the field") {
  json doc = mptrack::sim::scenario_to_json(builtin("seed000-s1"));
  doc["targets"][1]["snr"] = -2.0;
  CHECK(error_of(doc) == "targets[1].snr: expected a positive number");
  doc["targets"][1]["snr"] = "10/3";
  CHECK(error_of(doc) == "targets[1].snr: expected a positive number");
}

TEST_CASE("sim json: missing, unknown and mistyped fields are named") {
  const json good = mptrack::sim::scenario_to_json(builtin("seed000-s2"));
  json doc = good;
  doc["clutter"][2].erase("mean_count");
  CHECK(error_of(doc) == "clutter[2].mean_count: missing");
  doc = good;
  doc["targets"][0]["snrr"] = 3;
  CHECK(error_of(doc) == "targets[0].snrr: unknown field");
  doc = good;
  doc["targets"][0]["motion"][0]["type"] = "spiral";
  CHECK(error_of(doc) == "targets[0].motion[0].type: expected \"cv\", \"ca\", \"ct\" or \"set_velocity\"");
  doc = good;
  doc["region"]["range_m"] = json::array({10000.0});
  CHECK(error_of(doc) == "region.range_m: expected an array of 2 numbers");
  doc = good;
  doc["clutter"][1]["spread"]["sigma_azimuth_deg"] = 0.0;
  CHECK(error_of(doc) == "clutter[1].spread.sigma_azimuth_deg: expected a positive number");
  doc = good;
  doc["targets"][3]["swerling"] = 2;
  CHECK(error_of(doc) == "targets[3].swerling: expected 1 or 3");
  doc = good;
  doc["schema"] = "something-else";
  CHECK(error_of(doc) == "schema: expected \"mptrack-scenario/1\"");
}

TEST_CASE("sim json: semantic errors (lifetimes, duplicate ids) name the field") {
  json doc = mptrack::sim::scenario_to_json(builtin("seed000-s2"));
  doc["targets"][2]["lifetime"] = json::array({50, 20});
  CHECK(error_of(doc) == "targets[2].lifetime: expected [birth, death] with 1 <= birth <= death <= scans (340)");
  doc = mptrack::sim::scenario_to_json(builtin("seed000-s2"));
  doc["targets"][4]["id"] = 1;
  CHECK(error_of(doc) == "targets[4].id: duplicate id 1");
}

TEST_CASE("sim json: a file with a syntax error reports the file and JSON position") {
  const std::string path = "sim_json_test_bad.json";
  {
    std::ofstream f(path);
    f << "{ \"schema\": \"mptrack-scenario/1\", ";
  }
  std::string msg;
  try {
    (void)mptrack::sim::load_scenario_file(path);
  } catch (const ScenarioError& e) {
    msg = e.what();
  }
  CHECK(msg.rfind(path + ": invalid JSON", 0) == 0);
  std::remove(path.c_str());
}
