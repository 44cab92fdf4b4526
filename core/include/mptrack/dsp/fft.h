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
// even log2 N < 8; on x86-64 hosts forward() runs the same schedule
// compiled for AVX-512 or AVX2 when the CPU has them (N >= 64; no FMA).
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
#include <cstdint>

#include <cstring>
#include <type_traits>

#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"
#include "mptrack/status.h"

// Vector bit reversal where GCC's generic vectors map to real SIMD
// registers (SSE2, AArch64 NEON); elsewhere (Cortex-M, 32-bit Arm) the
// scalar swap list. Data movement only: no effect on any bit of the result.
#if defined(__GNUC__) && !defined(__clang__) && (defined(__SSE2__) || defined(__aarch64__))
#define MPTRACK_FFT_VECTOR_PERMUTE 1
#else
#define MPTRACK_FFT_VECTOR_PERMUTE 0
#endif

// Run-time ISA dispatch on x86-64 Linux hosts built with GCC: forward()
// runs the same schedule compiled for AVX-512 or AVX2 (never FMA) when
// the CPU supports it. Define MPTRACK_FFT_X86_DISPATCH=0 to build only the
// baseline (SSE2) copy. Targets (aarch64, armhf, Cortex-M) have one copy.
#ifndef MPTRACK_FFT_X86_DISPATCH
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define MPTRACK_FFT_X86_DISPATCH 1
#else
#define MPTRACK_FFT_X86_DISPATCH 0
#endif
#endif

// The butterfly loops must reach the loop vectoriser, which keeps the
// __restrict facts: GCC otherwise unrolls short constant-trip loops (4, 8)
// completely first, and its straight-line (SLP) vectoriser then gives up on
// possible aliasing and emits scalar stores that stall the next pass's
// vector loads (measured: N = 32 three times slower behind a call).
// Only where the loops are vectorised (SSE2, AArch64); scalar targets
// (Cortex-M, armhf) keep GCC's complete unrolling.
#if MPTRACK_FFT_VECTOR_PERMUTE
#define MPTRACK_FFT_NO_UNROLL _Pragma("GCC unroll 1")
#else
#define MPTRACK_FFT_NO_UNROLL
#endif

// Every pass is force-inlined into forward_schedule(), so each dispatch
// copy compiles the whole schedule for its own ISA.
#if MPTRACK_FFT_X86_DISPATCH
#define MPTRACK_FFT_INLINE __attribute__((always_inline)) inline
#else
#define MPTRACK_FFT_INLINE inline
#endif

