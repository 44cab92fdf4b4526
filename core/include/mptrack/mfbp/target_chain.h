// The target part of one MF sweep (seed 000 Algorithm 1 lines 5 and 7),
// per track over the window scans where it exists:
//   * visibility: the two-state HMM forward-backward of eq. (64)-(68);
//   * kinematics: a cubature forward filter on the pseudo-measurement of
//     eq. (40) (y_bar = sum_j a_ij y_j / w, R_bar = R / w, w = 1 - a_i0),
//     then RTS smoothing (linear CV dynamics: the unscented RTS reduces to
//     RTS), eq. (35)-(42);
//   * SNR: the inverse-gamma forward filter and backward statistics of
//     eq. (43)-(48).
// Departures (docs/algorithms/mfbp.md §Departures, our choice): the
// manoeuvre-adaptive process noise, the Doppler row of the pseudo-
// measurement, and the pooled pseudo-measurement of an unresolved pair.
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/model_constants.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/mfbp/track_slot.h"
#include "mptrack/mfbp/visibility_hmm.h"
#include "mptrack/mfbp/window_store.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

/// Visibility beliefs b_s on the track's window scans (eq. (64)-(68)).
template <class T, class Caps>
void visibility_sweep(TrackSlot<T, Caps>& t, std::size_t n, const MfbpParams<T>& p) {
  const std::size_t f = t.first;
  if (f >= n) return;
  const T pred0 = t.from_birth ? p.visibility_at_birth : visibility_predict(t.vis0, p.p_survive, p.p_birth);
  visibility_forward_backward(pred0, t.xi1.data() + f, t.xi0.data() + f, n - f, p.p_survive,
                              p.p_birth, t.visf.data() + f, t.vis.data() + f, t.extr.data() + f);
}

/// Manoeuvre-adaptive white-acceleration level (our choice,
/// docs/algorithms/mfbp.md §Departures), from the innovation-mean test
/// (Bar-Shalom, Li, Kirubarajan 2001, sec. 5.4 and 11.3). bias is the faded
/// mean u_bar of the whitened pseudo-measurement innovations u = L^-1 e
/// (S = L L^T); while the CV model holds, u ~ N(0, I) and
/// chi = |u_bar|^2 (1 + rho) / (2 (1 - rho)) is 1 on average. A per-scan NIS
/// test is blind here: S1's turn leaves a lag of ~0.5 sigma per scan, which
/// only the mean over many scans shows. Above 1 the level rises as chi^4
/// from accel_var_m2ps4 (the paper's quiet 0.01) to
/// manoeuvre_noise_var_max (reached at chi = 3.2 with the defaults), so one
/// model follows the 0.33 m/s^2 turn and averages 210-300 m cross-range
/// noise down afterwards. The exponent and the fading factor come from an
/// S1 sweep (docs/results/seed000-s1.md).
template <class T>
T manoeuvre_noise(const Vec2<T>& bias, const MfbpParams<T>& p) {
  const T q0 = p.accel_var_m2ps4;
  const T rho = p.manoeuvre_fading;
  const T chi = bias.squaredNorm() * (T(1) + rho) / (T(2) * (T(1) - rho));
  const T q_max = p.manoeuvre_noise_var_max;
  if (!(chi > T(1)) || !(q_max > q0)) return q0;
  const T chi2 = chi * chi;
  const T q = q0 * chi2 * chi2;
  return q < q_max ? q : q_max;
}

/// u_bar <- rho u_bar + (1 - rho) u; a pseudo-measurement of weight
/// w_sum < 1 moves it proportionally less.
template <class T>
Vec2<T> fade_bias(const Vec2<T>& bias_prev, Vec2<T> white, T w_sum, const MfbpParams<T>& p) {
  const T a = (T(1) - p.manoeuvre_fading) * (w_sum < T(1) ? w_sum : T(1));
  for (int i = 0; i < 2; ++i) {  // a wild outlier only saturates
    if (!(white(i) < T(100))) white(i) = T(100);
    if (!(white(i) > T(-100))) white(i) = T(-100);
  }
  return bias_prev + a * (white - bias_prev);
}

