// The VmpParams a raw-ADC scenario is tracked with (like frontend_config.h for
// the front end): waveform, array, path loss and noise from RadarSpec, so the
// tracker's atoms are the synthesiser's echoes; mean RCS from the drones (the
// amplitude prior scale, seed 004: lambda_alpha,p = 1 / E[sigma_RCS]); range gate
// and bearing span from FrontEndSpec; frame period from the scenario.
#pragma once

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/vmp/vmp_params.h"

namespace mptrack::adc {

inline VmpParams vmp_params_for(const AdcScenario& s) {
  VmpParams p;
  p.carrier_hz = s.radar.carrier_hz;
  p.bandwidth_hz = s.radar.bandwidth_hz;
  p.chirp_duration_s = s.radar.chirp_duration_s;
  p.sample_rate_hz = s.radar.sample_rate_hz;
  p.element_spacing_wavelengths = s.radar.element_spacing_wavelengths;
  p.tx_amplitude = s.radar.tx_amplitude;
  p.antenna_gain = s.radar.antenna_gain;
  // Same convention as FrameSynthesizer: k_b T0 times f_s (model A) or BW (literal).
  const double noise_bw = s.radar.noise_model == NoiseModel::kModelA ? s.radar.sample_rate_hz : s.radar.bandwidth_hz;
  p.noise_variance_v2 = kBoltzmann_J_per_K * s.radar.noise_temperature_k * noise_bw;
  if (!s.drones.empty()) p.mean_rcs_m2 = s.drones.front().mean_rcs_m2;
  p.min_range_m = s.frontend.min_range_m;
  p.max_range_m = s.frontend.max_range_m;
  p.max_abs_bearing_rad = s.frontend.max_abs_bearing_deg * (3.14159265358979323846 / 180.0);
  p.frame_period_s = s.frame_period_s;
  return p;
}

}  // namespace mptrack::adc
