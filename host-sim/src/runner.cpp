// Measurement-level Monte Carlo; see runner.h.
#include "runner.h"

#include <memory>

#include "run/run_loop.h"
#include "run/run_outputs.h"
#include "run/scan_source.h"
#include "svg_plot.h"
#include "writers.h"

namespace mptrack::sim {

Summary run_monte_carlo(const RunConfig& cfg) {
  MeasurementSource source(cfg.spec, cfg.seed, cfg.clutter_scale);
  const scenario::ScenarioSpec& spec = source.spec();
  LoopConfig loop;
  loop.trackers = {cfg.tracker};
  loop.runs = cfg.runs;
  loop.seed = cfg.seed;
  loop.clutter_scale = cfg.clutter_scale;
  loop.mfbp_params = cfg.mfbp_params;
  loop.progress_label = spec.name + " " + cfg.tracker;
  loop.progress = cfg.progress;
  check_loop_config(loop);  // before the output directory is created

  std::vector<RunObserver*> observers;
  std::unique_ptr<CsvObserver> csv;
  if (!cfg.out_dir.empty()) {
    csv = std::make_unique<CsvObserver>(cfg.out_dir, spec, cfg.csv_runs);
    observers.push_back(csv.get());
  }
  FirstRunKeeper first;
  observers.push_back(&first);
  const Summary sum = run_loop(source, loop, observers).front();

  if (!cfg.out_dir.empty()) {
    write_summary_json(sum, cfg.out_dir + "/summary.json");
    if (cfg.plot) {
      write_plot_svg(cfg.out_dir + "/plot.svg", spec, first.scans, first.estimates, sum.ospa_per_scan,
                     spec.name + " / " + cfg.tracker + " (run 0; OSPA mean of " + std::to_string(cfg.runs) +
                         " runs)");
    }
  }
  return sum;
}

}  // namespace mptrack::sim
