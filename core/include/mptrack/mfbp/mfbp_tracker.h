// MF-BP multitarget tracker of seed 000 (paper: MP-RMTT, Bai et al.): mean-
// field + loopy-BP message passing over a sliding window, with target SNR,
// visibility and non-uniform clutter estimation (docs/algorithms/mfbp.md).
//
// Call pattern (the tracker contract of tracker_contract.h):
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
// Per processed window (seed 000 Algorithm 1; docs/algorithms/mfbp.md
// §Window schedule), the schedule in process_window():
//   1. "no information" association beliefs on new scans, the previous
//      window's beliefs on overlapping scans;
//   2. one MF sweep (Dirichlet, visibility, clutter, targets) -> b^(0);
//   3. track birth (two-point) and clutter-component birth (grid seeds);
//   4. outer loop, up to mp_max_iterations: per scan local evidence and
//      loopy BP, then the MF sweep; stop when max |delta a_hat| < tolerance;
//   5. confirmation, output of the finalised scans, deletion, window shift
//      (the filtered beliefs at the last finalised scan become the priors).
// The parts live in this folder: window_store.h (scans), track_slot.h and
// clutter_slot.h (beliefs, each slot shifts itself), clutter_chain.h and
// target_chain.h (the MF sweeps), evidence.h and association.h (local
// evidence and BP), track_spawn.h and clutter_spawn.h (birth),
// track_management.h and reporting.h (confirmation, deletion, output).
//
// Doppler (not in the paper; our choice, docs/algorithms/mfbp.md
// §Departures): when a scan has_doppler and use_doppler is set, the radial
// velocity joins the cubature update as a third measurement row and the
// association evidence (predictive density for targets, uniform on
// [-span, span] for clutter).
//
// Memory (sizeof as built, EIGEN_DONT_VECTORIZE): x86-64 float/SmallBoardCaps
// 52 712 B, float/DefaultCaps 339 936 B, double/DefaultCaps 626 224 B;
// Cortex-M7 float 52 416 B and 339 200 B (docs/results/bench/footprint.json). The largest
// parts: per-track window beliefs, the stored scans, the BP messages and the
// output queue.
//
// Overflow policies (all counted, none silent):
//   * measurements: a Scan cannot exceed Caps::kMaxMeasurements, so no
//     measurement is dropped for capacity; invalid ones are skipped and
//     counted in measurements_invalid (step returns kPartial);
//   * gated pairs: each track keeps its mfbp::kMaxGatePairs<Caps> most
//     likely measurements per scan, from a pool of mfbp::kMaxGatePool<Caps>
//     per scan shared by every track; a short pool cuts the longest lists
//     to a common quota (association.h). association_cap_hits counts the
//     dropped pairs once per window that associates the scan; step returns
//     kCapacityExceeded;
//   * tracks: a birth that finds every slot taken evicts the least likely
//     tentative track if that one is less likely than a newborn
//     (tentative_evicted; not a cap hit); otherwise it is refused
//     (track_cap_hits). A confirmed track is never evicted. Components
//     beyond kMaxClutterComponents are refused (clutter_cap_hits); both
//     refusals make step return kCapacityExceeded;
//   * birth candidates: init() refuses birth_max_per_window above
//     Caps::kMaxBirthCandidates (kInvalidArgument).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/measurement.h"
#include "mptrack/mfbp/association.h"
#include "mptrack/mfbp/clutter_chain.h"
#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/clutter_spawn.h"
#include "mptrack/mfbp/mfbp_caps.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/nemp.h"
#include "mptrack/mfbp/reporting.h"
#include "mptrack/mfbp/target_chain.h"
#include "mptrack/mfbp/track_management.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/track_spawn.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/profile.h"
#include "mptrack/scan_clock.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"
#include "mptrack/tracker_contract.h"

