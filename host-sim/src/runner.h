// Measurement-level Monte Carlo of one scenario and one tracker (the default
// command, `demo --measurement-level`, every Table V cell): the run loop
// (run/run_loop.h) on a MeasurementSource, writing the output directory.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "eval/aggregator.h"
#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::sim {

struct RunConfig {
  scenario::ScenarioSpec spec;
  std::string tracker = "mfbp";
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  double clutter_scale = 1.0;   ///< multiplies every clutter mean count
  std::vector<std::string> mfbp_params;  ///< MfbpParams overrides "name=value" (MF-BP trackers)
  std::string out_dir;          ///< "" = write nothing
  std::int64_t csv_runs = -1;   ///< runs written to the CSVs (-1 = all)
  bool plot = true;             ///< write plot.svg (run 0)
  bool progress = true;         ///< progress bar on stderr
};

/// Runs everything; writes DIR/{summary.json,truth.csv,measurements.csv,
/// tracks.csv,metrics.csv,plot.svg} when out_dir is set. Throws
/// std::runtime_error on a bad configuration (unknown tracker, invalid spec).
Summary run_monte_carlo(const RunConfig& config);

}  // namespace mptrack::sim
