// Run-time parameters of the GNN + Kalman detect-then-track baseline
// (seed 004 spec 2.5). Defaults are the spec's [R] values where it gives
// them; units are in the names or the comments. validate() is what
// GnnTracker::init() runs once; nothing is re-checked per scan.
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T>
struct GnnParams {
  // --- models ---
  T accel_std_mps2 = T(2);          ///< CV white-acceleration std per axis [m/s^2] (spec 2.5: 2)
  T sigma_range_m = T(0.2);         ///< range noise std [m] (spec 2.5: R floor 0.2 m)
  T sigma_azimuth_rad = T(0.01);    ///< azimuth noise std [rad]
  T init_velocity_std_mps = T(10);  ///< velocity std of a new track, per axis [m/s] (spec 2.5: 10)

  // --- association ---
  /// Gate on the squared Mahalanobis distance nu^T S^-1 nu [-]:
  /// chi2_2(0.999) = 13.8155 (spec 2.5). Also the cost of leaving a track
  /// unassigned (see gnn_tracker.h, association).
  T gate_chi2 = T(13.8155);

  // --- track management (spec 2.5: trackerGNN [3 5] / [5 5]) ---
  std::uint32_t confirm_hits = 3;    ///< M: hits needed within the last confirm_window scans [-]
  std::uint32_t confirm_window = 5;  ///< N: window of the M-of-N rule [scans], <= 32
  std::uint32_t max_misses = 5;      ///< delete after this many consecutive misses [scans]
  bool report_tentative = false;     ///< false: outputs hold confirmed tracks only (spec 2.5)

  // --- surveillance region: measurements outside are rejected and counted ---
  T min_range_m = T(0.5);                    ///< [m], >= 0
  T max_range_m = T(200);                    ///< [m], > min_range_m
  T min_azimuth_rad = -dmath::kPi<T>;        ///< [rad], >= -pi
  T max_azimuth_rad = dmath::kPi<T>;         ///< [rad], <= pi, > min_azimuth_rad

  // --- scan gaps (scan_clock.h, docs/reliability.md F1) ---
  /// A scan more than this after the previous one drops every track
  /// (counted in gap_resets) and starts a new run [s], in [1e-3, 1e6].
  T max_gap_s = T(60);

  // --- numerics ---
  T min_variance = T(1e-6);  ///< diagonal floor used when a covariance is repaired [m^2 or (m/s)^2]

  // --- bounds (docs/reliability.md F12) ---
  // Every std below is squared, and the azimuth std is multiplied by the
  // range (polar_initiate: (r sigma_az)^2), in float. The bounds keep each
  // variance and each product far from float overflow (3.4e38) and above
  // the denormal range, and keep the position covariance of a new track
  // well conditioned in float (cross-range std <= kMaxStdRatio range std:
  // condition number <= 1e6, float epsilon 6e-8).
  static constexpr T kMaxRangeM = T(1e7);         ///< max_range_m ceiling [m] (10 000 km)
  static constexpr T kMinStdM = T(1e-3);          ///< sigma_range_m floor [m]
  static constexpr T kMaxStdM = T(1e4);           ///< sigma_range_m ceiling [m]
  static constexpr T kMinStdRad = T(1e-6);        ///< sigma_azimuth_rad floor [rad]
  static constexpr T kMaxStdRad = T(1);           ///< sigma_azimuth_rad ceiling [rad]
  static constexpr T kMinVelocityStdMps = T(1e-3);  ///< init_velocity_std_mps floor [m/s]
  static constexpr T kMaxVelocityStdMps = T(1e4); ///< init_velocity_std_mps ceiling [m/s]
  static constexpr T kMaxStdRatio = T(1e3);       ///< max_range_m sigma_az / sigma_range [-]
  static constexpr T kMaxGateChi2 = T(1e4);       ///< gate_chi2 ceiling [-]
  static constexpr T kMinVarianceFloor = T(1e-12);  ///< min_variance range [m^2] ...
  static constexpr T kMaxVarianceFloor = T(1e2);    ///< ... (default 1e-6)

  /// One check per documented constraint; kInvalidArgument on the first failure.
  Status validate() const {
    MPTRACK_TRY(check_range(accel_std_mps2, T(0), T(1e3)));
    MPTRACK_TRY(check_range(sigma_range_m, kMinStdM, kMaxStdM));
    MPTRACK_TRY(check_range(sigma_azimuth_rad, kMinStdRad, kMaxStdRad));
    MPTRACK_TRY(check_range(init_velocity_std_mps, kMinVelocityStdMps, kMaxVelocityStdMps));
    MPTRACK_TRY(check_positive(gate_chi2));
    MPTRACK_TRY(check(!(gate_chi2 > kMaxGateChi2)));
    MPTRACK_TRY(check(confirm_hits >= 1 && confirm_hits <= confirm_window));
    MPTRACK_TRY(check(confirm_window >= 1 && confirm_window <= 32));
    MPTRACK_TRY(check(max_misses >= 1 && max_misses <= 1000000));
    MPTRACK_TRY(check_range(min_range_m, T(0), max_range_m));
    MPTRACK_TRY(check_positive(max_range_m));
    MPTRACK_TRY(check(!(max_range_m > kMaxRangeM)));
    MPTRACK_TRY(check(max_range_m > min_range_m));
    MPTRACK_TRY(check(!(max_range_m * sigma_azimuth_rad > kMaxStdRatio * sigma_range_m)));
    MPTRACK_TRY(check_range(min_azimuth_rad, -dmath::kPi<T>, dmath::kPi<T>));
    MPTRACK_TRY(check_range(max_azimuth_rad, -dmath::kPi<T>, dmath::kPi<T>));
    MPTRACK_TRY(check(max_azimuth_rad > min_azimuth_rad));
    MPTRACK_TRY(check_range(min_variance, kMinVarianceFloor, kMaxVarianceFloor));
    MPTRACK_TRY(check_range(max_gap_s, T(1e-3), T(1e6)));
    return Status::kOk;
  }
};

}  // namespace mptrack
