// GM-PHD and GM-CPHD filters with amplitude information (IGGM, seed 001;
// docs/algorithms/gm-phd.md), in fixed memory. The two share everything except the
// weight factors of the update, selected by the Cardinalized parameter:
//   GmPhdFilter<T, Caps>  = PhdFilter<T, Caps, false>   (seed 001 eqs. (66)-(72);
//                                                        docs/algorithms/gm-phd.md §Update)
//   GmCphdFilter<T, Caps> = PhdFilter<T, Caps, true>    (Vo, Vo, Cantoni 2007)
//
// Per scan (step):
//   predict   w *= p_S, CV kinematics, power forgetting (seed 001 eq. (50)); births
//             seeded by the previous scan's measurements (filter_common.h);
//             clutter statistics forgotten (clutter_estimator.h)
//   update    PHD:  missed w (1 - P_D); detected w q(z) / (kappa(z) + sum w q(z))
//             CPHD: the same terms scaled by the cardinality ratios of
//                   cardinality.h, and p(n) updated
//             with q = P_D N(z; z_hat, S) K_RL(a) (K_RL = 1 without amplitude);
//             clutter statistics updated with P(z is clutter)
//   reduce    prune / merge / truncate to the J_max heaviest (mixture.h),
//             policy there; truncation counted in mixture_truncated
//   extract   PHD: components with w > extract_threshold;
//             CPHD: the MAP cardinality's heaviest components.
// The clutter model is the same object for the three filters (mode chosen
// by RfsFilterParams::clutter_mode).
//
// Caps: kMaxComponents = Caps::kMaxMixtureComponents (default 2 kMaxTargets,
// rfs/rfs_caps.h) after reduction; the update works in
// a buffer of kMaxWork components. Overflow policy there: when it is full a
// new component replaces the lightest one if it is heavier (else it is
// dropped); both are counted in counters().track_cap_hits, a capacity
// error (the buffer is sized so that it does not fill: 575 of 768 at most
// on seed000-s2, docs/algorithms/gm-phd.md §Mixture reduction).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/rfs/rfs_caps.h"
#include "mptrack/measurement.h"
#include "mptrack/phd/cardinality.h"
#include "mptrack/rfs/filter_common.h"
#include "mptrack/rfs/gm_filter_frame.h"
#include "mptrack/rfs/log_sum.h"
#include "mptrack/rfs/mixture.h"
#include "mptrack/static_vector.h"
#include "mptrack/status.h"
#include "mptrack/track_report.h"

namespace mptrack::phd {

template <class T, class Caps, bool Cardinalized>
class PhdFilter : public rfs::GmFilterFrame<PhdFilter<T, Caps, Cardinalized>, T, Caps> {
  using Frame = rfs::GmFilterFrame<PhdFilter<T, Caps, Cardinalized>, T, Caps>;
  friend Frame;

 public:
  using Params = typename Frame::Params;
  using Estimate = typename Frame::Estimate;
  using Component = rfs::TargetComponent<T>;

  static constexpr std::size_t kMaxMeasurements = Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxComponents = rfs::kMaxMixtureComponents<Caps>;
  static constexpr std::size_t kMaxPredicted = kMaxComponents + Caps::kMaxMeasurements;
  static constexpr std::size_t kMaxWork = 2 * kMaxPredicted;
  static constexpr std::size_t kMaxCardinality = Caps::kMaxTargets;

  const StaticVector<Component, kMaxComponents>& components() const { return components_; }
  /// Expected number of targets: sum of weights (PHD) or mean cardinality (CPHD).
  T expected_targets() const {
    if (Cardinalized) return cardinality_.mean();
    T s = T(0);
    for (const Component& c : components_) s += c.weight;
    return s;
  }
  const Cardinality<T, kMaxCardinality>& cardinality() const { return cardinality_; }

 private:
  // Frame hooks (gm_filter_frame.h).
  void reset_targets() {
    components_.clear();
    births_.clear();
    cardinality_.init();
  }

