// Run-time parameters of the multipath MF-BP tracker (seed 002;
// docs/algorithms/multipath.md). Defaults are the paper's OTHR scenario
// (seed 002 Sec. IV): 4 ionospheric paths (E 100 km, F 260 km), baseline
// 100 km, sigma = [5 km, 1 m/s, 3 mrad], PSD 1e-8 km^2/s^3 in ground range
// and 1e-8 rad^2/s^3 in bearing, Nc = 125, p_d = 0.75, meta-state
// transitions 0.85 / 0.15, counting threshold 0.85, grouping thresholds
// [80 km, 5 m/s, 0.03 rad]. Values the paper does not give are ours
// (docs/algorithms/multipath.md §Departures from the paper).
//
// Measurement convention (docs/algorithms/multipath.md §Measurements):
// Measurement::range_m is the slant (group) range, doppler_mps the slant
// range rate (positive opening), azimuth_rad the azimuth zeta; the ground
// state is reported as Cartesian [x m, vx, y m, vy] with x = g cos theta,
// y = g sin theta (receiver at the origin, transmitter at (0, d)).
#pragma once

#include <array>
#include <cstdint>

#include "mptrack/model/othr_measurement.h"
#include "mptrack/multipath/multipath_caps.h"
#include "mptrack/status.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T>
struct MultipathParams {
  // --- propagation paths (seed 002 Sec. IV-A) ---
  std::uint32_t num_paths = 4;  ///< N_P, in [1, Caps::kMaxPaths]
  /// (transmit, receive) virtual heights [km] of paths 0..num_paths-1: EE, EF, FE, FF.
  std::array<model::OthrPath<T>, multipath::kParamPaths> paths{
      {{T(100), T(100)}, {T(100), T(260)}, {T(260), T(100)}, {T(260), T(260)}}};
  /// Detection probability of an active target on each path [-], in (0, 1).
  std::array<T, multipath::kParamPaths> pd{T(0.75), T(0.75), T(0.75), T(0.75),
                                           T(0.75), T(0.75), T(0.75), T(0.75)};
  /// Detection probability of a dormant target, every path (the paper gives none) [-].
  T pd_dormant = T(0.01);
  T baseline_km = T(100);  ///< receiver-transmitter distance d [km], in [0, 1e4]

  // --- measurement space ---
  PolarRegion<T> region{T(1.5e6), T(2.0e6), T(0.428), T(0.608)};  ///< slant range [m], azimuth [rad]
  T range_rate_span_mps = T(524);  ///< |slant range rate| bound of the region [m/s]
  PolarNoise<T> noise{T(5000), T(0.003), T(1)};  ///< range [m], azimuth [rad], range rate [m/s]
  T clutter_mean_count = T(125);  ///< expected clutter detections per scan (uniform) [-]

  // --- motion (seed 002 Sec. IV) ---
  T range_psd_m2ps3 = T(1e-2);      ///< ground-range white-noise PSD [m^2/s^3] (1e-8 km^2/s^3)
  T bearing_psd_rad2ps3 = T(1e-8);  ///< bearing white-noise PSD [rad^2/s^3]

  // --- meta-state (seed 002 eq. (38)) ---
  T p_stay_active = T(0.85);    ///< p(s_k = 1 | s_k-1 = 1) [-]
  T p_become_active = T(0.15);  ///< p(s_k = 1 | s_k-1 = 0) [-]
  T confirm_existence = T(0.85);  ///< delta_s: reported (counted) when q(s = 1) >= this [-]
  /// A track counted before stays counted while q(s = 1) >= this [-]
  /// (hysteresis standing in for the paper's smoothed q(s); equal to
  /// confirm_existence: no hysteresis).
  T hold_existence = T(0.85);
  /// Deleted when the mean q(s = 1) over the last delete_window scans (the
  /// birth value included) falls below this [-]. A mean, not the last value:
  /// at low p_d the chain's floor (p_become_active) keeps a clutter track's
  /// q(s = 1) near 0.03 for ever (docs/algorithms/multipath.md §Track management).
  T delete_existence = T(0.1);
  std::uint32_t delete_window = 3;  ///< scans averaged by the deletion rule, in [1, 8] (seed 002 Sec. III-E: 3)

