// AVX-512 copy of CfarScreen's closed-form edge test under kShift for CA and
// GO (cfar_screen.h, shift_lower_edge / shift_upper_edge): 16 edge cells at
// a time, each window sum from masked contiguous loads of the prefix sums.
//
// Why: the portable loops run 1..16 cells with run-time bounds and byte
// stores, which GCC 12 leaves scalar; at 128-cell lines the edge cells (20
// at G = 2, T = 8) were the largest fixed cost of a line's screen
// (bench/README.md, session 15). The same integers (sums mod 2^32), one
// int32-to-float conversion, one product and one ordered compare per cell,
// as in the portable loops: the same cells are kept
// (tests/unit/cfar_screen_test.cpp compares the copies and the planned
// tables). Masked lanes load nothing, so indices past either end of the
// prefix array are never read. The maskz forms of convert and blend: GCC
// 12's plain forms start from an undefined vector and trip
// -Werror=maybe-uninitialized.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mptrack/dsp/fft_config.h"

#if MPTRACK_FFT_X86_DISPATCH
#include <immintrin.h>

namespace mptrack::frontend::cfar_detail {

/// Where the edge cells' window sums are read (cfar_screen.h, edge_prefix).
struct ShiftEdgeGeometry {
  const std::uint32_t* q = nullptr;  ///< prefix sums, kLen + 1 entries
  std::size_t len = 0;               ///< kLen
  std::size_t guard = 0;             ///< G
  std::size_t train = 0;             ///< T
};

#define MPTRACK_CFAR_AVX512 __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), always_inline)) inline

MPTRACK_CFAR_AVX512 __m512i load_at(const std::uint32_t* q, std::ptrdiff_t at, __mmask16 m) {
  return _mm512_maskz_loadu_epi32(m, q + at);
}

// flags[i..i+16) under mask m = line > float(int32(w)) * k.
MPTRACK_CFAR_AVX512 void store_flags(const float* line, std::uint8_t* flags, std::size_t i, __m512i w,
                                     __m512 k, __mmask16 m) {
  const __m512 threshold = _mm512_mul_ps(_mm512_maskz_cvtepi32_ps(m, w), k);
  const __m512 x = _mm512_maskz_loadu_ps(m, line + i);
  const __mmask16 kept = _mm512_mask_cmp_ps_mask(m, x, threshold, _CMP_GT_OQ);
  _mm512_mask_cvtepi32_storeu_epi8(flags + i, m, _mm512_maskz_set1_epi32(kept, 1));
}

MPTRACK_CFAR_AVX512 __mmask16 lanes_below(std::size_t from, std::size_t to) {
  const std::size_t n = to - from < 16 ? to - from : 16;
  return static_cast<__mmask16>((1u << n) - 1u);
}

// Mask of the lanes whose cell from + l is < bound.
MPTRACK_CFAR_AVX512 __mmask16 cells_below(std::size_t from, std::size_t bound) {
  if (bound <= from) return 0;
  return lanes_below(from, bound);
}

/// Lower edge cells [from, to): i <= G reads q[i+G+1+2T] - q[i+G+1],
/// i > G reads q[i-G] + q[E] - q[i+G+1] (E = 2(G + T) + 1).
MPTRACK_CFAR_AVX512 void shift_lower_edge_avx512(const ShiftEdgeGeometry& s, const float* line,
                                                 std::uint8_t* flags, std::size_t from, std::size_t to,
                                                 float k) {
  const std::ptrdiff_t g = static_cast<std::ptrdiff_t>(s.guard);
  const std::ptrdiff_t t = static_cast<std::ptrdiff_t>(s.train);
  const __m512i qe = _mm512_set1_epi32(static_cast<int>(s.q[2 * (s.guard + s.train) + 1]));
  const __m512 kv = _mm512_set1_ps(k);
  for (std::size_t i = from; i < to; i += 16) {
    const __mmask16 m = lanes_below(i, to);
    const __mmask16 near = static_cast<__mmask16>(m & cells_below(i, s.guard + 1));  // i <= G
    const __mmask16 far = static_cast<__mmask16>(m & ~near);
    const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(i);
    const __m512i right = load_at(s.q, at + g + 1, m);
    const __m512i w_near = _mm512_sub_epi32(load_at(s.q, at + g + 1 + 2 * t, near), right);
    const __m512i w_far = _mm512_sub_epi32(_mm512_add_epi32(load_at(s.q, at - g, far), qe), right);
    store_flags(line, flags, i, _mm512_mask_blend_epi32(near, w_far, w_near), kv, m);
  }
}

/// Upper edge cells [from, to): i < kLen - G - 1 reads (q[i-G] - q[B]) +
/// (q[kLen] - q[i+G+1]) (B = kLen - E), the rest q[i-G] - q[i-G-2T].
MPTRACK_CFAR_AVX512 void shift_upper_edge_avx512(const ShiftEdgeGeometry& s, const float* line,
                                                 std::uint8_t* flags, std::size_t from, std::size_t to,
                                                 float k) {
  const std::ptrdiff_t g = static_cast<std::ptrdiff_t>(s.guard);
  const std::ptrdiff_t t = static_cast<std::ptrdiff_t>(s.train);
  const std::size_t base = s.len - (2 * (s.guard + s.train) + 1);
  const __m512i tail = _mm512_set1_epi32(static_cast<int>(s.q[s.len] - s.q[base]));
  const __m512 kv = _mm512_set1_ps(k);
  for (std::size_t i = from; i < to; i += 16) {
    const __mmask16 m = lanes_below(i, to);
    const __mmask16 inner = static_cast<__mmask16>(m & cells_below(i, s.len - s.guard - 1));
    const __mmask16 outer = static_cast<__mmask16>(m & ~inner);
    const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(i);
    const __m512i left = load_at(s.q, at - g, m);
    const __m512i w_inner = _mm512_sub_epi32(_mm512_add_epi32(left, tail), load_at(s.q, at + g + 1, inner));
    const __m512i w_outer = _mm512_sub_epi32(left, load_at(s.q, at - g - 2 * t, outer));
    store_flags(line, flags, i, _mm512_mask_blend_epi32(inner, w_outer, w_inner), kv, m);
  }
}

#undef MPTRACK_CFAR_AVX512

}  // namespace mptrack::frontend::cfar_detail

#endif  // MPTRACK_FFT_X86_DISPATCH
