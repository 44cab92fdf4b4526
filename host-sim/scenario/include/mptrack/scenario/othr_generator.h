// OTHR scenarios (seed 002 Sec. IV; docs/algorithms/scenarios.md §Seed 002):
// targets move with constant ground-range rate and bearing rate; each scan,
// every live target is detected through each ionospheric path with that
// path's pd, and the detection is h^tau(x) (core model/othr_measurement.h)
// plus Gaussian noise in slant range, range rate and azimuth; uniform
// clutter fills the (range, range rate, azimuth) box with a Poisson count.
#pragma once

#include <array>
#include <cstdint>

#include "mptrack/scenario/generator.h"
#include "mptrack/scenario/rng.h"
#include "mptrack/scenario/scenario_spec.h"

namespace mptrack::scenario {

/// [g km, g_dot km/s, theta rad, theta_dot rad/s] of an OTHR target at t_s.
std::array<double, 4> othr_ground_state_at(const ScenarioSpec& spec, const TargetSpec& target, double t_s);

/// The Cartesian truth of a ground state [m, m/s]: x = g cos theta,
/// y = g sin theta (receiver at the origin, transmitter at (0, d)).
KinematicState othr_cartesian(const std::array<double, 4>& ground);

/// Draws scan k of an OTHR scenario into out (truth, measurements in
/// random order). Per scan, in this order: targets (spec order), per
/// target its paths (spec order): one uniform for the detection, then three
/// normals; then the clutter components; then a Fisher-Yates shuffle.
void generate_othr_scan(const ScenarioSpec& spec, double clutter_scale, Rng& rng, std::uint32_t k, SimScan& out);

}  // namespace mptrack::scenario
