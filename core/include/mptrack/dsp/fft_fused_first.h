// The first two stages of an odd-log2 FFT (radix 2, then half-sizes 2 and 4)
// fused with the bit-reversal permutation, in registers (fft.h schedule).
//
// In input order the operands of both stages for column q are the eight rows
// q + m N/8 (fft_kernels.h radix2_radix4_rows). Write a position as
// i = a (N/8) + c with a < 8; its bit reversal is rev(i) = r3(c') ... : for a
// block of eight rows and K contiguous columns the rows are exactly the
// operands of K first-stage groups, and the block's bit reversal is a small
// transpose. So the stages run on the rows in registers (the same operations
// per element as the in-memory pass), the block is transposed and stored at
// its partner: one pass over memory instead of two, no separate permutation.
// Pure data movement around unchanged arithmetic, so the same bits
// (tests/unit/fft_reorder_test.cpp, fft_dispatch_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mptrack/dsp/fft_bit_reversal.h"
#include "mptrack/dsp/fft_config.h"
#include "mptrack/dsp/fft_kernels.h"

namespace mptrack::dsp::fft_detail {

/// The fused first pass for odd log2 N (N = 32 on every vector target;
/// N >= 128 in the x86 AVX2 / AVX-512 copies).
template <std::size_t N>
struct FusedFirst {
  static constexpr std::size_t kLog2 = log2_exact(N);
  static constexpr std::size_t kRows = N / 8;  // stride of the eight rows

#if MPTRACK_FFT_VECTOR_PERMUTE
  using Bits = BitReversal<N>;
  using V4 = typename Bits::V4;

  // N = 32 (rows of 4): i = 4 a + c has rev(i) = 8 r2(c) + r3(a), so output
  // row x (8 contiguous slots at 8 x) is input column r2(x) read down the
  // rows r3(0..7) = 0, 4, 2, 6 | 1, 5, 3, 7. Bits::transpose_block takes its
  // rows as (v0, v2, v1, v3) and returns column r2(k) in v_k: given rows
  // (0, 2, 4, 6) it yields the first halves of output rows 0..3 in slots 0,
  // 2, 4, 6; given (1, 3, 5, 7) the second halves in slots 1, 3, 5, 7. So
  // slot k is stored at 4 k: the whole transform's first pass in registers.
  MPTRACK_FFT_INLINE static void store_rows32(float* x, const V4 (&v)[8]) {
    Bits::store4(x, v[0]);
    Bits::store4(x + 4, v[1]);
    Bits::store4(x + 8, v[2]);
    Bits::store4(x + 12, v[3]);
    Bits::store4(x + 16, v[4]);
    Bits::store4(x + 20, v[5]);
    Bits::store4(x + 24, v[6]);
    Bits::store4(x + 28, v[7]);
  }
  MPTRACK_FFT_INLINE static void radix2_radix4_permute_32(float* re, float* im,
                                                          const FirstTwiddles& w) {
    static_assert(N == 32, "the 8 x 4 block is the whole transform only at N = 32");
    V4 r[8] = {Bits::load4(re),      Bits::load4(re + 4),  Bits::load4(re + 8),
               Bits::load4(re + 12), Bits::load4(re + 16), Bits::load4(re + 20),
               Bits::load4(re + 24), Bits::load4(re + 28)};
    V4 m[8] = {Bits::load4(im),      Bits::load4(im + 4),  Bits::load4(im + 8),
               Bits::load4(im + 12), Bits::load4(im + 16), Bits::load4(im + 20),
               Bits::load4(im + 24), Bits::load4(im + 28)};
    radix2_radix4_rows(r, m, w);
    Bits::transpose_block(r[0], r[2], r[4], r[6]);
    Bits::transpose_block(r[1], r[3], r[5], r[7]);
    Bits::transpose_block(m[0], m[2], m[4], m[6]);
    Bits::transpose_block(m[1], m[3], m[5], m[7]);
    store_rows32(re, r);
    store_rows32(im, m);
  }
#endif

#if MPTRACK_FFT_X86_DISPATCH
  // N >= 128, only in the AVX2 / AVX-512 copies (8-float vectors are single
  // registers there). Blocks of 8 rows x 8 columns: i = a (N/8) + 8 b + c
  // (a, c < 8, b < N/64) has rev(i) = r3(c) (N/8) + 8 rev'(b) + r3(a), where
  // rev' reverses the middle log2 N - 6 bits. Block b becomes block rev'(b):
  // output row x is input column r3(x) read down the rows r3(0..7).
  using V8 = float __attribute__((vector_size(32)));
  using M8 = std::int32_t __attribute__((vector_size(32)));

