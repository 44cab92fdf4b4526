// Measurement-level Monte Carlo of one scenario and one tracker (the default
// command, `demo --measurement-level`, every Table V cell): the run loop
// (run/run_loop.h) on a MeasurementSource, writing the output directory.
#pragma once

#include "eval/aggregator.h"
#include "mptrack/scenario/scenario_spec.h"
#include "run/run_loop.h"

namespace mptrack::sim {

struct RunConfig : TrackerRunOptions {
  scenario::ScenarioSpec spec;
  double clutter_scale = 1.0;   ///< multiplies every clutter mean count
};

/// Runs everything; writes DIR/{summary.json,truth.csv,measurements.csv,
/// tracks.csv,metrics.csv,plot.svg} when out_dir is set. Throws
/// std::runtime_error on a bad configuration (unknown tracker, invalid spec).
Summary run_monte_carlo(const RunConfig& config);

/// The same loop and outputs on any scan source (replay of recorded
/// detections: replay/replay_source.h); config.spec is unused.
Summary run_on_source(ScanSource& source, const RunConfig& config);

}  // namespace mptrack::sim
