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

  // --- numerics ---
  T min_variance = T(1e-6);  ///< diagonal floor used when a covariance is repaired [m^2 or (m/s)^2]

  /// One check per documented constraint; kInvalidArgument on the first failure.
  Status validate() const {
    MPTRACK_TRY(check_range(accel_std_mps2, T(0), T(1e3)));
    MPTRACK_TRY(check_positive(sigma_range_m));
    MPTRACK_TRY(check_positive(sigma_azimuth_rad));
    MPTRACK_TRY(check_positive(init_velocity_std_mps));
    MPTRACK_TRY(check_positive(gate_chi2));
    MPTRACK_TRY(check(confirm_hits >= 1 && confirm_hits <= confirm_window));
    MPTRACK_TRY(check(confirm_window >= 1 && confirm_window <= 32));
    MPTRACK_TRY(check(max_misses >= 1 && max_misses <= 1000000));
    MPTRACK_TRY(check_range(min_range_m, T(0), max_range_m));
    MPTRACK_TRY(check_positive(max_range_m));
    MPTRACK_TRY(check(max_range_m > min_range_m));
    MPTRACK_TRY(check_range(min_azimuth_rad, -dmath::kPi<T>, dmath::kPi<T>));
    MPTRACK_TRY(check_range(max_azimuth_rad, -dmath::kPi<T>, dmath::kPi<T>));
    MPTRACK_TRY(check(max_azimuth_rad > min_azimuth_rad));
    MPTRACK_TRY(check_positive(min_variance));
    return Status::kOk;
  }
};

}  // namespace mptrack
