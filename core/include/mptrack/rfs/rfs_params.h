// Run-time parameters of the IGGM baselines (GM-PHD, GM-CPHD, CBMeMBer;
// seed 001). One struct for the three filters: they share the models, the
// clutter estimator, births and mixture management. Units in every comment;
// defaults are seed 001 section 6 where the paper gives a value, [impl]
// otherwise. validate() is called once by each filter's init().
#pragma once

#include <cstdint>

#include "mptrack/model/clutter_mode.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/rfs/measurement_model.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::rfs {

/// How clutter is handled (model/clutter_mode.h). The IGGM filters
/// implement kEstimatedMap (default), kEstimatedUniform and kKnownUniform.
using ClutterMode = model::ClutterMode;

template <class T>
struct FilterParams {
  // --- sensor ---
  MeasurementSpace space = MeasurementSpace::kCartesian;
  T sigma_r_m = T(10);           ///< polar range noise std [m] (Cartesian: x/y noise std [m])
  T sigma_az_rad = T(0.0104720); ///< polar azimuth noise std [rad]; unused for Cartesian
  T region_min0 = T(-1000);      ///< region, first coordinate: range [m] or x [m]
  T region_max0 = T(1000);
  T region_min1 = T(-1000);      ///< region, second coordinate: azimuth [rad] or y [m]
  T region_max1 = T(1000);
  T scan_period_s = T(1);        ///< nominal T [s]; the real dt comes from time_us
  /// A scan more than this after the previous one drops the whole target
  /// mixture and the pending births (counted in gap_resets) and starts a
  /// new run; the clutter estimate is kept (scan_clock.h, F1) [s], in [1e-3, 1e6].
  T max_gap_s = T(60);

  // --- targets ---
  T accel_std_mps2 = T(5);       ///< CV white-acceleration std sigma_nu [m/s^2] (spec 1.1)
  T survival_prob = T(0.99);     ///< p_S^t (spec 1.1)
  T birth_rate = T(0.2);         ///< expected births per scan, spread over last scan's measurements [-]
  T birth_velocity_std_mps = T(30);  ///< velocity std of a birth component [m/s] [impl]

  // --- amplitude ---
  bool use_amplitude = true;     ///< false: kinematics-only variant (amplitude ignored)
  T threshold = T(1.5174);       ///< amplitude threshold d, normalised [-] (seed 001: 2.146/sqrt(2))
  int swerling_order = 1;        ///< n: 1 (Swerling I) or 2 (Swerling III)
  T target_power_prior = T(101); ///< prior mean of varsigma = 1 + SNR at birth [-]
  T target_alpha_prior = T(3);   ///< prior IG shape at birth (spec 9, item 4) [-]
  T power_forgetting = T(1.1);   ///< v of spec 1.3, targets and clutter [-] (> 1)
  T min_alpha = T(2.01);         ///< shape clamp (spec 1.3 [impl]) [-]
  T max_alpha = T(1e4);          ///< cap after merges [-]
  T detection_prob = T(0.9775);  ///< P_D when use_amplitude = false [-]
  /// Amplitude ceiling [-] (docs/reliability.md F4): a measurement with a
  /// larger normalised amplitude is rejected and counted in
  /// measurements_invalid, as is one whose clutter term a^(2b) exceeds
  /// kMaxAmplitudeTerm. 1e4 is 80 dB above the noise floor, beyond any
  /// unsaturated receiver; the ceiling keeps the amplitude moments
  /// (a^2, a^(2b), summed with forgetting) finite in float.
  T max_amplitude = T(1e4);

  // --- clutter ---
  ClutterMode clutter_mode = ClutterMode::kEstimatedMap;
  T clutter_rate = T(40);        ///< known (or prior) clutter detections per scan [-]
  T weibull_shape = T(1);        ///< b of the clutter amplitude (1 = Rayleigh) [-]
  T clutter_scale = T(1);        ///< known (or prior) Weibull scale sigma0, normalised [-]
  T clutter_forgetting = T(1.1); ///< forgetting of clutter rate/moment statistics [-] (> 1)
  T clutter_alpha_prior = T(3);  ///< prior IG shape of a clutter power [-]
  T hotspot_half_width0 = T(30); ///< hot-spot seed box half-width, coordinate 0 [m]
  T hotspot_half_width1 = T(30); ///< ... coordinate 1 [rad (polar) or m]
  int hotspot_min_points = 5;    ///< measurements in one box needed to seed a source [-]
  T hotspot_min_rate = T(0.5);   ///< a source whose rate falls below this is deleted [1/scan]

