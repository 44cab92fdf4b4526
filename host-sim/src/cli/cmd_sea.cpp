// The seed 003 sea scenes on the command line (sea_runner.h): the default
// command (`--scenario seed003-sea-a --tracker nemp --scr 0 --runs N`) and
// `compare --scenario seed003-sea-a --scr -10,0,10` (tables over SCR).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "cli/commands.h"
#include "compare.h"
#include "run/staged_output.h"
#include "sea_runner.h"

namespace mptrack::sim {

namespace {

sea::SeaScenario sea_scenario_named(const std::string& name) {
  sea::SeaScenario s;
  if (!sea::builtin_sea_scenario(name, s)) throw std::runtime_error("unknown sea scenario " + name);
  return s;
}

std::vector<double> parse_scr_list(const std::string& text) {
  std::vector<double> out;
  if (text.empty()) {
    for (int db = -20; db <= 20; db += 4) out.push_back(db);  // seed 003 Sec. IV: 4 dB steps
    return out;
  }
  for (const std::string& item : parse_tracker_list(text)) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(v >= -60.0 && v <= 60.0)) {
      throw std::runtime_error("--scr: '" + item + "' is not an SCR in [-60, 60] dB");
    }
    out.push_back(v);
  }
  return out;
}

FeatureExtractor parse_classifier(const std::string& name) {
  if (name == "float") return FeatureExtractor::kFloat;
  if (name == "int8") return FeatureExtractor::kInt8;
  throw std::runtime_error("--classifier: '" + name + "' is not float or int8");
}

}  // namespace

int run_sea_command(const RunOptions& o) {
  SeaRunConfig cfg;
  static_cast<TrackerRunOptions&>(cfg) = o.run;
  cfg.classifier = parse_classifier(o.classifier);
  cfg.plot = !o.no_plot;
  cfg.progress = !o.no_progress;
  cfg.scenario = sea_scenario_named(o.scenario_name);
  if (o.scr_db != RunOptions::kNoScr) {
    if (!(o.scr_db >= -60.0 && o.scr_db <= 60.0)) throw std::runtime_error("--scr must be in [-60, 60] dB");
    cfg.scenario.scr_db = o.scr_db;
  }
  if (o.scans > 0 && o.scans < cfg.scenario.num_scans) cfg.scenario.num_scans = o.scans;
  if (cfg.out_dir.empty()) cfg.out_dir = "out/" + cfg.scenario.name + "-" + cfg.tracker;
  const std::string out_dir = cfg.out_dir;
  StagedOutputDir staged(out_dir);  // nothing half-written if the run fails
  cfg.out_dir = staged.path();
  const SeaSummary s = run_sea_monte_carlo(cfg);
  staged.commit();
  print_run_summary(s.base, out_dir);
  std::printf("  SCR %g dB: range RMSE %.2f m, range-rate RMSE %.2f cm/s, IDS %.2f, Frag %.2f per target; "
              "%.1f plots per scan (%.2f from targets)\n",
              s.scr_db, s.errors.rmse_range_m(), 100.0 * s.errors.rmse_velocity_mps(),
              s.base.track_scores.per_target(s.base.track_scores.id_switches),
              s.base.track_scores.per_target(s.base.track_scores.fragmentations), s.plots_per_scan,
              s.target_plots_per_scan);
  std::printf("  range-Doppler map: /usr/bin/python3 host-sim/plots/sea_rd_map.py %s\n", out_dir.c_str());
  return 0;
}

int run_sea_compare_command(const std::string& scenario, const std::string& trackers, const std::string& scr_list,
                            std::uint32_t runs, std::uint64_t seed, const std::vector<std::string>& mfbp_params,
                            const std::string& out_dir, const RunOptions& o) {
  SeaCompareConfig cfg;
  cfg.scenario = sea_scenario_named(scenario);
  if (!trackers.empty()) cfg.trackers = parse_tracker_list(trackers);
  cfg.scr_db = parse_scr_list(scr_list);
  cfg.runs = runs;
  cfg.seed = seed;
  cfg.mfbp_params = mfbp_params;
  cfg.progress = !o.no_progress;
  cfg.classifier = parse_classifier(o.classifier);
  const std::string dir = out_dir.empty() ? "out/compare-" + cfg.scenario.name : out_dir;
  StagedOutputDir staged(dir);
  const auto result = run_sea_compare(cfg);
  std::filesystem::create_directories(staged.path());
  std::ofstream md(staged.path() + "/compare.md");
  md << sea_compare_to_markdown(cfg, result);
  std::ofstream js(staged.path() + "/compare.json");
  js << sea_compare_to_json(cfg, result).dump(2) << "\n";
  if (!md || !js) throw std::runtime_error(dir + ": cannot write compare.md/compare.json");
  md.close();
  js.close();
  staged.commit();
  std::printf("%s", sea_compare_to_markdown(cfg, result).c_str());
  std::printf("wrote %s/{compare.md,compare.json}\n", dir.c_str());
  return 0;
}

}  // namespace mptrack::sim
