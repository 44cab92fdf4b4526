// The FrontEndParams a raw-ADC scenario is processed with: waveform and
// array from RadarSpec (so the reference chirp equals the synthesised one),
// gate, angle span, windows and CFAR from FrontEndSpec (names as in the JSON).
#pragma once

#include <string>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/frontend/frontend_params.h"

namespace mptrack::adc {

inline frontend::WindowType window_named(const std::string& w) {
  if (w == "hann") return frontend::WindowType::kHann;
  if (w == "hamming") return frontend::WindowType::kHamming;
  if (w == "blackman") return frontend::WindowType::kBlackman;
  return frontend::WindowType::kRectangular;
}

inline frontend::CfarType cfar_named(const std::string& t) {
  if (t == "go") return frontend::CfarType::kGreatestOf;
  if (t == "so") return frontend::CfarType::kSmallestOf;
  if (t == "os") return frontend::CfarType::kOrderedStatistic;
  return frontend::CfarType::kCellAveraging;
}

inline frontend::FrontEndParams frontend_params_for(const AdcScenario& s) {
  frontend::FrontEndParams p;
  p.carrier_hz = s.radar.carrier_hz;
  p.bandwidth_hz = s.radar.bandwidth_hz;
  p.chirp_duration_s = s.radar.chirp_duration_s;
  p.sample_rate_hz = s.radar.sample_rate_hz;
  p.element_spacing_wavelengths = s.radar.element_spacing_wavelengths;
  p.range_window = window_named(s.frontend.range_window);
  p.angle_window = window_named(s.frontend.angle_window);
  p.max_abs_bearing_rad = s.frontend.max_abs_bearing_deg * (3.14159265358979323846 / 180.0);
  p.min_range_m = s.frontend.min_range_m;
  p.max_range_m = s.frontend.max_range_m;
  p.cfar.type = cfar_named(s.frontend.cfar_type);
  p.cfar.edge = frontend::CfarEdge::kShift;
  p.cfar.pfa = s.frontend.cfar_pfa;
  p.cfar.guard_cells = s.frontend.cfar_guard_cells;
  p.cfar.training_cells = s.frontend.cfar_training_cells;
  // The int16 path's saturation test (float cubes never saturate).
  p.adc_bits = s.adc.bits;
  p.saturation_fraction = s.adc.saturation_fraction;
  return p;
}

}  // namespace mptrack::adc
