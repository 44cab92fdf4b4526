// One frame of raw TDM-MIMO ADC data (the front end's input).
//
// Layout (caller-provided, documented, no padding):
//   sample index  i = ((c * kNumTx + m) * kNumRx + j) * kNumSamples + s
//   c: chirp 0..kNumChirps-1 (slowest: hardware produces chirp by chirp)
//   m: Tx slot 0..kNumTx-1, j: Rx 0..kNumRx-1, s: fast-time sample (contiguous)
// The virtual channel is v = m * kNumRx + j, i.e. Tx spacing kNumRx * d and
// Rx spacing d for a filled virtual ULA of spacing d ("v = 3m + j";
// docs/algorithms/frontend.md §Frame input and checks).
// Each complex sample is interleaved (re, im); the array is 16-byte aligned.
//
// Int16 variant: raw ADC codes; sample value = code / 32768, so full scale
// is [-1, 1). The scale is a power of two, hence exact in float.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/frontend/radar_caps.h"

namespace mptrack::frontend {

/// Scale from int16 ADC code to float sample (exact: 2^-15).
inline constexpr float kInt16ToFloat = 1.0f / 32768.0f;

template <class Caps, class Sample>
struct RadarCubeT {
  static_assert(radar_caps_are_valid<Caps>());
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNumComplex = Caps::kNumChirps * kNumVirtual * Caps::kNumSamples;

  std::uint64_t time_us = 0;  ///< frame time [us]; copied to Scan::time_us
  alignas(16) std::array<Sample, 2 * kNumComplex> iq{};  ///< interleaved re, im

  /// Offset of the real part of sample s of (chirp c, Tx m, Rx j) in iq.
  static constexpr std::size_t offset(std::size_t c, std::size_t m, std::size_t j, std::size_t s) {
    return 2 * (((c * Caps::kNumTx + m) * Caps::kNumRx + j) * Caps::kNumSamples + s);
  }
};

/// Complex float cube (already scaled to volts or any linear unit).
template <class Caps>
using RadarCube = RadarCubeT<Caps, float>;

/// Raw int16 ADC cube (code / 32768 = sample value).
template <class Caps>
using RadarCubeInt16 = RadarCubeT<Caps, std::int16_t>;

}  // namespace mptrack::frontend
