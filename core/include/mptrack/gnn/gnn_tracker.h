// GNN + constant-velocity EKF detect-then-track baseline (seed 004 Sec. V-A,
// the "DTT" the VMP tracker is compared against; MATLAB trackerGNN
// with ConfirmationThreshold [3 5], DeletionThreshold [5 5]).
//
// Follows the tracker contract of tracker_contract.h. Per step():
//   1. validate the scan (time strictly increasing, NaN/Inf or out-of-region
//      measurements skipped and counted);
//   2. predict every track with the CV model (model/cv_motion.h);
//   3. gate and associate: global nearest neighbour by an optimal
//      assignment (metrics/assignment.h) on the squared Mahalanobis
//      distance d2 = nu^T S^-1 nu, gate d2 <= gate_chi2;
//   4. EKF update of assigned tracks (polar_ekf.h, Joseph form, SPD guard);
//   5. M-of-N confirmation and deletion (gnn_track.h);
//   6. a tentative track from every unassigned valid measurement;
//   7. report (confirmed tracks only, unless report_tentative).
//
// Association cost (docs/algorithms/gnn.md §Association). The cost we want is
// d2 + ln|S_i| for track i.
// Each track row also gets "not assigned" dummy columns at cost
// gate_chi2 + ln|S_i| (a measurement exactly on the gate). Every row is
// then assigned exactly once, so the row constant ln|S_i| adds the same
// amount to every feasible solution and drops out: the solver is given
// d2 - gate_chi2 (<= 0) for gated pairs, 0 for the dummies and +1 for
// pairs outside the gate. Since each row has as many dummies as there are
// tracks, an optimal solution never uses a +1 entry (a free dummy is always
// cheaper), so no "infinite" cost or big-M constant is needed and float
// costs stay O(gate). The ln|S| computation (a dmath log per track) is
// thus skipped without changing any decision.
//
// Memory: everything is a member (about 120 KiB for float + DefaultCaps,
// mostly the assignment matrix kMaxTargets x (kMaxMeasurements + kMaxTargets));
// place the tracker in static storage.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/caps.h"
#include "mptrack/gnn/gnn_params.h"
#include "mptrack/gnn/gnn_track.h"
#include "mptrack/gnn/polar_ekf.h"
#include "mptrack/measurement.h"
#include "mptrack/metrics/assignment.h"
#include "mptrack/model/cv_motion.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/model/spd_guard.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T, class Caps = DefaultCaps>
class GnnTracker {
  static_assert(caps_are_valid<Caps>());

 public:
  using Scalar = T;
  using Params = GnnParams<T>;
  using ScanType = Scan<T, Caps::kMaxMeasurements>;
  using Estimate = ScanEstimate<T, Caps::kMaxTargets, Caps::kMaxClutterComponents>;
  /// An online filter finalises exactly one scan per accepted step().
  using OutputQueue = StaticVector<Estimate, 1>;

  static constexpr std::size_t kMaxTracks = Caps::kMaxTargets;
  static constexpr std::size_t kMaxMeasurements = Caps::kMaxMeasurements;

  /// Checks params (GnnParams::validate; no field depends on Caps); on
  /// failure names the field in *where (validate.h).
  static Status validate(const Params& p, ParamError* where = nullptr) { return p.validate(where); }