/// The unresolved neighbour whose measurements t pools on scan k (our
/// choice, unresolved_pooling; docs/algorithms/mfbp.md §Departures), or null.
template <class T, class Caps>
const TrackSlot<T, Caps>* pooling_mate(const TrackSlot<T, Caps>& t, std::size_t k,
                                       const TrackTable<T, Caps>& tracks, const MfbpParams<T>& p) {
  if (!p.unresolved_pooling || t.mate[k] == 0) return nullptr;
  const TrackSlot<T, Caps>& m = tracks[t.mate[k] - 1u];
  return (m.alive && k >= m.first && m.n_edges[k] > 0) ? &m : nullptr;
}

/// Cubature update of (x, P) with the pseudo-measurement of eq. (40),
/// y_bar = z_ref + sum a_j wrap(y_j - z_ref) / w, pooled over t and mate;
/// with Doppler the weighted radial velocity is a third row. bias_k gets
/// the faded whitened innovation. Nothing happens if the weight is below w_min.
template <class T, class Caps>
void pseudo_measurement_update(const TrackSlot<T, Caps>& t, const TrackSlot<T, Caps>* mate,
                               std::size_t k, const ScanSlot<T, Caps>& s, const Vec2<T>& bias_prev,
                               const MfbpParams<T>& p, const ModelConstants<T>& mc,
                               TrackerCounters& counters, Vec4<T>& x, Mat4<T>& P, Vec2<T>& bias_k) {
  using Vec2 = mfbp::Vec2<T>;
  const Vec2 z_ref = model::polar_of_state<T>(x);
  Vec2 acc = Vec2::Zero();
  T w_sum = T(0);
  const TrackSlot<T, Caps>* pooled[2] = {&t, mate};
  for (const TrackSlot<T, Caps>* src : pooled) {
    if (src == nullptr) continue;
    for (std::size_t e = src->edge_begin[k]; e < std::size_t{src->edge_begin[k]} + src->n_edges[k]; ++e) {
      const std::size_t j = s.edge_meas[e];
      const T a = s.edge_w[e];
      acc(0) += a * (s.r[j] - z_ref(0));
      acc(1) += a * model::wrap_angle(s.az[j] - z_ref(1));
      w_sum += a;
    }
  }
  if (!(w_sum > p.w_min)) return;
  Vec2 y_bar = z_ref + acc / w_sum;
  y_bar(1) = model::wrap_angle(y_bar(1));
  Vec2 white = Vec2::Zero();
  if (s.doppler) {
    T dop = T(0);
    for (const TrackSlot<T, Caps>* src : pooled) {
      if (src == nullptr) continue;
      for (std::size_t e = src->edge_begin[k]; e < std::size_t{src->edge_begin[k]} + src->n_edges[k]; ++e) {
        dop += s.edge_w[e] * s.dop[s.edge_meas[e]];
      }
    }
    const Eigen::Matrix<T, 3, 1> y3(y_bar(0), y_bar(1), dop / w_sum);
    Eigen::Matrix<T, 3, 3> R3 = Eigen::Matrix<T, 3, 3>::Zero();
    R3(0, 0) = mc.R(0, 0) / w_sum;
    R3(1, 1) = mc.R(1, 1) / w_sum;
    R3(2, 2) = p.noise.doppler_std_mps * p.noise.doppler_std_mps / w_sum;
    note_repair(cubature_update_m<T, 3>(x, P, y3, R3, &white), counters);
  } else {
    const Mat2<T> R_bar = mc.R / w_sum;
    note_repair(cubature_update(x, P, y_bar, R_bar, &white), counters);
  }
  bias_k = fade_bias(bias_prev, white, w_sum, p);
}

/// SNR inverse-gamma update at scan k from the association's amplitude
/// statistics (eq. (43); snr_update selects the MF form or the mean).
template <class T>
void snr_update(model::InverseGamma<T>& ig, const AmplitudeStats<T>& amp, const MfbpParams<T>& p, T tn) {
  if (p.snr_update == SnrUpdate::kMf) {
    ig.update(tn * amp.w, tn * amp.s);
  } else if (amp.w > p.w_min) {
    ig.update(tn, tn * amp.s / amp.w);
  }
}

