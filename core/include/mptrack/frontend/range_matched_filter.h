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
#include "mptrack/dsp/fft_config.h"
#include "mptrack/frontend/frontend_params.h"
#include "mptrack/frontend/prefetch.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Sample tallies of one frame (docs/algorithms/frontend.md §Frame input and checks,
/// docs/reliability.md F2), counted by the range stage while it reads the cube: the frame is
/// streamed through memory once, not once to check it and once to compress it.
struct FrameTally {
  std::size_t zero = 0;          ///< sample values exactly 0
  std::size_t full_scale = 0;    ///< int16: at a rail (-32768, or >= the positive rail)
  std::size_t over_ceiling = 0;  ///< float: |x| > max_abs_sample (+-Inf included, NaN not)
  std::size_t nonfinite = 0;     ///< float: NaN or +-Inf
};

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
    ceiling_ = static_cast<float>(p.max_abs_sample);
    // Positive rail of a left-justified adc_bits ADC (32767 at 16 bits).
    positive_rail_ = static_cast<std::int16_t>(32768 - (std::int32_t{1} << (16 - p.adc_bits)));
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

  /// Compresses every (chirp, virtual channel) of the cube and tallies its
  /// samples (tally()). kNotInitialized before init(); kInvalidInput if a
  /// sample is NaN/Inf: the profiles holding one are not compressed (their
  /// outputs are stale, the caller discards the frame), the others are, so
  /// the tally covers the whole frame. Runs the widest copy this CPU has.
  template <class Sample>
  Status process(const RadarCubeT<Caps, Sample>& cube) {
    return process_copy(dsp::widest_fft_copy(), cube);
  }

  /// process() compiled for one ISA: on x86-64 hosts the FFT's copies
  /// (dsp/fft_config.h: baseline SSE2, AVX2, AVX-512, never FMA), so the
  /// de-interleaving load, the reference product and the calibrated store
  /// run as wide as the FFT does. Each element sees the same operations in
  /// every copy, so the same bits (tests/unit/frontend_range_test.cpp).
  /// A copy this build or CPU lacks falls back to the baseline.
  template <class Sample>
  Status process_copy(dsp::FftCopy copy, const RadarCubeT<Caps, Sample>& cube) {
    if (!initialized_) return Status::kNotInitialized;
    begin_frame();
    for (std::size_t v = 0; v < kNumVirtual; ++v) static_cast<void>(process_channel_copy(copy, cube, v));
    return tally_.nonfinite > 0 ? Status::kInvalidInput : Status::kOk;
  }

  /// Starts a frame processed channel by channel (process_channel()):
  /// clears the tallies.
  void begin_frame() { tally_ = FrameTally{}; }

  /// Compresses every chirp of virtual channel v (the rows [v][c][g]) and
  /// adds its samples to tally(). The front end runs the Doppler stage on
  /// the channel right after it, while its rows are still in cache
  /// (docs/algorithms/frontend.md §Range matched filter). kNotInitialized
  /// before init(), kInvalidArgument for v out of range, kInvalidInput if a
  /// sample of the frame so far is NaN/Inf (those profiles are not
  /// compressed). Runs the widest copy this CPU has.
  template <class Sample>
  Status process_channel(const RadarCubeT<Caps, Sample>& cube, std::size_t v) {
    return process_channel_copy(dsp::widest_fft_copy(), cube, v);
  }

  /// process_channel() compiled for one ISA (as process_copy()).
  template <class Sample>
  Status process_channel_copy(dsp::FftCopy copy, const RadarCubeT<Caps, Sample>& cube, std::size_t v) {
    if (!initialized_) return Status::kNotInitialized;
    if (v >= kNumVirtual) return Status::kInvalidArgument;
#if MPTRACK_FFT_X86_DISPATCH
    if (copy == dsp::FftCopy::kAvx512 && dsp::fft_copy_available(copy)) {
      process_avx512(cube, v);
    } else if (copy == dsp::FftCopy::kAvx2 && dsp::fft_copy_available(copy)) {
      process_avx2(cube, v);
    } else {
      process_chirps(cube, v);
    }
#else
    static_cast<void>(copy);
    process_chirps(cube, v);
#endif
    return tally_.nonfinite > 0 ? Status::kInvalidInput : Status::kOk;
  }

  /// Sample tallies of the frame since begin_frame() (or of the last
  /// process(); all zero before the first).
  const FrameTally& tally() const { return tally_; }

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
  /// The kNumRangeBins values of profile (c, v), contiguous (what the
  /// Doppler stage reads, 16 bins of every chirp at a time).
  const float* profile_re(std::size_t c, std::size_t v) const { return &out_re_[index(c, v, 0)]; }
  const float* profile_im(std::size_t c, std::size_t v) const { return &out_im_[index(c, v, 0)]; }
  /// Floats between adjacent profiles of one channel: kNumRangeBins plus one
  /// 64-byte line when there is a Doppler axis. The Doppler stage reads one
  /// line of every chirp's profile per block; at a stride of a whole number
  /// of 512-byte units those 2 x kNumChirps lines would share an eighth of the
  /// L1 sets and evict each other.
  static constexpr std::size_t kProfileStride = kNumRangeBins + (Caps::kNumChirps > 1 ? 16 : 0);
  /// Output layout [v][c][g]: one channel's profiles together (the unit the
  /// front end hands to the Doppler stage), each profile's bins contiguous.
  static constexpr std::size_t index(std::size_t c, std::size_t v, std::size_t g) {
    return (v * Caps::kNumChirps + c) * kProfileStride + g;
  }

  std::size_t chirp_len() const { return chirp_len_; }
  /// sum_i w[i]: peak amplitude of a unit-amplitude echo [-].
  float coherent_gain() const { return coherent_gain_; }
  /// sum_i w[i]^2: output noise variance per unit input noise variance [-].
  float noise_gain() const { return noise_gain_; }
  bool initialized() const { return initialized_; }

 private:
