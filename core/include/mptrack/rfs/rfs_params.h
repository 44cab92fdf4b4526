// Run-time parameters of the IGGM baselines (GM-PHD, GM-CPHD, CBMeMBer;
// seed 001). One struct for the three filters: they share the models, the
// clutter estimator, births and mixture management. Units in every comment;
// defaults are seed 001 Sec. 5 where the paper gives a value, ours
// otherwise (docs/algorithms/gm-phd.md §Departures from the paper). The
// region, noise and amplitude blocks, accel_var_m2ps4, clutter_mode and
// max_gap_s use the names shared by every tracker (tracker_params.h).
// Each filter's static validate() runs validate() once, in init().
#pragma once

#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/model/measurement_validator.h"
#include "mptrack/rfs/measurement_model.h"
#include "mptrack/status.h"
#include "mptrack/tracker_params.h"
#include "mptrack/validate.h"

namespace mptrack {

/// Parameters of GmPhdFilter, GmCphdFilter and CbMemberFilter. Clutter
/// modes implemented: kEstimatedMap (default), kEstimatedUniform and
/// kKnownUniform (model/clutter_mode.h).
template <class T>
struct RfsFilterParams {
  // --- sensor ---
  /// Polar: (range, azimuth) measurements, region and noise below.
  /// Cartesian: (x, y) measurements, cartesian_region and cartesian_std_m.
  MeasurementSpace space = MeasurementSpace::kCartesian;
  PolarRegion<T> region{T(0), T(1000), -dmath::kPi<T>, dmath::kPi<T>};  ///< kPolar only
  PolarNoise<T> noise{T(10), T(0.0104720), T(1)};  ///< kPolar only; Doppler unused
  CartesianRegion<T> cartesian_region{T(-1000), T(1000), T(-1000), T(1000)};  ///< kCartesian only
  T cartesian_std_m = T(10);     ///< x and y noise std [m], kCartesian only, in [1e-3, 1e5]
  T scan_period_s = T(1);        ///< nominal T [s]; the real dt comes from time_us
  /// A scan more than this after the previous one drops the whole target
  /// mixture and the pending births (counted in gap_resets) and starts a
  /// new run; the clutter estimate is kept (scan_clock.h, F1) [s], in [1e-3, 1e6].
  T max_gap_s = T(60);

  // --- targets ---
  /// CV white-acceleration variance q = sigma_nu^2 per axis [m^2/s^4]
  /// (seed 001 Sec. 5: sigma_nu = 5 m/s^2; docs/algorithms/models.md §CV motion model).
  T accel_var_m2ps4 = T(25);
  T survival_prob = T(0.99);     ///< p_S^t (seed 001 Sec. 5)
  T birth_rate = T(0.2);         ///< expected births per scan, spread over last scan's measurements [-]
  /// Velocity std of a birth component [m/s] (our choice:
  /// docs/algorithms/gm-phd.md §Departures from the paper).
  T birth_velocity_std_mps = T(30);

  // --- amplitude ---
  /// use_amplitude false: kinematics-only variant (amplitude ignored);
  /// threshold d normalised (seed 001: 2.146/sqrt(2)); Swerling I.
  /// max_amplitude (docs/reliability.md F4): a measurement with a larger
  /// normalised amplitude is rejected and counted in measurements_invalid,
  /// as is one whose clutter term a^(2b) exceeds kMaxAmplitudeTerm. 1e4 is
  /// 80 dB above the noise floor, beyond any unsaturated receiver; the
  /// ceiling keeps the amplitude moments (a^2, a^(2b), summed with
  /// forgetting) finite in float.
  AmplitudeModel<T> amplitude{true, T(1.5174), T(1e4), 1};
  T target_power_prior = T(101); ///< prior mean of varsigma = 1 + SNR at birth [-]
  T target_alpha_prior = T(3);   ///< prior IG shape at birth (docs/algorithms/gm-phd.md §Births) [-]
  T power_forgetting = T(1.1);   ///< v of seed 001 eq. (50), targets and clutter [-] (> 1)
  T min_alpha = T(2.01);         ///< shape clamp (docs/algorithms/models.md §Inverse-gamma power belief) [-]
  T max_alpha = T(1e4);          ///< cap after merges [-]
  T detection_prob = T(0.9775);  ///< P_D when amplitude.use_amplitude = false [-]

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

