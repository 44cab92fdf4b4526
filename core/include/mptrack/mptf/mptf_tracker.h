// Multipath track fusion (MPTF): the baseline of seed 002 Sec. IV. Path
// tracks are formed in slant coordinates by PDA filters with M/N logic,
// then carried to the ground under each path's geometry and fused there
// (docs/algorithms/mptf.md).
//
// The paper runs one PDA tracker per path. Every path tracker sees the same
// detections through the same slant-coordinate model (the slant measurement
// does not depend on the path), so N_P of them would hold the same tracks:
// we run the slant tracker once and register each confirmed track under
// every path (docs/algorithms/mptf.md §Departures from the paper). Per step():
//   1. intake: valid detections (region, range-rate span, NaN), km units,
//      sorted by slant range (model/othr_detections.h);
//   2. predict every path track (CV in r and in zeta, model/cwna_motion.h);
//   3. gate (p_g from gate_chi2) and PDA-update each track (pda_update.h);
//   4. M/N logic: confirm, or delete (slant_track.h);
//   5. births: one tentative track per detection in no track's gate;
//   6. fusion in ground coordinates (fusion_table.h);
//   7. report the fused tracks (Cartesian ground frame).
//
// Memory: everything is a member, sized by Caps (mptf_caps.h); place the
// tracker in static storage.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/caps.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/math/erf.h"
#include "mptrack/measurement.h"
#include "mptrack/model/cwna_motion.h"
#include "mptrack/model/othr_cartesian.h"
#include "mptrack/model/othr_detections.h"
#include "mptrack/model/othr_slant_state.h"
#include "mptrack/model/spd_guard_scaled.h"
#include "mptrack/mptf/fusion_table.h"
#include "mptrack/mptf/mptf_caps.h"
#include "mptrack/mptf/mptf_params.h"
#include "mptrack/mptf/pda_update.h"
#include "mptrack/mptf/slant_track.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T, class Caps = DefaultCaps>
class MptfTracker {
  static_assert(caps_are_valid<Caps>());
  static_assert(mptf::mptf_caps_are_valid<Caps>());

 public:
  using Scalar = T;
  using Params = MptfParams<T>;
  using ScanType = Scan<T, Caps::kMaxMeasurements>;
  using Estimate = ScanEstimate<T, Caps::kMaxTargets, Caps::kMaxClutterComponents>;
  using OutputQueue = StaticVector<Estimate, 1>;  ///< online: one finalised scan per step

  static constexpr std::size_t kMaxPaths = mptf::kMaxPaths<Caps>;
  static constexpr std::size_t kMaxPathTracks = mptf::kMaxPathTracks<Caps>;
  static constexpr std::size_t kMaxFused = Caps::kMaxTargets;
  static constexpr std::size_t kMaxCandidates = mptf::kMaxFusionCandidates<Caps>;
  static constexpr std::size_t kMaxMeasurements = Caps::kMaxMeasurements;
  using PathTrack = mptf::SlantTrack<T>;
  using Fusion = mptf::FusionTable<T, kMaxFused, kMaxPaths>;

