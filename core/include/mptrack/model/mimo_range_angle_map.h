// Matched-filter map of a residual over a coarse (range, sin theta) grid: where a
// new atom would explain most of what the current model leaves unexplained
// (seed 004 Alg. 2; docs/algorithms/vmp.md §Births).
//
// For every range cell r_g the per-channel matched filter
//   MF_v(r_g) = sum_k U_k^* exp(+j 2 pi f_k tau_g) r[v][k],   tau_g = 2 r_g / c,
// then for every grid bearing u_h = sin theta_h the beam
//   B(r_g, u_h) = sum_v exp(-j c_v u_h) MF_v(r_g),
// so that s(r_g, u_h)^H r = rho~(r_g) B (model/mimo_atom.h). The caller's score
// sees (r_g, u_h, |B|^2) and the map returns the best cell; cost
// O(N_R K_B N_V + N_R N_A N_V) complex MACs, no FFT scratch. The beam
// steering table (N_V x N_A) is built once in init(); the power map
// (N_R x N_A floats) is kept so that the next-best peaks cost a scan only.
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/model/mimo_atom.h"

namespace mptrack::model {

template <class T>
struct MapPeak {
  bool found = false;
  T range_m = T(0);
  T sin_t = T(0);
  T beam_power = T(0);  ///< |B|^2 = |s^H r|^2 / rho~^2
  T score = T(0);
};

template <class T, std::size_t NV, std::size_t KB, std::size_t kMaxRange, std::size_t kMaxAngle>
class MimoRangeAngleMap {
 public:
  /// Grid r = r_min + g r_step (g < kMaxRange, r <= r_max), u = -u_max + h u_step
  /// (h < kMaxAngle, u <= u_max). False if a grid is empty or an argument is not positive.
  bool init(const MimoAtomBasis<T, NV, KB>& b, T r_min, T r_max, T r_step, T u_max, T u_step) {
    if (!(r_step > T(0)) || !(u_step > T(0)) || !(r_min > T(0)) || !(r_max >= r_min) || !(u_max >= T(0))) {
      return false;
    }
    n_range_ = 0;
    while (n_range_ < kMaxRange && r_min + static_cast<T>(n_range_) * r_step <= r_max) ++n_range_;
    n_angle_ = 0;
    while (n_angle_ < kMaxAngle && -u_max + static_cast<T>(n_angle_) * u_step <= u_max) ++n_angle_;
    r_min_ = r_min;
    r_step_ = r_step;
    u_min_ = -u_max;
    u_step_ = u_step;
    for (std::size_t h = 0; h < n_angle_; ++h) {
      const T u = u_min_ + static_cast<T>(h) * u_step_;
      for (std::size_t v = 0; v < NV; ++v) {
        T s = T(0);
        T c = T(1);
        dmath::dsincos(-b.c(v) * u, s, c);
        steer_[h * NV + v] = {c, s};
      }
    }
    return n_range_ > 0 && n_angle_ > 0;
  }

  /// Evaluates |B|^2 on every cell for the residual r (planar, N_V K_B).
  /// Per range cell the phasors exp(+j 2 pi f_k tau) run as a recurrence
  /// (one dsincos for the first bin and one for the step, re-seeded every
  /// kReseed bins), so a map costs O(N_R (N_V K_B + N_A N_V)) multiplies and
  /// 2 N_R K_B / kReseed sincos.
  void evaluate(const MimoAtomBasis<T, NV, KB>& b, const T* r_re, const T* r_im) {
    std::array<Cx<T>, NV> mf{};
    const T df = KB > 1 ? b.f(1) - b.f(0) : T(0);  // uniform bin spacing
    for (std::size_t g = 0; g < n_range_; ++g) {
      const T tau = T(2) * (r_min_ + static_cast<T>(g) * r_step_) / kLightSpeed_mps<T>;
      for (std::size_t v = 0; v < NV; ++v) mf[v] = Cx<T>{};
      T ss = T(0);
      T cs = T(1);
      dmath::dsincos(dmath::kTwoPi<T> * df * tau, ss, cs);
      const Cx<T> step{cs, ss};
      Cx<T> ph{};
      for (std::size_t k = 0; k < KB; ++k) {
        if (k % kReseed == 0) {
          T s = T(0);
          T c = T(1);
          dmath::dsincos(dmath::kTwoPi<T> * b.f(k) * tau, s, c);
          ph = {c, s};
        } else {
          ph = cx_mul(ph, step);
        }
        const Cx<T> w = cx_cmul(b.u(k), ph);  // U_k^* e^{+j 2 pi f_k tau}
        for (std::size_t v = 0; v < NV; ++v) mf[v] = cx_add(mf[v], cx_mul(w, Cx<T>{r_re[v * KB + k], r_im[v * KB + k]}));
      }
      for (std::size_t h = 0; h < n_angle_; ++h) {
        Cx<T> beam{};
        for (std::size_t v = 0; v < NV; ++v) beam = cx_add(beam, cx_mul(steer_[h * NV + v], mf[v]));
        power_[g * kMaxAngle + h] = cx_norm2(beam);
      }
    }
  }

  /// The cell of the last evaluate() maximising score(range_m, sin_t, |B|^2),
  /// skipping cells within (|dr| < r_excl, |du| < u_excl) of the n_excl
  /// excluded peaks (the next-best distinct peak after a refused candidate).
  template <class Score>
  MapPeak<T> best(Score&& score, const MapPeak<T>* excl = nullptr, std::size_t n_excl = 0, T r_excl = T(0),
                  T u_excl = T(0)) const {
    MapPeak<T> peak;
    for (std::size_t g = 0; g < n_range_; ++g) {
      const T range = r_min_ + static_cast<T>(g) * r_step_;
      for (std::size_t h = 0; h < n_angle_; ++h) {
        const T u = u_min_ + static_cast<T>(h) * u_step_;
        bool skip = false;
        for (std::size_t e = 0; e < n_excl; ++e) {
          const T dr = range - excl[e].range_m, du = u - excl[e].sin_t;
          skip = skip || ((dr < r_excl && -dr < r_excl) && (du < u_excl && -du < u_excl));
        }
        if (skip) continue;
        const T p = power_[g * kMaxAngle + h];
        const T sc = score(range, u, p);
        if (!peak.found || sc > peak.score) {
          peak.found = true;
          peak.range_m = range;
          peak.sin_t = u;
          peak.beam_power = p;
          peak.score = sc;
        }
      }
    }
    return peak;
  }

  /// evaluate() then best(): the one-call form of the first version of this map.
  template <class Score>
  MapPeak<T> best(const MimoAtomBasis<T, NV, KB>& b, const T* r_re, const T* r_im, Score&& score,
                  const MapPeak<T>* excl = nullptr, std::size_t n_excl = 0, T r_excl = T(0), T u_excl = T(0)) {
    evaluate(b, r_re, r_im);
    return best(score, excl, n_excl, r_excl, u_excl);
  }

  std::size_t range_cells() const { return n_range_; }
  std::size_t angle_cells() const { return n_angle_; }

 private:
  static constexpr std::size_t kReseed = 32;
  std::array<Cx<T>, kMaxAngle * NV> steer_{};
  std::array<T, kMaxRange * kMaxAngle> power_{};  ///< |B|^2 of the last evaluate()
  std::size_t n_range_ = 0, n_angle_ = 0;
  T r_min_ = T(0), r_step_ = T(1), u_min_ = T(0), u_step_ = T(1);
};

}  // namespace mptrack::model
