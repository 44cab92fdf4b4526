// What the OTHR trackers (mfbp-multipath, mptf) take from an OTHR scenario
// the same way: path heights, baseline, slant region, range-rate span,
// measurement noise, the known uniform clutter rate and the gap limit
// (docs/algorithms/multipath.md §Evaluation, docs/algorithms/mptf.md).
#pragma once

#include <cstdint>
#include <string>

#include "mptrack/scenario/scenario_spec.h"
#include "trackers/core_adapter.h"

namespace mptrack::sim {

/// "" if `setup` is an OTHR scenario, else the refusal for `tracker`.
inline std::string othr_scenario_required(const TrackerSetup& setup, const std::string& tracker) {
  if (setup.spec.space == scenario::MeasurementSpace::kOthr) return "";
  return tracker + " needs an OTHR scenario (measurement_space \"othr\", e.g. seed002-othr)";
}

/// Mean uniform clutter count per scan after --clutter-scale (at least 1: the
/// trackers' clutter density needs a positive rate).
inline double othr_clutter_mean(const TrackerSetup& setup) {
  double clutter = 0.0;
  for (const scenario::ClutterSpec& c : setup.spec.clutter) clutter += c.mean_count * setup.clutter_scale;
  return clutter > 1.0 ? clutter : 1.0;
}

/// The bearing axis's white-noise PSD [rad^2/s^3] for the same acceleration
/// noise across the line of sight as along it: q_g / g^2, g the middle of
/// the region's range span (docs/algorithms/multipath.md §Track state).
/// Seed 002 Sec. IV gives 1e-8 for both axes, but 1e-8 rad^2/s^3 is 3e4
/// km^2/s^3 across the line of sight at 1750 km (3.7 mrad of bearing spread
/// per 16 s scan against 3 mrad of azimuth noise): no bearing averaging.
inline float othr_cross_range_bearing_psd(float range_psd_m2ps3, const PolarRegion<float>& region) {
  const double q_km2ps3 = static_cast<double>(range_psd_m2ps3) * 1e-6;
  const double g_km = 0.5e-3 * (static_cast<double>(region.range_min_m) + static_cast<double>(region.range_max_m));
  return static_cast<float>(q_km2ps3 / (g_km * g_km));
}

/// Fills the geometry, noise, clutter and gap fields every OTHR Params has.
template <class Params>
void configure_othr(const TrackerSetup& setup, Params& p) {
  const scenario::ScenarioSpec& s = setup.spec;
  p.num_paths = static_cast<std::uint32_t>(s.othr.paths.size());
  for (std::size_t i = 0; i < s.othr.paths.size() && i < p.paths.size(); ++i) {
    const scenario::OthrPathSpec& ps = s.othr.paths[i];
    p.paths[i] = {static_cast<float>(ps.tx_height_km), static_cast<float>(ps.rx_height_km)};
  }
  p.baseline_km = static_cast<float>(s.othr.baseline_km);
  const PolarRegion<double> r = scenario_region(s);
  p.region = {static_cast<float>(r.range_min_m), static_cast<float>(r.range_max_m),
              static_cast<float>(r.azimuth_min_rad), static_cast<float>(r.azimuth_max_rad)};
  p.range_rate_span_mps = static_cast<float>(s.othr.range_rate_max_mps);
  p.noise.range_std_m = static_cast<float>(s.sigma_range_m);
  p.noise.azimuth_std_rad = static_cast<float>(scenario::deg_to_rad(s.sigma_azimuth_deg));
  p.noise.doppler_std_mps = static_cast<float>(s.othr.sigma_range_rate_mps);
  p.clutter_mean_count = static_cast<float>(othr_clutter_mean(setup));
  p.max_gap_s = static_cast<float>(4.0 * s.scan_period_s);
}

}  // namespace mptrack::sim