  // --- mixture management (docs/algorithms/gm-phd.md §Mixture reduction) ---
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
  // clutter rate. The bounds (these and the blocks' in tracker_params.h)
  // keep these, and the derived clutter intensity rate / V, finite and
  // normal in float, and a polar covariance of condition number
  // <= kMaxStdRatio^2 = 1e6 (float epsilon 6e-8).
  static constexpr T kMaxCoordM = kMaxRegionCoordM<T>;  ///< |region bound| in metres [m]
  static constexpr T kMinStdM = T(1e-3);        ///< cartesian_std_m floor [m]
  static constexpr T kMaxStdM = T(1e5);         ///< cartesian_std_m ceiling [m]
  static constexpr T kMaxStdRatio = T(1e3);     ///< polar: region.range_max_m azimuth std / range std [-]
  static constexpr T kMinVolume = T(1e-6);      ///< region volume floor [m rad | m^2]
  static constexpr T kMaxAccelVar = T(1e6);     ///< accel_var_m2ps4 ceiling [m^2/s^4]
  static constexpr T kMaxVelocityStdMps = T(1e4);  ///< birth velocity std ceiling [m/s] (floor 1e-3)
  static constexpr T kMaxRate = T(1e6);         ///< rates and counts ceiling [1/scan]
  static constexpr T kMaxPower = T(1e12);       ///< power / scale / shape-prior ceiling [-]
  static constexpr T kMaxAmplitude = T(1e6);    ///< amplitude.max_amplitude ceiling [-]
  static constexpr T kMaxAmplitudeTerm = T(1e20);  ///< a^(2b) ceiling [-] (see amplitude)

  /// On the first out-of-range field names it in *where (if given) and
  /// returns kInvalidArgument.
  Status validate(ParamError* where = nullptr) const {
    ParamError* w = where;
    MPTRACK_TRY(validate_sensor(w));
    MPTRACK_CHECK_PARAM(w, "scan_period_s", check_positive(scan_period_s));
    MPTRACK_CHECK_PARAM(w, "scan_period_s", check_at_most(scan_period_s, T(3600)));
    MPTRACK_CHECK_PARAM(w, "max_gap_s", check_range(max_gap_s, T(1e-3), T(1e6)));
    MPTRACK_CHECK_PARAM(w, "accel_var_m2ps4", check_positive(accel_var_m2ps4));
    MPTRACK_CHECK_PARAM(w, "accel_var_m2ps4", check_at_most(accel_var_m2ps4, kMaxAccelVar, "kMaxAccelVar"));
    MPTRACK_CHECK_PARAM(w, "survival_prob", check_open_probability(survival_prob));
    MPTRACK_CHECK_PARAM(w, "birth_rate", check_range(birth_rate, T(1e-6), kMaxRate));
    MPTRACK_CHECK_PARAM(w, "birth_velocity_std_mps",
                        check_range(birth_velocity_std_mps, T(1e-3), kMaxVelocityStdMps));
    MPTRACK_TRY(amplitude.validate(w));
    MPTRACK_CHECK_PARAM(w, "amplitude.max_amplitude", check_at_most(amplitude.max_amplitude, kMaxAmplitude, "kMaxAmplitude"));
    MPTRACK_CHECK_PARAM(w, "target_power_prior",
                        check(target_power_prior > T(1) && !(target_power_prior > kMaxPower)));
    MPTRACK_CHECK_PARAM(w, "target_alpha_prior",
                        check(target_alpha_prior > T(1) && !(target_alpha_prior > kMaxPower)));
    MPTRACK_CHECK_PARAM(w, "power_forgetting", check(power_forgetting > T(1) && power_forgetting < T(10)));
    MPTRACK_CHECK_PARAM(w, "min_alpha", check_range(min_alpha, T(1.001), T(100)));
    MPTRACK_CHECK_PARAM(w, "max_alpha", check(max_alpha > min_alpha && !(max_alpha > kMaxPower)));
    MPTRACK_CHECK_PARAM(w, "detection_prob", check_open_probability(detection_prob));
    MPTRACK_TRY(validate_clutter(w));
    MPTRACK_CHECK_PARAM(w, "prune_threshold", check_open_probability(prune_threshold));
    MPTRACK_CHECK_PARAM(w, "merge_threshold", check_range_above(merge_threshold, T(0), kMaxRate));
    MPTRACK_CHECK_PARAM(w, "merge_threshold_power",
                        check_range_above(merge_threshold_power, T(0), kMaxRate));
    MPTRACK_CHECK_PARAM(w, "gate_probability", check_open_probability(gate_probability));
    MPTRACK_CHECK_PARAM(w, "extract_threshold", check_open_probability(extract_threshold));
    MPTRACK_CHECK_PARAM(w, "existence_prune", check_open_probability(existence_prune));
    MPTRACK_CHECK_PARAM(w, "existence_extract", check_open_probability(existence_extract));
    return Status::kOk;
  }

