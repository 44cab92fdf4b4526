// `mptrack-sim demo`: seed004-drones end to end from raw ADC frames (1 run
// streamed at 10 Hz, out/demo); --measurement-level: the first 180 scans of
// seed000-s2. Takes --tracker, --no-plot and --no-progress from the top level.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "mptrack/scenario/builtin.h"
#include "runner.h"

namespace mptrack::sim {

namespace {

int run_adc_demo(const RunOptions& o) {
  AdcRunConfig a;
  a.tracker = o.run.tracker;
  a.rate_hz = 10.0;
  a.out_dir = "out/demo";
  a.progress = !o.no_progress;
  std::printf("mptrack demo: seed004-drones from raw ADC frames (3x3 MIMO, 10 GHz, 100 frames streamed at 10 Hz "
              "through the ring buffer), front end + %s\n"
              "  (the seed 000 measurement-level demo: mptrack-sim demo --measurement-level)\n",
              o.run.tracker.c_str());
  return run_adc_command("seed004-drones", "", a);
}

int run_measurement_demo(const RunOptions& o) {
  RunConfig cfg;
  scenario::builtin_scenario("seed000-s2", cfg.spec);
  truncate_scans(cfg.spec, 180);
  cfg.tracker = o.run.tracker;
  cfg.out_dir = "out/demo";
  cfg.plot = !o.no_plot;
  cfg.progress = !o.no_progress;
  std::printf("mptrack demo: %s, first 180 scans (%s), tracker %s\n", cfg.spec.name.c_str(),
              "five targets, uniform clutter, chaff components from scan 130", cfg.tracker.c_str());
  const Summary s = run_monte_carlo(cfg);
  print_run_summary(s, cfg.out_dir);
  return 0;
}

}  // namespace

Subcommand add_demo_command(CLI::App& app) {
  auto measurement_level = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("demo", "seed004-drones end to end from raw ADC frames at 10 Hz, human-readable "
                                             "summary (out/demo); --measurement-level: seed000-s2, 180 scans");
  cmd->add_flag("--measurement-level", *measurement_level, "run the seed000-s2 measurement-level demo instead");
  return Subcommand{cmd,
                    [measurement_level](const RunOptions& o) {
                      return *measurement_level ? run_measurement_demo(o) : run_adc_demo(o);
                    },
                    {"--tracker", "--no-plot", "--no-progress"}};
}

}  // namespace mptrack::sim
