// The one Monte Carlo loop of the harness:
//   for each run r:   source.begin_run(r)
//     for each tracker: a fresh adapter; source.deliver(step) -> RunRecord;
//                       evaluator -> per-scan metrics; aggregator; observers
// Every subcommand (run, demo, table5, compare, the raw-ADC path) is this
// loop with a different source, tracker list and observers.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "eval/aggregator.h"
#include "eval/scan_evaluator.h"
#include "run/run_record.h"
#include "run/scan_source.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

class Progress;

/// A fresh adapter for `name`, or nullptr with `error` set.
using TrackerFactory = std::unique_ptr<TrackerAdapter> (*)(const std::string& name, std::string& error);

struct LoopConfig {
  std::vector<std::string> trackers;     ///< run in this order on the same data
  TrackerFactory factory = nullptr;      ///< nullptr = make_tracker (tracker_registry.h)
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;                ///< reported in the summaries (the source draws with it)
  double clutter_scale = 1.0;            ///< reported, and given to the adapters
  std::vector<std::string> mfbp_params;  ///< MfbpParams overrides "name=value" (MF-BP trackers)
  std::vector<std::string> rfs_params;   ///< RfsFilterParams overrides "name=value" (gmphd, gmcphd, cbmember)
  double ospa_cutoff_m = kOspaCutoff_m;  ///< OSPA/GOSPA c [m]
  double ospa_order = kOspaOrder;        ///< OSPA/GOSPA p
  std::string progress_label;
  bool progress = true;                  ///< progress bar on stderr
  std::shared_ptr<const adc::AdcScenario> raw_scenario;  ///< given to the adapters (TrackerSetup)
  std::shared_ptr<const sea::SeaScenario> sea_scenario;  ///< given to the adapters (TrackerSetup)
};

/// What every one-tracker Monte Carlo command takes (measurement level,
/// raw ADC).
struct TrackerRunOptions {
  std::string tracker = "mfbp";
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  std::vector<std::string> mfbp_params;  ///< MfbpParams overrides "name=value" (MF-BP trackers)
  std::vector<std::string> rfs_params;   ///< RfsFilterParams overrides "name=value" (gmphd, gmcphd, cbmember)
  std::string out_dir;                   ///< "" = write nothing
  std::int64_t csv_runs = -1;            ///< runs written to the CSVs (-1 = all)
  bool plot = true;                      ///< write plot.svg (run 0)
  bool progress = true;                  ///< progress bar on stderr
  bool write_detections = false;         ///< DIR/detections.csv of run 0 (replay format, replay/detections_csv.h)
};

/// The loop of one tracker from those options (progress "<scenario> <tracker>").
LoopConfig one_tracker_loop(const TrackerRunOptions& options, const std::string& scenario_name);

/// Sees every (tracker, run) after it was evaluated: CSV writers, the plot,
/// source-specific statistics.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// `tracker` indexes LoopConfig::trackers; metrics[k-1] is scan k's.
  virtual void on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& record,
                      const std::vector<ScanMetrics>& metrics) = 0;
};

/// Throws std::runtime_error if runs < 1, no tracker is given or a name is
/// unknown to the factory.
void check_loop_config(const LoopConfig& config);

/// Steps `tracker` through every scan `source` delivers for run `run`, then
/// flushes it (ticks `progress` once per scan if given).
RunRecord run_tracker(ScanSource& source, TrackerAdapter& tracker, std::uint32_t run, Progress* progress);

/// The Monte Carlo loop; one Summary per tracker, in order.
std::vector<Summary> run_loop(ScanSource& source, const LoopConfig& config,
                              const std::vector<RunObserver*>& observers);

}  // namespace mptrack::sim
