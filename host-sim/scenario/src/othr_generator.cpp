// OTHR scan generation; see othr_generator.h.
#include "mptrack/scenario/othr_generator.h"

#include <cmath>
#include <utility>

#include "mptrack/math/detmath.h"
#include "mptrack/model/othr_measurement.h"

namespace mptrack::scenario {

std::array<double, 4> othr_ground_state_at(const ScenarioSpec& spec, const TargetSpec& target, double t_s) {
  const double dt = t_s - scan_time_s(spec, target.birth_scan);
  std::array<double, 4> g = target.ground_state;
  g[0] += g[1] * dt;
  g[2] += g[3] * dt;
  return g;
}

KinematicState othr_cartesian(const std::array<double, 4>& ground) {
  double s = 0.0;
  double c = 0.0;
  dmath::dsincos(ground[2], s, c);
  const double g = ground[0] * 1e3;
  const double gd = ground[1] * 1e3;
  const double td = ground[3];
  return KinematicState{g * c, gd * c - g * td * s, g * s, gd * s + g * td * c};
}

void generate_othr_scan(const ScenarioSpec& spec, double clutter_scale, Rng& rng, std::uint32_t k, SimScan& out) {
  out.has_doppler = true;
  const Region& reg = spec.region;
  const double az_min = deg_to_rad(reg.azimuth_min_deg);
  const double az_max = deg_to_rad(reg.azimuth_max_deg);
  const double rate_max = spec.othr.range_rate_max_mps;
  const auto inside = [&](const SimMeasurement& m) {
    return m.range_m >= reg.range_min_m && m.range_m <= reg.range_max_m && m.azimuth_rad >= az_min &&
           m.azimuth_rad <= az_max && m.doppler_mps >= -rate_max && m.doppler_mps <= rate_max;
  };
  const double sigma_az = deg_to_rad(spec.sigma_azimuth_deg);
  const double t_k = scan_time_s(spec, k);
  for (const TargetSpec& tgt : spec.targets) {
    if (!alive(tgt.birth_scan, tgt.death_scan, k)) continue;
    TruthState truth;
    truth.target_id = tgt.id;
    const std::array<double, 4> ground = othr_ground_state_at(spec, tgt, t_k);
    truth.x = othr_cartesian(ground);
    truth.snr = tgt.snr;
    const model::OthrState<double> x(ground[0], ground[1], ground[2], ground[3]);
    for (std::size_t p = 0; p < spec.othr.paths.size(); ++p) {
      const OthrPathSpec& path = spec.othr.paths[p];
      if (!(rng.uniform() < path.pd)) continue;
      const model::OthrPath<double> hp{path.tx_height_km, path.rx_height_km};
      const model::OthrMeas<double> y = model::othr_measure(x, hp, spec.othr.baseline_km);
      SimMeasurement m;
      m.range_m = y(0) * 1e3 + spec.sigma_range_m * rng.normal();
      m.doppler_mps = y(1) * 1e3 + spec.othr.sigma_range_rate_mps * rng.normal();
      m.azimuth_rad = y(2) + sigma_az * rng.normal();
      m.amplitude = 1.0;  // not modelled in seed 002
      m.origin = Origin{OriginKind::kTarget, tgt.id};
      m.path = static_cast<std::int32_t>(p);
      truth.detected = true;
      if (inside(m)) {
        truth.in_region = true;
        out.measurements.push_back(m);
      } else {
        ++out.dropped_outside_region;
      }
    }
    out.truth.push_back(truth);
  }
  for (const ClutterSpec& c : spec.clutter) {
    if (!alive(c.birth_scan, c.death_scan, k) || !c.uniform) continue;  // validate(): uniform only
    const std::uint32_t count = rng.poisson(c.mean_count * clutter_scale);
    for (std::uint32_t i = 0; i < count; ++i) {
      SimMeasurement m;
      m.range_m = reg.range_min_m + (reg.range_max_m - reg.range_min_m) * rng.uniform();
      m.doppler_mps = rate_max * (2.0 * rng.uniform() - 1.0);
      m.azimuth_rad = az_min + (az_max - az_min) * rng.uniform();
      m.amplitude = 1.0;
      m.origin = Origin{OriginKind::kClutter, c.id};
      out.measurements.push_back(m);
    }
  }
  for (std::size_t i = out.measurements.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(rng.below(i));
    std::swap(out.measurements[i - 1], out.measurements[j]);
  }
  for (std::size_t j = 0; j < out.measurements.size(); ++j) {  // the first detection of each target
    const SimMeasurement& m = out.measurements[j];
    if (m.origin.kind != OriginKind::kTarget) continue;
    for (TruthState& t : out.truth) {
      if (t.target_id == m.origin.id && t.measurement_index < 0) t.measurement_index = static_cast<std::int32_t>(j);
    }
  }
}

}  // namespace mptrack::scenario
