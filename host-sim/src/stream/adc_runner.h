// End-to-end raw-ADC Monte Carlo: the run loop (run/run_loop.h) on an
// AdcScanSource (synthesizer -> ring buffer -> front end, adc_source.h), the
// tracker, then OSPA against the synthesizer's truth (seed 004: c = 10 m,
// p = 2) on every frame.
// Outputs in DIR: summary.json (harness fields plus stage_latency_us, ring,
// frontend, ospa_by_phase, track_start_delay_frames), truth.csv,
// measurements.csv, tracks.csv, metrics.csv, frontend.csv, plot.svg.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mptrack/adc/adc_scenario.h"
#include "eval/aggregator.h"
#include "run/run_loop.h"
#include "run/truncate.h"
#include "stream/stream_pipeline.h"

namespace mptrack::sim {

struct AdcRunConfig : TrackerRunOptions {
  adc::AdcScenario scenario;
  std::uint32_t frames = 0;        ///< keep only the first N frames (0 = all)
  double rate_hz = 0.0;            ///< producer frame rate [Hz]; 0 = lossless, as fast as consumed
  std::uint32_t consumer_delay_us = 0;  ///< extra sleep per consumed frame (tests: a slow consumer)
  std::string adc_format;          ///< --adc-format: overrides scenario.adc.sample_format ("" = keep)
  std::string saturation_policy;   ///< --saturation-policy: overrides scenario.adc.saturation_policy
};

/// Per-stage latency over all processed frames of all runs [us].
struct StageLatency {
  LatencyStats range, doppler, angle, cfar, tracker, frontend, frame, queue;
};

struct AdcSummary {
  Summary base;                    ///< harness summary (OSPA with c = scenario.ospa_cutoff_m)
  double rate_hz = 0.0;
  double ospa_cutoff_m = 0.0, ospa_order = 0.0;  ///< the scenario's OSPA (c [m], p)
  std::vector<adc::EvalPhase> phases;            ///< the scenario's named frame intervals
  StageLatency stages;
  StreamCounters ring;             ///< summed over runs
  double mean_detections = 0.0;    ///< per processed frame
  double drone_detection_rate = 0.0;   ///< fraction of (alive drone, processed frame) with a detection within 3 m
  double range_error_rms_m = 0.0;      ///< of those detections
  double bearing_error_rms_deg = 0.0;
  adc::AdcModelSpec adc;           ///< the scenario's ADC model
  std::uint64_t clipped_samples = 0;           ///< int16 path, summed over runs: values the ADC clipped
  std::uint64_t frames_saturated = 0;          ///< ... processed frames flagged saturated
  std::uint64_t saturated_detections = 0;      ///< ... detections of those frames
  std::uint64_t saturated_frames_dropped = 0;  ///< ... saturated frames handed to no tracker ("drop")
  std::map<std::string, double> ospa_by_phase;     ///< mean OSPA over runs x the phase's frames [m]
  std::map<std::uint32_t, double> start_delay;     ///< drone id -> mean frames from birth to a confirmed track within c
};

/// Runs everything for config.tracker and writes the run outputs
/// (throws std::runtime_error on a bad configuration).
AdcSummary run_adc_monte_carlo(const AdcRunConfig& config);

/// The Monte Carlo loop over `trackers` on identical frames (each tracker
/// sees the same synthesised cubes of run r). run_outputs: the CSVs and
/// plot of the single-tracker command (first tracker); otherwise only
/// frontend.csv (of the first tracker) is written under config.out_dir.
std::vector<AdcSummary> run_adc_loop(const AdcRunConfig& config, const std::vector<std::string>& trackers,
                                     bool run_outputs);

nlohmann::ordered_json adc_summary_to_json(const AdcSummary& s);

/// Human-readable report (the demo's output).
void print_adc_summary(const AdcSummary& s, const std::string& out_dir);

}  // namespace mptrack::sim
