// mptrack-sim: the host harness command-line tool.
//   mptrack-sim [run options]        Monte Carlo runs of one scenario and tracker
//   mptrack-sim table5 [options]     seed 000 Table V (S1: MF-BP vs MF-BP-KI)
//   mptrack-sim compare [options]    every tracker on identical measurements, side by side
//   mptrack-sim demo                 seed004-drones end to end from raw ADC frames (--measurement-level:
//                                    the short seed000-s2 run)
//   mptrack-sim --scenario seed004-drones|mimo-interference [--frames N --rate HZ]   raw-ADC path
//   mptrack-sim scenario-export NAME FILE   write a built-in scenario as JSON
//   mptrack-sim info                 build configuration and caps presets
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/scenario/builtin.h"
#include "compare.h"
#include "runner.h"
#include "scenario_json.h"
#include "stream/adc_cli.h"
#include "tracker_registry.h"

namespace {

using mptrack::scenario::ScenarioSpec;
using mptrack::scenario::Swerling;
using mptrack::sim::RunConfig;
using mptrack::sim::Summary;

template <class Caps>
void print_caps(const char* name) {
  using ScanF = mptrack::Scan<float, Caps::kMaxMeasurements>;
  std::printf("  %-11s targets %4zu  measurements %5zu  clutter comps %2zu  window %zu  sizeof(Scan<float>) %7zu B\n",
              name, Caps::kMaxTargets, Caps::kMaxMeasurements, Caps::kMaxClutterComponents,
              Caps::kMaxWindow, sizeof(ScanF));
}

int run_info() {
  std::printf("mptrack %s\n", "0.1.0");
  std::printf("caps presets:\n");
  print_caps<mptrack::SmallBoardCaps>("SmallBoard");
  print_caps<mptrack::DefaultCaps>("Default");
  print_caps<mptrack::LargeCaps>("Large");
  std::printf("trackers:\n");
  for (const auto& t : mptrack::sim::tracker_list()) {
    std::printf("  %-12s %s\n", t.name.c_str(), t.description.c_str());
  }
  std::printf("tracker footprint (sizeof, DefaultCaps):\n");
  for (const auto& f : mptrack::sim::tracker_footprints()) {
    std::printf("  %-40s float %9zu B  double %9zu B\n", f.name.c_str(), f.bytes_float, f.bytes_double);
  }
  std::printf("scenarios:");
  for (const auto& n : mptrack::scenario::builtin_scenario_names()) std::printf(" %s", n.c_str());
  std::printf("\n");
  return 0;
}

/// "10/3", "20" or "3.5" -> double; throws on anything else.
double parse_ratio(const std::string& text, const char* flag) {
  const auto slash = text.find('/');
  try {
    std::size_t used = 0;
    if (slash == std::string::npos) {
      const double v = std::stod(text, &used);
      if (used == text.size()) return v;
    } else {
      const double a = std::stod(text.substr(0, slash), &used);
      std::size_t used_b = 0;
      const std::string b_text = text.substr(slash + 1);
      const double b = std::stod(b_text, &used_b);
      if (used == slash && used_b == b_text.size() && b != 0.0) return a / b;
    }
  } catch (const std::exception&) {
  }
  throw std::runtime_error(std::string(flag) + ": expected a number or a ratio like 10/3, got '" + text + "'");
}

/// Keeps the first `scans` scans (eval interval and lifetimes clipped).
void truncate_scans(ScenarioSpec& s, std::uint32_t scans) {
  if (scans == 0 || scans >= s.num_scans) return;
  s.num_scans = scans;
  s.eval_last_scan = std::min(s.eval_last_scan, scans);
  if (s.eval_first_scan > scans) s.eval_first_scan = 1;
  std::vector<mptrack::scenario::TargetSpec> targets;
  for (auto t : s.targets) {
    if (t.birth_scan > scans) continue;
    t.death_scan = std::min(t.death_scan, scans);
    targets.push_back(t);
  }
  s.targets = targets;
  std::vector<mptrack::scenario::ClutterSpec> clutter;
  for (auto c : s.clutter) {
    if (c.birth_scan > scans) continue;
    c.death_scan = std::min(c.death_scan, scans);
    clutter.push_back(c);
  }
  s.clutter = clutter;
}

void print_summary(const Summary& s, const std::string& out_dir) {
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
  if (!out_dir.empty()) std::printf("  wrote %s/{summary.json,truth.csv,measurements.csv,tracks.csv,metrics.csv,plot.svg}\n", out_dir.c_str());
}



struct Table5Cell {
  double ospa = 0.0, car = 0.0;
};

int run_table5(std::uint32_t runs, std::uint64_t seed, const std::string& out_dir, std::uint32_t scans,
               bool progress, const std::vector<std::string>& mfbp_params) {
  const double snr1 = 10.0 / 3.0;
  const double snr2s[] = {10.0, 20.0, 30.0};
  const Swerling sws[] = {Swerling::kOne, Swerling::kThree};
  const char* trackers[] = {"mfbp-ki", "mfbp"};
  std::filesystem::create_directories(out_dir);
  std::ofstream csv(out_dir + "/table5.csv");
  csv << "tracker,swerling,snr1,snr2,mean_ospa,car,car_identity,runs\n";
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::string table = "| Algorithm |";
  for (double s2 : snr2s) {
    for (Swerling sw : sws) {
      char b[64];
      std::snprintf(b, sizeof b, " (10/3, %g) SW-%s |", s2, sw == Swerling::kOne ? "I" : "III");
      table += b;
    }
  }
  table += "\n|---|---|---|---|---|---|---|\n";
  for (const char* tr : trackers) {
    table += std::string("| ") + (std::string(tr) == "mfbp" ? "MF-BP" : "MF-BP-KI") + " |";
    for (double s2 : snr2s) {
      for (Swerling sw : sws) {
        RunConfig cfg;
        mptrack::scenario::builtin_scenario("seed000-s1", cfg.spec);
        mptrack::scenario::set_table5_row(cfg.spec, sw, snr1, s2);
        truncate_scans(cfg.spec, scans);
        cfg.tracker = tr;
        cfg.mfbp_params = mfbp_params;
        cfg.runs = runs;
        cfg.seed = seed;
        cfg.progress = progress;
        char dir[128];
        std::snprintf(dir, sizeof dir, "/%s-sw%d-snr%g", tr, static_cast<int>(sw), s2);
        cfg.out_dir = out_dir + dir;
        cfg.csv_runs = 0;
        cfg.plot = true;
        const Summary s = mptrack::sim::run_monte_carlo(cfg);
        char cell[64];
        std::snprintf(cell, sizeof cell, " %.1f / %.2f / %.2f |", s.mean_ospa, s.car, s.car_identity);
        table += cell;
        csv << tr << ',' << static_cast<int>(sw) << ',' << snr1 << ',' << s2 << ',' << s.mean_ospa << ',' << s.car
            << ',' << s.car_identity << ',' << runs << '\n';
        rows.push_back({{"tracker", tr}, {"swerling", static_cast<int>(sw)}, {"snr", {snr1, s2}},
                        {"mean_ospa", s.mean_ospa}, {"car", s.car}, {"car_identity", s.car_identity},
                        {"runs", runs}});
      }
    }
    table += "\n";
  }
  std::ofstream(out_dir + "/table5.json") << nlohmann::ordered_json{{"table", "seed000 Table V"}, {"rows", rows}}.dump(2)
                                          << "\n";
  std::ofstream(out_dir + "/table5.md") << table;
  std::printf("Table V (seed 000, Scenario 1, k >= 119): mean OSPA [m] / CAR / identity CAR, %u run(s), seed %llu\n%s", runs,
              static_cast<unsigned long long>(seed), table.c_str());
  std::printf("paper (100 runs): MP-RMTT-KI 49.2/0.51 49.7/0.52 49.5/0.48 48.7/0.51 51.8/0.46 48.2/0.48; "
              "MP-RMTT 42.0/0.80 39.0/0.90 36.8/0.92 35.0/0.97 37.2/0.94 34.7/0.98\n");
  std::printf("wrote %s/table5.{csv,json,md}\n", out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mptrack-sim: host harness for the mptrack multitarget tracker.\n"
               "Without a subcommand: Monte Carlo runs of one scenario and tracker, writing\n"
               "DIR/summary.json, truth.csv, measurements.csv, tracks.csv, metrics.csv and plot.svg."};
  app.require_subcommand(0, 1);
  app.fallthrough();  // e.g. `mptrack-sim demo --no-progress --tracker gnn`

  std::string tracker_help = "tracker:";
  for (const auto& t : mptrack::sim::tracker_list()) {
    tracker_help += "\n  " + t.name + ": " + t.description;
  }
  std::string scenario_name = "seed000-s2";
  std::string scenario_file;
  std::string tracker = "mfbp";
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  std::string out_dir;
  int swerling = 0;
  std::string snr1_text, snr2_text;
  double clutter_scale = 1.0;
  std::uint32_t scans = 0;
  std::int64_t csv_runs = -1;
  bool no_plot = false;
  bool no_progress = false;

  app.add_option("--scenario", scenario_name, "built-in scenario: seed000-s1 | seed000-s2 | seed000-s3 | seed004-drones | mimo-interference (raw ADC)")
      ->capture_default_str();
  app.add_option("--scenario-file", scenario_file, "load a scenario from JSON (schema: host-sim/scenarios/*.json)")
      ->check(CLI::ExistingFile);
  app.add_option("--tracker", tracker, tracker_help)->capture_default_str();
  app.add_option("--runs", runs, "Monte Carlo runs")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "random seed (run r uses stream (seed, r, scan))")->capture_default_str();
  app.add_option("--out", out_dir, "output directory (default out/<scenario>-<tracker>)");
  app.add_option("--swerling", swerling, "override the Swerling case of every target and clutter component (1 or 3)")
      ->check(CLI::IsMember({1, 3}));
  app.add_option("--snr1", snr1_text, "override target 1's mean SNR, linear (e.g. 10/3)");
  app.add_option("--snr2", snr2_text, "override target 2's mean SNR, linear (Table V: 10, 20, 30)");
  app.add_option("--clutter-scale", clutter_scale, "multiply every clutter mean count (spec 4.4 sweep)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--scans", scans, "use only the first N scans (0 = all)");
  std::uint32_t frames = 0;
  double rate_hz = 0.0;
  app.add_option("--frames", frames, "raw-ADC scenarios: use only the first N frames (0 = all)");
  app.add_option("--rate", rate_hz, "raw-ADC scenarios: producer frame rate [Hz], frames dropped on overrun "
                 "(0 = lossless, as fast as the consumer)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--csv-runs", csv_runs, "write CSV rows for the first N runs only (-1 = all)")->capture_default_str();
  std::vector<std::string> mfbp_params;
  app.add_option("--mfbp-param", mfbp_params, "override an MfbpParams field for the MF-BP trackers, NAME=VALUE (repeatable), e.g. "
      "process_noise_var=0.3 or unresolved_chi2=0; names in host-sim/README.md");
  app.add_flag("--no-plot", no_plot, "do not write plot.svg");
  app.add_flag("--no-progress", no_progress, "no progress output on stderr");

