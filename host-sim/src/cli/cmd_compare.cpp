// `mptrack-sim compare`: every tracker on identical measurement sets, side
// by side (compare.h); prints the table, writes DIR/compare.{md,json} and
// DIR/ospa.svg. Takes --no-plot and --no-progress from the top level.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "cli/input_checks.h"
#include "run/staged_output.h"
#include "compare.h"
#include "run/sea_source.h"
#include "stream/adc_compare.h"
#include "scenario_json.h"

namespace mptrack::sim {

namespace {

/// The options: text that needs resolving, the rest bound into `config`.
struct CompareArgs {
  std::string scenario = "seed000-s2";
  std::string trackers;
  std::uint32_t scans = 0;
  std::string scr;  ///< --scr list (sea scenes)
  std::string classifier = "float";  ///< --classifier (sea scenes)
  CompareConfig config;
};

/// The raw-frame pipelines of seed 004 (adc_compare.h) on a raw-ADC scenario.
int run_adc_compare_command(const CompareArgs& a, const RunOptions& o, const std::string& file) {
  AdcRunConfig cfg;
  if (!load_adc_scenario(a.scenario, file, cfg.scenario)) throw std::runtime_error("unknown scenario " + a.scenario);
  cfg.runs = a.config.runs;
  cfg.seed = a.config.seed;
  cfg.frames = a.scans;
  cfg.out_dir = a.config.out_dir.empty() ? "out/compare-" + cfg.scenario.name : a.config.out_dir;
  cfg.plot = !o.no_plot;
  cfg.progress = !o.no_progress;
  cfg.mfbp_params = a.config.mfbp_params;
  const std::vector<std::string> trackers =
      a.trackers.empty() ? std::vector<std::string>{"vmp", "sbl-gnn", "mfbp", "mfbp-filter", "gnn"}
                         : parse_tracker_list(a.trackers);
  const std::vector<AdcSummary> rows = run_adc_compare(cfg, trackers);
  std::printf("%s", adc_compare_to_markdown(rows, cfg).c_str());
  std::printf("wrote %s/{compare.md,compare.json,frames.csv,rmse.csv,frontend.csv%s}\n", cfg.out_dir.c_str(),
              cfg.plot ? ",ospa.svg" : "");
  std::printf("figures: python3 host-sim/plots/compare_figures.py %s\n", cfg.out_dir.c_str());
  return 0;
}

int run_compare_command(const CompareArgs& a, const RunOptions& o) {
  const bool is_file = std::filesystem::is_regular_file(a.scenario);
  if (!is_file && is_sea_scenario(a.scenario)) {
    RunOptions sea = o;
    sea.classifier = a.classifier;
    return run_sea_compare_command(a.scenario, a.trackers, a.scr, a.config.runs, a.config.seed,
                                   a.config.mfbp_params, a.config.out_dir, sea);
  }
  if (!a.scr.empty()) throw std::runtime_error("--scr applies to the seed003-sea scenarios only");
  if (a.classifier != "float") throw std::runtime_error("--classifier applies to the seed003-sea scenarios only");
  if (is_adc_scenario(is_file ? "" : a.scenario, is_file ? a.scenario : "")) {
    return run_adc_compare_command(a, o, is_file ? a.scenario : "");
  }
  CompareConfig cc = a.config;
  cc.spec = resolve_scenario(a.scenario);
  truncate_scans(cc.spec, a.scans);
  if (!a.trackers.empty()) cc.trackers = parse_tracker_list(a.trackers);
  if (cc.out_dir.empty()) cc.out_dir = "out/compare-" + cc.spec.name;
  cc.plot = !o.no_plot;
  cc.progress = !o.no_progress;
  check_bounded_work(cc.spec, cc.clutter_scale);
  const std::string out_dir = cc.out_dir;
  StagedOutputDir staged(out_dir);  // nothing half-written if the run fails
  cc.out_dir = staged.path();
  const CompareResult r = run_compare(cc);
  staged.commit();
  std::printf("%s", compare_to_markdown(r).c_str());
  std::printf("wrote %s/{compare.md,compare.json%s}\n", out_dir.c_str(), cc.plot ? ",ospa.svg" : "");
  return 0;
}

void add_options(CLI::App& cmd, CompareArgs& a) {
  a.config.runs = 10;
  cmd.add_option("--scenario", a.scenario, "built-in name (seed000-s1..s3, seed001-s1..s5; raw ADC: seed004-drones, mimo-interference) or a "
                 "scenario JSON file")
      ->capture_default_str();
  cmd.add_option("--trackers", a.trackers,
                 "comma-separated tracker names (see `mptrack-sim --help`). Default: polar scenarios "
                 "mfbp,mfbp-filter,gmphd,gmcphd,cbmember,gmcphd-known,gnn; Cartesian (seed001) "
                 "gmphd,gmphd-known,gmcphd,gmcphd-known,cbmember,cbmember-known; raw ADC "
                 "vmp,sbl-gnn,mfbp,mfbp-filter,gnn");
  cmd.add_option("--runs", a.config.runs, "Monte Carlo runs (each tracker sees the same runs)")
      ->capture_default_str()->check(integer_in(1, 1000000));
  cmd.add_option("--seed", a.config.seed, "random seed (run r, scan k use stream (seed, r, k))")->capture_default_str();
  cmd.add_option("--out", a.config.out_dir, "output directory (default out/compare-<scenario>)");
  cmd.add_option("--scans", a.scans, "use only the first N scans (raw ADC: frames; 0 = all)");
  cmd.add_option("--clutter-scale", a.config.clutter_scale, "multiply every clutter mean count")
      ->capture_default_str()->check(number_in(0.0, 1e6));
  cmd.add_option("--ospa-c", a.config.ospa_cutoff_m, "OSPA/GOSPA cutoff c [m] (default: 300 for seed001, 631 for seed000)")
      ->check(number_in(0.0, 1e9, true));
  cmd.add_option("--ospa-p", a.config.ospa_order, "OSPA/GOSPA order p (default: 1 for seed001, 2 for seed000)")
      ->check(number_in(1.0, 64.0));
  cmd.add_option("--mfbp-param", a.config.mfbp_params, kMfbpParamHelp);
  cmd.add_option("--rfs-param", a.config.rfs_params, kRfsParamHelp);
  cmd.add_option("--scr", a.scr, "seed003-sea scenarios: comma-separated SCRs [dB], one table column each "
                 "(default -20,-16,...,20); trackers default to mfbp,mfbp-nn,nemp");
  cmd.add_option("--classifier", a.classifier, kClassifierHelp)->capture_default_str()->check(CLI::IsMember({"float", "int8"}));
}

}  // namespace

Subcommand add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "run several trackers on identical measurement sets and write a comparison table\n"
      "(DIR/compare.md, DIR/compare.json: mean OSPA, GOSPA with localisation/missed/false,\n"
      "cardinality error, NFT, step() latency p50/p99/max) and DIR/ospa.svg (OSPA over time,\n"
      "one line per tracker). Progress on stderr.\n"
      "Example: mptrack-sim compare --scenario seed001-s2 --runs 20 --out out/cmp-s2");
  add_options(*cmd, *a);
  return Subcommand{cmd, [a](const RunOptions& o) { return run_compare_command(*a, o); }, {"--no-plot", "--no-progress"}};
}

}  // namespace mptrack::sim
