// Fixed-size complex FFT, float, bit-exact across targets.
//
// Why our own: the front end must give the same bits on x86-64, aarch64, armhf and Cortex-M
// (README.md §Conventions a firmware engineer can rely on). Library FFTs choose codelets
// and reduction orders per ISA at run time (FFTW plans, CMSIS per-core kernels), so their
// outputs differ in the last bits.
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
// Speed without changing a bit (bench/README.md has the numbers): every
// pass is instantiated with its half-size as a compile-time constant (known
// trip counts) and its butterflies are kernels with __restrict parameters
// (fft_detail), so GCC emits straight vector loops; the first stages run on
// the input order before the bit reversal (unit-stride runs instead of
// stride-2/4 gathers, see radix2_first); on SSE2/AArch64 the bit reversal
// is a blocked 4 x 4 transpose, fused with the first radix-4 stage for
// even log2 N < 8 and with the first two stages at N = 32
// (fft_fused_first.h); on x86-64 hosts forward() runs the same schedule
// compiled for AVX-512 or AVX2 when the CPU has them (N >= 32; no FMA),
// where the bit reversal uses 8 x 8 (8 x 16) register blocks fused with the
// first stages and N = 64 stays in registers (fft_register64.h).
// Each output element still sees the same operations on the same operands
// in the same order; -ffp-contract=off keeps vector and scalar builds from
// fusing anything, so tests/golden/data/frontend_*.golden match unchanged
// (tests/unit/fft_reorder_test.cpp and fft_dispatch_test.cpp check every
// size 2..4096 bit for bit against the textbook schedule).
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

#include "mptrack/dsp/fft_bit_reversal.h"
#include "mptrack/dsp/fft_config.h"
#include "mptrack/dsp/fft_fused_first.h"
#include "mptrack/dsp/fft_kernels.h"
#include "mptrack/dsp/fft_register64.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

namespace mptrack::dsp {


/// Radix-2^2 FFT of fixed length N (a power of two, 2..65536).
/// Footprint: 2 N floats of twiddles per object; the bit-reversal swap list
/// (about N 16-bit indices) is a static constexpr table, in rodata/flash.
template <std::size_t N>
class Fft {
  static_assert(is_power_of_two(N), "Fft length must be a power of two >= 2");
  static_assert(N <= 65536, "Fft length above 65536 is not supported");

 public:
  static constexpr std::size_t kSize = N;
  static constexpr std::size_t kLog2 = log2_exact(N);
  /// Below this size the wide copies lose (runs shorter than a vector,
  /// 4 x 4 blocks): forward() always runs the baseline copy (measured).
  static constexpr std::size_t kMinDispatchSize = 32;

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
    initialized_ = true;
    return Status::kOk;
  }

  bool initialized() const { return initialized_; }

  /// In-place forward DFT of planar data re[0..N), im[0..N). Unscaled.
  /// Precondition: init() succeeded (checked by the owning stage's init()).
  /// On x86-64 hosts the same schedule runs in a copy compiled for AVX-512
  /// or AVX2 when the CPU has it (see MPTRACK_FFT_X86_DISPATCH): wider
  /// vectors, the same operations per element, so the same bits.
  void forward(float* re, float* im) const {
#if MPTRACK_FFT_X86_DISPATCH
    if constexpr (N >= kMinDispatchSize) {
      const FftCopy copy = widest_fft_copy();
      if (copy == FftCopy::kAvx512) {
        forward_avx512(re, im);
        return;
      }
      if (copy == FftCopy::kAvx2) {
        forward_avx2(re, im);
        return;
      }
    }
#endif
    forward_schedule<false>(re, im);
  }

  /// forward() without run-time ISA dispatch: the baseline build's code
  /// (SSE2 on x86-64). For tests that prove every dispatch path gives the
  /// same bits.
  void forward_portable(float* re, float* im) const { forward_schedule<false>(re, im); }

