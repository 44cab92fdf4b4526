// Monte Carlo on the seed 003 sea scenes (docs/algorithms/sea_clutter.md
// §Tracking the sea scenes): the run loop on a SeaScanSource, one tracker
// (the default command) or several over a list of SCRs (`compare`).
//
// Metrics: the harness's (OSPA/GOSPA on range, here with seed 003's MOSPA
// order p = 2 and a cutoff of c = 9.4 range-noise deviations, 141 m; IDS and
// Frag from the track scores) plus, per (run, scan), range and range-rate
// RMSE of the confirmed track paired with each target: greedily by the
// Mahalanobis distance of seed 003's MOSPA on (range, range rate) with our
// measurement deviations (one range bin, one Doppler bin of range rate),
// within 9.4, each track used once.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/aggregator.h"
#include "mptrack/sea/sea_scenario.h"
#include "run/run_loop.h"
#include "run/sea_source.h"

namespace mptrack::sim {

/// Seed 003 Sec. IV: MOSPA p = 2, c = 9.4 (Mahalanobis units); in range
/// alone 9.4 range-noise deviations of 15 m.
inline constexpr double kSeaOspaOrder = 2.0;
inline constexpr double kSeaOspaCutoff_m = 9.4 * 15.0;
/// Seed 003 Sec. IV MOSPA cutoff in Mahalanobis units (track-to-target pairing).
inline constexpr double kSeaMatchCutoff = 9.4;
/// The pairing's deviations: one range bin [m], one Doppler bin of range rate [m/s].
double match_range_std_m(const sea::SeaScenario& s);
double match_rate_std_mps(const sea::SeaScenario& s);

/// Range and range-rate errors of one tracker, summed over runs and scans.
struct SeaTrackErrors {
  double sum_sq_range_m2 = 0.0, sum_sq_rate_m2ps2 = 0.0;
  std::uint64_t matched = 0;      ///< (run, scan, target) with a confirmed track within c
  std::uint64_t truths = 0;       ///< (run, scan, target) alive
  double rmse_range_m() const;
  double rmse_velocity_mps() const;
};

struct SeaSummary {
  Summary base;
  double scr_db = 0.0;
  SeaTrackErrors errors;
  double plots_per_scan = 0.0, target_plots_per_scan = 0.0;
  double feature_us_per_detection = 0.0;  ///< CNN time per detection (0 without features)
};

struct SeaRunConfig : TrackerRunOptions {
  sea::SeaScenario scenario;       ///< scr_db set by --scr
  std::uint32_t map_scan = 8;      ///< run 0's scan whose range-Doppler map is written (rd_map.npy)
  FeatureExtractor classifier = FeatureExtractor::kFloat;  ///< --classifier float|int8
};

/// `precision` if one of `trackers` needs the classifier's features
/// (mfbp-nn, nemp), else FeatureExtractor::kNone.
FeatureExtractor sea_features_for(const std::vector<std::string>& trackers, FeatureExtractor precision);

/// One tracker, cfg.runs runs; writes DIR/{summary.json, truth.csv,
/// measurements.csv, tracks.csv, metrics.csv, plot.svg, rd_map.npy,
/// rd_map.json, sea_detections.csv} when out_dir is set.
SeaSummary run_sea_monte_carlo(const SeaRunConfig& cfg);

struct SeaCompareConfig {
  sea::SeaScenario scenario;
  std::vector<std::string> trackers;  ///< empty = mfbp, mfbp-nn, nemp (MP, MP-NN, NEMP)
  std::vector<double> scr_db;         ///< one table column per SCR
  std::uint32_t runs = 1;
  std::uint64_t seed = 1;
  std::vector<std::string> mfbp_params;
  std::string out_dir;                ///< "" = write nothing
  FeatureExtractor classifier = FeatureExtractor::kFloat;  ///< --classifier float|int8
  bool progress = true;
};

/// Every tracker at every SCR on the same scenes (run r is the same clutter
/// and trajectories at every SCR); [scr][tracker].
std::vector<std::vector<SeaSummary>> run_sea_compare(const SeaCompareConfig& cfg);

nlohmann::ordered_json sea_summary_to_json(const SeaSummary& s);
/// Tables over SCR, one per metric, a row per tracker (seed 003 Tables I-II).
std::string sea_compare_to_markdown(const SeaCompareConfig& cfg, const std::vector<std::vector<SeaSummary>>& r);
nlohmann::ordered_json sea_compare_to_json(const SeaCompareConfig& cfg, const std::vector<std::vector<SeaSummary>>& r);

}  // namespace mptrack::sim