  // Truncation to kMaxComponents is the J_max step of the GM-PHD reduction
  // (mixture.h): counted in mixture_truncated, not a capacity error, unless
  // a component left out weighed extract_threshold or more (it would have
  // been reported as a target): that one is also a track_cap_hits.
  void reduce() {
    T max_dropped = T(0);
    counters_.mixture_truncated += rfs::reduce_mixture(work_, components_, reduction_, scratch_,
                                                       counters_.numerical_repairs, max_dropped);
    if (max_dropped >= params_.extract_threshold) ++counters_.track_cap_hits;
  }

  void predict(T dt) {
    predicted_.clear();
    T birth_mass = T(0);
    for (const Component& c : components_) {
      Component p = c;
      p.weight *= params_.survival_prob;
      rfs::predict_component(p, params_, dt);
      (void)predicted_.push_back(p);  // kMaxComponents <= kMaxPredicted
    }
    for (const Component& b : births_) {
      Component p = b;
      rfs::predict_component(p, params_, dt);
      birth_mass += p.weight;
      if (predicted_.push_back(p) != Status::kOk) ++counters_.track_cap_hits;
    }
    births_.clear();
    if (Cardinalized) cardinality_.predict(params_.survival_prob, birth_mass);
    clutter_.predict();
  }

  void push_work(const Component& c) {
    if (!(c.weight >= params_.prune_threshold)) return;
    if (work_.push_back(c) == Status::kOk) return;
    ++counters_.track_cap_hits;
    std::size_t lightest = 0;
    for (std::size_t k = 1; k < work_.size(); ++k) {
      if (work_[k].weight < work_[lightest].weight) lightest = k;
    }
    if (c.weight > work_[lightest].weight) work_[lightest] = c;
  }

  void update() {
    const std::size_t J = predicted_.size();
    const std::size_t M = batch_.n;
    T W = T(0);
    T missed = T(0);
    for (std::size_t j = 0; j < J; ++j) {
      if (rfs::linearize_component(predicted_[j], model_, params_, lin_[j])) ++counters_.numerical_repairs;
      W += predicted_[j].weight;
      missed += predicted_[j].weight * (T(1) - lin_[j].pd);
    }
    // Pass 1: ln sum_j w_j q_ij per measurement (ln 0 if nothing gated).
    for (std::size_t i = 0; i < M; ++i) {
      log_target_sum_[i] = Cardinality<T, kMaxCardinality>::kLogZero;
      if (!batch_.valid[i]) continue;
      rfs::LogSum<T> s;
      rfs::Vec2<T> v;
      T lq = T(0);
      for (std::size_t j = 0; j < J; ++j) {
        if (!(predicted_[j].weight > T(0))) continue;
        if (!rfs::log_detection_likelihood(predicted_[j], lin_[j], batch_, i, model_, params_, gate_, v, lq)) continue;
        s.add(dmath::dlog(predicted_[j].weight) + lq);
      }
      if (s.any) log_target_sum_[i] = s.value();
    }

    // Weight factors: ln of the missed-detection factor and of the
    // detected factor per measurement (the latter includes 1/denominator).
    T log_missed_factor = T(0);
    if (!Cardinalized || !(W > T(0))) {
      for (std::size_t i = 0; i < M; ++i) {
        if (!batch_.valid[i]) continue;
        log_detect_factor_[i] = -rfs::log_add(clutter_.log_intensity(i), log_target_sum_[i]);
      }
    } else {
      cphd_factors(W, missed, log_missed_factor);
    }

    // Pass 2: build the updated mixture.
    work_.clear();
    for (std::size_t j = 0; j < J; ++j) {
      Component c = predicted_[j];
      c.weight = predicted_[j].weight * (T(1) - lin_[j].pd) * dmath::dexp(log_missed_factor);
      push_work(c);
    }
    for (std::size_t i = 0; i < M; ++i) {
      target_prob_[i] = T(0);
      clutter_prob_[i] = T(0);
      if (!batch_.valid[i]) continue;
      if (log_target_sum_[i] > Cardinality<T, kMaxCardinality>::kLogZero) {
        rfs::Vec2<T> v;
        T lq = T(0);
        for (std::size_t j = 0; j < J; ++j) {
          if (!(predicted_[j].weight > T(0))) continue;
          if (!rfs::log_detection_likelihood(predicted_[j], lin_[j], batch_, i, model_, params_, gate_, v, lq)) continue;
          Component u = rfs::updated_component(predicted_[j], lin_[j], batch_, i, v, params_);
          u.weight = dmath::dexp(dmath::dlog(predicted_[j].weight) + lq + log_detect_factor_[i]);
          target_prob_[i] += u.weight;
          push_work(u);
        }
      }
      const T pt = target_prob_[i] < T(1) ? target_prob_[i] : T(1);
      clutter_prob_[i] = T(1) - pt;
    }
  }