  /// Runs one copy of the schedule whatever forward() would pick (any N),
  /// for tests that prove every copy gives the same bits, e.g. the AVX2
  /// copy on an AVX-512 host. False (nothing done) when this build or this
  /// CPU does not have that copy.
  bool forward_copy(FftCopy copy, float* re, float* im) const {
    if (!fft_copy_available(copy)) return false;
#if MPTRACK_FFT_X86_DISPATCH
    if (copy == FftCopy::kAvx512) {
      forward_avx512(re, im);
      return true;
    }
    if (copy == FftCopy::kAvx2) {
      forward_avx2(re, im);
      return true;
    }
#endif
    forward_schedule<false>(re, im);
    return true;
  }

  /// Which copy forward() runs on this CPU: "avx512", "avx2" or "baseline".
  static const char* dispatch_name() {
    return N < kMinDispatchSize ? "baseline" : fft_copy_name(widest_fft_copy());
  }

  /// In-place inverse DFT (unscaled): the forward transform with re/im swapped.
  void inverse(float* re, float* im) const { forward(im, re); }

  /// Read-only twiddle access for tests: w = exp(-j 2 pi j / (2h)), h a power of two < N.
  float twiddle_re(std::size_t h, std::size_t j) const { return tw_re_[h - 1 + j]; }
  float twiddle_im(std::size_t h, std::size_t j) const { return tw_im_[h - 1 + j]; }

 private:
  using Bits = fft_detail::BitReversal<N>;
  using Fused = fft_detail::FusedFirst<N>;

  // Twiddles of half-sizes 2 and 4 for j = 0, 1 (offsets 1, 2 and 3, 4).
  fft_detail::FirstTwiddles first_twiddles() const {
    return {{tw_re_[1], tw_re_[2]}, {tw_im_[1], tw_im_[2]}, {tw_re_[3], tw_re_[4]},
            {tw_im_[3], tw_im_[4]}};
  }

#if MPTRACK_FFT_X86_DISPATCH
  // The dispatch copies: the whole schedule (every helper is always_inline)
  // compiled for a wider ISA. Neither target enables FMA, and
  // -ffp-contract=off forbids contraction anyway, so each element sees the
  // same roundings as in the baseline copy.
  __attribute__((target("avx2"), noinline)) void forward_avx2(float* re, float* im) const {
    forward_schedule<true>(re, im);
  }
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void forward_avx512(
      float* re, float* im) const {
    forward_schedule<true, true>(re, im);
  }
#endif