  // By reference: a V8 passed by value would warn (-Wpsabi) in the baseline build.
  MPTRACK_FFT_INLINE static void load8(V8& v, const float* p) { std::memcpy(&v, p, sizeof v); }
  MPTRACK_FFT_INLINE static void store8(float* p, const V8& v) { std::memcpy(p, &v, sizeof v); }

  // Rows k at stride N/8, constant indices (see radix2_radix4_rows).
  MPTRACK_FFT_INLINE static void load_rows8(const float* x, V8 (&v)[8]) {
    load8(v[0], x);
    load8(v[1], x + kRows);
    load8(v[2], x + 2 * kRows);
    load8(v[3], x + 3 * kRows);
    load8(v[4], x + 4 * kRows);
    load8(v[5], x + 5 * kRows);
    load8(v[6], x + 6 * kRows);
    load8(v[7], x + 7 * kRows);
  }
  MPTRACK_FFT_INLINE static void store_rows8(float* x, const V8 (&v)[8]) {
    store8(x, v[0]);
    store8(x + kRows, v[1]);
    store8(x + 2 * kRows, v[2]);
    store8(x + 3 * kRows, v[3]);
    store8(x + 4 * kRows, v[4]);
    store8(x + 5 * kRows, v[5]);
    store8(x + 6 * kRows, v[6]);
    store8(x + 7 * kRows, v[7]);
  }

  // v[y] = row r3(y) in, v[x] = column x out (a plain 8 x 8 transpose of
  // the rows taken in the order 0, 4, 2, 6, 1, 5, 3, 7).
  MPTRACK_FFT_INLINE static void transpose8(V8 (&v)[8]) {
    const V8 t0 = __builtin_shuffle(v[0], v[4], M8{0, 8, 1, 9, 4, 12, 5, 13});
    const V8 t1 = __builtin_shuffle(v[0], v[4], M8{2, 10, 3, 11, 6, 14, 7, 15});
    const V8 t2 = __builtin_shuffle(v[2], v[6], M8{0, 8, 1, 9, 4, 12, 5, 13});
    const V8 t3 = __builtin_shuffle(v[2], v[6], M8{2, 10, 3, 11, 6, 14, 7, 15});
    const V8 t4 = __builtin_shuffle(v[1], v[5], M8{0, 8, 1, 9, 4, 12, 5, 13});
    const V8 t5 = __builtin_shuffle(v[1], v[5], M8{2, 10, 3, 11, 6, 14, 7, 15});
    const V8 t6 = __builtin_shuffle(v[3], v[7], M8{0, 8, 1, 9, 4, 12, 5, 13});
    const V8 t7 = __builtin_shuffle(v[3], v[7], M8{2, 10, 3, 11, 6, 14, 7, 15});
    // s_k: columns k | k + 4 of the upper (t0..t3) or lower (t4..t7) four rows.
    const V8 s0 = __builtin_shuffle(t0, t2, M8{0, 1, 8, 9, 4, 5, 12, 13});
    const V8 s1 = __builtin_shuffle(t0, t2, M8{2, 3, 10, 11, 6, 7, 14, 15});
    const V8 s2 = __builtin_shuffle(t1, t3, M8{0, 1, 8, 9, 4, 5, 12, 13});
    const V8 s3 = __builtin_shuffle(t1, t3, M8{2, 3, 10, 11, 6, 7, 14, 15});
    const V8 s4 = __builtin_shuffle(t4, t6, M8{0, 1, 8, 9, 4, 5, 12, 13});
    const V8 s5 = __builtin_shuffle(t4, t6, M8{2, 3, 10, 11, 6, 7, 14, 15});
    const V8 s6 = __builtin_shuffle(t5, t7, M8{0, 1, 8, 9, 4, 5, 12, 13});
    const V8 s7 = __builtin_shuffle(t5, t7, M8{2, 3, 10, 11, 6, 7, 14, 15});
    // Output row x = column r3(x).
    v[0] = __builtin_shuffle(s0, s4, M8{0, 1, 2, 3, 8, 9, 10, 11});    // column 0
    v[4] = __builtin_shuffle(s1, s5, M8{0, 1, 2, 3, 8, 9, 10, 11});    // column 1
    v[2] = __builtin_shuffle(s2, s6, M8{0, 1, 2, 3, 8, 9, 10, 11});    // column 2
    v[6] = __builtin_shuffle(s3, s7, M8{0, 1, 2, 3, 8, 9, 10, 11});    // column 3
    v[1] = __builtin_shuffle(s0, s4, M8{4, 5, 6, 7, 12, 13, 14, 15});  // column 4
    v[5] = __builtin_shuffle(s1, s5, M8{4, 5, 6, 7, 12, 13, 14, 15});  // column 5
    v[3] = __builtin_shuffle(s2, s6, M8{4, 5, 6, 7, 12, 13, 14, 15});  // column 6
    v[7] = __builtin_shuffle(s3, s7, M8{4, 5, 6, 7, 12, 13, 14, 15});  // column 7
  }