  // CPHD factors (cardinality.h): ln of the missed factor, and per
  // measurement ln(<A^1(Z\z),p> / (W <A^0(Z),p>)) - ln kappa(z).
  //
  // ln R'_z is capped at kMaxLogRatio (docs/reliability.md F8). A strong
  // measurement far from the known clutter amplitude scale has
  // ln kappa(z) ~ -1e12 (the Weibull term -a^(2b)/sigma0), so ln R'_z ~ 1e12,
  // and l0, l1 and the leave-one-out sums all carry it: in float their
  // differences keep no digit (ulp(1e12) = 6e4) and a weight became
  // e^(6e4) = +Inf. Capping lowers the clutter intensity used for that z
  // to ln kappa_eff = ln sum w q - ln W - kMaxLogRatio: the measurement is
  // then a target with probability 1 - e^-200, which is 1 in float. Below
  // the cap the code path is the old one, bit for bit (golden vectors
  // unchanged); above it the old result had lost its precision anyway.
  static constexpr T kMaxLogRatio = T(200);

  void cphd_factors(T W, T missed, T& log_missed_factor) {
    const T log_w = dmath::dlog(W);
    const T phi = rfs::clamp_probability(missed / W);
    const T log_phi = dmath::dlog(phi);
    // R'_z over the measurements with a gated component.
    std::size_t active = 0;
    for (std::size_t i = 0; i < batch_.n; ++i) {
      if (!batch_.valid[i] || !(log_target_sum_[i] > Cardinality<T, kMaxCardinality>::kLogZero)) continue;
      active_index_[active] = i;
      const T lk = clutter_.log_intensity(i);
      const T lr = log_target_sum_[i] - lk - log_w;
      const bool capped = !(lr < kMaxLogRatio);
      log_ratio_[active] = capped ? kMaxLogRatio : lr;
      log_kappa_eff_[active] = capped ? log_target_sum_[i] - log_w - kMaxLogRatio : lk;
      ++active;
    }
    const std::size_t none = active;  // skip index that matches nothing
    std::size_t top = cardinality_.esf(log_ratio_.data(), active, none, esf_);
    cardinality_.log_a(esf_, top, 0, log_phi, la0_);
    cardinality_.log_a(esf_, top, 1, log_phi, la1_);
    const T l0 = cardinality_.log_inner(la0_);
    const T l1 = cardinality_.log_inner(la1_);
    log_missed_factor = l1 - l0 - log_w;
    for (std::size_t a = 0; a < active; ++a) {
      top = cardinality_.esf(log_ratio_.data(), active, a, esf_loo_);
      cardinality_.log_a(esf_loo_, top, 1, log_phi, la_loo_);
      const std::size_t i = active_index_[a];
      log_detect_factor_[i] = cardinality_.log_inner(la_loo_) - l0 - log_w - log_kappa_eff_[a];
    }
    cardinality_.update(la0_, l0);
  }

  void make_births() {
    births_.clear();
    T denom = T(0);
    for (std::size_t i = 0; i < batch_.n; ++i) {
      if (batch_.valid[i]) denom += clutter_prob_[i];
    }
    if (!(denom > T(0))) return;
    for (std::size_t i = 0; i < batch_.n; ++i) {
      if (!batch_.valid[i]) continue;
      const T w = params_.birth_rate * clutter_prob_[i] / denom;
      if (!(w >= params_.prune_threshold)) continue;
      if (births_.push_back(rfs::birth_component(batch_.z[i], w, next_label_, model_, params_)) != Status::kOk) {
        ++counters_.track_cap_hits;
        continue;
      }
      ++next_label_;
      ++counters_.tracks_born;
    }
  }

