// Multipath MF-BP: joint detection and tracking when one target returns up
// to one detection per propagation path per scan (seed 002, OTHR;
// docs/algorithms/multipath.md).
//
// An online filter (docs/algorithms/multipath.md §Online filter): the
// paper's variational Bayes runs here on the current scan, with the
// previous posterior as prior. Per step():
//   1. intake: valid detections (region, range-rate span, NaN) in km units;
//   2. predict every track (model/cwna_motion.h) and its meta-state
//      (the transition of seed 002 eq. (38));
//   3. vb_iterations passes of
//      a. association: every track is num_paths pseudo-targets (i, tau);
//         gated pairs get the mean-field log-evidence of seed 002 eq. (43)
//         normalised by clutter and "missed" (the chi differences), and the
//         shared loopy BP (assoc/association_bp.h, uniform clutter source
//         only) gives E[a^{i,j,tau}] under the corrected constraints: one
//         detection per (target, path), one origin per detection;
//      b. meta-state: q(s = 1) from the expected detections over all paths
//         (seed 002 eqs. (38)-(40), one forward step);
//      c. state: synthetic measurement per path and the stacked update from
//         the prior, linearised at the current iterate (multipath/path_fusion.h);
//   4. management: counting threshold, deletion when the mean q(s = 1) of
//      the last delete_window scans is below delete_existence;
//   5. births from multi-detection groups among detections the association
//      left to clutter (multipath/group_birth.h);
//   6. report the counted tracks (Cartesian ground frame, path_track.h), at
//      once or smoothed smoothing_lag_scans later (multipath/fixed_lag_smoother.h).
//
// Memory: everything is a member, sized by Caps (kMaxTargets x kMaxPaths
// pseudo-targets, kMaxGatePairs each); place the tracker in static storage.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/assoc/association_bp.h"
#include "mptrack/caps.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/model/cwna_motion.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/model/othr_detections.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/model/spd_guard_scaled.h"
#include "mptrack/multipath/fixed_lag_smoother.h"
#include "mptrack/multipath/group_birth.h"
#include "mptrack/multipath/multipath_caps.h"
#include "mptrack/multipath/multipath_params.h"
#include "mptrack/multipath/path_fusion.h"
#include "mptrack/multipath/path_track.h"
#include "mptrack/multipath/retrodiction.h"
#include "mptrack/multipath/track_output.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T, class Caps = DefaultCaps>
class MultipathMfbpTracker {
  static_assert(caps_are_valid<Caps>());
  static_assert(multipath::multipath_caps_are_valid<Caps>());

 public:
  using Scalar = T;
  using Params = MultipathParams<T>;
  using ScanType = Scan<T, Caps::kMaxMeasurements>;
  using Estimate = ScanEstimate<T, Caps::kMaxTargets, Caps::kMaxClutterComponents>;
  static constexpr std::size_t kMaxLag = multipath::kMaxSmoothingLag<Caps>;
  /// One finalised scan per step; flush() and a restart after a gap give
  /// every scan the smoother still holds.
  using OutputQueue = StaticVector<Estimate, kMaxLag + 1>;

  static constexpr std::size_t kMaxTracks = Caps::kMaxTargets;
  static constexpr std::size_t kMaxMeasurements = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxPaths = multipath::kMaxPaths<Caps>;
  static constexpr std::size_t kGatePairs = multipath::kMaxPathGatePairs<Caps>;
  static constexpr std::size_t kPseudoTargets = kMaxTracks * kMaxPaths;
  using Track = multipath::PathTrack<T, kMaxPaths>;

