// The SblParams a raw-ADC scenario is processed with (the SBL detector of
// seed 004's detect-then-track baseline, docs/algorithms/sbl.md): waveform,
// array, transmit amplitude and noise variance from RadarSpec (so the atoms
// match the synthesised echoes), the mean RCS of the first drone (the atom
// scale only; 0.05 m^2 without drones), range gate and bearing span from
// FrontEndSpec (the same search region as the matched-filter front end).
#pragma once

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/sbl/sbl_params.h"

namespace mptrack::adc {

/// sigma_w^2 per complex sample [V^2] of the scenario's noise model.
inline double noise_variance_v2(const RadarSpec& r) {
  const double band = r.noise_model == NoiseModel::kModelA ? r.sample_rate_hz : r.bandwidth_hz;
  return kBoltzmann_J_per_K * r.noise_temperature_k * band;
}

inline SblParams sbl_params_for(const AdcScenario& s) {
  SblParams p;
  p.carrier_hz = s.radar.carrier_hz;
  p.bandwidth_hz = s.radar.bandwidth_hz;
  p.chirp_duration_s = s.radar.chirp_duration_s;
  p.sample_rate_hz = s.radar.sample_rate_hz;
  p.element_spacing_wavelengths = s.radar.element_spacing_wavelengths;
  p.tx_amplitude = s.radar.tx_amplitude;
  p.antenna_gain = s.radar.antenna_gain;
  p.noise_variance_v2 = noise_variance_v2(s.radar);
  p.mean_rcs_m2 = s.drones.empty() ? 0.05 : s.drones.front().mean_rcs_m2;
  p.min_range_m = s.frontend.min_range_m;
  p.max_range_m = s.frontend.max_range_m;
  p.max_abs_bearing_rad = s.frontend.max_abs_bearing_deg * (3.14159265358979323846 / 180.0);
  return p;
}

}  // namespace mptrack::adc