  // --- association (seed 002 eqs. (41)-(55), pseudo-target BP) ---
  T gate_chi2 = T(9);                    ///< 3-dof gate (p_g 0.971, seed 002 Sec. IV) [-]
  std::uint32_t vb_iterations = 3;       ///< VB passes per scan (association, meta-state, state)
  std::uint32_t bp_max_iterations = 30;  ///< loopy BP iteration cap
  T bp_tolerance = T(1e-5);              ///< BP stops when no message moves more [-]
  T bp_damping = T(0);                   ///< message damping in [0, 1)

  // --- births from multi-detection groups (seed 002 Sec. III-E) ---
  T group_range_m = T(80000);          ///< rho_r [m]
  T group_range_rate_mps = T(5);       ///< rho_r_dot [m/s]
  T group_azimuth_rad = T(0.03);       ///< rho_zeta [rad]
  std::uint32_t min_group_size = 2;    ///< detections a group needs to start a track [-]
  T birth_clutter_belief = T(0.5);     ///< a detection seeds births if P(clutter) >= this [-]
  /// Largest mean squared normalised spread of a group's ground points per
  /// degree of freedom (docs/algorithms/multipath.md §Births) [-].
  T birth_max_spread = T(4);
  /// Birth existence = birth_existence_scale min(1, (m / N_P)^2) for a group of m (seed 002 Sec. III-E).
  T birth_existence_scale = T(1);
  /// Also start the best assignment whose ground range differs from the best
  /// one's by more than birth_distinct_range_m, when it passes the spread test:
  /// an ambiguous group starts both and the association keeps the one the
  /// next scans support (docs/algorithms/multipath.md §Births).
  bool birth_ambiguous_both = true;
  T birth_distinct_range_m = T(15000);
  T init_range_rate_std_mps = T(1);        ///< ground range-rate std of a new track, / sqrt(m) for m detections [m/s]
  T init_bearing_rate_std_radps = T(2e-4);  ///< bearing-rate std of a new track [rad/s]

