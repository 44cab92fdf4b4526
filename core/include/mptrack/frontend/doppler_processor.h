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
//
// Batches (docs/algorithms/frontend.md §FFT): the kNumVirtual transforms of
// one range bin run together in an FftBatch, lane = channel. The range
// stage's [g][c][v] rows are the batch's input rows (one contiguous run per
// chirp) and each output row k is the snapshot run of cell (g, d(k)): no
// scatter on either side. Every lane gets the bits of Fft<N_c>::forward().
// The lanes are padded to a multiple of 8 (12 channels: 16 lanes), so every
// butterfly is whole 8- or 16-float vectors; the pad lanes hold zeros and are
// never read (measured, frontend/large: Doppler stage 0.52 -> 0.43 of the
// angle stage's time with padded lanes, against 0.50 unpadded; bench/README.md).
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/dsp/fft_batch.h"
#include "mptrack/frontend/frontend_params.h"
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
      MPTRACK_TRY(batch_.init());
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

  /// Reads the range profiles of rmf and fills the snapshots. Runs the
  /// widest copy this CPU has (process_copy).
  Status process(const RangeMatchedFilter<Caps>& rmf) {
    return process_copy(dsp::widest_fft_copy(), rmf);
  }

  /// process() compiled for one ISA (the FFT's copies, dsp/fft_config.h;
  /// never FMA): the window products and the fftshift row moves run as wide
  /// as the batch FFT does. Each element sees the same operation in every
  /// copy, so the same bits (tests/unit/frontend_doppler_test.cpp). A copy
  /// this build or CPU lacks falls back to the baseline.
  Status process_copy(dsp::FftCopy copy, const RangeMatchedFilter<Caps>& rmf) {
    if (!initialized_) return Status::kNotInitialized;
#if MPTRACK_FFT_X86_DISPATCH
    if (copy == dsp::FftCopy::kAvx512 && dsp::fft_copy_available(copy)) {
      process_avx512(rmf);
    } else if (copy == dsp::FftCopy::kAvx2 && dsp::fft_copy_available(copy)) {
      process_avx2(rmf);
    } else {
      process_bins(rmf);
    }
#else
    static_cast<void>(copy);
    process_bins(rmf);
#endif
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
#if MPTRACK_FFT_X86_DISPATCH
  __attribute__((target("avx2"), noinline)) void process_avx2(const RangeMatchedFilter<Caps>& rmf) {
    process_bins(rmf);
  }
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void process_avx512(
      const RangeMatchedFilter<Caps>& rmf) {
    process_bins(rmf);
  }
#endif

  // Every helper is force-inlined (MPTRACK_FFT_INLINE), so each copy
  // compiles all of it.
  MPTRACK_FFT_INLINE void process_bins(const RangeMatchedFilter<Caps>& rmf) {
    for (std::size_t g = 0; g < kNumRangeBins; ++g) {
      if constexpr (kHasDoppler) {
        transform(rmf.bin_re(g), rmf.bin_im(g), g);
      } else {  // one chirp: bin g's row is the snapshot of cell (g, 0)
        for (std::size_t v = 0; v < kNumVirtual; ++v) {
          snap_re_[g * kNumVirtual + v] = rmf.bin_re(g)[v];
          snap_im_[g * kNumVirtual + v] = rmf.bin_im(g)[v];
        }
      }
    }
  }

  // Lanes rounded up to a multiple of 8 (header); the extra lanes stay zero.
  static constexpr std::size_t kLanes = (kNumVirtual + 7) / 8 * 8;
  using Batch = dsp::FftBatch<(kNc > 1 ? kNc : 2), kLanes>;

  // Slow-time FFTs of range bin g (pr, pi: chirp c, channel v at
  // c * kNumVirtual + v): windowed rows w[c] x, one batch, and the fftshift
  // d = (k + kNc/2) mod kNc, whole rows. The real rows and the imaginary
  // rows are scaled in separate loops: interleaved in one loop, GCC 12
  // built each 12-value row from scalar loads and inserts (2 floats at a
  // time) instead of one 8- and one 4-wide load (bench/README.md session 15).
  MPTRACK_FFT_INLINE void transform(const float* pr, const float* pi, std::size_t g) {
    for (std::size_t c = 0; c < kNc; ++c) scale_row(pr + c * kNumVirtual, window_[c], batch_.input_re(c));
    for (std::size_t c = 0; c < kNc; ++c) scale_row(pi + c * kNumVirtual, window_[c], batch_.input_im(c));
    batch_.forward();
    float* sr = snap_re_.data() + g * kNc * kNumVirtual;
    float* si = snap_im_.data() + g * kNc * kNumVirtual;
    constexpr std::size_t kHalf = kNc / 2;
    for (std::size_t k = 0; k < kNc; ++k) {
      const std::size_t d = k < kHalf ? k + kHalf : k - kHalf;
      copy_row(batch_.output_re(k), sr + d * kNumVirtual);
      copy_row(batch_.output_im(k), si + d * kNumVirtual);
    }
  }

  MPTRACK_FFT_INLINE static void scale_row(const float* __restrict x, float w, float* __restrict y) {
    for (std::size_t v = 0; v < kNumVirtual; ++v) y[v] = x[v] * w;
  }
  MPTRACK_FFT_INLINE static void copy_row(const float* __restrict x, float* __restrict y) {
    for (std::size_t v = 0; v < kNumVirtual; ++v) y[v] = x[v];
  }

  Batch batch_{};
  std::array<float, kNc> window_{};
  std::array<float, kNumCells * kNumVirtual> snap_re_{};
  std::array<float, kNumCells * kNumVirtual> snap_im_{};
  double velocity_per_bin_mps_ = 0.0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