namespace mptrack::dsp {

namespace fft_detail {

// Butterfly kernels over runs of kLen elements. The no-alias facts are
// __restrict FUNCTION PARAMETERS: GCC keeps those when it inlines the
// kernel into a pass (the dispatch copies inline everything), whereas
// __restrict local variables lose them and the loops stop vectorising.
// Each is the exact per-element operation sequence of the DIT radix-2 /
// radix-2^2 butterfly (see Fft); only the schedule differs between users.

/// Radix-2, twiddle 1: (a, b) -> (a + b, a - b).
template <std::size_t kLen>
MPTRACK_FFT_INLINE void radix2_run(float* __restrict r0, float* __restrict i0,
                                   float* __restrict r1, float* __restrict i1) {
  MPTRACK_FFT_NO_UNROLL
  for (std::size_t r = 0; r < kLen; ++r) {
    const float tr = r1[r];
    const float ti = i1[r];
    r1[r] = r0[r] - tr;
    i1[r] = i0[r] - ti;
    r0[r] = r0[r] + tr;
    i0[r] = i0[r] + ti;
  }
}

/// Half-sizes 1 and 2 fused (twiddles 1 and -j): no multiplies.
template <std::size_t kLen>
MPTRACK_FFT_INLINE void radix4_first_run(float* __restrict r0, float* __restrict i0,
                                         float* __restrict r1, float* __restrict i1,
                                         float* __restrict r2, float* __restrict i2,
                                         float* __restrict r3, float* __restrict i3) {
  MPTRACK_FFT_NO_UNROLL
  for (std::size_t r = 0; r < kLen; ++r) {
    const float b0r = r0[r] + r1[r];
    const float b0i = i0[r] + i1[r];
    const float b1r = r0[r] - r1[r];
    const float b1i = i0[r] - i1[r];
    const float b2r = r2[r] + r3[r];
    const float b2i = i2[r] + i3[r];
    const float b3r = r2[r] - r3[r];
    const float b3i = i2[r] - i3[r];
    r0[r] = b0r + b2r;
    i0[r] = b0i + b2i;
    r2[r] = b0r - b2r;
    i2[r] = b0i - b2i;
    // -j * b3 = (b3i, -b3r)
    r1[r] = b1r + b3i;
    i1[r] = b1i - b3r;
    r3[r] = b1r - b3i;
    i3[r] = b1i + b3r;
  }
}

/// Two radix-2 stages (half-sizes h, 2h) fused: operands a0..a3 at
/// r0..r3, twiddles W_{2h}^j (w1) and W_{4h}^j (w2), the odd pair's second
/// twiddle -j w2 applied as a swap. W is float* (one twiddle per element)
/// or float (one twiddle for the whole run).
template <std::size_t kLen, class W>
MPTRACK_FFT_INLINE void radix4_run(float* __restrict r0, float* __restrict i0,
                                   float* __restrict r1, float* __restrict i1,
                                   float* __restrict r2, float* __restrict i2,
                                   float* __restrict r3, float* __restrict i3, W w1r, W w1i,
                                   W w2r, W w2i) {
  constexpr bool kPerElement = !std::is_same<W, float>::value;
  MPTRACK_FFT_NO_UNROLL
  for (std::size_t j = 0; j < kLen; ++j) {
    float a1r, a1i, a2r, a2i;  // w1, w2 of this element
    if constexpr (kPerElement) {
      a1r = w1r[j];
      a1i = w1i[j];
      a2r = w2r[j];
      a2i = w2i[j];
    } else {
      a1r = w1r;
      a1i = w1i;
      a2r = w2r;
      a2i = w2i;
    }
    // Stage h: (a0, a1) and (a2, a3) with w1.
    const float t1r = a1r * r1[j] - a1i * i1[j];
    const float t1i = a1r * i1[j] + a1i * r1[j];
    const float t3r = a1r * r3[j] - a1i * i3[j];
    const float t3i = a1r * i3[j] + a1i * r3[j];
    const float b0r = r0[j] + t1r;
    const float b0i = i0[j] + t1i;
    const float b1r = r0[j] - t1r;
    const float b1i = i0[j] - t1i;
    const float b2r = r2[j] + t3r;
    const float b2i = i2[j] + t3i;
    const float b3r = r2[j] - t3r;
    const float b3i = i2[j] - t3i;
    // Stage 2h: (b0, b2) with w2, (b1, b3) with -j w2.
    const float u2r = a2r * b2r - a2i * b2i;
    const float u2i = a2r * b2i + a2i * b2r;
    const float u3r = a2r * b3r - a2i * b3i;
    const float u3i = a2r * b3i + a2i * b3r;
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

}  // namespace fft_detail

/// Compile-time check: n is a power of two >= 2.
constexpr bool is_power_of_two(std::size_t n) { return n >= 2 && (n & (n - 1)) == 0; }

/// log2 of a power of two.
constexpr std::size_t log2_exact(std::size_t n) {
  std::size_t l = 0;
  while ((std::size_t{1} << l) < n) ++l;
  return l;
}

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
  static constexpr std::size_t kMinDispatchSize = 64;

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
    if constexpr (N < kMinDispatchSize) {
      forward_schedule(re, im);
      return;
    }
    if (__builtin_cpu_supports("avx512f")) {
      forward_avx512(re, im);
      return;
    }
    if (__builtin_cpu_supports("avx2")) {
      forward_avx2(re, im);
      return;
    }
#endif
    forward_schedule(re, im);
  }

  /// forward() without run-time ISA dispatch: the baseline build's code
  /// (SSE2 on x86-64). For tests that prove every dispatch path gives the
  /// same bits.
  void forward_portable(float* re, float* im) const { forward_schedule(re, im); }

