// Generic adapter for a core tracker that follows the track_report.h
// contract (init/step/flush/outputs/counters). The tracker object can be
// large (fixed caps), so it lives on the heap of the host process.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mptrack/scenario/generator.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"
#include "param_error_text.h"
#include "tracker_adapter.h"

namespace mptrack::sim {

template <class Tracker>
class CoreTrackerAdapter : public TrackerAdapter {
 public:
  using Scalar = typename Tracker::Scalar;
  using Params = typename Tracker::Params;

  CoreTrackerAdapter() : tracker_(std::make_unique<Tracker>()), scan_(std::make_unique<typename Tracker::ScanType>()) {}

  Status step(const scenario::SimScan& scan, std::vector<EstimateOut>& out) override {
    const Status conv = scenario::to_scan(scan, *scan_);
    // Measurements past the tracker's cap are dropped here, and counted.
    truncated_ += scan.measurements.size() - scan_->measurements.size();
    before_step(scan.scan);
    const Status st = tracker_->step(*scan_);
    collect(out);
    return st != Status::kOk ? st : conv;
  }

  Status flush(std::vector<EstimateOut>& out) override {
    const Status st = tracker_->flush();
    collect(out);
    return st;
  }

  TrackerCounters counters() const override {
    TrackerCounters c = tracker_->counters();
    c.measurements_over_cap += truncated_;
    return c;
  }

  bool provisional(EstimateOut& out) const override {
    if constexpr (has_provisional_output_v<Tracker>) {
      if (!tracker_->has_provisional()) return false;
      out = to_estimate_out(tracker_->provisional());
      return true;
    } else {
      return false;
    }
  }

 protected:
  /// Hook run before each step (e.g. the known clutter map of mfbp-kce).
  virtual void before_step(std::uint32_t /*scan*/) {}

  /// Initialises the tracker; on refusal the message names the field and
  /// the rule it broke (Tracker::validate, tracker_contract.h), prefixed
  /// with `family` ("mfbp.window_length = 100: must be <= 7 (Caps::kMaxWindow)").
  std::string init_tracker(const Params& params, const char* family = "") {
    ParamError where;
    if (Tracker::validate(params, &where) != Status::kOk) return describe_param_error(family, where);
    const Status st = tracker_->init(params);
    return st == Status::kOk ? std::string() : std::string("init failed: ") + to_string(st);
  }

  Tracker& tracker() { return *tracker_; }

 private:
  void collect(std::vector<EstimateOut>& out) {
    for (const auto& e : tracker_->outputs()) out.push_back(to_estimate_out(e));
  }

  std::unique_ptr<Tracker> tracker_;
  std::unique_ptr<typename Tracker::ScanType> scan_;
  std::uint64_t truncated_ = 0;
};

/// The scenario's polar surveillance region in the trackers' units.
inline PolarRegion<double> scenario_region(const scenario::ScenarioSpec& s) {
  return {s.region.range_min_m, s.region.range_max_m, scenario::deg_to_rad(s.region.azimuth_min_deg),
          scenario::deg_to_rad(s.region.azimuth_max_deg)};
}

/// "" unless `setup` is a Cartesian (seed 001) scenario, which `tracker`
/// cannot model: its measurement model is polar (range, azimuth), so every
/// Cartesian detection would fail the region check and the run would end
/// with no track at all. The refusal names the trackers that do run there.
inline std::string polar_scenario_required(const TrackerSetup& setup, const std::string& tracker) {
  if (setup.spec.space != scenario::MeasurementSpace::kCartesian) return "";
  return tracker +
         " models polar (range, azimuth) measurements and cannot run measurement_space \"cartesian\" "
         "(the seed001-* scenarios); use gmphd, gmcphd, cbmember (and their variants) or oracle there";
}

/// The scenario's range and azimuth noise; the Doppler std stays the tracker's.
inline void set_scenario_noise(const scenario::ScenarioSpec& s, PolarNoise<double>& n) {
  n.range_std_m = s.sigma_range_m;
  n.azimuth_std_rad = scenario::deg_to_rad(s.sigma_azimuth_deg);
}

/// The Swerling case the tracker assumes: the first target's (1 if none).
inline int scenario_swerling(const scenario::ScenarioSpec& spec) {
  return spec.targets.empty() ? 1 : static_cast<int>(spec.targets.front().swerling);
}

}  // namespace mptrack::sim
