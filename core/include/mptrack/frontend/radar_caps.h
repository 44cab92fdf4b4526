// Compile-time capacity traits of the MIMO radar front end.
//
// A front-end caps type is a struct with the static members below; every
// buffer of the front end is sized from it (README.md §Conventions a firmware engineer
// can rely on).
// Run-time tunables (chirp, windows, CFAR) live in FrontEndParams instead.
#pragma once

#include <cstddef>

#include "mptrack/dsp/fft.h"

namespace mptrack::frontend {

/// Seed 004 (docs/algorithms/frontend.md §Departures from the paper): 3x3 TDM MIMO, one
/// chirp per Tx per frame (no Doppler axis), 8 us slot at 32 MHz = 256 fast-time samples.
struct Seed004RadarCaps {
  static constexpr std::size_t kNumTx = 3;           ///< transmitters (TDM slots per chirp)
  static constexpr std::size_t kNumRx = 3;           ///< receivers
  static constexpr std::size_t kNumSamples = 256;    ///< fast-time samples per Tx slot
  static constexpr std::size_t kRangeFftSize = 256;  ///< range FFT length (>= kNumSamples, power of 2)
  static constexpr std::size_t kNumRangeBins = 64;   ///< range bins kept after the matched filter
  static constexpr std::size_t kNumChirps = 1;       ///< chirps per Tx per frame (1: no Doppler FFT)
  static constexpr std::size_t kNumAngleBins = 64;   ///< angle FFT length (zero-padded beams)
  static constexpr std::size_t kMaxDetections = 64;  ///< measurements per frame
  /// In-band fast-time DFT bins kept by the whitened spectrum (mimo_spectrum.h):
  /// k = -96..95 at 125 kHz, +-12 MHz around the 20 MHz chirp (99.4 % of its energy).
  static constexpr std::size_t kNumInBandBins = 192;
};

/// A Doppler-capable automotive-class configuration (benchmark size):
/// 3 Tx x 4 Rx = 12 virtual channels, 256 samples, 128 chirps.
struct LargeRadarCaps {
  static constexpr std::size_t kNumTx = 3;
  static constexpr std::size_t kNumRx = 4;
  static constexpr std::size_t kNumSamples = 256;
  static constexpr std::size_t kRangeFftSize = 256;
  static constexpr std::size_t kNumRangeBins = 128;
  static constexpr std::size_t kNumChirps = 128;
  static constexpr std::size_t kNumAngleBins = 32;
  static constexpr std::size_t kMaxDetections = 256;
};

/// A small Doppler configuration used by the unit tests (fast under qemu).
struct SmallDopplerRadarCaps {
  static constexpr std::size_t kNumTx = 2;
  static constexpr std::size_t kNumRx = 4;
  static constexpr std::size_t kNumSamples = 64;
  static constexpr std::size_t kRangeFftSize = 64;
  static constexpr std::size_t kNumRangeBins = 32;
  static constexpr std::size_t kNumChirps = 16;
  static constexpr std::size_t kNumAngleBins = 32;
  static constexpr std::size_t kMaxDetections = 16;
};

/// Compile-time validation; every front-end component static_asserts it.
template <class Caps>
constexpr bool radar_caps_are_valid() {
  static_assert(Caps::kNumTx >= 1 && Caps::kNumRx >= 1, "need at least one Tx and one Rx");
  static_assert(Caps::kNumSamples >= 2, "need at least two fast-time samples");
  static_assert(dsp::is_power_of_two(Caps::kRangeFftSize) && Caps::kRangeFftSize >= Caps::kNumSamples,
                "kRangeFftSize must be a power of two >= kNumSamples");
  static_assert(Caps::kNumRangeBins >= 3 && Caps::kNumRangeBins <= Caps::kRangeFftSize,
                "3 <= kNumRangeBins <= kRangeFftSize");
  static_assert(Caps::kNumChirps == 1 || dsp::is_power_of_two(Caps::kNumChirps),
                "kNumChirps must be 1 (no Doppler) or a power of two");
  // >= 2 N_V: the angle refinement searches +-1 grid step around the FFT
  // peak, which must stay inside the main lobe (half-width 1 / (N_V d)).
  static_assert(dsp::is_power_of_two(Caps::kNumAngleBins) &&
                    Caps::kNumAngleBins >= 2 * Caps::kNumTx * Caps::kNumRx,
                "kNumAngleBins must be a power of two >= 2 x the number of virtual channels");
  static_assert(Caps::kMaxDetections >= 1 && Caps::kMaxDetections <= 65535,
                "1 <= kMaxDetections <= 65535");
  return true;
}

}  // namespace mptrack::frontend
