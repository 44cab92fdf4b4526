// Benchmark workloads: scenario specs (seed 000 S2 and a synthetic
// targets x measurements x clutter-components grid), scan generation and
// the tracker parameters for each (the same settings the host harness's
// adapters use, so benchmark and harness run the same configuration).
//
// Host-only code: it allocates (std::vector, std::unique_ptr) freely; only
// the tracker step() calls it times are core.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/caps.h"
#include "mptrack/gnn/gnn_params.h"
#include "mptrack/measurement.h"
#include "mptrack/mfbp/mfbp_params.h"
#include "mptrack/rfs/rfs_params.h"
#include "mptrack/scenario/builtin.h"
#include "mptrack/scenario/generator.h"

namespace mptrack::bench {

/// Caps of the workload grid: up to 512 measurements per scan (the issue's
/// upper end), room for 64 true targets plus tentative tracks.
struct BenchCaps {
  static constexpr std::size_t kMaxTargets = 128;
  static constexpr std::size_t kMaxMeasurements = 512;
  static constexpr std::size_t kMaxClutterComponents = 8;
  static constexpr std::size_t kMaxWindow = 7;
};

/// One point of the workload grid.
struct Workload {
  std::uint32_t targets = 8;              ///< true targets, all alive for the whole run
  std::uint32_t measurements = 128;       ///< expected measurements per scan (targets + clutter)
  std::uint32_t clutter_components = 2;   ///< non-uniform (Gaussian) clutter components
};

/// Synthetic polar scenario in seed 000's region and sensor (10-50 km,
/// 10-60 deg, sigma 20 m / 0.6 deg, T = 1.25 s): targets on an 8 x 8 grid of
/// (range, azimuth) cells moving at constant velocity, SNR 10 (P_D 0.95),
/// Gaussian clutter components between them and uniform clutter making up
/// the rest of the expected measurement count.
scenario::ScenarioSpec workload_spec(const Workload& w, std::uint32_t num_scans);

/// The built-in seed 000 S2 (Table IV); aborts if missing (cannot happen).
scenario::ScenarioSpec seed000_s2();

/// Sum of the uniform components' mean counts (the known uniform rate).
double uniform_rate(const scenario::ScenarioSpec& spec);

/// Scans first..first+count-1 of run 0 converted to tracker input.
template <class T, std::size_t N>
std::vector<std::unique_ptr<Scan<T, N>>> generate_scans(const scenario::ScenarioSpec& spec,
                                                        std::uint64_t seed, std::uint32_t first,
                                                        std::uint32_t count) {
  std::vector<std::unique_ptr<Scan<T, N>>> out;
  scenario::Generator gen;
  if (gen.init(spec, seed, 0) != Status::kOk) return out;
  scenario::SimScan sim;
  for (std::uint32_t k = first; k < first + count; ++k) {
    if (gen.generate(k, sim) != Status::kOk) break;
    auto scan = std::make_unique<Scan<T, N>>();
    (void)scenario::to_scan(sim, *scan);  // over-cap measurements are cut (counted by nobody: caps are sized)
    out.push_back(std::move(scan));
  }
  return out;
}

/// MF-BP parameters for a polar scenario (as host-sim's mfbp adapter):
/// window 1 = online filter, 7 = the smoother of `base` (the paper's, slide
/// 3, unless base is every_scan_smoother_params(), mfbp-s1).
template <class T>
MfbpParams<T> mfbp_params_for(const scenario::ScenarioSpec& s, std::size_t window,
                              const MfbpParams<T>& base = seed000_default_params<T>()) {
  MfbpParams<T> p = base;
  p.region.range_min_m = T(s.region.range_min_m);
  p.region.range_max_m = T(s.region.range_max_m);
  p.region.azimuth_min_rad = T(scenario::deg_to_rad(s.region.azimuth_min_deg));
  p.region.azimuth_max_rad = T(scenario::deg_to_rad(s.region.azimuth_max_deg));
  p.scan_period_s = T(s.scan_period_s);
  p.noise.range_std_m = T(s.sigma_range_m);
  p.noise.azimuth_std_rad = T(scenario::deg_to_rad(s.sigma_azimuth_deg));
  p.amplitude.threshold = T(s.threshold);
  p.amplitude.swerling = s.targets.empty() ? 1 : static_cast<int>(s.targets.front().swerling);
  p.uniform_rate_per_scan = T(uniform_rate(s) > 0.0 ? uniform_rate(s) : 1.0);
  for (const auto& c : s.clutter) {
    if (c.uniform) {
      p.uniform_cnr_prior = T(c.cnr);
      break;
    }
  }
  if (window == 1) {
    p.window_length = 1;
    p.slide = 1;
  }
  return p;
}

/// GM-PHD / GM-CPHD parameters for a polar scenario (as host-sim's gmphd adapter).
template <class T>
RfsFilterParams<T> phd_params_for(const scenario::ScenarioSpec& s) {
  RfsFilterParams<T> p;
  p.space = MeasurementSpace::kPolar;
  p.noise.range_std_m = T(s.sigma_range_m);
  p.noise.azimuth_std_rad = T(scenario::deg_to_rad(s.sigma_azimuth_deg));
  p.region.range_min_m = T(s.region.range_min_m);
  p.region.range_max_m = T(s.region.range_max_m);
  p.region.azimuth_min_rad = T(scenario::deg_to_rad(s.region.azimuth_min_deg));
  p.region.azimuth_max_rad = T(scenario::deg_to_rad(s.region.azimuth_max_deg));
  p.scan_period_s = T(s.scan_period_s);
  p.accel_var_m2ps4 = T(1);
  p.birth_velocity_std_mps = T(60);
  p.amplitude.threshold = T(s.threshold);
  const bool sw3 = !s.targets.empty() && s.targets.front().swerling == scenario::Swerling::kThree;
  p.amplitude.swerling = sw3 ? 3 : 1;
  double snr = 0.0;
  for (const auto& t : s.targets) snr += t.snr;
  p.target_power_prior = T(1.0 + (s.targets.empty() ? 10.0 : snr / static_cast<double>(s.targets.size())));
  p.detection_prob = T(0.9);
  const double rate = uniform_rate(s);
  p.clutter_rate = T(rate > 0.0 ? rate : 1.0);
  p.weibull_shape = T(1);
  double cnr = 0.0;
  for (const auto& c : s.clutter) {
    if (c.uniform) {
      cnr = c.cnr;
      break;
    }
  }
  p.clutter_scale = T(1.0 + cnr);
  p.hotspot_half_width0 = T(500);
  p.hotspot_half_width1 = T(scenario::deg_to_rad(2.0));
  p.clutter_mode = ClutterMode::kEstimatedMap;
  return p;
}

/// GNN parameters for a polar scenario (as host-sim's gnn adapter).
template <class T>
GnnParams<T> gnn_params_for(const scenario::ScenarioSpec& s) {
  GnnParams<T> p;
  p.noise.range_std_m = T(s.sigma_range_m);
  p.noise.azimuth_std_rad = T(scenario::deg_to_rad(s.sigma_azimuth_deg));
  p.region.range_min_m = T(s.region.range_min_m);
  p.region.range_max_m = T(s.region.range_max_m);
  p.region.azimuth_min_rad = T(scenario::deg_to_rad(s.region.azimuth_min_deg));
  p.region.azimuth_max_rad = T(scenario::deg_to_rad(s.region.azimuth_max_deg));
  p.accel_var_m2ps4 = T(1);
  p.init_velocity_std_mps = T(60);
  return p;
}

}  // namespace mptrack::bench
