// Neural enhanced message passing (seed 003 section III-F, Algorithm 1
// lines 15-24; docs/algorithms/nemp.md §NEMP loop) in MF-BP's association.
//
// Per detection j of a window scan the state keeps the classifier features
// h_j (computed once, when the scan arrives) and the log factor L_j that
// currently multiplies every clutter evidence of j (the NEMP message on
// a_0j, seed 003 eqs. (24)-(25) mapped to ratio-form BP). One NEMP round,
// after a BP run:
//   1. extrinsic tracker belief: the clutter posterior of j with its own
//      factor e^{L_j} divided out (no double counting over rounds and MP
//      iterations), p_FG = P(target-originated) (the polarity fix);
//   2. w_j = g_c(h_j, p_FG), corrected for the training prior;
//   3. BetP_j = DS(p_FG, w_j) (optionally discounted);
//   4. L_j = ln odds(p_FG) - ln odds(BetP_j), so the next BP's posterior of
//      j is BetP_j given the same extrinsic messages.
// A detection without a patch keeps L_j = 0 (w = 0.5, the neutral element),
// and L_j = 0 is never applied, so with no evidence MF-BP runs the exact
// operations it runs without NEMP.
//
// The state is owned by the caller (static storage on a board) and attached
// to the tracker with MfbpTracker::attach_nemp(); the tracker does not grow.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/classify/ds_fusion.h"
#include "mptrack/classify/sea_classifier.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::mfbp {

/// Upper bound of NempParams::rounds (each round is one more BP run per
/// association).
inline constexpr std::size_t kMaxNempRounds = 8;

template <class T>
struct NempParams {
  /// NEMP rounds T per association (1..kMaxNempRounds); each reruns BP
  /// with the fused clutter messages.
  std::size_t rounds = 2;
  /// Reliability alpha of the classifier in the DS fusion, in [0, 1]
  /// (1 = the paper's plain Dempster rule).
  T nn_reliability = T(1);
  /// Gain on the classifier's log-odds before the fusion, in (0, 16]
  /// (docs/algorithms/nemp.md §Fusion, "Gain"; 1 = the network's output).
  T nn_log_odds_gain = T(1);
  /// Upper bound on the classifier's probability before the fusion, in
  /// [0.5, 1] (docs/algorithms/nemp.md §Fusion, "Clutter side"): 0.5 lets
  /// the classifier only raise a detection's clutter weight, never lower
  /// it; 1 = no bound. w = 0.5 stays neutral.
  T nn_max_target_prob = T(1);
  /// Two-point birth uses the belief too (docs/algorithms/nemp.md §Birth):
  /// a detection of a window scan whose classifier probability at the
  /// uninformative tracker belief 0.5 (prior-corrected) is below this value
  /// cannot be a birth point. 0 = off; 0.5 vetoes what MP-NN removes. A
  /// detection without a patch, or w = 0.5 exactly, is never vetoed for
  /// values <= 0.5, so the neutral element stays neutral.
  T birth_min_target_prob = T(0);
  /// A veto over a track's tentative life (docs/algorithms/nemp.md §Birth,
  /// "Tentative tracks"): a detection whose classifier probability at
  /// belief 0.5 (as for the birth veto) is below this value is left out of
  /// the association of every unconfirmed track, as MP-NN's removal leaves
  /// it out at 0.5; confirmed tracks keep the soft fusion. 0 = off; the
  /// neutral element stays neutral for values <= 0.5.
  T tentative_min_target_prob = T(0);
};

template <class T>
[[nodiscard]] Status validate(const NempParams<T>& p) {
  if (p.rounds < 1 || p.rounds > kMaxNempRounds) return Status::kInvalidArgument;
  if (!(p.nn_reliability >= T(0) && p.nn_reliability <= T(1))) return Status::kInvalidArgument;
  if (!(p.nn_log_odds_gain > T(0) && p.nn_log_odds_gain <= T(16))) return Status::kInvalidArgument;
  if (!(p.nn_max_target_prob >= T(0.5) && p.nn_max_target_prob <= T(1))) return Status::kInvalidArgument;
  if (!(p.birth_min_target_prob >= T(0) && p.birth_min_target_prob <= T(1))) return Status::kInvalidArgument;
  if (!(p.tentative_min_target_prob >= T(0) && p.tentative_min_target_prob <= T(1))) return Status::kInvalidArgument;
  return Status::kOk;
}

