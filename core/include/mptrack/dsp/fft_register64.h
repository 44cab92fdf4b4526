// N = 64 in the x86 AVX2 / AVX-512 copies: the whole transform in registers
// (8 rows of 8 floats per array; fft.h schedule). Between passes of different
// widths, memory costs more than the arithmetic here: a pass that loads a
// wide vector over four narrower stores of the pass before waits for them
// to reach the cache (no store forwarding; measured with perf, ~40 % of
// the in-memory schedule at N = 64). Each stage performs the operations of
// its in-memory pass (fft_kernels.h *_values) on the same operands; only
// which lanes of which register hold them differs. So the same bits
// (tests/unit/fft_dispatch_test.cpp, fft_reorder_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mptrack/dsp/fft_config.h"
#include "mptrack/dsp/fft_fused_first.h"
#include "mptrack/dsp/fft_kernels.h"

namespace mptrack::dsp::fft_detail {

#if MPTRACK_FFT_X86_DISPATCH
/// Forward transform of 64 points held as rows x (slots 8 x .. 8 x + 7).
struct Register64 {
  using Block = FusedFirst<64>;
  using V8 = Block::V8;
  using M8 = Block::M8;

  /// Twiddle run w[j], j = 0..3, in both halves (two groups per register).
  /// One 8-float load and a lane shuffle (two 4-float copies into a stack
  /// register would stall the wide load that reads them back).
  MPTRACK_FFT_INLINE static void load_twice4(V8& v, const float* w) {
    V8 t;
    Block::load8(t, w);  // w[0..7]: within the 64-float table for w = tw + 3, tw + 7
    v = __builtin_shuffle(t, M8{0, 1, 2, 3, 0, 1, 2, 3});
  }

  // Lower / upper halves of two registers: [a.lo | b.lo], [a.hi | b.hi].
  MPTRACK_FFT_INLINE static void halves(const V8& a, const V8& b, V8& lo, V8& hi) {
    lo = __builtin_shuffle(a, b, M8{0, 1, 2, 3, 8, 9, 10, 11});
    hi = __builtin_shuffle(a, b, M8{4, 5, 6, 7, 12, 13, 14, 15});
  }

  // radix4_pass<4> on rows 2 g, 2 g + 1 for the group pair g = q, q + 1
  // (q = 0 or 2): operands base + j + 4 k are the row halves, packed as
  // [group q | group q + 1], j = 0..3 in each half.
  MPTRACK_FFT_INLINE static void pass4_pair(V8 (&r)[8], V8 (&m)[8], std::size_t q,
                                            const float* tw_re, const float* tw_im) {
    const std::size_t a = 2 * q, b = 2 * q + 1, c = 2 * q + 2, d = 2 * q + 3;
    V8 r0, r1, r2, r3, i0, i1, i2, i3;
    halves(r[a], r[c], r0, r1);
    halves(r[b], r[d], r2, r3);
    halves(m[a], m[c], i0, i1);
    halves(m[b], m[d], i2, i3);
    V8 w1r, w1i, w2r, w2i;
    load_twice4(w1r, tw_re + 3);  // W_8^j at offset h - 1 = 3
    load_twice4(w1i, tw_im + 3);
    load_twice4(w2r, tw_re + 7);  // W_16^j at offset 2 h - 1 = 7
    load_twice4(w2i, tw_im + 7);
    radix4_values(r0, i0, r1, i1, r2, i2, r3, i3, w1r, w1i, w2r, w2i);
    halves(r0, r1, r[a], r[c]);
    halves(r2, r3, r[b], r[d]);
    halves(i0, i1, m[a], m[c]);
    halves(i2, i3, m[b], m[d]);
  }

