// Parameter blocks every tracker's Params shares: one name and one unit per
// quantity across MF-BP, GNN, GM-PHD/CPHD and CBMeMBer.
//
//   region            PolarRegion<T>     surveillance region in (range, azimuth)
//   cartesian_region  CartesianRegion<T> surveillance region in (x, y) (RFS filters,
//                                        MeasurementSpace::kCartesian)
//   noise             PolarNoise<T>      measurement noise standard deviations
//   amplitude         AmplitudeModel<T>  amplitude use, detector threshold, Swerling case
//   clutter_mode      ClutterMode        model/clutter_mode.h
//   accel_var_m2ps4   T                  per-axis white-acceleration variance q
//                                        [m^2/s^4] of the CV model
//                                        (docs/algorithms/models.md §CV motion model)
//   max_gap_s         T                  scan gap that restarts a tracker (scan_clock.h)
//
// Each tracker keeps its own defaults (aggregate initialisers in its Params).
// Each block validates the rules that hold for every tracker and names the
// offending field as "<member>.<field>" (validate.h, ParamError); a tracker's
// Params::validate() adds its own, tighter rules under the same names.
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/model/clutter_mode.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

/// How clutter is modelled (model/clutter_mode.h); member `clutter_mode`.
using ClutterMode = model::ClutterMode;

/// The coordinates a sensor reports measurements in (RFS filters).
enum class MeasurementSpace : std::uint8_t {
  kPolar,      ///< z = (range m, azimuth rad), R = diag(range_std^2, azimuth_std^2)
  kCartesian,  ///< z = (x m, y m), R = cartesian_std^2 I
};

/// Largest |coordinate| or range a region may have [m] (10 000 km): keeps
/// the region volume and every squared coordinate finite in float.
template <class T>
inline constexpr T kMaxRegionCoordM = T(1e7);

/// Surveillance region in measurement coordinates; member `region`.
/// Measurements outside are rejected and counted (measurements_invalid).
template <class T>
struct PolarRegion {
  T range_min_m = T(0);      ///< [m], >= 0
  T range_max_m = T(0);      ///< [m], > range_min_m, <= 1e7
  T azimuth_min_rad = T(0);  ///< [rad], in [-pi, pi]
  T azimuth_max_rad = T(0);  ///< [rad], in [-pi, pi], > azimuth_min_rad

  /// Measurement-space volume (range span x azimuth span) [m rad].
  T volume() const { return (range_max_m - range_min_m) * (azimuth_max_rad - azimuth_min_rad); }

  /// Bounds included; NaN is outside.
  bool contains(T range_m, T azimuth_rad) const {
    return range_m >= range_min_m && range_m <= range_max_m && azimuth_rad >= azimuth_min_rad &&
           azimuth_rad <= azimuth_max_rad;
  }

  /// The shared intake check over this region (model/measurement_validator.h);
  /// the caller adds its amplitude and Doppler rules.
  model::MeasurementValidator<T> validator() const {
    model::MeasurementValidator<T> v;
    v.min0 = range_min_m;
    v.max0 = range_max_m;
    v.min1 = azimuth_min_rad;
    v.max1 = azimuth_max_rad;
    return v;
  }

  Status validate(ParamError* where) const {
    const T pi = dmath::kPi<T>;
    MPTRACK_CHECK_PARAM(where, "region.range_min_m", check_range(range_min_m, T(0), kMaxRegionCoordM<T>));
    MPTRACK_CHECK_PARAM(where, "region.range_max_m", check_range(range_max_m, T(0), kMaxRegionCoordM<T>));
    MPTRACK_CHECK_PARAM(where, "region.range_max_m", check_above(range_max_m, range_min_m, "range_min_m"));
    MPTRACK_CHECK_PARAM(where, "region.azimuth_min_rad", check_range(azimuth_min_rad, -pi, pi));
    MPTRACK_CHECK_PARAM(where, "region.azimuth_max_rad", check_range(azimuth_max_rad, -pi, pi));
    MPTRACK_CHECK_PARAM(where, "region.azimuth_max_rad", check_above(azimuth_max_rad, azimuth_min_rad, "azimuth_min_rad"));
    return Status::kOk;
  }
};

/// Surveillance region of a Cartesian sensor; member `cartesian_region`.
template <class T>
struct CartesianRegion {
  T x_min_m = T(0);  ///< [m], |x| <= 1e7
  T x_max_m = T(0);  ///< [m], > x_min_m
  T y_min_m = T(0);  ///< [m], |y| <= 1e7
  T y_max_m = T(0);  ///< [m], > y_min_m

