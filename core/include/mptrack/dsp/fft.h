// Fixed-size complex FFT, float, bit-exact across targets.
//
// Why our own: the front end must give the same bits on x86-64, aarch64,
// armhf and Cortex-M (developers' guide rule 2). Library FFTs choose
// codelets and reduction orders per ISA at run time (FFTW plans, CMSIS
// per-core kernels), so their outputs differ in the last bits.
//
// Algorithm: iterative decimation in time (Cooley-Tukey), in place, with the
// radix-2 stages fused in pairs (radix-2^2: one radix-2 stage first when
// log2 N is odd, then radix-4 passes), on planar (split) complex data: one
// float array for the real parts, one for the imaginary parts. Planar storage lets the compiler vectorise the
// butterfly loops without reassociating anything (it only widens the same
// scalar operations), so vectorised and scalar builds round identically.
// Each stage uses its own contiguous twiddle run, w_s[j] = exp(-j 2 pi j / 2h)
// for the stage of half-size h, so the inner loop is unit stride.
//
// Twiddles are computed once in init() in double with mptrack::dmath
// (no libm), then rounded to float, so the table is identical everywhere.
// The complex multiply is written as four real products (never
// std::complex, whose operator* may call __mulsc3).
//
// Scaling: forward() computes X[k] = sum_n x[n] exp(-j 2 pi k n / N) and
// inverse() computes x[n] = sum_k X[k] exp(+j 2 pi k n / N), both unscaled
// (so inverse(forward(x)) = N x). inverse() is forward() with the real and
// imaginary arrays swapped: conj(FFT(conj(x))) expressed as a swap, which is
// exact.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::dsp {

/// Compile-time check: n is a power of two >= 2.
constexpr bool is_power_of_two(std::size_t n) { return n >= 2 && (n & (n - 1)) == 0; }

/// log2 of a power of two.
constexpr std::size_t log2_exact(std::size_t n) {
  std::size_t l = 0;
  while ((std::size_t{1} << l) < n) ++l;
  return l;
}

/// Radix-2^2 FFT of fixed length N (a power of two, 2..65536).
/// Footprint: 2 N floats of twiddles + N 16-bit bit-reversal swap indices.
template <std::size_t N>
class Fft {
  static_assert(is_power_of_two(N), "Fft length must be a power of two >= 2");
  static_assert(N <= 65536, "Fft length above 65536 is not supported");

 public:
  static constexpr std::size_t kSize = N;
  static constexpr std::size_t kLog2 = log2_exact(N);

  /// Builds the twiddle and bit-reversal tables. Always kOk; returns a
  /// Status so every component's init() chains the same way.
  Status init() {
    // Per-stage twiddles: stage with half-size h stores w[j] = exp(-j 2 pi j/(2h))
    // at offset h - 1 (h = 1, 2, 4, ..., N/2; offsets 0, 1, 3, ..., total N - 1).
    constexpr double kTwoPi = mptrack::dmath::kTwoPi<double>;
    for (std::size_t h = 1; h < N; h <<= 1) {
      for (std::size_t j = 0; j < h; ++j) {
        // Exact symmetries first, so tw(0)=1, tw(h/2)=-j are exact in float.
        double s = 0.0;
        double c = 1.0;
        if (j != 0) {
          const double angle = -kTwoPi * static_cast<double>(j) / static_cast<double>(2 * h);
          mptrack::dmath::dsincos(angle, s, c);
          if (2 * j == h) {  // angle = -pi/2
            s = -1.0;
            c = 0.0;
          }
        }
        tw_re_[h - 1 + j] = static_cast<float>(c);
        tw_im_[h - 1 + j] = static_cast<float>(s);
      }
    }
    tw_re_[N - 1] = 0.0f;  // unused slot, defined for determinism
    tw_im_[N - 1] = 0.0f;
    // Bit-reversal permutation as a list of swaps (i < rev(i)), so the
    // permutation loop has no branch.
    num_swaps_ = 0;
    for (std::size_t i = 0; i < N; ++i) {
      std::size_t r = 0;
      for (std::size_t b = 0; b < kLog2; ++b) {
        if ((i >> b) & 1u) r |= std::size_t{1} << (kLog2 - 1 - b);
      }
      if (r > i) {
        swap_a_[num_swaps_] = static_cast<Index>(i);
        swap_b_[num_swaps_] = static_cast<Index>(r);
        ++num_swaps_;
      }
    }
    initialized_ = true;
    return Status::kOk;
  }

  bool initialized() const { return initialized_; }

  /// In-place forward DFT of planar data re[0..N), im[0..N). Unscaled.
  /// Precondition: init() succeeded (checked by the owning stage's init()).
  void forward(float* re, float* im) const {
    permute(re, im);
    std::size_t h = 1;
    if constexpr (kLog2 % 2 == 1) {
      radix2_first(re, im);
      h = 2;
    } else {
      radix4_first(re, im);
      h = 4;
    }
    for (; h < N; h *= 4) radix4_pass(re, im, h);
  }

  /// In-place inverse DFT (unscaled): the forward transform with re/im swapped.
  void inverse(float* re, float* im) const { forward(im, re); }

  /// Read-only twiddle access for tests: w = exp(-j 2 pi j / (2h)), h a power of two < N.
  float twiddle_re(std::size_t h, std::size_t j) const { return tw_re_[h - 1 + j]; }
  float twiddle_im(std::size_t h, std::size_t j) const { return tw_im_[h - 1 + j]; }