  // The schedule. Which passes run before the bit reversal (input order,
  // runs of N/(4h)) and which after (natural order, runs of h) is chosen
  // per size for run length (measured, bench/README.md); every choice
  // performs the same operations per element.
  template <bool kWide, bool kZmm = false>
  MPTRACK_FFT_INLINE void forward_schedule(float* re, float* im) const {
    if constexpr (kLog2 % 2 == 1) {
      if constexpr (N >= 32) {
#if MPTRACK_FFT_VECTOR_PERMUTE
        if constexpr (N == 32) {  // the whole first pass and permutation in registers
          Fused::radix2_radix4_permute_32(re, im, first_twiddles());
          radix4_passes<8>(re, im);
          return;
        }
#endif
#if MPTRACK_FFT_X86_DISPATCH
        if constexpr (kZmm && N == 128) {  // one 8 x 16 block in the AVX-512 copy
          Fused::radix2_radix4_permute_128(re, im, first_twiddles());
          radix4_passes<8>(re, im);
          return;
        }
        if constexpr (kWide && N >= 128) {  // 8 x 8 blocks in the AVX copies
          Fused::radix2_radix4_permute_8x8(re, im, first_twiddles());
          radix4_passes<8>(re, im);
          return;
        }
#endif
        // Half-size 2 in input order: runs of N/8 instead of 2.
        radix2_radix4_input_order(re, im);
        Bits::permute(re, im);
        radix4_passes<8>(re, im);
      } else {
        radix2_first(re, im);
        Bits::permute(re, im);
        radix4_passes<2>(re, im);
      }
    } else {
#if MPTRACK_FFT_VECTOR_PERMUTE
      if constexpr (N >= 256) {
        // h = 4 in input order: runs of N/16 >= 16 instead of 4.
        radix4_first(re, im);
        radix4_pass_input_order<4>(re, im);
#if MPTRACK_FFT_X86_DISPATCH
        if constexpr (kWide) {  // 8 x 8 blocks in the AVX copies
          Fused::permute_8x8(re);
          Fused::permute_8x8(im);
          radix4_passes<16>(re, im);
          return;
        }
#endif
        Bits::permute(re, im);
        radix4_passes<16>(re, im);
        return;
      } else if constexpr (N >= 16) {
#if MPTRACK_FFT_X86_DISPATCH
        if constexpr (kZmm && N == 64) {  // the whole transform in 16-float registers
          fft_detail::Register64Zmm::forward(re, im, tw_re_.data(), tw_im_.data());
          return;
        }
        if constexpr (kWide && N == 64) {  // the whole transform in registers
          fft_detail::Register64::forward(re, im, tw_re_.data(), tw_im_.data());
          return;
        }
#endif
        Bits::radix4_first_permute(re, im);
        radix4_passes<4>(re, im);
        return;
      }
#endif
      radix4_first(re, im);
      Bits::permute(re, im);
      radix4_passes<4>(re, im);
    }
  }

  // The first stage runs BEFORE the bit-reversal permutation, on the
  // input order. After the permutation, slot a + k holds x[rev(a + k)], and
  // for a group start a (a multiple of 2, resp. 4) rev(a + k) = rev(a) +
  // rev(k): the group's operands sit at r, r + N/2 (radix 2) or r, r + N/2,
  // r + N/4, r + 3N/4 (radix 4) with r = rev(a) running over [0, N/2), resp.
  // [0, N/4). Computing each group there and writing output k to slot
  // rev(a + k), which the permutation then moves to a + k, performs exactly
  // the same operations on the same operands (same bits) with unit-stride,
  // vectorisable runs instead of stride-2/4 gathers.

  // Stage of half-size 1 (twiddle 1): no multiplies.
  MPTRACK_FFT_INLINE static void radix2_first(float* re, float* im) {
    constexpr std::size_t kH = N / 2;
    fft_detail::radix2_run<kH>(re, im, re + kH, im + kH);
  }

  // Stages of half-size 1 and 2 fused (twiddles 1 and -j): no multiplies.
  // Group slots a..a+3 (natural order) are runs p0 = r, p1 = r + N/2,
  // p2 = r + N/4, p3 = r + 3N/4 here.
  MPTRACK_FFT_INLINE static void radix4_first(float* re, float* im) {
    constexpr std::size_t kQ = N / 4;
    fft_detail::radix4_first_run<kQ>(re, im, re + 2 * kQ, im + 2 * kQ, re + kQ, im + kQ,
                                     re + 3 * kQ, im + 3 * kQ);
  }

  // radix4_pass<h> done before the permutation (see radix2_first): natural
  // slot base + j + k h sits at rev(base) + rev(j) + rev(k h), where
  // rev(base) = q runs over [0, N/(4h)), rev(j) is a multiple of N/h and
  // rev(h), rev(2h), rev(3h) = N/(2h), N/(4h), 3N/(4h). So for each j the
  // pass is a unit-stride run of N/(4h) butterflies with one twiddle pair:
  // the same operations on the same operands as radix4_pass<h>. Used for
  // h = 2 (odd log2 N), whose natural-order runs are only 2 long.
  template <std::size_t h>
  MPTRACK_FFT_INLINE void radix4_pass_input_order(float* re, float* im) const {
    constexpr std::size_t kRun = N / (4 * h);
    for (std::size_t j = 0; j < h; ++j) {
      const std::size_t off = Bits::reverse(j);
      fft_detail::radix4_run<kRun, float>(
          re + off, im + off, re + off + 2 * kRun, im + off + 2 * kRun, re + off + kRun,
          im + off + kRun, re + off + 3 * kRun, im + off + 3 * kRun, tw_re_[h - 1 + j],
          tw_im_[h - 1 + j], tw_re_[2 * h - 1 + j], tw_im_[2 * h - 1 + j]);
    }
  }