  // --- reporting, gaps, numerics ---
  bool report_tentative = false;  ///< true: also report tracks below confirm_existence
  /// Scans the output is held back for fixed-lag smoothing (0 = the filter's
  /// estimate at once; at most Caps::kMaxSmoothingLag; docs/algorithms/
  /// multipath.md §Fixed-lag smoother) [scans].
  std::uint32_t smoothing_lag_scans = 0;
  /// With a lag: carry a new track back through the held-back scans'
  /// leftover detections (docs/algorithms/multipath.md §Retrodiction).
  bool retrodict_births = true;
  T max_gap_s = T(120);           ///< a longer gap drops every track (scan_clock.h) [s]
  T min_variance = T(1e-14);      ///< diagonal floor of the last-resort covariance repair [-]

  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "num_paths", check_range(num_paths, 1, multipath::kParamPaths, "multipath::kParamPaths"));
    for (std::uint32_t p = 0; p < num_paths; ++p) {
      MPTRACK_CHECK_PARAM(where, "paths", check_range(paths[p].tx_height_km, T(0), T(1e4)));
      MPTRACK_CHECK_PARAM(where, "paths", check_range(paths[p].rx_height_km, T(0), T(1e4)));
      MPTRACK_CHECK_PARAM(where, "pd", check(pd[p] > T(0) && pd[p] < T(1)));
      MPTRACK_CHECK_PARAM(where, "pd", check(pd[p] > pd_dormant));
    }
    MPTRACK_CHECK_PARAM(where, "pd_dormant", check_open_probability(pd_dormant));
    MPTRACK_CHECK_PARAM(where, "baseline_km", check_range(baseline_km, T(0), T(1e4)));
    MPTRACK_TRY(region.validate(where));
    MPTRACK_CHECK_PARAM(where, "region.range_min_m", check_positive(region.range_min_m));
    MPTRACK_CHECK_PARAM(where, "range_rate_span_mps", check_range(range_rate_span_mps, T(1e-3), T(1e5)));
    MPTRACK_TRY(noise.validate(where));
    MPTRACK_CHECK_PARAM(where, "clutter_mean_count", check_range(clutter_mean_count, T(1e-3), T(1e5)));
    MPTRACK_CHECK_PARAM(where, "range_psd_m2ps3", check_range(range_psd_m2ps3, T(0), T(1e6)));
    MPTRACK_CHECK_PARAM(where, "bearing_psd_rad2ps3", check_range(bearing_psd_rad2ps3, T(0), T(1)));
    MPTRACK_CHECK_PARAM(where, "p_stay_active", check_open_probability(p_stay_active));
    MPTRACK_CHECK_PARAM(where, "p_become_active", check_open_probability(p_become_active));
    MPTRACK_CHECK_PARAM(where, "confirm_existence", check_open_probability(confirm_existence));
    MPTRACK_CHECK_PARAM(where, "delete_existence",
                        check(delete_existence >= T(0) && delete_existence < confirm_existence));
    MPTRACK_CHECK_PARAM(where, "hold_existence",
                        check(hold_existence > T(0) && hold_existence <= confirm_existence));
    MPTRACK_CHECK_PARAM(where, "delete_window", check_range(delete_window, 1, 8));
    MPTRACK_CHECK_PARAM(where, "gate_chi2", check_range(gate_chi2, T(1e-3), T(1e4)));
    MPTRACK_CHECK_PARAM(where, "vb_iterations", check_range(vb_iterations, 1, 50));
    MPTRACK_CHECK_PARAM(where, "bp_max_iterations", check_range(bp_max_iterations, 1, 1000));
    MPTRACK_CHECK_PARAM(where, "bp_tolerance", check_range(bp_tolerance, T(0), T(1)));
    MPTRACK_CHECK_PARAM(where, "bp_damping", check_range_below(bp_damping, T(0), T(1)));
    MPTRACK_CHECK_PARAM(where, "group_range_m", check_range(group_range_m, T(0), T(1e7)));
    MPTRACK_CHECK_PARAM(where, "group_range_rate_mps", check_range(group_range_rate_mps, T(0), T(1e5)));
    MPTRACK_CHECK_PARAM(where, "group_azimuth_rad", check_range(group_azimuth_rad, T(0), T(7)));
    MPTRACK_CHECK_PARAM(where, "min_group_size", check_range(min_group_size, 1, num_paths, "num_paths"));
    MPTRACK_CHECK_PARAM(where, "birth_clutter_belief", check_range(birth_clutter_belief, T(0), T(1)));
    MPTRACK_CHECK_PARAM(where, "birth_max_spread", check_range(birth_max_spread, T(0), T(1e6)));
    MPTRACK_CHECK_PARAM(where, "birth_existence_scale",
                        check(birth_existence_scale > T(0) && birth_existence_scale <= T(1)));
    MPTRACK_CHECK_PARAM(where, "birth_distinct_range_m", check_range(birth_distinct_range_m, T(0), T(1e7)));
    MPTRACK_CHECK_PARAM(where, "init_range_rate_std_mps", check_range(init_range_rate_std_mps, T(1e-3), T(1e5)));
    MPTRACK_CHECK_PARAM(where, "init_bearing_rate_std_radps",
                        check_range(init_bearing_rate_std_radps, T(1e-9), T(1)));
    MPTRACK_CHECK_PARAM(where, "max_gap_s", check_range(max_gap_s, T(1e-3), T(1e6)));
    MPTRACK_CHECK_PARAM(where, "min_variance", check_range(min_variance, T(1e-30), T(1)));
    return Status::kOk;
  }
};

}  // namespace mptrack
