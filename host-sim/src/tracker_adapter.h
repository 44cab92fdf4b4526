// Host-side tracker interface of the harness. Core trackers are duck-typed
// templates (track_report.h contract); an adapter wraps one behind this
// small virtual interface so the runner can pick a tracker by name.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "run/frame_input.h"
#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/scenario_spec.h"
#include "mptrack/sea/sea_scenario.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"

namespace mptrack::sim {

/// One reported track (double, Cartesian, state [px, vx, py, vy]).
struct TrackOut {
  std::uint32_t id = 0;
  double px = 0.0, vx = 0.0, py = 0.0, vy = 0.0;  ///< [m, m/s, m, m/s]
  double existence = 0.0;
  double snr = 0.0;                               ///< linear, 0 if not estimated
  bool confirmed = false;
  std::int32_t measurement_index = -1;            ///< most likely measurement, -1 = missed
};

/// One estimated clutter component (measurement space).
struct ClutterOut {
  std::uint32_t id = 0;
  bool uniform = false;
  double mean_range_m = 0.0, mean_azimuth_rad = 0.0;
  double cov_rr = 0.0, cov_ra = 0.0, cov_aa = 0.0;  ///< [m^2, m rad, rad^2]
  double expected_count = 0.0;
  double cnr = 0.0;
};

/// Everything a tracker finalised for one scan.
struct EstimateOut {
  std::uint32_t scan = 0;  ///< 1-based scan number (tracker scan_index + 1)
  /// The source scan whose step() handed this estimate out (the last one
  /// delivered for flush()'s): `scan` for a filter, later by the output lag
  /// for a smoother. Set by the run loop (run_tracker); 0 = not recorded,
  /// read as `scan`.
  std::uint32_t reported_after_scan = 0;
  std::vector<TrackOut> tracks;
  std::vector<ClutterOut> clutter;
};

/// Variant knobs the harness passes to every adapter.
struct TrackerSetup {
  scenario::ScenarioSpec spec;           ///< the scenario (region, noise, threshold, known clutter)
  double clutter_scale = 1.0;            ///< applied to known clutter rates (mfbp-kce/nce)
  std::vector<std::string> mfbp_params;  ///< "name=value" MfbpParams overrides (--mfbp-param)
  std::vector<std::string> rfs_params;   ///< "name=value" RfsFilterParams overrides (--rfs-param)
  /// The raw-ADC scenario behind `spec` (its measurement-level view), or
  /// nullptr: what raw-frame trackers configure their signal model from.
  std::shared_ptr<const adc::AdcScenario> raw_scenario;
  /// The seed 003 sea scenario behind `spec` (run/sea_source.h), or nullptr:
  /// what the sea trackers (mfbp, mfbp-nn, nemp) configure their radar from.
  std::shared_ptr<const sea::SeaScenario> sea_scenario;
};

class TrackerAdapter {
 public:
  virtual ~TrackerAdapter() = default;
  /// Validates and initialises; returns "" or an error message.
  virtual std::string init(const TrackerSetup& setup) = 0;
  /// Feeds one scan. Finalised estimates are appended to `out`. `scan`
  /// carries truth and origins, which only the oracle may look at.
  virtual Status step(const scenario::SimScan& scan, std::vector<EstimateOut>& out) = 0;
  /// End of data: appends every estimate still held back.
  virtual Status flush(std::vector<EstimateOut>& out) = 0;
  /// What the tracker consumes on a raw-ADC scenario (run/frame_input.h).
  virtual FrameInput frame_input() const { return FrameInput::kCfarDetections; }
  /// FrameInput::kRawFrame trackers: one raw frame (scan: its number, time
  /// and truth, which only an oracle may look at). Others never get a frame.
  virtual Status step_frame(const RawFrame& /*frame*/, const scenario::SimScan& /*scan*/,
                            std::vector<EstimateOut>& /*out*/) {
    return Status::kInvalidArgument;
  }
  virtual TrackerCounters counters() const = 0;
  /// After step(): the tracker's provisional (lag-0) estimate of the scan it
  /// just consumed, when it hands one out (MF-BP's smoother:
  /// MfbpTracker::provisional(), docs/algorithms/mfbp.md §Provisional
  /// output). False for trackers whose outputs have no lag.
  virtual bool provisional(EstimateOut& /*out*/) const { return false; }
};

/// Converts a core ScanEstimate into the harness form.
template <class Estimate>
EstimateOut to_estimate_out(const Estimate& e) {
  EstimateOut o;
  o.scan = e.scan_index + 1;
  for (const auto& t : e.tracks) {
    TrackOut r;
    r.id = t.id;
    r.px = static_cast<double>(t.state(0));
    r.vx = static_cast<double>(t.state(1));
    r.py = static_cast<double>(t.state(2));
    r.vy = static_cast<double>(t.state(3));
    r.existence = static_cast<double>(t.existence);
    r.snr = static_cast<double>(t.snr);
    r.confirmed = t.confirmed;
    r.measurement_index = t.measurement_index;
    o.tracks.push_back(r);
  }
  for (const auto& c : e.clutter) {
    ClutterOut r;
    r.id = c.id;
    r.uniform = c.uniform;
    r.mean_range_m = static_cast<double>(c.mean(0));
    r.mean_azimuth_rad = static_cast<double>(c.mean(1));
    r.cov_rr = static_cast<double>(c.covariance(0, 0));
    r.cov_ra = static_cast<double>(c.covariance(0, 1));
    r.cov_aa = static_cast<double>(c.covariance(1, 1));
    r.expected_count = static_cast<double>(c.expected_count);
    r.cnr = static_cast<double>(c.cnr);
    o.clutter.push_back(r);
  }
  return o;
}

}  // namespace mptrack::sim