#if MPTRACK_FFT_X86_DISPATCH
  template <class Sample>
  __attribute__((target("avx2"), noinline)) void process_avx2(const RadarCubeT<Caps, Sample>& cube,
                                                              std::size_t v) {
    process_chirps(cube, v);
  }
  template <class Sample>
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void process_avx512(
      const RadarCubeT<Caps, Sample>& cube, std::size_t v) {
    process_chirps(cube, v);
  }
#endif

  // The chirps of channel v in order: in the cube its profiles are runs of
  // kNumSamples complex values, one per chirp, kNumVirtual profiles apart,
  // so the next chirp's run is prefetched during this one's FFTs (the
  // hardware prefetchers do not follow jumps of that size: prefetch.h).
  // The frame checks are tallied on the way (each sample is read once).
  // Every helper is force-inlined (MPTRACK_FFT_INLINE), so each copy
  // compiles all of it.
  template <class Sample>
  MPTRACK_FFT_INLINE void process_chirps(const RadarCubeT<Caps, Sample>& cube, std::size_t v) {
    constexpr std::size_t kProfile = 2 * Caps::kNumSamples;  // Sample values
    const Sample* src = cube.iq.data() + RadarCubeT<Caps, Sample>::offset(0, 0, 0, 0) + v * kProfile;
    constexpr std::size_t kChirpStride = kNumVirtual * kProfile;
    for (std::size_t c = 0; c < Caps::kNumChirps; ++c, src += kChirpStride) {
      if (c + 1 < Caps::kNumChirps) prefetch_read(src + kChirpStride, kProfile * sizeof(Sample));
      if (load(src)) compress(c, v);
    }
  }

  // De-interleaves one profile into buf_ and adds its samples to tally_;
  // false if it holds a NaN/Inf (not to be compressed). The tallies are
  // sums of comparisons and the NaN/Inf test is on the bit pattern
  // (exponent all ones), so the copy vectorises with no branch per sample.
  // Per profile the counts fit 32 bits (kNumSamples < 2^31).
  MPTRACK_FFT_INLINE bool load(const float* src) {
    std::uint32_t nonfinite = 0u;
    std::uint32_t zero = 0u;
    std::uint32_t over = 0u;
    const float hi = ceiling_;
    const float lo = -ceiling_;
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      const float re = src[2 * i];
      const float im = src[2 * i + 1];
      nonfinite += exponent_all_ones(re) + exponent_all_ones(im);
      zero += static_cast<std::uint32_t>(re == 0.0f) + static_cast<std::uint32_t>(im == 0.0f);
      over += static_cast<std::uint32_t>((re > hi) | (re < lo)) +
              static_cast<std::uint32_t>((im > hi) | (im < lo));
      buf_re_[i] = re;
      buf_im_[i] = im;
    }
    tally_.nonfinite += nonfinite;
    tally_.zero += zero;
    tally_.over_ceiling += over;
    if (nonfinite != 0u) return false;
    zero_tail();
    if (remove_dc_) subtract_mean();
    return true;
  }

  MPTRACK_FFT_INLINE bool load(const std::int16_t* src) {
    std::uint32_t zero = 0u;
    std::uint32_t rail = 0u;
    const std::int16_t top = positive_rail_;
    for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
      const std::int16_t re = src[2 * i];
      const std::int16_t im = src[2 * i + 1];
      zero += static_cast<std::uint32_t>(re == 0) + static_cast<std::uint32_t>(im == 0);
      rail += static_cast<std::uint32_t>((re == std::int16_t{-32768}) | (re >= top)) +
              static_cast<std::uint32_t>((im == std::int16_t{-32768}) | (im >= top));
      buf_re_[i] = static_cast<float>(re) * kInt16ToFloat;
      buf_im_[i] = static_cast<float>(im) * kInt16ToFloat;
    }
    tally_.zero += zero;
    tally_.full_scale += rail;
    zero_tail();
    if (remove_dc_) subtract_mean();
    return true;
  }

  // DC (static leakage) removal: subtract the complex mean of the
  // kNumSamples samples, accumulated in index order.
  MPTRACK_FFT_INLINE void subtract_mean() {
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

  MPTRACK_FFT_INLINE void zero_tail() {
    for (std::size_t i = Caps::kNumSamples; i < kM; ++i) {
      buf_re_[i] = 0.0f;
      buf_im_[i] = 0.0f;
    }
  }

  // 1 if x is NaN or +-Inf (IEEE 754 binary32: exponent field all ones).
  MPTRACK_FFT_INLINE static std::uint32_t exponent_all_ones(float x) {
    std::uint32_t u = 0;
    std::memcpy(&u, &x, sizeof u);
    return static_cast<std::uint32_t>((u & 0x7f800000u) == 0x7f800000u);
  }

  // Pulse compression of the profile in buf_, then the calibration multiply
  // (with c_v = 1 it reproduces the input bits) into the profile's
  // contiguous output run.
  MPTRACK_FFT_INLINE void compress(std::size_t c, std::size_t v) {
    fft_.forward(buf_re_.data(), buf_im_.data());
    for (std::size_t k = 0; k < kM; ++k) {
      const float yr = buf_re_[k];
      const float yi = buf_im_[k];
      buf_re_[k] = yr * ref_re_[k] - yi * ref_im_[k];
      buf_im_[k] = yr * ref_im_[k] + yi * ref_re_[k];
    }
    fft_.inverse(buf_re_.data(), buf_im_.data());
    const float cr = cal_re_[v];
    const float ci = cal_im_[v];
    float* __restrict dst_re = &out_re_[index(c, v, 0)];
    float* __restrict dst_im = &out_im_[index(c, v, 0)];
    for (std::size_t g = 0; g < kNumRangeBins; ++g) {
      dst_re[g] = buf_re_[g] * cr - buf_im_[g] * ci;
      dst_im[g] = buf_im_[g] * cr + buf_re_[g] * ci;
    }
  }

  dsp::Fft<kM> fft_{};
  std::array<float, kM> ref_re_{};  ///< conj(FFT(w u)) / M
  std::array<float, kM> ref_im_{};
  alignas(16) std::array<float, kM> buf_re_{};
  alignas(16) std::array<float, kM> buf_im_{};
  alignas(64) std::array<float, kNumProfiles * kProfileStride> out_re_{};
  alignas(64) std::array<float, kNumProfiles * kProfileStride> out_im_{};
  std::array<float, kNumVirtual> cal_re_{};
  std::array<float, kNumVirtual> cal_im_{};
  FrameTally tally_{};
  std::size_t chirp_len_ = 0;
  bool remove_dc_ = false;
  float ceiling_ = 1e6f;                ///< FrontEndParams::max_abs_sample
  std::int16_t positive_rail_ = 32767;  ///< int16 code of positive full scale (init: adc_bits)
  float coherent_gain_ = 0.0f;
  float noise_gain_ = 0.0f;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