  /// Which copy forward() runs on this CPU: "avx512", "avx2" or "baseline".
  static const char* dispatch_name() {
#if MPTRACK_FFT_X86_DISPATCH
    if (N < kMinDispatchSize) return "baseline";
    if (__builtin_cpu_supports("avx512f")) return "avx512";
    if (__builtin_cpu_supports("avx2")) return "avx2";
#endif
    return "baseline";
  }

  /// In-place inverse DFT (unscaled): the forward transform with re/im swapped.
  void inverse(float* re, float* im) const { forward(im, re); }

  /// Read-only twiddle access for tests: w = exp(-j 2 pi j / (2h)), h a power of two < N.
  float twiddle_re(std::size_t h, std::size_t j) const { return tw_re_[h - 1 + j]; }
  float twiddle_im(std::size_t h, std::size_t j) const { return tw_im_[h - 1 + j]; }

 private:
#if MPTRACK_FFT_X86_DISPATCH
  // The dispatch copies: the whole schedule (every helper is always_inline)
  // compiled for a wider ISA. Neither target enables FMA, and
  // -ffp-contract=off forbids contraction anyway, so each element sees the
  // same roundings as in the baseline copy.
  __attribute__((target("avx2"), noinline)) void forward_avx2(float* re, float* im) const {
    forward_schedule(re, im);
  }
  __attribute__((target("avx512f,prefer-vector-width=512"), noinline)) void forward_avx512(
      float* re, float* im) const {
    forward_schedule(re, im);
  }
#endif

