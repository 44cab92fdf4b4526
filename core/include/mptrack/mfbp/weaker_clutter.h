// Is a point inside a Gaussian clutter component weaker than a target?
// (docs/algorithms/mfbp.md §Birth, "Young tracks inside weaker clutter").
//
// A component "holds" a measurement-space point (r, az) when the point lies
// in its gate (clutter_gate_chi2 under E[D^-1], the gate of the clutter
// evidence), and it is weaker than a target of mean total power
// varsigma_t = E[1 + SNR] when its own mean total power E[1 + CNR] is
// lower: there the amplitude favours the target (seed 000 eq. (13): the
// same truncated density with the larger power). The estimated map uses
// the component beliefs on window scan k, the known map (KCE ablation) the
// components that exist at that scan's time. False without amplitude (KI ablation) or Gaussian
// components (NCE ablation, or none alive).
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/model/mahalanobis.h"
#include "mptrack/model/polar_measurement.h"

namespace mptrack::mfbp {

/// fn(mean, covariance, mean total power E[1 + CNR]) for every Gaussian
/// clutter component: the known map's components that produce clutter
/// at time_us, the time of window scan k (kKnownMap), or the live estimated
/// ones on window scan k (their NW mean, E[D^-1] and CNR belief); none in
/// the NCE ablation.
template <class T, class Caps, class Fn>
void for_each_gaussian_component(std::size_t k, std::uint64_t time_us, const ClutterTable<T, Caps>& cl,
                                 const MfbpParams<T>& p, Fn&& fn) {
  if (p.clutter_mode == ClutterMode::kKnownMap) {
    const std::size_t nk = known_components(p, Caps::kMaxClutterComponents);
    for (std::size_t c = 0; c < nk; ++c) {
      const auto& kc = p.known_clutter.components[c];
      if (kc.produces_at(time_us)) fn(kc.mean, kc.covariance, T(1) + kc.cnr);
    }
  } else if (estimate_clutter(p)) {
    for (const auto& cs : cl.comps) {
      if (cs.alive) fn(cs.nws[k].mu, cs.nws[k].expected_covariance(), cs.igs[k].mean());
    }
  }
}

/// Is (r, az) within Mahalanobis^2 chi2 of a Gaussian of mean mu and
/// covariance cov (a clutter component's gate under E[D^-1])?
template <class T>
bool in_gaussian_gate(T r, T az, const Vec2<T>& mu, const Mat2<T>& cov, T chi2) {
  const model::Mahalanobis2<T> gate(cov);
  return gate.valid() && !(gate.distance2(r - mu(0), model::wrap_angle(az - mu(1))) > chi2);
}

/// Is (r, az) in the gate (clutter_gate_chi2 under E[D^-1]) of a Gaussian
/// component whose mean total power E[1 + CNR] passes accept(power)?
template <class T, class Caps, class Accept>
bool inside_component_gate(T r, T az, std::size_t k, std::uint64_t time_us, const ClutterTable<T, Caps>& cl,
                           const MfbpParams<T>& p, Accept&& accept) {
  bool inside = false;
  const auto consider = [&](const Vec2<T>& mu, const Mat2<T>& cov, T varsigma_c) {
    if (inside || !accept(varsigma_c)) return;
    inside = in_gaussian_gate(r, az, mu, cov, p.clutter_gate_chi2);
  };
  for_each_gaussian_component(k, time_us, cl, p, consider);
  return inside;
}

template <class T, class Caps>
bool inside_weaker_component(T r, T az, T varsigma_t, std::size_t k, std::uint64_t time_us,
                             const ClutterTable<T, Caps>& cl, const MfbpParams<T>& p) {
  if (!p.amplitude.use_amplitude) return false;
  return inside_component_gate(r, az, k, time_us, cl, p, [varsigma_t](T varsigma_c) { return varsigma_c < varsigma_t; });
}

/// Inside the gate of a Gaussian clutter component of any power; a pure
/// gate test, so also without amplitude (KI ablation).
template <class T, class Caps>
bool inside_any_component(T r, T az, std::size_t k, std::uint64_t time_us, const ClutterTable<T, Caps>& cl,
                          const MfbpParams<T>& p) {
  return inside_component_gate(r, az, k, time_us, cl, p, [](T /*varsigma_c*/) { return true; });
}

/// Does the online-filter rule filter_score_in_any_component apply to
/// track t (tentative, window of one scan, rule and score test on)?
template <class T, class Caps>
bool filter_holds_in_any_component(const TrackSlot<T, Caps>& t, const MfbpParams<T>& p) {
  return p.filter_score_in_any_component && p.window_length == 1 && p.tentative_predictive_in_clutter &&
         p.filter_confirm_score_in_clutter > T(0) && !t.confirmed;
}

}  // namespace mptrack::mfbp
