// Direct multi-object tracking on raw MIMO frames by variational message
// passing (seed 004, Westerkam et al.; docs/algorithms/vmp.md).
//
// Follows the tracker contract of tracker_contract.h with ScanType = one raw
// float RadarCube (the frame the ring buffer carries; time from cube.time_us),
// as an online filter: each accepted frame is finalised by its step(). Per frame
// (docs/algorithms/vmp.md §Per-frame schedule):
//   0. whitened in-band spectrum z (frontend/mimo_spectrum.h);
//   1. predict every track (window push, constant velocity with its learned
//      process noise) and its existence prior log-odds (eq. (17));
//   2. amplitudes and existences at the predicted positions (eqs. (12)-(16));
//   3. per track, strongest first: data message by Gauss-Newton (eq. (19)), then
//      N_OUT times one exact window smoother pass and the Gamma update of the
//      process-noise precisions (eqs. (20)-(25));
//   4. amplitudes and existences again at the updated positions; prune tracks
//      with logit xi < logit delta_minus;
//   5. greedy births from the residual (Alg. 2), at most B_MAX, each accepted
//      only if its existence log-odds exceed logit(1 - p_b);
//   6. report every track (state [px, vx, py, vy], covariance, existence xi,
//      SNR (|mu|^2 + C_kk) Gamma_kk; confirmed = xi >= delta_minus).
// A frame with a NaN/Inf sample is not used: tracks coast (prediction only),
// counted in measurements_invalid (measurements_in counts frames), kPartial.
// Memory: everything is a member (141 KB for float and VmpDefaultCaps);
// place the tracker in static storage.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cmath>

#include "mptrack/frontend/mimo_spectrum.h"
#include "mptrack/frontend/radar_caps.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/mimo_atom.h"
#include "mptrack/model/mimo_range_angle_map.h"
#include "mptrack/profile.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"
#include "mptrack/validate.h"
#include "mptrack/vmp/amplitude_existence.h"
#include "mptrack/vmp/data_message.h"
#include "mptrack/vmp/existence.h"
#include "mptrack/vmp/track_chain.h"
#include "mptrack/vmp/vmp_caps.h"
#include "mptrack/vmp/vmp_params.h"
#include "mptrack/vmp/vmp_track.h"

namespace mptrack {

template <class T, class Caps = VmpDefaultCaps, class RadarCaps = frontend::Seed004RadarCaps>
class VmpTracker {
  static_assert(vmp_caps_are_valid<Caps>());

 public:
  using Scalar = T;
  using Params = VmpParams;
  using ScanType = frontend::RadarCube<RadarCaps>;
  using Estimate = ScanEstimate<T, Caps::kMaxTargets, 0>;
  using OutputQueue = StaticVector<Estimate, 1>;

  static constexpr std::size_t kMaxTracks = Caps::kMaxTargets;
  static constexpr std::size_t kWindow = Caps::kWindow;
  /// Distinct birth-map peaks examined per birth (docs/algorithms/vmp.md §Births).
  static constexpr std::size_t kPeakTries = 3;
  using Spectrum = frontend::MimoSpectrum<T, RadarCaps>;
  static constexpr std::size_t kNV = Spectrum::kNumVirtual;
  static constexpr std::size_t kKB = Spectrum::kNumBins;
  static constexpr std::size_t kSize = Spectrum::kSize;
  using Basis = model::MimoAtomBasis<T, kNV, kKB>;
  using Atom = model::MimoAtom<T, kNV, kKB>;
  using Track = vmp::VmpTrack<T, kWindow, kNV, kKB>;

