// The frame every Gaussian-mixture RFS filter shares (GM-PHD, GM-CPHD,
// CBMeMBer; docs/algorithms/gm-phd.md, cbmember.md): the tracker contract's
// public API (tracker_contract.h), params and their validation, scan
// admission and the max-gap rule (scan_clock.h), measurement intake
// (filter_common.h), the clutter estimator around the filter's own update,
// the counters and the status rule.
//
// One scan (step): admit -> [gap: reset_targets] -> intake -> predict(dt)
// -> clutter evaluate -> update() -> clutter update -> reduce() ->
// make_births() -> extract(time). The filter (Derived, CRTP: no virtual
// calls) supplies the six bracketed/named operations and its target state;
// everything else lives here once.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/rfs/clutter_estimator.h"
#include "mptrack/rfs/filter_common.h"
#include "mptrack/rfs/mixture.h"
#include "mptrack/rfs/rfs_caps.h"
#include "mptrack/rfs/rfs_params.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"

namespace mptrack::rfs {

template <class Derived, class T, class Caps>
class GmFilterFrame {
  static_assert(caps_are_valid<Caps>(), "invalid caps");
  static_assert(rfs_caps_are_valid<Caps>());

 public:
  using Scalar = T;
  using Params = RfsFilterParams<T>;
  using ScanType = Scan<T, Caps::kMaxMeasurements>;
  using Estimate = ScanEstimate<T, Caps::kMaxTargets, Caps::kMaxClutterComponents>;
  using OutputQueue = StaticVector<Estimate, 1>;  ///< online filters: one scan per step
  using Clutter = ClutterEstimator<T, Caps::kMaxMeasurements, Caps::kMaxClutterComponents>;

  /// Checks p (RfsFilterParams::validate; no field depends on Caps); on
  /// failure names the field in *where (validate.h).
  static Status validate(const Params& p, ParamError* where = nullptr) { return p.validate(where); }

  /// Validates p and resets everything: no targets, zero counters, labels restart at 1.
  Status init(const Params& p) {
    static_assert(tracker_contract_holds<Derived>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(p));
    params_ = p;
    model_ = p.measurement_model();
    gate_ = chi2_gate_2dof(p.gate_probability);
    MPTRACK_TRY(clutter_.init(p));
    reduction_.prune_threshold = p.prune_threshold;
    reduction_.merge_threshold = p.merge_threshold;
    reduction_.merge_threshold_power = p.merge_threshold_power;
    reduction_.use_power = p.amplitude.use_amplitude;
    reduction_.max_alpha = p.max_alpha;
    derived().reset_targets();
    outputs_.clear();
    counters_ = TrackerCounters{};
    next_label_ = 1;
    scan_index_ = 0;
    clock_.start(p.max_gap_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Predict + update with one scan (tracker_contract.h rules): kPartial if
  /// measurements were rejected (counted), kCapacityExceeded if a cap
  /// dropped a component or Bernoulli (track_cap_hits) or a clutter source.
  Status step(const ScanType& scan) {
    outputs_.clear();
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    if (clock_.gap_exceeded(scan.time_us)) {  // max-gap rule (scan_clock.h, F1)
      ++counters_.gap_resets;
      derived().reset_targets();
      clock_.restart();
    }
    const T dt = clock_.elapsed_s(scan.time_us, params_.scan_period_s);
    clock_.advance(scan.time_us);
    ++counters_.scans;
    counters_.measurements_in += scan.measurements.size();
    batch_.load(scan, params_, model_);
    counters_.measurements_invalid += batch_.invalid;
    counters_.measurements_duplicate += batch_.duplicate;
    const std::uint64_t caps_before = total_cap_hits(counters_);

    derived().predict(dt);
    clutter_.evaluate(batch_.z.data(), batch_.amp.data(), batch_.valid.data(), batch_.n);
    derived().update();
    clutter_.update(batch_.z.data(), batch_.amp.data(), batch_.valid.data(), clutter_prob_.data());
    counters_.clutter_born = clutter_.born();
    counters_.clutter_deleted = clutter_.deleted();
    counters_.clutter_cap_hits = clutter_.cap_hits();
    derived().reduce();
    derived().make_births();
    derived().extract(scan.time_us);
    ++scan_index_;
    return accepted_status(counters_, caps_before, batch_.invalid + batch_.duplicate > 0);
  }

  /// Online filter: nothing is held back.
  Status flush() {
    outputs_.clear();
    return initialized_ ? Status::kOk : Status::kNotInitialized;
  }

  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  /// The params of the last successful init().
  const Params& params() const { return params_; }
  const Clutter& clutter() const { return clutter_; }

 protected:
  Derived& derived() { return static_cast<Derived&>(*this); }

  Params params_;
  MeasurementModel<T> model_;
  ReductionSettings<T> reduction_;
  T gate_ = T(0);
  bool initialized_ = false;
  ScanClock clock_;
  std::uint32_t scan_index_ = 0;
  std::uint32_t next_label_ = 1;
  TrackerCounters counters_;
  MeasurementBatch<T, Caps::kMaxMeasurements> batch_;
  std::array<T, Caps::kMaxMeasurements> clutter_prob_{};  ///< P(z is clutter), set by update()
  Clutter clutter_;
  OutputQueue outputs_;
};

/// The report of one Gaussian component: state, covariance, SNR (when the
/// amplitude is used), last measurement; the caller sets id and existence.
template <class T>
TrackReport<T> component_report(const TargetComponent<T>& c, bool use_amplitude) {
  TrackReport<T> r;
  r.state = c.x;
  r.covariance = c.P;
  r.snr = use_amplitude ? (c.power.mean() > T(1) ? c.power.mean() - T(1) : T(0)) : T(0);
  r.confirmed = true;
  r.measurement_index = c.measurement;
  return r;
}

}  // namespace mptrack::rfs

/// Brings the frame's state into a filter's scope (its members are names of
/// a dependent base, which unqualified lookup does not search).
#define MPTRACK_GM_FRAME_MEMBERS(Frame) \
  using Frame::batch_;                  \
  using Frame::clutter_;                \
  using Frame::clutter_prob_;           \
  using Frame::counters_;               \
  using Frame::gate_;                   \
  using Frame::model_;                  \
  using Frame::next_label_;             \
  using Frame::outputs_;                \
  using Frame::params_;                 \
  using Frame::reduction_;              \
  using Frame::scan_index_
