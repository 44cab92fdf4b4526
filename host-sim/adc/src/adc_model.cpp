// ADC model; see adc_model.h.
#include "mptrack/adc/adc_model.h"

#include <cmath>

namespace mptrack::adc {

std::int16_t adc_code(double v_volts, const AdcModelSpec& adc, bool* clipped) {
  const double levels = std::ldexp(1.0, static_cast<int>(adc.bits) - 1);  // 2^(bits-1)
  const double x = v_volts / adc.full_scale_v * levels;
  double q = std::isnan(x) ? 0.0 : std::floor(x + 0.5);
  const bool clip = q < -levels || q > levels - 1.0;
  if (q < -levels) q = -levels;
  if (q > levels - 1.0) q = levels - 1.0;
  if (clipped != nullptr) *clipped = clip;
  const double shift = std::ldexp(1.0, 16 - static_cast<int>(adc.bits));  // 2^(16-bits)
  return static_cast<std::int16_t>(q * shift);  // exact: |q * shift| <= 32768, in range
}

std::size_t quantise(const AdcCube& volts, const AdcModelSpec& adc, AdcCube16& codes) {
  codes.time_us = volts.time_us;
  std::size_t n = 0;
  for (std::size_t i = 0; i < volts.iq.size(); ++i) {
    bool clip = false;
    codes.iq[i] = adc_code(static_cast<double>(volts.iq[i]), adc, &clip);
    if (clip) ++n;
  }
  return n;
}

void codes_to_volts(const AdcCube16& codes, const AdcModelSpec& adc, AdcCube& volts) {
  volts.time_us = codes.time_us;
  const float scale = static_cast<float>(adc.full_scale_v / 32768.0);
  for (std::size_t i = 0; i < codes.iq.size(); ++i) volts.iq[i] = static_cast<float>(codes.iq[i]) * scale;
}

std::size_t codes_at_rail(const AdcCube16& codes, std::uint32_t bits) {
  const std::int32_t positive = 32768 - (std::int32_t{1} << (16 - bits));
  std::size_t n = 0;
  for (const std::int16_t x : codes.iq) {
    if (x == -32768 || x >= positive) ++n;
  }
  return n;
}

bool frame_saturated(const AdcCube16& codes, const AdcModelSpec& adc) {
  // The front end's integer limit (FrontEnd::init): fraction x sample values, truncated.
  const auto limit = static_cast<std::size_t>(adc.saturation_fraction * static_cast<double>(codes.iq.size()));
  return codes_at_rail(codes, adc.bits) > limit;
}

}  // namespace mptrack::adc
