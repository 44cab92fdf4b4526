// Bit-reversal permutation of the FFT (fft.h): pure data movement, so no
// schedule here can change a bit of the result. A compile-time swap list on
// every target; on SSE2 / AArch64 blocked vector transposes, and the first
// radix-4 stage fused into those blocks (the rows of a block are exactly the
// operands of first-stage groups, so the butterfly runs in registers).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mptrack/dsp/fft_config.h"

namespace mptrack::dsp::fft_detail {

/// Bit reversal of N points (a power of two) and the fused first blocks.
template <std::size_t N>
struct BitReversal {
  static constexpr std::size_t kLog2 = log2_exact(N);

  /// j with its kLog2 bits reversed.
  static constexpr std::size_t reverse(std::size_t j) { return reverse_low_bits(j, kLog2); }

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
      const std::size_t rb = reverse_low_bits(b, kMid);
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
      const std::size_t rb = reverse_low_bits(b, kMid);
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
};

}  // namespace mptrack::dsp::fft_detail
