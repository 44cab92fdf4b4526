// Stage 2: slow-time (Doppler) FFT across chirps, and the transpose into
// per-cell virtual-channel snapshots.
//
// For each virtual channel v and range bin g the kNumChirps range-profile
// values are windowed and transformed:
//   X_{v,g}[k] = sum_c w[c] r_{c,v}[g] exp(-j 2 pi k c / N_c)
// and stored fftshift-ed: Doppler index d = (k + N_c/2) mod N_c, so d = N_c/2
// is zero velocity and h = d - N_c/2 in [-N_c/2, N_c/2).
// Signal model (Doppler extension, docs/algorithms/frontend.md §Doppler): chirp c of a
// target with radial velocity v_r (positive = receding, range increasing) carries the phase
// exp(-j 4 pi v_r c T_c / lambda), so it peaks at
//   h = -2 v_r T_c N_c / lambda,  i.e.  v_r(h) = -h lambda / (2 N_c T_c).
// Unambiguous span |v_r| < lambda / (4 T_c). TDM intra-chirp Tx offsets are
// not compensated (docs/algorithms/frontend.md §Doppler: 0.023 rad per slot at 7 m/s;
// documented bias).
//
// With kNumChirps == 1 (seed 004) there is no FFT and no window: the stage
// only transposes, and d = 0 is the single Doppler bin (v_r = 0).
//
// Output layout (what the angle stage consumes): snapshot of cell (g, d) is
// kNumVirtual contiguous complex values, planar:
//   index ((g * kNumChirps) + d) * kNumVirtual + v.
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/prefetch.h"
#include "mptrack/frontend/range_matched_filter.h"
#include "mptrack/frontend/window.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

template <class Caps>
class DopplerProcessor {
  static_assert(radar_caps_are_valid<Caps>());

 public:
  static constexpr std::size_t kNc = Caps::kNumChirps;
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNumRangeBins = Caps::kNumRangeBins;
  static constexpr std::size_t kNumCells = kNumRangeBins * kNc;
  static constexpr bool kHasDoppler = (kNc > 1);

  Status init(const FrontEndParams& p) {
    initialized_ = false;
    MPTRACK_TRY(check(is_valid_window(p.doppler_window)));
    MPTRACK_TRY(check_positive(p.chirp_repetition_s));
    MPTRACK_TRY(check_positive(p.carrier_hz));
    if constexpr (kHasDoppler) {
      MPTRACK_TRY(fft_.init());
      fill_window(p.doppler_window, window_.data(), kNc);
    } else {
      window_[0] = 1.0f;
    }
    const double lambda = wavelength_m(p);
    velocity_per_bin_mps_ =
        -lambda / (2.0 * static_cast<double>(kNc) * p.chirp_repetition_s);
    initialized_ = true;
    return Status::kOk;
  }

  /// Reads the range profiles of rmf and fills the snapshots.
  Status process(const RangeMatchedFilter<Caps>& rmf) {
    if (!initialized_) return Status::kNotInitialized;
    // Range bin outer, channel inner: each transform reads its kNc chirps
    // as one run (the range stage's [v][g][c] layout) and the snapshots of
    // bin g (kNc x kNumVirtual values per plane) stay in L1 while the
    // kNumVirtual transforms fill them.
    for (std::size_t g = 0; g < kNumRangeBins; ++g) {
      for (std::size_t v = 0; v < kNumVirtual; ++v) {
        if constexpr (kHasDoppler) {
          // Next transform's run: the next channel (kNumRangeBins rows ahead)
          // or, after the last channel, channel 0 of the next range bin.
          const std::size_t v_next = v + 1 < kNumVirtual ? v + 1 : 0;
          const std::size_t g_next = v + 1 < kNumVirtual ? g : g + 1;
          if (g_next < kNumRangeBins) {
            prefetch_read(rmf.chirps_re(v_next, g_next), kNc * sizeof(float));
            prefetch_read(rmf.chirps_im(v_next, g_next), kNc * sizeof(float));
          }
          transform(rmf.chirps_re(v, g), rmf.chirps_im(v, g), g, v);
        } else {
          const std::size_t idx = g * kNumVirtual + v;
          snap_re_[idx] = rmf.value_re(0, v, g);
          snap_im_[idx] = rmf.value_im(0, v, g);
        }
      }
    }
    return Status::kOk;
  }

  /// Planar snapshot (kNumVirtual values) of range bin g, Doppler index d.
  const float* snapshot_re(std::size_t g, std::size_t d) const {
    return &snap_re_[(g * kNc + d) * kNumVirtual];
  }
  const float* snapshot_im(std::size_t g, std::size_t d) const {
    return &snap_im_[(g * kNc + d) * kNumVirtual];
  }

  /// Radial velocity of (possibly fractional) Doppler index d [m/s], positive receding.
  double velocity_mps(double d) const {
    if constexpr (!kHasDoppler) {
      static_cast<void>(d);
      return 0.0;
    } else {
      return (d - static_cast<double>(kNc / 2)) * velocity_per_bin_mps_;
    }
  }

  /// sum_c w[c] (coherent amplitude gain of the Doppler FFT).
  float coherent_gain() const {
    float s = 0.0f;
    for (std::size_t c = 0; c < kNc; ++c) s += window_[c];
    return s;
  }

  bool initialized() const { return initialized_; }

 private:
  // Slow-time FFT of channel v at range bin g: windowed copy (each element
  // w[c] x), one FFT, and the fftshift scatter d = (k + kNc/2) mod kNc as
  // two runs (no modulo per element).
  void transform(const float* pr, const float* pi, std::size_t g, std::size_t v) {
    for (std::size_t c = 0; c < kNc; ++c) {
      buf_re_[c] = pr[c] * window_[c];
      buf_im_[c] = pi[c] * window_[c];
    }
    fft_.forward(buf_re_.data(), buf_im_.data());
    float* sr = snap_re_.data() + g * kNc * kNumVirtual + v;
    float* si = snap_im_.data() + g * kNc * kNumVirtual + v;
    constexpr std::size_t kHalf = kNc / 2;
    for (std::size_t k = 0; k < kHalf; ++k) {
      sr[(k + kHalf) * kNumVirtual] = buf_re_[k];
      si[(k + kHalf) * kNumVirtual] = buf_im_[k];
    }
    for (std::size_t k = kHalf; k < kNc; ++k) {
      sr[(k - kHalf) * kNumVirtual] = buf_re_[k];
      si[(k - kHalf) * kNumVirtual] = buf_im_[k];
    }
  }

  dsp::Fft<(kNc > 1 ? kNc : 2)> fft_{};
  std::array<float, kNc> window_{};
  alignas(64) std::array<float, (kNc > 1 ? kNc : 1)> buf_re_{};
  alignas(64) std::array<float, (kNc > 1 ? kNc : 1)> buf_im_{};
  std::array<float, kNumCells * kNumVirtual> snap_re_{};
  std::array<float, kNumCells * kNumVirtual> snap_im_{};
  double velocity_per_bin_mps_ = 0.0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