 private:
  // Stage of half-size 1 (twiddle 1): no multiplies.
  static void radix2_first(float* re, float* im) {
    for (std::size_t a = 0; a < N; a += 2) {
      const float tr = re[a + 1];
      const float ti = im[a + 1];
      re[a + 1] = re[a] - tr;
      im[a + 1] = im[a] - ti;
      re[a] = re[a] + tr;
      im[a] = im[a] + ti;
    }
  }

  // Stages of half-size 1 and 2 fused (twiddles 1 and -j): no multiplies.
  static void radix4_first(float* re, float* im) {
    for (std::size_t a = 0; a < N; a += 4) {
      const float b0r = re[a] + re[a + 1];
      const float b0i = im[a] + im[a + 1];
      const float b1r = re[a] - re[a + 1];
      const float b1i = im[a] - im[a + 1];
      const float b2r = re[a + 2] + re[a + 3];
      const float b2i = im[a + 2] + im[a + 3];
      const float b3r = re[a + 2] - re[a + 3];
      const float b3i = im[a + 2] - im[a + 3];
      re[a] = b0r + b2r;
      im[a] = b0i + b2i;
      re[a + 2] = b0r - b2r;
      im[a + 2] = b0i - b2i;
      // -j * b3 = (b3i, -b3r)
      re[a + 1] = b1r + b3i;
      im[a + 1] = b1i - b3r;
      re[a + 3] = b1r - b3i;
      im[a + 3] = b1i + b3r;
    }
  }

  // Two radix-2 DIT stages (half-sizes h and 2h) fused into one pass over
  // the data (radix-2^2): per group of four points, 3 complex multiplies
  // instead of 4 and half the memory traffic. The second-stage twiddle of
  // the odd pair is W_{4h}^{j+h} = -j W_{4h}^j, applied exactly as a swap.
  void radix4_pass(float* re, float* im, std::size_t h) const {
    const float* w1r = &tw_re_[h - 1];      // W_{2h}^j
    const float* w1i = &tw_im_[h - 1];
    const float* w2r = &tw_re_[2 * h - 1];  // W_{4h}^j
    const float* w2i = &tw_im_[2 * h - 1];
    for (std::size_t base = 0; base < N; base += 4 * h) {
      // The eight runs [0, h) are disjoint: __restrict lets the compiler
      // vectorise without run-time overlap checks (it does not change the
      // arithmetic, so results are the same bits).
      float* __restrict r0 = re + base;
      float* __restrict i0 = im + base;
      float* __restrict r1 = re + base + h;
      float* __restrict i1 = im + base + h;
      float* __restrict r2 = re + base + 2 * h;
      float* __restrict i2 = im + base + 2 * h;
      float* __restrict r3 = re + base + 3 * h;
      float* __restrict i3 = im + base + 3 * h;
      for (std::size_t j = 0; j < h; ++j) {
        // Stage h: (a0, a1) and (a2, a3) with w1.
        const float t1r = w1r[j] * r1[j] - w1i[j] * i1[j];
        const float t1i = w1r[j] * i1[j] + w1i[j] * r1[j];
        const float t3r = w1r[j] * r3[j] - w1i[j] * i3[j];
        const float t3i = w1r[j] * i3[j] + w1i[j] * r3[j];
        const float b0r = r0[j] + t1r;
        const float b0i = i0[j] + t1i;
        const float b1r = r0[j] - t1r;
        const float b1i = i0[j] - t1i;
        const float b2r = r2[j] + t3r;
        const float b2i = i2[j] + t3i;
        const float b3r = r2[j] - t3r;
        const float b3i = i2[j] - t3i;
        // Stage 2h: (b0, b2) with w2, (b1, b3) with -j w2.
        const float u2r = w2r[j] * b2r - w2i[j] * b2i;
        const float u2i = w2r[j] * b2i + w2i[j] * b2r;
        const float u3r = w2r[j] * b3r - w2i[j] * b3i;
        const float u3i = w2r[j] * b3i + w2i[j] * b3r;
        r0[j] = b0r + u2r;
        i0[j] = b0i + u2i;
        r2[j] = b0r - u2r;
        i2[j] = b0i - u2i;
        // -j * u3 = (u3i, -u3r)
        r1[j] = b1r + u3i;
        i1[j] = b1i - u3r;
        r3[j] = b1r - u3i;
        i3[j] = b1i + u3r;
      }
    }
  }

  using Index = std::uint16_t;  // N <= 65536, so every index fits

  void permute(float* re, float* im) const {
    for (std::size_t k = 0; k < num_swaps_; ++k) {
      const std::size_t i = swap_a_[k];
      const std::size_t r = swap_b_[k];
      const float t_re = re[i];
      const float t_im = im[i];
      re[i] = re[r];
      im[i] = im[r];
      re[r] = t_re;
      im[r] = t_im;
    }
  }

  std::array<float, N> tw_re_{};
  std::array<float, N> tw_im_{};
  std::array<Index, N / 2> swap_a_{};  ///< fewer than N/2 pairs have i < rev(i)
  std::array<Index, N / 2> swap_b_{};
  std::size_t num_swaps_ = 0;
  bool initialized_ = false;
};

}  // namespace mptrack::dsp
