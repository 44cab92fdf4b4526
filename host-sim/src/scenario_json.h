// Scenario files: JSON <-> ScenarioSpec (schema "mptrack-scenario/1", the
// format of host-sim/scenarios/*.json; fields documented in host-sim/README.md).
// Loading is strict: a missing, mistyped, out-of-range or unknown field is an
// error naming the field, e.g. "targets[1].snr: expected a positive number".
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::sim {

inline constexpr const char* kScenarioSchema = "mptrack-scenario/1";

/// Thrown by the loaders; what() is "<file>: <field path>: <problem>".
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses a document; errors name the field (no file prefix).
scenario::ScenarioSpec scenario_from_json(const nlohmann::ordered_json& doc);
/// Serialises a spec; scenario_from_json(scenario_to_json(s)) == s exactly.
nlohmann::ordered_json scenario_to_json(const scenario::ScenarioSpec& spec);

/// Reads and parses a file (JSON syntax errors carry the byte position).
scenario::ScenarioSpec load_scenario_file(const std::string& path);
/// Writes a file, 2-space indented, newline-terminated.
void save_scenario_file(const scenario::ScenarioSpec& spec, const std::string& path);

/// Built-in name (seed000-s1...) or a path to a JSON file.
scenario::ScenarioSpec resolve_scenario(const std::string& name_or_file);

}  // namespace mptrack::sim
