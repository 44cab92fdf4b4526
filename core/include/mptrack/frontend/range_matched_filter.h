// Stage 1: fast-time pulse compression (range matched filter) via FFT.
//
// For every chirp c and virtual channel v the range profile is the
// correlation of the received samples with the (windowed) transmitted chirp
//   r_{c,v}[g] = sum_i y_{c,v}[i + g] * w[i] * conj(u[i]),  g = 0..kNumRangeBins-1
// computed as IFFT( FFT(y) * conj(FFT(w u)) / M ) with M = kRangeFftSize
// (frequency-domain matched filter: docs/algorithms/frontend.md §Range matched filter).
// M is a power of two, so the 1/M folded into the reference is exact. The correlation is
// circular over M; it equals the linear one for g <= M - L (L = chirp
// samples), which holds for every kept bin when kNumRangeBins <= M - L + 1
// (checked in init()). Bin g is the two-way delay g / f_s, range g c / (2 f_s).
//
// Reference chirp (docs/algorithms/frontend.md §Range matched filter, centred so it
// sweeps -BW/2..+BW/2):
//   u[i] = exp(j pi kappa t_i^2),  t_i = (i - (L-1)/2) / f_s,  kappa = BW / T_Tx,
// i = 0..L-1, L = round(T_Tx f_s). An echo delayed by d samples,
// y[i] = a u[i - d], peaks at g = d with value a * sum_i w[i] (processing gain
// (sum w)^2 / sum w^2 over white noise; L for the rectangular window).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

template <class Caps>
class RangeMatchedFilter {
  static_assert(radar_caps_are_valid<Caps>());

 public:
  static constexpr std::size_t kM = Caps::kRangeFftSize;
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNumRangeBins = Caps::kNumRangeBins;
  static constexpr std::size_t kNumProfiles = Caps::kNumChirps * kNumVirtual;