  auto* info = app.add_subcommand("info", "print build configuration, caps presets, trackers and scenarios");
  auto* demo = app.add_subcommand("demo", "seed004-drones end to end from raw ADC frames at 10 Hz, human-readable "
                                          "summary (out/demo); --measurement-level: seed000-s2, 180 scans");
  bool measurement_level = false;
  demo->add_flag("--measurement-level", measurement_level, "run the seed000-s2 measurement-level demo instead");
  auto* table5 = app.add_subcommand("table5", "seed 000 Table V: MF-BP and MF-BP-KI on S1, Swerling I/III, SNR "
                                              "(10/3, 10|20|30); prints and writes DIR/table5.{csv,json,md}");
  std::uint32_t t5_runs = 10;
  std::uint64_t t5_seed = 1;
  std::string t5_out = "out/table5";
  std::uint32_t t5_scans = 0;
  table5->add_option("--runs", t5_runs, "Monte Carlo runs per cell (paper: 100)")->capture_default_str();
  table5->add_option("--seed", t5_seed, "random seed")->capture_default_str();
  table5->add_option("--out", t5_out, "output directory")->capture_default_str();
  table5->add_option("--scans", t5_scans, "use only the first N scans (0 = all 340)");
  std::vector<std::string> t5_mfbp_params;
  table5->add_option("--mfbp-param", t5_mfbp_params, "override an MfbpParams field for the MF-BP trackers, NAME=VALUE (repeatable), e.g. "
      "process_noise_var=0.3 or unresolved_chi2=0; names in host-sim/README.md");
  auto* compare = app.add_subcommand(
      "compare",
      "run several trackers on identical measurement sets and write a comparison table\n"
      "(DIR/compare.md, DIR/compare.json: mean OSPA, GOSPA with localisation/missed/false,\n"
      "cardinality error, NFT, step() latency p50/p99/max) and DIR/ospa.svg (OSPA over time,\n"
      "one line per tracker). Progress on stderr.\n"
      "Example: mptrack-sim compare --scenario seed001-s2 --runs 20 --out out/cmp-s2");
  std::string cmp_scenario = "seed000-s2";
  std::string cmp_trackers;
  std::uint32_t cmp_runs = 10;
  std::uint64_t cmp_seed = 1;
  std::string cmp_out;
  std::uint32_t cmp_scans = 0;
  double cmp_clutter_scale = 1.0;
  double cmp_ospa_c = 0.0;
  double cmp_ospa_p = 0.0;
  compare->add_option("--scenario", cmp_scenario,
                      "built-in name (seed000-s1..s3, seed001-s1..s5) or a scenario JSON file")
      ->capture_default_str();
  compare->add_option("--trackers", cmp_trackers,
                      "comma-separated tracker names (see `mptrack-sim --help`). Default: polar scenarios "
                      "mfbp,mfbp-filter,gmphd,gmcphd,cbmember,gmcphd-known,gnn; Cartesian (seed001) "
                      "gmphd,gmphd-known,gmcphd,gmcphd-known,cbmember,cbmember-known");
  compare->add_option("--runs", cmp_runs, "Monte Carlo runs (each tracker sees the same runs)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  compare->add_option("--seed", cmp_seed, "random seed (run r, scan k use stream (seed, r, k))")->capture_default_str();
  compare->add_option("--out", cmp_out, "output directory (default out/compare-<scenario>)");
  compare->add_option("--scans", cmp_scans, "use only the first N scans (0 = all)");
  compare->add_option("--clutter-scale", cmp_clutter_scale, "multiply every clutter mean count")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  compare->add_option("--ospa-c", cmp_ospa_c, "OSPA/GOSPA cutoff c [m] (default: 300 for seed001, 631 for seed000)")
      ->check(CLI::NonNegativeNumber);
  compare->add_option("--ospa-p", cmp_ospa_p, "OSPA/GOSPA order p (default: 1 for seed001, 2 for seed000)")
      ->check(CLI::NonNegativeNumber);
  std::vector<std::string> cmp_mfbp_params;
  compare->add_option("--mfbp-param", cmp_mfbp_params, "override an MfbpParams field for the MF-BP trackers, NAME=VALUE (repeatable), e.g. "
      "process_noise_var=0.3 or unresolved_chi2=0; names in host-sim/README.md");
  auto* export_cmd = app.add_subcommand("scenario-export", "write a built-in scenario as a JSON template");
  std::string export_name, export_file;
  export_cmd->add_option("name", export_name, "built-in scenario name")->required();
  export_cmd->add_option("file", export_file, "output JSON file")->required();

  CLI11_PARSE(app, argc, argv);

  try {
    if (info->parsed()) return run_info();
    if (export_cmd->parsed()) {
      if (mptrack::sim::export_adc_scenario(export_name, export_file)) return 0;
      ScenarioSpec s;
      if (!mptrack::scenario::builtin_scenario(export_name, s)) {
        std::fprintf(stderr, "error: unknown scenario '%s'\n", export_name.c_str());
        return 2;
      }
      mptrack::sim::save_scenario_file(s, export_file);
      return 0;
    }
    if (table5->parsed()) return run_table5(t5_runs, t5_seed, t5_out, t5_scans, !no_progress, t5_mfbp_params);
    if (compare->parsed()) {
      mptrack::sim::CompareConfig cc;
      cc.spec = mptrack::sim::resolve_scenario(cmp_scenario);
      truncate_scans(cc.spec, cmp_scans);
      if (!cmp_trackers.empty()) cc.trackers = mptrack::sim::parse_tracker_list(cmp_trackers);
      cc.runs = cmp_runs;
      cc.seed = cmp_seed;
      cc.clutter_scale = cmp_clutter_scale;
      cc.mfbp_params = cmp_mfbp_params;
      cc.ospa_cutoff_m = cmp_ospa_c;
      cc.ospa_order = cmp_ospa_p;
      cc.out_dir = cmp_out.empty() ? "out/compare-" + cc.spec.name : cmp_out;
      cc.plot = !no_plot;
      cc.progress = !no_progress;
      const mptrack::sim::CompareResult r = mptrack::sim::run_compare(cc);
      std::printf("%s", mptrack::sim::compare_to_markdown(r).c_str());
      std::printf("wrote %s/{compare.md,compare.json%s}\n", cc.out_dir.c_str(), cc.plot ? ",ospa.svg" : "");
      return 0;
    }

    RunConfig cfg;
    if (demo->parsed() && !measurement_level) {
      return mptrack::sim::run_adc_demo(tracker, !no_progress);
    }
    if (!demo->parsed() && mptrack::sim::is_adc_scenario(scenario_name, scenario_file)) {
      mptrack::sim::AdcCliArgs a;
      a.scenario_name = scenario_file.empty() ? scenario_name : "";
      a.scenario_file = scenario_file;
      a.tracker = tracker;
      a.runs = runs;
      a.seed = seed;
      a.frames = frames;
      a.rate_hz = rate_hz;
      a.out_dir = out_dir;
      a.csv_runs = csv_runs;
      a.plot = !no_plot;
      a.progress = !no_progress;
      a.mfbp_params = mfbp_params;
      return mptrack::sim::run_adc_cli(a);
    }
    if (demo->parsed()) {
      mptrack::scenario::builtin_scenario("seed000-s2", cfg.spec);
      truncate_scans(cfg.spec, 180);
      cfg.tracker = tracker;
      cfg.out_dir = "out/demo";
      std::printf("mptrack demo: %s, first 180 scans (%s), tracker %s\n", cfg.spec.name.c_str(),
                  "five targets, uniform clutter, chaff components from scan 130", cfg.tracker.c_str());
    } else {
      cfg.spec = scenario_file.empty() ? mptrack::sim::resolve_scenario(scenario_name)
                                       : mptrack::sim::load_scenario_file(scenario_file);
      if (swerling != 0 || !snr1_text.empty() || !snr2_text.empty()) {
        for (auto& t : cfg.spec.targets) {
          if (swerling != 0) t.swerling = swerling == 3 ? Swerling::kThree : Swerling::kOne;
          if (t.id == 1 && !snr1_text.empty()) t.snr = parse_ratio(snr1_text, "--snr1");
          if (t.id == 2 && !snr2_text.empty()) t.snr = parse_ratio(snr2_text, "--snr2");
        }
        for (auto& c : cfg.spec.clutter) {
          if (swerling != 0) c.swerling = swerling == 3 ? Swerling::kThree : Swerling::kOne;
        }
      }
      truncate_scans(cfg.spec, scans);
      cfg.tracker = tracker;
      cfg.runs = runs;
      cfg.seed = seed;
      cfg.clutter_scale = clutter_scale;
      cfg.mfbp_params = mfbp_params;
      cfg.csv_runs = csv_runs;
      cfg.out_dir = out_dir.empty() ? "out/" + cfg.spec.name + "-" + tracker : out_dir;
    }
    cfg.plot = !no_plot;
    cfg.progress = !no_progress;
    const Summary s = mptrack::sim::run_monte_carlo(cfg);
    print_summary(s, cfg.out_dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
