// `mptrack-sim dataset`: classifier training data from the seed 003 sea
// scenes (docs/algorithms/sea_clutter.md §Dataset).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "mptrack/sea/sea_dataset.h"
#include "trackers/sea_beliefs.h"

namespace mptrack::sim {

namespace {

struct DatasetArgs {
  std::string scenario = "seed003-sea-a";
  double scr_min = -20.0, scr_max = 20.0, scr_step = 4.0;
  std::uint32_t runs = 4, run_offset = 0;
  std::uint64_t seed = 3;
  double pfa = 0.28;
  double scr = -1000.0;  ///< --scr: one SCR for every target (overrides the sweep)
  std::string out;
  std::string beliefs = "nemp";  ///< --beliefs: nemp or mfbp (that tracker's runs) or none (0.5)
};

int run_dataset(const DatasetArgs& a) {
  sea::DatasetConfig c;
  if (!sea::builtin_sea_scenario(a.scenario, c.scenario)) {
    std::fprintf(stderr, "error: unknown sea scenario '%s' (seed003-sea-a, seed003-sea-b, seed003-sea-c)\n", a.scenario.c_str());
    return 2;
  }
  const bool one_scr = a.scr > -999.0;
  c.scr_min_db = one_scr ? a.scr : a.scr_min;
  c.scr_max_db = one_scr ? a.scr : a.scr_max;
  c.scr_step_db = a.scr_step;
  c.runs = a.runs;
  c.run_offset = a.run_offset;
  c.seed = a.seed;
  c.detector = sea::detector_params_for(c.scenario);
  c.detector.cfar.pfa = a.pfa;
  if (a.beliefs == "mfbp" || a.beliefs == "nemp") {
    if (sea_beliefs_available()) {
      const BeliefSource source = a.beliefs == "nemp" ? BeliefSource::kNemp : BeliefSource::kMfbp;
      c.beliefs = [source](const sea::SeaScenario& s, const sea::ScenePlots& scene) {
        return scene_beliefs(source, s, scene);
      };
      c.beliefs_source = a.beliefs;
    } else {
      std::fprintf(stderr, "note: no trained classifier header yet: belief.npy keeps the 0.5 placeholder\n");
    }
  } else if (a.beliefs != "none") {
    std::fprintf(stderr, "error: --beliefs must be nemp, mfbp or none\n");
    return 2;
  }
  c.out_dir = a.out.empty() ? "out/dataset-" + a.scenario : a.out;
  std::filesystem::create_directories(c.out_dir);
  const sea::DatasetCounts n = sea::build_dataset(c);
  std::printf("%s: %llu scenes, %llu scans, %llu plots (%llu target, %llu clutter), targets detected %llu / %llu,"
              " scans at the plot cap %llu (clusters %llu, CFAR cells %llu) -> %s\n",
              a.scenario.c_str(), static_cast<unsigned long long>(n.scenes),
              static_cast<unsigned long long>(n.scans), static_cast<unsigned long long>(n.plots),
              static_cast<unsigned long long>(n.targets), static_cast<unsigned long long>(n.plots - n.targets),
              static_cast<unsigned long long>(n.truth_detected), static_cast<unsigned long long>(n.truth_total),
              static_cast<unsigned long long>(n.partial_scans), static_cast<unsigned long long>(n.clusters),
              static_cast<unsigned long long>(n.detections), c.out_dir.c_str());
  return 0;
}

}  // namespace

Subcommand add_dataset_command(CLI::App& app) {
  auto args = std::make_shared<DatasetArgs>();
  CLI::App* cmd = app.add_subcommand(
      "dataset", "seed 003 classifier data: 5x512 range-Doppler patches of every plot, labels, SCR (.npy)");
  cmd->add_option("--scenario", args->scenario, "seed003-sea-a (train), seed003-sea-b or seed003-sea-c (held out)");
  cmd->add_option("--scr-min", args->scr_min, "lowest SCR [dB]");
  cmd->add_option("--scr-max", args->scr_max, "highest SCR [dB]");
  cmd->add_option("--scr-step", args->scr_step, "SCR step [dB]");
  cmd->add_option("--scr", args->scr, "every target's SCR [dB] (one level instead of the sweep)");
  cmd->add_option("--runs", args->runs, "scenes per SCR");
  cmd->add_option("--run-offset", args->run_offset, "first run index (held-out sets: e.g. 1000)");
  cmd->add_option("--seed", args->seed, "master seed");
  cmd->add_option("--pfa", args->pfa, "CFAR false-alarm probability per cell");
  cmd->add_option("--out", args->out, "output directory (default out/dataset-<scenario>)");
  cmd->add_option("--beliefs", args->beliefs,
                  "belief.npy, the MLP's tracker input: nemp = NEMP's extrinsic association belief per plot (sea"
                  " settings, committed network), mfbp = plain MF-BP's, none = 0.5")
      ->capture_default_str();
  return Subcommand{cmd, [args](const RunOptions&) { return run_dataset(*args); }};
}

}  // namespace mptrack::sim