/// Per-detection evidence passed with a scan, indexed like the scan's
/// measurements: features of detections with a patch.
template <std::size_t N>
struct ScanEvidence {
  std::array<classify::Features, N> features{};
  std::array<bool, N> has_patch{};
};

template <class T, class Caps>
class NempState {
 public:
  static constexpr std::size_t kMaxMeas = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxWindow = Caps::kMaxWindow;
  using Evidence = ScanEvidence<kMaxMeas>;

  /// Binds a ready classifier (kept by pointer) and validated params.
  [[nodiscard]] Status init(const classify::SeaClassifier* classifier, const NempParams<T>& p) {
    if (classifier == nullptr || !classifier->ready()) return Status::kNotInitialized;
    const Status s = validate(p);
    if (s != Status::kOk) return s;
    classifier_ = classifier;
    params_ = p;
    prior_ = classifier->weights().train_target_fraction;
    return Status::kOk;
  }

  bool ready() const { return classifier_ != nullptr; }
  const NempParams<T>& params() const { return params_; }

  /// Evidence of the scan just stored at window index k: stored measurement
  /// c is input measurement orig_index[c]. ev == nullptr: no patches. The
  /// vetoes go into the slot (ScanSlot::kBirthVetoed, kTentativeVetoed), so
  /// they move into history with the scan.
  template <class Slot>
  void store_scan(std::size_t k, Slot& s, const Evidence* ev) {
    for (std::size_t c = 0; c < s.count; ++c) {
      const std::size_t j = s.orig_index[c];
      has_[k][c] = ev != nullptr && ev->has_patch[j];
      features_[k][c] = ev != nullptr ? ev->features[j] : classify::Features{};
      log_factor_[k][c] = T(0);
      const T w = has_[k][c] ? target_prob_at_half(features_[k][c]) : T(0.5);
      s.set_birth_vetoed(c, below(w, params_.birth_min_target_prob));
      s.set_tentative_vetoed(c, below(w, params_.tentative_min_target_prob));
    }
    // Belief record: input detection j starts at the uninformative 0.5
    // (detections refused at intake keep it).
    belief_[k].fill(0.5f);
    for (std::size_t c = 0; c < s.count; ++c) orig_[k][c] = static_cast<std::uint16_t>(s.orig_index[c]);
  }

  /// The window slides by fc scans (MfbpTracker::shift_window).
  void shift(std::size_t fc, std::size_t n) {
    for (std::size_t k = 0; k < fc && k < n; ++k) {
      if (finalised_ < kMaxWindow) finalised_belief_[finalised_++] = belief_[k];
    }
    for (std::size_t k = fc; k < n; ++k) {
      has_[k - fc] = has_[k];
      features_[k - fc] = features_[k];
      log_factor_[k - fc] = log_factor_[k];
      belief_[k - fc] = belief_[k];
      orig_[k - fc] = orig_[k];
    }
  }

  /// The tracker's extrinsic P(target-originated) of every detection of the
  /// scans finalised since clear_finalised(), oldest first, indexed like the
  /// scan's input measurements: the last p_FG a NEMP round computed before
  /// the scan left the window, 0.5 for detections without a patch or
  /// refused at intake. With nn_reliability = 0 the rounds change nothing
  /// (BetP = p_FG, L = 0), so this records plain MF-BP's association belief:
  /// the classifier's stage-2 input (seed 003 Sec. III-D;
  /// docs/algorithms/nemp.md §Belief record). At most kMaxWindow scans are
  /// kept between clears.
  std::size_t finalised_scans() const { return finalised_; }
  float finalised_belief(std::size_t f, std::size_t j) const { return finalised_belief_[f][j]; }
  void clear_finalised() { finalised_ = 0; }

