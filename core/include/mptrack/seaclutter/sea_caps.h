// Compile-time sizes of the sea-clutter detection chain
// (docs/algorithms/sea_clutter.md §Detection chain). Memory per SeaDetector
// instance is dominated by the power map and the label grid:
// R * D * (4 + 2) bytes (96 x 512: 288 KiB), plus kMaxPlots patches of
// kPatchRangeBins * D bytes (64 x 2560 B = 160 KiB).
#pragma once

#include <cstddef>

namespace mptrack::seaclutter {

/// Seed 003 Sec. IV radar: 96 range bins, 512-pulse CPI, 5 x 512 patches.
struct SeaClutterCaps {
  static constexpr std::size_t kRangeBins = 96;        ///< range cells per CPI
  static constexpr std::size_t kDopplerBins = 512;     ///< pulses per CPI = FFT size (power of two)
  static constexpr std::size_t kPatchRangeBins = 5;    ///< patch height (odd, <= kRangeBins)
  static constexpr std::size_t kMaxPlots = 64;         ///< plots (and patches) per scan
  static constexpr std::size_t kMaxClusterCells = 4096;  ///< flood-fill queue of one cluster
};

}  // namespace mptrack::seaclutter
