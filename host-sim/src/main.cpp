// mptrack-sim: the host harness command-line tool. Each subcommand lives in
// cli/cmd_*.cpp; main() registers them and dispatches.
//   mptrack-sim [run options]        Monte Carlo runs of one scenario and tracker (cmd_run.cpp)
//   mptrack-sim table5 [options]     seed 000 Table V (S1: MF-BP vs MF-BP-KI)
//   mptrack-sim compare [options]    every tracker on identical measurements, side by side
//   mptrack-sim demo                 seed004-drones end to end from raw ADC frames (--measurement-level:
//                                    the short seed000-s2 run)
//   mptrack-sim --scenario seed004-drones|mimo-interference [--frames N --rate HZ]   raw-ADC path
//   mptrack-sim scenario-export NAME FILE   write a built-in scenario as JSON
//   mptrack-sim replay --detections FILE   recorded detections through one tracker (cmd_replay.cpp)
//   mptrack-sim info                 build configuration and caps presets
//   mptrack-sim dataset [options]    seed 003 classifier patches from the sea-clutter scenes
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <vector>

#include "cli/commands.h"

int main(int argc, char** argv) {
  using namespace mptrack::sim;
  CLI::App app{"mptrack-sim: host harness for the mptrack multitarget tracker.\n"
               "Without a subcommand: Monte Carlo runs of one scenario and tracker, writing\n"
               "DIR/summary.json, truth.csv, measurements.csv, tracks.csv, metrics.csv and plot.svg."};
  app.require_subcommand(0, 1);
  app.fallthrough();  // e.g. `mptrack-sim demo --no-progress --tracker gnn`
  RunOptions options;
  add_run_options(app, options);
  const std::vector<Subcommand> commands = {add_info_command(app), add_demo_command(app), add_table5_command(app),
                                            add_compare_command(app), add_scenario_export_command(app),
                                            add_dataset_command(app), add_replay_command(app)};
  CLI11_PARSE(app, argc, argv);
  try {
    for (const Subcommand& c : commands) {
      if (!c.app->parsed()) continue;
      check_top_level_options(app, c);
      return c.run(options);
    }
    return run_default_command(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
