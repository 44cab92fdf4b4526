// Run-time tunables of the VMP tracker (docs/algorithms/vmp.md; seed 004 Sec. V-A
// for the values the paper gives, docs/algorithms/vmp.md §Parameters for the
// ones it leaves open). Units in the comments; validate() names the failing field.
// The waveform/array/noise block must describe the radar that produced the frames
// (host-sim: adc::vmp_params_for builds it from adc::RadarSpec).
#pragma once

#include <cstddef>

#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

struct VmpParams {
  // Waveform, array, receiver (match adc::RadarSpec).
  double carrier_hz = 10e9;                  ///< f_c [Hz]
  double bandwidth_hz = 20e6;                ///< chirp sweep BW [Hz]
  double chirp_duration_s = 3.6e-6;          ///< T_Tx [s]
  double sample_rate_hz = 32e6;              ///< f_s [Hz]
  double element_spacing_wavelengths = 0.5;  ///< virtual ULA spacing d [lambda], (0, 1]
  double tx_amplitude = 0.53;                ///< A of rho(r) = A G lambda / ((4 pi)^1.5 r^2) [V/m]
  double antenna_gain = 1.0;                 ///< G [-]
  double mean_rcs_m2 = 0.05;                 ///< E[sigma_RCS] [m^2] (amplitude prior scale)
  double noise_variance_v2 = 1.380649e-23 * 290.0 * 32e6;  ///< sigma_w^2 per complex sample [V^2]
                                                          ///< (default: k_b T0 f_s, model A)
  // Existence (seed 004 eqs. (6), (17); Sec. V-A).
  double survival_probability = 0.95;  ///< p_s, (0, 1)
  double birth_probability = 1e-8;     ///< p_b, (0, 1); birth test logit xi > logit(1 - p_b)
  double prune_existence = 0.1;        ///< delta_minus: tracks below are deleted, (0, 1)
  bool predictive_existence_prior = true;   ///< false: the mean-field prior log-odds of seed 004
                                           ///< eq. (17), xi (logit p_s - logit p_b) + logit p_b; true:
                                           ///< the Bernoulli-filter prediction logit(p_s xi + p_b (1 - xi))
                                           ///< (docs/algorithms/vmp.md §Corrections)
  double amplitude_prior_precision = 1.0;  ///< lambda_p in whitened units (1 = 1 / mean RCS) [-]
  // Dynamics (seed 004 eqs. (4)-(5), (23)-(25)).
  double gamma_shape_zeta = 4.0;         ///< zeta: prior shape zeta/2 of each lambda_j [-], > 0
  double gamma_rate_chi = 36.0;          ///< chi: prior rate chi/2 (prior mean lambda = zeta/chi) [-], > 0
  double gamma_rate_floor = 1e-6;        ///< floor on chi + sum V_jj [-], > 0
  double birth_velocity_std_mps = 5.0;   ///< sigma_v0 of the zero-mean birth velocity [m/s], > 0
  double frame_period_s = 0.1;           ///< nominal frame interval [s] (first frame only), > 0
  double max_gap_s = 60.0;               ///< longer gaps drop every track (scan_clock.h) [s]
  // Surveillance region (births and the birth map).
  double min_range_m = 3.0;              ///< [m], > 0
  double max_range_m = 100.0;            ///< [m] (seed 004: R_max), > min_range_m
  double max_abs_bearing_rad = 1.3089969389957472;  ///< |theta| <= this [rad] (75 deg), (0, pi/2)
  double map_range_step_m = 1.17;        ///< birth map range step [m], > 0
  double map_sin_step = 1.0 / 32.0;      ///< birth map step in sin theta [-], > 0
  // Iterations and safeguards (docs/algorithms/vmp.md §Numerics).
  std::size_t gn_iterations = 8;         ///< Gauss-Newton iterations of the data message, 1..64
  double gn_max_step_m = 1.0;            ///< step cap [m], > 0
  double gn_tol_m = 1e-3;                ///< step below which Gauss-Newton stops [m], > 0
  std::size_t gn_backtracks = 4;         ///< step halvings, <= 16
  double min_message_energy = 1e-3;      ///< e_k below this: no data message [-], >= 0
  double min_message_precision = 1e-6;   ///< eigenvalue floor of the message precision [1/m^2], > 0
  double max_message_precision = 1e8;    ///< eigenvalue cap [1/m^2], > min
  std::size_t existence_sweeps = 10;     ///< coordinate sweeps of q(xi), 1..100
  double existence_tol = 0.01;           ///< stop when no log-odds moves more [-], > 0
  std::size_t outer_iterations = 3;      ///< N_OUT: smoother pass + Gamma update per frame, 1..16
  std::size_t max_births_per_frame = 4;  ///< B_MAX (<= Caps::kMaxBirthsPerFrame)
  bool literal_path_loss_derivative = false;  ///< differentiate rho~(r) in the data message
  bool diagonal_message = false;         ///< diagonal message precision (the paper's restriction)
  double min_variance = 1e-9;            ///< covariance repair floor [m^2, m^2/s^2], > 0

