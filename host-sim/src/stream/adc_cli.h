// mptrack-sim glue for raw-ADC scenarios (seed004-drones, mimo-interference
// or a "mptrack-adc-scenario/1" JSON file): option values in, report out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::sim {

struct AdcCliArgs {
  std::string scenario_name;     ///< built-in name ("" if a file is given)
  std::string scenario_file;     ///< JSON file ("" = built-in)
  std::string tracker = "mfbp";
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  std::uint32_t frames = 0;      ///< 0 = all
  double rate_hz = 0.0;          ///< 0 = lossless, as fast as consumed
  std::string out_dir;           ///< "" = out/<scenario>-<tracker>
  std::int64_t csv_runs = -1;
  bool plot = true;
  bool progress = true;
  std::vector<std::string> mfbp_params;  ///< --mfbp-param overrides
};

/// True for a built-in raw-ADC name or a file with the raw-ADC schema.
bool is_adc_scenario(const std::string& name, const std::string& file);

/// Runs the Monte Carlo and prints the report; returns the exit code.
int run_adc_cli(const AdcCliArgs& args);

/// `mptrack-sim demo`: seed004-drones end to end from raw frames, 1 run at
/// the paper's 10 Hz frame rate, report with tracks found, OSPA, latency.
int run_adc_demo(const std::string& tracker, bool progress);

/// scenario-export for raw-ADC built-ins; false if `name` is not one.
bool export_adc_scenario(const std::string& name, const std::string& file);

}  // namespace mptrack::sim