  /// Measurement model built from the sensor fields.
  rfs::MeasurementModel<T> measurement_model() const {
    rfs::MeasurementModel<T> mm;
    mm.space = space;
    mm.R.setZero();
    if (space == MeasurementSpace::kPolar) {
      mm.R(0, 0) = noise.range_std_m * noise.range_std_m;
      mm.R(1, 1) = noise.azimuth_std_rad * noise.azimuth_std_rad;
    } else {
      mm.R(0, 0) = cartesian_std_m * cartesian_std_m;
      mm.R(1, 1) = cartesian_std_m * cartesian_std_m;
    }
    return mm;
  }

  /// The intake check (model/measurement_validator.h) over the region in
  /// measurement coordinates; amplitude thresholded when it is used.
  model::MeasurementValidator<T> validator() const {
    model::MeasurementValidator<T> v;
    if (space == MeasurementSpace::kPolar) {
      v = region.validator();
    } else {
      v.min0 = cartesian_region.x_min_m;
      v.max0 = cartesian_region.x_max_m;
      v.min1 = cartesian_region.y_min_m;
      v.max1 = cartesian_region.y_max_m;
    }
    v.amplitude = amplitude.use_amplitude ? model::AmplitudeRule::kThresholded : model::AmplitudeRule::kPositive;
    v.threshold = amplitude.threshold;
    v.max_amplitude = amplitude.max_amplitude;
    return v;
  }

  /// Measurement-space volume of the active region [m rad | m^2].
  T region_volume() const {
    return space == MeasurementSpace::kPolar ? region.volume() : cartesian_region.volume();
  }

 private:
  /// The active space's region and noise.
  Status validate_sensor(ParamError* w) const {
    MPTRACK_CHECK_PARAM(w, "space", check(space == MeasurementSpace::kPolar ||
                                          space == MeasurementSpace::kCartesian));
    if (space == MeasurementSpace::kPolar) {
      MPTRACK_TRY(noise.validate(w));
      MPTRACK_TRY(region.validate(w));
      MPTRACK_CHECK_PARAM(w, "noise.azimuth_std_rad",
                          check(!(region.range_max_m * noise.azimuth_std_rad >
                                  kMaxStdRatio * noise.range_std_m)));
      MPTRACK_CHECK_PARAM(w, "region", check(region_volume() >= kMinVolume && is_finite(region_volume())));
    } else {
      MPTRACK_CHECK_PARAM(w, "cartesian_std_m", check_range(cartesian_std_m, kMinStdM, kMaxStdM));
      MPTRACK_TRY(cartesian_region.validate(w));
      MPTRACK_CHECK_PARAM(w, "cartesian_region",
                          check(region_volume() >= kMinVolume && is_finite(region_volume())));
    }
    return Status::kOk;
  }

  Status validate_clutter(ParamError* w) const {
    MPTRACK_CHECK_PARAM(w, "clutter_mode", check(clutter_mode == ClutterMode::kEstimatedMap ||
                                                 clutter_mode == ClutterMode::kEstimatedUniform ||
                                                 clutter_mode == ClutterMode::kKnownUniform));
    MPTRACK_CHECK_PARAM(w, "clutter_rate", check_range(clutter_rate, T(1e-6), kMaxRate));
    MPTRACK_CHECK_PARAM(w, "weibull_shape", check_range(weibull_shape, T(0.1), T(5)));
    MPTRACK_CHECK_PARAM(w, "clutter_scale", check_range(clutter_scale, T(1e-6), kMaxPower));
    MPTRACK_CHECK_PARAM(w, "clutter_forgetting",
                        check(clutter_forgetting > T(1) && clutter_forgetting < T(10)));
    MPTRACK_CHECK_PARAM(w, "clutter_alpha_prior",
                        check(clutter_alpha_prior > T(1) && !(clutter_alpha_prior > kMaxPower)));
    MPTRACK_CHECK_PARAM(w, "hotspot_half_width0",
                        check_range_above(hotspot_half_width0, T(0), kMaxCoordM));
    MPTRACK_CHECK_PARAM(w, "hotspot_half_width1",
                        check_range_above(hotspot_half_width1, T(0), kMaxCoordM));
    MPTRACK_CHECK_PARAM(w, "hotspot_min_points", check_range(hotspot_min_points, 2, 1000));
    MPTRACK_CHECK_PARAM(w, "hotspot_min_rate",
                        check_range_above(hotspot_min_rate, T(0), kMaxRate));
    return Status::kOk;
  }
};

}  // namespace mptrack
