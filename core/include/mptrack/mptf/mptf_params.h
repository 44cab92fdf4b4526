// Run-time parameters of the multipath track fusion baseline (MPTF, seed
// 002 Sec. IV; docs/algorithms/mptf.md). Defaults are the paper's OTHR
// scenario: 4 ionospheric paths (E 100 km, F 260 km), baseline 100 km,
// sigma = [5 km, 1 m/s, 3 mrad], Nc = 125, p_d = 0.75, gate p_g = 0.971,
// M/N confirmation 2/2 & 1/3, deletion after 3 scans with nothing in the
// gate (5 at Nc = 400). Values the paper does not give are ours
// (docs/algorithms/mptf.md §Departures from the paper).
//
// Measurement convention: as the multipath MF-BP tracker's
// (docs/algorithms/multipath.md §Measurements): range_m is the slant range,
// doppler_mps the slant range rate, azimuth_rad the azimuth zeta.
#pragma once

#include <array>
#include <cstdint>

#include "mptrack/model/othr_measurement.h"
#include "mptrack/mptf/mptf_caps.h"
#include "mptrack/status.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T>
struct MptfParams {
  // --- propagation paths (seed 002 Sec. IV-A) ---
  std::uint32_t num_paths = 4;  ///< N_P, in [1, Caps::kMaxPaths]
  /// (transmit, receive) virtual heights [km] of paths 0..num_paths-1: EE, EF, FE, FF.
  std::array<model::OthrPath<T>, mptf::kParamPaths> paths{
      {{T(100), T(100)}, {T(100), T(260)}, {T(260), T(100)}, {T(260), T(260)}}};
  T baseline_km = T(100);  ///< receiver-transmitter distance d [km], in [0, 1e4]

  // --- measurement space ---
  PolarRegion<T> region{T(1.5e6), T(2.0e6), T(0.428), T(0.608)};  ///< slant range [m], azimuth [rad]
  T range_rate_span_mps = T(524);  ///< |slant range rate| bound of the region [m/s]
  PolarNoise<T> noise{T(5000), T(0.003), T(1)};  ///< range [m], azimuth [rad], range rate [m/s]
  T clutter_mean_count = T(125);  ///< expected clutter detections per scan (uniform) [-]

  // --- path trackers: PDA on a slant-coordinate CV model ---
  T pd = T(0.75);        ///< detection probability of a path track [-], in (0, 1]
  T gate_chi2 = T(9);    ///< gate on the 3-dof innovation: p_g = 0.971 (seed 002 Sec. IV) [-]
  T range_psd_m2ps3 = T(1e-2);      ///< slant-range white-noise PSD [m^2/s^3] (1e-8 km^2/s^3)
  T azimuth_psd_rad2ps3 = T(1e-8);  ///< azimuth white-noise PSD [rad^2/s^3]
  T init_azimuth_rate_std_radps = T(2e-4);  ///< azimuth-rate std of a new path track [rad/s]

  // --- M/N track logic (seed 002 Sec. IV: 2/2 & 1/3; deletion after 3 or 5 empty gates) ---
  std::uint32_t confirm_m1 = 2;  ///< stage 1: hits needed ...
  std::uint32_t confirm_n1 = 2;  ///< ... in the first n1 scans of a track (birth scan included)
  std::uint32_t confirm_m2 = 1;  ///< stage 2: hits needed ...
  std::uint32_t confirm_n2 = 3;  ///< ... in the next n2 scans (0: confirmed at the end of stage 1)
  std::uint32_t delete_misses = 3;  ///< confirmed track deleted after this many scans with an empty gate

  // --- fusion in ground coordinates ---
  T fusion_gate_chi2 = T(11.34);   ///< 3-dof gate on the ground (g, g_dot, theta) distance (99 %) [-]
  std::uint32_t fuse_min_paths = 2;  ///< path tracks a new fused track needs, in [1, num_paths]
  /// Do not start a fused track while another reading of its path tracks
  /// (other paths) has as much support: fewer ghosts, later tracks
  /// (docs/algorithms/mptf.md §Fusion).
  bool fuse_defer_ambiguous = false;

  // --- gaps, numerics ---
  T max_gap_s = T(120);       ///< a longer gap drops every track (scan_clock.h) [s]
  T min_variance = T(1e-14);  ///< diagonal floor of the last-resort covariance repair [-]

  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "num_paths", check(num_paths >= 1 && num_paths <= mptf::kParamPaths));
    for (std::uint32_t p = 0; p < num_paths; ++p) {
      MPTRACK_CHECK_PARAM(where, "paths", check_range(paths[p].tx_height_km, T(0), T(1e4)));
      MPTRACK_CHECK_PARAM(where, "paths", check_range(paths[p].rx_height_km, T(0), T(1e4)));
    }
    MPTRACK_CHECK_PARAM(where, "baseline_km", check_range(baseline_km, T(0), T(1e4)));
    MPTRACK_TRY(region.validate(where));
    MPTRACK_CHECK_PARAM(where, "region.range_min_m", check(region.range_min_m > T(0)));
    MPTRACK_CHECK_PARAM(where, "range_rate_span_mps", check_range(range_rate_span_mps, T(1e-3), T(1e5)));
    MPTRACK_TRY(noise.validate(where));
    MPTRACK_CHECK_PARAM(where, "clutter_mean_count", check_range(clutter_mean_count, T(1e-3), T(1e5)));
    MPTRACK_CHECK_PARAM(where, "pd", check(pd > T(0) && pd <= T(1)));
    MPTRACK_CHECK_PARAM(where, "gate_chi2", check_range(gate_chi2, T(1e-3), T(1e4)));
    MPTRACK_CHECK_PARAM(where, "range_psd_m2ps3", check_range(range_psd_m2ps3, T(0), T(1e6)));
    MPTRACK_CHECK_PARAM(where, "azimuth_psd_rad2ps3", check_range(azimuth_psd_rad2ps3, T(0), T(1)));
    MPTRACK_CHECK_PARAM(where, "init_azimuth_rate_std_radps",
                        check_range(init_azimuth_rate_std_radps, T(1e-9), T(1)));
    MPTRACK_CHECK_PARAM(where, "confirm_n1", check(confirm_n1 >= 2 && confirm_n1 <= 8));
    MPTRACK_CHECK_PARAM(where, "confirm_m1", check(confirm_m1 >= 1 && confirm_m1 <= confirm_n1));
    MPTRACK_CHECK_PARAM(where, "confirm_n2", check(confirm_n2 <= 8));
    MPTRACK_CHECK_PARAM(where, "confirm_m2", check(confirm_n2 == 0 ? confirm_m2 == 0 || confirm_m2 == 1
                                                                   : confirm_m2 >= 1 && confirm_m2 <= confirm_n2));
    MPTRACK_CHECK_PARAM(where, "delete_misses", check(delete_misses >= 1 && delete_misses <= 64));
    MPTRACK_CHECK_PARAM(where, "fusion_gate_chi2", check_range(fusion_gate_chi2, T(1e-3), T(1e4)));
    MPTRACK_CHECK_PARAM(where, "fuse_min_paths", check(fuse_min_paths >= 1 && fuse_min_paths <= num_paths));
    MPTRACK_CHECK_PARAM(where, "max_gap_s", check_range(max_gap_s, T(1e-3), T(1e6)));
    MPTRACK_CHECK_PARAM(where, "min_variance", check_range(min_variance, T(1e-30), T(1)));
    return Status::kOk;
  }
};

}  // namespace mptrack
