// Trackers on front-end detections of a raw-ADC scenario. Same names as the
// measurement-level registry, configured for seed 004's short-range drones
// (10 Hz frames, metre-scale noise, a few m/s) instead of seed 000's
// 10-50 km targets:
//   mfbp, mfbp-filter  MF-BP smoother / online filter (seed 000 algorithm)
//   gnn                GNN + CV Kalman, 3-of-5 confirmation, 5-miss deletion (seed 004
//                      Sec. V-A's tracker) on the matched filter + CFAR detections
//   sbl-gnn            the same GNN on the per-frame SBL detector's detections: seed 004's
//                      detect-then-track baseline
//   vmp                seed 004's VMP tracker on the raw frames (no detector)
// Any other registered name (e.g. oracle) gets the generic adapter.
#pragma once

#include <memory>
#include <string>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/scenario/scenario_spec.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

/// The measurement-level view of a raw-ADC scenario that trackers, CSV
/// writers and the plot use: region = the front end's gate and angle span
/// (azimuth = 90 deg - bearing), noise = tracker_model, threshold = the
/// CA-CFAR amplitude threshold sqrt(alpha), scan period = frame period.
/// Clutter patches and chaff clouds appear as Gaussian components (for the
/// plot); no targets (truth comes from the synthesizer).
scenario::ScenarioSpec tracker_view(const adc::AdcScenario& s);

/// CFAR amplitude threshold sqrt(alpha) (alpha solved by frontend::Cfar for
/// the scenario's variant and pfa): amplitude^2 = P / noise estimate > alpha.
double cfar_amplitude_threshold(const adc::AdcScenario& s);

/// What the pipeline of tracker `name` feeds it, e.g. "matched filter + CFAR
/// detections -> gnn" or "raw frames (seed 004 VMP)".
std::string pipeline_description(const std::string& name);

/// A fresh adapter or nullptr with `error` set.
std::unique_ptr<TrackerAdapter> make_adc_tracker(const std::string& name, std::string& error);

}  // namespace mptrack::sim