  // Block at column 8 b: load, both stages, transpose into output rows.
  MPTRACK_FFT_INLINE static void block8(const float* re, const float* im, const FirstTwiddles& w,
                                        V8 (&r)[8], V8 (&m)[8]) {
    load_rows8(re, r);
    load_rows8(im, m);
    radix2_radix4_rows(r, m, w);
    transpose8(r);
    transpose8(m);
  }
  MPTRACK_FFT_INLINE static void store_block8(float* re, float* im, const V8 (&r)[8],
                                              const V8 (&m)[8]) {
    store_rows8(re, r);
    store_rows8(im, m);
  }

  // The bit reversal alone in 8 x 8 blocks (even log2 N >= 8 in the AVX
  // copies): the same block pairing as radix2_radix4_permute_8x8.
  MPTRACK_FFT_INLINE static void permute_8x8(float* x) {
    static_assert(N >= 64, "8 x 8 blocks need N >= 64");
    constexpr std::size_t kMid = kLog2 - 6;
    for (std::size_t b = 0; b < N / 64; ++b) {
      const std::size_t rb = reverse_low_bits(b, kMid);
      if (rb < b) continue;  // the pair was handled at rb
      V8 p[8];
      load_rows8(x + 8 * b, p);
      transpose8(p);
      if (rb == b) {
        store_rows8(x + 8 * b, p);
        continue;
      }
      V8 q[8];
      load_rows8(x + 8 * rb, q);
      transpose8(q);
      store_rows8(x + 8 * rb, p);
      store_rows8(x + 8 * b, q);
    }
  }