  void extract(std::uint64_t time_us) {
    (void)outputs_.resize(1);
    Estimate& e = outputs_[0];
    e.time_us = time_us;
    e.scan_index = scan_index_;
    e.tracks.clear();
    e.clutter.clear();
    // A component of weight w stands for round(w) targets (closely spaced
    // targets merge into one component): it is reported that many times,
    // copy k with id label + k * 2^24. CPHD: components heaviest first until
    // the MAP cardinality is reached; PHD: components with w > extract_threshold
    // (at least one copy each, so a threshold below 0.5 reports lighter ones
    // and one above 0.5 holds back a component until it is that sure).
    const std::size_t n = components_.size();
    const std::size_t want = Cardinalized ? cardinality_.map() : Caps::kMaxTargets;
    std::size_t reported = 0;
    // A weight that is not finite (none is expected since F8) is never
    // cast: the component is skipped and counted in numerical_repairs,
    // and at most kMaxTargets copies are made of any weight.
    for (std::size_t k = 0; k < n && reported < want; ++k) {
      const T w = components_[k].weight;
      if (!is_finite(w) || !is_finite(components_[k].x(0)) || !is_finite(components_[k].x(2))) {
        ++counters_.numerical_repairs;
        continue;
      }
      const T rounded = w + T(0.5);
      std::size_t copies = rounded < static_cast<T>(Caps::kMaxTargets)
                               ? static_cast<std::size_t>(rounded > T(0) ? rounded : T(0))
                               : Caps::kMaxTargets;
      if (!Cardinalized) copies = w > params_.extract_threshold ? (copies > 0 ? copies : 1) : 0;
      if (Cardinalized && copies == 0) copies = 1;
      for (std::size_t c = 0; c < copies && reported < want; ++c, ++reported) {
        if (add_track(e, components_[k], static_cast<std::uint32_t>(c)) != Status::kOk) break;
      }
    }
    clutter_.report(e.clutter);
  }

  Status add_track(Estimate& e, const Component& c, std::uint32_t copy) {
    TrackReport<T> r = rfs::component_report(c, params_.amplitude.use_amplitude);
    r.id = c.label + (copy << 24);
    r.existence = c.weight < T(1) ? c.weight : T(1);
    return e.tracks.push_back(r);
  }

  MPTRACK_GM_FRAME_MEMBERS(Frame);

  StaticVector<Component, kMaxComponents> components_;
  StaticVector<Component, Caps::kMaxMeasurements> births_;
  StaticVector<Component, kMaxPredicted> predicted_;
  StaticVector<Component, kMaxWork> work_;
  rfs::ReductionScratch<kMaxWork> scratch_;
  std::array<rfs::Linearized<T>, kMaxPredicted> lin_{};
  std::array<T, Caps::kMaxMeasurements> log_target_sum_{};
  std::array<T, Caps::kMaxMeasurements> log_detect_factor_{};
  std::array<T, Caps::kMaxMeasurements> target_prob_{};
  std::array<T, Caps::kMaxMeasurements> log_ratio_{};
  std::array<T, Caps::kMaxMeasurements> log_kappa_eff_{};  ///< ln kappa used per active z (F8 cap)
  std::array<std::size_t, Caps::kMaxMeasurements> active_index_{};
  std::array<T, kMaxCardinality + 1> esf_{}, esf_loo_{}, la0_{}, la1_{}, la_loo_{};
  Cardinality<T, kMaxCardinality> cardinality_;
};

}  // namespace mptrack::phd

namespace mptrack {

/// GM-PHD filter with amplitude information (seed 001).
template <class T, class Caps = DefaultCaps>
using GmPhdFilter = phd::PhdFilter<T, Caps, false>;
/// GM-CPHD filter with amplitude information (seed 001; Vo, Vo, Cantoni 2007).
template <class T, class Caps = DefaultCaps>
using GmCphdFilter = phd::PhdFilter<T, Caps, true>;

}  // namespace mptrack
