// Whitened in-band spectrum of one raw MIMO frame: the data vector the direct
// (track-before-detect) trackers work on (seed 004 eqs. (2)-(3);
// docs/algorithms/vmp.md §Signal model).
//
// Per virtual channel v (= m kNumRx + j, radar_cube.h) the kNumSamples fast-time
// samples of the single chirp are transformed by a UNITARY DFT of length
// N = kRangeFftSize (no zero padding: white noise stays white and unit-variance per
// bin after whitening), the K_B = Caps::kNumInBandBins bins around DC are kept,
//   k = -K_B/2 .. K_B/2 - 1,  f_k = k f_s / N  [Hz],
// and divided by sigma_w (noise std per complex sample):
//   z[v][k] = N^-1/2 sum_i y_v[i] exp(-j 2 pi (k mod N) i / N) / sigma_w.
// An echo a u(t - tau) then gives z[v][k] = (a / sigma_w) [a(theta)]_v U[k] exp(-j 2 pi f_k tau)
// with U the unitary DFT of the sampled reference chirp, the same chirp as the
// range matched filter's (range_matched_filter.h):
//   u[i] = exp(j pi kappa t_i^2),  t_i = (i - (L-1)/2) / f_s,  i = 0..L-1.
// Matched filtering in the frequency domain against U is then an inner product
// with z, and the noise is CN(0, 1) i.i.d. over (v, k) (model/mimo_atom.h).
//
// The DFT runs in float (dsp/fft.h, bit-exact on every target); z, U and f_k are
// stored as T (float on targets, double for the host reference). Planar storage,
// index v * K_B + (k + K_B/2).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/reference_chirp.h"
#include "mptrack/frontend/radar_cube.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack::frontend {

/// Waveform and noise the spectrum is built from (units in the names).
struct MimoSpectrumConfig {
  double bandwidth_hz = 20e6;        ///< chirp sweep BW [Hz]
  double chirp_duration_s = 3.6e-6;  ///< T_Tx [s]
  double sample_rate_hz = 32e6;      ///< f_s [Hz]
  double noise_variance_v2 = 0.0;    ///< sigma_w^2 per complex sample [V^2] (> 0)
};

template <class T, class Caps>
class MimoSpectrum {
  static_assert(radar_caps_are_valid<Caps>());
  static_assert(Caps::kNumChirps == 1, "the whitened spectrum is for one chirp per Tx per frame");

 public:
  static constexpr std::size_t kN = Caps::kRangeFftSize;
  static constexpr std::size_t kNumVirtual = Caps::kNumTx * Caps::kNumRx;
  static constexpr std::size_t kNumBins = Caps::kNumInBandBins;
  static constexpr std::size_t kSize = kNumVirtual * kNumBins;
  static_assert(kNumBins >= 2 && kNumBins % 2 == 0 && kNumBins <= kN, "K_B must be even and <= N");

