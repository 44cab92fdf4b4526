// ScenarioSpec validation and equality.
#include "mptrack/scenario/scenario_spec.h"

#include <cstdio>
#include <string>

#include "mptrack/validate.h"

namespace mptrack::scenario {

namespace {

bool finite(double x) { return is_finite(x); }
bool positive(double x) { return finite(x) && x > 0.0; }
bool non_negative(double x) { return finite(x) && x >= 0.0; }

std::string at(const char* list, std::size_t i, const char* field) {
  return std::string(list) + "[" + std::to_string(i) + "]." + field;
}

// Bounds that keep a scenario's work and arithmetic finite (issue 17: a
// period of 1e-320 s, a velocity of 1e308 m/s or a clutter mean of 1e308
// hung or failed scans later instead of being refused here).
constexpr double kMinScanPeriod_s = 1e-4;  // scan times are whole microseconds (generator.h)
constexpr double kMaxScanPeriod_s = 3600.0;
constexpr double kMaxCoord_m = 1e7;        // kMaxRegionCoordM (tracker_params.h)
constexpr double kMaxSpeed_mps = 1e4;      // MfbpParams v_max bound
constexpr double kMaxAccel_mps2 = 1e3;
constexpr double kMaxRangeStd_m = 1e5;     // PolarNoise bounds (tracker_params.h)
constexpr double kMaxAzimuthStd_deg = 57.29;  // 1 rad
constexpr double kMaxThreshold = 1e3;      // AmplitudeModel::kMaxThreshold
constexpr double kMaxPower = 1e12;         // SNR / CNR, linear

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}

/// "" if lo <= x <= hi (lo < x if lo_open) and finite, else
/// "NAME = X: must be in [lo, hi] UNIT".
std::string bounded(const std::string& name, double x, double lo, double hi, const char* unit,
                    bool lo_open = false) {
  const bool ok = finite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
  if (ok) return {};
  return name + " = " + num(x) + ": must be in " + (lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + "]" +
         (unit[0] != '\0' ? std::string(" ") + unit : std::string());
}

std::string check_lifetime(const std::string& where, std::uint32_t birth, std::uint32_t death,
                           std::uint32_t num_scans) {
  if (birth < 1 || birth > death || death > num_scans) {
    return where + ": expected [birth, death] with 1 <= birth <= death <= scans (" +
           std::to_string(num_scans) + ")";
  }
  return {};
}

// The OTHR block (seed 002 Sec. IV-A) and the targets' ground states.
std::string validate_othr(const ScenarioSpec& s) {
  const OthrSpec& o = s.othr;
  if (!non_negative(o.baseline_km) || o.baseline_km > 1e4) return "paths.baseline_km: expected a number in [0, 1e4]";
  if (!positive(o.range_rate_max_mps)) return "region.range_rate_mps: expected a positive bound";
  if (!positive(o.sigma_range_rate_mps)) return "measurement_noise.sigma_range_rate_mps: expected a positive number";
  if (o.paths.empty() || o.paths.size() > 8) return "paths.list: expected 1 to 8 paths";
  for (std::size_t i = 0; i < o.paths.size(); ++i) {
    const OthrPathSpec& p = o.paths[i];
    if (!non_negative(p.tx_height_km) || p.tx_height_km > 1e4) return at("paths.list", i, "tx_height_km") + ": expected a number in [0, 1e4]";
    if (!non_negative(p.rx_height_km) || p.rx_height_km > 1e4) return at("paths.list", i, "rx_height_km") + ": expected a number in [0, 1e4]";
    if (!(finite(p.pd) && p.pd > 0.0 && p.pd <= 1.0)) return at("paths.list", i, "pd") + ": expected a number in (0, 1]";
  }
  for (std::size_t i = 0; i < s.targets.size(); ++i) {
    for (double v : s.targets[i].ground_state) {
      if (!finite(v)) return at("targets", i, "ground_state") + ": expected 4 finite numbers";
    }
    if (!(s.targets[i].ground_state[0] > 0.0)) return at("targets", i, "ground_state") + ": expected a positive ground range";
  }
  for (std::size_t i = 0; i < s.clutter.size(); ++i) {
    if (!s.clutter[i].uniform) return at("clutter", i, "type") + ": an OTHR scenario has uniform clutter only";
  }
  return {};
}

}  // namespace

std::string validate(const ScenarioSpec& s) {
  if (s.num_scans < 1) return "scans: expected a positive integer";
  if (std::string e = bounded("scan_period_s", s.scan_period_s, kMinScanPeriod_s, kMaxScanPeriod_s,
                              "s (scan times are whole microseconds)");
      !e.empty()) {
    return e;
  }
  const Region& r = s.region;
  if (!non_negative(r.range_min_m) || !finite(r.range_max_m) || !(r.range_max_m > r.range_min_m)) {
    return "region.range_m: expected [min, max] with 0 <= min < max";
  }
  if (!finite(r.azimuth_min_deg) || !finite(r.azimuth_max_deg) ||
      !(r.azimuth_max_deg > r.azimuth_min_deg) || r.azimuth_min_deg < -180.0 ||
      r.azimuth_max_deg > 180.0) {
    return "region.azimuth_deg: expected [min, max] with -180 <= min < max <= 180";
  }
  if (std::string e = bounded("measurement_noise.sigma_range_m", s.sigma_range_m, 0.0, kMaxRangeStd_m, "m", true);
      !e.empty()) {
    return e;
  }
  if (std::string e = bounded("measurement_noise.sigma_azimuth_deg", s.sigma_azimuth_deg, 0.0, kMaxAzimuthStd_deg,
                              "deg", true);
      !e.empty()) {
    return e;
  }
  if (std::string e = bounded("threshold", s.threshold, 0.0, kMaxThreshold, "", true); !e.empty()) return e;
  if (s.eval_first_scan < 1 || s.eval_first_scan > s.eval_last_scan || s.eval_last_scan > s.num_scans) {
    return "evaluation: expected 1 <= first_scan <= last_scan <= scans";
  }
  if (s.space == MeasurementSpace::kCartesian) {
    const CartesianRegion& q = s.xy_region;
    if (!finite(q.x_min_m) || !finite(q.x_max_m) || !(q.x_max_m > q.x_min_m)) {
      return "region.x_m: expected [min, max] with min < max";
    }
    if (!finite(q.y_min_m) || !finite(q.y_max_m) || !(q.y_max_m > q.y_min_m)) {
      return "region.y_m: expected [min, max] with min < max";
    }
    if (!positive(s.sigma_xy_m)) return "measurement_noise.sigma_xy_m: expected a positive number";
  }
  if (s.space == MeasurementSpace::kOthr) {
    const std::string e = validate_othr(s);
    if (!e.empty()) return e;
  }
  for (std::size_t i = 0; i < s.targets.size(); ++i) {
    const TargetSpec& t = s.targets[i];
    if (t.id < 1) return at("targets", i, "id") + ": expected a positive integer";
    for (std::size_t j = 0; j < i; ++j) {
      if (s.targets[j].id == t.id) return at("targets", i, "id") + ": duplicate id " + std::to_string(t.id);
    }
    for (std::size_t j = 0; j < 4; ++j) {
      const bool speed = j % 2 == 1;  // [px, vx, py, vy]
      const std::string e = bounded(at("targets", i, "initial_state") + "[" + std::to_string(j) + "]",
                                    t.initial_state[j], speed ? -kMaxSpeed_mps : -kMaxCoord_m,
                                    speed ? kMaxSpeed_mps : kMaxCoord_m, speed ? "m/s" : "m");
      if (!e.empty()) return e;
    }
    std::string e = check_lifetime(at("targets", i, "lifetime"), t.birth_scan, t.death_scan, s.num_scans);
    if (!e.empty()) return e;
    e = bounded(at("targets", i, "snr"), t.snr, 0.0, kMaxPower, "(linear)", true);
    if (!e.empty()) return e;
    double last_start = -1e300;
    for (std::size_t j = 0; j < t.motion.size(); ++j) {
      const MotionSegment& m = t.motion[j];
      const std::string w = at("targets", i, "motion") + "[" + std::to_string(j) + "]";
      if (!finite(m.start_s) || m.start_s < last_start) {
        return w + ".start_s: expected a finite time, not before the previous segment";
      }
      last_start = m.start_s;
      for (std::size_t d = 0; d < 2; ++d) {
        std::string em = bounded(w + ".accel_mps2[" + std::to_string(d) + "]", m.accel_mps2[d], -kMaxAccel_mps2,
                                kMaxAccel_mps2, "m/s^2");
        if (em.empty()) {
          em = bounded(w + ".velocity_mps[" + std::to_string(d) + "]", m.velocity_mps[d], -kMaxSpeed_mps,
                       kMaxSpeed_mps, "m/s");
        }
        if (!em.empty()) return em;
      }
      if (!finite(m.turn_rate_deg_s)) return w + ".turn_rate_deg_s: expected a finite number";
      if (!finite(m.velocity_mps[0]) || !finite(m.velocity_mps[1])) {
        return w + ".velocity_mps: expected 2 finite numbers";
      }
    }
  }
  for (std::size_t i = 0; i < s.clutter.size(); ++i) {
    const ClutterSpec& c = s.clutter[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (s.clutter[j].id == c.id) return at("clutter", i, "id") + ": duplicate id " + std::to_string(c.id);
    }
    if (std::string e = bounded(at("clutter", i, "mean_count"), c.mean_count, 0.0, kMaxClutterMeanCount,
                                "per scan (kMaxClutterMeanCount)");
        !e.empty()) {
      return e;
    }
    if (std::string e = bounded(at("clutter", i, "cnr"), c.cnr, 0.0, kMaxPower, "(linear)", true); !e.empty()) {
      return e;
    }
    std::string e = check_lifetime(at("clutter", i, "lifetime"), c.birth_scan, c.death_scan, s.num_scans);
    if (!e.empty()) return e;
    const TimeVariation& v = c.variation;
    if (!finite(v.count_sin_amplitude) || v.count_sin_amplitude < -1.0) {
      return at("clutter", i, "variation.count_sin_amplitude") + ": expected a number >= -1";
    }
    if (c.amplitude == ClutterAmplitude::kWeibull) {
      if (!finite(c.weibull_shape) || c.weibull_shape < 0.1 || c.weibull_shape > 5.0) {
        return at("clutter", i, "amplitude.shape") + ": expected a number in [0.1, 5]";
      }
      if (!positive(c.weibull_scale)) return at("clutter", i, "amplitude.scale") + ": expected a positive number";
    }
    if (!c.uniform && s.space == MeasurementSpace::kCartesian) {
      if (!finite(c.mean_x_m) || !finite(c.mean_y_m)) return at("clutter", i, "mean") + ": expected finite x_m, y_m";
      if (!positive(c.sigma_x_m)) return at("clutter", i, "spread.sigma_x_m") + ": expected a positive number";
      if (!positive(c.sigma_y_m)) return at("clutter", i, "spread.sigma_y_m") + ": expected a positive number";
      if (!finite(c.correlation) || !(c.correlation > -1.0 && c.correlation < 1.0)) {
        return at("clutter", i, "spread.correlation") + ": expected a number in (-1, 1)";
      }
      if (!positive(v.cov_scale_start) || !positive(v.cov_scale_end)) {
        return at("clutter", i, "variation.cov_scale") + ": expected positive numbers";
      }
      if (v.drift_range_mps != 0.0 || v.drift_azimuth_deg_s != 0.0) {
        return at("clutter", i, "variation.drift") + ": polar drift is not supported in a Cartesian scenario";
      }
    } else if (!c.uniform) {
      if (!finite(c.mean_range_m)) return at("clutter", i, "mean.range_m") + ": expected a finite number";
      if (!finite(c.mean_azimuth_deg)) return at("clutter", i, "mean.azimuth_deg") + ": expected a finite number";
      if (!positive(c.sigma_range_m)) return at("clutter", i, "spread.sigma_range_m") + ": expected a positive number";
      if (!positive(c.sigma_azimuth_deg)) {
        return at("clutter", i, "spread.sigma_azimuth_deg") + ": expected a positive number";
      }
      if (!finite(c.correlation) || !(c.correlation > -1.0 && c.correlation < 1.0)) {
        return at("clutter", i, "spread.correlation") + ": expected a number in (-1, 1)";
      }
      if (!positive(v.cov_scale_start)) return at("clutter", i, "variation.cov_scale") + ": expected positive numbers";
      if (!positive(v.cov_scale_end)) return at("clutter", i, "variation.cov_scale") + ": expected positive numbers";
      if (!finite(v.drift_range_mps) || !finite(v.drift_azimuth_deg_s)) {
        return at("clutter", i, "variation.drift") + ": expected finite numbers";
      }
    }
  }
  return {};
}

double expected_measurements_per_scan(const ScenarioSpec& spec, double clutter_scale) {
  double n = 0.0;
  for (const ClutterSpec& c : spec.clutter) {
    const double a = c.variation.count_sin_amplitude;
    n += c.mean_count * (1.0 + (a < 0.0 ? -a : a)) * clutter_scale;
  }
  const double per_target = spec.space == MeasurementSpace::kOthr ? static_cast<double>(spec.othr.paths.size()) : 1.0;
  return n + per_target * static_cast<double>(spec.targets.size());
}

bool operator==(const MotionSegment& a, const MotionSegment& b) {
  return a.start_s == b.start_s && a.kind == b.kind && a.accel_mps2 == b.accel_mps2 &&
         a.turn_rate_deg_s == b.turn_rate_deg_s && a.velocity_mps == b.velocity_mps;
}

bool operator==(const TargetSpec& a, const TargetSpec& b) {
  return a.id == b.id && a.initial_state == b.initial_state && a.birth_scan == b.birth_scan &&
         a.death_scan == b.death_scan && a.snr == b.snr && a.swerling == b.swerling && a.motion == b.motion &&
         a.ground_state == b.ground_state;
}

bool operator==(const TimeVariation& a, const TimeVariation& b) {
  return a.count_sin_amplitude == b.count_sin_amplitude && a.cov_scale_start == b.cov_scale_start &&
         a.cov_scale_end == b.cov_scale_end && a.drift_range_mps == b.drift_range_mps &&
         a.drift_azimuth_deg_s == b.drift_azimuth_deg_s;
}

bool operator==(const ClutterSpec& a, const ClutterSpec& b) {
  return a.id == b.id && a.uniform == b.uniform && a.mean_count == b.mean_count &&
         a.mean_range_m == b.mean_range_m && a.mean_azimuth_deg == b.mean_azimuth_deg &&
         a.sigma_range_m == b.sigma_range_m && a.sigma_azimuth_deg == b.sigma_azimuth_deg &&
         a.correlation == b.correlation && a.cnr == b.cnr && a.swerling == b.swerling &&
         a.birth_scan == b.birth_scan && a.death_scan == b.death_scan && a.variation == b.variation &&
         a.mean_x_m == b.mean_x_m && a.mean_y_m == b.mean_y_m && a.sigma_x_m == b.sigma_x_m &&
         a.sigma_y_m == b.sigma_y_m && a.amplitude == b.amplitude && a.weibull_shape == b.weibull_shape &&
         a.weibull_scale == b.weibull_scale;
}

bool operator==(const CartesianRegion& a, const CartesianRegion& b) {
  return a.x_min_m == b.x_min_m && a.x_max_m == b.x_max_m && a.y_min_m == b.y_min_m && a.y_max_m == b.y_max_m;
}

bool operator==(const OthrPathSpec& a, const OthrPathSpec& b) {
  return a.name == b.name && a.tx_height_km == b.tx_height_km && a.rx_height_km == b.rx_height_km && a.pd == b.pd;
}

bool operator==(const OthrSpec& a, const OthrSpec& b) {
  return a.baseline_km == b.baseline_km && a.range_rate_max_mps == b.range_rate_max_mps &&
         a.sigma_range_rate_mps == b.sigma_range_rate_mps && a.paths == b.paths;
}

bool operator==(const Region& a, const Region& b) {
  return a.range_min_m == b.range_min_m && a.range_max_m == b.range_max_m &&
         a.azimuth_min_deg == b.azimuth_min_deg && a.azimuth_max_deg == b.azimuth_max_deg;
}

bool operator==(const ScenarioSpec& a, const ScenarioSpec& b) {
  return a.name == b.name && a.description == b.description && a.num_scans == b.num_scans &&
         a.scan_period_s == b.scan_period_s && a.region == b.region && a.sigma_range_m == b.sigma_range_m &&
         a.sigma_azimuth_deg == b.sigma_azimuth_deg && a.threshold == b.threshold &&
         a.eval_first_scan == b.eval_first_scan && a.eval_last_scan == b.eval_last_scan &&
         a.targets == b.targets && a.clutter == b.clutter && a.space == b.space && a.xy_region == b.xy_region &&
         a.sigma_xy_m == b.sigma_xy_m && a.othr == b.othr;
}

}  // namespace mptrack::scenario