  /// Validates the waveform part of p and builds the reference spectrum.
  /// kInvalidArgument if the chirp does not fit: 1 <= L and L + kNumRangeBins - 1 <= M
  /// and L <= kNumSamples.
  Status init(const FrontEndParams& p) {
    initialized_ = false;
    MPTRACK_TRY(check_positive(p.bandwidth_hz));
    MPTRACK_TRY(check_positive(p.chirp_duration_s));
    MPTRACK_TRY(check_positive(p.sample_rate_hz));
    MPTRACK_TRY(check(is_valid_window(p.range_window)));
    const std::size_t len = chirp_samples(p);
    MPTRACK_TRY(check(len >= 1 && len <= Caps::kNumSamples && len + kNumRangeBins - 1 <= kM));
    MPTRACK_TRY(fft_.init());
    chirp_len_ = len;
    remove_dc_ = p.remove_dc;
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      cal_re_[v] = 1.0f;
      cal_im_[v] = 0.0f;
    }
    const ReferenceChirp chirp(p.bandwidth_hz, p.chirp_duration_s, p.sample_rate_hz, len);
    for (std::size_t i = 0; i < kM; ++i) {
      ref_re_[i] = 0.0f;
      ref_im_[i] = 0.0f;
    }
    double sum_w = 0.0;
    double sum_w2 = 0.0;
    for (std::size_t i = 0; i < len; ++i) {
      double c = 1.0;
      double s = 0.0;
      chirp.sample(i, c, s);
      const double w = window_value(p.range_window, i, len);
      sum_w += w;
      sum_w2 += w * w;
      ref_re_[i] = static_cast<float>(w * c);
      ref_im_[i] = static_cast<float>(w * s);
    }
    coherent_gain_ = static_cast<float>(sum_w);
    noise_gain_ = static_cast<float>(sum_w2);
    fft_.forward(ref_re_.data(), ref_im_.data());
    // H[k] = conj(U_w[k]) / M (exact power-of-two scale).
    const float inv_m = 1.0f / static_cast<float>(kM);
    for (std::size_t k = 0; k < kM; ++k) {
      ref_re_[k] = ref_re_[k] * inv_m;
      ref_im_[k] = -(ref_im_[k] * inv_m);
    }
    initialized_ = true;
    return Status::kOk;
  }

  /// Compresses every (chirp, virtual channel) of the cube. kNotInitialized
  /// before init(); kInvalidInput (outputs untouched past the bad profile
  /// are left stale, the caller discards the frame) if a sample is NaN/Inf.
  template <class Sample>
  Status process(const RadarCubeT<Caps, Sample>& cube) {
    if (!initialized_) return Status::kNotInitialized;
    // Chirp outer, channel inner: the chirp's profiles are adjacent in the
    // cube (read as one stream), and its kNumRangeBins output runs of
    // kNumVirtual values complete while they are in L1.
    for (std::size_t c = 0; c < Caps::kNumChirps; ++c) {
      for (std::size_t v = 0; v < kNumVirtual; ++v) {
        MPTRACK_TRY(load(cube.iq.data() + RadarCubeT<Caps, Sample>::offset(c, 0, 0, 0) +
                         2 * v * Caps::kNumSamples));
        compress(c, v);
      }
    }
    return Status::kOk;
  }

  /// Compresses one profile given as planar float samples (kNumSamples
  /// each). Used by process() and by tests that bypass the cube.
  Status process_profile(const float* re, const float* im, std::size_t profile) {
    if (!initialized_) return Status::kNotInitialized;
    if (profile >= kNumProfiles) return Status::kInvalidArgument;
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      if (!is_finite(re[i]) || !is_finite(im[i])) return Status::kInvalidInput;
      buf_re_[i] = re[i];
      buf_im_[i] = im[i];
    }
    zero_tail();
    if (remove_dc_) subtract_mean();
    compress(profile / kNumVirtual, profile % kNumVirtual);
    return Status::kOk;
  }

  /// Per-virtual-channel complex calibration c_v (docs/algorithms/frontend.md §Range
  /// matched filter), applied to every range profile of channel v: r_v <- c_v r_v.
  /// init() resets it to 1. kInvalidArgument (calibration unchanged) if any value is NaN/Inf.
  Status set_channel_calibration(const std::array<float, kNumVirtual>& re,
                                 const std::array<float, kNumVirtual>& im) {
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      if (!is_finite(re[v]) || !is_finite(im[v])) return Status::kInvalidArgument;
    }
    cal_re_ = re;
    cal_im_ = im;
    return Status::kOk;
  }

  /// Range profile of (chirp c, virtual channel v) at range bin g.
  float value_re(std::size_t c, std::size_t v, std::size_t g) const { return out_re_[index(c, v, g)]; }
  float value_im(std::size_t c, std::size_t v, std::size_t g) const { return out_im_[index(c, v, g)]; }
  /// The kNumChirps x kNumVirtual values of range bin g, planar: (c, v) at
  /// c * kNumVirtual + v (what the Doppler stage transforms, a batch per bin).
  const float* bin_re(std::size_t g) const { return &out_re_[index(0, 0, g)]; }
  const float* bin_im(std::size_t g) const { return &out_im_[index(0, 0, g)]; }
  /// Floats between adjacent range bins: kNumChirps x kNumVirtual plus one
  /// 64-byte line when there is a Doppler axis. Without the pad the stores
  /// of one profile (stride 6 KiB at 128 chirps x 12 channels) would map to
  /// two groups of L1 sets only and evict each other before the chirp's
  /// other channels complete their lines (the pad of the earlier [v][g][c]
  /// layout was measured: 1.32 against 0.95-1.0 ms).
  static constexpr std::size_t kBinStride =
      Caps::kNumChirps * kNumVirtual + (Caps::kNumChirps > 1 ? 16 : 0);
  /// Output layout [g][c][v]: the channels of one (bin, chirp) contiguous,
  /// one input row of the Doppler stage's batch.
  static constexpr std::size_t index(std::size_t c, std::size_t v, std::size_t g) {
    return g * kBinStride + c * kNumVirtual + v;
  }

  std::size_t chirp_len() const { return chirp_len_; }
  /// sum_i w[i]: peak amplitude of a unit-amplitude echo [-].
  float coherent_gain() const { return coherent_gain_; }
  /// sum_i w[i]^2: output noise variance per unit input noise variance [-].
  float noise_gain() const { return noise_gain_; }
  bool initialized() const { return initialized_; }

 private:
  template <class Sample>
  Status load(const Sample* src) {
    if constexpr (std::is_same_v<Sample, float>) {
      // One flag for the whole profile instead of an exit per sample, and
      // the NaN/Inf test on the bit pattern (exponent all ones) instead of a
      // float compare per sample: integer and/compare/or, so the
      // de-interleaving copy vectorises; a bad profile is still refused
      // before compress().
      std::uint32_t nonfinite = 0u;
      for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
        const float re = src[2 * i];
        const float im = src[2 * i + 1];
        nonfinite |= exponent_all_ones(re) | exponent_all_ones(im);
        buf_re_[i] = re;
        buf_im_[i] = im;
      }
      if (nonfinite != 0u) return Status::kInvalidInput;
    } else {
      for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
        buf_re_[i] = static_cast<float>(src[2 * i]) * kInt16ToFloat;
        buf_im_[i] = static_cast<float>(src[2 * i + 1]) * kInt16ToFloat;
      }
    }
    zero_tail();
    if (remove_dc_) subtract_mean();
    return Status::kOk;
  }

  // DC (static leakage) removal: subtract the complex mean of the
  // kNumSamples samples, accumulated in index order.
  void subtract_mean() {
    float sr = 0.0f;
    float si = 0.0f;
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      sr += buf_re_[i];
      si += buf_im_[i];
    }
    const float mr = sr / static_cast<float>(Caps::kNumSamples);
    const float mi = si / static_cast<float>(Caps::kNumSamples);
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      buf_re_[i] -= mr;
      buf_im_[i] -= mi;
    }
  }

  void zero_tail() {
    for (std::size_t i = Caps::kNumSamples; i < kM; ++i) {
      buf_re_[i] = 0.0f;
      buf_im_[i] = 0.0f;
    }
  }

  // 1 if x is NaN or +-Inf (IEEE 754 binary32: exponent field all ones).
  static std::uint32_t exponent_all_ones(float x) {
    std::uint32_t u = 0;
    std::memcpy(&u, &x, sizeof u);
    return static_cast<std::uint32_t>((u & 0x7f800000u) == 0x7f800000u);
  }

  void compress(std::size_t c, std::size_t v) {
    fft_.forward(buf_re_.data(), buf_im_.data());
    for (std::size_t k = 0; k < kM; ++k) {
      const float yr = buf_re_[k];
      const float yi = buf_im_[k];
      buf_re_[k] = yr * ref_re_[k] - yi * ref_im_[k];
      buf_im_[k] = yr * ref_im_[k] + yi * ref_re_[k];
    }
    fft_.inverse(buf_re_.data(), buf_im_.data());
    float* dst_re = &out_re_[index(c, v, 0)];
    float* dst_im = &out_im_[index(c, v, 0)];
    // Calibration multiply; with c_v = 1 it reproduces the input bits.
    const float cr = cal_re_[v];
    const float ci = cal_im_[v];
    for (std::size_t g = 0; g < kNumRangeBins; ++g) {
      dst_re[g * kBinStride] = buf_re_[g] * cr - buf_im_[g] * ci;
      dst_im[g * kBinStride] = buf_im_[g] * cr + buf_re_[g] * ci;
    }
  }

  dsp::Fft<kM> fft_{};
  std::array<float, kM> ref_re_{};  ///< conj(FFT(w u)) / M
  std::array<float, kM> ref_im_{};
  alignas(16) std::array<float, kM> buf_re_{};
  alignas(16) std::array<float, kM> buf_im_{};
  std::array<float, kNumRangeBins * kBinStride> out_re_{};
  std::array<float, kNumRangeBins * kBinStride> out_im_{};
  std::array<float, kNumVirtual> cal_re_{};
  std::array<float, kNumVirtual> cal_im_{};
  std::size_t chirp_len_ = 0;
  bool remove_dc_ = false;
  float coherent_gain_ = 0.0f;
  float noise_gain_ = 0.0f;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