  /// Checks params (MptfParams::validate) and num_paths against Caps::kMaxPaths.
  static Status validate(const Params& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "num_paths", check(p.num_paths <= kMaxPaths));
    return Status::kOk;
  }

  /// Validates params and resets: no tracks, zero counters, ids from 1.
  Status init(const Params& params) {
    static_assert(tracker_contract_holds<MptfTracker>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(params));
    params_ = params;
    derive_constants();
    tracks_.clear();
    fusion_.clear();
    outputs_.clear();
    counters_ = TrackerCounters{};
    next_track_id_ = 1;
    next_fused_id_ = 1;
    clock_.start(params_.max_gap_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Consumes one scan (statuses as every tracker: tracker_contract.h).
  /// Invalid detections (outside the region or range-rate span, NaN/Inf)
  /// count in measurements_invalid, exact duplicates in
  /// measurements_duplicate (kPartial); births refused at kMaxPathTracks
  /// and fused tracks refused at kMaxTargets count in track_cap_hits;
  /// confirmed path tracks beyond kMaxTargets x kMaxPaths are left out of
  /// fusion for the scan (association_cap_hits).
  Status step(const ScanType& scan) {
    outputs_.clear();
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    const std::uint64_t caps_before = total_cap_hits(counters_);
    if (clock_.restart_on_gap(scan.time_us, tracks_.size(), counters_)) {
      tracks_.clear();
      fusion_.clear();
    }
    const std::size_t rejected = det_.select(scan, params_.region, params_.range_rate_span_mps, counters_);
    set_scan_noise(scan.has_doppler);
    const T dt = clock_.has_time() ? clock_.elapsed_s(scan.time_us, T(0)) : T(0);
    for (std::size_t j = 0; j < det_.size(); ++j) in_gate_[j] = false;
    for (PathTrack& t : tracks_) {
      predict(t, dt);
      associate(t);
    }
    manage();
    births();
    fuse();
    report(scan);
    clock_.advance(scan.time_us);
    ++counters_.scans;
    return accepted_status(counters_, caps_before, rejected > 0);
  }

  /// End of data. An online filter holds nothing: clears outputs().
  Status flush() {
    outputs_.clear();
    return initialized_ ? Status::kOk : Status::kNotInitialized;
  }

  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  const Params& params() const { return params_; }
  /// Live path tracks (slant coordinates), birth order.
  const StaticVector<PathTrack, kMaxPathTracks>& path_tracks() const { return tracks_; }
  /// Live fused tracks (ground coordinates [km, km/s, rad, rad/s]).
  const StaticVector<typename Fusion::Fused, kMaxFused>& fused_tracks() const { return fusion_.tracks(); }

 private:
  // Logs and unit conversions of the params, once per init().
  void derive_constants() {
    r_var_ << params_.noise.range_std_m * params_.noise.range_std_m * T(1e-6),
        params_.noise.doppler_std_mps * params_.noise.doppler_std_mps * T(1e-6),
        params_.noise.azimuth_std_rad * params_.noise.azimuth_std_rad;
    // Clutter density per km (km/s) rad of the measurement box (seed 002 Sec. IV).
    const T volume = (params_.region.range_max_m - params_.region.range_min_m) * T(1e-3) *
                     (T(2) * params_.range_rate_span_mps * T(1e-3)) *
                     (params_.region.azimuth_max_rad - params_.region.azimuth_min_rad);
    ln_pd_lambda_ = dmath::dlog(params_.pd) - dmath::dlog(params_.clutter_mean_count / volume);
    // p_g of the gate: P(chi2_3 <= gamma) = erf(sqrt(gamma/2)) - sqrt(2 gamma/pi) exp(-gamma/2).
    const T g = params_.gate_chi2;
    const T pg = dmath::derf(std::sqrt(g / T(2))) -
                 std::sqrt(T(2) * g / dmath::kPi<T>) * dmath::dexp(-g / T(2));
    miss_ = T(1) - params_.pd * pg;
    if (!(miss_ > T(1e-6))) miss_ = T(1e-6);  // p_d = 1 with a wide gate
    cfg_.num_paths = params_.num_paths;
    cfg_.gate_chi2 = params_.fusion_gate_chi2;
    cfg_.min_paths = params_.fuse_min_paths;
    cfg_.min_variance = params_.min_variance;
    cfg_.defer_ambiguous = params_.fuse_defer_ambiguous;
  }

  // Without Doppler the range-rate row is uninformative: residual 0 and
  // the span squared as its variance (as the multipath tracker does,
  // docs/algorithms/multipath.md §Measurements).
  void set_scan_noise(bool has_doppler) {
    has_doppler_ = has_doppler;
    scan_r_var_ = r_var_;
    if (!has_doppler) {
      const T span_kmps = params_.range_rate_span_mps * T(1e-3);
      scan_r_var_(1) = span_kmps * span_kmps;
    }
  }

  // Step 2.
  void predict(PathTrack& t, T dt_s) {
    ++t.age_scans;
    if (!(dt_s > T(0))) return;
    model::cwna_predict(t.s, t.P, dt_s, params_.range_psd_m2ps3 * T(1e-6), params_.azimuth_psd_rad2ps3);
  }

  // Step 3: the gated detections of t (range window first) and its PDA update.
  void associate(PathTrack& t) {
    t.hit = false;
    t.measurement_index = -1;
    mptf::SlantGate<T> g;
    if (!mptf::slant_gate(t, scan_r_var_, g)) {
      ++counters_.numerical_repairs;  // S not SPD: the track misses this scan
      return;
    }
    const T half = std::sqrt(params_.gate_chi2) * g.L(0, 0);
    std::size_t n = 0;
    for (std::size_t q = det_.first_at_or_above(t.s(0) - half); q < det_.size(); ++q) {
      const std::size_t j = det_.by_range(q);
      if (det_.y(j)(0) > t.s(0) + half) break;
      model::OthrMeas<T> v = det_.y(j) - t.s.template head<3>();
      if (!has_doppler_) v(1) = T(0);
      const T d2 = mptf::gate_distance2(g, v);
      if (!(d2 <= params_.gate_chi2)) continue;
      in_gate_[j] = true;
      gate_v_[n] = v;
      gate_d2_[n] = d2;
      gate_j_[n] = static_cast<std::uint16_t>(j);
      ++n;
    }
    t.hit = n > 0;
    const int best = mptf::pda_update(t, g, gate_v_.data(), gate_d2_.data(), n, ln_pd_lambda_, miss_, beta_.data());
    if (best >= 0) t.measurement_index = static_cast<std::int32_t>(det_.scan_index(gate_j_[static_cast<std::size_t>(best)]));
    if (model::keep_spd_scaled(t.P, params_.min_variance)) ++counters_.numerical_repairs;
  }

  // Step 4: M/N logic, birth order kept.
  void manage() {
    std::size_t w = 0;
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      PathTrack& t = tracks_[i];
      const mptf::Verdict v = mptf::track_logic(t, params_.confirm_m1, params_.confirm_n1, params_.confirm_m2,
                                                params_.confirm_n2, params_.delete_misses);
      if (v == mptf::Verdict::kDelete || !t.finite()) {
        ++counters_.tracks_deleted;
        continue;
      }
      if (v == mptf::Verdict::kConfirm) {
        t.stage = mptf::TrackStage::kConfirmed;
        ++counters_.tracks_confirmed;
      }
      if (w != i) tracks_[w] = t;
      ++w;
    }
    static_cast<void>(tracks_.resize(w));  // shrinking cannot fail
  }

  // Step 5: a tentative track at every detection no track gated, in slant-range order.
  void births() {
    for (std::size_t q = 0; q < det_.size(); ++q) {
      const std::size_t j = det_.by_range(q);
      if (in_gate_[j]) continue;
      if (tracks_.size() == kMaxPathTracks) {
        ++counters_.track_cap_hits;
        continue;
      }
      PathTrack t;
      t.id = next_track_id_++;
      t.s << det_.y(j)(0), det_.y(j)(1), det_.y(j)(2), T(0);
      t.P.setZero();
      t.P(0, 0) = scan_r_var_(0);
      t.P(1, 1) = scan_r_var_(1);
      t.P(2, 2) = scan_r_var_(2);
      t.P(3, 3) = params_.init_azimuth_rate_std_radps * params_.init_azimuth_rate_std_radps;
      t.stage_hits = 1;  // the birth detection
      t.hit = true;
      t.measurement_index = static_cast<std::int32_t>(det_.scan_index(j));
      static_cast<void>(tracks_.push_back(t));  // size checked above
      ++counters_.tracks_born;
    }
  }

  // Step 6: confirmed path tracks (ascending ids: tracks_ is in birth order)
  // under every path, then the fusion table.
  void fuse() {
    std::size_t n = 0;
    for (const PathTrack& t : tracks_) {
      if (t.stage != mptf::TrackStage::kConfirmed) continue;
      if (n == kMaxCandidates) {
        ++counters_.association_cap_hits;
        continue;
      }
      typename Fusion::Cand& c = cand_[n++];
      c.track_id = t.id;
      c.measurement_index = t.hit ? t.measurement_index : -1;
      for (std::size_t p = 0; p < params_.num_paths; ++p) {
        c.ok[p] = model::othr_slant_to_ground(t.s, t.P, params_.paths[p], params_.baseline_km, c.x[p], c.P[p]);
      }
    }
    fusion_.update(cand_.data(), n, cfg_, counters_, next_fused_id_);
  }

  // Step 7.
  void report(const ScanType& scan) {
    static_cast<void>(outputs_.resize(1));  // capacity 1
    Estimate& e = outputs_[0];
    e.time_us = scan.time_us;
    e.scan_index = static_cast<std::uint32_t>(counters_.scans);
    e.tracks.clear();
    e.clutter.clear();
    for (const typename Fusion::Fused& f : fusion_.tracks()) {
      TrackReport<T> r;
      r.id = f.id;
      model::othr_ground_to_cartesian(f.x, f.P, r.state, r.covariance);
      r.existence = T(1);
      r.confirmed = true;
      r.measurement_index = f.measurement_index;
      static_cast<void>(e.tracks.push_back(r));  // kMaxFused == kMaxTargets
    }
  }

  Params params_{};
  StaticVector<PathTrack, kMaxPathTracks> tracks_;
  Fusion fusion_;
  typename Fusion::Config cfg_{};
  OutputQueue outputs_;
  TrackerCounters counters_{};
  ScanClock clock_;
  std::uint32_t next_track_id_ = 1;
  std::uint32_t next_fused_id_ = 1;
  bool initialized_ = false;
  T ln_pd_lambda_ = T(0), miss_ = T(1);
  model::OthrMeas<T> r_var_ = model::OthrMeas<T>::Ones();  ///< [km^2, (km/s)^2, rad^2]
  model::OthrMeas<T> scan_r_var_ = model::OthrMeas<T>::Ones();
  bool has_doppler_ = false;
  // Per-step scratch (members, not stack).
  model::OthrDetections<T, kMaxMeasurements> det_;  ///< this scan's valid detections
  std::array<bool, kMaxMeasurements> in_gate_{};
  std::array<model::OthrMeas<T>, kMaxMeasurements> gate_v_{};
  std::array<T, kMaxMeasurements> gate_d2_{};
  std::array<T, kMaxMeasurements> beta_{};
  std::array<std::uint16_t, kMaxMeasurements> gate_j_{};
  std::array<typename Fusion::Cand, kMaxCandidates> cand_{};
};

}  // namespace mptrack