  /// Checks params (MultipathParams::validate) and num_paths against Caps::kMaxPaths.
  static Status validate(const Params& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "num_paths", check_at_most(p.num_paths, kMaxPaths, "kMaxPaths"));
    MPTRACK_CHECK_PARAM(where, "smoothing_lag_scans", check_at_most(p.smoothing_lag_scans, kMaxLag, "kMaxSmoothingLag"));
    return Status::kOk;
  }

  /// Validates params and resets: no tracks, zero counters, ids from 1.
  Status init(const Params& params) {
    static_assert(tracker_contract_holds<MultipathMfbpTracker>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(params));
    params_ = params;
    derive_constants();
    tracks_.clear();
    outputs_.clear();
    smoother_.reset();
    counters_ = TrackerCounters{};
    next_id_ = 1;
    clock_.start(params_.max_gap_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Consumes one scan (statuses as every tracker: tracker_contract.h).
  /// Measurements outside the region or the range-rate span, or NaN/Inf,
  /// are skipped (measurements_invalid, kPartial); exact duplicates too
  /// (measurements_duplicate). Gated pairs beyond kMaxGatePairs per
  /// (track, path) are dropped, farthest first (association_cap_hits);
  /// births refused at kMaxTargets tracks count in track_cap_hits.
  Status step(const ScanType& scan) {
    outputs_.clear();
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    const std::uint64_t caps_before = total_cap_hits(counters_);
    if (clock_.restart_on_gap(scan.time_us, tracks_.size(), counters_)) {
      drain_smoother();  // the held-back scans belong to the old tracks
      tracks_.clear();
    }
    const std::size_t rejected = in_.select(scan, params_.region, params_.range_rate_span_mps, counters_);
    scan_time_us_ = scan.time_us;
    set_scan_noise(scan.has_doppler);
    predict(clock_.has_time() ? clock_.elapsed_s(scan.time_us, T(0)) : T(0));
    for (std::uint32_t r = 0; r < params_.vb_iterations; ++r) {
      associate(r == 0);  // first pass: caps counted once, predictive evidence
      update_tracks();
    }
    manage();
    births();
    if (params_.smoothing_lag_scans == 0) {
      report(scan);
    } else {
      report_lagged(scan);
    }
    clock_.advance(scan.time_us);
    ++counters_.scans;
    return accepted_status(counters_, caps_before, rejected > 0);
  }

  /// End of data: outputs() gets the scans the smoother still holds.
  Status flush() {
    outputs_.clear();
    if (!initialized_) return Status::kNotInitialized;
    drain_smoother();
    return Status::kOk;
  }

  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  const Params& params() const { return params_; }
  /// Live tracks in ground coordinates [km, km/s, rad, rad/s], birth order.
  const StaticVector<Track, kMaxTracks>& tracks() const { return tracks_; }

 private:
  using Bp = assoc::AssociationBp<T, kPseudoTargets, kMaxMeasurements, 1, kPseudoTargets * kGatePairs>;
  static constexpr T kMinWeight = T(1e-6);  ///< sum E[a] below this: no information on the path

  // Logs and unit conversions of the params, once per init().
  void derive_constants() {
    const std::size_t np = params_.num_paths;
    const T pd0 = params_.pd_dormant;
    ln_pd0_ = dmath::dlog(pd0);
    ln_miss0_ = dmath::dlog(T(1) - pd0);
    for (std::size_t p = 0; p < np; ++p) {
      ln_pd1_[p] = dmath::dlog(params_.pd[p]);
      ln_miss1_[p] = dmath::dlog(T(1) - params_.pd[p]);
    }
    r_var_ << params_.noise.range_std_m * params_.noise.range_std_m * T(1e-6),
        params_.noise.doppler_std_mps * params_.noise.doppler_std_mps * T(1e-6),
        params_.noise.azimuth_std_rad * params_.noise.azimuth_std_rad;
    // Clutter density per km (km/s) rad of the measurement box (seed 002 Sec. IV).
    const T volume = (params_.region.range_max_m - params_.region.range_min_m) * T(1e-3) *
                     (T(2) * params_.range_rate_span_mps * T(1e-3)) *
                     (params_.region.azimuth_max_rad - params_.region.azimuth_min_rad);
    ln_lambda_ = dmath::dlog(params_.clutter_mean_count / volume);
  }

  // Without Doppler the range-rate row is uninformative: its residual is 0
  // and its variance the span squared, about the uniform spread clutter has
  // on that axis (docs/algorithms/multipath.md §Measurements).
  void set_scan_noise(bool has_doppler) {
    has_doppler_ = has_doppler;
    scan_r_var_ = r_var_;
    if (!has_doppler) {
      const T span_kmps = params_.range_rate_span_mps * T(1e-3);
      scan_r_var_(1) = span_kmps * span_kmps;
    }
    half_ln_det_ = T(1.5) * dmath::kLnTwoPi<T>;
    for (int r = 0; r < 3; ++r) half_ln_det_ += T(0.5) * dmath::dlog(scan_r_var_(r));
  }

  // Step 2.
  void predict(T dt_s) {
    last_dt_s_ = dt_s;
    const T q_range = params_.range_psd_m2ps3 * T(1e-6);  // km^2/s^3
    for (Track& t : tracks_) {
      if (dt_s > T(0)) {
        model::cwna_predict(t.x, t.P, dt_s, q_range, params_.bearing_psd_rad2ps3);
        if (model::keep_spd_scaled(t.P, params_.min_variance)) ++counters_.numerical_repairs;
        t.existence = multipath::existence_predict(t.existence, params_.p_stay_active, params_.p_become_active);
      }
      t.x_prior = t.x;
      t.P_prior = t.P;
      t.existence_prior = t.existence;
    }
  }

  // Step 3a: pseudo-targets, gated pairs and their evidence, then BP.
  void associate(bool first_pass) {
    const std::size_t nv = in_.size();
    has_bp_ = false;
    if (tracks_.empty() || nv == 0) {
      for (std::size_t i = 0; i < tracks_.size(); ++i) pseudo_[i].fill(-1);
      return;
    }
    static_cast<void>(bp_.reset(nv, 1));  // nv <= kMaxMeasurements, one source
    for (std::size_t j = 0; j < nv; ++j) bp_.set_clutter_log(0, j, T(0));  // chi^0j - chi^0j
    std::int32_t n_pseudo = 0;
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      for (std::size_t p = 0; p < params_.num_paths; ++p) {
        pseudo_[i][p] = -1;
        if (!gate(tracks_[i], p, first_pass)) continue;
        add_pseudo_target(tracks_[i], p, first_pass);
        pseudo_[i][p] = n_pseudo++;
      }
    }
    const auto res = bp_.run(params_.bp_damping, params_.bp_tolerance, params_.bp_max_iterations);
    if (!res.converged) ++counters_.bp_not_converged;
    has_bp_ = true;
  }

  // Gated detections of (track, path): the kGatePairs closest in S^-1
  // (gate_d2_, gate_j_, gate_n_). False if the path cannot be linearised.
  bool gate(const Track& t, std::size_t p, bool count_caps) {
    lin_ = multipath::linearize_path(t.x, t.P, params_.paths[p], params_.baseline_km, scan_r_var_);
    gate_n_ = 0;
    if (!lin_.valid) return false;
    std::size_t dropped = 0;
    // Only detections within the gate's range extent sqrt(gamma S_rr) can pass.
    const T half = std::sqrt(params_.gate_chi2) * lin_.L(0, 0);
    for (std::size_t q = in_.first_at_or_above(lin_.h(0) - half); q < in_.size(); ++q) {
      const std::size_t j = in_.by_range(q);
      if (in_.y(j)(0) > lin_.h(0) + half) break;
      model::OthrMeas<T> v = in_.y(j) - lin_.h;
      if (!has_doppler_) v(1) = T(0);
      const T d2 = multipath::mahalanobis2(lin_, v);
      if (!(d2 <= params_.gate_chi2)) continue;
      if (gate_n_ == kGatePairs) {
        ++dropped;
        if (!(d2 < gate_d2_[gate_n_ - 1])) continue;
        --gate_n_;  // the farthest kept pair makes room
      }
      std::size_t k = gate_n_++;
      while (k > 0 && gate_d2_[k - 1] > d2) {
        gate_d2_[k] = gate_d2_[k - 1];
        gate_j_[k] = gate_j_[k - 1];
        --k;
      }
      gate_d2_[k] = d2;
      gate_j_[k] = static_cast<std::uint16_t>(j);
    }
    if (count_caps) counters_.association_cap_hits += dropped;
    return true;
  }

  // Seed 002 eq. (43) for the pairs of gate(), as log beta = chi^{i,j,tau}
  // - chi^{0,j} - chi^{i,0,tau}: clutter and "missed" normalised to 1
  // (docs/algorithms/multipath.md §Association). The first VB pass of a
  // scan (predictive = true) uses the predictive likelihood N(y; h, S)
  // instead of the mean-field E_q ln N(y; h(x), R): with the prior's
  // spread the trace penalty would reject every pair of a young track and
  // the iteration could not start (docs/algorithms/multipath.md §Departures
  // from the paper). Later passes use eq. (43) at the updated q(x).
  void add_pseudo_target(const Track& t, std::size_t p, bool predictive) {
    const T q1 = t.existence;
    const T q0 = T(1) - q1;
    const T detect = q1 * ln_pd1_[p] + q0 * ln_pd0_ - (q1 * ln_miss1_[p] + q0 * ln_miss0_);
    T base = detect - ln_lambda_;
    if (predictive) {
      T half_ln_det_s = T(1.5) * dmath::kLnTwoPi<T>;
      for (int r = 0; r < 3; ++r) half_ln_det_s += dmath::dlog(lin_.L(r, r));
      base -= half_ln_det_s;
    } else {
      base -= half_ln_det_ + T(0.5) * lin_.trace_penalty;
    }
    static_cast<void>(bp_.add_target(T(1)));  // <= kPseudoTargets pseudo-targets
    for (std::size_t k = 0; k < gate_n_; ++k) {
      const std::size_t j = gate_j_[k];
      T d = gate_d2_[k];
      if (!predictive) {
        const model::OthrMeas<T> v = in_.y(j) - lin_.h;
        d = v(0) * v(0) / scan_r_var_(0) + v(2) * v(2) / scan_r_var_(2);
        if (has_doppler_) d += v(1) * v(1) / scan_r_var_(1);
      }
      static_cast<void>(bp_.add_edge(j, base - T(0.5) * d));  // <= kGatePairs per pseudo-target
    }
  }

  // Steps 3b and 3c for every track.
  void update_tracks() {
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      Track& t = tracks_[i];
      T best = T(0.5);
      t.measurement_index = -1;
      for (std::size_t p = 0; p < params_.num_paths; ++p) {
        synth_w_[p] = T(0);
        synth_y_[p].setZero();
        const std::int32_t u = pseudo_[i][p];
        if (!has_bp_ || u < 0) continue;
        const std::size_t ui = static_cast<std::size_t>(u);
        for (std::size_t e = bp_.edge_begin(ui); e < bp_.edge_end(ui); ++e) {
          const T a = bp_.edge_belief(e);
          synth_w_[p] += a;
          synth_y_[p] += a * in_.y(bp_.edge_meas(e));
          if (a > best) {
            best = a;
            t.measurement_index = static_cast<std::int32_t>(in_.scan_index(bp_.edge_meas(e)));
          }
        }
      }
      for (std::size_t p = 0; p < params_.num_paths; ++p) t.detected[p] = synth_w_[p];
      t.existence = multipath::existence_update(t.existence_prior, t.detected.data(), params_.num_paths,
                                                ln_pd1_.data(), ln_miss1_.data(), ln_pd0_, ln_miss0_);
      update_state(t);
    }
  }

  // Step 3c: the stacked path update from the prior at the current iterate.
  void update_state(Track& t) {
    const model::OthrState<T> x_lin = t.x;
    model::OthrState<T> x = t.x_prior;
    multipath::Mat4<T> P = t.P_prior;
    for (std::size_t p = 0; p < params_.num_paths; ++p) {
      const T w = synth_w_[p];
      if (!(w > kMinWeight)) continue;
      const model::OthrMeas<T> y_bar = synth_y_[p] / w;
      if (!multipath::path_update(x, P, x_lin, params_.paths[p], params_.baseline_km, y_bar, w,
                                  scan_r_var_, has_doppler_)) {
        ++counters_.numerical_repairs;  // S not SPD: this path is skipped
      }
    }
    if (model::keep_spd_scaled(P, params_.min_variance)) ++counters_.numerical_repairs;
    t.x = x;
    t.P = P;
  }

  // Step 4: counting (confirmation) and deletion, birth order kept.
  void manage() {
    std::size_t w = 0;
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      Track& t = tracks_[i];
      ++t.age_scans;
      if (!t.confirmed && t.existence >= params_.confirm_existence) {
        t.confirmed = true;
        ++counters_.tracks_confirmed;
      }
      t.counted = t.existence >= (t.counted ? params_.hold_existence : params_.confirm_existence);
      t.record_existence();
      if (t.mean_existence(params_.delete_window) < params_.delete_existence || !t.finite()) {
        ++counters_.tracks_deleted;
        continue;
      }
      if (w != i) tracks_[w] = t;
      ++w;
    }
    static_cast<void>(tracks_.resize(w));  // shrinking cannot fail
  }

  // Step 5: groups of leftover detections, swept in slant range.
  void births() {
    std::size_t n = 0;
    for (std::size_t q = 0; q < in_.size(); ++q) {  // in slant-range order
      const std::size_t j = in_.by_range(q);
      const T clutter = has_bp_ ? bp_.clutter_belief(0, j) : T(1);
      used_[j] = false;
      if (clutter >= params_.birth_clutter_belief) cand_[n++] = static_cast<std::uint16_t>(j);
    }
    cand_n_ = n;
    const std::size_t max_members = params_.num_paths < multipath::kMaxGroup ? params_.num_paths : multipath::kMaxGroup;
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t ja = cand_[a];
      if (used_[ja]) continue;  // a member of an earlier group's birth (only a later anchor is tested)
      std::array<std::uint16_t, multipath::kMaxGroup> members{};
      std::size_t m = 0;
      members[m++] = static_cast<std::uint16_t>(ja);
      for (std::size_t b = a + 1; b < n && m < max_members; ++b) {
        const std::size_t jb = cand_[b];
        if (in_.y(jb)(0) - in_.y(ja)(0) > params_.group_range_m * T(1e-3)) break;  // sorted by range
        if (!used_[jb] && close(in_.y(ja), in_.y(jb))) members[m++] = static_cast<std::uint16_t>(jb);
      }
      if (m < params_.min_group_size) continue;
      if (try_birth(members.data(), m)) {
        for (std::size_t k = 0; k < m; ++k) used_[members[k]] = true;
      }
    }
  }

  bool close(const model::OthrMeas<T>& a, const model::OthrMeas<T>& b) const {
    const T dr = a(1) - b(1);
    const T dz = a(2) - b(2);
    const T rate_gate = has_doppler_ ? params_.group_range_rate_mps * T(1e-3) : T(1e30);
    return !(dr > rate_gate || -dr > rate_gate) && !(dz > params_.group_azimuth_rad || -dz > params_.group_azimuth_rad);
  }

  bool try_birth(const std::uint16_t* members, std::size_t m) {
    std::array<model::OthrMeas<T>, multipath::kMaxGroup> ys{};
    for (std::size_t k = 0; k < m; ++k) ys[k] = in_.y(members[k]);
    model::OthrMeas<T> sigma;
    for (int r = 0; r < 3; ++r) sigma(r) = std::sqrt(scan_r_var_(r));
    multipath::GroupHypothesis<T> second;
    const multipath::GroupHypothesis<T> h = multipath::best_path_assignment<T, kMaxPaths>(
        ys.data(), m, params_.paths.data(), params_.num_paths, params_.baseline_km, sigma, &second,
        params_.birth_distinct_range_m * T(1e-3));
    if (!h.valid || h.spread_per_dof > params_.birth_max_spread) return false;
    if (!spawn(h, m, in_.scan_index(members[0]))) return false;
    if (params_.birth_ambiguous_both && second.valid && !(second.spread_per_dof > params_.birth_max_spread)) {
      static_cast<void>(spawn(second, m, in_.scan_index(members[0])));
    }
    return true;
  }

  // A new track at the ground point of hypothesis h from m detections.
  bool spawn(const multipath::GroupHypothesis<T>& h, std::size_t m, std::size_t scan_index) {
    if (tracks_.size() == kMaxTracks) {
      ++counters_.track_cap_hits;
      return false;
    }
    static_cast<void>(tracks_.push_back(multipath::new_track<T, kMaxPaths>(
        h, m, params_, scan_r_var_, has_doppler_, next_id_++, static_cast<std::int32_t>(scan_index))));
    ++counters_.tracks_born;
    if (params_.smoothing_lag_scans > 0 && params_.retrodict_births) retrodict(tracks_[tracks_.size() - 1]);
    return true;
  }

  // Step 6, filter: the counted tracks of this scan.
  void report(const ScanType& scan) {
    Estimate& e = open_estimate(scan.time_us, static_cast<std::uint32_t>(counters_.scans));
    for (const Track& t : tracks_) {
      if (!t.counted && !params_.report_tentative) continue;
      multipath::add_ground_report(e, t.id, t.x, t.P, t.existence, t.counted, t.measurement_index);
    }
  }

  // A new track carried back through the held-back scans.
  void retrodict(const Track& t) {
    multipath::RetroModel<T> m;
    m.paths = params_.paths.data();
    m.num_paths = params_.num_paths;
    m.baseline_km = params_.baseline_km;
    m.ln_pd1 = ln_pd1_.data();
    m.ln_miss1 = ln_miss1_.data();
    m.ln_lambda = ln_lambda_;
    m.gate_chi2 = params_.gate_chi2;
    m.q_range = params_.range_psd_m2ps3 * T(1e-6);  // km^2/s^3
    m.q_bearing = params_.bearing_psd_rad2ps3;
    std::size_t refused = 0;
    static_cast<void>(multipath::retrodict(smoother_, t, scan_time_us_, m, refused));
    counters_.track_cap_hits += refused;
  }

  // Step 6, fixed lag: record this scan (tracks and the detections left
  // over for retrodiction), report the one smoothing_lag_scans back.
  void report_lagged(const ScanType& scan) {
    static_cast<void>(smoother_.open_scan(scan.time_us, static_cast<std::uint32_t>(counters_.scans)));  // popped below
    auto& slot = smoother_.newest();
    slot.r_var = scan_r_var_;
    slot.has_doppler = has_doppler_;
    for (std::size_t a = 0; a < cand_n_; ++a) {
      const std::size_t j = cand_[a];
      if (!used_[j]) static_cast<void>(slot.leftovers.push_back({in_.y(j), static_cast<std::uint16_t>(in_.scan_index(j)), false}));  // <= scan size
    }
    for (const Track& t : tracks_) {
      if (!smoother_.record(multipath::lag_entry(t, last_dt_s_))) ++counters_.track_cap_hits;
    }
    if (smoother_.pending() > params_.smoothing_lag_scans) emit_oldest();
  }

  // The oldest held-back scan, smoothed (multipath::counted_when_smoothed).
  void emit_oldest() {
    const auto& slot = smoother_.oldest();
    Estimate& e = open_estimate(slot.time_us, slot.scan_index);
    const multipath::LagModel<T> model{params_.p_stay_active, params_.p_become_active};
    for (std::size_t i = 0; i < slot.entries.size(); ++i) {
      multipath::SmoothedEntry<T> s;
      if (!smoother_.smooth(i, model, s)) ++counters_.numerical_repairs;
      const bool counted = multipath::counted_when_smoothed(s, params_.hold_existence);
      if (!counted && !params_.report_tentative) continue;
      multipath::add_ground_report(e, s.id, s.x, s.P, s.q, counted, s.measurement_index);
    }
    smoother_.pop();
  }

  void drain_smoother() {
    while (smoother_.pending() > 0) emit_oldest();
  }

  Estimate& open_estimate(std::uint64_t time_us, std::uint32_t scan_index) {
    return multipath::open_estimate(outputs_, time_us, scan_index);  // <= kMaxLag + 1 per step
  }

  Params params_{};
  StaticVector<Track, kMaxTracks> tracks_;
  OutputQueue outputs_;
  TrackerCounters counters_{};
  ScanClock clock_;
  std::uint32_t next_id_ = 1;
  bool initialized_ = false;
  multipath::FixedLagSmoother<T, kMaxTracks, kMaxLag, kMaxMeasurements> smoother_;
  std::uint64_t scan_time_us_ = 0;  ///< of the scan being processed
  T last_dt_s_ = T(0);  ///< time since the previous scan, 0 at the first [s]
  // Constants of the params (derive_constants) and of the scan (set_scan_noise).
  std::array<T, multipath::kParamPaths> ln_pd1_{}, ln_miss1_{};
  T ln_pd0_ = T(0), ln_miss0_ = T(0), ln_lambda_ = T(0), half_ln_det_ = T(0);
  model::OthrMeas<T> r_var_ = model::OthrMeas<T>::Ones();       ///< [km^2, (km/s)^2, rad^2]
  model::OthrMeas<T> scan_r_var_ = model::OthrMeas<T>::Ones();
  bool has_doppler_ = false;
  // Per-step scratch (members, not stack).
  model::OthrDetections<T, kMaxMeasurements> in_;  ///< this scan's valid detections, in slant-range order too
  std::array<std::array<std::int32_t, kMaxPaths>, kMaxTracks> pseudo_{};  ///< BP index of (i, tau), -1 = none
  Bp bp_;
  bool has_bp_ = false;
  multipath::PathLinearization<T> lin_;
  std::array<T, kGatePairs> gate_d2_{};
  std::array<std::uint16_t, kGatePairs> gate_j_{};
  std::size_t gate_n_ = 0;
  std::array<T, kMaxPaths> synth_w_{};
  std::array<model::OthrMeas<T>, kMaxPaths> synth_y_{};
  std::array<std::uint16_t, kMaxMeasurements> cand_{};  ///< birth candidates in slant-range order
  std::size_t cand_n_ = 0;
  std::array<bool, kMaxMeasurements> used_{};
};

}  // namespace mptrack