namespace mptrack {

template <class T, class Caps = DefaultCaps>
class MfbpTracker {
  static_assert(caps_are_valid<Caps>());
  static_assert(mfbp::mfbp_caps_are_valid<Caps>());
  static_assert(Caps::kMaxWindow <= 64, "visibility_forward_backward keeps 64 scans at most");
  static_assert(Caps::kMaxTargets < 65535, "TrackSlot::mate is a 16-bit index");

 public:
  using Scalar = T;
  using Params = MfbpParams<T>;
  static constexpr std::size_t kMaxTargets = Caps::kMaxTargets;
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxComp = Caps::kMaxClutterComponents;
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  /// Gated measurements kept per track and scan (mfbp_caps.h).
  static constexpr std::size_t kMaxGate = mfbp::kMaxGatePairs<Caps>;
  /// Gated pairs per scan shared by every track (mfbp_caps.h).
  static constexpr std::size_t kGatePool = mfbp::kMaxGatePool<Caps>;

  using ScanType = Scan<T, kMaxMeas>;
  using Estimate = ScanEstimate<T, kMaxTargets, kMaxComp>;
  using OutputQueue = StaticVector<Estimate, kMaxWindow>;

  /// Checks params (MfbpParams::validate) and against the caps this
  /// tracker was instantiated with: the window, the ranked birth
  /// candidates (mfbp_caps.h; more would be cut silently) and the known
  /// clutter components. On failure names the field in *where (validate.h).
  static Status validate(const Params& p, ParamError* where = nullptr) {
    MPTRACK_TRY(p.validate(where));
    MPTRACK_CHECK_PARAM(where, "window_length", check_at_most(p.window_length, kMaxWindow, "Caps::kMaxWindow"));
    MPTRACK_CHECK_PARAM(where, "birth_max_per_window",
                        check_at_most(p.birth_max_per_window, mfbp::kMaxBirthCandidates<Caps>, "mfbp::kMaxBirthCandidates<Caps>"));
    if (p.clutter_mode == ClutterMode::kKnownMap) {
      MPTRACK_CHECK_PARAM(where, "known_clutter.num_components",
                          check_at_most(p.known_clutter.num_components, kMaxComp, "Caps::kMaxClutterComponents"));
    }
    return Status::kOk;
  }

  /// Validates params (validate() above) and resets every state.
  Status init(const Params& params) {
    static_assert(tracker_contract_holds<MfbpTracker>());  // tracker_contract.h
    initialized_ = false;
    MPTRACK_TRY(validate(params));
    params_ = params;
    model_.set(params);
    for (auto& t : tracks_) t.alive = false;
    for (auto& c : clutter_.comps) c.alive = false;
    counters_ = TrackerCounters{};
    outputs_.clear();
    has_provisional_ = false;
    provisional_base_ = false;
    store_.clear();
    next_track_id_ = 1;
    next_comp_id_ = 1;
    finalized_ = 0;
    assoc_stats_ = mfbp::AssociationStats{};
    clock_.start(params_.max_gap_s);
    // Clutter priors at "scan -1".
    clutter_.uniform.ig0.a = params.uniform_cnr_prior_shape;
    clutter_.uniform.ig0.b = (T(1) + params.uniform_cnr_prior) * (params.uniform_cnr_prior_shape - T(1));
    clutter_.uniform.alpha0 = effective_uniform_rate(params.uniform_rate_per_scan, params);
    clutter_.m_prev = effective_uniform_rate(params.uniform_rate_per_scan, params);
    initialized_ = true;
    return Status::kOk;
  }

  /// Replaces the known clutter map (ClutterMode::kKnown) between scans.
  Status set_known_clutter(const KnownClutter<T>& kc) {
    if (!initialized_) return Status::kNotInitialized;
    Params p = params_;
    p.known_clutter = kc;
    MPTRACK_TRY(validate(p));
    params_.known_clutter = kc;
    return Status::kOk;
  }

  /// Consumes one scan. kOutOfOrder (state unchanged) if time does not
  /// increase; kPartial if measurements were rejected (counted);
  /// kCapacityExceeded if an internal cap was hit (see the file comment;
  /// takes precedence over kPartial). Both are successes with losses.
  Status step(const ScanType& scan) { return step_with(scan, nullptr); }

