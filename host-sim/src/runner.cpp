// Measurement-level Monte Carlo; see runner.h.
#include "runner.h"

#include "compare.h"
#include "run/run_outputs.h"
#include "run/scan_source.h"
#include "writers.h"

namespace mptrack::sim {

Summary run_monte_carlo(const RunConfig& cfg) {
  MeasurementSource source(cfg.spec, cfg.seed, cfg.clutter_scale);
  const scenario::ScenarioSpec& spec = source.spec();
  LoopConfig loop = one_tracker_loop(cfg, spec.name);
  loop.clutter_scale = cfg.clutter_scale;
  if (spec.space == scenario::MeasurementSpace::kOthr) default_ospa(spec, loop.ospa_cutoff_m, loop.ospa_order);
  check_loop_config(loop);  // before the output directory is created

  RunOutputs outputs(cfg, spec);
  const Summary sum = run_loop(source, loop, outputs.observers()).front();
  if (!cfg.out_dir.empty()) write_summary_json(sum, cfg.out_dir + "/summary.json");
  outputs.write_plot(sum.ospa_per_scan,
                     spec.name + " / " + cfg.tracker + " (run 0; OSPA mean of " + std::to_string(cfg.runs) + " runs)");
  return sum;
}

}  // namespace mptrack::sim