  // radix2_first and radix4_pass_input_order<2> fused (odd log2 N >= 5):
  // in input order the operands of both stages for column q are the eight
  // rows q + m N/8 (radix 2: rows m, m + 4; half-size 2, j = 0: rows 0, 2,
  // 1, 3; j = 1: rows 4, 6, 5, 7), so each chunk of columns goes through
  // both stages while it is in L1 / registers. Same operations per element.
  MPTRACK_FFT_INLINE void radix2_radix4_input_order(float* re, float* im) const {
    constexpr std::size_t kE = N / 8;
    constexpr std::size_t kC = kE < 16 ? kE : 16;
    const float w1r0 = tw_re_[1], w1i0 = tw_im_[1], w2r0 = tw_re_[3], w2i0 = tw_im_[3];
    const float w1r1 = tw_re_[2], w1i1 = tw_im_[2], w2r1 = tw_re_[4], w2i1 = tw_im_[4];
    for (std::size_t q = 0; q < kE; q += kC) {
      float* r = re + q;
      float* m = im + q;
      for (std::size_t k = 0; k < 4; ++k) {
        fft_detail::radix2_run<kC>(r + k * kE, m + k * kE, r + (k + 4) * kE, m + (k + 4) * kE);
      }
      fft_detail::radix4_run<kC, float>(r, m, r + 2 * kE, m + 2 * kE, r + kE, m + kE, r + 3 * kE,
                                        m + 3 * kE, w1r0, w1i0, w2r0, w2i0);
      fft_detail::radix4_run<kC, float>(r + 4 * kE, m + 4 * kE, r + 6 * kE, m + 6 * kE,
                                        r + 5 * kE, m + 5 * kE, r + 7 * kE, m + 7 * kE, w1r1,
                                        w1i1, w2r1, w2i1);
    }
  }

  // The radix-4 passes for half-sizes H, 4H, ... < N, each with its half-size
  // as a compile-time constant (inner trip count known: full vector loops).
  template <std::size_t H>
  MPTRACK_FFT_INLINE void radix4_passes(float* re, float* im) const {
    if constexpr (H < N) {
      radix4_pass<H>(re, im);
      radix4_passes<4 * H>(re, im);
    }
  }

  // Two radix-2 DIT stages (half-sizes h and 2h) fused into one pass over
  // the data (radix-2^2): per group of four points, 3 complex multiplies
  // instead of 4 and half the memory traffic. The second-stage twiddle of
  // the odd pair is W_{4h}^{j+h} = -j W_{4h}^j, applied exactly as a swap.
  template <std::size_t h>
  MPTRACK_FFT_INLINE void radix4_pass(float* re, float* im) const {
    // Twiddles W_{2h}^j at offset h - 1, W_{4h}^j at 2h - 1.
    for (std::size_t base = 0; base < N; base += 4 * h) {
      fft_detail::radix4_run<h, const float*>(
          re + base, im + base, re + base + h, im + base + h, re + base + 2 * h,
          im + base + 2 * h, re + base + 3 * h, im + base + 3 * h, &tw_re_[h - 1],
          &tw_im_[h - 1], &tw_re_[2 * h - 1], &tw_im_[2 * h - 1]);
    }
  }

  std::array<float, N> tw_re_{};
  std::array<float, N> tw_im_{};
  bool initialized_ = false;
};

}  // namespace mptrack::dsp