  // The schedule. Which passes run before the bit reversal (input order,
  // runs of N/(4h)) and which after (natural order, runs of h) is chosen
  // per size for run length (measured, bench/README.md); every choice
  // performs the same operations per element.
  MPTRACK_FFT_INLINE void forward_schedule(float* re, float* im) const {
    if constexpr (kLog2 % 2 == 1) {
      if constexpr (N >= 32) {
        // Half-size 2 in input order: runs of N/8 instead of 2.
        radix2_radix4_input_order(re, im);
        permute(re, im);
        radix4_passes<8>(re, im);
      } else {
        radix2_first(re, im);
        permute(re, im);
        radix4_passes<2>(re, im);
      }
    } else {
#if MPTRACK_FFT_VECTOR_PERMUTE
      if constexpr (N >= 256) {
        // h = 4 in input order: runs of N/16 >= 16 instead of 4.
        radix4_first(re, im);
        radix4_pass_input_order<4>(re, im);
        permute(re, im);
        radix4_passes<16>(re, im);
        return;
      } else if constexpr (N >= 16) {
        radix4_first_permute(re, im);
        radix4_passes<4>(re, im);
        return;
      }
#endif
      radix4_first(re, im);
      permute(re, im);
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

  // Two radix-2 DIT stages (half-sizes h and 2h) fused into one pass over
  // the data (radix-2^2): per group of four points, 3 complex multiplies
  // instead of 4 and half the memory traffic. The second-stage twiddle of
  // the odd pair is W_{4h}^{j+h} = -j W_{4h}^j, applied exactly as a swap.
  /// j with its kLog2 bits reversed.
  static constexpr std::size_t bit_reverse(std::size_t j) {
    std::size_t r = 0;
    for (std::size_t b = 0; b < kLog2; ++b) {
      if ((j >> b) & 1u) r |= std::size_t{1} << (kLog2 - 1 - b);
    }
    return r;
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
      const std::size_t off = bit_reverse(j);
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

  using Index = std::uint16_t;  // N <= 65536, so every index fits

  // Bit-reversal permutation as a compile-time list of swaps (i < rev(i)):
  // in flash/rodata, shared by all instances, and a loop of known length.
  // Of the N indices, 2^ceil(log2(N)/2) are bit palindromes; the rest pair up.
  static constexpr std::size_t kNumSwaps = (N - (std::size_t{1} << ((kLog2 + 1) / 2))) / 2;
  struct SwapPair {
    Index a;
    Index b;
  };
  static constexpr std::array<SwapPair, (kNumSwaps > 0 ? kNumSwaps : 1)> make_swaps() {
    std::array<SwapPair, (kNumSwaps > 0 ? kNumSwaps : 1)> t{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < N; ++i) {
      std::size_t r = 0;
      for (std::size_t b = 0; b < kLog2; ++b) {
        if ((i >> b) & 1u) r |= std::size_t{1} << (kLog2 - 1 - b);
      }
      if (r > i) {
        t[n].a = static_cast<Index>(i);
        t[n].b = static_cast<Index>(r);
        ++n;
      }
    }
    return t;
  }
  static constexpr std::array<SwapPair, (kNumSwaps > 0 ? kNumSwaps : 1)> kSwaps = make_swaps();

  MPTRACK_FFT_INLINE static void permute(float* re, float* im) {
#if MPTRACK_FFT_VECTOR_PERMUTE
    if constexpr (N >= 16) {
      permute_blocks(re);
      permute_blocks(im);
      return;
    }
#endif
    for (std::size_t k = 0; k < kNumSwaps; ++k) {
      const std::size_t i = kSwaps[k].a;
      const std::size_t r = kSwaps[k].b;
      const float t_re = re[i];
      const float t_im = im[i];
      re[i] = re[r];
      im[i] = im[r];
      re[r] = t_re;
      im[r] = t_im;
    }
  }

#if MPTRACK_FFT_VECTOR_PERMUTE
  // Blocked bit reversal (pure data movement, so trivially the same bits):
  // with i = a (N/4) + 4 b + c (a, c < 4, b < N/16), rev(i) = r(c) (N/4) +
  // 4 rev'(b) + r(a), where r reverses 2 bits and rev' the middle log2 N - 4.
  // Block b (rows a at stride N/4, 4 contiguous columns c) therefore becomes
  // block rev'(b) transposed with rows and columns permuted by r: four
  // vector loads, a 4 x 4 transpose in registers, four vector stores.
  using V4 = float __attribute__((vector_size(16)));
  MPTRACK_FFT_INLINE static V4 load4(const float* p) {
    V4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  MPTRACK_FFT_INLINE static void store4(float* p, V4 v) { std::memcpy(p, &v, sizeof v); }
  // W_{a'} = (V0, V2, V1, V3)^T row r(a').
  MPTRACK_FFT_INLINE static void transpose_block(V4& v0, V4& v1, V4& v2, V4& v3) {
    using M = std::int32_t __attribute__((vector_size(16)));
    // Rows in the order V0, V2, V1, V3, then a standard 4 x 4 transpose.
    const V4 t0 = __builtin_shuffle(v0, v2, M{0, 4, 1, 5});  // V0[0] V2[0] V0[1] V2[1]
    const V4 t1 = __builtin_shuffle(v1, v3, M{0, 4, 1, 5});  // V1[0] V3[0] V1[1] V3[1]
    const V4 t2 = __builtin_shuffle(v0, v2, M{2, 6, 3, 7});  // V0[2] V2[2] V0[3] V2[3]
    const V4 t3 = __builtin_shuffle(v1, v3, M{2, 6, 3, 7});  // V1[2] V3[2] V1[3] V3[3]
    const V4 c0 = __builtin_shuffle(t0, t1, M{0, 1, 4, 5});  // column 0: V0[0] V2[0] V1[0] V3[0]
    const V4 c1 = __builtin_shuffle(t0, t1, M{2, 3, 6, 7});  // column 1
    const V4 c2 = __builtin_shuffle(t2, t3, M{0, 1, 4, 5});  // column 2
    const V4 c3 = __builtin_shuffle(t2, t3, M{2, 3, 6, 7});  // column 3
    v0 = c0;  // W_0 = column r(0) = 0
    v1 = c2;  // W_1 = column r(1) = 2
    v2 = c1;  // W_2 = column r(2) = 1
    v3 = c3;  // W_3 = column 3
  }
  // radix4_first and the permutation in one pass (even log2 N < 8): the four
  // rows of block b (stride N/4) are exactly the operands p0, p2, p1, p3 of
  // four first-stage groups (one per column), so the butterfly runs on the
  // rows in registers (the same per-lane operations as radix4_first_run),
  // then the block is transposed and stored at its partner rev'(b).
  MPTRACK_FFT_INLINE static void first_block(const float* re, const float* im, V4 (&yr)[4],
                                             V4 (&yi)[4]) {
    constexpr std::size_t kQ = N / 4;
    const V4 x0r = load4(re), x1r = load4(re + kQ), x2r = load4(re + 2 * kQ),
             x3r = load4(re + 3 * kQ);
    const V4 x0i = load4(im), x1i = load4(im + kQ), x2i = load4(im + 2 * kQ),
             x3i = load4(im + 3 * kQ);
    // Rows 0, 2, 1, 3 play r0, r1, r2, r3 of radix4_first_run.
    const V4 b0r = x0r + x2r;
    const V4 b0i = x0i + x2i;
    const V4 b1r = x0r - x2r;
    const V4 b1i = x0i - x2i;
    const V4 b2r = x1r + x3r;
    const V4 b2i = x1i + x3i;
    const V4 b3r = x1r - x3r;
    const V4 b3i = x1i - x3i;
    yr[0] = b0r + b2r;
    yi[0] = b0i + b2i;
    yr[1] = b0r - b2r;
    yi[1] = b0i - b2i;
    yr[2] = b1r + b3i;
    yi[2] = b1i - b3r;
    yr[3] = b1r - b3i;
    yi[3] = b1i + b3r;
    transpose_block(yr[0], yr[1], yr[2], yr[3]);
    transpose_block(yi[0], yi[1], yi[2], yi[3]);
  }
  MPTRACK_FFT_INLINE static void store_block(float* x, const V4 (&v)[4]) {
    constexpr std::size_t kQ = N / 4;
    store4(x, v[0]);
    store4(x + kQ, v[1]);
    store4(x + 2 * kQ, v[2]);
    store4(x + 3 * kQ, v[3]);
  }
  MPTRACK_FFT_INLINE static void radix4_first_permute(float* re, float* im) {
    constexpr std::size_t kMid = kLog2 - 4;
    for (std::size_t b = 0; b < N / 16; ++b) {
      std::size_t rb = 0;
      for (std::size_t k = 0; k < kMid; ++k) {
        if ((b >> k) & 1u) rb |= std::size_t{1} << (kMid - 1 - k);
      }
      if (rb < b) continue;  // the pair was handled at rb
      V4 pr[4], pi[4];
      first_block(re + 4 * b, im + 4 * b, pr, pi);
      if (rb == b) {
        store_block(re + 4 * b, pr);
        store_block(im + 4 * b, pi);
        continue;
      }
      V4 qr[4], qi[4];
      first_block(re + 4 * rb, im + 4 * rb, qr, qi);
      store_block(re + 4 * rb, pr);
      store_block(im + 4 * rb, pi);
      store_block(re + 4 * b, qr);
      store_block(im + 4 * b, qi);
    }
  }

  MPTRACK_FFT_INLINE static void permute_blocks(float* x) {
    constexpr std::size_t kQ = N / 4;
    constexpr std::size_t kMid = kLog2 - 4;
    for (std::size_t b = 0; b < N / 16; ++b) {
      std::size_t rb = 0;
      for (std::size_t k = 0; k < kMid; ++k) {
        if ((b >> k) & 1u) rb |= std::size_t{1} << (kMid - 1 - k);
      }
      if (rb < b) continue;  // the pair was handled at rb
      float* p = x + 4 * b;
      float* q = x + 4 * rb;
      V4 v0 = load4(p), v1 = load4(p + kQ), v2 = load4(p + 2 * kQ), v3 = load4(p + 3 * kQ);
      transpose_block(v0, v1, v2, v3);
      if (rb == b) {
        store4(p, v0);
        store4(p + kQ, v1);
        store4(p + 2 * kQ, v2);
        store4(p + 3 * kQ, v3);
        continue;
      }
      V4 w0 = load4(q), w1 = load4(q + kQ), w2 = load4(q + 2 * kQ), w3 = load4(q + 3 * kQ);
      transpose_block(w0, w1, w2, w3);
      store4(q, v0);
      store4(q + kQ, v1);
      store4(q + 2 * kQ, v2);
      store4(q + 3 * kQ, v3);
      store4(p, w0);
      store4(p + kQ, w1);
      store4(p + 2 * kQ, w2);
      store4(p + 3 * kQ, w3);
    }
  }
#endif

  std::array<float, N> tw_re_{};
  std::array<float, N> tw_im_{};
  bool initialized_ = false;
};

}  // namespace mptrack::dsp
