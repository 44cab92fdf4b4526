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
// Output layout (what the angle stage consumes): for each channel v and
// Doppler index d, the kNumRangeBins values of every range bin, contiguous
// ("rows", planar): index (v * kNumChirps + d) * kNumRangeBins + g.
//
// Batches (docs/algorithms/frontend.md §FFT): the transforms of 16 adjacent
// range bins of one channel run together in an FftBatch, lane = range bin.
// Input row c is 16 adjacent bins of the range stage's profile (c, v) (one
// 64-byte run) times w[c]; output row k is the same 16 bins of snapshot row
// (v, d(k)). No transposes on either side, and every lane does useful work
// (the earlier lane = channel batch padded 12 channels to 16 lanes). Every
// lane gets the bits of Fft<N_c>::forward(). The front end calls
// process_channel() right after the range stage has compressed that
// channel, so its 2 x N_c profiles are read from cache.
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

  /// The snapshot rows of channel v alone (the front end interleaves this
  /// with the range stage, channel by channel). kInvalidArgument for v out
  /// of range.
  Status process_channel(const RangeMatchedFilter<Caps>& rmf, std::size_t v) {
    return process_channel_copy(dsp::widest_fft_copy(), rmf, v);
  }

  /// process() compiled for one ISA (the FFT's copies, dsp/fft_config.h;
  /// never FMA): the window products and the fftshift row moves run as wide
  /// as the batch FFT does. Each element sees the same operation in every
  /// copy, so the same bits (tests/unit/frontend_doppler_test.cpp). A copy
  /// this build or CPU lacks falls back to the baseline.
  Status process_copy(dsp::FftCopy copy, const RangeMatchedFilter<Caps>& rmf) {
    if (!initialized_) return Status::kNotInitialized;
    for (std::size_t v = 0; v < kNumVirtual; ++v) static_cast<void>(process_channel_copy(copy, rmf, v));
    return Status::kOk;
  }

  /// process_channel() compiled for one ISA (as process_copy()).
  Status process_channel_copy(dsp::FftCopy copy, const RangeMatchedFilter<Caps>& rmf, std::size_t v) {
    if (!initialized_) return Status::kNotInitialized;
    if (v >= kNumVirtual) return Status::kInvalidArgument;
#if MPTRACK_FFT_X86_DISPATCH
    if (copy == dsp::FftCopy::kAvx512 && dsp::fft_copy_available(copy)) {
      process_avx512(rmf, v);
    } else if (copy == dsp::FftCopy::kAvx2 && dsp::fft_copy_available(copy)) {
      process_avx2(rmf, v);
    } else {
      process_blocks(rmf, v);
    }
#else
    static_cast<void>(copy);
    process_blocks(rmf, v);
#endif
    return Status::kOk;
  }

  /// Snapshot value of channel v at range bin g, Doppler index d.
  float snapshot_re(std::size_t g, std::size_t d, std::size_t v) const { return snap_re_[index(v, d, g)]; }
  float snapshot_im(std::size_t g, std::size_t d, std::size_t v) const { return snap_im_[index(v, d, g)]; }
  /// Row (v, d): the kNumRangeBins values of channel v at Doppler index d,
  /// contiguous in g (the angle stage's input rows).
  const float* row_re(std::size_t v, std::size_t d) const { return &snap_re_[index(v, d, 0)]; }
  const float* row_im(std::size_t v, std::size_t d) const { return &snap_im_[index(v, d, 0)]; }
  static constexpr std::size_t index(std::size_t v, std::size_t d, std::size_t g) {
    return (v * kNc + d) * kNumRangeBins + g;
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
  __attribute__((target("avx2"), noinline)) void process_avx2(const RangeMatchedFilter<Caps>& rmf,
                                                              std::size_t v) {
    process_blocks(rmf, v);
  }
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void process_avx512(
      const RangeMatchedFilter<Caps>& rmf, std::size_t v) {
    process_blocks(rmf, v);
  }
#endif

  /// Range bins per batch (16 floats: one 64-byte line per row).
  static constexpr std::size_t kBlock = 16;
  using Batch = dsp::FftBatch<(kNc > 1 ? kNc : 2), kBlock>;

  // Every helper is force-inlined (MPTRACK_FFT_INLINE), so each copy
  // compiles all of it.
  MPTRACK_FFT_INLINE void process_blocks(const RangeMatchedFilter<Caps>& rmf, std::size_t v) {
    if constexpr (kHasDoppler) {
      for (std::size_t g0 = 0; g0 < kNumRangeBins; g0 += kBlock) {
        const std::size_t lanes = kNumRangeBins - g0 < kBlock ? kNumRangeBins - g0 : kBlock;
        transform(rmf, v, g0, lanes);
      }
    } else {  // one chirp: profile (0, v) is snapshot row (v, 0)
      const float* pr = rmf.profile_re(0, v);
      const float* pi = rmf.profile_im(0, v);
      for (std::size_t g = 0; g < kNumRangeBins; ++g) {
        snap_re_[index(v, 0, g)] = pr[g];
        snap_im_[index(v, 0, g)] = pi[g];
      }
    }
  }

  // Slow-time FFTs of range bins g0..g0+lanes of channel v: windowed rows
  // w[c] r_c (lanes past the last bin of a partial block hold zeros), one
  // batch, and the fftshift d = (k + kNc/2) mod kNc, whole rows. The real
  // and the imaginary rows are scaled in separate loops: interleaved in one
  // loop, GCC 12 built each row from scalar loads and inserts.
  MPTRACK_FFT_INLINE void transform(const RangeMatchedFilter<Caps>& rmf, std::size_t v, std::size_t g0,
                                    std::size_t lanes) {
    if (lanes == kBlock) {
      for (std::size_t c = 0; c < kNc; ++c) scale_row(rmf.profile_re(c, v) + g0, window_[c], batch_.input_re(c));
      for (std::size_t c = 0; c < kNc; ++c) scale_row(rmf.profile_im(c, v) + g0, window_[c], batch_.input_im(c));
    } else {
      for (std::size_t c = 0; c < kNc; ++c) {
        float* yr = batch_.input_re(c);
        float* yi = batch_.input_im(c);
        for (std::size_t l = 0; l < kBlock; ++l) {
          yr[l] = l < lanes ? rmf.profile_re(c, v)[g0 + l] * window_[c] : 0.0f;
          yi[l] = l < lanes ? rmf.profile_im(c, v)[g0 + l] * window_[c] : 0.0f;
        }
      }
    }
    batch_.forward();
    constexpr std::size_t kHalf = kNc / 2;
    for (std::size_t k = 0; k < kNc; ++k) {
      const std::size_t d = k < kHalf ? k + kHalf : k - kHalf;
      float* sr = &snap_re_[index(v, d, g0)];
      float* si = &snap_im_[index(v, d, g0)];
      if (lanes == kBlock) {
        copy_row(batch_.output_re(k), sr);
        copy_row(batch_.output_im(k), si);
      } else {
        for (std::size_t l = 0; l < lanes; ++l) {
          sr[l] = batch_.output_re(k)[l];
          si[l] = batch_.output_im(k)[l];
        }
      }
    }
  }

  MPTRACK_FFT_INLINE static void scale_row(const float* __restrict x, float w, float* __restrict y) {
    for (std::size_t l = 0; l < kBlock; ++l) y[l] = x[l] * w;
  }
  MPTRACK_FFT_INLINE static void copy_row(const float* __restrict x, float* __restrict y) {
    for (std::size_t l = 0; l < kBlock; ++l) y[l] = x[l];
  }

  Batch batch_{};
  std::array<float, kNc> window_{};
  alignas(64) std::array<float, kNumCells * kNumVirtual> snap_re_{};
  alignas(64) std::array<float, kNumCells * kNumVirtual> snap_im_{};
  double velocity_per_bin_mps_ = 0.0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