  MPTRACK_FFT_INLINE static void forward(float* re, float* im, const float* tw_re,
                                         const float* tw_im) {
    V8 r[8], m[8];
    Block::load_rows8(re, r);
    Block::load_rows8(im, m);
    // radix4_first in input order: groups (rows 0, 4, 2, 6) and (1, 5, 3, 7).
    radix4_first_values(r[0], m[0], r[4], m[4], r[2], m[2], r[6], m[6]);
    radix4_first_values(r[1], m[1], r[5], m[5], r[3], m[3], r[7], m[7]);
    Block::transpose8(r);  // bit reversal: now row x holds slots 8 x .. 8 x + 7
    Block::transpose8(m);
    pass4_pair(r, m, 0, tw_re, tw_im);
    pass4_pair(r, m, 2, tw_re, tw_im);
    // radix4_pass<16>: operands j + 16 k, rows (0, 2, 4, 6) for j < 8 and
    // (1, 3, 5, 7) for j >= 8; twiddles at offsets 15 and 31.
    for (std::size_t h = 0; h < 2; ++h) {
      V8 w1r, w1i, w2r, w2i;
      Block::load8(w1r, tw_re + 15 + 8 * h);
      Block::load8(w1i, tw_im + 15 + 8 * h);
      Block::load8(w2r, tw_re + 31 + 8 * h);
      Block::load8(w2i, tw_im + 31 + 8 * h);
      radix4_values(r[h], m[h], r[h + 2], m[h + 2], r[h + 4], m[h + 4], r[h + 6], m[h + 6], w1r,
                    w1i, w2r, w2i);
    }
    Block::store_rows8(re, r);
    Block::store_rows8(im, m);
  }
};
/// N = 64 in the AVX-512 copy: the same stages on 16-float registers (two
/// rows each, four per array), so half the instructions of Register64.
struct Register64Zmm {
  using V16 = FusedFirst<128>::V16;
  using M16 = FusedFirst<128>::M16;

  MPTRACK_FFT_INLINE static void load16(V16& v, const float* p) { std::memcpy(&v, p, sizeof v); }
  MPTRACK_FFT_INLINE static void store16(float* p, const V16& v) { std::memcpy(p, &v, sizeof v); }
  MPTRACK_FFT_INLINE static void load4x16(const float* x, V16 (&v)[4]) {
    load16(v[0], x);
    load16(v[1], x + 16);
    load16(v[2], x + 32);
    load16(v[3], x + 48);
  }
  MPTRACK_FFT_INLINE static void store4x16(float* x, const V16 (&v)[4]) {
    store16(x, v[0]);
    store16(x + 16, v[1]);
    store16(x + 32, v[2]);
    store16(x + 48, v[3]);
  }

  // Input order A_q = slots 16 q .. 16 q + 15 (after radix4_first) to the
  // operands of radix4_pass<4>: R_k lane 4 g + i = natural slot 16 g + 4 k +
  // i = input slot rev(16 g + 4 k + i) = 16 r2(i) + 4 r2(k) + r2(g), i.e.
  // A_{r2(i)} lane s = 4 r2(k) + r2(g). Lanes i = 0, 2 come from A_0, A_1
  // and i = 1, 3 from A_2, A_3 with the same lane pattern: two shuffles
  // and a blend per R_k.
  MPTRACK_FFT_INLINE static void to_pass4(const V16 (&a)[4], V16 (&r)[4]) {
    constexpr M16 kM0{0, 0, 16, 16, 2, 2, 18, 18, 1, 1, 17, 17, 3, 3, 19, 19};
    constexpr M16 kM1{8, 8, 24, 24, 10, 10, 26, 26, 9, 9, 25, 25, 11, 11, 27, 27};
    constexpr M16 kM2{4, 4, 20, 20, 6, 6, 22, 22, 5, 5, 21, 21, 7, 7, 23, 23};
    constexpr M16 kM3{12, 12, 28, 28, 14, 14, 30, 30, 13, 13, 29, 29, 15, 15, 31, 31};
    constexpr M16 kBlend{0, 17, 2, 19, 4, 21, 6, 23, 8, 25, 10, 27, 12, 29, 14, 31};
    r[0] = __builtin_shuffle(__builtin_shuffle(a[0], a[1], kM0), __builtin_shuffle(a[2], a[3], kM0),
                             kBlend);
    r[1] = __builtin_shuffle(__builtin_shuffle(a[0], a[1], kM1), __builtin_shuffle(a[2], a[3], kM1),
                             kBlend);
    r[2] = __builtin_shuffle(__builtin_shuffle(a[0], a[1], kM2), __builtin_shuffle(a[2], a[3], kM2),
                             kBlend);
    r[3] = __builtin_shuffle(__builtin_shuffle(a[0], a[1], kM3), __builtin_shuffle(a[2], a[3], kM3),
                             kBlend);
  }

