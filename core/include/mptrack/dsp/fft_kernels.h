// Butterfly kernels of the FFT (fft.h): the exact per-element operation
// sequences of the DIT radix-2 and radix-2^2 butterflies over runs of
// elements. Every schedule in fft.h and fft_bit_reversal.h performs these
// operations, in this order, on the same operands (the bit-exact rule).
#pragma once

#include <cstddef>
#include <type_traits>

#include "mptrack/dsp/fft_config.h"

namespace mptrack::dsp {

namespace fft_detail {

// The butterflies on one set of values (*_values: a float, or a GCC vector
// whose lanes each see the same operations), the only place where the
// per-element operation sequence of the DIT radix-2 / radix-2^2 butterfly
// is written; every schedule (the loops below, the register blocks of
// fft_fused_first.h and fft_register64.h) calls them, so only the schedule
// differs between users.

/// Radix 2, twiddle 1: (a, b) -> (a + b, a - b).
template <class T>
MPTRACK_FFT_INLINE void radix2_values(T& r0, T& i0, T& r1, T& i1) {
  const T tr = r1;
  const T ti = i1;
  r1 = r0 - tr;
  i1 = i0 - ti;
  r0 = r0 + tr;
  i0 = i0 + ti;
}

/// Half-sizes 1 and 2 fused (twiddles 1 and -j): no multiplies.
template <class T>
MPTRACK_FFT_INLINE void radix4_first_values(T& r0, T& i0, T& r1, T& i1, T& r2, T& i2, T& r3,
                                            T& i3) {
  const T b0r = r0 + r1;
  const T b0i = i0 + i1;
  const T b1r = r0 - r1;
  const T b1i = i0 - i1;
  const T b2r = r2 + r3;
  const T b2i = i2 + i3;
  const T b3r = r2 - r3;
  const T b3i = i2 - i3;
  r0 = b0r + b2r;
  i0 = b0i + b2i;
  r2 = b0r - b2r;
  i2 = b0i - b2i;
  r1 = b1r + b3i;  // -j * b3 = (b3i, -b3r)
  i1 = b1i - b3r;
  r3 = b1r - b3i;
  i3 = b1i + b3r;
}

/// Two radix-2 stages (half-sizes h, 2h) fused: operands a0..a3, twiddles
/// w1 = W_{2h}^j, w2 = W_{4h}^j (W: float, which GCC broadcasts to every
/// lane without arithmetic, or T); the odd pair's second twiddle -j w2 is
/// applied as a swap.
template <class T, class W>
MPTRACK_FFT_INLINE void radix4_values(T& r0, T& i0, T& r1, T& i1, T& r2, T& i2, T& r3, T& i3,
                                      const W& a1r, const W& a1i, const W& a2r, const W& a2i) {
  const T t1r = a1r * r1 - a1i * i1;
  const T t1i = a1r * i1 + a1i * r1;
  const T t3r = a1r * r3 - a1i * i3;
  const T t3i = a1r * i3 + a1i * r3;
  const T b0r = r0 + t1r;
  const T b0i = i0 + t1i;
  const T b1r = r0 - t1r;
  const T b1i = i0 - t1i;
  const T b2r = r2 + t3r;
  const T b2i = i2 + t3i;
  const T b3r = r2 - t3r;
  const T b3i = i2 - t3i;
  const T u2r = a2r * b2r - a2i * b2i;
  const T u2i = a2r * b2i + a2i * b2r;
  const T u3r = a2r * b3r - a2i * b3i;
  const T u3i = a2r * b3i + a2i * b3r;
  r0 = b0r + u2r;
  i0 = b0i + u2i;
  r2 = b0r - u2r;
  i2 = b0i - u2i;
  r1 = b1r + u3i;  // -j * u3 = (u3i, -u3r)
  i1 = b1i - u3r;
  r3 = b1r - u3i;
  i3 = b1i + u3r;
}

// The same over runs of kLen elements. The no-alias facts are __restrict
// FUNCTION PARAMETERS: GCC keeps those when it inlines the kernel into a
// pass (the dispatch copies inline everything), whereas __restrict local
// variables lose them and the loops stop vectorising.

/// radix2_values over a run.
template <std::size_t kLen>
MPTRACK_FFT_INLINE void radix2_run(float* __restrict r0, float* __restrict i0,
                                   float* __restrict r1, float* __restrict i1) {
  MPTRACK_FFT_NO_UNROLL
  for (std::size_t r = 0; r < kLen; ++r) radix2_values(r0[r], i0[r], r1[r], i1[r]);
}

/// radix4_first_values over a run.
template <std::size_t kLen>
MPTRACK_FFT_INLINE void radix4_first_run(float* __restrict r0, float* __restrict i0,
                                         float* __restrict r1, float* __restrict i1,
                                         float* __restrict r2, float* __restrict i2,
                                         float* __restrict r3, float* __restrict i3) {
  MPTRACK_FFT_NO_UNROLL
  for (std::size_t r = 0; r < kLen; ++r) {
    radix4_first_values(r0[r], i0[r], r1[r], i1[r], r2[r], i2[r], r3[r], i3[r]);
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
    if constexpr (kPerElement) {
      radix4_values(r0[j], i0[j], r1[j], i1[j], r2[j], i2[j], r3[j], i3[j], w1r[j], w1i[j],
                    w2r[j], w2i[j]);
    } else {
      radix4_values(r0[j], i0[j], r1[j], i1[j], r2[j], i2[j], r3[j], i3[j], w1r, w1i, w2r, w2i);
    }
  }
}

/// Twiddles of the half-size-2 stage pair (h = 2, 4) for j = 0, 1:
/// w1 = W_4^j, w2 = W_8^j (Fft's table at offsets 1 + j and 3 + j).
struct FirstTwiddles {
  float w1r[2];
  float w1i[2];
  float w2r[2];
  float w2i[2];
};

/// radix2_radix4_input_order's work on eight rows held in values (rows
/// q + m N/8, m = 0..7, of the input order): radix 2 on rows (m, m + 4),
/// then half-size 2 with j = 0 on rows 0, 2, 1, 3 and j = 1 on rows 4, 6,
/// 5, 7. The same operations per element as the in-memory pass.
// Written out with constant indices (no loops): GCC keeps the arrays in
// registers only when every index is a constant before its scalar
// replacement pass runs (with loops it spilled every row to the stack).
template <class V>
MPTRACK_FFT_INLINE void radix2_radix4_rows(V (&r)[8], V (&m)[8], const FirstTwiddles& w) {
  radix2_values(r[0], m[0], r[4], m[4]);
  radix2_values(r[1], m[1], r[5], m[5]);
  radix2_values(r[2], m[2], r[6], m[6]);
  radix2_values(r[3], m[3], r[7], m[7]);
  radix4_values(r[0], m[0], r[2], m[2], r[1], m[1], r[3], m[3], w.w1r[0], w.w1i[0], w.w2r[0],
                w.w2i[0]);
  radix4_values(r[4], m[4], r[6], m[6], r[5], m[5], r[7], m[7], w.w1r[1], w.w1i[1], w.w2r[1],
                w.w2i[1]);
}

}  // namespace fft_detail

}  // namespace mptrack::dsp