  // --- mixture management (spec 5.5) ---
  T prune_threshold = T(1e-5);   ///< drop components below this weight [-]
  T merge_threshold = T(4);      ///< Mahalanobis^2 merge gate on the kinematics, U [-]
  T merge_threshold_power = T(4);///< symmetric-KL merge gate on the IG part, U_sigma [-]
  T gate_probability = T(0.9999);///< kinematic gate; d^2 gate = -2 ln(1 - p) for 2 dof [-]
  T extract_threshold = T(0.5);  ///< PHD: report components with weight above this [-]

  // --- CBMeMBer ---
  T existence_prune = T(1e-3);   ///< drop Bernoulli components with r below this [-]
  T existence_extract = T(0.5);  ///< report tracks with r above this [-]

  // --- bounds (docs/reliability.md F10, F12) ---
  // Each std is squared, and polar azimuth std is multiplied by the range
  // (position_of: (r sigma_az)^2), in float; the region volume divides the
  // clutter rate. The bounds keep these, and the derived clutter intensity
  // rate / V, finite and normal in float, and a polar covariance of
  // condition number <= kMaxStdRatio^2 = 1e6 (float epsilon 6e-8).
  static constexpr T kMaxCoordM = T(1e7);       ///< |region bound| in metres [m] (10 000 km)
  static constexpr T kMaxAzimuthRad = T(6.2831853);  ///< |polar azimuth bound| [rad] (2 pi)
  static constexpr T kMinStdM = T(1e-3);        ///< sigma_r_m floor [m]
  static constexpr T kMaxStdM = T(1e5);         ///< sigma_r_m ceiling [m]
  static constexpr T kMinStdRad = T(1e-6);      ///< polar sigma_az_rad floor [rad]
  static constexpr T kMaxStdRad = T(1);         ///< polar sigma_az_rad ceiling [rad]
  static constexpr T kMaxStdRatio = T(1e3);     ///< polar: region_max0 sigma_az / sigma_r [-]
  static constexpr T kMinVolume = T(1e-6);      ///< region volume floor [m rad | m^2]
  static constexpr T kMaxVelocityStdMps = T(1e4);  ///< birth velocity std ceiling [m/s] (floor 1e-3)
  static constexpr T kMaxRate = T(1e6);         ///< rates and counts ceiling [1/scan]
  static constexpr T kMaxPower = T(1e12);       ///< power / scale / shape-prior ceiling [-]
  static constexpr T kMaxAmplitudeTerm = T(1e20);  ///< a^(2b) ceiling [-] (see max_amplitude)

