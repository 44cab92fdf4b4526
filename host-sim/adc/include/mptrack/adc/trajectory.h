// Drone truth per frame (docs/algorithms/scenarios.md §Seed 004): positions follow the
// discrete recursion p_{n+1} = p_n + v_n dt, and within a leg of S steps
// the velocity after s steps is v_start + (v_end - v_start) s / S.
// With this convention tracks 1 and 2 are 0.21 m apart at n = 22
// (docs/algorithms/scenarios.md §Seed 004: 0.21-0.26 m depending on the discretisation).
#pragma once

#include <cstdint>

#include "mptrack/adc/adc_scenario.h"

namespace mptrack::adc {

struct DroneState {
  double x = 0.0, y = 0.0;    ///< [m]
  double vx = 0.0, vy = 0.0;  ///< [m/s]
};

/// State of `d` at frame n (any n >= birth_frame; lifetime is not checked).
DroneState drone_state_at(const DroneSpec& d, std::uint32_t frame, double frame_period_s);

/// Mean component SNR over the 9 virtual channels, linear (SNR_c of
/// docs/algorithms/scenarios.md §Seed 004):
/// N_V |rho(r)|^2 E[sigma] L / sigma_w^2, L = chirp samples at f_s.
double mean_component_snr(const AdcScenario& s, double range_m, double mean_rcs_m2);

}  // namespace mptrack::adc
