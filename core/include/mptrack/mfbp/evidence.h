// Local evidence of one scan for the association BP (seed 000 eqs. (99)-
// (102), Appendix B), in the log domain:
//   ln theta^c_tau,j = ln lambda_hat + E ln pi_tau + E ln c_tau(y_j) + E ln R(m_j; CNR_tau)
//   ln theta^t_i,j   = E ln N(y_j; h(x_i), R) + E ln R(m_j; SNR_i)
//   theta^t_i,0      = [q(1)(1 - P_D) + q(0)(1 - eps)] / [q(1) P_D + q(0) eps]
// with the expected Gaussian log-likelihood of eq. (79) keeping its -1/2
// factor and normalising constants (they are compared with the clutter
// densities), the Dirichlet expectation E ln pi (eq. (91) with digamma),
// and the amplitude terms of Appendix A. Known clutter (ClutterMode::kKnown)
// uses the given densities instead of the beliefs.
// Departures (docs/algorithms/mfbp.md §Departures, our choice): the chi^2
// gate and the kMaxGatePairs most likely pairs per track, the Doppler
// densities, the cavity moments and the coupling of unresolved tracks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/cavity.h"
#include "mptrack/mfbp/clutter_slot.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/dirichlet.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/model/mahalanobis.h"

namespace mptrack::mfbp {

/// Clutter sources of a scan's association: 0 = uniform, then the live
/// components (estimated) or the known ones, as source slots 1 + c.
template <std::size_t Sources>
struct ClutterSources {
  std::array<std::size_t, Sources> slot{};
  std::size_t count = 1;
};

template <class T, class Caps>
ClutterSources<Caps::kMaxClutterComponents + 1> clutter_sources(const ClutterTable<T, Caps>& cl,
                                                                const MfbpParams<T>& p) {
  constexpr std::size_t kMaxComp = Caps::kMaxClutterComponents;
  ClutterSources<kMaxComp + 1> src{};
  if (estimate_clutter(p)) {
    for (std::size_t c = 0; c < kMaxComp; ++c) {
      if (cl.comps[c].alive) src.slot[src.count++] = c + 1;
    }
  } else if (p.clutter_mode == ClutterMode::kKnown) {
    const std::size_t nk = known_components(p, kMaxComp);
    for (std::size_t c = 0; c < nk; ++c) src.slot[src.count++] = c + 1;
  }
  return src;
}

/// Expected clutter count lambda_hat = N_M - sum_i P_D,i b_s,i, at least 1
/// (docs/algorithms/mfbp.md §Evidence and association).
template <class T, class Caps>
T expected_clutter_count(const TrackTable<T, Caps>& tracks, std::size_t k, std::size_t nm,
                         const MfbpParams<T>& p, int n_order) {
  T expected_targets = T(0);
  for (const auto& t : tracks) {
    if (t.participates(k)) expected_targets += detection_prob(p, n_order, t.igs[k]) * t.vis[k];
  }
  T lambda = static_cast<T>(nm) - expected_targets;
  if (lambda < T(1)) lambda = T(1);
  return lambda;
}

/// Clutter evidence with the known clutter map: the components that exist
/// at the scan's time (KnownClutterComponent::produces_at).
template <class T, class Caps, class Bp, std::size_t S>
void known_clutter_evidence(Bp& bp, const ScanSlot<T, Caps>& s, const ClutterSources<S>& src,
                            const MfbpParams<T>& p, const ModelConstants<T>& mc, T log_dop_clutter) {
  const auto& kc = p.known_clutter;
  const T d = p.amplitude.threshold;
  const T rate_u = effective_uniform_rate(kc.uniform_rate_per_scan, p);
  const T lu = dmath::dlog(rate_u) - mc.log_volume + log_dop_clutter;
  for (std::size_t j = 0; j < s.count; ++j) {
    T v = lu;
    if (p.amplitude.use_amplitude) v += amplitude_loglik(s.amp[j], d, T(1) + kc.uniform_cnr, mc.n_order);
    bp.set_clutter_log(0, j, v);
  }
  for (std::size_t q = 1; q < src.count; ++q) {
    const auto& comp = kc.components[src.slot[q] - 1];
    bp.set_clutter_absent(q, T(0));  // known components are always present
    if (!comp.produces_at(s.time_us)) continue;
    const model::Mahalanobis2<T> dist(comp.covariance);
    if (!dist.valid()) continue;  // validate() refuses such maps already
    const T base = dmath::dlog(comp.rate_per_scan) - dmath::kLnTwoPi<T> - T(0.5) * dmath::dlog(dist.det()) +
                   log_dop_clutter;
    for (std::size_t j = 0; j < s.count; ++j) {
      const Vec2<T> e(s.r[j] - comp.mean(0), model::wrap_angle(s.az[j] - comp.mean(1)));
      const T maha = dist.distance2(e);
      if (maha > p.clutter_gate_chi2) continue;
      T v = base - T(0.5) * maha;
      if (p.amplitude.use_amplitude) v += amplitude_loglik(s.amp[j], d, T(1) + comp.cnr, mc.n_order);
      bp.set_clutter_log(q, j, v);
    }
  }
}

/// Clutter evidence from the clutter beliefs (uniform only, or estimated
/// components with their Dirichlet weights) on window scan k.
template <class T, class Caps, class Bp, std::size_t S>
void estimated_clutter_evidence(Bp& bp, const ScanSlot<T, Caps>& s, std::size_t k,
                                const ClutterSources<S>& src, const ClutterTable<T, Caps>& cl,
                                T lambda, const MfbpParams<T>& p, const ModelConstants<T>& mc,
                                T log_dop_clutter) {
  const T d = p.amplitude.threshold;
  std::array<T, S> alpha{}, e_log_pi{};
  T log_rate = T(0);
  if (estimate_clutter(p)) {
    for (std::size_t q = 0; q < src.count; ++q) alpha[q] = cl.alpha_s[k][src.slot[q]];
    dirichlet_expected_log(alpha.data(), e_log_pi.data(), src.count);
    log_rate = p.clutter_rate_in_da ? dmath::dlog(lambda) : T(0);
  } else {
    e_log_pi[0] = T(0);
    log_rate = dmath::dlog(effective_uniform_rate(p.uniform_rate_per_scan, p));
  }
  const model::InverseGamma<T>& ig0 = cl.uniform.igs[k];
  const T lu = log_rate + e_log_pi[0] - mc.log_volume + log_dop_clutter;
  ExpectedAmplitudeLoglik<T> amp_loglik0(d, ig0.a, ig0.b, mc.n_order, p.amp_loglik);
  for (std::size_t j = 0; j < s.count; ++j) {
    T v = lu;
    if (p.amplitude.use_amplitude) v += amp_loglik0(s.amp[j]);
    bp.set_clutter_log(0, j, v);
  }
  for (std::size_t q = 1; q < src.count; ++q) {
    const CompSlot<T, Caps>& cs = cl.comps[src.slot[q] - 1];
    const NormalWishart<T>& nw = cs.nws[k];
    const model::InverseGamma<T>& ig = cs.igs[k];
    bp.set_clutter_absent(q, p.component_absent_evidence);
    const T base = log_rate + e_log_pi[q] + nw.expected_log_norm() + log_dop_clutter;
    ExpectedAmplitudeLoglik<T> amp_loglik(d, ig.a, ig.b, mc.n_order, p.amp_loglik);
    for (std::size_t j = 0; j < s.count; ++j) {
      const Vec2<T> y(s.r[j], s.az[j]);
      const T em = nw.expected_mahalanobis(y);
      if (em - T(2) / nw.c > p.clutter_gate_chi2) continue;
      T v = base - T(0.5) * em;
      if (p.amplitude.use_amplitude) v += amp_loglik(s.amp[j]);
      bp.set_clutter_log(q, j, v);
    }
  }
}

/// Predicted measurement moments of one track on the scan being associated.
template <class T>
struct TrackMoments {
  Vec2<T> z = Vec2<T>::Zero();         ///< [range m, azimuth rad] (cavity if association_cavity)
  Vec2<T> z_shared = Vec2<T>::Zero();  ///< z, or the common mean of unresolved tracks
  Mat2<T> Sz = Mat2<T>::Zero();        ///< its covariance (without R)
  T z_dop = T(0);                      ///< predicted radial velocity [m/s]
  T var_dop = T(0);                    ///< its variance [(m/s)^2]
  bool ok = false;                     ///< participates and the moments exist
  /// A tentative track inside a weaker Gaussian clutter component
  /// (weaker_clutter.h): its spatial evidence is the predictive density
  /// (target_evidence; docs/algorithms/mfbp.md §Birth).
  bool predictive = false;
};

/// Removes the scan-k pseudo-measurement (y_bar, R / w) of the previous
/// iteration from the smoothed measurement-space moments (z_hat, Sz)
/// (cavity.h). Our choice (docs/algorithms/mfbp.md §Departures): the MF
/// belief of x_k already contains the measurement it was associated with,
/// so evidence from it is self-reinforcing; the extrinsic (cavity) moments
/// are what BP would pass. It does not remove the pair repulsion on S1 (see
/// association_cavity in mfbp_params.h): that feedback runs through the
/// other window scans and the prior. Unchanged when there is no previous
/// association or the division is not positive definite.
template <class T, class Caps>
void cavity_moments(const TrackSlot<T, Caps>& t, std::size_t k, const ScanSlot<T, Caps>& s,
                    const MfbpParams<T>& p, const ModelConstants<T>& mc, Vec2<T>& z_hat, Mat2<T>& Sz) {
  const T w = T(1) - t.missed[k];
  if (!(w > p.w_min) || t.n_edges[k] == 0) return;
  Vec2<T> acc = Vec2<T>::Zero();
  T w_sum = T(0);
  for (std::size_t e = t.edge_begin[k]; e < std::size_t{t.edge_begin[k]} + t.n_edges[k]; ++e) {
    const std::size_t j = s.edge_meas[e];
    const T a = s.edge_w[e];
    acc(0) += a * (s.r[j] - z_hat(0));
    acc(1) += a * model::wrap_angle(s.az[j] - z_hat(1));
    w_sum += a;
  }
  if (!(w_sum > p.w_min)) return;
  const Vec2<T> e_bar = acc / w_sum;  // y_bar - z_hat (azimuth wrapped)
  (void)remove_pseudo_measurement(z_hat, Sz, e_bar, w_sum, Vec2<T>(mc.R_inv(0, 0), mc.R_inv(1, 1)));
}

/// Moments of [range, azimuth, radial velocity] of track t on window scan
/// k (the Doppler row is used only when the scan has it). False if the
/// smoothed covariance cannot be made usable.
template <class T, class Caps>
bool track_moments(const TrackSlot<T, Caps>& t, std::size_t k, const ScanSlot<T, Caps>& s,
                   const MfbpParams<T>& p, const ModelConstants<T>& mc, TrackerCounters& counters,
                   TrackMoments<T>& mo) {
  Eigen::Matrix<T, 3, 1> z3;
  Eigen::Matrix<T, 3, 3> S3;
  Mat4<T> P_k = t.Ps[k].get();
  if (!cubature_measurement_moments<T, 3>(t.xs[k], P_k, z3, S3)) {
    note_repair(make_spd(P_k), counters);
    if (!cubature_measurement_moments<T, 3>(t.xs[k], P_k, z3, S3)) return false;
  }
  mo.z = z3.template head<2>();
  mo.Sz = S3.template topLeftCorner<2, 2>();
  mo.z_dop = z3(2);
  mo.var_dop = S3(2, 2);
  if (p.association_cavity) cavity_moments(t, k, s, p, mc, mo.z, mo.Sz);
  return true;
}

/// Weight of a neighbour at d2 < chi2 in an unresolved track's common mean:
/// (1 - d2 / chi2)^2 with the taper (1 at d2 = 0, 0 with zero slope at
/// the coupling edge), 1 without (docs/algorithms/mfbp.md §Departures).
template <class T>
T unresolved_weight(T d2, T chi2, bool taper) {
  if (!taper) return T(1);
  const T u = T(1) - d2 / chi2;
  return u * u;
}

/// Residual e = z_b - z_a (azimuth wrapped) between two tracks' predicted
/// measurements and its d^2 under Sz_a + Sz_b; false if that sum is not
/// usable.
template <class T>
bool unresolved_distance2(const TrackMoments<T>& ma, const TrackMoments<T>& mb, Vec2<T>& e, T& d2) {
  e = Vec2<T>(mb.z(0) - ma.z(0), model::wrap_angle(mb.z(1) - ma.z(1)));
  const model::Mahalanobis2<T> dist(ma.Sz + mb.Sz);
  if (!dist.valid()) return false;
  d2 = dist.distance2(e);
  return true;
}

/// Our choice (docs/algorithms/mfbp.md §Departures): tracks whose
/// predicted measurements are statistically indistinguishable,
/// (z_a - z_b)^T (Sz_a + Sz_b)^-1 (z_a - z_b) < unresolved_chi2, score
/// measurements against their common mean (the average over the track and
/// such neighbours, each weighted by unresolved_weight), so that position
/// alone never decides which of them takes which measurement: amplitude,
/// Doppler and visibility still do. For a confirmed track the taper lets
/// position back in as the tracks separate, instead of at one Mahalanobis
/// distance: on S2's three-target crossing amplitude alone let the strong
/// target's track take its weaker neighbours' detections. Tentative tracks
/// keep equal weights: several start on one target inside clutter, and
/// tapered they compete by position and confirm a scan later
/// (docs/results/issue18-clutter.md §KI ablation).
/// Without it, on S1's unresolved pair (20 m apart, 210-300 m cross-range
/// noise) the track that drifted left takes the left measurements, an
/// outward pull that cancels the measurement's restoring pull (loop gain 1
/// with eq. (79), 1 - K^2 even with the predictive density), and the tracks
/// drift ~200 m apart (docs/results/seed000-s1.md). Each track still
/// updates on its own pseudo-measurement. O(tracks^2) 2x2 tests per scan
/// over the tracks with moments.
template <class T, class Caps, std::size_t N>
void couple_unresolved(std::array<TrackMoments<T>, N>& moments, TrackTable<T, Caps>& tracks,
                       std::size_t k, const MfbpParams<T>& p) {
  // The tracks with moments, in slot order (the others never take part).
  std::array<std::uint16_t, N> live{};
  std::size_t n_live = 0;
  for (std::size_t a = 0; a < N; ++a) {
    if (moments[a].ok) live[n_live++] = static_cast<std::uint16_t>(a);
  }
  for (std::size_t qa = 0; qa < n_live; ++qa) {
    const std::size_t a = live[qa];
    TrackMoments<T>& ma = moments[a];
    Vec2<T> sum = ma.z;
    T count = T(1);
    T nearest = p.unresolved_chi2;
    for (std::size_t qb = 0; qb < n_live; ++qb) {
      if (qb == qa) continue;
      const std::size_t b = live[qb];
      const TrackMoments<T>& mb = moments[b];
      Vec2<T> e;
      T d2;
      if (!unresolved_distance2(ma, mb, e, d2)) continue;
      if (!(d2 < p.unresolved_chi2)) continue;
      const T w = unresolved_weight(d2, p.unresolved_chi2, p.unresolved_taper && tracks[a].confirmed);
      sum += w * Vec2<T>(ma.z(0) + e(0), ma.z(1) + e(1));
      count += w;
      if (d2 < nearest) {
        nearest = d2;
        tracks[a].mate[k] = static_cast<std::uint16_t>(b + 1);
      }
    }
    ma.z_shared = sum / count;
    ma.z_shared(1) = model::wrap_angle(ma.z_shared(1));
  }
}

/// The `cap` (<= G) most likely gated measurements of one track, by log
/// evidence (sorted insertion; ties keep the earlier measurement). cap is
/// below G when the scan's shared pool is short (association.h).
template <class T, std::size_t G>
struct GateList {
  std::array<T, G> v{};
  std::array<std::uint16_t, G> j{};
  std::size_t size = 0;
  std::size_t cap = G;

