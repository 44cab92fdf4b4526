// Synthetic workload scenarios for the latency grid (see workload.h).
#include "workload.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace mptrack::bench {

double uniform_rate(const scenario::ScenarioSpec& spec) {
  double rate = 0.0;
  for (const auto& c : spec.clutter) {
    if (c.uniform) rate += c.mean_count;
  }
  return rate;
}

scenario::ScenarioSpec seed000_s2() {
  scenario::ScenarioSpec s;
  if (!scenario::builtin_scenario("seed000-s2", s)) std::abort();
  return s;
}

scenario::ScenarioSpec workload_spec(const Workload& w, std::uint32_t num_scans) {
  scenario::ScenarioSpec s;
  s.name = "bench-T" + std::to_string(w.targets) + "-M" + std::to_string(w.measurements) + "-C" +
           std::to_string(w.clutter_components);
  s.num_scans = num_scans;
  s.eval_first_scan = 1;
  s.eval_last_scan = num_scans;
  // Region, noise, threshold and scan period: seed 000 defaults (seed 000 Sec. IV-A).
  constexpr double kSnr = 10.0;  // P_D = exp(-d^2 / (1 + snr)) = 0.955 at d = 0.715
                                 // (docs/algorithms/models.md §Detection probability)
  constexpr double kPd = 0.955;
  // Targets on an 8 x 8 (range, azimuth) grid: 4 km x 5.5 deg cells, far
  // apart compared with the 20 m / 0.6 deg noise, so the association load
  // is set by the clutter, not by target crossings.
  for (std::uint32_t i = 0; i < w.targets; ++i) {
    const double r = 14000.0 + 4000.0 * static_cast<double>(i % 8);
    const double az = scenario::deg_to_rad(14.0 + 5.5 * static_cast<double>(i / 8));
    // Polar -> Cartesian by a short series-free formula is not needed here:
    // the generator only needs an initial state, so use the host libm.
    scenario::TargetSpec t;
    t.id = i + 1;
    t.initial_state = {r * std::cos(az), 20.0, r * std::sin(az), 10.0};
    t.birth_scan = 1;
    t.death_scan = num_scans;
    t.snr = kSnr;
    s.targets.push_back(t);
  }
  // Clutter: whatever the targets do not supply; 30 % of it (at most 10
  // per component) in the Gaussian components, the rest uniform.
  const double rest = std::max(1.0, static_cast<double>(w.measurements) - kPd * static_cast<double>(w.targets));
  const double per_comp =
      w.clutter_components > 0 ? std::min(10.0, 0.3 * rest / static_cast<double>(w.clutter_components)) : 0.0;
  scenario::ClutterSpec u;
  u.id = 0;
  u.uniform = true;
  u.mean_count = std::max(0.5, rest - per_comp * static_cast<double>(w.clutter_components));
  u.cnr = 1.0;
  u.birth_scan = 1;
  u.death_scan = num_scans;
  s.clutter.push_back(u);
  for (std::uint32_t c = 0; c < w.clutter_components; ++c) {
    scenario::ClutterSpec g;
    g.id = c + 1;
    g.mean_count = per_comp;
    // Between the target rows: ranges 12..44 km, azimuth 11.5 + 5.5 (c / 4) deg.
    g.mean_range_m = 12000.0 + 4000.0 * static_cast<double>(2 * (c % 4) + 1);
    g.mean_azimuth_deg = 11.5 + 5.5 * static_cast<double>(c / 4);
    g.sigma_range_m = 400.0;
    g.sigma_azimuth_deg = 0.8;
    g.cnr = 2.0;
    g.birth_scan = 1;
    g.death_scan = num_scans;
    s.clutter.push_back(g);
  }
  return s;
}

}  // namespace mptrack::bench
