// Built-in scenarios: seed 000 S1, S2, S3 (seed 000 Sec. IV-A, Tables II-IV).
// These constants mirror host-sim/scenarios/seed000-s{1,2,3}.json exactly;
// the JSON files are what users copy, and scenario_json_test checks that
// each shipped file loads to exactly the spec returned here.
#pragma once

#include <string>
#include <vector>

#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::scenario {

/// Names accepted by builtin_scenario(): seed000-s1..s3 (polar, seed 000) and
/// seed001-s1..s5 (Cartesian, seed 001 Sec. 5).
std::vector<std::string> builtin_scenario_names();

/// The named built-in scenario; false if the name is unknown.
bool builtin_scenario(const std::string& name, ScenarioSpec& out);

/// Seed 000 S1 as a Table V column: Targets 1 and 2 get SNR (snr1, snr2),
/// every target and clutter component gets the Swerling case.
void set_table5_row(ScenarioSpec& s1, Swerling swerling, double snr1, double snr2);

}  // namespace mptrack::scenario