  /// Validates params (validate() above) and resets the tracker: no
  /// tracks, zero counters, ids restart at 1. On failure the tracker is
  /// left uninitialised.
  Status init(const Params& params) {
    static_assert(tracker_contract_holds<GnnTracker>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(params));
    params_ = params;
    tracks_.clear();
    outputs_.clear();
    counters_ = TrackerCounters{};
    next_id_ = 1;
    clock_.start(params_.max_gap_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Consumes one scan. Returns
  ///  - kNotInitialized / kOutOfOrder (time_us not after the previous
  ///    accepted scan): scan refused whole, tracks untouched, outputs()
  ///    empty, counters().scans_rejected incremented;
  ///  - kPartial: processed, but some measurements were NaN/Inf or outside
  ///    the surveillance region (skipped, counted in measurements_invalid)
  ///    or exact duplicates (measurements_duplicate, measurement.h);
  ///  - kOk otherwise.
  /// A scan more than params().max_gap_s after the previous one first
  /// drops every track (counted in gap_resets and tracks_deleted) and is
  /// then processed as the first scan of a new run (scan_clock.h).
  /// Births refused because kMaxTracks tracks are alive are counted in
  /// track_cap_hits and make the step return kCapacityExceeded (the scan
  /// is still processed: tracker_contract.h rule 2); covariance repairs in
  /// numerical_repairs.
  Status step(const ScanType& scan) {
    outputs_.clear();
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    const std::uint64_t caps_before = total_cap_hits(counters_);
    if (clock_.restart_on_gap(scan.time_us, tracks_.size(), counters_)) tracks_.clear();
    const std::size_t invalid = select_valid(scan);
    if (clock_.has_time()) {
      const T dt = clock_.elapsed_s(scan.time_us, T(0));
      for (auto& t : tracks_) {
        model::cv_predict(t.x, t.P, dt, params_.accel_var_m2ps4);
        if (model::keep_spd(t.P, params_.min_variance)) ++counters_.numerical_repairs;
      }
    }
    MPTRACK_TRY(associate(scan));
    update_and_manage(scan);
    initiate(scan);
    report(scan);
    clock_.advance(scan.time_us);
    ++counters_.scans;
    return accepted_status(counters_, caps_before, invalid > 0);
  }

  /// End of data. Nothing is held back by an online filter: clears outputs().
  Status flush() {
    outputs_.clear();
    return initialized_ ? Status::kOk : Status::kNotInitialized;
  }

  /// The estimate of the last accepted scan (one entry), empty after a
  /// refused step() or flush().
  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  const Params& params() const { return params_; }
  /// Live tracks (tentative and confirmed), in birth order.
  const StaticVector<gnn::GnnTrack<T>, kMaxTracks>& tracks() const { return tracks_; }

 private:
  // Step 1: indices of the valid measurements, in scan order; exact
  // duplicates (measurement.h, F11) dropped. Returns the number rejected.
  std::size_t select_valid(const ScanType& scan) {
    valid_.clear();
    std::size_t invalid = 0;
    std::size_t duplicate = 0;
    counters_.measurements_in += scan.measurements.size();
    // model/measurement_validator.h over the region; amplitude unused.
    const model::MeasurementValidator<T> check = params_.region.validator();
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const Measurement<T>& m = scan.measurements[j];
      const bool ok = check.valid(m);
      kept_[j] = false;
      if (!ok) {
        ++invalid;
      } else if (is_duplicate(scan, j, [this](std::size_t i) { return kept_[i]; })) {
        ++duplicate;  // measurement.h: the first copy is kept
      } else {
        kept_[j] = true;
        // Cannot overflow: valid_ has the scan's capacity.
        static_cast<void>(valid_.push_back(static_cast<std::uint16_t>(j)));
      }
    }
    counters_.measurements_invalid += invalid;
    counters_.measurements_duplicate += duplicate;
    return invalid + duplicate;
  }

  // Step 3: fills assigned_[track] (index into valid_, or -1) and
  // measurement_used_[valid index].
  Status associate(const ScanType& scan) {
    const std::size_t n_tracks = tracks_.size();
    const std::size_t n_meas = valid_.size();
    for (std::size_t j = 0; j < n_meas; ++j) measurement_used_[j] = false;
    for (std::size_t i = 0; i < n_tracks; ++i) assigned_[i] = -1;
    if (n_tracks == 0) return Status::kOk;

    MPTRACK_TRY(solver_.resize(n_tracks, n_meas + n_tracks));
    const T gate = params_.gate_chi2;
    for (std::size_t i = 0; i < n_tracks; ++i) {
      const gnn::GnnTrack<T>& t = tracks_[i];
      pred_[i] = gnn::polar_predict(t.x, t.P, params_.noise.range_std_m, params_.noise.azimuth_std_rad);
      for (std::size_t j = 0; j < n_meas; ++j) {
        T cost = T(1);  // outside the gate (never chosen, see header)
        if (pred_[i].valid) {
          const Measurement<T>& m = scan.measurements[valid_[j]];
          const T d2 = gnn::mahalanobis2(gnn::polar_innovation(m.range_m, m.azimuth_rad, pred_[i]), pred_[i]);
          if (d2 <= gate) cost = d2 - gate;
        }
        solver_.cost(i, j) = cost;
      }
      for (std::size_t k = 0; k < n_tracks; ++k) solver_.cost(i, n_meas + k) = T(0);
    }
    MPTRACK_TRY(solver_.solve());
    for (std::size_t i = 0; i < n_tracks; ++i) {
      const std::int32_t c = solver_.row_assignment(i);
      if (c >= 0 && static_cast<std::size_t>(c) < n_meas &&
          solver_.cost(i, static_cast<std::size_t>(c)) <= T(0)) {
        assigned_[i] = c;
        measurement_used_[static_cast<std::size_t>(c)] = true;
      }
    }
    return Status::kOk;
  }

  // Steps 4-5: update or coast each track, then confirm / delete.
  void update_and_manage(const ScanType& scan) {
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      gnn::GnnTrack<T>& t = tracks_[i];
      const bool hit = assigned_[i] >= 0;
      t.measurement_index = -1;
      if (hit) {
        const std::size_t scan_j = valid_[static_cast<std::size_t>(assigned_[i])];
        const Measurement<T>& m = scan.measurements[scan_j];
        gnn::polar_update(t.x, t.P, gnn::polar_innovation(m.range_m, m.azimuth_rad, pred_[i]), pred_[i],
                     params_.noise.range_std_m, params_.noise.azimuth_std_rad);
        if (model::keep_spd(t.P, params_.min_variance)) ++counters_.numerical_repairs;
        t.measurement_index = static_cast<std::int32_t>(scan_j);
      }
      gnn::record_scan(t, hit);
      if (!t.confirmed &&
          gnn::passes_confirmation(t, params_.confirm_hits, params_.confirm_window)) {
        t.confirmed = true;
        ++counters_.tracks_confirmed;
      }
    }
    // Deletion keeps the birth order of the survivors (deterministic output).
    std::size_t i = 0;
    while (i < tracks_.size()) {
      if (gnn::should_delete(tracks_[i], params_.confirm_hits, params_.confirm_window,
                        params_.max_misses)) {
        static_cast<void>(tracks_.erase(i));  // i < size: cannot fail
        ++counters_.tracks_deleted;
      } else {
        ++i;
      }
    }
  }