  /// NEMP (docs/algorithms/nemp.md): a caller-owned, initialised state whose
  /// classifier evidence enters every association; nullptr detaches it.
  /// Attach before the first scan (or after flush()): scans stored without
  /// the state carry no evidence.
  [[nodiscard]] Status attach_nemp(mfbp::NempState<T, Caps>* nemp) {
    if (nemp != nullptr && !nemp->ready()) return Status::kNotInitialized;
    nemp_ = nemp;
    return Status::kOk;
  }

  /// step() with the classifier features of the scan's detections (indexed
  /// like scan.measurements). kNotInitialized without an attached NEMP state.
  Status step(const ScanType& scan, const mfbp::ScanEvidence<kMaxMeas>& evidence) {
    if (nemp_ == nullptr) return Status::kNotInitialized;
    return step_with(scan, &evidence);
  }

 private:
  Status step_with(const ScanType& scan, const mfbp::ScanEvidence<kMaxMeas>* evidence) {
    outputs_.clear();  // tracker_contract.h rule 1: a refused scan finalises nothing
    has_provisional_ = false;
    MPTRACK_TRY(clock_.admit(initialized_, scan.time_us, counters_));
    const std::uint64_t caps_before = total_cap_hits(counters_);
    if (clock_.gap_exceeded(scan.time_us)) {
      restart_after_gap();
      clock_.restart();
    }
    clock_.advance(scan.time_us);
    ++counters_.scans;
    MPTRACK_PROFILE_STEP(g_mfbp);
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kInput);
    const bool partial = store_.store_scan(scan, params_, counters_, kept_);
    if (nemp_ != nullptr) nemp_->store_scan(store_.n_win(), store_.win(store_.n_win()), evidence);
    // "No information" association for the tracks on this new scan.
    for (auto& t : tracks_) {
      if (t.alive) t.open_scan(store_.n_win());
    }
    store_.push_window();
    if (store_.n_win() >= params_.window_length) {
      process_window(params_.slide, /*provisional=*/true);
    } else if (provisional_base_) {
      // A step that only stores its scan: the last provisional estimate, predicted.
      mfbp::coast_report(provisional_, scan.time_us, finalized_ + store_.n_win() - 1, params_.accel_var_m2ps4);
      has_provisional_ = true;
    }
    return accepted_status(counters_, caps_before, partial);
  }

 public:
  /// End of data: processes and finalises every scan still held back.
  Status flush() {
    if (!initialized_) return Status::kNotInitialized;
    outputs_.clear();
    has_provisional_ = false;
    provisional_base_ = false;  // every held scan is final now
    const std::uint64_t caps_before = total_cap_hits(counters_);
    MPTRACK_PROFILE_STEP(g_mfbp);
    if (store_.n_win() > 0) process_window(store_.n_win());
    return accepted_status(counters_, caps_before, false);
  }

  const OutputQueue& outputs() const { return outputs_; }
  /// Provisional (lag-0) output (docs/algorithms/mfbp.md §Provisional
  /// output): the estimate of the scan the last step() consumed. After a
  /// step() that processed a window without finalising its newest scan,
  /// that scan's estimate as the window sees it now, every confirmed track
  /// with the rules of outputs(); after a step() that only stored its scan
  /// (slide > 1), that estimate predicted to the scan's time (CV model, no
  /// measurement). Later windows revise it; outputs() hands out the final
  /// estimate of the same scan window_length - slide scans later. None
  /// (has_provisional() false) before the first window, after a refused
  /// scan, flush() or a gap restart (until the next window), or when every
  /// scan is finalised at once (the online filter, whose outputs() have no
  /// lag). Valid until the next call.
  bool has_provisional() const { return has_provisional_; }
  const Estimate& provisional() const { return provisional_; }
  const TrackerCounters& counters() const { return counters_; }
  /// Loopy-BP runs and their total iterations since init() (diagnostics).
  std::uint64_t bp_runs() const { return assoc_stats_.bp_runs; }
  std::uint64_t bp_iterations() const { return assoc_stats_.bp_iterations; }
  const Params& params() const { return params_; }
  /// Live tracks (tentative and confirmed) right now.
  std::size_t live_tracks() const { return tracks_.live(); }
  /// Live non-uniform clutter components right now.
  std::size_t live_components() const { return clutter_.live(); }

