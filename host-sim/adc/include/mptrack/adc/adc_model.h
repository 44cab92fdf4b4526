// The receiver's ADC between the synthesised volts and the ring buffer
// (docs/algorithms/scenarios.md §ADC model; parameters: AdcModelSpec).
//
// Each of I and Q is quantised on its own by a `bits`-bit mid-tread
// quantiser with step lsb = full_scale_v / 2^(bits-1):
//   q = floor(v / lsb + 1/2), clipped to [-2^(bits-1), 2^(bits-1) - 1],
//   code = q * 2^(16 - bits)     (left-justified in int16)
// so code / 32768 = q lsb / full_scale_v, the core's int16 convention
// (frontend/radar_cube.h), and the rails are -32768 and
// 32768 - 2^(16 - bits), the front end's saturation test
// (FrontEndParams::adc_bits). Host-only.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/frontend/radar_cube.h"

namespace mptrack::adc {

/// The int16 frame a board's ADC DMA writes: raw codes.
using AdcCube16 = frontend::RadarCubeInt16<AdcCaps>;

/// The int16 code of one sample value v [V]; *clipped (if given) is set
/// when v lies beyond the rails (a NaN reads as 0 V).
std::int16_t adc_code(double v_volts, const AdcModelSpec& adc, bool* clipped = nullptr);

/// Quantises every sample of `volts` into `codes` (time_us copied).
/// Returns the number of sample values (I or Q) that clipped.
std::size_t quantise(const AdcCube& volts, const AdcModelSpec& adc, AdcCube16& codes);

/// Codes back to volts for the float-only stages (SBL detector, VMP):
/// v = code * full_scale_v / 32768, the quantised value.
void codes_to_volts(const AdcCube16& codes, const AdcModelSpec& adc, AdcCube& volts);

/// Sample values at a rail (-32768 or >= the positive rail): the count
/// the front end's saturation test compares with saturation_fraction.
std::size_t codes_at_rail(const AdcCube16& codes, std::uint32_t bits);

/// True when more than saturation_fraction of the frame's sample values are
/// at a rail (the front end's rule, frontend/front_end.h check_frame).
bool frame_saturated(const AdcCube16& codes, const AdcModelSpec& adc);

}  // namespace mptrack::adc
