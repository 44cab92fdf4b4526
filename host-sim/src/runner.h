// Monte Carlo runner: generate -> track -> evaluate -> write, per run.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "metrics.h"
#include "mptrack/scenario/scenario_spec.h"
#include "mptrack/track_report.h"
#include "tracker_adapter.h"

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

struct LatencyStats {
  double p50_us = 0.0, p99_us = 0.0, max_us = 0.0, mean_us = 0.0;
  std::size_t count = 0;        ///< step() calls measured
};

/// Percentiles by the nearest-rank method on a copy of `samples_us`.
LatencyStats latency_stats(std::vector<double> samples_us);

struct Summary {
  std::string scenario;
  std::string tracker;
  std::uint32_t runs = 0;
  std::uint32_t scans = 0;
  std::uint64_t seed = 0;
  std::uint32_t eval_first_scan = 0, eval_last_scan = 0;
  double clutter_scale = 1.0;
  double mean_ospa = 0.0;       ///< over runs x evaluation scans [m]
  double mean_gospa = 0.0;      ///< [m]
  double car = 0.0;             ///< car_correct / car_total (0 if no detected truth)
  std::uint64_t car_correct = 0, car_total = 0;
  double car_identity = 0.0;    ///< car_id_correct / car_total (identity CAR, metrics.cpp)
  std::uint64_t car_id_correct = 0;
  double nft = 0.0;             ///< mean false confirmed tracks per evaluation scan
  double mean_confirmed_tracks = 0.0;   ///< per evaluation scan
  double mean_truths = 0.0;             ///< per evaluation scan
  double tracks_found_per_run = 0.0;    ///< distinct confirmed track ids per run (mean)
  double mean_measurements = 0.0;       ///< per scan
  LatencyStats latency;
  std::vector<double> ospa_per_scan;    ///< mean over runs, index scan-1 [m]
  std::uint64_t step_errors = 0;        ///< step()/flush() calls returning an error (not kOk, kPartial, kCapacityExceeded)
  std::uint64_t steps_partial = 0;      ///< kPartial: some measurements rejected (see counters)
  std::uint64_t steps_capacity = 0;     ///< kCapacityExceeded: an internal cap was hit (see counters)
  std::map<std::string, std::uint64_t> step_status;  ///< every step()/flush() status by name
  TrackerCounters counters;             ///< summed over runs

  /// Tallies one step()/flush() status into step_status and the three counts.
  void count_status(Status st);
  /// Adds one run's tracker counters to `counters`.
  void add_counters(const TrackerCounters& run);
};

/// Runs everything; writes DIR/{summary.json,truth.csv,measurements.csv,
/// tracks.csv,metrics.csv,plot.svg} when out_dir is set. Throws
/// std::runtime_error on a bad configuration (unknown tracker, invalid spec).
Summary run_monte_carlo(const RunConfig& config);

}  // namespace mptrack::sim
