// Range-Doppler power map of one CPI (seed 003 Sec. III-A step 1; the pulses
// are already range-compressed, so only the coherent integration is left):
// per range bin, taper the P pulses, P-point FFT, |X|^2, and fftshift so that
// zero Doppler is bin P/2 and bin d is f_D = (d - P/2) * PRF / P.
// Deterministic: core FFT and window tables (bit-exact on every target).
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/window.h"
#include "mptrack/status.h"

namespace mptrack::seaclutter {

template <class Caps>
class RangeDopplerMap {
 public:
  static constexpr std::size_t kRange = Caps::kRangeBins;
  static constexpr std::size_t kDoppler = Caps::kDopplerBins;

  Status init(frontend::WindowType window) {
    if (!frontend::is_valid_window(window)) return Status::kInvalidArgument;
    frontend::fill_window(window, window_.data(), kDoppler);
    MPTRACK_TRY(fft_.init());
    initialized_ = true;
    return Status::kOk;
  }

  /// Computes the map from planar samples re/im laid out [range][pulse]
  /// (kRange * kDoppler floats each). Non-finite input -> kInvalidInput.
  Status compute(const float* re, const float* im) {
    if (!initialized_) return Status::kNotInitialized;
    std::array<float, kDoppler> xr;
    std::array<float, kDoppler> xi;
    for (std::size_t m = 0; m < kRange; ++m) {
      const float* r = re + m * kDoppler;
      const float* i = im + m * kDoppler;
      for (std::size_t p = 0; p < kDoppler; ++p) {
        if (!(r[p] - r[p] == 0.0f) || !(i[p] - i[p] == 0.0f)) return Status::kInvalidInput;
        xr[p] = r[p] * window_[p];
        xi[p] = i[p] * window_[p];
      }
      fft_.forward(xr.data(), xi.data());
      float* row = power_[m].data();
      for (std::size_t k = 0; k < kDoppler; ++k) {
        const std::size_t d = (k + kDoppler / 2) % kDoppler;  // fftshift
        row[d] = xr[k] * xr[k] + xi[k] * xi[k];
      }
    }
    return Status::kOk;
  }

  /// Power of range bin m, Doppler bin d (fftshifted) [input units^2].
  float power(std::size_t m, std::size_t d) const { return power_[m][d]; }
  const float* row(std::size_t m) const { return power_[m].data(); }

 private:
  std::array<std::array<float, kDoppler>, kRange> power_{};
  std::array<float, kDoppler> window_{};
  dsp::Fft<kDoppler> fft_;
  bool initialized_ = false;
};

}  // namespace mptrack::seaclutter