  /// Offers (log_theta, meas); returns true if a pair was dropped (cap).
  bool offer(T log_theta, std::size_t meas) {
    bool dropped = false;
    if (size == cap) {
      dropped = true;
      if (cap == 0) return dropped;
      if (!(log_theta > v[size - 1])) return dropped;
      --size;
    }
    std::size_t pos = size;
    while (pos > 0 && log_theta > v[pos - 1]) {
      v[pos] = v[pos - 1];
      j[pos] = j[pos - 1];
      --pos;
    }
    v[pos] = log_theta;
    j[pos] = static_cast<std::uint16_t>(meas);
    ++size;
    return dropped;
  }

  /// Indices into v / j in measurement order (deterministic edges,
  /// independent of the ranking).
  std::array<std::uint16_t, G> measurement_order() const {
    std::array<std::uint16_t, G> order{};
    for (std::size_t a = 0; a < size; ++a) order[a] = static_cast<std::uint16_t>(a);
    for (std::size_t a = 1; a < size; ++a) {
      for (std::size_t b = a; b > 0 && j[order[b]] < j[order[b - 1]]; --b) {
        const std::uint16_t tmp = order[b];
        order[b] = order[b - 1];
        order[b - 1] = tmp;
      }
    }
    return order;
  }
};

/// Missed-detection evidence theta^t_i,0 from P_D and the extrinsic
/// visibility message q(1) (eq. (99)-(102) with the visibility of eq. (64)).
template <class T>
T missed_evidence(T pd, T q1, T eps) {
  return (q1 * (T(1) - pd) + (T(1) - q1) * (T(1) - eps)) / (q1 * pd + (T(1) - q1) * eps);
}

/// Gated target evidence ln theta^t_i,j of track t (moments mo, innovation
/// covariance checked in `gate`) for every measurement of scan s, window
/// scan k, into list. Returns the number of pairs dropped by the list's cap.
template <class T, class Caps, std::size_t G>
std::size_t target_evidence(const TrackSlot<T, Caps>& t, const TrackMoments<T>& mo,
                            const model::Mahalanobis2<T>& gate, const ScanSlot<T, Caps>& s,
                            std::size_t k, const MfbpParams<T>& p, const ModelConstants<T>& mc,
                            GateList<T, G>& list) {
  const Vec2<T>& z_hat = mo.z_shared;
  const T var_d = p.noise.doppler_std_mps * p.noise.doppler_std_mps;
  const T trace_term = (mc.R_inv * mo.Sz).trace();
  // Per-track terms of the loop below, computed once (same operations).
  const T log_det_gate = mo.predictive ? dmath::dlog(gate.det()) : T(0);
  const T var_dop = var_d + mo.var_dop;
  const T log_norm_dop = s.doppler ? -T(0.5) * (dmath::kLnTwoPi<T> + dmath::dlog(var_dop)) : T(0);
  ExpectedAmplitudeLoglik<T> amp_loglik(p.amplitude.threshold, t.igs[k].a, t.igs[k].b, mc.n_order, p.amp_loglik);
  std::size_t dropped = 0;
  for (std::size_t j = 0; j < s.count; ++j) {
    const Vec2<T> e(s.r[j] - z_hat(0), model::wrap_angle(s.az[j] - z_hat(1)));
    if (gate.distance2(e) > p.gate_chi2) continue;
    // NEMP's veto over the tentative life (docs/algorithms/nemp.md §Birth):
    // a detection the classifier calls clutter carries no unconfirmed track.
    if (!t.confirmed && s.tentative_vetoed(j)) continue;
    // Young tracks inside weaker clutter (docs/algorithms/mfbp.md §Birth):
    // the predictive density N(y; z, Sz + R) = ln E[N(y; h(x), R)] instead
    // of the MF expectation E[ln N] of seed 000 eq. (79), whose
    // -tr(R^-1 Sz) / 2 term (~ -5 one scan after a two-point birth) puts a
    // new track below a dense component's clutter density on every
    // measurement, so it never takes its target's detections; the same
    // reason as the Doppler row below.
    T v = mo.predictive
              ? -dmath::kLnTwoPi<T> - T(0.5) * (log_det_gate + gate.distance2(e))
              : mc.log_norm_R - T(0.5) * (e.dot(mc.R_inv * e) + trace_term);
    if (s.doppler) {
      // Doppler is our choice (docs/algorithms/mfbp.md §Departures): the
      // predictive density N(d; z_d, S_dd + sigma_d^2) rather than the MF
      // expectation, whose -S_dd / (2 sigma_d^2) term rejects every
      // association of a young track (velocity spread >> sigma_d) and so
      // would never let it learn.
      const T ed = s.dop[j] - mo.z_dop;
      v += log_norm_dop - T(0.5) * ed * ed / var_dop;
    }
    if (p.amplitude.use_amplitude) v += amp_loglik(s.amp[j]);
    if (list.offer(v, j)) ++dropped;
  }
  return dropped;
}

}  // namespace mptrack::mfbp
