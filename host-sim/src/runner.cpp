// Measurement-level Monte Carlo; see runner.h.
#include "runner.h"

#include "compare.h"
#include "run/run_outputs.h"
#include "run/scan_source.h"
#include "writers.h"

#include <fstream>
#include <stdexcept>

namespace mptrack::sim {

Summary run_monte_carlo(const RunConfig& cfg) {
  MeasurementSource source(cfg.spec, cfg.seed, cfg.clutter_scale);
  return run_on_source(source, cfg);
}

Summary run_on_source(ScanSource& source, const RunConfig& cfg) {
  const scenario::ScenarioSpec& spec = source.spec();
  LoopConfig loop = one_tracker_loop(cfg, spec.name);
  loop.clutter_scale = cfg.clutter_scale;
  // The scenario's own metric (c, p), as compare uses (default_ospa, compare.h).
  default_ospa(spec, loop.ospa_cutoff_m, loop.ospa_order);
  check_loop_config(loop);  // before the output directory is created

  RunOutputs outputs(cfg, spec);
  const Summary sum = run_loop(source, loop, outputs.observers()).front();
  if (!cfg.out_dir.empty()) {
    // summary.json carries the metric the run used (plots read it).
    nlohmann::ordered_json j = summary_to_json(sum);
    j["ospa"] = {{"cutoff_m", loop.ospa_cutoff_m}, {"order_p", loop.ospa_order}};
    std::ofstream f(cfg.out_dir + "/summary.json");
    if (!f) throw std::runtime_error(cfg.out_dir + "/summary.json: cannot write");
    f << j.dump(2) << "\n";
  }
  outputs.write_detections();
  outputs.write_plot(sum.ospa_per_scan,
                     spec.name + " / " + cfg.tracker + " (run 0; OSPA mean of " + std::to_string(cfg.runs) + " runs)", loop.ospa_order, loop.ospa_cutoff_m);
  return sum;
}

}  // namespace mptrack::sim