  MPTRACK_FFT_INLINE static void radix2_radix4_permute_8x8(float* re, float* im,
                                                           const FirstTwiddles& w) {
    static_assert(N >= 128 && kLog2 % 2 == 1, "8 x 8 blocks of an odd log2 N >= 7");
    constexpr std::size_t kMid = kLog2 - 6;
    for (std::size_t b = 0; b < N / 64; ++b) {
      const std::size_t rb = reverse_low_bits(b, kMid);
      if (rb < b) continue;  // the pair was handled at rb
      V8 pr[8], pm[8];
      block8(re + 8 * b, im + 8 * b, w, pr, pm);
      if (rb == b) {
        store_block8(re + 8 * b, im + 8 * b, pr, pm);
        continue;
      }
      V8 qr[8], qm[8];
      block8(re + 8 * rb, im + 8 * rb, w, qr, qm);
      store_block8(re + 8 * rb, im + 8 * rb, pr, pm);
      store_block8(re + 8 * b, im + 8 * b, qr, qm);
    }
  }
  // N = 128, only in the AVX-512 copy: the eight rows (stride N/8 = 16) are
  // one 16-float register each. i = 16 a + c has rev(i) = 8 r4(c) + r3(a),
  // so output rows 2 k, 2 k + 1 (one register at 16 k) are input columns
  // r3(k) and 8 + r3(k) read down the rows r3(0..7): transpose8's shuffles
  // on each 128-bit lane (columns 0..7 and 8..15 at once), then the lanes
  // paired as [c | c + 8]. One block, in place.
  using V16 = float __attribute__((vector_size(64)));
  using M16 = std::int32_t __attribute__((vector_size(64)));
  MPTRACK_FFT_INLINE static void load16(V16& v, const float* p) { std::memcpy(&v, p, sizeof v); }
  MPTRACK_FFT_INLINE static void store16(float* p, const V16& v) { std::memcpy(p, &v, sizeof v); }
  MPTRACK_FFT_INLINE static void transpose8x16(V16 (&v)[8]) {
    constexpr M16 kLo{0, 16, 1, 17, 4, 20, 5, 21, 8, 24, 9, 25, 12, 28, 13, 29};
    constexpr M16 kHi{2, 18, 3, 19, 6, 22, 7, 23, 10, 26, 11, 27, 14, 30, 15, 31};
    constexpr M16 k44{0, 1, 16, 17, 4, 5, 20, 21, 8, 9, 24, 25, 12, 13, 28, 29};
    constexpr M16 kEe{2, 3, 18, 19, 6, 7, 22, 23, 10, 11, 26, 27, 14, 15, 30, 31};
    constexpr M16 kC0{0, 1, 2, 3, 16, 17, 18, 19, 8, 9, 10, 11, 24, 25, 26, 27};
    constexpr M16 kC4{4, 5, 6, 7, 20, 21, 22, 23, 12, 13, 14, 15, 28, 29, 30, 31};
    const V16 t0 = __builtin_shuffle(v[0], v[4], kLo);
    const V16 t1 = __builtin_shuffle(v[0], v[4], kHi);
    const V16 t2 = __builtin_shuffle(v[2], v[6], kLo);
    const V16 t3 = __builtin_shuffle(v[2], v[6], kHi);
    const V16 t4 = __builtin_shuffle(v[1], v[5], kLo);
    const V16 t5 = __builtin_shuffle(v[1], v[5], kHi);
    const V16 t6 = __builtin_shuffle(v[3], v[7], kLo);
    const V16 t7 = __builtin_shuffle(v[3], v[7], kHi);
    const V16 s0 = __builtin_shuffle(t0, t2, k44);
    const V16 s1 = __builtin_shuffle(t0, t2, kEe);
    const V16 s2 = __builtin_shuffle(t1, t3, k44);
    const V16 s3 = __builtin_shuffle(t1, t3, kEe);
    const V16 s4 = __builtin_shuffle(t4, t6, k44);
    const V16 s5 = __builtin_shuffle(t4, t6, kEe);
    const V16 s6 = __builtin_shuffle(t5, t7, k44);
    const V16 s7 = __builtin_shuffle(t5, t7, kEe);
    v[0] = __builtin_shuffle(s0, s4, kC0);  // columns 0 | 8
    v[4] = __builtin_shuffle(s1, s5, kC0);  // 1 | 9
    v[2] = __builtin_shuffle(s2, s6, kC0);  // 2 | 10
    v[6] = __builtin_shuffle(s3, s7, kC0);  // 3 | 11
    v[1] = __builtin_shuffle(s0, s4, kC4);  // 4 | 12
    v[5] = __builtin_shuffle(s1, s5, kC4);  // 5 | 13
    v[3] = __builtin_shuffle(s2, s6, kC4);  // 6 | 14
    v[7] = __builtin_shuffle(s3, s7, kC4);  // 7 | 15
  }
  MPTRACK_FFT_INLINE static void load_rows16(const float* x, V16 (&v)[8]) {
    load16(v[0], x);
    load16(v[1], x + 16);
    load16(v[2], x + 32);
    load16(v[3], x + 48);
    load16(v[4], x + 64);
    load16(v[5], x + 80);
    load16(v[6], x + 96);
    load16(v[7], x + 112);
  }
  MPTRACK_FFT_INLINE static void store_rows16(float* x, const V16 (&v)[8]) {
    store16(x, v[0]);
    store16(x + 16, v[1]);
    store16(x + 32, v[2]);
    store16(x + 48, v[3]);
    store16(x + 64, v[4]);
    store16(x + 80, v[5]);
    store16(x + 96, v[6]);
    store16(x + 112, v[7]);
  }
  MPTRACK_FFT_INLINE static void radix2_radix4_permute_128(float* re, float* im,
                                                           const FirstTwiddles& w) {
    static_assert(N == 128, "the 8 x 16 block is the whole transform only at N = 128");
    V16 r[8], m[8];
    load_rows16(re, r);
    load_rows16(im, m);
    radix2_radix4_rows(r, m, w);
    transpose8x16(r);
    transpose8x16(m);
    store_rows16(re, r);
    store_rows16(im, m);
  }
#endif
};

}  // namespace mptrack::dsp::fft_detail