  // Step 6: single-point initiation from every unassigned valid measurement.
  void initiate(const ScanType& scan) {
    for (std::size_t j = 0; j < valid_.size(); ++j) {
      if (measurement_used_[j]) continue;
      if (tracks_.full()) {
        ++counters_.track_cap_hits;
        continue;
      }
      const Measurement<T>& m = scan.measurements[valid_[j]];
      gnn::GnnTrack<T> t;
      t.id = next_id_++;
      gnn::polar_initiate(m.range_m, m.azimuth_rad, params_.noise.range_std_m, params_.noise.azimuth_std_rad,
                     params_.init_velocity_std_mps, t.x, t.P);
      t.measurement_index = static_cast<std::int32_t>(valid_[j]);
      gnn::record_scan(t, true);
      // M = 1 confirms at birth.
      if (gnn::passes_confirmation(t, params_.confirm_hits, params_.confirm_window)) {
        t.confirmed = true;
        ++counters_.tracks_confirmed;
      }
      static_cast<void>(tracks_.push_back(t));  // checked full() above
      ++counters_.tracks_born;
    }
  }

  // Step 7.
  void report(const ScanType& scan) {
    static_cast<void>(outputs_.resize(1));  // capacity 1: cannot fail
    Estimate& e = outputs_[0];
    e.time_us = scan.time_us;
    e.scan_index = static_cast<std::uint32_t>(counters_.scans);
    e.tracks.clear();
    e.clutter.clear();
    const T inv_window = T(1) / static_cast<T>(params_.confirm_window);
    for (const gnn::GnnTrack<T>& t : tracks_) {
      if (!t.confirmed && !params_.report_tentative) continue;
      TrackReport<T> r;
      r.id = t.id;
      r.state = t.x;
      r.covariance = t.P;
      // No existence model in a GNN: report the hit fraction of the M-of-N window.
      r.existence = static_cast<T>(gnn::hits_in_window(t.hit_history, params_.confirm_window)) * inv_window;
      r.snr = T(0);  // not estimated
      r.confirmed = t.confirmed;
      r.measurement_index = t.measurement_index;
      static_cast<void>(e.tracks.push_back(r));  // tracks_.size() <= capacity
    }
  }

  Params params_{};
  StaticVector<gnn::GnnTrack<T>, kMaxTracks> tracks_;
  OutputQueue outputs_;
  TrackerCounters counters_{};
  // Per-step scratch (members, not stack: README.md §Conventions a firmware engineer
  // can rely on).
  StaticVector<std::uint16_t, kMaxMeasurements> valid_;           ///< scan indices of valid measurements
  std::array<bool, kMaxMeasurements> kept_{};                     ///< per scan index: in valid_
  std::array<bool, kMaxMeasurements> measurement_used_{};         ///< per valid measurement
  std::array<std::int32_t, kMaxTracks> assigned_{};               ///< per track: valid index or -1
  std::array<gnn::PolarPrediction<T>, kMaxTracks> pred_{};
  AssignmentSolver<T, kMaxTracks, kMaxMeasurements + kMaxTracks> solver_;
  ScanClock clock_;
  std::uint32_t next_id_ = 1;
  bool initialized_ = false;
};

}  // namespace mptrack
