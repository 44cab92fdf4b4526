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
// Speed without changing a bit (bench/README.md has the numbers): every
// pass is instantiated with its half-size as a compile-time constant (known
// trip counts, all pointers __restrict, so GCC emits straight vector loops);
// the first, multiply-free stage runs on the input order before the
// bit-reversal (unit-stride runs instead of stride-4 gathers, see
// radix2_first); the swap list is a constexpr table. Each output element
// still sees the same operations on the same operands in the same order;
// -ffp-contract=off keeps vector and scalar builds from fusing anything, so
// tests/golden/data/frontend_*.golden match unchanged.
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
/// Footprint: 2 N floats of twiddles per object; the bit-reversal swap list
/// (about N 16-bit indices) is a static constexpr table, in rodata/flash.
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
    initialized_ = true;
    return Status::kOk;
  }

  bool initialized() const { return initialized_; }

  /// In-place forward DFT of planar data re[0..N), im[0..N). Unscaled.
  /// Precondition: init() succeeded (checked by the owning stage's init()).
  void forward(float* re, float* im) const {
    if constexpr (kLog2 % 2 == 1) {
      radix2_first(re, im);
      if constexpr (N >= 128) {
        // Long enough input-order runs (N/8 >= 16) to beat the 2-long natural runs.
        radix4_pass_input_order<2>(re, im);
        permute(re, im);
        radix4_passes<8>(re, im);
      } else {
        permute(re, im);
        radix4_passes<2>(re, im);
      }
    } else {
      radix4_first(re, im);
      permute(re, im);
      radix4_passes<4>(re, im);
    }
  }

  /// In-place inverse DFT (unscaled): the forward transform with re/im swapped.
  void inverse(float* re, float* im) const { forward(im, re); }

  /// Read-only twiddle access for tests: w = exp(-j 2 pi j / (2h)), h a power of two < N.
  float twiddle_re(std::size_t h, std::size_t j) const { return tw_re_[h - 1 + j]; }
  float twiddle_im(std::size_t h, std::size_t j) const { return tw_im_[h - 1 + j]; }

 private:
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
  static void radix2_first(float* re, float* im) {
    constexpr std::size_t kH = N / 2;
    float* __restrict r0 = re;
    float* __restrict i0 = im;
    float* __restrict r1 = re + kH;
    float* __restrict i1 = im + kH;
    for (std::size_t r = 0; r < kH; ++r) {
      const float tr = r1[r];
      const float ti = i1[r];
      r1[r] = r0[r] - tr;
      i1[r] = i0[r] - ti;
      r0[r] = r0[r] + tr;
      i0[r] = i0[r] + ti;
    }
  }

  // Stages of half-size 1 and 2 fused (twiddles 1 and -j): no multiplies.
  // Group slots a..a+3 (natural order) are runs p0 = r, p1 = r + N/2,
  // p2 = r + N/4, p3 = r + 3N/4 here.
  static void radix4_first(float* re, float* im) {
    constexpr std::size_t kQ = N / 4;
    float* __restrict r0 = re;
    float* __restrict i0 = im;
    float* __restrict r1 = re + 2 * kQ;
    float* __restrict i1 = im + 2 * kQ;
    float* __restrict r2 = re + kQ;
    float* __restrict i2 = im + kQ;
    float* __restrict r3 = re + 3 * kQ;
    float* __restrict i3 = im + 3 * kQ;
    for (std::size_t r = 0; r < kQ; ++r) {
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
  void radix4_pass_input_order(float* re, float* im) const {
    constexpr std::size_t kRun = N / (4 * h);
    for (std::size_t j = 0; j < h; ++j) {
      const std::size_t off = bit_reverse(j);
      const float w1r = tw_re_[h - 1 + j];  // W_{2h}^j
      const float w1i = tw_im_[h - 1 + j];
      const float w2r = tw_re_[2 * h - 1 + j];  // W_{4h}^j
      const float w2i = tw_im_[2 * h - 1 + j];
      float* __restrict r0 = re + off;
      float* __restrict i0 = im + off;
      float* __restrict r1 = re + off + 2 * kRun;
      float* __restrict i1 = im + off + 2 * kRun;
      float* __restrict r2 = re + off + kRun;
      float* __restrict i2 = im + off + kRun;
      float* __restrict r3 = re + off + 3 * kRun;
      float* __restrict i3 = im + off + 3 * kRun;
      for (std::size_t q = 0; q < kRun; ++q) {
        const float t1r = w1r * r1[q] - w1i * i1[q];
        const float t1i = w1r * i1[q] + w1i * r1[q];
        const float t3r = w1r * r3[q] - w1i * i3[q];
        const float t3i = w1r * i3[q] + w1i * r3[q];
        const float b0r = r0[q] + t1r;
        const float b0i = i0[q] + t1i;
        const float b1r = r0[q] - t1r;
        const float b1i = i0[q] - t1i;
        const float b2r = r2[q] + t3r;
        const float b2i = i2[q] + t3i;
        const float b3r = r2[q] - t3r;
        const float b3i = i2[q] - t3i;
        const float u2r = w2r * b2r - w2i * b2i;
        const float u2i = w2r * b2i + w2i * b2r;
        const float u3r = w2r * b3r - w2i * b3i;
        const float u3i = w2r * b3i + w2i * b3r;
        r0[q] = b0r + u2r;
        i0[q] = b0i + u2i;
        r2[q] = b0r - u2r;
        i2[q] = b0i - u2i;
        r1[q] = b1r + u3i;
        i1[q] = b1i - u3r;
        r3[q] = b1r - u3i;
        i3[q] = b1i + u3r;
      }
    }
  }

  // The radix-4 passes for half-sizes H, 4H, ... < N, each with its half-size
  // as a compile-time constant (inner trip count known: full vector loops).
  template <std::size_t H>
  void radix4_passes(float* re, float* im) const {
    if constexpr (H < N) {
      radix4_pass<H>(re, im);
      radix4_passes<4 * H>(re, im);
    }
  }

  template <std::size_t h>
  void radix4_pass(float* re, float* im) const {
    const float* __restrict w1r = &tw_re_[h - 1];      // W_{2h}^j
    const float* __restrict w1i = &tw_im_[h - 1];
    const float* __restrict w2r = &tw_re_[2 * h - 1];  // W_{4h}^j
    const float* __restrict w2i = &tw_im_[2 * h - 1];
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

  static void permute(float* re, float* im) {
#if MPTRACK_FFT_VECTOR_PERMUTE
    if constexpr (N >= 64) {
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
  static V4 load4(const float* p) {
    V4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static void store4(float* p, V4 v) { std::memcpy(p, &v, sizeof v); }
  // W_{a'} = (V0, V2, V1, V3)^T row r(a').
  static void transpose_block(V4& v0, V4& v1, V4& v2, V4& v3) {
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
  static void permute_blocks(float* x) {
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