  /// Field ranges (VmpParams::validate), then the fit to the caps: births per
  /// frame, birth-map grid size, chirp length.
  static Status validate(const Params& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "max_births_per_frame", check_at_most(p.max_births_per_frame, Caps::kMaxBirthsPerFrame, "Caps::kMaxBirthsPerFrame"));
    MPTRACK_CHECK_PARAM(where, "map_range_step_m",
                        check((p.max_range_m - p.min_range_m) / p.map_range_step_m + 1.0 <=
                              static_cast<double>(Caps::kMapRangeCells)));
    MPTRACK_CHECK_PARAM(where, "map_sin_step",
                        check(2.0 * dmath::dsin(p.max_abs_bearing_rad) / p.map_sin_step + 1.0 <=
                              static_cast<double>(Caps::kMapAngleCells)));
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s",
                        check(p.chirp_duration_s * p.sample_rate_hz + 0.5 <
                              static_cast<double>(RadarCaps::kNumSamples) + 1.0));
    return Status::kOk;
  }

  /// Validates, builds the chirp spectrum, atom basis and birth map, and resets:
  /// no tracks, zero counters, ids from 1. On failure the tracker is uninitialised.
  Status init(const Params& params) {
    static_assert(tracker_contract_holds<VmpTracker>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(params));
    params_ = params;
    frontend::MimoSpectrumConfig sc;
    sc.bandwidth_hz = params.bandwidth_hz;
    sc.chirp_duration_s = params.chirp_duration_s;
    sc.sample_rate_hz = params.sample_rate_hz;
    sc.noise_variance_v2 = params.noise_variance_v2;
    MPTRACK_TRY(spectrum_.init(sc));
    // rho~(r) = sqrt(mean RCS) A G lambda / ((4 pi)^1.5 r^2 sigma_w) (docs/algorithms/vmp.md §Signal model).
    const double lambda_m = 299792458.0 / params.carrier_hz;
    const double four_pi = 4.0 * dmath::kPi<double>;
    const double rho_scale = std::sqrt(params.mean_rcs_m2) * params.tx_amplitude * params.antenna_gain * lambda_m /
                             (four_pi * std::sqrt(four_pi) * std::sqrt(params.noise_variance_v2));
    basis_.init(spectrum_.u_re(), spectrum_.u_im(), spectrum_.f_hz(), static_cast<T>(params.element_spacing_wavelengths),
                static_cast<T>(rho_scale));
    MPTRACK_TRY(check(map_.init(basis_, static_cast<T>(params.min_range_m), static_cast<T>(params.max_range_m),
                                static_cast<T>(params.map_range_step_m),
                                static_cast<T>(dmath::dsin(params.max_abs_bearing_rad)),
                                static_cast<T>(params.map_sin_step))));
    msg_.iterations = params.gn_iterations;
    msg_.max_step_m = static_cast<T>(params.gn_max_step_m);
    msg_.tol_m = static_cast<T>(params.gn_tol_m);
    msg_.backtracks = params.gn_backtracks;
    msg_.min_energy = static_cast<T>(params.min_message_energy);
    msg_.min_precision = static_cast<T>(params.min_message_precision);
    msg_.max_precision = static_cast<T>(params.max_message_precision);
    msg_.literal = params.literal_path_loss_derivative;
    msg_.diagonal = params.diagonal_message;
    logit_ps_ = static_cast<T>(vmp::logit(params.survival_probability));
    logit_pb_ = static_cast<T>(vmp::logit(params.birth_probability));
    logit_prune_ = static_cast<T>(vmp::logit(params.prune_existence));
    logit_birth_ = -logit_pb_;  // logit(1 - p_b)
    lambda_p_ = static_cast<T>(params.amplitude_prior_precision);
    const T l0 = static_cast<T>(params.gamma_shape_zeta / params.gamma_rate_chi);
    lambda0_ << l0, l0, l0, l0;
    tracks_.clear();
    outputs_.clear();
    counters_ = TrackerCounters{};
    next_id_ = 1;
    clock_.start(params.max_gap_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Consumes one frame; see the file comment. kNotInitialized / kOutOfOrder
  /// refuse it whole (counted in scans_rejected, outputs() empty); kPartial for a
  /// frame with NaN/Inf samples (tracks coast); kCapacityExceeded when a birth was
  /// refused because kMaxTracks tracks are alive (track_cap_hits); else kOk.
  Status step(const ScanType& cube) {
    outputs_.clear();
    MPTRACK_TRY(clock_.admit(initialized_, cube.time_us, counters_));
    MPTRACK_PROFILE_STEP(g_vmp);
    MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kInput);
    const std::uint64_t caps_before = total_cap_hits(counters_);
    if (clock_.restart_on_gap(cube.time_us, tracks_.size(), counters_)) tracks_.clear();
    const T dt = clock_.elapsed_s(cube.time_us, static_cast<T>(params_.frame_period_s));
    ++counters_.measurements_in;
    const bool usable = spectrum_.process(cube) == Status::kOk;
    if (!usable) ++counters_.measurements_invalid;
    predict(dt);
    if (usable) {
      amplitudes_and_existence();
      data_messages();
      amplitudes_and_existence();
    } else {
      // No data: the prior log-odds, and one window pass so that the filtered
      // marginal the window freezes next (next_tail) belongs to its new oldest frame.
      for (Track& t : tracks_) {
        t.logit_xi = t.g;
        counters_.numerical_repairs += smoother_.smooth(t.chain, static_cast<T>(params_.min_variance));
      }
    }
    MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kOutput);
    const bool pruned = prune();
    if (usable) births(pruned);
    for (Track& t : tracks_) t.xi_prev = vmp::sigmoid(t.logit_xi);
    report(cube.time_us);
    clock_.advance(cube.time_us);
    ++counters_.scans;
    return accepted_status(counters_, caps_before, !usable);
  }

  /// End of data. An online filter holds nothing: clears outputs().
  Status flush() {
    outputs_.clear();
    return initialized_ ? Status::kOk : Status::kNotInitialized;
  }

  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  const Params& params() const { return params_; }
  /// Live tracks, in birth order.
  const StaticVector<Track, kMaxTracks>& tracks() const { return tracks_; }
  /// The whitened spectrum of the last frame and the atom basis (tests, tools).
  const Spectrum& spectrum() const { return spectrum_; }
  const Basis& basis() const { return basis_; }

 private:
  using Vec4 = vmp::Vec4<T>;
  using Mat4 = vmp::Mat4<T>;
  using Mat2 = vmp::Mat2<T>;
  using Cx = model::Cx<T>;

  void set_atom(Track& t) { model::make_atom(basis_, t.x_gamma(0), t.x_gamma(2), T(-1), t.atom); }

  // Step 1: constant-velocity prediction with each track's learned process
  // noise; prior log-odds g = xi_prev (logit p_s - logit p_b) + logit p_b (eq. (17)).
  void predict(T dt) {
    const Mat4 f = vmp::cv_transition(dt);
    for (Track& t : tracks_) {
      t.x_gamma = f * t.chain.x;
      t.p_gamma = f * t.chain.p * f.transpose() + vmp::process_noise(dt, t.chain.lambda);
      t.chain.push(dt);
      t.chain.x = t.x_gamma;  // until the data message arrives
      t.chain.p = t.p_gamma;
      t.g = prior_logit(t.xi_prev);
      t.logit_xi = t.g;
      set_atom(t);
    }
  }

  T prior_logit(T xi_prev) const {
    if (!params_.predictive_existence_prior) return xi_prev * (logit_ps_ - logit_pb_) + logit_pb_;
    const T ps = static_cast<T>(params_.survival_probability);
    const T pb = static_cast<T>(params_.birth_probability);
    return vmp::logit(ps * xi_prev + pb * (T(1) - xi_prev));  // in [p_b, p_s]: finite
  }

  // Gamma_kk with the delta-method trace tr(P_pos Re{J^H J}) (seed 004 eq. (34)).
  T gram_diagonal(const Track& t) const {
    const auto b = model::atom_fisher(basis_, t.atom, params_.literal_path_loss_derivative);
    const T tr = t.p_gamma(0, 0) * b(0, 0) + T(2) * t.p_gamma(0, 2) * b(0, 1) + t.p_gamma(2, 2) * b(1, 1);
    return model::atom_norm2(basis_, t.atom) + tr;
  }

  // The q(alpha), q(xi) problem of the first n tracks (existing logits as start).
  void fill_problem(std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      const Track& t = tracks_[k];
      q_.c(k) = model::atom_inner(t.atom, spectrum_.z_re(), spectrum_.z_im());
      q_.gamma(k, k) = Cx{gram_diagonal(t), T(0)};
      q_.g(k) = t.g;
      q_.logit_xi(k) = t.logit_xi;
      for (std::size_t j = 0; j < k; ++j) {
        q_.gamma(k, j) = model::atom_gram(basis_, t.atom, tracks_[j].atom);
        q_.gamma(j, k) = model::cx_conj(q_.gamma(k, j));
      }
    }
  }

  // Steps 2 and 4 (eqs. (12)-(16)).
  void amplitudes_and_existence() {
    MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kAmplitudeExistence);
    const std::size_t n = tracks_.size();
    q_.reset(n, lambda_p_);
    fill_problem(n);
    counters_.numerical_repairs += q_.sweep(params_.existence_sweeps, static_cast<T>(params_.existence_tol));
    if (!q_.solve_amplitudes()) ++counters_.numerical_repairs;
    for (std::size_t k = 0; k < n; ++k) {
      Track& t = tracks_[k];
      t.logit_xi = q_.logit_xi(k);
      t.mu = q_.mu(k);
      t.snr = (model::cx_norm2(t.mu) + q_.cov(k, k).re) * q_.gamma(k, k).re;
    }
  }

  // buf = scale z - sum_{j in tracks, j != skip} coef_j s_j.
  template <class Coef>
  void residual(Cx scale, std::size_t skip, Coef&& coef) {
    const T* zr = spectrum_.z_re();
    const T* zi = spectrum_.z_im();
    for (std::size_t i = 0; i < kSize; ++i) {
      buf_re_[i] = scale.re * zr[i] - scale.im * zi[i];
      buf_im_[i] = scale.re * zi[i] + scale.im * zr[i];
    }
    for (std::size_t j = 0; j < tracks_.size(); ++j) {
      if (j == skip) continue;
      const Cx c = coef(j);
      model::atom_accumulate(tracks_[j].atom, Cx{-c.re, -c.im}, buf_re_.data(), buf_im_.data());
    }
  }

  // Step 3: per track, strongest first (Gauss-Seidel over tracks).
  void data_messages() {
    MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kDataMessage);
    const std::size_t n = tracks_.size();
    for (std::size_t k = 0; k < n; ++k) {
      const T w = model::atom_norm2(basis_, tracks_[k].atom) * model::cx_norm2(tracks_[k].mu);
      std::size_t i = k;
      while (i > 0 &&
             model::atom_norm2(basis_, tracks_[order_[i - 1]].atom) * model::cx_norm2(tracks_[order_[i - 1]].mu) < w) {
        order_[i] = order_[i - 1];
        --i;
      }
      order_[i] = k;
    }
    for (std::size_t o = 0; o < n; ++o) {
      const std::size_t k = order_[o];
      Track& t = tracks_[k];
      const T xi = q_.xi(k);
      const T e = xi * (model::cx_norm2(q_.mu(k)) + q_.cov(k, k).re);
      const Cx mk_conj = model::cx_conj(q_.mu(k));
      // r~_k = mu_k^* z - sum_{j != k} xi_j (mu_k^* mu_j + C_jk) s_j (eq. (32) with the C_jk terms).
      residual(mk_conj, k, [&](std::size_t j) {
        return model::cx_scale(model::cx_add(model::cx_mul(mk_conj, q_.mu(j)), q_.cov(j, k)), q_.xi(j));
      });
      const auto m = vmp::data_message(basis_, t.x_gamma(0), t.x_gamma(2), buf_re_.data(), buf_im_.data(), xi, e,
                                       msg_, cand_, trial_);
      if (m.repaired) ++counters_.numerical_repairs;
      vmp::ChainSlot<T>& slot = t.chain.newest();
      slot.has_msg = m.valid;
      slot.m = m.m;
      slot.omega = m.omega;
      MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kChain);  // to the end of this object's turn
      for (std::size_t it = 0; it < params_.outer_iterations; ++it) {
        counters_.numerical_repairs += smoother_.smooth(t.chain, static_cast<T>(params_.min_variance));
        smoother_.update_gamma(t.chain, static_cast<T>(params_.gamma_shape_zeta),
                               static_cast<T>(params_.gamma_rate_chi), static_cast<T>(params_.gamma_rate_floor));
      }
      t.x_gamma = t.chain.x;
      t.p_gamma = t.chain.p;
      set_atom(t);
    }
  }

  bool in_region(T x, T y, T margin_m) const {
    const T r = std::sqrt(x * x + y * y);
    if (!(y > T(0)) || !(r >= static_cast<T>(params_.min_range_m) - margin_m) ||
        !(r <= static_cast<T>(params_.max_range_m) + margin_m)) {
      return false;
    }
    return x / r <= static_cast<T>(dmath::dsin(params_.max_abs_bearing_rad)) + margin_m / r &&
           -x / r <= static_cast<T>(dmath::dsin(params_.max_abs_bearing_rad)) + margin_m / r;
  }

  // Step 4 (pruning): logit xi < logit delta_minus, or the track left the region.
  bool prune() {
    bool any = false;
    std::size_t i = 0;
    while (i < tracks_.size()) {
      const Track& t = tracks_[i];
      if (!(t.logit_xi >= logit_prune_) || !in_region(t.chain.x(0), t.chain.x(2), T(5))) {
        static_cast<void>(tracks_.erase(i));
        ++counters_.tracks_deleted;
        any = true;
      } else {
        ++i;
      }
    }
    return any;
  }

  // Step 5: greedy births on the residual (seed 004 Alg. 2); see docs/algorithms/vmp.md §Births.
  // Each round tries the best kPeakTries distinct map peaks (a refused peak, e.g. a
  // strong track's unexplained remainder, must not hide a new object elsewhere)
  // and accepts the first candidate whose existence log-odds exceed logit(1 - p_b).
  void births(bool refresh) {
    MPTRACK_PROFILE_STAGE(g_vmp, VmpStage::kBirth);
    if (refresh) amplitudes_and_existence();
    const T nve = static_cast<T>(kNV) * basis_.e_u();
    // Incremental objective |s^H r|^2 / rho_S - ln rho_S, rho_S ~ ||s||^2 + lambda_p.
    const auto score = [&](T r, T, T p) {
      const T rho2 = basis_.rho(r) * basis_.rho(r);
      const T den = rho2 * nve + lambda_p_;
      return rho2 * p / den - dmath::dlog(den);
    };
    const auto coef = [&](std::size_t j) { return model::cx_scale(tracks_[j].mu, vmp::sigmoid(tracks_[j].logit_xi)); };
    for (std::size_t b = 0; b < params_.max_births_per_frame; ++b) {
      residual(Cx{T(1), T(0)}, kMaxTracks, coef);
      map_.evaluate(basis_, buf_re_.data(), buf_im_.data());
      bool born = false;
      std::size_t n_excl = 0;
      for (std::size_t attempt = 0; attempt < kPeakTries && !born; ++attempt) {
        const auto peak = map_.best(score, excl_.data(), n_excl, kExclRange_m, kExclSin);
        if (!peak.found) return;
        excl_[n_excl++] = peak;
        if (attempt > 0) residual(Cx{T(1), T(0)}, kMaxTracks, coef);  // refine_candidate overwrote it
        const vmp::PositionMessage<T> m = refine_candidate(peak);
        if (!m.valid || !in_region(m.m(0), m.m(1), T(0))) continue;
        if (!(candidate_logit(m) > logit_birth_)) continue;
        if (tracks_.full()) {
          ++counters_.track_cap_hits;
          return;
        }
        add_track(m);
        amplitudes_and_existence();
        born = true;
      }
      if (!born) return;
    }
  }

  // Gauss-Newton on the residual in buf_ from a map peak, with the candidate's
  // concentrated amplitude (xi = 1); leaves the refined atom in cand_.
  vmp::PositionMessage<T> refine_candidate(const model::MapPeak<T>& peak) {
    const T x0 = peak.range_m * peak.sin_t;
    const T y0 = peak.range_m * std::sqrt(T(1) - peak.sin_t * peak.sin_t);
    model::make_atom(basis_, x0, y0, T(-1), cand_);
    const T prec = model::atom_norm2(basis_, cand_) + lambda_p_;
    const Cx mu = model::cx_scale(model::atom_inner(cand_, buf_re_.data(), buf_im_.data()), T(1) / prec);
    const T e = model::cx_norm2(mu) + T(1) / prec;
    for (std::size_t i = 0; i < kSize; ++i) {  // r~ = mu^* r
      const T re = buf_re_[i], im = buf_im_[i];
      buf_re_[i] = mu.re * re + mu.im * im;
      buf_im_[i] = mu.re * im - mu.im * re;
    }
    vmp::PositionMessage<T> m =
        vmp::data_message(basis_, x0, y0, buf_re_.data(), buf_im_.data(), T(1), e, msg_, cand_, trial_);
    if (m.valid) model::make_atom(basis_, m.m(0), m.m(1), T(-1), cand_);
    return m;
  }

  // Existence log-odds of the candidate in cand_ against the current tracks
  // (eq. (16) with g = logit p_b: it has no predecessor).
  T candidate_logit(const vmp::PositionMessage<T>& m) {
    const std::size_t n = tracks_.size();
    q_.reset(n + 1, lambda_p_);
    fill_problem(n);
    const auto b = model::atom_fisher(basis_, cand_, params_.literal_path_loss_derivative);
    const T det = m.omega(0, 0) * m.omega(1, 1) - m.omega(0, 1) * m.omega(1, 0);
    // tr(Omega^-1 B) with Omega^-1 = adj(Omega) / det.
    const T tr = (m.omega(1, 1) * b(0, 0) - T(2) * m.omega(0, 1) * b(0, 1) + m.omega(0, 0) * b(1, 1)) / det;
    q_.c(n) = model::atom_inner(cand_, spectrum_.z_re(), spectrum_.z_im());
    q_.gamma(n, n) = Cx{model::atom_norm2(basis_, cand_) + tr, T(0)};
    q_.g(n) = logit_pb_;
    q_.logit_xi(n) = logit_pb_;
    for (std::size_t j = 0; j < n; ++j) {
      q_.gamma(n, j) = model::atom_gram(basis_, cand_, tracks_[j].atom);
      q_.gamma(j, n) = model::cx_conj(q_.gamma(n, j));
    }
    vmp::ExistenceTerms<T> te;
    if (!q_.terms(n, te)) {
      ++counters_.numerical_repairs;
      return logit_pb_;
    }
    return vmp::maximise_existence(te);
  }

  void add_track(const vmp::PositionMessage<T>& m) {
    static_cast<void>(tracks_.resize(tracks_.size() + 1));  // checked full() before
    Track& t = tracks_[tracks_.size() - 1];
    t.id = next_id_++;
    const T sv = static_cast<T>(params_.birth_velocity_std_mps);
    t.chain.start(m.m, m.omega, lambda0_, sv * sv);
    counters_.numerical_repairs += smoother_.smooth(t.chain, static_cast<T>(params_.min_variance));
    t.x_gamma = t.chain.x;
    t.p_gamma = t.chain.p;
    t.atom = cand_;
    t.g = logit_pb_;
    t.logit_xi = logit_pb_;
    t.xi_prev = T(0);
    t.mu = Cx{};
    t.snr = T(0);
    ++counters_.tracks_born;
    ++counters_.tracks_confirmed;  // born with xi > 1 - p_b > delta_minus
  }

  // Step 6.
  void report(std::uint64_t time_us) {
    static_cast<void>(outputs_.resize(1));  // capacity 1: cannot fail
    Estimate& e = outputs_[0];
    e.time_us = time_us;
    e.scan_index = static_cast<std::uint32_t>(counters_.scans);
    e.tracks.clear();
    e.clutter.clear();
    for (const Track& t : tracks_) {
      TrackReport<T> r;
      r.id = t.id;
      r.state = t.chain.x;
      r.covariance = t.chain.p;
      r.existence = vmp::sigmoid(t.logit_xi);
      r.snr = t.snr;
      r.confirmed = t.logit_xi >= logit_prune_;
      static_cast<void>(e.tracks.push_back(r));  // tracks_.size() <= capacity
    }
  }

  Params params_{};
  StaticVector<Track, kMaxTracks> tracks_;
  OutputQueue outputs_;
  TrackerCounters counters_{};
  ScanClock clock_;
  Spectrum spectrum_;
  Basis basis_;
  model::MimoRangeAngleMap<T, kNV, kKB, Caps::kMapRangeCells, Caps::kMapAngleCells> map_;
  vmp::MessageSettings<T> msg_{};
  vmp::AmplitudeExistence<T, kMaxTracks + 1> q_;
  vmp::ChainSmoother<T, kWindow> smoother_;
  // Per-step scratch (members, not stack).
  std::array<T, kSize> buf_re_{};
  std::array<T, kSize> buf_im_{};
  std::array<std::size_t, kMaxTracks> order_{};
  std::array<model::MapPeak<T>, kPeakTries> excl_{};
  /// Exclusion half-widths around a refused peak: half the range resolution
  /// c / (2 BW) and half the array beamwidth 2 / N_V in sin theta.
  static constexpr T kExclRange_m = T(3.75);
  static constexpr T kExclSin = T(1) / T(9);
  Atom cand_{};
  Atom trial_{};
  Vec4 lambda0_ = Vec4::Ones();
  T logit_ps_ = T(0), logit_pb_ = T(0), logit_prune_ = T(0), logit_birth_ = T(0), lambda_p_ = T(1);
  std::uint32_t next_id_ = 1;
  bool initialized_ = false;
};

}  // namespace mptrack
