// MF-BP multitarget tracker of seed 000 (paper: MP-RMTT, Bai et al.): mean-
// field + loopy-BP message passing over a sliding window, with target SNR,
// visibility and non-uniform clutter estimation (spec 3.0-3.12).
//
// Call pattern (the tracker contract of track_report.h):
//   static MfbpTracker<float, SmallBoardCaps> tracker;     // .bss, no heap
//   if (!ok(tracker.init(params))) { ... }
//   for each scan:  Status s = tracker.step(scan);        // kOk / kPartial / ...
//                   for (auto& est : tracker.outputs()) { ... }
//   at the end:     tracker.flush();
//
// One code path for both modes: window_length K = 1 is the online filter
// (every step finalises its scan), K = 7 / slide 3 the paper's smoother
// (a window is processed when K scans are held; `slide` scans are then
// finalised, flush() finalises the rest).
//
// Per processed window (spec 3.12):
//   1. "no information" association beliefs on new scans, the previous
//      window's beliefs on overlapping scans (spec 3.1);
//   2. one MF sweep (Dirichlet, visibility, clutter, targets) -> b^(0);
//   3. track birth (two-point) and clutter-component birth (grid seeds);
//   4. outer loop, up to mp_max_iterations: per scan local evidence and
//      loopy BP, then the MF sweep; stop when max |delta a_hat| < tolerance;
//   5. confirmation, output of the finalised scans, deletion, window shift
//      (the filtered beliefs at the last finalised scan become the priors).
//
// Doppler (not in the paper [impl]): when a scan has_doppler and
// use_doppler is set, the radial velocity joins the cubature update as a
// third measurement row and the association evidence (predictive density
// for targets, uniform on [-span, span] for clutter).
//
// Memory (sizeof, x86-64): float/SmallBoardCaps 72 160 B, float/DefaultCaps
// 280 160 B, double/DefaultCaps 523 888 B. The largest parts: per-track
// window beliefs, the stored scans, the BP messages and the output queue.
//
// Overflow policies (all counted, none silent):
//   * measurements: a Scan cannot exceed Caps::kMaxMeasurements, so no
//     measurement is dropped for capacity; invalid ones are skipped and
//     counted in measurements_invalid (step returns kPartial);
//   * gated pairs: each track keeps its kMaxGate most likely measurements
//     per scan (gate_overflows() counts the dropped pairs, step returns
//     kCapacityExceeded);
//   * tracks: births beyond kMaxTargets live tracks are refused
//     (track_cap_hits); components beyond kMaxClutterComponents likewise
//     (clutter_cap_hits); both make step return kCapacityExceeded.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/caps.h"
#include "mptrack/math/detmath.h"
#include "mptrack/measurement.h"
#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/association_bp.h"
#include "mptrack/mfbp/cavity.h"
#include "mptrack/mfbp/clutter_birth.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/dirichlet.h"
#include "mptrack/mfbp/inverse_gamma.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/normal_wishart.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/mfbp/track_birth.h"
#include "mptrack/mfbp/visibility_hmm.h"
#include "mptrack/profile.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T, class Caps = DefaultCaps>
class MfbpTracker {
  static_assert(caps_are_valid<Caps>());
  static_assert(Caps::kMaxWindow <= 64, "visibility_forward_backward keeps 64 scans at most");
  static_assert(Caps::kMaxTargets < 65535, "TrackSlot::mate is a 16-bit index");

 public:
  using Scalar = T;
  using Params = MfbpParams<T>;
  static constexpr std::size_t kMaxTargets = Caps::kMaxTargets;
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxComp = Caps::kMaxClutterComponents;
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  /// Gated measurements kept per track and scan (sparse association).
  static constexpr std::size_t kMaxGate = 8;
  /// Scans stored: the window, and in front of it as many finalised
  /// (history) scans as fit. The online filter (window 1) keeps 6 history
  /// scans for two-point birth (lag <= 3) and clutter seeding; a window-K
  /// smoother needs none: a birth pair that reaches before the window
  /// has its second point on an overlap scan and was considered already.
  static constexpr std::size_t kStore = kMaxWindow;
  static constexpr std::size_t kSources = kMaxComp + 1;  ///< + the uniform component
  static constexpr std::size_t kMaxGridCells = 512;  ///< seed grid (coarsened to fit)
  static constexpr std::size_t kMinSeedScans = 7;    ///< seed threshold counts >= 7 scans

  using ScanType = Scan<T, kMaxMeas>;
  using Estimate = ScanEstimate<T, kMaxTargets, kMaxComp>;
  using OutputQueue = StaticVector<Estimate, kMaxWindow>;

  /// Validates params (mfbp_params.h) and resets every state.
  Status init(const Params& params) {
    initialized_ = false;
    MPTRACK_TRY(validate(params, kMaxWindow));
    params_ = params;
    n_order_ = mfbp::swerling_order(params.swerling);
    volume_ = (params.r_max_m - params.r_min_m) * (params.az_max_rad - params.az_min_rad);
    log_volume_ = dmath::dlog(volume_);
    R_.setZero();
    R_(0, 0) = params.sigma_r_m * params.sigma_r_m;
    R_(1, 1) = params.sigma_az_rad * params.sigma_az_rad;
    R_inv_.setZero();
    R_inv_(0, 0) = T(1) / R_(0, 0);
    R_inv_(1, 1) = T(1) / R_(1, 1);
    log_norm_R_ = -T(1.8378770664093453) - T(0.5) * dmath::dlog(R_(0, 0) * R_(1, 1));
    for (auto& t : tracks_) t.alive = false;
    for (auto& c : comps_) c.alive = false;
    counters_ = TrackerCounters{};
    outputs_.clear();
    n_hist_ = 0;
    n_win_ = 0;
    next_track_id_ = 1;
    next_comp_id_ = 1;
    finalized_ = 0;
    gate_overflows_ = 0;
    bp_runs_ = 0;
    bp_iterations_ = 0;
    clock_.reset();
    clock_.set_max_gap_s(params_.max_gap_s);
    // Clutter priors at "scan -1".
    uniform_.ig0.a = params.uniform_cnr_prior_shape;
    uniform_.ig0.b = (T(1) + params.uniform_cnr_prior) * (params.uniform_cnr_prior_shape - T(1));
    uniform_.alpha0 = params.uniform_rate_per_scan;
    m_prev_ = params.uniform_rate_per_scan;
    initialized_ = true;
    return Status::kOk;
  }

  /// Replaces the known clutter map (ClutterMode::kKnown) between scans.
  Status set_known_clutter(const KnownClutter<T>& kc) {
    if (!initialized_) return Status::kNotInitialized;
    Params p = params_;
    p.known_clutter = kc;
    MPTRACK_TRY(validate(p, kMaxWindow));
    params_.known_clutter = kc;
    return Status::kOk;
  }

