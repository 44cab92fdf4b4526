// `mptrack-sim replay --detections FILE [--scenario NAME | --scenario-file F] --tracker T`:
// recorded detections (replay/detections_csv.h, or detections_json.h for a
// .json file) through one tracker, writing
// the output directory of a normal run (tracks.csv, summary.json, plot).
// The scenario gives the sensor the tracker is set up with (region, noise,
// threshold, scan period, clutter rates); its targets are not truth here.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "replay/detections_json.h"
#include "replay/replay_source.h"
#include "run/staged_output.h"
#include "runner.h"
#include "scenario_json.h"

namespace mptrack::sim {

namespace {

int run_replay(const std::string& detections, const RunOptions& o) {
  RunConfig cfg;
  static_cast<TrackerRunOptions&>(cfg) = o.run;
  cfg.runs = 1;
  cfg.plot = !o.no_plot;
  cfg.progress = !o.no_progress;
  cfg.write_detections = false;
  scenario::ScenarioSpec sensor =
      o.scenario_file.empty() ? resolve_scenario(o.scenario_name) : load_scenario_file(o.scenario_file);
  truncate_scans(sensor, o.scans);
  ReplaySource source(sensor, read_detections_file(detections));
  cfg.clutter_scale = o.clutter_scale;
  if (cfg.out_dir.empty()) cfg.out_dir = "out/replay-" + cfg.tracker;
  const std::string out_dir = cfg.out_dir;
  StagedOutputDir staged(out_dir);  // nothing half-written if the replay fails
  cfg.out_dir = staged.path();
  const Summary s = run_on_source(source, cfg);
  staged.commit();
  std::printf("replay of %s (%zu scans) through %s, sensor from %s\n", detections.c_str(), source.scans().size(),
              cfg.tracker.c_str(), sensor.name.c_str());
  std::printf("  confirmed tracks per scan %.2f, distinct confirmed tracks %.0f, %.1f detections per scan\n",
              s.mean_confirmed_tracks, s.tracks_found_per_run, s.mean_measurements);
  std::printf("  latency per scan: p50 %.1f us  p99 %.1f us  max %.1f us\n", s.latency.p50_us, s.latency.p99_us,
              s.latency.max_us);
  std::printf("  (no truth in a recording: the OSPA/CAR figures of summary.json score against none)\n");
  std::printf("  wrote %s/{summary.json,tracks.csv,measurements.csv,metrics.csv%s}\n", out_dir.c_str(),
              cfg.plot ? ",plot.svg" : "");
  return 0;
}

}  // namespace

Subcommand add_replay_command(CLI::App& app) {
  auto detections = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "run one tracker on recorded detections (CSV: time_s,range_m,azimuth_rad|azimuth_deg,amplitude"
      "[,doppler_mps], header required; or a .json file, schema mptrack-detections/1;\n"
      "host-sim/README.md \"Replaying recorded detections\").\n"
      "The sensor set-up comes from --scenario/--scenario-file (default seed000-s2); writes tracks.csv,\n"
      "summary.json and plot.svg like a run. `mptrack-sim --write-detections` exports a run's detections.\n"
      "Example: mptrack-sim replay --detections rec.csv --scenario seed000-s2 --tracker mfbp --out out/rec");
  cmd->add_option("--detections", *detections, "detections file: CSV, or JSON if the name ends in .json")->required()->check(CLI::ExistingFile);
  return Subcommand{cmd, [detections](const RunOptions& o) { return run_replay(*detections, o); },
                    {"--scenario", "--scenario-file", "--tracker", "--out", "--csv-runs", "--mfbp-param", "--rfs-param", "--scans",
                     "--clutter-scale", "--no-plot", "--no-progress"}};
}

}  // namespace mptrack::sim
