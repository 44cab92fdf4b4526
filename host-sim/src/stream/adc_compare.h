// `mptrack-sim compare` on a raw-ADC scenario: several raw-frame pipelines
// on identical frames (run r synthesises its cubes once; every tracker gets
// the same ones, through the ring buffer). The pipelines differ in what they
// consume: the matched filter + CFAR detections (mfbp, mfbp-filter, gnn), a
// per-frame SBL detector's detections (sbl-gnn) or the raw frame itself (vmp).
//
// Writes DIR/compare.md (the table: mean OSPA, OSPA by phase, cardinality,
// per-object RMSE, track start delay, tracker latency), DIR/compare.json
// (every tracker's raw-ADC summary), DIR/frames.csv (per frame and tracker:
// mean OSPA, mean and std of the confirmed-track count, mean truth count),
// DIR/rmse.csv (per (run, object) RMSE, sorted: the empirical CDF) and
// DIR/ospa.svg. host-sim/plots/compare_figures.py draws the seed 004 figures
// (OSPA over frames, cardinality +-3 sigma, RMSE ECDF) from the CSVs.
#pragma once

#include <string>
#include <vector>

#include "stream/adc_runner.h"

namespace mptrack::sim {

/// Runs every tracker of `trackers` and writes the outputs when
/// config.out_dir is set; throws std::runtime_error on a bad configuration.
std::vector<AdcSummary> run_adc_compare(const AdcRunConfig& config, const std::vector<std::string>& trackers);

/// The markdown table of a raw-ADC comparison.
std::string adc_compare_to_markdown(const std::vector<AdcSummary>& rows, const AdcRunConfig& config);

}  // namespace mptrack::sim
