// Classifier training data from sea-clutter scenes
// (docs/algorithms/sea_clutter.md §Dataset): every plot of the core detection
// chain on every scan of every (SCR, run) scene, with its 5 x 512 patch and
// its label (target-generated or clutter).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mptrack/sea/sea_generator.h"
#include "mptrack/sea/sea_scenario.h"
#include "mptrack/seaclutter/sea_detector_params.h"
#include "mptrack/seaclutter/sea_plot.h"

namespace mptrack::sea {

/// Label rule (seed 003 eq. (23) with T_dist as in its DBSCAN): a plot is
/// target-generated if some true target is within these of its centroid.
struct LabelRule {
  double max_range_m = 45.0;       ///< |range - true range| <= this [m] (3 range bins)
  double max_doppler_bins = 2.0;   ///< |Doppler - true Doppler| <= this [bins] (3.9 Hz at 1 kHz / 512)
};

/// Index of the true target the plot belongs to, or -1 (clutter).
int label_plot(double range_m, double doppler_bin, const std::vector<SeaTruth>& truth, const LabelRule& rule);

/// The plots of one scene, scan by scan, for a tracker that supplies the
/// belief column (DatasetConfig::beliefs).
struct ScenePlots {
  std::vector<double> time_s;                            ///< CPI centre of each scan [s]
  std::vector<std::vector<seaclutter::SeaPlot>> plots;   ///< [scan][plot]
  /// [scan] the plots' 5 x 512 patch codes, plot after plot (the classifier's
  /// input, for a belief source that runs NEMP)
  std::vector<std::vector<std::uint8_t>> patches;
};
/// Per scan and plot, the tracker's P(target-originated) of the plot.
using SceneBeliefs = std::vector<std::vector<float>>;
using BeliefFn = std::function<SceneBeliefs(const SeaScenario& scenario, const ScenePlots& scene)>;

struct DatasetConfig {
  SeaScenario scenario;
  double scr_min_db = -20.0, scr_max_db = 20.0, scr_step_db = 4.0;
  std::uint32_t runs = 4;
  std::uint32_t run_offset = 0;  ///< runs are run_offset .. run_offset + runs - 1 (held-out sets use another)
  std::uint64_t seed = 3;
  LabelRule label;
  seaclutter::SeaDetectorParams detector;
  std::string out_dir;
  /// Fills belief.npy (seed 003 Sec. III-D: the MLP's tracker input, from
  /// MP runs on the training sequences); empty = the 0.5 placeholder.
  BeliefFn beliefs;
  std::string beliefs_source = "placeholder 0.5";  ///< what filled belief.npy, for meta.json
};

struct DatasetCounts {
  std::uint64_t scenes = 0, scans = 0, plots = 0, targets = 0, truth_detected = 0, truth_total = 0;
  std::uint64_t partial_scans = 0;
  std::uint64_t clusters = 0;    ///< clusters before the per-scan plot cap
  std::uint64_t detections = 0;  ///< CFAR hits (cells)
};

/// SeaDetectorParams matching a scenario's radar (paper defaults otherwise).
seaclutter::SeaDetectorParams detector_params_for(const SeaScenario& s);

/// Generates, detects, labels and writes DIR/{patches,labels,scr_db,scene,run,scan,belief,plot}.npy and
/// DIR/meta.json. Throws on I/O errors.
DatasetCounts build_dataset(const DatasetConfig& config);

}  // namespace mptrack::sea
