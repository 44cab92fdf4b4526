// `mptrack-sim scenario-export NAME FILE`: a built-in scenario (measurement
// level or raw ADC) as a JSON template.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "mptrack/adc/adc_json.h"
#include "mptrack/scenario/builtin.h"
#include "scenario_json.h"

namespace mptrack::sim {

namespace {

struct ExportArgs {
  std::string name, file;
};

int run_export(const ExportArgs& a) {
  adc::AdcScenario adc_scenario;
  if (adc::builtin_adc_scenario(a.name, adc_scenario)) {
    adc::save_adc_scenario_file(adc_scenario, a.file);
    return 0;
  }
  scenario::ScenarioSpec s;
  if (!scenario::builtin_scenario(a.name, s)) {
    std::fprintf(stderr, "error: unknown scenario '%s'\n", a.name.c_str());
    return 2;
  }
  save_scenario_file(s, a.file);
  return 0;
}

}  // namespace

Subcommand add_scenario_export_command(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand("scenario-export", "write a built-in scenario as a JSON template");
  cmd->add_option("name", args->name, "built-in scenario name")->required();
  cmd->add_option("file", args->file, "output JSON file")->required();
  return Subcommand{cmd, [args](const RunOptions&) { return run_export(*args); }};
}

}  // namespace mptrack::sim
