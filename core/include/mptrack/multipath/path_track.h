// One track of the multipath tracker: a ground-coordinate Gaussian
// q(x) = N(x; x, P) in [g km, g_dot km/s, theta rad, theta_dot rad/s] and the
// active/dormant meta-state q(s = 1) (seed 002 eqs. (28)-(40);
// docs/algorithms/multipath.md §Track state). The prior of the current scan
// (prediction) is kept beside the VB iterate: every VB pass restarts the
// state update from it (seed 002 eq. (28): q(x) is prior x likelihood).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "mptrack/model/othr_measurement.h"

namespace mptrack::multipath {

template <class T>
using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;

template <class T, std::size_t MaxPaths>
struct PathTrack {
  std::uint32_t id = 0;  ///< stable, never reused within a run
  model::OthrState<T> x = model::OthrState<T>::Zero();  ///< VB iterate (posterior mean)
  Mat4<T> P = Mat4<T>::Zero();
  model::OthrState<T> x_prior = model::OthrState<T>::Zero();  ///< prediction of this scan
  Mat4<T> P_prior = Mat4<T>::Zero();
  T existence = T(0);        ///< q(s = 1) after this scan's update
  T existence_prior = T(0);  ///< predicted p(s = 1) of this scan
  /// E[d^tau]: expected detection indicator per path this scan (seed 002 eq. (40)).
  std::array<T, MaxPaths> detected{};
  std::int32_t measurement_index = -1;  ///< scan index of the most likely detection, -1 = none
  std::uint32_t age_scans = 0;
  bool confirmed = false;  ///< has reached the counting threshold once
  bool counted = false;    ///< reported at the last scan
  /// q(s = 1) of the last scans (ring, newest at history_next - 1), for
  /// the deletion rule; history_count of them are filled.
  std::array<T, 8> history{};
  std::uint32_t history_next = 0;
  std::uint32_t history_count = 0;

  void record_existence() {
    history[history_next] = existence;
    history_next = (history_next + 1) % 8u;
    if (history_count < 8u) ++history_count;
  }
  /// Finite mean and variances (a track that is not is deleted).
  bool finite() const {
    for (int r = 0; r < 4; ++r) {
      if (!(x(r) - x(r) == T(0)) || !(P(r, r) - P(r, r) == T(0))) return false;
    }
    return true;
  }

  /// Mean q(s = 1) over the last min(window, history_count) records.
  T mean_existence(std::uint32_t window) const {
    const std::uint32_t n = window < history_count ? window : history_count;
    if (n == 0) return existence;
    T sum = T(0);
    for (std::uint32_t k = 1; k <= n; ++k) sum += history[(history_next + 8u - k) % 8u];
    return sum / static_cast<T>(n);
  }
};

/// Meta-state prediction p(s_k = 1) from q(s_k-1 = 1) (the transition of seed 002 eq. (38)).
template <class T>
T existence_predict(T q1, T p_stay, T p_become) {
  return p_stay * q1 + p_become * (T(1) - q1);
}

/// Meta-state update with the emission exp(xi(s)) of seed 002 eqs. (38)-(39):
/// xi(s) = sum_tau E[d^tau] ln pd^tau(s) + (1 - E[d^tau]) ln(1 - pd^tau(s)).
/// ln_pd1[tau], ln_miss1[tau] are ln pd^tau(1), ln(1 - pd^tau(1)); ln_pd0,
/// ln_miss0 the same for the dormant state. Computed through the difference
/// xi(0) - xi(1) so that neither weight underflows.
template <class T>
T existence_update(T prior1, const T* detected, std::size_t num_paths, const T* ln_pd1,
                   const T* ln_miss1, T ln_pd0, T ln_miss0) {
  T diff = T(0);  // xi(0) - xi(1)
  for (std::size_t tau = 0; tau < num_paths; ++tau) {
    const T d = detected[tau];
    diff += d * (ln_pd0 - ln_pd1[tau]) + (T(1) - d) * (ln_miss0 - ln_miss1[tau]);
  }
  const T prior0 = T(1) - prior1;
  if (!(prior1 > T(0))) return T(0);
  if (diff > T(80)) return T(0);
  return prior1 / (prior1 + prior0 * dmath::dexp(diff));
}

}  // namespace mptrack::multipath