  /// Builds U[k] and f_k. kInvalidArgument if a field is not positive/finite or the
  /// chirp (L = round(T_Tx f_s) samples) does not fit the slot.
  Status init(const MimoSpectrumConfig& c) {
    initialized_ = false;
    MPTRACK_TRY(check_positive(c.bandwidth_hz));
    MPTRACK_TRY(check_positive(c.chirp_duration_s));
    MPTRACK_TRY(check_positive(c.sample_rate_hz));
    MPTRACK_TRY(check_positive(c.noise_variance_v2));
    const std::size_t len = chirp_length(c.chirp_duration_s, c.sample_rate_hz);
    MPTRACK_TRY(check_range(len, 1, Caps::kNumSamples, "Caps::kNumSamples"));
    MPTRACK_TRY(fft_.init());
    const ReferenceChirp chirp(c.bandwidth_hz, c.chirp_duration_s, c.sample_rate_hz, len);
    const double inv_sqrt_n = 1.0 / std::sqrt(static_cast<double>(kN));
    const double two_pi = dmath::kTwoPi<double>;
    // Unitary DFT of the reference chirp, direct sum in double (init only).
    for (std::size_t b = 0; b < kNumBins; ++b) {
      const long k = static_cast<long>(b) - static_cast<long>(kNumBins / 2);
      const std::size_t kk = static_cast<std::size_t>((k + static_cast<long>(kN)) % static_cast<long>(kN));
      double sr = 0.0;
      double si = 0.0;
      for (std::size_t i = 0; i < len; ++i) {
        double uc = 1.0;
        double us = 0.0;
        chirp.sample(i, uc, us);
        // e^{-j 2 pi kk i / N}, argument reduced exactly with integers.
        double es = 0.0;
        double ec = 1.0;
        dmath::dsincos(-two_pi * static_cast<double>((kk * i) % kN) / static_cast<double>(kN), es, ec);
        sr += uc * ec - us * es;
        si += uc * es + us * ec;
      }
      u_re_[b] = static_cast<T>(sr * inv_sqrt_n);
      u_im_[b] = static_cast<T>(si * inv_sqrt_n);
      f_hz_[b] = static_cast<T>(static_cast<double>(k) * c.sample_rate_hz / static_cast<double>(kN));
    }
    scale_ = static_cast<float>(inv_sqrt_n / std::sqrt(c.noise_variance_v2));
    chirp_len_ = len;
    initialized_ = true;
    return Status::kOk;
  }

  /// z from a float cube. kNotInitialized before init(); kInvalidInput (z stale)
  /// if a sample is NaN/Inf.
  Status process(const RadarCube<Caps>& cube) {
    if (!initialized_) return Status::kNotInitialized;
    for (std::size_t v = 0; v < kNumVirtual; ++v) {
      const float* src = cube.iq.data() + RadarCube<Caps>::offset(0, v / Caps::kNumRx, v % Caps::kNumRx, 0);
      for (std::size_t i = 0; i < Caps::kNumSamples; ++i) {
        if (!is_finite(src[2 * i]) || !is_finite(src[2 * i + 1])) return Status::kInvalidInput;
        buf_re_[i] = src[2 * i];
        buf_im_[i] = src[2 * i + 1];
      }
      for (std::size_t i = Caps::kNumSamples; i < kN; ++i) {
        buf_re_[i] = 0.0f;
        buf_im_[i] = 0.0f;
      }
      fft_.forward(buf_re_.data(), buf_im_.data());
      for (std::size_t b = 0; b < kNumBins; ++b) {
        const std::size_t kk = (b + kN - kNumBins / 2) % kN;
        z_re_[v * kNumBins + b] = static_cast<T>(buf_re_[kk] * scale_);
        z_im_[v * kNumBins + b] = static_cast<T>(buf_im_[kk] * scale_);
      }
    }
    return Status::kOk;
  }

  /// Whitened data z[v][k], planar, index v * kNumBins + (k + kNumBins/2).
  const T* z_re() const { return z_re_.data(); }
  const T* z_im() const { return z_im_.data(); }
  /// Unitary DFT of the reference chirp at the kept bins (unit amplitude).
  const T* u_re() const { return u_re_.data(); }
  const T* u_im() const { return u_im_.data(); }
  /// Bin frequencies f_k [Hz].
  const T* f_hz() const { return f_hz_.data(); }
  std::size_t chirp_len() const { return chirp_len_; }
  bool initialized() const { return initialized_; }

 private:
  dsp::Fft<kN> fft_{};
  alignas(16) std::array<float, kN> buf_re_{};
  alignas(16) std::array<float, kN> buf_im_{};
  std::array<T, kSize> z_re_{};
  std::array<T, kSize> z_im_{};
  std::array<T, kNumBins> u_re_{};
  std::array<T, kNumBins> u_im_{};
  std::array<T, kNumBins> f_hz_{};
  float scale_ = 0.0f;  ///< N^-1/2 / sigma_w [1/V]
  std::size_t chirp_len_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack::frontend
