// Raw-ADC scenario files: JSON <-> AdcScenario (schema
// "mptrack-adc-scenario/1", the format of host-sim/scenarios/seed004-drones.json
// and mimo-interference.json; fields documented in host-sim/README.md).
// Strict: a mistyped, out-of-range or unknown field is an error naming the
// field, e.g. "drones[1].legs[0].steps: expected a positive integer".
// Optional fields (everything except schema, name, num_frames and drones)
// take the AdcScenario defaults.
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "mptrack/adc/adc_scenario.h"

namespace mptrack::adc {

inline constexpr const char* kAdcScenarioSchema = "mptrack-adc-scenario/1";

/// Thrown by the loaders; what() is "[<file>: ]<field path>: <problem>".
class AdcScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

AdcScenario adc_scenario_from_json(const nlohmann::ordered_json& doc);
/// adc_scenario_from_json(adc_scenario_to_json(s)) == s exactly.
nlohmann::ordered_json adc_scenario_to_json(const AdcScenario& s);
AdcScenario load_adc_scenario_file(const std::string& path);
void save_adc_scenario_file(const AdcScenario& s, const std::string& path);

/// True if `path` is a JSON file whose "schema" is kAdcScenarioSchema.
bool is_adc_scenario_file(const std::string& path);

}  // namespace mptrack::adc
