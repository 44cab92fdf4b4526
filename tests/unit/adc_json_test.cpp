// Raw-ADC scenario JSON: shipped files equal the built-ins, round trip, and
// every loading error names the field.
#include <doctest/doctest.h>

#include <string>

#include "mptrack/adc/adc_json.h"
#include "mptrack/adc/adc_scenario.h"

namespace adc = mptrack::adc;
using json = nlohmann::ordered_json;

namespace {

std::string error_of(const json& doc) {
  try {
    (void)adc::adc_scenario_from_json(doc);
  } catch (const adc::AdcScenarioError& e) {
    return e.what();
  }
  return "";
}

json builtin_json(const char* name) {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario(name, s));
  return adc::adc_scenario_to_json(s);
}

}  // namespace

TEST_CASE("adc json: the shipped scenario files load to exactly the built-ins") {
  for (const std::string name : {"seed004-drones", "mimo-interference", "strong-target"}) {
    adc::AdcScenario builtin;
    REQUIRE(adc::builtin_adc_scenario(name, builtin));
    const std::string path = std::string(MPTRACK_SCENARIO_DIR) + "/" + name + ".json";
    CHECK(adc::is_adc_scenario_file(path));
    const adc::AdcScenario file = adc::load_adc_scenario_file(path);
    CHECK(file == builtin);
  }
  CHECK_FALSE(adc::is_adc_scenario_file(std::string(MPTRACK_SCENARIO_DIR) + "/seed000-s2.json"));
}

TEST_CASE("adc json: to_json / from_json round trip is exact") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("mimo-interference", s));
  s.radar.noise_model = adc::NoiseModel::kLiteral;
  s.drones[1].mean_rcs_m2 = 0.1 / 3.0;  // not a short decimal
  CHECK(adc::adc_scenario_from_json(adc::adc_scenario_to_json(s)) == s);
}

TEST_CASE("adc json: errors name the offending field") {
  json d = builtin_json("seed004-drones");
  d["drones"][1]["legs"][0]["steps"] = 0;
  CHECK(error_of(d) == "drones[1].legs[0].steps: expected a positive integer");

  d = builtin_json("seed004-drones");
  d["drones"][0]["colour"] = "red";
  CHECK(error_of(d) == "drones[0].colour: unknown field");

  d = builtin_json("seed004-drones");
  d["radar"]["carrier_hz"] = "10 GHz";
  CHECK(error_of(d) == "radar.carrier_hz: expected a number");

  d = builtin_json("seed004-drones");
  d["radar"]["noise_model"] = "kTB";
  CHECK(error_of(d) == "radar.noise_model: expected \"model_a\" or \"literal\"");

  d = builtin_json("seed004-drones");
  d["drones"][2]["death_frame"] = 101;
  CHECK(error_of(d) == "drones[2].death_frame: expected birth_frame..num_frames");

  d = builtin_json("mimo-interference");
  d["jammers"][0].erase("jnr_db");
  CHECK(error_of(d) == "jammers[0].jnr_db: missing");

  d = builtin_json("mimo-interference");
  d["clutter_patches"][0]["range_m"] = json::array({60.0});
  CHECK(error_of(d) == "clutter_patches[0].range_m: expected an array of 2 numbers");

  d = builtin_json("seed004-drones");
  d["schema"] = "mptrack-scenario/1";
  CHECK(error_of(d) == "schema: expected \"mptrack-adc-scenario/1\"");

  d = builtin_json("seed004-drones");
  d["drones"][0]["mean_rcs_m2"] = -1.0;
  CHECK(error_of(d) == "drones[0].mean_rcs_m2: expected a positive number");
}
