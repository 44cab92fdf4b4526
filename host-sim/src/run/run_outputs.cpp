// Per-run output observers; see run_outputs.h.
#include "run/run_outputs.h"

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

}  // namespace mptrack::sim
