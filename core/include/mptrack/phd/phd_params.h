// Run-time parameters of the IGGM baselines (GM-PHD, GM-CPHD, CBMeMBer;
// seed 001). One struct for the three filters: they share the models, the
// clutter estimator, births and mixture management. Units in every comment;
// defaults are seed 001 section 6 where the paper gives a value, [impl]
// otherwise. validate() is called once by each filter's init().
#pragma once

#include <cstdint>

#include "mptrack/phd/measurement_model.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::phd {

/// How clutter is handled (issue: "selectable three ways").
enum class ClutterMode : std::uint8_t {
  kKnownUniform,      ///< uniform, known rate and known amplitude scale (GM-CPHD of Vo 2007)
  kEstimatedUniform,  ///< uniform, rate and amplitude scale estimated online (lambda-CPHD style)
  kEstimatedMap,      ///< uniform + Gaussian clutter sources, each with position, rate, power (seed 001)
};

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

  /// kInvalidArgument on any out-of-range field.
  Status validate() const {
    MPTRACK_TRY(check_positive(sigma_r_m));
    MPTRACK_TRY(check_positive(sigma_az_rad));
    MPTRACK_TRY(check(region_max0 > region_min0 && region_max1 > region_min1));
    MPTRACK_TRY(check(is_finite(region_min0) && is_finite(region_max0) &&
                      is_finite(region_min1) && is_finite(region_max1)));
    MPTRACK_TRY(check_positive(scan_period_s));
    MPTRACK_TRY(check_positive(accel_std_mps2));
    MPTRACK_TRY(check_open_probability(survival_prob));
    MPTRACK_TRY(check_positive(birth_rate));
    MPTRACK_TRY(check_positive(birth_velocity_std_mps));
    MPTRACK_TRY(check_positive(threshold));
    MPTRACK_TRY(check(swerling_order == 1 || swerling_order == 2));
    MPTRACK_TRY(check(target_power_prior > T(1) && is_finite(target_power_prior)));
    MPTRACK_TRY(check(target_alpha_prior > T(1) && is_finite(target_alpha_prior)));
    MPTRACK_TRY(check(power_forgetting > T(1) && power_forgetting < T(10)));
    MPTRACK_TRY(check_range(min_alpha, T(1.001), T(100)));
    MPTRACK_TRY(check(max_alpha > min_alpha && is_finite(max_alpha)));
    MPTRACK_TRY(check_open_probability(detection_prob));
    MPTRACK_TRY(check_positive(clutter_rate));
    MPTRACK_TRY(check_range(weibull_shape, T(0.1), T(5)));
    MPTRACK_TRY(check_positive(clutter_scale));
    MPTRACK_TRY(check(clutter_forgetting > T(1) && clutter_forgetting < T(10)));
    MPTRACK_TRY(check(clutter_alpha_prior > T(1) && is_finite(clutter_alpha_prior)));
    MPTRACK_TRY(check_positive(hotspot_half_width0));
    MPTRACK_TRY(check_positive(hotspot_half_width1));
    MPTRACK_TRY(check(hotspot_min_points >= 2 && hotspot_min_points <= 1000));
    MPTRACK_TRY(check_positive(hotspot_min_rate));
    MPTRACK_TRY(check_open_probability(prune_threshold));
    MPTRACK_TRY(check_positive(merge_threshold));
    MPTRACK_TRY(check_positive(merge_threshold_power));
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

  /// Measurement-space volume of the region [m rad | m^2].
  T region_volume() const { return (region_max0 - region_min0) * (region_max1 - region_min1); }
};

}  // namespace mptrack::phd