  /// Multiplies the clutter evidence of each detection of scan k by its
  /// NEMP factor (log domain, before bp.run()); factors of 0 are skipped.
  template <class Bp>
  void apply(std::size_t k, std::size_t count, Bp& bp) const {
    for (std::size_t j = 0; j < count; ++j) {
      if (log_factor_[k][j] != T(0)) bp.add_clutter_log(j, log_factor_[k][j]);
    }
  }

  /// One NEMP round from the beliefs of a finished BP run on scan k (file
  /// comment, steps 1-4). Returns whether any factor changed (else another
  /// BP run would repeat this one).
  template <class Bp>
  bool update(std::size_t k, std::size_t count, const Bp& bp) {
    bool changed = false;
    for (std::size_t j = 0; j < count; ++j) {
      if (!has_[k][j]) continue;
      const T p_fg = extrinsic_target_belief(bp, j, log_factor_[k][j]);
      belief_[k][orig_[k][j]] = static_cast<float>(p_fg);
      const float w_raw = classifier_->target_probability(features_[k][j], static_cast<float>(p_fg));
      const T w_bal = static_cast<T>(classify::correct_training_prior(w_raw, prior_));
      const T w_scaled = classify::scale_log_odds(w_bal, params_.nn_log_odds_gain);
      const T w = w_scaled > params_.nn_max_target_prob ? params_.nn_max_target_prob : w_scaled;
      const T betp = classify::ds_discounted_betp(p_fg, w, params_.nn_reliability);
      const T l = classify::clutter_log_factor(p_fg, betp);
      changed = changed || l != log_factor_[k][j];
      log_factor_[k][j] = l;
    }
    return changed;
  }

  /// The NEMP factor of stored detection c of window scan k (tests, reports).
  T log_factor(std::size_t k, std::size_t c) const { return log_factor_[k][c]; }

  /// The tracker's P(target-originated) of detection j without its own
  /// NEMP factor: clutter log-odds of the posterior minus L_j.
  template <class Bp>
  static T extrinsic_target_belief(const Bp& bp, std::size_t j, T log_factor) {
    T pc = T(0);
    for (std::size_t tau = 0; tau < bp.num_sources(); ++tau) pc += bp.clutter_belief(tau, j);
    pc = classify::clamp_probability(pc);
    const T clutter_log_odds = (dmath::dlog(pc) - dmath::dlog1p(-pc)) - log_factor;
    return T(1) / (T(1) + dmath::dexp(clutter_log_odds));
  }

 private:
  /// The classifier probability the vetoes test (birth_min_target_prob,
  /// tentative_min_target_prob): the MLP at the uninformative belief 0.5,
  /// prior-corrected, as MP-NN's removal, so a veto does not depend on the
  /// association state of the moment. Not computed while both are off.
  T target_prob_at_half(const classify::Features& h) const {
    if (!(params_.birth_min_target_prob > T(0)) && !(params_.tentative_min_target_prob > T(0))) return T(0.5);
    const float w_raw = classifier_->target_probability(h, 0.5f);
    return static_cast<T>(classify::correct_training_prior(w_raw, prior_));
  }

  /// A veto at `threshold` (0 = off) holds for probabilities below it.
  static bool below(T w, T threshold) { return threshold > T(0) && w < threshold; }

  const classify::SeaClassifier* classifier_ = nullptr;
  NempParams<T> params_{};
  float prior_ = 0.5f;
  std::array<std::array<bool, kMaxMeas>, kMaxWindow> has_{};
  std::array<std::array<classify::Features, kMaxMeas>, kMaxWindow> features_{};
  std::array<std::array<T, kMaxMeas>, kMaxWindow> log_factor_{};
  // Belief record (finalised_belief()): per window scan, by input index.
  static_assert(kMaxMeas <= 65536, "orig_ holds input indices in 16 bits");
  std::array<std::array<float, kMaxMeas>, kMaxWindow> belief_{};
  std::array<std::array<std::uint16_t, kMaxMeas>, kMaxWindow> orig_{};
  std::array<std::array<float, kMaxMeas>, kMaxWindow> finalised_belief_{};
  std::size_t finalised_ = 0;
};

}  // namespace mptrack::mfbp
