// Run-time parameters of the GNN + Kalman detect-then-track baseline
// (seed 004 Sec. V-A; docs/algorithms/gnn.md). Values the paper does not give
// are ours (docs/algorithms/gnn.md §Departures from the paper); units are in
// the names or the comments. The region and noise blocks and the motion
// noise use the names shared by every tracker (tracker_params.h).
// GnnTracker::validate() runs validate() and the caps checks once, in
// init(); nothing is re-checked per scan.
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/status.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T>
struct GnnParams {
  // --- models ---
  /// CV white-acceleration variance q per axis [m^2/s^4] ((2 m/s^2)^2;
  /// docs/algorithms/gnn.md §Departures from the paper), in [0, 1e6].
  T accel_var_m2ps4 = T(4);
  /// Measurement noise; range std 0.2 m is the R floor of
  /// docs/algorithms/gnn.md §Departures from the paper. Doppler is unused.
  PolarNoise<T> noise{T(0.2), T(0.01), T(1)};
  /// Velocity std of a new track, per axis [m/s] (docs/algorithms/gnn.md
  /// §Departures from the paper: 10).
  T init_velocity_std_mps = T(10);

  // --- association ---
  /// Gate on the squared Mahalanobis distance nu^T S^-1 nu [-]:
  /// chi2_2(0.999) = 13.8155 (seed 004 Sec. V-A). Also the cost of leaving
  /// a track unassigned (see gnn_tracker.h, association).
  T gate_chi2 = T(13.8155);

  // --- track management (MATLAB trackerGNN [3 5] / [5 5]) ---
  std::uint32_t confirm_hits = 3;    ///< M: hits needed within the last confirm_window scans [-]
  std::uint32_t confirm_window = 5;  ///< N: window of the M-of-N rule [scans], <= 32
  std::uint32_t max_misses = 5;      ///< delete after this many consecutive misses [scans]
  /// false: outputs hold confirmed tracks only (docs/algorithms/gnn.md §Reporting).
  bool report_tentative = false;

  // --- surveillance region: measurements outside are rejected and counted ---
  PolarRegion<T> region{T(0.5), T(200), -dmath::kPi<T>, dmath::kPi<T>};

  // --- scan gaps (scan_clock.h, docs/reliability.md F1) ---
  /// A scan more than this after the previous one drops every track
  /// (counted in gap_resets) and starts a new run [s], in [1e-3, 1e6].
  T max_gap_s = T(60);

  // --- numerics ---
  T min_variance = T(1e-6);  ///< diagonal floor used when a covariance is repaired [m^2 or (m/s)^2]

  // --- bounds (docs/reliability.md F12) ---
  // Every std is squared, and the azimuth std is multiplied by the range
  // (polar_initiate: (r sigma_az)^2), in float. PolarNoise and PolarRegion
  // keep each variance and each product far from float overflow (3.4e38)
  // and above the denormal range; kMaxStdRatio keeps the position
  // covariance of a new track well conditioned in float (cross-range std
  // <= kMaxStdRatio range std: condition number <= 1e6, float epsilon 6e-8).
  static constexpr T kMaxAccelVar = T(1e6);       ///< accel_var_m2ps4 ceiling [m^2/s^4]
  static constexpr T kMinVelocityStdMps = T(1e-3);  ///< init_velocity_std_mps floor [m/s]
  static constexpr T kMaxVelocityStdMps = T(1e4); ///< init_velocity_std_mps ceiling [m/s]
  static constexpr T kMaxStdRatio = T(1e3);       ///< region.range_max_m azimuth std / range std [-]
  static constexpr T kMaxGateChi2 = T(1e4);       ///< gate_chi2 ceiling [-]
  static constexpr T kMinVarianceFloor = T(1e-12);  ///< min_variance range [m^2] ...
  static constexpr T kMaxVarianceFloor = T(1e2);    ///< ... (default 1e-6)
  static constexpr std::uint32_t kMaxConfirmWindow = 32;  ///< bits of GnnTrack::hit_history

  /// One check per documented constraint; on the first failure names the
  /// field in *where (if given) and returns kInvalidArgument.
  Status validate(ParamError* where = nullptr) const {
    MPTRACK_CHECK_PARAM(where, "accel_var_m2ps4", check_range(accel_var_m2ps4, T(0), kMaxAccelVar));
    MPTRACK_TRY(noise.validate(where));
    MPTRACK_CHECK_PARAM(where, "init_velocity_std_mps",
                        check_range(init_velocity_std_mps, kMinVelocityStdMps, kMaxVelocityStdMps));
    MPTRACK_CHECK_PARAM(where, "gate_chi2", check_positive(gate_chi2));
    MPTRACK_CHECK_PARAM(where, "gate_chi2", check_at_most(gate_chi2, kMaxGateChi2, "kMaxGateChi2"));
    MPTRACK_CHECK_PARAM(where, "confirm_hits", check_range(confirm_hits, 1, confirm_window, "confirm_window"));
    MPTRACK_CHECK_PARAM(where, "confirm_window",
                        check_range(confirm_window, 1, kMaxConfirmWindow, "kMaxConfirmWindow"));
    MPTRACK_CHECK_PARAM(where, "max_misses", check_range(max_misses, 1, 1000000));
    MPTRACK_TRY(region.validate(where));
    MPTRACK_CHECK_PARAM(where, "noise.azimuth_std_rad",
                        check(!(region.range_max_m * noise.azimuth_std_rad >
                                kMaxStdRatio * noise.range_std_m)));
    MPTRACK_CHECK_PARAM(where, "min_variance",
                        check_range(min_variance, kMinVarianceFloor, kMaxVarianceFloor));
    MPTRACK_CHECK_PARAM(where, "max_gap_s", check_range(max_gap_s, T(1e-3), T(1e6)));
    return Status::kOk;
  }
};

}  // namespace mptrack