  // R_k lane block g -> Z_g lane block k (a 4 x 4 transpose of 4-float
  // blocks): Z_g = natural slots 16 g .. 16 g + 15, radix4_pass<16>'s operands.
  MPTRACK_FFT_INLINE static void to_natural(const V16 (&r)[4], V16 (&z)[4]) {
    constexpr M16 kLo{0, 1, 2, 3, 16, 17, 18, 19, 4, 5, 6, 7, 20, 21, 22, 23};
    constexpr M16 kHi{8, 9, 10, 11, 24, 25, 26, 27, 12, 13, 14, 15, 28, 29, 30, 31};
    constexpr M16 kFirst{0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23};
    constexpr M16 kSecond{8, 9, 10, 11, 12, 13, 14, 15, 24, 25, 26, 27, 28, 29, 30, 31};
    const V16 x01lo = __builtin_shuffle(r[0], r[1], kLo);  // R0.b0 R1.b0 R0.b1 R1.b1
    const V16 x01hi = __builtin_shuffle(r[0], r[1], kHi);  // R0.b2 R1.b2 R0.b3 R1.b3
    const V16 x23lo = __builtin_shuffle(r[2], r[3], kLo);
    const V16 x23hi = __builtin_shuffle(r[2], r[3], kHi);
    z[0] = __builtin_shuffle(x01lo, x23lo, kFirst);
    z[1] = __builtin_shuffle(x01lo, x23lo, kSecond);
    z[2] = __builtin_shuffle(x01hi, x23hi, kFirst);
    z[3] = __builtin_shuffle(x01hi, x23hi, kSecond);
  }

  /// Twiddle run w[0..3] in all four 4-float blocks.
  MPTRACK_FFT_INLINE static void load_four4(V16& v, const float* w) {
    constexpr M16 kRep{0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3};
    V16 t;
    load16(t, w);  // w[0..15]: within the 64-float table for w = tw + 3, tw + 7
    v = __builtin_shuffle(t, kRep);
  }

  MPTRACK_FFT_INLINE static void forward(float* re, float* im, const float* tw_re,
                                         const float* tw_im) {
    V16 ar[4], am[4];  // constant indices only: kept in registers
    load4x16(re, ar);
    load4x16(im, am);
    // radix4_first in input order: p0, p1, p2, p3 = slots r, r + 32, r + 16, r + 48.
    radix4_first_values(ar[0], am[0], ar[2], am[2], ar[1], am[1], ar[3], am[3]);
    V16 rr[4], rm[4];
    to_pass4(ar, rr);
    to_pass4(am, rm);
    V16 w1r, w1i, w2r, w2i;
    load_four4(w1r, tw_re + 3);  // W_8^j at offset h - 1 = 3
    load_four4(w1i, tw_im + 3);
    load_four4(w2r, tw_re + 7);  // W_16^j at offset 2 h - 1 = 7
    load_four4(w2i, tw_im + 7);
    radix4_values(rr[0], rm[0], rr[1], rm[1], rr[2], rm[2], rr[3], rm[3], w1r, w1i, w2r, w2i);
    to_natural(rr, ar);
    to_natural(rm, am);
    load16(w1r, tw_re + 15);  // W_32^j, j = 0..15
    load16(w1i, tw_im + 15);
    load16(w2r, tw_re + 31);  // W_64^j
    load16(w2i, tw_im + 31);
    radix4_values(ar[0], am[0], ar[1], am[1], ar[2], am[2], ar[3], am[3], w1r, w1i, w2r, w2i);
    store4x16(re, ar);
    store4x16(im, am);
  }
};
#endif

}  // namespace mptrack::dsp::fft_detail
