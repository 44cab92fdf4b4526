// Run observers that write the per-run outputs of an output directory:
// the four CSV files (writers.h) and what plot.svg draws (run 0).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "run/run_loop.h"
#include "writers.h"

namespace mptrack::sim {

/// Writes truth/measurements/tracks/metrics.csv for the first `csv_runs`
/// runs (-1 = all) of the first tracker.
class CsvObserver final : public RunObserver {
 public:
  /// Creates `dir` and writes the header rows (throws on I/O errors).
  CsvObserver(const std::string& dir, const scenario::ScenarioSpec& spec, std::int64_t csv_runs);
  void on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& record,
              const std::vector<ScanMetrics>& metrics) override;

 private:
  CsvWriters writers_;
  const scenario::ScenarioSpec& spec_;
  std::int64_t csv_runs_ = -1;
};

/// Keeps the first tracker's run 0 (scans and estimates) for plot.svg.
class FirstRunKeeper final : public RunObserver {
 public:
  void on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& record,
              const std::vector<ScanMetrics>& metrics) override;
  std::vector<scenario::SimScan> scans;
  std::vector<EstimateOut> estimates;
};

/// The output directory of a one-tracker run: the CSV writers (when
/// out_dir is set) and run 0 for plot.svg.
class RunOutputs {
 public:
  /// Creates the directory and the CSV headers when options.out_dir is set.
  RunOutputs(const TrackerRunOptions& options, const scenario::ScenarioSpec& spec);
  /// The observers to give run_loop().
  std::vector<RunObserver*> observers();
  /// DIR/plot.svg of run 0 when out_dir is set and plot is on.
  /// order_p, cutoff_m: the run's OSPA metric, printed on the plot.
  void write_plot(const std::vector<double>& ospa_per_scan, const std::string& title, double order_p = 2.0,
                  double cutoff_m = 631.0) const;
  /// DIR/detections.csv of run 0 when out_dir is set and write_detections is on.
  void write_detections() const;

 private:
  const TrackerRunOptions& options_;
  const scenario::ScenarioSpec& spec_;
  std::unique_ptr<CsvObserver> csv_;
  FirstRunKeeper first_;
};

}  // namespace mptrack::sim