  /// kInvalidArgument on any out-of-range field.
  Status validate() const {
    MPTRACK_TRY(check(space == MeasurementSpace::kPolar || space == MeasurementSpace::kCartesian));
    MPTRACK_TRY(check_range(sigma_r_m, kMinStdM, kMaxStdM));
    if (space == MeasurementSpace::kPolar) {
      MPTRACK_TRY(check_range(sigma_az_rad, kMinStdRad, kMaxStdRad));
    } else {
      MPTRACK_TRY(check_positive(sigma_az_rad));  // unused
    }
    MPTRACK_TRY(check(region_max0 > region_min0 && region_max1 > region_min1));
    MPTRACK_TRY(check_range(region_min0, -kMaxCoordM, kMaxCoordM));
    MPTRACK_TRY(check_range(region_max0, -kMaxCoordM, kMaxCoordM));
    if (space == MeasurementSpace::kPolar) {
      MPTRACK_TRY(check(!(region_min0 < T(0))));  // a range
      MPTRACK_TRY(check_range(region_min1, -kMaxAzimuthRad, kMaxAzimuthRad));
      MPTRACK_TRY(check_range(region_max1, -kMaxAzimuthRad, kMaxAzimuthRad));
      MPTRACK_TRY(check(!(region_max0 * sigma_az_rad > kMaxStdRatio * sigma_r_m)));
    } else {
      MPTRACK_TRY(check_range(region_min1, -kMaxCoordM, kMaxCoordM));
      MPTRACK_TRY(check_range(region_max1, -kMaxCoordM, kMaxCoordM));
    }
    MPTRACK_TRY(check(region_volume() >= kMinVolume && is_finite(region_volume())));
    MPTRACK_TRY(check_positive(scan_period_s));
    MPTRACK_TRY(check(!(scan_period_s > T(3600))));
    MPTRACK_TRY(check_range(max_gap_s, T(1e-3), T(1e6)));
    MPTRACK_TRY(check_positive(accel_std_mps2));
    MPTRACK_TRY(check(!(accel_std_mps2 > T(1e3))));
    MPTRACK_TRY(check_open_probability(survival_prob));
    MPTRACK_TRY(check_range(birth_rate, T(1e-6), kMaxRate));
    MPTRACK_TRY(check_range(birth_velocity_std_mps, T(1e-3), kMaxVelocityStdMps));
    MPTRACK_TRY(check_positive(threshold));
    MPTRACK_TRY(check(max_amplitude > threshold && !(max_amplitude > T(1e6))));
    MPTRACK_TRY(check(swerling_order == 1 || swerling_order == 2));
    MPTRACK_TRY(check(target_power_prior > T(1) && !(target_power_prior > kMaxPower)));
    MPTRACK_TRY(check(target_alpha_prior > T(1) && !(target_alpha_prior > kMaxPower)));
    MPTRACK_TRY(check(power_forgetting > T(1) && power_forgetting < T(10)));
    MPTRACK_TRY(check_range(min_alpha, T(1.001), T(100)));
    MPTRACK_TRY(check(max_alpha > min_alpha && !(max_alpha > kMaxPower)));
    MPTRACK_TRY(check_open_probability(detection_prob));
    MPTRACK_TRY(check(clutter_mode == ClutterMode::kEstimatedMap ||
                      clutter_mode == ClutterMode::kEstimatedUniform ||
                      clutter_mode == ClutterMode::kKnownUniform));
    MPTRACK_TRY(check_range(clutter_rate, T(1e-6), kMaxRate));
    MPTRACK_TRY(check_range(weibull_shape, T(0.1), T(5)));
    MPTRACK_TRY(check_range(clutter_scale, T(1e-6), kMaxPower));
    MPTRACK_TRY(check(clutter_forgetting > T(1) && clutter_forgetting < T(10)));
    MPTRACK_TRY(check(clutter_alpha_prior > T(1) && !(clutter_alpha_prior > kMaxPower)));
    MPTRACK_TRY(check(hotspot_half_width0 > T(0) && !(hotspot_half_width0 > kMaxCoordM)));
    MPTRACK_TRY(check(hotspot_half_width1 > T(0) && !(hotspot_half_width1 > kMaxCoordM)));
    MPTRACK_TRY(check(hotspot_min_points >= 2 && hotspot_min_points <= 1000));
    MPTRACK_TRY(check(hotspot_min_rate > T(0) && !(hotspot_min_rate > kMaxRate)));
    MPTRACK_TRY(check_open_probability(prune_threshold));
    MPTRACK_TRY(check(merge_threshold > T(0) && !(merge_threshold > kMaxRate)));
    MPTRACK_TRY(check(merge_threshold_power > T(0) && !(merge_threshold_power > kMaxRate)));
    MPTRACK_TRY(check_open_probability(gate_probability));
    MPTRACK_TRY(check_open_probability(extract_threshold));
    MPTRACK_TRY(check_open_probability(existence_prune));
    MPTRACK_TRY(check_open_probability(existence_extract));
    return Status::kOk;
  }

  /// Measurement model built from the sensor fields.
  MeasurementModel<T> measurement_model() const {
    MeasurementModel<T> mm;
    mm.space = space;
    mm.R.setZero();
    if (space == MeasurementSpace::kPolar) {
      mm.R(0, 0) = sigma_r_m * sigma_r_m;
      mm.R(1, 1) = sigma_az_rad * sigma_az_rad;
    } else {
      mm.R(0, 0) = sigma_r_m * sigma_r_m;
      mm.R(1, 1) = sigma_r_m * sigma_r_m;
    }
    return mm;
  }

  /// The intake check (model/measurement_validator.h) over the region in
  /// measurement coordinates; amplitude thresholded when it is used.
  model::MeasurementValidator<T> validator() const {
    model::MeasurementValidator<T> v;
    v.min0 = region_min0;
    v.max0 = region_max0;
    v.min1 = region_min1;
    v.max1 = region_max1;
    v.amplitude = use_amplitude ? model::AmplitudeRule::kThresholded : model::AmplitudeRule::kPositive;
    v.threshold = threshold;
    v.max_amplitude = max_amplitude;
    return v;
  }

  /// Measurement-space volume of the region [m rad | m^2].
  T region_volume() const { return (region_max0 - region_min0) * (region_max1 - region_min1); }
};

}  // namespace mptrack::rfs
