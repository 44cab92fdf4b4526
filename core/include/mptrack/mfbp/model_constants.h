// Quantities every MF-BP stage derives from the params once per init():
// the measurement noise R of seed 000 eq. (40) and its inverse, the
// log-normaliser of the expected Gaussian log-likelihood (eq. (79) with the
// -1/2 factor and the constants kept, docs/algorithms/mfbp.md §Evidence and
// association), the surveillance volume of the uniform clutter density
// (eq. (12)) and the Swerling order of the amplitude model. Also the small
// helpers the stages share (scan interval, detection probability).
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/mfbp/amplitude_model.h"
#include "mptrack/mfbp/cubature.h"
#include "mptrack/mfbp/amplitude_stats.h"
#include "mptrack/model/inverse_gamma.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/mfbp/target_filter.h"
#include "mptrack/track_report.h"

namespace mptrack::mfbp {

template <class T>
struct ModelConstants {
  int n_order = 1;        ///< Swerling order of the amplitude density
  T volume = T(1);        ///< surveillance region [m rad]
  T log_volume = T(0);
  T log_norm_R = T(0);    ///< -ln(2 pi) - ln|R| / 2
  Mat2<T> R = Mat2<T>::Identity();      ///< diag(sigma_r^2, sigma_az^2)
  Mat2<T> R_inv = Mat2<T>::Identity();

  void set(const MfbpParams<T>& params) {
    n_order = params.amplitude.order();
    volume = params.region.volume();
    log_volume = dmath::dlog(volume);
    R.setZero();
    R(0, 0) = params.noise.range_std_m * params.noise.range_std_m;
    R(1, 1) = params.noise.azimuth_std_rad * params.noise.azimuth_std_rad;
    R_inv.setZero();
    R_inv(0, 0) = T(1) / R(0, 0);
    R_inv(1, 1) = T(1) / R(1, 1);
    log_norm_R = -dmath::kLnTwoPi<T> - T(0.5) * dmath::dlog(R(0, 0) * R(1, 1));
  }
};

/// Seconds between two scan times [us].
template <class T>
T dt_s(std::uint64_t t_from, std::uint64_t t_to) {
  return static_cast<T>(static_cast<double>(t_to - t_from) * 1e-6);
}

/// P_D at the SNR belief's mean (seed 000 eq. (21)); a constant without amplitude.
template <class T>
T detection_prob(const MfbpParams<T>& p, int n_order, const model::InverseGamma<T>& ig) {
  if (!p.amplitude.use_amplitude) return p.pd_no_amplitude;
  return detection_probability(ig.mean(), p.amplitude.threshold, n_order, p.pd_model);
}

template <class T>
bool estimate_clutter(const MfbpParams<T>& p) {
  return p.clutter_mode == ClutterMode::kEstimate;
}

/// Known clutter components in use (the list is cut at the caps' component count).
template <class T>
std::size_t known_components(const MfbpParams<T>& p, std::size_t max_comp) {
  return p.known_clutter.num_components < max_comp ? p.known_clutter.num_components : max_comp;
}

inline void note_repair(bool repaired, TrackerCounters& counters) {
  if (repaired) ++counters.numerical_repairs;
}

}  // namespace mptrack::mfbp