  /// Consumes one scan. kOutOfOrder (state unchanged) if time does not
  /// increase; kPartial if measurements were rejected (counted);
  /// kCapacityExceeded if an internal cap was hit (see the file comment;
  /// takes precedence over kPartial). Both are successes with losses.
  Status step(const ScanType& scan) {
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    outputs_.clear();
    step_cap_hit_ = false;
    if (clock_.gap_exceeded(scan.time_us)) {
      restart_after_gap();
      clock_.restart();
    }
    clock_.advance(scan.time_us);
    ++counters_.scans;
    MPTRACK_PROFILE_STEP(g_mfbp);
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kInput);
    const bool partial = store_scan(scan);
    ++n_win_;
    if (n_win_ >= params_.window_length) {
      process_window(params_.slide);
    }
    if (step_cap_hit_) return Status::kCapacityExceeded;
    return partial ? Status::kPartial : Status::kOk;
  }

  /// End of data: processes and finalises every scan still held back.
  Status flush() {
    if (!initialized_) return Status::kNotInitialized;
    outputs_.clear();
    step_cap_hit_ = false;
    MPTRACK_PROFILE_STEP(g_mfbp);
    if (n_win_ > 0) process_window(n_win_);
    return step_cap_hit_ ? Status::kCapacityExceeded : Status::kOk;
  }

  const OutputQueue& outputs() const { return outputs_; }
  const TrackerCounters& counters() const { return counters_; }
  /// Gated (track, measurement) pairs dropped by the kMaxGate cap.
  std::uint64_t gate_overflows() const { return gate_overflows_; }
  /// Loopy-BP runs and their total iterations since init() (diagnostics).
  std::uint64_t bp_runs() const { return bp_runs_; }
  std::uint64_t bp_iterations() const { return bp_iterations_; }
  const Params& params() const { return params_; }
  /// Live tracks (tentative and confirmed) right now.
  std::size_t live_tracks() const {
    std::size_t n = 0;
    for (const auto& t : tracks_) n += t.alive ? 1u : 0u;
    return n;
  }
  /// Live non-uniform clutter components right now.
  std::size_t live_components() const {
    std::size_t n = 0;
    for (const auto& c : comps_) n += c.alive ? 1u : 0u;
    return n;
  }

 private:
  using Vec2 = mfbp::Vec2<T>;
  using Vec4 = mfbp::Vec4<T>;
  using Mat2 = mfbp::Mat2<T>;
  using Mat4 = mfbp::Mat4<T>;
  using IG = mfbp::InverseGamma<T>;
  using AmpStats = mfbp::AmplitudeStats<T>;
  using NW = mfbp::NormalWishart<T>;
  using NwStats = mfbp::NwStats<T>;
  using Bp = mfbp::AssociationBp<T, kMaxTargets, kMaxMeas, kSources, kMaxTargets * kMaxGate>;

  /// One stored scan (window or history).
  struct ScanSlot {
    std::uint64_t time_us = 0;
    std::size_t count = 0;
    bool has_beliefs = false;          ///< BP has run on it (overlap scan)
    bool doppler = false;              ///< dop[] is valid and used
    T lambda_hat = T(0);               ///< expected clutter count used by the BP
    std::array<T, kMaxMeas> r{}, az{}, amp{}, dop{};
    std::array<std::uint16_t, kMaxMeas> orig_index{};
    std::array<T, kMaxMeas> target_share{};   ///< sum_i a_hat^t_ij
    std::array<T, kMaxMeas> uniform_share{};  ///< a_hat^c_0j
    std::array<std::uint8_t, kMaxMeas> consumed{};  ///< used by a two-point birth
    std::array<std::uint16_t, kMaxMeas> by_range{};  ///< indices sorted by (range, index)
    std::array<NwStats, kSources> nw_stats{};       ///< per source slot (0 = uniform)
    std::array<AmpStats, kSources> amp_stats{};
  };

  struct TrackSlot {
    bool alive = false;
    bool confirmed = false;
    bool from_birth = false;     ///< state at `first` is the birth state (no update there)
    std::uint32_t id = 0;
    std::size_t first = 0;       ///< first window scan of the track
    std::uint32_t low_run = 0;   ///< finalised consecutive scans with b_s < delete_threshold
    std::uint32_t age = 0;       ///< finalised scans since birth
    // prior: filtered at the scan before the window (or birth state)
    Vec4 x0 = Vec4::Zero();
    Mat4 P0 = Mat4::Identity();
    IG ig0{};
    T vis0 = T(0.5);
    Vec2 bias0 = Vec2::Zero();    ///< faded whitened innovation before the window
    T vis_emitted = T(1);         ///< b_s(1) at the last finalised scan reported on
    std::uint64_t t0_us = 0;
    // per window scan
    std::array<Vec4, kMaxWindow> xf{}, xs{};
    std::array<mfbp::PackedCov4<T>, kMaxWindow> Pf{}, Ps{};  // symmetric, packed
    std::array<IG, kMaxWindow> igf{}, igs{};
    std::array<AmpStats, kMaxWindow> amp{};
    std::array<T, kMaxWindow> xi1{}, xi0{}, visf{}, vis{}, extr{}, missed{};
    std::array<std::uint8_t, kMaxWindow> n_edges{};
    std::array<std::array<std::uint16_t, kMaxGate>, kMaxWindow> edge_meas{};
    std::array<std::array<T, kMaxGate>, kMaxWindow> edge_w{};
    std::array<std::int32_t, kMaxWindow> best{};
    std::array<Vec2, kMaxWindow> biasf{};  ///< faded whitened innovation after the update at k
    std::array<T, kMaxWindow> qk{};    ///< process noise used to predict into k [(m/s^2)^2]
    std::array<std::uint16_t, kMaxWindow> mate{};  ///< nearest unresolved track + 1 (0: none)
  };

  struct CompSlot {
    bool alive = false;
    std::uint32_t id = 0;
    std::uint32_t low_windows = 0;
    NW nw0{};
    IG ig0{};
    T alpha0 = T(1);
    std::array<NW, kMaxWindow> nwf{}, nws{};
    std::array<IG, kMaxWindow> igf{}, igs{};
  };

  struct UniformSlot {
    IG ig0{};
    T alpha0 = T(30);
    std::array<IG, kMaxWindow> igf{}, igs{};
  };

  // ---------------------------------------------------------------- input
  ScanSlot& win(std::size_t k) { return store_[n_hist_ + k]; }
  const ScanSlot& win(std::size_t k) const { return store_[n_hist_ + k]; }

  bool in_region(T r, T az) const {
    return !(r < params_.r_min_m) && !(r > params_.r_max_m) && !(az < params_.az_min_rad) &&
           !(az > params_.az_max_rad);
  }

  /// Max-gap rule (scan_clock.h, docs/reliability.md F1): the scans still
  /// in the window are finalised first (their estimates go to outputs(), so
  /// nothing accepted is lost), then every track and Gaussian clutter
  /// component is dropped and the scan history cleared; the uniform clutter
  /// and the Dirichlet state carry over.
  void restart_after_gap() {
    ++counters_.gap_resets;
    if (n_win_ > 0) process_window(n_win_);
    for (auto& t : tracks_) {
      if (!t.alive) continue;
      t.alive = false;
      ++counters_.tracks_deleted;
    }
    for (auto& c : comps_) {
      if (!c.alive) continue;
      c.alive = false;
      ++counters_.clutter_deleted;
    }
    n_hist_ = 0;
    n_win_ = 0;
  }

  /// Copies the valid measurements of `scan` to the next window slot.
  /// Returns true if some were rejected.
  bool store_scan(const ScanType& scan) {
    ScanSlot& s = store_[n_hist_ + n_win_];
    s.time_us = scan.time_us;
    s.count = 0;
    s.has_beliefs = false;
    s.lambda_hat = T(0);
    s.doppler = scan.has_doppler && params_.use_doppler;
    bool rejected = false;
    const T d = params_.amplitude_threshold;
    for (std::size_t j = 0; j < scan.measurements.size(); ++j) {
      const Measurement<T>& m = scan.measurements[j];
      ++counters_.measurements_in;
      const bool ok_values = is_finite(m.range_m) && is_finite(m.azimuth_rad) &&
                             is_finite(m.amplitude) && m.amplitude > d &&
                             !(m.amplitude > params_.max_amplitude) &&
                             in_region(m.range_m, m.azimuth_rad) &&
                             (!s.doppler || (is_finite(m.doppler_mps) &&
                                             !(m.doppler_mps > params_.doppler_span_mps) &&
                                             !(m.doppler_mps < -params_.doppler_span_mps)));
      kept_[j] = false;
      if (!ok_values) {
        ++counters_.measurements_invalid;
        rejected = true;
        continue;
      }
      if (is_duplicate(scan, j, [this](std::size_t i) { return kept_[i]; })) {
        ++counters_.measurements_duplicate;  // the first copy is kept (measurement.h)
        rejected = true;
        continue;
      }
      kept_[j] = true;
      const std::size_t c = s.count++;
      s.r[c] = m.range_m;
      s.az[c] = m.azimuth_rad;
      s.amp[c] = m.amplitude;
      s.dop[c] = s.doppler ? m.doppler_mps : T(0);
      s.orig_index[c] = static_cast<std::uint16_t>(j);
      s.target_share[c] = T(0);
      s.uniform_share[c] = T(1);
      s.consumed[c] = 0;
    }
    for (std::size_t src = 0; src < kSources; ++src) {
      s.nw_stats[src] = NwStats{};
      s.amp_stats[src] = AmpStats{};
    }
    // Range order for the birth search (spawn_tracks); ties by index, so the
    // order is unique and the same on every target.
    for (std::size_t c = 0; c < s.count; ++c) s.by_range[c] = static_cast<std::uint16_t>(c);
    std::sort(s.by_range.begin(), s.by_range.begin() + static_cast<std::ptrdiff_t>(s.count),
              [&s](std::uint16_t a, std::uint16_t b) { return s.r[a] < s.r[b] || (!(s.r[b] < s.r[a]) && a < b); });
    // "No information" association for the tracks on this new scan (spec 3.1).
    const std::size_t k = n_win_;
    for (auto& t : tracks_) {
      if (!t.alive) continue;
      t.missed[k] = T(1);
      t.n_edges[k] = 0;
      t.best[k] = -1;
      t.xi1[k] = T(1);
      t.xi0[k] = T(1);
      t.amp[k] = AmpStats{};
      t.extr[k] = T(0.5);
    }
    return rejected;
  }

  T dt_s(std::uint64_t t_from, std::uint64_t t_to) const {
    return static_cast<T>(static_cast<double>(t_to - t_from) * 1e-6);
  }

  T detection_prob(const IG& ig) const {
    if (!params_.use_amplitude) return params_.pd_no_amplitude;
    return mfbp::detection_probability(ig.mean(), params_.amplitude_threshold, n_order_,
                                       params_.pd_model);
  }

  bool estimate_clutter() const { return params_.clutter_mode == ClutterMode::kEstimate; }

  // ------------------------------------------------------------ window loop
  void process_window(std::size_t finalize_count) {
    const std::size_t n = n_win_;
    if (finalize_count > n) finalize_count = n;
    mf_sweep(n);
    spawn_tracks(n);
    if (estimate_clutter() && params_.clutter_birth) spawn_components(n);
    mf_sweep(n);
    for (std::size_t l = 0; l < params_.mp_max_iterations; ++l) {
      T delta = T(0);
      for (std::size_t k = 0; k < n; ++k) {
        const T d = associate_scan(k);
        delta = d > delta ? d : delta;
      }
      mf_sweep(n);
      if (delta < params_.mp_tolerance) break;
    }
    // Second birth pass [impl]: every scan now has association beliefs, so
    // "unexplained" is sum_i a_ij < threshold everywhere. Before the loop a
    // new scan could only use the gate test, which never lets a second
    // track start inside an existing track's gate (two close targets; the
    // online filter, whose current scan is always new, depends on this).
    // Tracks born here enter the association from the next window on.
    if (params_.late_birth) {
      MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
      const std::uint32_t first_new = next_track_id_;
      spawn_tracks(n);
      for (auto& t : tracks_) {
        if (t.alive && t.id >= first_new) {
          visibility_sweep(t, n);
          target_sweep(t, n);
        }
      }
    }
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kOutput);
    confirm_tracks(n);
    for (std::size_t k = 0; k < finalize_count; ++k) emit_estimate(k);
    manage_tracks(n, finalize_count);
    if (estimate_clutter()) manage_components(n, finalize_count);
    shift_window(finalize_count);
  }

  // One MF sweep (spec 3.0 steps 2-5): Dirichlet, visibility, clutter, targets.
  void mf_sweep(std::size_t n) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kMfUpdate);
    if (params_.clutter_mode != ClutterMode::kKnown) clutter_sweep(n);
    for (auto& t : tracks_) {
      if (!t.alive) continue;
      visibility_sweep(t, n);
      target_sweep(t, n);
    }
  }

  // Dirichlet forward + backward statistics (spec 3.6, 3.8.1), then the NW
  // and CNR IG chains of every component and the uniform CNR IG (spec 3.8).
  void clutter_sweep(std::size_t n) {
    const bool est = estimate_clutter();
    // source slot list: 0 uniform, 1 + c for live components
    std::array<T, kSources> alpha_prev{}, alpha_pred{}, counts{};
    for (std::size_t src = 0; src < kSources; ++src) {
      alpha_prev[src] = src == 0 ? uniform_.alpha0 : (comps_[src - 1].alive ? comps_[src - 1].alpha0 : T(0));
    }
    T m_prev = m_prev_;
    for (std::size_t k = 0; k < n; ++k) {
      mfbp::dirichlet_predict(alpha_prev.data(), alpha_pred.data(), kSources,
                              params_.dirichlet_kappa, m_prev);
      T m_k = T(0);
      for (std::size_t src = 0; src < kSources; ++src) {
        const bool live = src == 0 || comps_[src - 1].alive;
        counts[src] = live ? win(k).amp_stats[src].w : T(0);
        if (!live) alpha_pred[src] = T(0);
        m_k += counts[src];
        alpha_f_[k][src] = live ? alpha_pred[src] + counts[src] : T(0);
      }
      // A scan without association results carries the predicted count.
      if (!win(k).has_beliefs) m_k = m_prev;
      m_[k] = m_k;
      m_prev = m_k;
      alpha_prev = alpha_f_[k];
    }
    // Backward statistics smoother for the Dirichlet, g = kappa/(kappa+1).
    const T g_d = params_.dirichlet_kappa / (params_.dirichlet_kappa + T(1));
    std::array<T, kSources> B{};
    for (std::size_t kk = n; kk-- > 0;) {
      if (kk + 1 < n) {
        for (std::size_t src = 0; src < kSources; ++src) B[src] = g_d * (B[src] + win(kk + 1).amp_stats[src].w);
      }
      for (std::size_t src = 0; src < kSources; ++src) {
        alpha_s_[kk][src] = alpha_f_[kk][src] > T(0) ? alpha_f_[kk][src] + B[src] : T(0);
      }
    }
    // CNR IG chains (uniform and components) and NW chains.
    const T g_ig = T(1) / params_.forgetting_clutter;
    const T tn = T(n_order_);
    {
      IG prev = uniform_.ig0;
      for (std::size_t k = 0; k < n; ++k) {
        IG f = prev.predicted(params_.forgetting_clutter);
        if (params_.use_amplitude) f.update(tn * win(k).amp_stats[0].w, tn * win(k).amp_stats[0].s);
        uniform_.igf[k] = f;
        prev = f;
      }
      AmpStats B_amp{};
      for (std::size_t kk = n; kk-- > 0;) {
        if (kk + 1 < n) {
          B_amp.w = g_ig * (B_amp.w + win(kk + 1).amp_stats[0].w);
          B_amp.s = g_ig * (B_amp.s + win(kk + 1).amp_stats[0].s);
        }
        IG s = uniform_.igf[kk];
        if (params_.use_amplitude) s.update(tn * B_amp.w, tn * B_amp.s);
        uniform_.igs[kk] = s;
      }
    }
    if (!est) return;
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      CompSlot& cs = comps_[c];
      if (!cs.alive) continue;
      const std::size_t src = c + 1;
      NW nw_prev = cs.nw0;
      IG ig_prev = cs.ig0;
      for (std::size_t k = 0; k < n; ++k) {
        NW nw = nw_prev.predicted(params_.nw_forgetting_factor, params_.nw_forgetting);
        nw.update(win(k).nw_stats[src]);
        cs.nwf[k] = nw;
        nw_prev = nw;
        IG ig = ig_prev.predicted(params_.forgetting_clutter);
        if (params_.use_amplitude) ig.update(tn * win(k).amp_stats[src].w, tn * win(k).amp_stats[src].s);
        cs.igf[k] = ig;
        ig_prev = ig;
      }
      NwStats B_nw{};
      AmpStats B_amp{};
      for (std::size_t kk = n; kk-- > 0;) {
        if (kk + 1 < n) {
          B_nw.accumulate(win(kk + 1).nw_stats[src]);
          B_nw.scale(params_.nw_forgetting_factor);
          B_amp.w = g_ig * (B_amp.w + win(kk + 1).amp_stats[src].w);
          B_amp.s = g_ig * (B_amp.s + win(kk + 1).amp_stats[src].s);
        }
        NW s = cs.nwf[kk];
        s.update(B_nw);
        cs.nws[kk] = s;
        IG is = cs.igf[kk];
        if (params_.use_amplitude) is.update(tn * B_amp.w, tn * B_amp.s);
        cs.igs[kk] = is;
      }
    }
  }

  void visibility_sweep(TrackSlot& t, std::size_t n) {
    const std::size_t f = t.first;
    if (f >= n) return;
    const T pred0 = t.from_birth ? params_.visibility_at_birth
                                 : mfbp::visibility_predict(t.vis0, params_.p_survive, params_.p_birth);
    mfbp::visibility_forward_backward(pred0, t.xi1.data() + f, t.xi0.data() + f, n - f,
                                      params_.p_survive, params_.p_birth, t.visf.data() + f,
                                      t.vis.data() + f, t.extr.data() + f);
  }

  // Cubature forward filter on the pseudo-measurement + RTS, and the SNR IG
  // forward filter + backward statistics (spec 3.9).
  void target_sweep(TrackSlot& t, std::size_t n) {
    const std::size_t f = t.first;
    if (f >= n) return;
    const T tn = T(n_order_);
    for (std::size_t k = f; k < n; ++k) {
      Vec4 x;
      Mat4 P;
      IG ig;
      if (k == f && t.from_birth) {
        t.xf[k] = t.x0;
        t.Pf[k].set(t.P0);
        t.igf[k] = t.ig0;
        t.biasf[k] = t.bias0;
        t.qk[k] = params_.process_noise_var;
        continue;
      }
      const Vec2 bias_prev = k == f ? t.bias0 : t.biasf[k - 1];
      const T q = manoeuvre_noise(bias_prev);
      t.qk[k] = q;
      if (k == f) {
        x = t.x0;
        P = t.P0;
        ig = t.ig0;
        note_repair(mfbp::cv_predict(x, P, dt_s(t.t0_us, win(k).time_us), q));
      } else {
        x = t.xf[k - 1];
        P = t.Pf[k - 1].get();
        ig = t.igf[k - 1];
        note_repair(mfbp::cv_predict(x, P, dt_s(win(k - 1).time_us, win(k).time_us), q));
      }
      Vec2 bias_k = bias_prev;
      ig = ig.predicted(params_.forgetting_target);
      const T w = T(1) - t.missed[k];
      // [impl] pooled kinematics of an unresolved pair (unresolved_pooling).
      const TrackSlot* mate = nullptr;
      if (params_.unresolved_pooling && t.mate[k] > 0) {
        const TrackSlot& m = tracks_[t.mate[k] - 1u];
        if (m.alive && k >= m.first && m.n_edges[k] > 0) mate = &m;
      }
      if ((w > params_.w_min && t.n_edges[k] > 0) || mate != nullptr) {
        // Pseudo-measurement (P40): y_bar = z_ref + sum a_j wrap(y_j - z_ref) / w.
        const Vec2 z_ref = mfbp::polar_of_state<T>(x);
        Vec2 acc = Vec2::Zero();
        T w_sum = T(0);
        const ScanSlot& s = win(k);
        const TrackSlot* pooled[2] = {&t, mate};
        for (const TrackSlot* src : pooled) {
          if (src == nullptr) continue;
          for (std::size_t e = 0; e < src->n_edges[k]; ++e) {
            const std::size_t j = src->edge_meas[k][e];
            const T a = src->edge_w[k][e];
            acc(0) += a * (s.r[j] - z_ref(0));
            acc(1) += a * mfbp::wrap_angle(s.az[j] - z_ref(1));
            w_sum += a;
          }
        }
        if (w_sum > params_.w_min) {
          Vec2 y_bar = z_ref + acc / w_sum;
          y_bar(1) = mfbp::wrap_angle(y_bar(1));
          if (s.doppler) {
            T dop = T(0);
            for (const TrackSlot* src : pooled) {
              if (src == nullptr) continue;
              for (std::size_t e = 0; e < src->n_edges[k]; ++e) {
                dop += src->edge_w[k][e] * s.dop[src->edge_meas[k][e]];
              }
            }
            const Eigen::Matrix<T, 3, 1> y3(y_bar(0), y_bar(1), dop / w_sum);
            Eigen::Matrix<T, 3, 3> R3 = Eigen::Matrix<T, 3, 3>::Zero();
            R3(0, 0) = R_(0, 0) / w_sum;
            R3(1, 1) = R_(1, 1) / w_sum;
            R3(2, 2) = params_.sigma_doppler_mps * params_.sigma_doppler_mps / w_sum;
            Vec2 white = Vec2::Zero();
            note_repair(mfbp::cubature_update_m<T, 3>(x, P, y3, R3, &white));
            bias_k = fade_bias(bias_prev, white, w_sum);
          } else {
            const Mat2 R_bar = R_ / w_sum;
            Vec2 white = Vec2::Zero();
            note_repair(mfbp::cubature_update(x, P, y_bar, R_bar, &white));
            bias_k = fade_bias(bias_prev, white, w_sum);
          }
        }
        if (params_.use_amplitude && w > params_.w_min) {
          if (params_.snr_update == SnrUpdate::kMf) {
            ig.update(tn * t.amp[k].w, tn * t.amp[k].s);
          } else if (t.amp[k].w > params_.w_min) {
            ig.update(tn, tn * t.amp[k].s / t.amp[k].w);
          }
        }
      }
      t.xf[k] = x;
      t.Pf[k].set(P);
      t.igf[k] = ig;
      t.biasf[k] = bias_k;
    }
    // RTS backward (linear dynamics: URTSS reduces to RTS).
    t.xs[n - 1] = t.xf[n - 1];
    t.Ps[n - 1] = t.Pf[n - 1];
    Mat4 Ps_next = t.Ps[n - 1].get();
    for (std::size_t kk = n - 1; kk-- > f;) {
      Mat4 Ps;
      note_repair(mfbp::rts_step(t.xf[kk], t.Pf[kk].get(), t.xs[kk + 1], Ps_next,
                                 dt_s(win(kk).time_us, win(kk + 1).time_us), t.qk[kk + 1],
                                 t.xs[kk], Ps));
      t.Ps[kk].set(Ps);
      Ps_next = Ps;
    }
    // SNR backward statistics, g = 1/u^t (spec 3.8.1).
    const T g = T(1) / params_.forgetting_target;
    AmpStats B{};
    for (std::size_t kk = n; kk-- > f;) {
      if (kk + 1 < n) {
        B.w = g * (B.w + t.amp[kk + 1].w);
        B.s = g * (B.s + t.amp[kk + 1].s);
      }
      IG s = t.igf[kk];
      if (params_.use_amplitude && params_.snr_update == SnrUpdate::kMf) s.update(tn * B.w, tn * B.s);
      t.igs[kk] = s;
    }
  }

  /// [impl, not in the paper] Manoeuvre-adaptive white-acceleration level,
  /// from the innovation-mean test (Bar-Shalom, Li, Kirubarajan 2001,
  /// sec. 5.4 and 11.3). bias is the faded mean u_bar of the whitened
  /// pseudo-measurement innovations u = L^-1 e (S = L L^T); while the CV
  /// model holds, u ~ N(0, I) and chi = |u_bar|^2 (1 + rho) / (2 (1 - rho))
  /// is 1 on average. A per-scan NIS test is blind here: S1's turn leaves a
  /// lag of ~0.5 sigma per scan, which only the mean over many scans shows.
  /// Above 1 the level rises as chi^4 from process_noise_var (the paper's
  /// quiet 0.01) to manoeuvre_noise_var_max (reached at chi = 3.2 with the
  /// defaults), so one model follows the 0.33 m/s^2 turn and averages
  /// 210-300 m cross-range noise down afterwards. The exponent and the
  /// fading factor come from an S1 sweep (docs/results/seed000-s1.md).
  T manoeuvre_noise(const Vec2& bias) const {
    const T q0 = params_.process_noise_var;
    const T rho = params_.manoeuvre_fading;
    const T chi = bias.squaredNorm() * (T(1) + rho) / (T(2) * (T(1) - rho));
    const T q_max = params_.manoeuvre_noise_var_max;
    if (!(chi > T(1)) || !(q_max > q0)) return q0;
    const T chi2 = chi * chi;
    const T q = q0 * chi2 * chi2;
    return q < q_max ? q : q_max;
  }

  /// u_bar <- rho u_bar + (1 - rho) u; a pseudo-measurement of weight
  /// w_sum < 1 moves it proportionally less.
  Vec2 fade_bias(const Vec2& bias_prev, Vec2 white, T w_sum) const {
    const T a = (T(1) - params_.manoeuvre_fading) * (w_sum < T(1) ? w_sum : T(1));
    for (int i = 0; i < 2; ++i) {  // a wild outlier only saturates
      if (!(white(i) < T(100))) white(i) = T(100);
      if (!(white(i) > T(-100))) white(i) = T(-100);
    }
    return bias_prev + a * (white - bias_prev);
  }

  void note_repair(bool repaired) {
    if (repaired) ++counters_.numerical_repairs;
  }

  // ----------------------------------------------------------- association
  /// Removes the scan-k pseudo-measurement (y_bar, R / w) of the previous
  /// iteration from the smoothed measurement-space moments (z_hat, Sz)
  /// (cavity.h). [impl, not in the paper] The MF belief of x_k already
  /// contains the measurement it was associated with, so evidence from it is
  /// self-reinforcing; the extrinsic (cavity) moments are what BP would pass.
  /// It does not remove the pair repulsion on S1 (see association_cavity in
  /// mfbp_params.h): that feedback runs through the other window scans and
  /// the prior. Unchanged when there is no previous association or the
  /// division is not positive definite.
  void cavity_moments(const TrackSlot& t, std::size_t k, Vec2& z_hat, Mat2& Sz) const {
    const T w = T(1) - t.missed[k];
    if (!(w > params_.w_min) || t.n_edges[k] == 0) return;
    const ScanSlot& s = win(k);
    Vec2 acc = Vec2::Zero();
    T w_sum = T(0);
    for (std::size_t e = 0; e < t.n_edges[k]; ++e) {
      const std::size_t j = t.edge_meas[k][e];
      const T a = t.edge_w[k][e];
      acc(0) += a * (s.r[j] - z_hat(0));
      acc(1) += a * mfbp::wrap_angle(s.az[j] - z_hat(1));
      w_sum += a;
    }
    if (!(w_sum > params_.w_min)) return;
    const Vec2 e_bar = acc / w_sum;  // y_bar - z_hat (azimuth wrapped)
    (void)mfbp::remove_pseudo_measurement(z_hat, Sz, e_bar, w_sum,
                                          Vec2(R_inv_(0, 0), R_inv_(1, 1)));
  }

  /// [impl, not in the paper] Tracks whose predicted measurements are
  /// statistically indistinguishable, (z_a - z_b)^T (Sz_a + Sz_b)^-1
  /// (z_a - z_b) < unresolved_chi2, score measurements against their common
  /// mean (the plain average over the track and such neighbours), so that
  /// position alone never decides which of them takes which measurement:
  /// amplitude, Doppler and visibility still do. Without it, on S1's
  /// unresolved pair (20 m apart, 210-300 m cross-range noise) the track
  /// that drifted left takes the left measurements, an outward pull that
  /// cancels the measurement's restoring pull (loop gain 1 with (P79),
  /// 1 - K^2 even with the predictive density), and the tracks drift ~200 m apart
  /// (docs/results/seed000-s1.md). Each track still updates on its own
  /// pseudo-measurement. O(tracks^2) 2x2 tests per associated scan.
  void couple_unresolved(std::size_t k) {
    for (std::size_t a = 0; a < kMaxTargets; ++a) {
      TrackMoments& ma = moments_[a];
      if (!ma.ok) continue;
      Vec2 sum = ma.z;
      T count = T(1);
      T nearest = params_.unresolved_chi2;
      for (std::size_t b = 0; b < kMaxTargets; ++b) {
        const TrackMoments& mb = moments_[b];
        if (b == a || !mb.ok) continue;
        const Vec2 e(mb.z(0) - ma.z(0), mfbp::wrap_angle(mb.z(1) - ma.z(1)));
        const Mat2 C = ma.Sz + mb.Sz;
        const T det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
        if (!(det > T(0))) continue;
        const T d2 = (C(1, 1) * e(0) * e(0) - T(2) * C(0, 1) * e(0) * e(1) + C(0, 0) * e(1) * e(1)) / det;
        if (!(d2 < params_.unresolved_chi2)) continue;
        sum += Vec2(ma.z(0) + e(0), ma.z(1) + e(1));
        count += T(1);
        if (d2 < nearest) {
          nearest = d2;
          tracks_[a].mate[k] = static_cast<std::uint16_t>(b + 1);
        }
      }
      ma.z_shared = sum / count;
      ma.z_shared(1) = mfbp::wrap_angle(ma.z_shared(1));
    }
  }

  /// Does track t take part in the association of window scan k?
  static bool participates(const TrackSlot& t, std::size_t k) {
    return t.alive && k >= t.first && !(t.from_birth && k == t.first);
  }

  /// Local evidence (spec 3.2-3.3), loopy BP (spec 3.5), and storage of the
  /// beliefs and statistics of window scan k. Returns max |delta a_hat|.
  T associate_scan(std::size_t k) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kEvidence);
    ScanSlot& s = win(k);
    const std::size_t nm = s.count;
    const T d = params_.amplitude_threshold;
    const bool amp = params_.use_amplitude;
    // Clutter sources: 0 = uniform, then live components (or known ones).
    std::array<std::size_t, kSources> src_slot{};
    std::size_t ns = 1;
    src_slot[0] = 0;
    if (estimate_clutter()) {
      for (std::size_t c = 0; c < kMaxComp; ++c) {
        if (comps_[c].alive) src_slot[ns++] = c + 1;
      }
    } else if (params_.clutter_mode == ClutterMode::kKnown) {
      const std::size_t nk = params_.known_clutter.num_components < kMaxComp
                                 ? params_.known_clutter.num_components
                                 : kMaxComp;
      for (std::size_t c = 0; c < nk; ++c) src_slot[ns++] = c + 1;
    }
    (void)bp_.reset(nm, ns);

    // Expected clutter count lambda_hat (spec 3.3).
    T expected_targets = T(0);
    for (const auto& t : tracks_) {
      if (participates(t, k)) expected_targets += detection_prob(t.igs[k]) * t.vis[k];
    }
    T lambda = static_cast<T>(nm) - expected_targets;
    if (lambda < T(1)) lambda = T(1);
    s.lambda_hat = lambda;

    // --- clutter evidence; with Doppler every clutter source has a uniform
    // radial-velocity density 1 / (2 span) [impl].
    const T log_dop_clutter = s.doppler ? -dmath::dlog(T(2) * params_.doppler_span_mps) : T(0);
    if (params_.clutter_mode == ClutterMode::kKnown) {
      const auto& kc = params_.known_clutter;
      const T lu = dmath::dlog(kc.uniform_rate_per_scan) - log_volume_ + log_dop_clutter;
      for (std::size_t j = 0; j < nm; ++j) {
        T v = lu;
        if (amp) v += mfbp::amplitude_loglik(s.amp[j], d, T(1) + kc.uniform_cnr, n_order_);
        bp_.set_clutter_log(0, j, v);
      }
      for (std::size_t q = 1; q < ns; ++q) {
        const auto& comp = kc.components[src_slot[q] - 1];
        bp_.set_clutter_absent(q, T(0));  // known components are always present
        if (!(comp.rate_per_scan > T(0))) continue;
        const T det = comp.covariance(0, 0) * comp.covariance(1, 1) -
                      comp.covariance(0, 1) * comp.covariance(1, 0);
        const T base = dmath::dlog(comp.rate_per_scan) - T(1.8378770664093453) -
                       T(0.5) * dmath::dlog(det) + log_dop_clutter;
        Mat2 inv;  // closed-form 2x2 inverse
        inv << comp.covariance(1, 1) / det, -comp.covariance(0, 1) / det,
            -comp.covariance(1, 0) / det, comp.covariance(0, 0) / det;
        for (std::size_t j = 0; j < nm; ++j) {
          Vec2 e(s.r[j] - comp.mean(0), mfbp::wrap_angle(s.az[j] - comp.mean(1)));
          const T maha = e.dot(inv * e);
          if (maha > params_.clutter_gate_chi2) continue;
          T v = base - T(0.5) * maha;
          if (amp) v += mfbp::amplitude_loglik(s.amp[j], d, T(1) + comp.cnr, n_order_);
          bp_.set_clutter_log(q, j, v);
        }
      }
    } else {
      std::array<T, kSources> alpha{}, e_log_pi{};
      T log_rate = T(0);
      if (estimate_clutter()) {
        for (std::size_t q = 0; q < ns; ++q) alpha[q] = alpha_s_[k][src_slot[q]];
        mfbp::dirichlet_expected_log(alpha.data(), e_log_pi.data(), ns);
        log_rate = params_.clutter_rate_in_da ? dmath::dlog(lambda) : T(0);
      } else {
        e_log_pi[0] = T(0);
        log_rate = dmath::dlog(params_.uniform_rate_per_scan);
      }
      const IG& ig0 = uniform_.igs[k];
      const T lu = log_rate + e_log_pi[0] - log_volume_ + log_dop_clutter;
      for (std::size_t j = 0; j < nm; ++j) {
        T v = lu;
        if (amp) {
          v += mfbp::expected_amplitude_loglik(s.amp[j], d, ig0.a, ig0.b, n_order_, params_.amp_loglik);
        }
        bp_.set_clutter_log(0, j, v);
      }
      for (std::size_t q = 1; q < ns; ++q) {
        const CompSlot& cs = comps_[src_slot[q] - 1];
        const NW& nw = cs.nws[k];
        const IG& ig = cs.igs[k];
        bp_.set_clutter_absent(q, params_.component_absent_evidence);
        const T base = log_rate + e_log_pi[q] + nw.expected_log_norm() + log_dop_clutter;
        for (std::size_t j = 0; j < nm; ++j) {
          const Vec2 y(s.r[j], s.az[j]);
          const T em = nw.expected_mahalanobis(y);
          if (em - T(2) / nw.c > params_.clutter_gate_chi2) continue;
          T v = base - T(0.5) * em;
          if (amp) v += mfbp::expected_amplitude_loglik(s.amp[j], d, ig.a, ig.b, n_order_, params_.amp_loglik);
          bp_.set_clutter_log(q, j, v);
        }
      }
    }

    // --- target evidence: predicted measurement moments of every track
    // first, so that unresolved tracks can share them (couple_unresolved).
    for (std::size_t i = 0; i < kMaxTargets; ++i) {
      TrackSlot& t = tracks_[i];
      TrackMoments& mo = moments_[i];
      mo.ok = false;
      t.mate[k] = 0;
      if (!participates(t, k)) continue;
      // Moments of [range, azimuth, radial velocity]; the Doppler row is
      // used only when the scan has it.
      Eigen::Matrix<T, 3, 1> z3;
      Eigen::Matrix<T, 3, 3> S3;
      Eigen::Matrix<T, 4, 3> C3;
      Mat4 P_k = t.Ps[k].get();
      if (!mfbp::cubature_moments<T, 3>(t.xs[k], P_k, z3, S3, C3)) {
        note_repair(mfbp::make_spd(P_k));
        if (!mfbp::cubature_moments<T, 3>(t.xs[k], P_k, z3, S3, C3)) continue;
      }
      mo.z = z3.template head<2>();
      mo.Sz = S3.template topLeftCorner<2, 2>();
      mo.z_dop = z3(2);
      mo.var_dop = S3(2, 2);
      if (params_.association_cavity) cavity_moments(t, k, mo.z, mo.Sz);
      mo.ok = true;
    }
    if (params_.unresolved_chi2 > T(0)) {
      couple_unresolved(k);
    } else {
      for (auto& mo : moments_) mo.z_shared = mo.z;
    }

    std::array<std::size_t, kMaxTargets> bp_track{};
    std::size_t nbt = 0;
    for (std::size_t i = 0; i < kMaxTargets; ++i) {
      TrackSlot& t = tracks_[i];
      const TrackMoments& mo = moments_[i];
      if (!mo.ok) continue;
      const Vec2& z_hat = mo.z_shared;
      const Mat2& Sz = mo.Sz;
      const T var_d = params_.sigma_doppler_mps * params_.sigma_doppler_mps;
      const Mat2 S = Sz + R_;
      const T det_s = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
      if (!(det_s > T(0))) continue;
      const T trace_term = (R_inv_ * Sz).trace();
      const T pd = detection_prob(t.igs[k]);
      const T q1 = t.extr[k];
      const T eps = params_.pd_invisible;
      const T theta0 = (q1 * (T(1) - pd) + (T(1) - q1) * (T(1) - eps)) / (q1 * pd + (T(1) - q1) * eps);
      // Gate and keep the kMaxGate most likely pairs (sorted insertion).
      std::array<T, kMaxGate> best_v{};
      std::array<std::uint16_t, kMaxGate> best_j{};
      std::size_t nb = 0;
      for (std::size_t j = 0; j < nm; ++j) {
        Vec2 e(s.r[j] - z_hat(0), mfbp::wrap_angle(s.az[j] - z_hat(1)));
        const T gate = (S(1, 1) * e(0) * e(0) - T(2) * S(0, 1) * e(0) * e(1) + S(0, 0) * e(1) * e(1)) / det_s;
        if (gate > params_.gate_chi2) continue;
        T v = log_norm_R_ - T(0.5) * (e.dot(R_inv_ * e) + trace_term);
        if (s.doppler) {
          // Doppler is not in the paper [impl]: the predictive density
          // N(d; z_d, S_dd + sigma_d^2) rather than the MF expectation, whose
          // -S_dd / (2 sigma_d^2) term rejects every association of a young
          // track (velocity spread >> sigma_d) and so would never let it learn.
          const T ed = s.dop[j] - mo.z_dop;
          const T var = var_d + mo.var_dop;
          v += -T(0.5) * (T(1.8378770664093453) + dmath::dlog(var)) - T(0.5) * ed * ed / var;
        }
        if (amp) {
          v += mfbp::expected_amplitude_loglik(s.amp[j], d, t.igs[k].a, t.igs[k].b, n_order_,
                                               params_.amp_loglik);
        }
        if (nb == kMaxGate) {
          ++gate_overflows_;
          step_cap_hit_ = true;
          if (!(v > best_v[nb - 1])) continue;
          --nb;
        }
        std::size_t pos = nb;
        while (pos > 0 && v > best_v[pos - 1]) {
          best_v[pos] = best_v[pos - 1];
          best_j[pos] = best_j[pos - 1];
          --pos;
        }
        best_v[pos] = v;
        best_j[pos] = static_cast<std::uint16_t>(j);
        ++nb;
      }
      if (bp_.add_target(theta0) != Status::kOk) continue;
      // Edges in measurement order (deterministic, independent of the ranking).
      std::array<std::uint16_t, kMaxGate> order{};
      for (std::size_t a = 0; a < nb; ++a) order[a] = static_cast<std::uint16_t>(a);
      for (std::size_t a = 1; a < nb; ++a) {
        for (std::size_t b = a; b > 0 && best_j[order[b]] < best_j[order[b - 1]]; --b) {
          const std::uint16_t tmp = order[b];
          order[b] = order[b - 1];
          order[b - 1] = tmp;
        }
      }
      for (std::size_t a = 0; a < nb; ++a) (void)bp_.add_edge(best_j[order[a]], best_v[order[a]]);
      bp_track[nbt++] = i;
    }

    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBp);
    const auto res = bp_.run(params_.bp_damping, params_.bp_tolerance, params_.bp_max_iterations);
    if (!res.converged) ++counters_.bp_not_converged;
    bp_iterations_ += res.iterations;
    ++bp_runs_;

    // --- store beliefs
    T delta = T(0);
    auto track_delta = [&delta](T a, T b) {
      const T dd = a > b ? a - b : b - a;
      delta = dd > delta ? dd : delta;
    };
    for (auto& t : tracks_) {
      if (!t.alive || k < t.first) continue;
      if (!participates(t, k)) {
        t.missed[k] = T(1);
        t.n_edges[k] = 0;
        t.best[k] = -1;
        t.xi1[k] = T(1);
        t.xi0[k] = T(1);
        t.amp[k] = AmpStats{};
      }
    }
    std::array<T, kMaxMeas> new_share{};
    for (std::size_t i = 0; i < nbt; ++i) {
      TrackSlot& t = tracks_[bp_track[i]];
      const T missed = bp_.missed_belief(i);
      track_delta(missed, t.missed[k]);
      t.missed[k] = missed;
      std::size_t ne = 0;
      T best_w = missed;
      std::int32_t best_j = -1;
      AmpStats as{};
      for (std::size_t e = bp_.edge_begin(i); e < bp_.edge_end(i); ++e) {
        const std::size_t j = bp_.edge_meas(e);
        const T a = bp_.edge_belief(e);
        t.edge_meas[k][ne] = static_cast<std::uint16_t>(j);
        t.edge_w[k][ne] = a;
        ++ne;
        new_share[j] += a;
        as.w += a;
        as.s += a * (s.amp[j] * s.amp[j] - d * d);
        if (a > best_w) {
          best_w = a;
          best_j = static_cast<std::int32_t>(j);
        }
      }
      t.n_edges[k] = static_cast<std::uint8_t>(ne);
      t.best[k] = best_j;
      t.amp[k] = as;
      const T pd = detection_prob(t.igs[k]);
      const T lam = bp_.lambda(i);
      T x1 = T(1) - pd + pd * lam;
      T x0 = T(1) - params_.pd_invisible + params_.pd_invisible * lam;
      const T z = x1 + x0;
      t.xi1[k] = x1 / z;
      t.xi0[k] = x0 / z;
    }
    for (std::size_t j = 0; j < nm; ++j) {
      track_delta(new_share[j], s.target_share[j]);
      s.target_share[j] = new_share[j];
      const T u = bp_.clutter_belief(0, j);
      track_delta(u, s.uniform_share[j]);
      s.uniform_share[j] = u;
    }
    // Clutter statistics per source slot (spec 3.6, 3.8).
    for (std::size_t src = 0; src < kSources; ++src) {
      s.nw_stats[src] = NwStats{};
      s.amp_stats[src] = AmpStats{};
    }
    for (std::size_t q = 0; q < ns; ++q) {
      const std::size_t src = src_slot[q];
      NwStats st{};
      if (src > 0 && estimate_clutter()) st.ref = comps_[src - 1].nws[k].mu;
      AmpStats as{};
      for (std::size_t j = 0; j < nm; ++j) {
        const T a = bp_.clutter_belief(q, j);
        if (!(a > T(0))) continue;
        if (src > 0) st.add(Vec2(s.r[j], s.az[j]), a);
        as.w += a;
        as.s += a * (s.amp[j] * s.amp[j] - d * d);
      }
      s.nw_stats[src] = st;
      s.amp_stats[src] = as;
    }
    s.has_beliefs = true;
    return delta;
  }

  // ----------------------------------------------------------------- birth
  /// Marks every stored measurement that is unexplained by the tracks
  /// (spec 3.10) in unexplained_[si][j]: not consumed by a birth and, on
  /// scans with beliefs, sum_i a_ij < unexplained_threshold and Gaussian
  /// clutter share < birth_max_component_share; on new scans, outside the
  /// gate of every track present. One cubature per track and new scan.
  void mark_unexplained() {
    for (std::size_t si = 0; si < n_hist_ + n_win_; ++si) {
      ScanSlot& s = store_[si];
      for (std::size_t j = 0; j < s.count; ++j) {
        bool u = s.consumed[j] == 0;
        if (u && s.has_beliefs) {
          const T comp_share = T(1) - s.target_share[j] - s.uniform_share[j];
          u = s.target_share[j] < params_.unexplained_threshold &&
              (params_.birth_max_component_share >= T(1) ||
               comp_share < params_.birth_max_component_share);
        }
        unexplained_[si][j] = u ? 1u : 0u;
      }
      if (s.has_beliefs || si < n_hist_) continue;
      const std::size_t k = si - n_hist_;
      for (const auto& t : tracks_) {
        if (!t.alive || k < t.first) continue;
        Vec2 z_hat;
        Mat2 Sz;
        mfbp::Mat42<T> Cxz;
        if (!mfbp::cubature_polar_moments(t.xs[k], t.Ps[k].get(), z_hat, Sz, Cxz)) continue;
        const Mat2 S = Sz + R_;
        const T det_s = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
        for (std::size_t j = 0; j < s.count; ++j) {
          if (unexplained_[si][j] == 0) continue;
          const T er = s.r[j] - z_hat(0);
          const T ea = mfbp::wrap_angle(s.az[j] - z_hat(1));
          const T gate = (S(1, 1) * er * er - T(2) * S(0, 1) * er * ea + S(0, 0) * ea * ea) / det_s;
          if (gate <= params_.gate_chi2) unexplained_[si][j] = 0;
        }
      }
    }
  }

  bool unexplained(std::size_t si, std::size_t j) const {
    return unexplained_[si][j] != 0 && store_[si].consumed[j] == 0;
  }

  struct BirthCandidate {
    T score = T(0);
    std::uint16_t s1 = 0, j1 = 0, s2 = 0, j2 = 0;
  };

  // Two-point initiation (spec 3.10): pairs (k1, k2 = k1 + delta), delta <=
  // L_max, inside the v_max box; at most one pair per second point (the
  // shortest lag, then the nearest first point), no measurement in two pairs;
  // the best birth_max_per_window by amplitude sum are born.
  void spawn_tracks(std::size_t n) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
    mark_unexplained();
    std::array<BirthCandidate, 32> cand{};
    std::size_t nc = 0;
    const std::size_t max_births = params_.birth_max_per_window < cand.size() ? params_.birth_max_per_window : cand.size();
    for (std::size_t k2 = 0; k2 < n; ++k2) {
      const std::size_t s2 = n_hist_ + k2;
      for (std::size_t j2 = 0; j2 < store_[s2].count; ++j2) {
        if (!unexplained(s2, j2)) continue;
        const Vec2 p2 = mfbp::cartesian_of_polar(store_[s2].r[j2], store_[s2].az[j2]);
        bool found = false;
        for (std::size_t lag = 1; lag <= params_.birth_max_lag && lag <= s2 && !found; ++lag) {
          const std::size_t s1 = s2 - lag;
          const T dt = dt_s(store_[s1].time_us, store_[s2].time_us);
          T best_d = T(0);
          std::size_t best_j = kMaxMeas;
          // Only first points within the range reach can pass the box gate
          // (birth_range_gate): start at the first one in range order, stop
          // after the last, so the search is O(log N + hits), not O(N).
          const ScanSlot& a1 = store_[s1];
          const T r2 = store_[s2].r[j2];
          std::size_t lo = 0, hi = a1.count;
          while (lo < hi) {
            const std::size_t mid = (lo + hi) / 2;
            if (a1.r[a1.by_range[mid]] < r2 &&
                !mfbp::birth_range_gate(a1.r[a1.by_range[mid]], r2, dt, params_.v_max_x_mps, params_.v_max_y_mps)) {
              lo = mid + 1;
            } else {
              hi = mid;
            }
          }
          for (std::size_t q = lo; q < a1.count; ++q) {
            const std::size_t j1 = a1.by_range[q];
            if (!mfbp::birth_range_gate(a1.r[j1], r2, dt, params_.v_max_x_mps, params_.v_max_y_mps)) {
              if (a1.r[j1] > r2) break;  // beyond the reach: so is every later one
              continue;
            }
            if (!unexplained(s1, j1)) continue;
            const Vec2 p1 = mfbp::cartesian_of_polar(a1.r[j1], a1.az[j1]);
            if (!mfbp::birth_gate(p1, p2, dt, params_.v_max_x_mps, params_.v_max_y_mps)) continue;
            const T dist = (p2 - p1).squaredNorm();
            // Nearest first point; ties go to the lowest index (as in index order).
            if (best_j == kMaxMeas || dist < best_d || (!(best_d < dist) && j1 < best_j)) {
              best_d = dist;
              best_j = j1;
            }
          }
          if (best_j == kMaxMeas) continue;
          found = true;
          BirthCandidate c;
          c.score = store_[s1].amp[best_j] + store_[s2].amp[j2];
          c.s1 = static_cast<std::uint16_t>(s1);
          c.j1 = static_cast<std::uint16_t>(best_j);
          c.s2 = static_cast<std::uint16_t>(s2);
          c.j2 = static_cast<std::uint16_t>(j2);
          // Mark now so no measurement joins two pairs.
          store_[s1].consumed[best_j] = 1;
          store_[s2].consumed[j2] = 1;
          // Keep the best max_births by score (ties: earlier wins).
          if (nc == max_births) {
            if (!(c.score > cand[nc - 1].score)) {
              store_[s1].consumed[best_j] = 0;
              store_[s2].consumed[j2] = 0;
              continue;
            }
            store_[cand[nc - 1].s1].consumed[cand[nc - 1].j1] = 0;
            store_[cand[nc - 1].s2].consumed[cand[nc - 1].j2] = 0;
            --nc;
          }
          std::size_t pos = nc;
          while (pos > 0 && c.score > cand[pos - 1].score) {
            cand[pos] = cand[pos - 1];
            --pos;
          }
          cand[pos] = c;
          ++nc;
        }
      }
    }
    for (std::size_t b = 0; b < nc; ++b) {
      const BirthCandidate& c = cand[b];
      std::size_t slot = kMaxTargets;
      for (std::size_t i = 0; i < kMaxTargets; ++i) {
        if (!tracks_[i].alive) {
          slot = i;
          break;
        }
      }
      if (slot == kMaxTargets) {
        ++counters_.track_cap_hits;
        step_cap_hit_ = true;
        store_[c.s1].consumed[c.j1] = 0;
        store_[c.s2].consumed[c.j2] = 0;
        continue;
      }
      const ScanSlot& a = store_[c.s1];
      const ScanSlot& bsl = store_[c.s2];
      TrackSlot& t = tracks_[slot];
      t = TrackSlot{};
      t.alive = true;
      t.id = next_track_id_++;
      t.first = c.s2 - n_hist_;
      t.from_birth = true;
      mfbp::two_point_state(a.r[c.j1], a.az[c.j1], bsl.r[c.j2], bsl.az[c.j2],
                            dt_s(a.time_us, bsl.time_us), params_.sigma_r_m, params_.sigma_az_rad,
                            params_.v_max_x_mps, params_.v_max_y_mps, t.x0, t.P0);
      t.ig0 = mfbp::birth_snr_belief(a.amp[c.j1], bsl.amp[c.j2], params_.amplitude_threshold,
                                     params_.ig_birth_shape, params_.ig_birth_scale_factor);
      t.vis0 = params_.visibility_at_birth;
      t.t0_us = bsl.time_us;
      for (std::size_t k = 0; k < kMaxWindow; ++k) {
        t.missed[k] = T(1);
        t.best[k] = -1;
        t.xi1[k] = T(1);
        t.xi0[k] = T(1);
        t.extr[k] = params_.visibility_at_birth;
      }
      ++counters_.tracks_born;
    }
  }

  // Clutter-component birth by grid seeding (spec 3.10 [impl]).
  void spawn_components(std::size_t n) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
    const std::size_t pool_first = (n_hist_ + n > kMaxWindow) ? n_hist_ + n - kMaxWindow : 0;
    const std::size_t pool_end = n_hist_ + n;
    const std::size_t n_pool = pool_end - pool_first;
    T cell_r = params_.clutter_cell_range_m;
    T cell_a = params_.clutter_cell_az_rad;
    const T span_r = params_.r_max_m - params_.r_min_m;
    const T span_a = params_.az_max_rad - params_.az_min_rad;
    std::size_t nr = 0, na = 0;
    for (int attempt = 0; attempt < 16; ++attempt) {
      nr = static_cast<std::size_t>(span_r / cell_r) + 1u;
      na = static_cast<std::size_t>(span_a / cell_a) + 1u;
      if (grid_.reset(nr, na)) break;
      cell_r *= T(2);
      cell_a *= T(2);
      nr = 0;
    }
    if (nr == 0) return;
    // Pool uniform-explained measurements outside every component gate.
    mark_pooled(pool_first, pool_end);
    T uniform_total = T(0);
    for (std::size_t si = pool_first; si < pool_end; ++si) {
      const ScanSlot& s = store_[si];
      for (std::size_t j = 0; j < s.count; ++j) {
        if (pooled_[si][j] == 0) continue;
        uniform_total += T(1);
        grid_.add(cell_index(s.r[j], s.az[j], cell_r, cell_a, na));
      }
    }
    const T lambda0 = uniform_total / static_cast<T>(n_pool);
    const T mu_cell = static_cast<T>(n_pool) * lambda0 * cell_r * cell_a / volume_;
    T thr = params_.clutter_seed_factor * mu_cell;
    // 2 points per pooled scan, counted as if at least 7 scans (the paper's
    // K) were pooled: with only a few scans pooled (start of an online run)
    // two nearby points - e.g. two targets - would seed a component, and two
    // neighbouring clouds would merge into one seed [impl].
    const std::size_t n_eff = n_pool > kMinSeedScans ? n_pool : kMinSeedScans;
    const T thr2 = T(2) * static_cast<T>(n_eff);
    if (thr < thr2) thr = thr2;
    const std::size_t threshold = static_cast<std::size_t>(thr) + 1u;  // count >= ceil-ish
    const std::size_t groups = grid_.label_seeds(threshold > 1u ? threshold - 1u : 1u);
    for (std::size_t g = 1; g <= groups; ++g) {
      NwStats st{};
      AmpStats as{};
      bool have_ref = false;
      for (std::size_t si = pool_first; si < pool_end; ++si) {
        const ScanSlot& s = store_[si];
        for (std::size_t j = 0; j < s.count; ++j) {
          if (pooled_[si][j] == 0) continue;
          if (grid_.label(cell_index(s.r[j], s.az[j], cell_r, cell_a, na)) != g) continue;
          if (!have_ref) {
            st.ref = Vec2(s.r[j], s.az[j]);
            have_ref = true;
          }
          st.add(Vec2(s.r[j], s.az[j]), T(1));
          as.w += T(1);
          as.s += s.amp[j] * s.amp[j] - params_.amplitude_threshold * params_.amplitude_threshold;
        }
      }
      if (!(st.n > thr2 - T(0.5))) continue;
      std::size_t slot = kMaxComp;
      for (std::size_t c = 0; c < kMaxComp; ++c) {
        if (!comps_[c].alive) {
          slot = c;
          break;
        }
      }
      if (slot == kMaxComp) {
        ++counters_.clutter_cap_hits;
        step_cap_hit_ = true;
        break;
      }
      const T N = st.n;
      const Vec2 off = st.sum / N;
      Mat2 S = st.sum_sq / N - off * off.transpose();
      // Floor the spread at the measurement noise so a tight seed stays SPD.
      S(0, 0) += R_(0, 0);
      S(1, 1) += R_(1, 1);
      const T per_scan = N / static_cast<T>(n_pool);
      CompSlot& cs = comps_[slot];
      cs = CompSlot{};
      cs.alive = true;
      cs.id = next_comp_id_++;
      cs.nw0.mu = st.ref + off;
      cs.nw0.mu(1) = mfbp::wrap_angle(cs.nw0.mu(1));
      cs.nw0.c = per_scan;
      cs.nw0.nu = per_scan + T(3);
      cs.nw0.w_inv = cs.nw0.nu * S;  // W = S^-1 / nu  =>  W^-1 = nu S
      cs.ig0.a = params_.ig_birth_shape;
      T mean_excess = as.s / as.w;
      if (!(mean_excess > T(1e-3))) mean_excess = T(1e-3);
      cs.ig0.b = params_.ig_birth_scale_factor * mean_excess;
      cs.alpha0 = per_scan;
      for (std::size_t k = 0; k < kMaxWindow; ++k) {  // until the next MF sweep
        cs.nwf[k] = cs.nw0;
        cs.nws[k] = cs.nw0;
        cs.igf[k] = cs.ig0;
        cs.igs[k] = cs.ig0;
      }
      ++counters_.clutter_born;
    }
  }

  std::size_t cell_index(T r, T az, T cell_r, T cell_a, std::size_t na) const {
    const std::size_t ir = static_cast<std::size_t>((r - params_.r_min_m) / cell_r);
    const std::size_t ia = static_cast<std::size_t>((az - params_.az_min_rad) / cell_a);
    return ir * na + ia;
  }

  /// Marks in pooled_ the measurements pooled for clutter seeding: explained
  /// by uniform clutter (or, on new scans, unexplained by tracks) and outside
  /// the gate of every live component (spec 3.10 step 1).
  void mark_pooled(std::size_t first, std::size_t end) {
    const std::size_t k_ref = n_win_ > 0 ? n_win_ - 1 : 0;
    for (std::size_t si = first; si < end; ++si) {
      const ScanSlot& s = store_[si];
      for (std::size_t j = 0; j < s.count; ++j) {
        pooled_[si][j] = (s.has_beliefs ? !(s.uniform_share[j] < T(0.5)) : unexplained(si, j)) ? 1u : 0u;
      }
    }
    for (const auto& cs : comps_) {
      if (!cs.alive) continue;
      const NW& nw = cs.nws[k_ref];
      const Mat2 C = nw.expected_covariance();
      const T det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
      for (std::size_t si = first; si < end; ++si) {
        const ScanSlot& s = store_[si];
        for (std::size_t j = 0; j < s.count; ++j) {
          if (pooled_[si][j] == 0) continue;
          const T er = s.r[j] - nw.mu(0);
          const T ea = mfbp::wrap_angle(s.az[j] - nw.mu(1));
          const T maha = (C(1, 1) * er * er - T(2) * C(0, 1) * er * ea + C(0, 0) * ea * ea) / det;
          if (maha < params_.clutter_gate_chi2) pooled_[si][j] = 0;
        }
      }
    }
  }

  // ------------------------------------------------------------ management
  void confirm_tracks(std::size_t n) {
    for (auto& t : tracks_) {
      if (!t.alive || t.confirmed) continue;
      for (std::size_t k = t.first; k < n; ++k) {
        if (t.vis[k] >= params_.confirm_threshold) {
          t.confirmed = true;
          ++counters_.tracks_confirmed;
          break;
        }
      }
    }
  }

  // Deletion (spec 3.10): b_s < delete_threshold on delete_run consecutive
  // scans (finalised history + the window tail), or tentative too long.
  void manage_tracks(std::size_t n, std::size_t fc) {
    for (auto& t : tracks_) {
      if (!t.alive) continue;
      for (std::size_t k = t.first; k < fc; ++k) {
        t.low_run = t.vis[k] < params_.delete_threshold ? t.low_run + 1u : 0u;
        ++t.age;
      }
      bool remove = t.low_run >= params_.delete_run;
      std::uint32_t run = t.low_run;
      for (std::size_t k = (fc > t.first ? fc : t.first); k < n && !remove; ++k) {
        run = t.vis[k] < params_.delete_threshold ? run + 1u : 0u;
        remove = run >= params_.delete_run;
      }
      if (!t.confirmed && t.age >= params_.tentative_timeout_scans) remove = true;
      if (remove) {
        t.alive = false;
        ++counters_.tracks_deleted;
      }
    }
  }

  // Component death: M_tau < clutter_death_count on all finalised scans of
  // clutter_death_windows consecutive windows.
  void manage_components(std::size_t n, std::size_t fc) {
    (void)n;
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      CompSlot& cs = comps_[c];
      if (!cs.alive) continue;
      bool all_low = fc > 0;
      for (std::size_t k = 0; k < fc; ++k) {
        if (!(component_count(k, c + 1) < params_.clutter_death_count)) all_low = false;
      }
      cs.low_windows = all_low ? cs.low_windows + 1u : 0u;
      if (cs.low_windows >= params_.clutter_death_windows) {
        cs.alive = false;
        ++counters_.clutter_deleted;
      }
    }
  }

  /// M_tau,k = M_k E[pi_tau] (spec 1.2 [fix], A12).
  T component_count(std::size_t k, std::size_t src) const {
    T total = T(0);
    for (std::size_t q = 0; q < kSources; ++q) total += alpha_s_[k][q];
    return total > T(0) ? m_[k] * alpha_s_[k][src] / total : T(0);
  }

  // ---------------------------------------------------------------- output
  void emit_estimate(std::size_t k) {
    // Filled in place: a ScanEstimate is kilobytes, too big for the stack.
    if (outputs_.resize(outputs_.size() + 1) != Status::kOk) return;  // <= kMaxWindow per call
    Estimate& est = outputs_.back();
    est.tracks.clear();
    est.clutter.clear();
    est.time_us = win(k).time_us;
    est.scan_index = static_cast<std::uint32_t>(finalized_);
    ++finalized_;
    for (auto& t : tracks_) {
      if (!t.alive || k < t.first || !t.confirmed) continue;
      // [impl] One missed scan is tolerated (report_existence_min).
      const T vis_prev = t.vis_emitted;
      t.vis_emitted = t.vis[k];
      if (t.vis[k] < params_.report_existence_min && vis_prev < params_.report_existence_min) continue;
      TrackReport<T> r;
      r.id = t.id;
      r.state = t.xs[k];
      r.covariance = t.Ps[k].get();
      r.existence = t.vis[k];
      r.snr = params_.use_amplitude ? t.igs[k].snr() : T(0);
      r.confirmed = true;
      r.measurement_index = t.best[k] >= 0 ? static_cast<std::int32_t>(win(k).orig_index[static_cast<std::size_t>(t.best[k])]) : -1;
      (void)est.tracks.push_back(r);  // cannot overflow: one report per track slot
    }
    ClutterReport<T> u;
    u.id = 0;
    u.uniform = true;
    u.mean = Vec2(T(0.5) * (params_.r_min_m + params_.r_max_m), T(0.5) * (params_.az_min_rad + params_.az_max_rad));
    u.covariance.setZero();
    if (params_.clutter_mode == ClutterMode::kKnown) {
      u.expected_count = params_.known_clutter.uniform_rate_per_scan;
      u.cnr = params_.known_clutter.uniform_cnr;
      (void)est.clutter.push_back(u);
      const std::size_t nk = params_.known_clutter.num_components < kMaxComp ? params_.known_clutter.num_components : kMaxComp;
      for (std::size_t c = 0; c < nk; ++c) {
        const auto& comp = params_.known_clutter.components[c];
        ClutterReport<T> r;
        r.id = static_cast<std::uint32_t>(c + 1);
        r.mean = comp.mean;
        r.covariance = comp.covariance;
        r.expected_count = comp.rate_per_scan;
        r.cnr = comp.cnr;
        (void)est.clutter.push_back(r);
      }
    } else {
      u.expected_count = estimate_clutter() ? component_count(k, 0) : params_.uniform_rate_per_scan;
      u.cnr = uniform_.igs[k].snr();
      (void)est.clutter.push_back(u);
      if (estimate_clutter()) {
        for (std::size_t c = 0; c < kMaxComp; ++c) {
          const CompSlot& cs = comps_[c];
          if (!cs.alive) continue;
          ClutterReport<T> r;
          r.id = cs.id;
          r.mean = cs.nws[k].mu;
          r.covariance = cs.nws[k].expected_covariance();
          r.expected_count = component_count(k, c + 1);
          r.cnr = cs.igs[k].snr();
          (void)est.clutter.push_back(r);
        }
      }
    }
  }

  // ----------------------------------------------------------------- shift
  void shift_window(std::size_t fc) {
    if (fc == 0) return;
    const std::size_t n = n_win_;
    const std::size_t last = fc - 1;
    for (auto& t : tracks_) {
      if (!t.alive) continue;
      if (t.first <= last) {
        t.x0 = t.xf[last];
        t.P0 = t.Pf[last].get();
        t.ig0 = t.igf[last];
        t.vis0 = t.visf[last];
        t.bias0 = t.biasf[last];
        t.t0_us = win(last).time_us;
        t.first = 0;
        t.from_birth = false;
      } else {
        t.first -= fc;
      }
      for (std::size_t k = fc; k < n; ++k) {
        const std::size_t d = k - fc;
        t.xf[d] = t.xf[k]; t.xs[d] = t.xs[k]; t.Pf[d] = t.Pf[k]; t.Ps[d] = t.Ps[k];
        t.igf[d] = t.igf[k]; t.igs[d] = t.igs[k]; t.amp[d] = t.amp[k];
        t.xi1[d] = t.xi1[k]; t.xi0[d] = t.xi0[k]; t.visf[d] = t.visf[k]; t.vis[d] = t.vis[k];
        t.extr[d] = t.extr[k]; t.missed[d] = t.missed[k]; t.n_edges[d] = t.n_edges[k];
        t.edge_meas[d] = t.edge_meas[k]; t.edge_w[d] = t.edge_w[k]; t.best[d] = t.best[k];
        t.mate[d] = t.mate[k]; t.biasf[d] = t.biasf[k]; t.qk[d] = t.qk[k];
      }
    }
    if (params_.clutter_mode != ClutterMode::kKnown) {
      uniform_.ig0 = uniform_.igf[last];
      uniform_.alpha0 = alpha_f_[last][0];
      for (std::size_t k = fc; k < n; ++k) {
        uniform_.igf[k - fc] = uniform_.igf[k];
        uniform_.igs[k - fc] = uniform_.igs[k];
      }
      for (std::size_t c = 0; c < kMaxComp; ++c) {
        CompSlot& cs = comps_[c];
        if (!cs.alive) continue;
        cs.nw0 = cs.nwf[last];
        cs.ig0 = cs.igf[last];
        cs.alpha0 = alpha_f_[last][c + 1];
        if (!(cs.alpha0 > T(1e-3))) cs.alpha0 = T(1e-3);
        for (std::size_t k = fc; k < n; ++k) {
          cs.nwf[k - fc] = cs.nwf[k];
          cs.nws[k - fc] = cs.nws[k];
          cs.igf[k - fc] = cs.igf[k];
          cs.igs[k - fc] = cs.igs[k];
        }
      }
      m_prev_ = m_[last];
      for (std::size_t k = fc; k < n; ++k) {
        alpha_f_[k - fc] = alpha_f_[k];
        alpha_s_[k - fc] = alpha_s_[k];
        m_[k - fc] = m_[k];
      }
    }
    // Scan storage: finalised scans become history, the oldest fall off.
    const std::size_t hist_cap = kStore - params_.window_length;
    std::size_t new_hist = n_hist_ + fc;
    std::size_t drop = new_hist > hist_cap ? new_hist - hist_cap : 0;
    if (drop > 0) {
      for (std::size_t si = drop; si < n_hist_ + n; ++si) store_[si - drop] = store_[si];
      new_hist -= drop;
    }
    n_hist_ = new_hist;
    n_win_ = n - fc;
  }

  // ----------------------------------------------------------------- state
  Params params_{};
  bool initialized_ = false;
  int n_order_ = 1;
  T volume_ = T(1);
  T log_volume_ = T(0);
  T log_norm_R_ = T(0);
  Mat2 R_ = Mat2::Identity();
  Mat2 R_inv_ = Mat2::Identity();

  std::array<ScanSlot, kStore> store_{};
  std::size_t n_hist_ = 0;  ///< history scans at the front of store_
  std::size_t n_win_ = 0;   ///< window scans after them

  std::array<TrackSlot, kMaxTargets> tracks_{};
  std::array<CompSlot, kMaxComp> comps_{};
  UniformSlot uniform_{};
  std::array<std::array<T, kSources>, kMaxWindow> alpha_f_{}, alpha_s_{};
  std::array<T, kMaxWindow> m_{};
  T m_prev_ = T(30);

  /// Predicted measurement moments of each track on the scan being associated.
  struct TrackMoments {
    Vec2 z = Vec2::Zero();         ///< [range m, azimuth rad] (cavity if association_cavity)
    Vec2 z_shared = Vec2::Zero();  ///< z, or the common mean of unresolved tracks
    Mat2 Sz = Mat2::Zero();        ///< its covariance (without R)
    T z_dop = T(0);                ///< predicted radial velocity [m/s]
    T var_dop = T(0);              ///< its variance [(m/s)^2]
    bool ok = false;               ///< participates and the moments exist
  };
  std::array<TrackMoments, kMaxTargets> moments_{};

  Bp bp_{};
  mfbp::SeedGrid<kMaxGridCells> grid_{};
  std::array<std::array<std::uint8_t, kMaxMeas>, kStore> unexplained_{};  ///< birth scratch
  std::array<std::array<std::uint8_t, kMaxMeas>, kStore> pooled_{};       ///< seeding scratch

  OutputQueue outputs_{};
  TrackerCounters counters_{};
  std::uint64_t gate_overflows_ = 0;
  std::uint64_t bp_runs_ = 0;
  std::uint64_t bp_iterations_ = 0;
  std::uint32_t next_track_id_ = 1;
  std::uint32_t next_comp_id_ = 1;
  std::uint64_t finalized_ = 0;
  ScanClock clock_{};
  std::array<bool, kMaxMeas> kept_{};  ///< store_scan: input measurement j kept (duplicate rule)
  bool step_cap_hit_ = false;
};

}  // namespace mptrack
