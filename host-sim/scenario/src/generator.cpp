// Scenario generator (docs/algorithms/scenarios.md §Measurement generation); the draw order
// is documented in generator.h.
#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/othr_generator.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "mptrack/math/detmath.h"
#include "mptrack/validate.h"

namespace mptrack::scenario {

namespace {

// Advances a Cartesian state by dt under one motion mode (exact solutions).
void propagate(KinematicState& x, const MotionSegment& mode, double dt) {
  switch (mode.kind) {
    case MotionKind::kConstantAcceleration: {
      const double ax = mode.accel_mps2[0];
      const double ay = mode.accel_mps2[1];
      x.px += x.vx * dt + 0.5 * ax * dt * dt;
      x.py += x.vy * dt + 0.5 * ay * dt * dt;
      x.vx += ax * dt;
      x.vy += ay * dt;
      return;
    }
    case MotionKind::kCoordinatedTurn: {
      const double w = deg_to_rad(mode.turn_rate_deg_s);
      if (w != 0.0) {
        double s = 0.0;
        double c = 0.0;
        dmath::dsincos(w * dt, s, c);
        // Constant-speed turn (Bar-Shalom, Li, Kirubarajan 2001, eq. 11.7.1-4).
        const double px = x.px + (x.vx * s - x.vy * (1.0 - c)) / w;
        const double py = x.py + (x.vx * (1.0 - c) + x.vy * s) / w;
        const double vx = x.vx * c - x.vy * s;
        const double vy = x.vx * s + x.vy * c;
        x = KinematicState{px, vx, py, vy};
        return;
      }
      break;
    }
    case MotionKind::kConstantVelocity:
    case MotionKind::kSetVelocity:
      break;
  }
  x.px += x.vx * dt;
  x.py += x.vy * dt;
}

}  // namespace

std::uint64_t scan_time_us(const ScenarioSpec& spec, std::uint32_t k) {
  const double t_us = scan_time_s(spec, k) * 1e6;
  return static_cast<std::uint64_t>(t_us + 0.5);
}

KinematicState target_state_at(const ScenarioSpec& spec, const TargetSpec& target, double t_s) {
  if (spec.space == MeasurementSpace::kOthr) {
    return othr_cartesian(othr_ground_state_at(spec, target, t_s));
  }
  KinematicState x{target.initial_state[0], target.initial_state[1], target.initial_state[2],
                   target.initial_state[3]};
  double now = scan_time_s(spec, target.birth_scan);
  MotionSegment mode;  // CV until the first segment starts
  for (const MotionSegment& seg : target.motion) {
    if (seg.start_s > t_s) break;
    if (seg.start_s > now) {
      propagate(x, mode, seg.start_s - now);
      now = seg.start_s;
    }
    mode = seg;
    if (seg.kind == MotionKind::kSetVelocity) {
      x.vx = seg.velocity_mps[0];
      x.vy = seg.velocity_mps[1];
    }
  }
  propagate(x, mode, t_s - now);
  return x;
}

ClutterAtScan clutter_at_scan(const ScenarioSpec& spec, const ClutterSpec& c, std::uint32_t k) {
  // seed 000 eq. (104) time variation, f = (k - k_start) / (k_end - k_start).
  const double span = static_cast<double>(c.death_scan) - static_cast<double>(c.birth_scan);
  const double age = static_cast<double>(k) - static_cast<double>(c.birth_scan);
  const double f = span > 0.0 ? age / span : 0.0;
  const TimeVariation& v = c.variation;
  ClutterAtScan out;
  double count_scale = 1.0;
  if (v.count_sin_amplitude != 0.0) count_scale += v.count_sin_amplitude * dmath::dsin(kPi * f);
  out.mean_count = c.mean_count * count_scale;
  out.cnr = c.cnr;
  if (!c.uniform && spec.space == MeasurementSpace::kCartesian) {
    const double cov_scale = v.cov_scale_start + (v.cov_scale_end - v.cov_scale_start) * f;
    out.cov_xx = cov_scale * c.sigma_x_m * c.sigma_x_m;
    out.cov_xy = cov_scale * c.correlation * c.sigma_x_m * c.sigma_y_m;
    out.cov_yy = cov_scale * c.sigma_y_m * c.sigma_y_m;
    out.mean_x_m = c.mean_x_m;
    out.mean_y_m = c.mean_y_m;
  } else if (!c.uniform) {
    const double cov_scale = v.cov_scale_start + (v.cov_scale_end - v.cov_scale_start) * f;
    const double sr = c.sigma_range_m;
    const double sa = deg_to_rad(c.sigma_azimuth_deg);
    out.cov_rr = cov_scale * sr * sr;
    out.cov_ra = cov_scale * c.correlation * sr * sa;
    out.cov_aa = cov_scale * sa * sa;
    const double elapsed_s = age * spec.scan_period_s;
    out.mean_range_m = c.mean_range_m + v.drift_range_mps * elapsed_s;
    out.mean_azimuth_rad = deg_to_rad(c.mean_azimuth_deg + v.drift_azimuth_deg_s * elapsed_s);
  }
  return out;
}

Status Generator::init(const ScenarioSpec& spec, std::uint64_t seed, std::uint32_t run,
                       const GeneratorOptions& options) {
  ready_ = false;
  error_ = validate(spec);
  if (error_.empty() && !(options.clutter_scale >= 0.0 && is_finite(options.clutter_scale))) {
    error_ = "clutter_scale: expected a non-negative number";
  }
  for (std::size_t i = 0; error_.empty() && i < spec.clutter.size(); ++i) {
    // Bounded work: the Poisson draw of a scan is O(mean) (rng.h).
    const double mean = spec.clutter[i].mean_count * options.clutter_scale;
    if (mean > kMaxClutterMeanCount) {
      char b[200];
      std::snprintf(b, sizeof b, "clutter[%zu].mean_count x clutter_scale = %g x %g = %g: must be <= %g per scan",
                    i, spec.clutter[i].mean_count, options.clutter_scale, mean, kMaxClutterMeanCount);
      error_ = b;
    }
  }
  if (!error_.empty()) return Status::kInvalidArgument;
  spec_ = spec;
  options_ = options;
  seed_ = seed;
  run_ = run;
  ready_ = true;
  return Status::kOk;
}

Status Generator::generate(std::uint32_t k, SimScan& out) const {
  if (!ready_ || k < 1 || k > spec_.num_scans) return Status::kInvalidArgument;
  Rng rng(derive_seed(seed_, run_, k));
  out.scan = k;
  out.time_us = scan_time_us(spec_, k);
  out.truth.clear();
  out.measurements.clear();
  out.dropped_outside_region = 0;

  if (spec_.space == MeasurementSpace::kOthr) {
    generate_othr_scan(spec_, options_.clutter_scale, rng, k, out);
    return Status::kOk;
  }
  const Region& reg = spec_.region;
  const double az_min = deg_to_rad(reg.azimuth_min_deg);
  const double az_max = deg_to_rad(reg.azimuth_max_deg);
  const bool cartesian = spec_.space == MeasurementSpace::kCartesian;
  const CartesianRegion& box = spec_.xy_region;
  const auto inside = [&](double r, double az) {
    return r >= reg.range_min_m && r <= reg.range_max_m && az >= az_min && az <= az_max;
  };
  const auto inside_xy = [&](double x, double y) {
    return x >= box.x_min_m && x <= box.x_max_m && y >= box.y_min_m && y <= box.y_max_m;
  };
  // A Cartesian point as the tracker receives it: (range, azimuth) of (x, y).
  const auto set_xy = [](SimMeasurement& m, double x, double y) {
    m.x_m = x;
    m.y_m = y;
    m.range_m = std::sqrt(x * x + y * y);
    m.azimuth_rad = dmath::datan2(y, x);
  };
  const double d2 = spec_.threshold * spec_.threshold;
  const double sigma_az = deg_to_rad(spec_.sigma_azimuth_deg);
  const double t_k = scan_time_s(spec_, k);

  // 1. Targets: draw the power, threshold it (exact P_D for Gamma(n):
  // docs/algorithms/scenarios.md §Measurement generation).
  for (const TargetSpec& tgt : spec_.targets) {
    if (!alive(tgt.birth_scan, tgt.death_scan, k)) continue;
    TruthState truth;
    truth.target_id = tgt.id;
    truth.x = target_state_at(spec_, tgt, t_k);
    truth.snr = tgt.snr;
    const int n = swerling_shape(tgt.swerling);
    const double power = rng.gamma_int(n, (1.0 + tgt.snr) / static_cast<double>(n));
    truth.detected = power > d2;
    if (truth.detected && cartesian) {
      SimMeasurement m;
      const double x = truth.x.px + spec_.sigma_xy_m * rng.normal();
      const double y = truth.x.py + spec_.sigma_xy_m * rng.normal();
      set_xy(m, x, y);
      m.amplitude = std::sqrt(power);
      m.origin = Origin{OriginKind::kTarget, tgt.id};
      truth.in_region = inside_xy(x, y);
      if (truth.in_region) {
        out.measurements.push_back(m);
      } else {
        ++out.dropped_outside_region;
      }
    } else if (truth.detected) {
      const double r0 = std::sqrt(truth.x.px * truth.x.px + truth.x.py * truth.x.py);
      const double az0 = dmath::datan2(truth.x.py, truth.x.px);
      SimMeasurement m;
      m.range_m = r0 + spec_.sigma_range_m * rng.normal();
      m.azimuth_rad = az0 + sigma_az * rng.normal();
      m.amplitude = std::sqrt(power);
      m.origin = Origin{OriginKind::kTarget, tgt.id};
      truth.in_region = inside(m.range_m, m.azimuth_rad);
      if (truth.in_region) {
        out.measurements.push_back(m);
      } else {
        ++out.dropped_outside_region;
      }
    }
    out.truth.push_back(truth);
  }

  // 2. Clutter: Poisson counts (docs/algorithms/scenarios.md §Seed 000), positions,
  // truncated-Gamma amplitudes.
  for (const ClutterSpec& c : spec_.clutter) {
    if (!alive(c.birth_scan, c.death_scan, k)) continue;
    const ClutterAtScan p = clutter_at_scan(spec_, c, k);
    const std::uint32_t count = rng.poisson(p.mean_count * options_.clutter_scale);
    const int n = swerling_shape(c.swerling);
    const double scale = (1.0 + c.cnr) / static_cast<double>(n);
    // Cholesky factor of the polar covariance.
    const double l11 = std::sqrt(p.cov_rr);
    const double l21 = l11 > 0.0 ? p.cov_ra / l11 : 0.0;
    const double l22_sq = p.cov_aa - l21 * l21;
    const double l22 = l22_sq > 0.0 ? std::sqrt(l22_sq) : 0.0;
    // Cholesky factor of the Cartesian covariance (zero when polar or uniform).
    const double c11 = std::sqrt(p.cov_xx);
    const double c21 = c11 > 0.0 ? p.cov_xy / c11 : 0.0;
    const double c22_sq = p.cov_yy - c21 * c21;
    const double c22 = c22_sq > 0.0 ? std::sqrt(c22_sq) : 0.0;
    for (std::uint32_t i = 0; i < count; ++i) {
      SimMeasurement m;
      if (cartesian) {
        double x = 0.0;
        double y = 0.0;
        if (c.uniform) {
          x = box.x_min_m + (box.x_max_m - box.x_min_m) * rng.uniform();
          y = box.y_min_m + (box.y_max_m - box.y_min_m) * rng.uniform();
        } else {
          const double z1 = rng.normal();
          const double z2 = rng.normal();
          x = p.mean_x_m + c11 * z1;
          y = p.mean_y_m + c21 * z1 + c22 * z2;
        }
        set_xy(m, x, y);
        m.amplitude = c.amplitude == ClutterAmplitude::kWeibull
                          ? rng.weibull_above(c.weibull_shape, c.weibull_scale, spec_.threshold)
                          : std::sqrt(rng.gamma_int_above(n, scale, d2));
        m.origin = Origin{OriginKind::kClutter, c.id};
        if (inside_xy(x, y)) {
          out.measurements.push_back(m);
        } else {
          ++out.dropped_outside_region;
        }
        continue;
      }
      if (c.uniform) {
        m.range_m = reg.range_min_m + (reg.range_max_m - reg.range_min_m) * rng.uniform();
        m.azimuth_rad = az_min + (az_max - az_min) * rng.uniform();
      } else {
        const double z1 = rng.normal();
        const double z2 = rng.normal();
        m.range_m = p.mean_range_m + l11 * z1;
        m.azimuth_rad = p.mean_azimuth_rad + l21 * z1 + l22 * z2;
      }
      m.amplitude = c.amplitude == ClutterAmplitude::kWeibull
                        ? rng.weibull_above(c.weibull_shape, c.weibull_scale, spec_.threshold)
                        : std::sqrt(rng.gamma_int_above(n, scale, d2));
      m.origin = Origin{OriginKind::kClutter, c.id};
      if (inside(m.range_m, m.azimuth_rad)) {
        out.measurements.push_back(m);
      } else {
        ++out.dropped_outside_region;
      }
    }
  }

  // 3. Random order (Fisher-Yates), then record where each target's measurement went.
  for (std::size_t i = out.measurements.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(rng.below(i));
    std::swap(out.measurements[i - 1], out.measurements[j]);
  }
  for (std::size_t j = 0; j < out.measurements.size(); ++j) {
    const SimMeasurement& m = out.measurements[j];
    if (m.origin.kind != OriginKind::kTarget) continue;
    for (TruthState& t : out.truth) {
      if (t.target_id == m.origin.id) t.measurement_index = static_cast<std::int32_t>(j);
    }
  }
  return Status::kOk;
}

}  // namespace mptrack::scenario