 private:
  /// Max-gap rule (scan_clock.h, docs/reliability.md F1): the scans still
  /// in the window are finalised first (their estimates go to outputs(), so
  /// nothing accepted is lost), then every track and Gaussian clutter
  /// component is dropped and the scan history cleared; the uniform clutter
  /// and the Dirichlet state carry over.
  void restart_after_gap() {
    ++counters_.gap_resets;
    provisional_base_ = false;
    if (store_.n_win() > 0) process_window(store_.n_win());
    mfbp::drop_all(tracks_, clutter_, counters_);
    store_.clear();
  }

  bool estimate_clutter() const { return mfbp::estimate_clutter(params_); }

  // ------------------------------------------------------------ window loop
  void process_window(std::size_t finalize_count, bool provisional = false) {
    const std::size_t n = store_.n_win();
    if (finalize_count > n) finalize_count = n;
    const std::uint64_t newest_index = finalized_ + n - 1;  // scan number of window scan n - 1
    mf_sweep(n);
    spawn_tracks(n);
    const std::uint32_t first_new_component = next_comp_id_;
    if (estimate_clutter() && params_.clutter_birth) {
      clutter_spawner_.spawn(n, store_, clutter_, track_spawner_, params_, model_, next_comp_id_,
                             counters_);
    }
    mf_sweep(n);
    // Only when this spawn made a component (ids are issued in birth order).
    if (params_.retire_in_new_clutter && next_comp_id_ != first_new_component) {
      retire_explained_tracks(n, first_new_component);
    }
    for (std::size_t l = 0; l < params_.mp_max_iterations; ++l) {
      T delta = T(0);
      for (std::size_t k = 0; k < n; ++k) {
        const T d = associator_.associate(k, store_, tracks_, clutter_, params_, model_, counters_,
                                          assoc_stats_, l == 0, nemp_);
        delta = d > delta ? d : delta;
      }
      mf_sweep(n);
      if (delta < params_.mp_tolerance) break;
    }
    if (params_.late_birth) late_birth(n);
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kOutput);
    mfbp::confirm_tracks(tracks_, n, mfbp::confirm_lookahead(n, finalize_count, params_), params_, counters_);
    mfbp::suppress_duplicates(tracks_, n, params_, counters_);
    for (std::size_t k = 0; k < finalize_count; ++k) emit_estimate(k);
    mfbp::manage_tracks(tracks_, clutter_, n, finalize_count, n > 0 ? store_.win(n - 1).time_us : 0u, params_,
                        counters_);
    if (estimate_clutter()) mfbp::manage_components(clutter_, finalize_count, params_, counters_);
    if (provisional && finalize_count < n) {
      mfbp::report_scan(provisional_, n - 1, newest_index, store_, tracks_, clutter_, params_,
                        mfbp::ReportKind::kProvisional);
      has_provisional_ = true;
      provisional_base_ = true;
    }
    shift_window(finalize_count);
  }

  // The tracks the components born by this window's spawn (ids from
  // first_new) explain (mfbp::retire_tracks_in_new_component); after a
  // sweep, so every track has a state on the newest window scan. They were
  // seeded from the stored scans up to the newest, at most kMaxWindow.
  void retire_explained_tracks(std::size_t n, std::uint32_t first_new) {
    const std::size_t stored = store_.n_hist() + n;
    const std::size_t seed_scans = stored < kMaxWindow ? stored : kMaxWindow;
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      if (!clutter_.comps[c].alive || clutter_.comps[c].id < first_new) continue;
      mfbp::retire_tracks_in_new_component(tracks_, clutter_, c, seed_scans, n, params_, counters_);
    }
  }

  // One MF sweep (seed 000 Algorithm 1 lines 4-7): Dirichlet, clutter,
  // then per track visibility and targets.
  void mf_sweep(std::size_t n) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kMfUpdate);
    if (params_.clutter_mode != ClutterMode::kKnown) {
      mfbp::clutter_sweep(clutter_, store_, n, params_, model_.n_order);
    }
    for (auto& t : tracks_) {
      if (t.alive) sweep_track(t, n);
    }
  }

  void sweep_track(mfbp::TrackSlot<T, Caps>& t, std::size_t n) {
    mfbp::visibility_sweep(t, n, params_);
    mfbp::target_sweep(t, tracks_, store_, n, params_, model_, counters_);
  }

  void spawn_tracks(std::size_t n) {
    track_spawner_.spawn(n, store_, tracks_, clutter_, params_, model_, next_track_id_, counters_);
  }

  // Second birth pass (our choice, docs/algorithms/mfbp.md §Departures):
  // every scan now has association beliefs, so "unexplained" is
  // sum_i a_ij < threshold everywhere. Before the loop a new scan could
  // only use the gate test, which never lets a second track start inside
  // an existing track's gate (two close targets; the online filter, whose
  // current scan is always new, depends on this). Tracks born here enter
  // the association from the next window on.
  void late_birth(std::size_t n) {
    MPTRACK_PROFILE_STAGE(g_mfbp, MfbpStage::kBirth);
    const std::uint32_t first_new = next_track_id_;
    spawn_tracks(n);
    for (auto& t : tracks_) {
      if (t.alive && t.id >= first_new) sweep_track(t, n);
    }
  }

  void emit_estimate(std::size_t k) {
    // Filled in place: a ScanEstimate is kilobytes, too big for the stack.
    if (outputs_.resize(outputs_.size() + 1) != Status::kOk) return;  // <= kMaxWindow per call
    mfbp::report_scan(outputs_.back(), k, finalized_, store_, tracks_, clutter_, params_);
    ++finalized_;
  }

  /// The window slides by fc finalised scans: every slot moves its beliefs
  /// (the clutter ones only when they are estimated), the scans become history.
  void shift_window(std::size_t fc) {
    if (fc == 0) return;
    const std::size_t n = store_.n_win();
    const std::uint64_t t_last_us = store_.win(fc - 1).time_us;
    for (auto& t : tracks_) {
      if (t.alive) t.shift(fc, n, t_last_us);
    }
    if (params_.clutter_mode != ClutterMode::kKnown) clutter_.shift(fc, n);
    store_.shift(fc, params_.window_length);
    if (nemp_ != nullptr) nemp_->shift(fc, n);
  }

  // ----------------------------------------------------------------- state
  Params params_{};
  bool initialized_ = false;
  mfbp::ModelConstants<T> model_{};
  mfbp::WindowStore<T, Caps> store_{};
  mfbp::TrackTable<T, Caps> tracks_{};
  mfbp::ClutterTable<T, Caps> clutter_{};
  mfbp::Associator<T, Caps> associator_{};
  mfbp::ClutterSpawner<T, Caps> clutter_spawner_{};
  mfbp::TrackSpawner<T, Caps> track_spawner_{};

  OutputQueue outputs_{};
  Estimate provisional_{};
  bool has_provisional_ = false;
  bool provisional_base_ = false;  ///< provisional_ holds a window's estimate that buffering steps predict
  TrackerCounters counters_{};
  mfbp::AssociationStats assoc_stats_{};
  std::uint32_t next_track_id_ = 1;
  std::uint32_t next_comp_id_ = 1;
  std::uint64_t finalized_ = 0;
  ScanClock clock_{};
  std::array<bool, kMaxMeas> kept_{};  ///< store_scan: input measurement j kept (duplicate rule)
  mfbp::NempState<T, Caps>* nemp_ = nullptr;  ///< attach_nemp(); not owned
};

}  // namespace mptrack
