// Per-run output observers; see run_outputs.h.
#include "run/run_outputs.h"

#include "replay/detections_csv.h"
#include "replay/detections_json.h"
#include "svg_plot.h"

namespace mptrack::sim {

CsvObserver::CsvObserver(const std::string& dir, const scenario::ScenarioSpec& spec, std::int64_t csv_runs)
    : writers_(dir), spec_(spec), csv_runs_(csv_runs) {}

void CsvObserver::on_run(std::size_t tracker, const std::vector<scenario::SimScan>& scans, const RunRecord& record,
                         const std::vector<ScanMetrics>& metrics) {
  if (tracker != 0) return;
  if (csv_runs_ >= 0 && static_cast<std::int64_t>(record.run) >= csv_runs_) return;
  writers_.write_run(record.run, spec_, scans, record.by_scan, metrics, record.latency_us);
}

void FirstRunKeeper::on_run(std::size_t tracker, const std::vector<scenario::SimScan>& s, const RunRecord& record,
                            const std::vector<ScanMetrics>& /*metrics*/) {
  if (tracker != 0 || record.run != 0) return;
  scans = s;
  estimates = record.by_scan;
}

RunOutputs::RunOutputs(const TrackerRunOptions& options, const scenario::ScenarioSpec& spec)
    : options_(options), spec_(spec) {
  if (!options.out_dir.empty()) csv_ = std::make_unique<CsvObserver>(options.out_dir, spec, options.csv_runs);
}

std::vector<RunObserver*> RunOutputs::observers() {
  std::vector<RunObserver*> out;
  if (csv_) out.push_back(csv_.get());
  out.push_back(&first_);
  return out;
}

void RunOutputs::write_plot(const std::vector<double>& ospa_per_scan, const std::string& title, double order_p,
                            double cutoff_m) const {
  if (options_.out_dir.empty() || !options_.plot) return;
  write_plot_svg(options_.out_dir + "/plot.svg", spec_, first_.scans, first_.estimates, ospa_per_scan, title,
                 order_p, cutoff_m);
}

void RunOutputs::write_detections() const {
  if (options_.out_dir.empty() || !options_.write_detections) return;
  write_detections_csv(options_.out_dir + "/detections.csv", first_.scans);
  write_detections_json(options_.out_dir + "/detections.json", first_.scans);
}

}  // namespace mptrack::sim
