// MfbpParams<T>::validate and its two helpers: the bounds every MF-BP
// parameter is checked against once, in init() (docs/reliability.md F5, F9,
// F12). Included at the end of mfbp_params.h; include that header, not
// this one.
#pragma once

#include "mptrack/mfbp/mfbp_params.h"

namespace mptrack {

/// Checks every documented constraint; on the first failure names the field
/// in *where (if given) and returns kInvalidArgument. The checks against
/// the caps (window_length, birth_max_per_window, known clutter
/// components) are MfbpTracker::validate()'s.
///
/// Bounds beyond the sign checks (docs/reliability.md F5, F9, F12): every
/// std is squared in float, the clutter-birth grid has
/// (range span / clutter_cell_range_m) x (azimuth span / clutter_cell_az_rad)
/// cells and its seed threshold is clutter_seed_factor x (expected count per
/// cell), whose cell-to-region volume ratio multiplies the clutter rate.
/// The limits below keep all of these finite and the grid sizes and the
/// threshold far inside size_t:
///   region.range_max_m <= 1e7 m; region volume >= 1e-3 m rad;
///   cells per axis <= 1e6 and range x azimuth cells <= 1e8;
///   one cell at most 1e3 region volumes; clutter_seed_factor <= 1e6;
///   noise stds as PolarNoise (tracker_params.h), accel_var_m2ps4 <= 1e6;
///   rates, IG shapes, dirichlet_kappa, evidence and death counts <= 1e6
///   (uniform rates and dirichlet_kappa >= 1e-6);
///   CNR priors, known CNRs and ig_birth_scale_factor in [1e-6, 1e12]
///   (known CNRs may be 0); forgetting factors in [1, 10]; v_max <= 1e4 m/s;
///   amplitude.threshold <= 1e3.
template <class T>
Status MfbpParams<T>::validate(ParamError* where) const {
  constexpr T kMinVolume = T(1e-3);        // [m rad]
  constexpr T kMaxCellsPerAxis = T(1e6);
  constexpr T kMaxSeedCells = T(1e8);      // range x azimuth cells of the birth grid
  constexpr T kMaxCellVolumeRatio = T(1e3);
  constexpr T kMaxSeedFactor = T(1e6);
  constexpr T kMinCount = T(1e-6);         // positive rates and dirichlet_kappa [-]
  constexpr T kMaxCount = T(1e6);          // rates, shapes, Dirichlet kappa [-]
  constexpr T kMaxPower = T(1e12);         // CNR / SNR priors and scales, linear [-]
  ParamError* w = where;
  MPTRACK_TRY(region.validate(w));
  MPTRACK_CHECK_PARAM(w, "region.range_min_m", check_positive(region.range_min_m));
  const T span_r = region.range_max_m - region.range_min_m;
  const T span_a = region.azimuth_max_rad - region.azimuth_min_rad;
  MPTRACK_CHECK_PARAM(w, "region", check(!(span_r * span_a < kMinVolume)));
  MPTRACK_CHECK_PARAM(w, "scan_period_s", check_range_above(scan_period_s, T(0), T(3600)));
  MPTRACK_CHECK_PARAM(w, "max_gap_s", check_range(max_gap_s, T(1e-3), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "accel_var_m2ps4", check_range_above(accel_var_m2ps4, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "manoeuvre_noise_var_max",
                      check_range_above(manoeuvre_noise_var_max, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "manoeuvre_fading", check_range_below(manoeuvre_fading, T(0), T(1)));
  MPTRACK_TRY(noise.validate(w));
  MPTRACK_CHECK_PARAM(w, "gate_chi2", check_range_above(gate_chi2, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "clutter_gate_chi2",
                      check_range_above(clutter_gate_chi2, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "unresolved_chi2", check_range(unresolved_chi2, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "doppler_span_mps", check_range_above(doppler_span_mps, T(0), T(1e6)));
  MPTRACK_TRY(amplitude.validate(w));
  MPTRACK_CHECK_PARAM(w, "pd_no_amplitude", check_open_probability(pd_no_amplitude));
  MPTRACK_CHECK_PARAM(w, "forgetting_target", check_range(forgetting_target, T(1), T(10)));
  MPTRACK_CHECK_PARAM(w, "forgetting_clutter", check_range(forgetting_clutter, T(1), T(10)));
  MPTRACK_CHECK_PARAM(w, "ig_birth_shape", check(ig_birth_shape > T(2) && !(ig_birth_shape > kMaxCount)));
  MPTRACK_CHECK_PARAM(w, "ig_birth_scale_factor", check_range(ig_birth_scale_factor, T(1e-6), kMaxPower));
  MPTRACK_CHECK_PARAM(w, "p_survive", check_open_probability(p_survive));
  MPTRACK_CHECK_PARAM(w, "p_birth", check_open_probability(p_birth));
  MPTRACK_CHECK_PARAM(w, "pd_invisible", check_open_probability(pd_invisible));
  MPTRACK_CHECK_PARAM(w, "visibility_at_birth", check_open_probability(visibility_at_birth));
  MPTRACK_CHECK_PARAM(w, "window_length", check_at_least(window_length, 1));
  MPTRACK_CHECK_PARAM(w, "slide", check_range(slide, 1, window_length, "window_length"));
  MPTRACK_CHECK_PARAM(w, "mp_max_iterations", check_range(mp_max_iterations, 1, 100));
  MPTRACK_CHECK_PARAM(w, "mp_tolerance", check_positive(mp_tolerance));
  MPTRACK_CHECK_PARAM(w, "bp_max_iterations",
                      check_range(bp_max_iterations, 1, 100000));
  MPTRACK_CHECK_PARAM(w, "bp_tolerance", check_positive(bp_tolerance));
  MPTRACK_CHECK_PARAM(w, "bp_damping",
                      check_range_below(bp_damping, T(0), T(1)));
  MPTRACK_CHECK_PARAM(w, "w_min", check_positive(w_min));
  MPTRACK_CHECK_PARAM(w, "uniform_rate_per_scan", check_range(uniform_rate_per_scan, T(0), kMaxCount));
  MPTRACK_CHECK_PARAM(w, "uniform_rate_floor_per_scan",
                      check_range(uniform_rate_floor_per_scan, kMinCount, kMaxCount));
  MPTRACK_CHECK_PARAM(w, "nw_forgetting_factor",
                      check(is_finite(nw_forgetting_factor) && nw_forgetting_factor > T(0) &&
                            !(nw_forgetting_factor > T(1))));
  MPTRACK_CHECK_PARAM(w, "dirichlet_kappa", check_range(dirichlet_kappa, kMinCount, kMaxCount));
  MPTRACK_CHECK_PARAM(w, "component_absent_evidence", check_range(component_absent_evidence, T(0), kMaxCount));
  MPTRACK_CHECK_PARAM(w, "uniform_cnr_prior", check_range(uniform_cnr_prior, T(1e-6), kMaxPower));
  MPTRACK_CHECK_PARAM(w, "uniform_cnr_prior_shape",
                      check(uniform_cnr_prior_shape > T(1) && !(uniform_cnr_prior_shape > kMaxCount)));
  MPTRACK_CHECK_PARAM(w, "v_max_x_mps", check_range_above(v_max_x_mps, T(0), T(1e4)));
  MPTRACK_CHECK_PARAM(w, "v_max_y_mps", check_range_above(v_max_y_mps, T(0), T(1e4)));
  MPTRACK_CHECK_PARAM(w, "birth_max_lag", check_range(birth_max_lag, 1, 3));
  MPTRACK_CHECK_PARAM(w, "birth_max_per_window", check_at_least(birth_max_per_window, 1));
  MPTRACK_CHECK_PARAM(w, "unexplained_threshold", check_open_probability(unexplained_threshold));
  MPTRACK_CHECK_PARAM(w, "birth_max_component_share", check_range(birth_max_component_share, T(0), T(1)));
  MPTRACK_CHECK_PARAM(w, "birth_in_clutter_max_cnr", check_range(birth_in_clutter_max_cnr, T(0), T(1e6)));
  MPTRACK_CHECK_PARAM(w, "birth_single_point_tail",
                      check(birth_single_point_tail >= T(0) && !(birth_single_point_tail > birth_amplitude_tail)));
  MPTRACK_CHECK_PARAM(w, "birth_amplitude_tail",
                      check(birth_amplitude_tail >= T(0) && birth_amplitude_tail < T(1)));
  MPTRACK_CHECK_PARAM(w, "confirm_threshold", check_open_probability(confirm_threshold));
  MPTRACK_CHECK_PARAM(w, "confirm_threshold_in_clutter",
                      check_open_probability(confirm_threshold_in_clutter));
  MPTRACK_CHECK_PARAM(w, "filter_confirm_score_in_clutter",
                      check_range(filter_confirm_score_in_clutter, T(0), T(100)));
  MPTRACK_CHECK_PARAM(w, "delete_threshold", check_open_probability(delete_threshold));
  MPTRACK_CHECK_PARAM(w, "delete_run", check_at_least(delete_run, 1));
  MPTRACK_CHECK_PARAM(w, "tentative_timeout_scans", check_at_least(tentative_timeout_scans, 1));
  MPTRACK_CHECK_PARAM(w, "tentative_timeout_in_clutter_scans", check_at_least(tentative_timeout_in_clutter_scans, 1));
  MPTRACK_CHECK_PARAM(w, "report_existence_min", check_range(report_existence_min, T(0), T(1)));
  MPTRACK_CHECK_PARAM(w, "duplicate_chi2", check_range(duplicate_chi2, T(0), T(1e6)));
  MPTRACK_TRY(validate_clutter_grid(span_r, span_a, kMaxCellsPerAxis, kMaxSeedCells,
                                    kMaxCellVolumeRatio, kMaxSeedFactor, kMaxCount, w));
  MPTRACK_CHECK_PARAM(w, "clutter_mode",
                      check(clutter_mode == ClutterMode::kEstimatedMap ||
                            clutter_mode == ClutterMode::kKnownRateUniform ||
                            clutter_mode == ClutterMode::kKnownMap));
  return validate_known_clutter(kMaxCount, kMaxPower, w);
}

/// The clutter-birth grid fields (see validate()).
template <class T>
Status MfbpParams<T>::validate_clutter_grid(T span_r, T span_a, T max_cells_per_axis, T max_seed_cells,
                                            T max_cell_volume_ratio, T max_seed_factor, T max_count,
                                            ParamError* w) const {
  MPTRACK_CHECK_PARAM(w, "clutter_cell_range_m", check_positive(clutter_cell_range_m));
  MPTRACK_CHECK_PARAM(w, "clutter_cell_az_rad", check_positive(clutter_cell_az_rad));
  MPTRACK_CHECK_PARAM(w, "clutter_cell_range_m",
                      check(!(span_r > max_cells_per_axis * clutter_cell_range_m)));
  MPTRACK_CHECK_PARAM(w, "clutter_cell_az_rad", check(!(span_a > max_cells_per_axis * clutter_cell_az_rad)));
  MPTRACK_CHECK_PARAM(w, "clutter_cell_range_m",
                      check(!((span_r / clutter_cell_range_m) * (span_a / clutter_cell_az_rad) >
                              max_seed_cells)));
  MPTRACK_CHECK_PARAM(w, "clutter_cell_range_m",
                      check(!(clutter_cell_range_m * clutter_cell_az_rad >
                              max_cell_volume_ratio * span_r * span_a)));
  MPTRACK_CHECK_PARAM(w, "clutter_seed_factor",
                      check_range_above(clutter_seed_factor, T(0), max_seed_factor));
  MPTRACK_CHECK_PARAM(w, "clutter_death_count", check_range(clutter_death_count, T(0), max_count));
  MPTRACK_CHECK_PARAM(w, "clutter_death_windows", check_at_least(clutter_death_windows, 1));
  return Status::kOk;
}

/// known_clutter (used by ClutterMode::kKnownMap only; see validate()).
template <class T>
Status MfbpParams<T>::validate_known_clutter(T max_count, T max_power, ParamError* w) const {
  const auto& kc = known_clutter;
  MPTRACK_CHECK_PARAM(w, "known_clutter.num_components",
                      check_at_most(kc.num_components, kMaxKnownClutterComponents, "kMaxKnownClutterComponents"));
  if (clutter_mode != ClutterMode::kKnownMap) return Status::kOk;
  MPTRACK_CHECK_PARAM(w, "known_clutter.uniform_rate_per_scan",
                      check_range(kc.uniform_rate_per_scan, T(0), max_count));
  MPTRACK_CHECK_PARAM(w, "known_clutter.uniform_cnr", check_range(kc.uniform_cnr, T(0), max_power));
  for (std::size_t c = 0; c < kc.num_components; ++c) {
    const auto& comp = kc.components[c];
    MPTRACK_CHECK_PARAM(w, "known_clutter.components.rate_per_scan",
                        check_range(comp.rate_per_scan, T(0), max_count));
    MPTRACK_CHECK_PARAM(w, "known_clutter.components.cnr", check_range(comp.cnr, T(0), max_power));
    MPTRACK_CHECK_PARAM(w, "known_clutter.components.active_until_us",
                        check(comp.active_from_us <= comp.active_until_us));
    const T det = comp.covariance(0, 0) * comp.covariance(1, 1) -
                  comp.covariance(0, 1) * comp.covariance(1, 0);
    MPTRACK_CHECK_PARAM(w, "known_clutter.components.covariance",
                        check(is_finite(det) && det > T(0) && comp.covariance(0, 0) > T(0)));
  }
  return Status::kOk;
}

}  // namespace mptrack
