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
#endif

}  // namespace mptrack::dsp::fft_detail
