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
// Output layout (what the angle stage consumes): channel-major rows of range
// bins, planar, index (d * kNumVirtual + v) * kNumRangeBins + g, so the
// angle stage's batch of adjacent range bins (dsp::FftBatch lanes) reads
// each (d, v) as one run; snapshot_value_re(g, d, v) / copy_snapshot() give
// one cell's kNumVirtual values.
//
// The slow-time transforms run as dsp::FftBatch over kBlock adjacent range
// bins of one channel: each lane gets the bits of Fft<kNc>::forward() on its
// windowed chirps, and output row k is the kBlock adjacent range bins of
// one (d, v) row of the snapshots.
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
  /// Range bins per batch of slow-time transforms (16 floats: one 64-byte line).
  static constexpr std::size_t kBlock = 16;

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

  /// Reads the range profiles of rmf and fills the snapshots.
  Status process(const RangeMatchedFilter<Caps>& rmf) {
    if (!initialized_) return Status::kNotInitialized;
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      if constexpr (kHasDoppler) {
        for (std::size_t g0 = 0; g0 < kNumRangeBins; g0 += kBlock) {
          const std::size_t lanes = kNumRangeBins - g0 < kBlock ? kNumRangeBins - g0 : kBlock;
          load_block(rmf, v, g0, lanes);
          batch_.forward();
          store_block(v, g0, lanes);
        }
      } else {
        for (std::size_t g = 0; g < kNumRangeBins; ++g) {
          snap_re_[index(g, 0, v)] = rmf.value_re(0, v, g);
          snap_im_[index(g, 0, v)] = rmf.value_im(0, v, g);
        }
      }
    }
    return Status::kOk;
  }

  /// Snapshot value of range bin g, Doppler index d, virtual channel v.
  float snapshot_value_re(std::size_t g, std::size_t d, std::size_t v) const {
    return snap_re_[index(g, d, v)];
  }
  float snapshot_value_im(std::size_t g, std::size_t d, std::size_t v) const {
    return snap_im_[index(g, d, v)];
  }
  /// Copies the kNumVirtual values of cell (g, d) to re[], im[].
  void copy_snapshot(std::size_t g, std::size_t d, float* re, float* im) const {
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      re[v] = snap_re_[index(g, d, v)];
      im[v] = snap_im_[index(g, d, v)];
    }
  }
  /// Channel v's values at Doppler index d for range bins 0..kNumRangeBins-1
  /// (one run: what the angle stage's batches read).
  const float* range_run_re(std::size_t d, std::size_t v) const { return &snap_re_[index(0, d, v)]; }
  const float* range_run_im(std::size_t d, std::size_t v) const { return &snap_im_[index(0, d, v)]; }

  static constexpr std::size_t index(std::size_t g, std::size_t d, std::size_t v) {
    return (d * kNumVirtual + v) * kNumRangeBins + g;
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
  // Lane l = range bin g0 + l of channel v: its windowed chirps (each
  // element w[c] x); input row c is one run of chirp c's range profile.
  void load_block(const RangeMatchedFilter<Caps>& rmf, std::size_t v, std::size_t g0,
                  std::size_t lanes) {
    for (std::size_t c = 0; c < kNc; ++c) {
      batch_.load_scaled(c, rmf.profile_re(c, v) + g0, rmf.profile_im(c, v) + g0, window_[c],
                         lanes);
    }
  }

  // Output row k to snapshot row (d = (k + kNc/2) mod kNc, v): one run of
  // range bins (fftshift without modulo).
  void store_block(std::size_t v, std::size_t g0, std::size_t lanes) {
    constexpr std::size_t kHalf = kNc / 2;
    for (std::size_t k = 0; k < kNc; ++k) {
      const std::size_t d = k < kHalf ? k + kHalf : k - kHalf;
      copy_run(batch_.output_re(k), batch_.output_im(k), &snap_re_[index(g0, d, v)],
               &snap_im_[index(g0, d, v)], lanes);
    }
  }

  // __restrict parameters so GCC emits vector copies.
  static void copy_run(const float* __restrict re, const float* __restrict im,
                       float* __restrict out_re, float* __restrict out_im, std::size_t lanes) {
    if (lanes == kBlock) {
      for (std::size_t l = 0; l < kBlock; ++l) {
        out_re[l] = re[l];
        out_im[l] = im[l];
      }
    } else {
      for (std::size_t l = 0; l < lanes; ++l) {
        out_re[l] = re[l];
        out_im[l] = im[l];
      }
    }
  }

  dsp::FftBatch<(kNc > 1 ? kNc : 2), (kNc > 1 ? kBlock : 1)> batch_{};
  std::array<float, kNc> window_{};
  std::array<float, kNumCells * kNumVirtual> snap_re_{};
  std::array<float, kNumCells * kNumVirtual> snap_im_{};
  double velocity_per_bin_mps_ = 0.0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
