// The default command: Monte Carlo runs of one scenario x one tracker,
// measurement level (runner.h) or, for a raw-ADC scenario, from raw frames
// through the front end (stream/adc_runner.h).
#include <cstdio>
#include <stdexcept>

#include "cli/commands.h"
#include "cli/input_checks.h"
#include "run/staged_output.h"
#include "mptrack/adc/adc_json.h"
#include "run/sea_source.h"
#include "runner.h"
#include "scenario_json.h"
#include "tracker_registry.h"

namespace mptrack::sim {

namespace {

void apply_target_overrides(const RunOptions& o, scenario::ScenarioSpec& spec) {
  using scenario::Swerling;
  if (o.swerling == 0 && o.snr1_text.empty() && o.snr2_text.empty()) return;
  for (auto& t : spec.targets) {
    if (o.swerling != 0) t.swerling = o.swerling == 3 ? Swerling::kThree : Swerling::kOne;
    if (t.id == 1 && !o.snr1_text.empty()) t.snr = parse_ratio(o.snr1_text, "--snr1");
    if (t.id == 2 && !o.snr2_text.empty()) t.snr = parse_ratio(o.snr2_text, "--snr2");
  }
  for (auto& c : spec.clutter) {
    if (o.swerling != 0) c.swerling = o.swerling == 3 ? Swerling::kThree : Swerling::kOne;
  }
}

/// --pd P: every propagation path of an OTHR scenario detects with P
/// (seed 002 Table IV: 0.75 and 0.4); the trackers read it from the spec.
void apply_pd_override(const RunOptions& o, scenario::ScenarioSpec& spec) {
  if (o.pd < 0.0) return;
  if (spec.space != scenario::MeasurementSpace::kOthr) {
    throw std::runtime_error("--pd applies to OTHR scenarios only (per-path detection probability)");
  }
  for (auto& p : spec.othr.paths) p.pd = o.pd;
}

/// The options both paths share.
void fill_common(const RunOptions& o, TrackerRunOptions& t) {
  t = o.run;
  t.plot = !o.no_plot;
  t.progress = !o.no_progress;
}

int run_adc_scenario(const RunOptions& o) {
  if (o.run.write_detections) {
    // Replay configures a tracker from a measurement-level sensor, not from a
    // raw-ADC scenario's front end: refuse rather than write a file nothing reads.
    throw std::runtime_error("--write-detections applies to measurement-level scenarios only; the front-end "
                             "detections of a raw-ADC run are in DIR/measurements.csv");
  }
  AdcRunConfig cfg;
  fill_common(o, cfg);
  cfg.frames = o.frames;
  cfg.rate_hz = o.rate_hz;
  cfg.adc_format = o.adc_format;
  cfg.saturation_policy = o.saturation_policy;
  return run_adc_command(o.scenario_file.empty() ? o.scenario_name : "", o.scenario_file, cfg);
}

}  // namespace

void add_run_options(CLI::App& app, RunOptions& o) {
  std::string tracker_help = "tracker:";
  for (const auto& t : tracker_list()) tracker_help += "\n  " + t.name + ": " + t.description;
  app.add_option("--scenario", o.scenario_name, "built-in scenario: seed000-s1 | seed000-s2 | seed000-s3 | seed001-s1..s5 | seed002-othr | seed004-drones | mimo-interference (raw ADC) | seed003-sea-a | seed003-sea-b | seed003-sea-c (sea clutter)")
      ->capture_default_str();
  app.add_option("--scenario-file", o.scenario_file, "load a scenario from JSON (schema: host-sim/scenarios/*.json)")
      ->check(CLI::ExistingFile);
  app.add_option("--tracker", o.run.tracker, tracker_help)->capture_default_str();
  app.add_option("--runs", o.run.runs, "Monte Carlo runs")->capture_default_str()->check(integer_in(1, 4294967295u));
  app.add_option("--seed", o.run.seed, "random seed (run r uses stream (seed, r, scan))")->capture_default_str();
  app.add_option("--out", o.run.out_dir, "output directory (default out/<scenario>-<tracker>)");
  app.add_option("--swerling", o.swerling, "override the Swerling case of every target and clutter component (1 or 3)")
      ->check(CLI::IsMember({1, 3}));
  app.add_option("--snr1", o.snr1_text, "override target 1's mean SNR, linear (e.g. 10/3)");
  app.add_option("--snr2", o.snr2_text, "override target 2's mean SNR, linear (Table V: 10, 20, 30)");
  app.add_option("--clutter-scale", o.clutter_scale, "multiply every clutter mean count (sweeps: docs/algorithms/scenarios.md#seed-000)")
      ->capture_default_str()->check(number_in(0.0, 1e6));
  app.add_option("--pd", o.pd, "OTHR scenarios: detection probability of every propagation path, in (0, 1]")
      ->check(CLI::Range(1e-6, 1.0));
  app.add_option("--scans", o.scans, "use only the first N scans (0 = all)");
  app.add_option("--frames", o.frames, "raw-ADC scenarios: use only the first N frames (0 = all)");
  app.add_option("--rate", o.rate_hz, "raw-ADC scenarios: producer frame rate [Hz], frames dropped on overrun "
                 "(0 = lossless, as fast as the consumer)")
      ->capture_default_str()->check(number_in(0.0, 1e6));
  app.add_option("--adc-format", o.adc_format, "raw-ADC scenarios: float (volts, no ADC) or int16 (the scenario's "
                 "ADC model quantises each frame; the ring carries int16 codes); default: the scenario's adc.sample_format")
      ->check(CLI::IsMember({"float", "int16"}));
  app.add_option("--saturation-policy", o.saturation_policy, "raw-ADC int16 path: keep (a saturated frame's "
                 "detections are used, counted) or drop (the frame reaches no tracker, counted); default: the scenario's")
      ->check(CLI::IsMember({"keep", "drop"}));
  app.add_option("--csv-runs", o.run.csv_runs, "write CSV rows for the first N runs only (-1 = all)")->capture_default_str();
  app.add_option("--mfbp-param", o.run.mfbp_params, kMfbpParamHelp);
  app.add_option("--rfs-param", o.run.rfs_params, kRfsParamHelp);
  app.add_option("--scr", o.scr_db, "seed003-sea scenarios: every target's signal-to-clutter ratio [dB] (default 0)");
  app.add_option("--classifier", o.classifier, kClassifierHelp)->capture_default_str()->check(CLI::IsMember({"float", "int8"}));
  app.add_flag("--no-plot", o.no_plot, "do not write plot.svg");
  app.add_flag("--no-progress", o.no_progress, "no progress output on stderr");
  app.add_flag("--write-detections", o.run.write_detections,
               "also write DIR/detections.csv: run 0's detections in the replay format (mptrack-sim replay)");
  app.add_flag("--force", o.force, "write the CSVs even when their estimated size exceeds 2 GB");
}

int run_default_command(const RunOptions& o) {
  if (o.scenario_file.empty() && is_sea_scenario(o.scenario_name)) return run_sea_command(o);
  if (o.scr_db != RunOptions::kNoScr) throw std::runtime_error("--scr applies to the seed003-sea scenarios only");
  if (o.classifier != "float") throw std::runtime_error("--classifier applies to the seed003-sea scenarios only");
  if (is_adc_scenario(o.scenario_name, o.scenario_file)) return run_adc_scenario(o);
  check_raw_adc_only_flags(o.scenario_file.empty() ? o.scenario_name : o.scenario_file, o.rate_hz, o.frames);
  check_raw_adc_only_adc_flags(o.scenario_file.empty() ? o.scenario_name : o.scenario_file, o.adc_format,
                               o.saturation_policy);
  RunConfig cfg;
  fill_common(o, cfg);
  cfg.spec = o.scenario_file.empty() ? resolve_scenario(o.scenario_name) : load_scenario_file(o.scenario_file);
  apply_target_overrides(o, cfg.spec);
  apply_pd_override(o, cfg.spec);
  truncate_scans(cfg.spec, o.scans);
  cfg.clutter_scale = o.clutter_scale;
  if (cfg.out_dir.empty()) cfg.out_dir = "out/" + cfg.spec.name + "-" + cfg.tracker;
  check_bounded_work(cfg.spec, cfg.clutter_scale);
  check_output_size(cfg.spec, cfg.clutter_scale, cfg.runs, cfg.csv_runs, cfg.out_dir, o.force);
  const std::string out_dir = cfg.out_dir;
  StagedOutputDir staged(out_dir);  // nothing half-written if the run fails
  cfg.out_dir = staged.path();
  const Summary s = run_monte_carlo(cfg);
  staged.commit();
  print_run_summary(s, out_dir);
  return 0;
}

int run_adc_command(const std::string& name, const std::string& file, AdcRunConfig cfg) {
  if (!load_adc_scenario(name, file, cfg.scenario)) {
    std::fprintf(stderr, "error: unknown raw-ADC scenario '%s'\n", name.c_str());
    return 2;
  }
  if (cfg.out_dir.empty()) cfg.out_dir = "out/" + cfg.scenario.name + "-" + cfg.tracker;
  const std::string out_dir = cfg.out_dir;
  StagedOutputDir staged(out_dir);  // nothing half-written if the run fails
  cfg.out_dir = staged.path();
  const AdcSummary s = run_adc_monte_carlo(cfg);
  staged.commit();
  print_adc_summary(s, out_dir);
  return 0;
}

void print_run_summary(const Summary& s, const std::string& out_dir) {
  std::printf("scenario %s, tracker %s: %u run(s) x %u scans, seed %llu, evaluated scans %u..%u\n",
              s.scenario.c_str(), s.tracker.c_str(), s.runs, s.scans, static_cast<unsigned long long>(s.seed),
              s.eval_first_scan, s.eval_last_scan);
  std::printf("  mean OSPA %.2f m   mean GOSPA %.2f m   CAR %.3f (%llu/%llu)   NFT %.3f per scan\n", s.mean_ospa,
              s.mean_gospa, s.car, static_cast<unsigned long long>(s.car_correct),
              static_cast<unsigned long long>(s.car_total), s.nft);
  std::printf("  confirmed tracks per scan %.2f (truths %.2f), distinct confirmed tracks per run %.1f\n",
              s.mean_confirmed_tracks, s.mean_truths, s.tracks_found_per_run);
  std::printf("  latency per scan: p50 %.1f us  p99 %.1f us  max %.1f us  (%.1f measurements per scan)\n",
              s.latency.p50_us, s.latency.p99_us, s.latency.max_us, s.mean_measurements);
  if (s.step_errors > 0 || s.steps_capacity > 0 || s.steps_partial > 0) {
    std::string statuses;
    for (const auto& [name, n] : s.step_status) statuses += " " + name + "=" + std::to_string(n);
    std::printf("  note: tracker step statuses:%s (counters in summary.json)\n", statuses.c_str());
  }
  if (!out_dir.empty()) {
    std::printf("  wrote %s/{summary.json,truth.csv,measurements.csv,tracks.csv,metrics.csv,plot.svg}\n",
                out_dir.c_str());
  }
}

}  // namespace mptrack::sim
