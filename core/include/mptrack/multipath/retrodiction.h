// Retrodiction of a new track through the scans the fixed-lag smoother
// still holds (docs/algorithms/multipath.md §Retrodiction). A track starts
// from two or more detections of one scan; at p_d 0.4 the scans before
// that often held one detection of the target, which no birth could use.
// With the output held back L scans, a new track is carried back through
// them: at each held-back scan its state is predicted backwards (CWNA,
// x_t = F(-dt) x_t+1, P_t = F(-dt) (P_t+1 + Q(dt)) F(-dt)^T), each path's
// leftover detections are gated, and the closest one per path is taken if
// it is more likely the target's than clutter,
//   ln pd - ln(1 - pd) - ln lambda - ln N-normaliser(S) - d^2 / 2 > 0,
// and the state is updated with it (path_fusion.h). Scans back to the
// earliest one with such support get an entry marked `retro`; the track
// is reported there once it is confirmed, like any held-back scan.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/model/cwna_motion.h"
#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/fixed_lag_smoother.h"
#include "mptrack/multipath/path_fusion.h"
#include "mptrack/multipath/path_track.h"

namespace mptrack::multipath {

/// What retrodiction needs of the tracker's params and constants.
template <class T>
struct RetroModel {
  const model::OthrPath<T>* paths = nullptr;
  std::size_t num_paths = 0;
  T baseline_km = T(0);
  const T* ln_pd1 = nullptr;    ///< ln pd per path
  const T* ln_miss1 = nullptr;  ///< ln (1 - pd) per path
  T ln_lambda = T(0);           ///< ln clutter density [per km km/s rad]
  T gate_chi2 = T(9);
  T q_range = T(0);             ///< ground-range PSD [km^2/s^3]
  T q_bearing = T(0);           ///< bearing PSD [rad^2/s^3]
};

/// x <- F(-dt) x, P <- F(-dt) (P + Q(dt)) F(-dt)^T (dt > 0 [s]).
template <class T>
void cwna_retrodict(model::OthrState<T>& x, Mat4<T>& P, T dt_s, T q0, T q1) {
  model::OthrState<T> zero = model::OthrState<T>::Zero();
  Mat4<T> Q = Mat4<T>::Zero();
  model::cwna_predict(zero, Q, dt_s, q0, q1);  // Q(dt) = F 0 F^T + Q
  Mat4<T> B = Mat4<T>::Identity();
  B(0, 1) = -dt_s;
  B(2, 3) = -dt_s;
  const model::OthrState<T> xb = B * x;
  x = xb;
  const Mat4<T> PQ = P + Q;
  const Mat4<T> BP = B * PQ;
  P = BP * B.transpose();
}

/// First index of `v` (sorted by slant range) at or above r_km.
template <class Vec, class T>
std::size_t first_leftover_at_or_above(const Vec& v, T r_km) {
  std::size_t lo = 0;
  std::size_t hi = v.size();
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (v[mid].y(0) < r_km) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

/// Carries track t back through every scan `sm` holds (newest first);
/// `now_us` is the time of the scan the track was born in. Returns the
/// number of held-back scans it was given; `refused` counts scans whose
/// entry table was full.
template <class T, std::size_t MaxPaths, class Smoother>
std::size_t retrodict(Smoother& sm, const PathTrack<T, MaxPaths>& t, std::uint64_t now_us, const RetroModel<T>& m,
                      std::size_t& refused) {
  constexpr std::size_t kMaxBack = 16;
  std::array<LagEntry<T>, kMaxBack> back{};
  std::array<std::array<std::int32_t, MaxPaths>, kMaxBack> taken{};
  std::size_t n = 0;
  std::size_t earliest = 0;  // entries back[0..earliest) are kept
  model::OthrState<T> x = t.x;
  Mat4<T> P = t.P;
  std::uint64_t next_us = now_us;
  for (std::size_t age = sm.pending(); age-- > 0 && n < kMaxBack;) {
    const auto& slot = sm.slot(age);
    const T dt = static_cast<T>(next_us - slot.time_us) * T(1e-6);
    cwna_retrodict(x, P, dt, m.q_range, m.q_bearing);
    const model::OthrState<T> x_lin = x;
    bool supported = false;
    for (std::size_t p = 0; p < m.num_paths; ++p) {
      taken[n][p] = -1;
      const PathLinearization<T> lin = linearize_path(x_lin, P, m.paths[p], m.baseline_km, slot.r_var);
      if (!lin.valid) continue;
      T half_ln_det_s = T(1.5) * dmath::kLnTwoPi<T>;
      for (int r = 0; r < 3; ++r) half_ln_det_s += dmath::dlog(lin.L(r, r));
      T best = m.gate_chi2;
      // Leftovers are in slant-range order: only the gate's range extent.
      const T half = std::sqrt(m.gate_chi2) * lin.L(0, 0);
      for (std::size_t j = first_leftover_at_or_above(slot.leftovers, lin.h(0) - half); j < slot.leftovers.size(); ++j) {
        if (slot.leftovers[j].y(0) > lin.h(0) + half) break;
        if (slot.leftovers[j].taken) continue;
        model::OthrMeas<T> v = slot.leftovers[j].y - lin.h;
        if (!slot.has_doppler) v(1) = T(0);
        const T d2 = mahalanobis2(lin, v);
        if (d2 < best) {
          best = d2;
          taken[n][p] = static_cast<std::int32_t>(j);
        }
      }
      if (taken[n][p] < 0) continue;
      const T score = m.ln_pd1[p] - m.ln_miss1[p] - m.ln_lambda - half_ln_det_s - T(0.5) * best;
      if (!(score > T(0))) {
        taken[n][p] = -1;
        continue;
      }
      const model::OthrMeas<T>& y = slot.leftovers[static_cast<std::size_t>(taken[n][p])].y;
      if (!path_update(x, P, x_lin, m.paths[p], m.baseline_km, y, T(1), slot.r_var, slot.has_doppler)) {
        taken[n][p] = -1;
      } else {
        supported = true;
      }
    }
    LagEntry<T>& e = back[n];
    e.id = t.id;
    e.x = x;
    e.P = P;
    e.x_pred = x;
    e.P_pred = P;
    e.q = t.existence;
    e.q_pred = t.existence;
    e.dt_s = dt;
    e.retro = true;
    for (std::size_t p = 0; p < m.num_paths && e.measurement_index < 0; ++p) {
      if (taken[n][p] >= 0) e.measurement_index = slot.leftovers[static_cast<std::size_t>(taken[n][p])].scan_index;
    }
    ++n;
    if (supported) earliest = n;
    next_us = slot.time_us;
  }
  // back[i] belongs to the scan of age pending() - 1 - i.
  for (std::size_t i = 0; i < earliest; ++i) {
    auto& slot = sm.slot(sm.pending() - 1 - i);
    if (!sm.record_at(sm.pending() - 1 - i, back[i])) {
      ++refused;
      continue;
    }
    for (std::size_t p = 0; p < m.num_paths; ++p) {
      if (taken[i][p] >= 0) slot.leftovers[static_cast<std::size_t>(taken[i][p])].taken = true;
    }
  }
  return earliest;
}

}  // namespace mptrack::multipath
