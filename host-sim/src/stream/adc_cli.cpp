// mptrack-sim glue for raw-ADC scenarios; see adc_cli.h.
#include "stream/adc_cli.h"

#include <cstdio>

#include "mptrack/adc/adc_json.h"
#include "stream/adc_runner.h"

namespace mptrack::sim {

bool is_adc_scenario(const std::string& name, const std::string& file) {
  if (!file.empty()) return adc::is_adc_scenario_file(file);
  adc::AdcScenario s;
  return adc::builtin_adc_scenario(name, s);
}

int run_adc_cli(const AdcCliArgs& a) {
  AdcRunConfig cfg;
  if (!a.scenario_file.empty()) {
    cfg.scenario = adc::load_adc_scenario_file(a.scenario_file);
  } else if (!adc::builtin_adc_scenario(a.scenario_name, cfg.scenario)) {
    std::fprintf(stderr, "error: unknown raw-ADC scenario '%s'\n", a.scenario_name.c_str());
    return 2;
  }
  cfg.tracker = a.tracker;
  cfg.runs = a.runs;
  cfg.seed = a.seed;
  cfg.frames = a.frames;
  cfg.rate_hz = a.rate_hz;
  cfg.csv_runs = a.csv_runs;
  cfg.plot = a.plot;
  cfg.progress = a.progress;
  cfg.mfbp_params = a.mfbp_params;
  cfg.out_dir = a.out_dir.empty() ? "out/" + cfg.scenario.name + "-" + a.tracker : a.out_dir;
  const AdcSummary s = run_adc_monte_carlo(cfg);
  print_adc_summary(s, cfg.out_dir);
  return 0;
}

int run_adc_demo(const std::string& tracker, bool progress) {
  AdcCliArgs a;
  a.scenario_name = "seed004-drones";
  a.tracker = tracker;
  a.rate_hz = 10.0;
  a.out_dir = "out/demo";
  a.progress = progress;
  std::printf("mptrack demo: seed004-drones from raw ADC frames (3x3 MIMO, 10 GHz, 100 frames streamed at 10 Hz "
              "through the ring buffer), front end + %s\n"
              "  (the seed 000 measurement-level demo: mptrack-sim demo --measurement-level)\n",
              tracker.c_str());
  return run_adc_cli(a);
}

bool export_adc_scenario(const std::string& name, const std::string& file) {
  adc::AdcScenario s;
  if (!adc::builtin_adc_scenario(name, s)) return false;
  adc::save_adc_scenario_file(s, file);
  return true;
}

}  // namespace mptrack::sim
