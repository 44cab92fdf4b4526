// Drone truth and the SNR table; see trajectory.h.
#include "mptrack/adc/trajectory.h"

#include <cmath>

#include "mptrack/frontend/frontend_params.h"
#include "mptrack/math/constants.h"

namespace mptrack::adc {

DroneState drone_state_at(const DroneSpec& d, std::uint32_t frame, double dt) {
  DroneState s;
  s.x = d.start_m[0];
  s.y = d.start_m[1];
  s.vx = d.velocity_mps[0];
  s.vy = d.velocity_mps[1];
  if (frame <= d.birth_frame) return s;
  const std::uint32_t steps = frame - d.birth_frame;
  std::uint32_t done = 0;
  std::size_t leg = 0;
  // Velocity at the start of the current leg, and steps taken inside it.
  double leg_vx = s.vx, leg_vy = s.vy;
  std::uint32_t in_leg = 0;
  while (done < steps) {
    // p_{n+1} = p_n + v_n dt (docs/algorithms/scenarios.md §Seed 004), then v_{n+1} from
    // the schedule.
    s.x += s.vx * dt;
    s.y += s.vy * dt;
    ++done;
    if (leg < d.legs.size()) {
      const MotionLeg& l = d.legs[leg];
      ++in_leg;
      const double f = static_cast<double>(in_leg) / static_cast<double>(l.steps);
      s.vx = leg_vx + (l.velocity_mps[0] - leg_vx) * f;
      s.vy = leg_vy + (l.velocity_mps[1] - leg_vy) * f;
      if (in_leg == l.steps) {
        // Land exactly on the leg's end velocity (no accumulated rounding).
        s.vx = l.velocity_mps[0];
        s.vy = l.velocity_mps[1];
        leg_vx = s.vx;
        leg_vy = s.vy;
        in_leg = 0;
        ++leg;
      }
    }
  }
  return s;
}

double mean_component_snr(const AdcScenario& s, double range_m, double mean_rcs_m2) {
  const RadarSpec& r = s.radar;
  const double lambda = frontend::kSpeedOfLight_mps / r.carrier_hz;
  const double four_pi = 4.0 * dmath::kPi<double>;
  const double rho = r.tx_amplitude * r.antenna_gain * lambda / (four_pi * std::sqrt(four_pi) * range_m * range_m);
  const double noise_bw = r.noise_model == NoiseModel::kModelA ? r.sample_rate_hz : r.bandwidth_hz;
  const double noise_var = kBoltzmann_J_per_K * r.noise_temperature_k * noise_bw;
  const double len = static_cast<double>(static_cast<std::size_t>(r.chirp_duration_s * r.sample_rate_hz + 0.5));
  return static_cast<double>(kNumVirtual) * rho * rho * mean_rcs_m2 * len / noise_var;
}

}  // namespace mptrack::adc