/// Forward filter step into window scan k (the birth scan keeps the birth state).
template <class T, class Caps>
void target_forward_step(TrackSlot<T, Caps>& t, std::size_t k, const TrackTable<T, Caps>& tracks,
                         const WindowStore<T, Caps>& store, const MfbpParams<T>& p,
                         const ModelConstants<T>& mc, TrackerCounters& counters) {
  const std::size_t f = t.first;
  if (k == f && t.from_birth) {
    t.xf[k] = t.x0;
    t.Pf[k].set(t.P0);
    t.igf[k] = t.ig0;
    t.biasf[k] = t.bias0;
    t.qk[k] = p.accel_var_m2ps4;
    return;
  }
  Vec4<T> x;
  Mat4<T> P;
  model::InverseGamma<T> ig;
  const Vec2<T> bias_prev = k == f ? t.bias0 : t.biasf[k - 1];
  const T q = manoeuvre_noise(bias_prev, p);
  t.qk[k] = q;
  if (k == f) {
    x = t.x0;
    P = t.P0;
    ig = t.ig0;
    note_repair(cv_predict(x, P, dt_s<T>(t.t0_us, store.win(k).time_us), q), counters);
  } else {
    x = t.xf[k - 1];
    P = t.Pf[k - 1].get();
    ig = t.igf[k - 1];
    note_repair(cv_predict(x, P, dt_s<T>(store.win(k - 1).time_us, store.win(k).time_us), q), counters);
  }
  Vec2<T> bias_k = bias_prev;
  ig = ig.predicted(p.forgetting_target);
  const T w = T(1) - t.missed[k];
  const TrackSlot<T, Caps>* mate = pooling_mate(t, k, tracks, p);
  if ((w > p.w_min && t.n_edges[k] > 0) || mate != nullptr) {
    pseudo_measurement_update(t, mate, k, store.win(k), bias_prev, p, mc, counters, x, P, bias_k);
    if (p.amplitude.use_amplitude && w > p.w_min) snr_update(ig, t.amp[k], p, T(mc.n_order));
  }
  t.xf[k] = x;
  t.Pf[k].set(P);
  t.igf[k] = ig;
  t.biasf[k] = bias_k;
}

/// RTS backward pass from the last window scan down to t.first.
template <class T, class Caps>
void target_smooth(TrackSlot<T, Caps>& t, std::size_t n, const WindowStore<T, Caps>& store,
                   TrackerCounters& counters) {
  t.xs[n - 1] = t.xf[n - 1];
  t.Ps[n - 1] = t.Pf[n - 1];
  Mat4<T> Ps_next = t.Ps[n - 1].get();
  for (std::size_t kk = n - 1; kk-- > t.first;) {
    Mat4<T> Ps;
    note_repair(rts_step(t.xf[kk], t.Pf[kk].get(), t.xs[kk + 1], Ps_next,
                         dt_s<T>(store.win(kk).time_us, store.win(kk + 1).time_us), t.qk[kk + 1],
                         t.xs[kk], Ps),
                counters);
    t.Ps[kk].set(Ps);
    Ps_next = Ps;
  }
}

/// SNR backward statistics, g = 1/u^t (eq. (48)).
template <class T, class Caps>
void snr_smooth(TrackSlot<T, Caps>& t, std::size_t n, const MfbpParams<T>& p, int n_order) {
  const T tn = T(n_order);
  const T g = T(1) / p.forgetting_target;
  AmplitudeStats<T> B{};
  for (std::size_t kk = n; kk-- > t.first;) {
    if (kk + 1 < n) {
      B.w = g * (B.w + t.amp[kk + 1].w);
      B.s = g * (B.s + t.amp[kk + 1].s);
    }
    model::InverseGamma<T> s = t.igf[kk];
    if (p.amplitude.use_amplitude && p.snr_update == SnrUpdate::kMf) s.update(tn * B.w, tn * B.s);
    t.igs[kk] = s;
  }
}

/// Kinematic and SNR beliefs of track t on the n window scans.
template <class T, class Caps>
void target_sweep(TrackSlot<T, Caps>& t, const TrackTable<T, Caps>& tracks,
                  const WindowStore<T, Caps>& store, std::size_t n, const MfbpParams<T>& p,
                  const ModelConstants<T>& mc, TrackerCounters& counters) {
  if (t.first >= n) return;
  for (std::size_t k = t.first; k < n; ++k) target_forward_step(t, k, tracks, store, p, mc, counters);
  target_smooth(t, n, store, counters);
  snr_smooth(t, n, p, mc.n_order);
}

}  // namespace mptrack::mfbp