  /// Area [m^2].
  T volume() const { return (x_max_m - x_min_m) * (y_max_m - y_min_m); }

  /// Bounds included; NaN is outside.
  bool contains(T x_m, T y_m) const {
    return x_m >= x_min_m && x_m <= x_max_m && y_m >= y_min_m && y_m <= y_max_m;
  }

  Status validate(ParamError* where) const {
    const T c = kMaxRegionCoordM<T>;
    MPTRACK_CHECK_PARAM(where, "cartesian_region.x_min_m", check_range(x_min_m, -c, c));
    MPTRACK_CHECK_PARAM(where, "cartesian_region.x_max_m", check_range(x_max_m, -c, c));
    MPTRACK_CHECK_PARAM(where, "cartesian_region.x_max_m", check_above(x_max_m, x_min_m, "x_min_m"));
    MPTRACK_CHECK_PARAM(where, "cartesian_region.y_min_m", check_range(y_min_m, -c, c));
    MPTRACK_CHECK_PARAM(where, "cartesian_region.y_max_m", check_range(y_max_m, -c, c));
    MPTRACK_CHECK_PARAM(where, "cartesian_region.y_max_m", check_above(y_max_m, y_min_m, "y_min_m"));
    return Status::kOk;
  }
};

/// Measurement noise standard deviations of a polar sensor; member `noise`.
/// The bounds keep each variance (std squared in float) and the cross-range
/// variance (range x azimuth std)^2 finite and normal (docs/reliability.md F12).
template <class T>
struct PolarNoise {
  T range_std_m = T(1);      ///< [m], in [1e-3, 1e5]
  T azimuth_std_rad = T(0.01);  ///< [rad], in [1e-6, 1]
  T doppler_std_mps = T(1);  ///< radial velocity [m/s], in [1e-3, 1e4] (trackers using Doppler)

  static constexpr T kMinRangeStdM = T(1e-3);
  static constexpr T kMaxRangeStdM = T(1e5);
  static constexpr T kMinAzimuthStdRad = T(1e-6);
  static constexpr T kMaxAzimuthStdRad = T(1);
  static constexpr T kMinDopplerStdMps = T(1e-3);
  static constexpr T kMaxDopplerStdMps = T(1e4);

  Status validate(ParamError* where) const {
    MPTRACK_CHECK_PARAM(where, "noise.range_std_m",
                        check_range(range_std_m, kMinRangeStdM, kMaxRangeStdM));
    MPTRACK_CHECK_PARAM(where, "noise.azimuth_std_rad",
                        check_range(azimuth_std_rad, kMinAzimuthStdRad, kMaxAzimuthStdRad));
    MPTRACK_CHECK_PARAM(where, "noise.doppler_std_mps",
                        check_range(doppler_std_mps, kMinDopplerStdMps, kMaxDopplerStdMps));
    return Status::kOk;
  }
};

/// The amplitude model of the detections (normalised envelope, measurement.h;
/// docs/algorithms/models.md §Detection probability); member `amplitude`.
template <class T>
struct AmplitudeModel {
  bool use_amplitude = true;  ///< false: kinematics only (amplitudes must only be > 0)
  T threshold = T(1);         ///< detector threshold d on the normalised envelope [-], (0, 1e3]
  /// Amplitudes above this are invalid (measurements_invalid): m^2 and the
  /// amplitude moments must stay finite in float (docs/reliability.md F4) [-].
  T max_amplitude = T(1e4);
  int swerling = 1;  ///< Swerling case of the targets: 1 or 3

  static constexpr T kMaxThreshold = T(1e3);
  static constexpr T kMaxAmplitude = T(1e15);

  /// n, the order of the Gamma power law: 1 (Swerling I) or 2 (Swerling III).
  int order() const { return swerling == 3 ? 2 : 1; }

  Status validate(ParamError* where) const {
    MPTRACK_CHECK_PARAM(where, "amplitude.threshold", check_positive(threshold));
    MPTRACK_CHECK_PARAM(where, "amplitude.threshold", check_at_most(threshold, kMaxThreshold, "AmplitudeModel::kMaxThreshold"));
    MPTRACK_CHECK_PARAM(where, "amplitude.max_amplitude",
                        check_range_above(max_amplitude, threshold, kMaxAmplitude, "threshold, kMaxAmplitude"));
    MPTRACK_CHECK_PARAM(where, "amplitude.swerling", check(swerling == 1 || swerling == 3));
    return Status::kOk;
  }
};

}  // namespace mptrack
