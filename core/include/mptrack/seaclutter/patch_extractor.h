// Range-Doppler patch of a plot for the classifier (seed 003 Sec. III-A
// step 5 and Sec. III-D): kPatchRangeBins range bins centred on the plot's
// range bin (shifted inside the map at the edges) x all kDopplerBins Doppler
// bins, as 8-bit codes of dB relative to the patch median
// (docs/algorithms/sea_clutter.md §Patch scaling):
//   code = clip(floor((10 log10(P / median) - floor_db) * 255 / span_db), 0, 255).
// Relative to the median so that the absolute level (radar calibration,
// clutter power, which differ between sea states and radars) does not reach
// the network, while the peak-to-background contrast that separates a
// target's narrow line from clutter's broad spectrum does.
// No logarithm at run time: init() tabulates the 255 code boundaries
// 10^((floor_db + k span_db / 255) / 10), k = 1..255, in double with
// mptrack::dmath; a cell's code is the number of boundaries b_k with
// P >= median * b_k (a binary search), identical on every target.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::seaclutter {

template <class Caps>
class PatchExtractor {
 public:
  static constexpr std::size_t kRows = Caps::kPatchRangeBins;
  static constexpr std::size_t kCols = Caps::kDopplerBins;
  static constexpr std::size_t kSize = kRows * kCols;
  static_assert(kRows % 2 == 1 && kRows <= Caps::kRangeBins, "odd patch height within the map");
  using Patch = std::array<std::uint8_t, kSize>;

  Status init(double floor_db, double span_db) {
    if (!(span_db > 0.0)) return Status::kInvalidArgument;
    for (std::size_t k = 1; k <= 255; ++k) {
      const double db = floor_db + static_cast<double>(k) * span_db / 255.0;
      bound_[k - 1] = static_cast<float>(mptrack::dmath::dexp(db / 10.0 * 2.302585092994046));
    }
    return Status::kOk;
  }

  /// First range bin of the patch around range bin `centre` (shifted inside).
  static std::size_t start_row(std::size_t centre) {
    const std::size_t half = kRows / 2;
    std::size_t start = centre >= half ? centre - half : 0;
    if (start + kRows > Caps::kRangeBins) start = Caps::kRangeBins - kRows;
    return start;
  }

  /// Patch rows start..start+kRows of `map` (power(m, d) accessor) into out,
  /// row-major [range][doppler].
  template <class Map>
  void extract(const Map& map, std::size_t start, Patch& out) {
    for (std::size_t r = 0; r < kRows; ++r) {
      for (std::size_t d = 0; d < kCols; ++d) scratch_[r * kCols + d] = map.power(start + r, d);
    }
    // Lower median (element kSize/2 - 1 of the sorted values): a value, so the
    // selection algorithm cannot change it.
    std::nth_element(scratch_.begin(), scratch_.begin() + (kSize / 2 - 1), scratch_.end());
    const float median = scratch_[kSize / 2 - 1];
    std::array<float, 255> thr;
    for (std::size_t k = 0; k < 255; ++k) thr[k] = median * bound_[k];
    for (std::size_t r = 0; r < kRows; ++r) {
      for (std::size_t d = 0; d < kCols; ++d) {
        const float p = map.power(start + r, d);
        // Number of thresholds <= p (thresholds ascend).
        std::size_t lo = 0;
        std::size_t hi = 255;
        while (lo < hi) {
          const std::size_t mid = (lo + hi) / 2;
          if (p >= thr[mid]) lo = mid + 1;
          else hi = mid;
        }
        out[r * kCols + d] = static_cast<std::uint8_t>(lo);
      }
    }
  }

 private:
  std::array<float, 255> bound_{};
  std::array<float, kSize> scratch_{};
};

}  // namespace mptrack::seaclutter