  /// Every field on its own; the caps fit is VmpTracker::validate()'s.
  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "carrier_hz", check_carrier_hz(carrier_hz));
    MPTRACK_CHECK_PARAM(where, "bandwidth_hz", check_positive(bandwidth_hz));
    MPTRACK_CHECK_PARAM(where, "chirp_duration_s", check_positive(chirp_duration_s));
    MPTRACK_CHECK_PARAM(where, "sample_rate_hz", check_positive(sample_rate_hz));
    MPTRACK_CHECK_PARAM(where, "element_spacing_wavelengths", check_range(element_spacing_wavelengths, 1e-3, 1.0));
    MPTRACK_CHECK_PARAM(where, "tx_amplitude", check_positive(tx_amplitude));
    MPTRACK_CHECK_PARAM(where, "antenna_gain", check_positive(antenna_gain));
    MPTRACK_CHECK_PARAM(where, "mean_rcs_m2", check_positive(mean_rcs_m2));
    MPTRACK_CHECK_PARAM(where, "noise_variance_v2", check_positive(noise_variance_v2));
    MPTRACK_CHECK_PARAM(where, "survival_probability", check_open_probability(survival_probability));
    MPTRACK_CHECK_PARAM(where, "birth_probability", check_open_probability(birth_probability));
    MPTRACK_CHECK_PARAM(where, "prune_existence", check_open_probability(prune_existence));
    MPTRACK_CHECK_PARAM(where, "amplitude_prior_precision", check_positive(amplitude_prior_precision));
    MPTRACK_CHECK_PARAM(where, "gamma_shape_zeta", check_positive(gamma_shape_zeta));
    MPTRACK_CHECK_PARAM(where, "gamma_rate_chi", check_positive(gamma_rate_chi));
    MPTRACK_CHECK_PARAM(where, "gamma_rate_floor", check_positive(gamma_rate_floor));
    MPTRACK_CHECK_PARAM(where, "birth_velocity_std_mps", check_positive(birth_velocity_std_mps));
    MPTRACK_CHECK_PARAM(where, "frame_period_s", check_positive(frame_period_s));
    MPTRACK_CHECK_PARAM(where, "max_gap_s", check_range(max_gap_s, 1e-6, 1e6));
    MPTRACK_CHECK_PARAM(where, "min_range_m", check_positive(min_range_m));
    MPTRACK_CHECK_PARAM(where, "max_range_m", check_above(max_range_m, min_range_m, "min_range_m"));
    MPTRACK_CHECK_PARAM(where, "max_abs_bearing_rad", check_range(max_abs_bearing_rad, 1e-3, 1.5707));
    MPTRACK_CHECK_PARAM(where, "map_range_step_m", check_positive(map_range_step_m));
    MPTRACK_CHECK_PARAM(where, "map_sin_step", check_range(map_sin_step, 1e-4, 1.0));
    MPTRACK_CHECK_PARAM(where, "gn_iterations", check_range(gn_iterations, 1, 64));
    MPTRACK_CHECK_PARAM(where, "gn_max_step_m", check_positive(gn_max_step_m));
    MPTRACK_CHECK_PARAM(where, "gn_tol_m", check_positive(gn_tol_m));
    MPTRACK_CHECK_PARAM(where, "gn_backtracks", check_at_most(gn_backtracks, 16));
    MPTRACK_CHECK_PARAM(where, "min_message_energy", check_range(min_message_energy, 0.0, 1e6));
    MPTRACK_CHECK_PARAM(where, "min_message_precision", check_positive(min_message_precision));
    MPTRACK_CHECK_PARAM(where, "max_message_precision",
                        check_above(max_message_precision, min_message_precision, "min_message_precision"));
    MPTRACK_CHECK_PARAM(where, "existence_sweeps", check_range(existence_sweeps, 1, 100));
    MPTRACK_CHECK_PARAM(where, "existence_tol", check_positive(existence_tol));
    MPTRACK_CHECK_PARAM(where, "outer_iterations", check_range(outer_iterations, 1, 16));
    MPTRACK_CHECK_PARAM(where, "max_births_per_frame", check_at_most(max_births_per_frame, 64));
    MPTRACK_CHECK_PARAM(where, "min_variance", check_positive(min_variance));
    return Status::kOk;
  }
};

}  // namespace mptrack
