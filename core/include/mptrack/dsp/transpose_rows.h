// Row-to-column moves of planar float blocks: rows[r][g] (R rows of G
// values, row stride G) into runs out[g][0..R) (run stride kOutStride).
// Data movement only: every value is copied bit for bit, in any copy.
//
// The range stage stages the R = kNumVirtual compressed profiles of one chirp
// as rows and needs them as one run of R channels per range bin
// (docs/algorithms/frontend.md §FFT). Done value by value that is one load and
// one store per value; the AVX-512 copy moves 16 bins at a time through a
// 16 x 16 register transpose (rows R..15 zero) and writes each run with one
// masked store of R lanes.
#pragma once

#include <cstddef>

#include "mptrack/dsp/fft_config.h"

#if MPTRACK_FFT_X86_DISPATCH
#include <immintrin.h>
#endif

namespace mptrack::dsp {

/// Portable copy: out[g * kOutStride + r] = rows[r * G + g] for bins
/// g = first..G-1 (first > 0: the tail the AVX-512 copy leaves).
template <std::size_t R, std::size_t G, std::size_t kOutStride>
MPTRACK_FFT_INLINE void transpose_rows(const float* __restrict rows, float* __restrict out,
                                       std::size_t first = 0) {
  for (std::size_t g = first; g < G; ++g) {
    float* __restrict run = out + g * kOutStride;
    for (std::size_t r = 0; r < R; ++r) run[r] = rows[r * G + g];
  }
}

#if MPTRACK_FFT_X86_DISPATCH
namespace transpose_detail {

// In-register transpose of 16 rows of 16 floats: v[j] becomes column j.
// Interleave pairs of rows, then pairs of pairs (64-bit), then the 128-bit
// lanes in two rounds. The all-lanes masked forms are the same instructions
// as the plain intrinsics; GCC 12's plain forms start from an undefined
// register, which -Werror=uninitialized rejects.
__attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), always_inline)) inline void
transpose16(__m512 v[16]) {
  const __m512 zs = _mm512_setzero_ps();
  const __m512d zd = _mm512_setzero_pd();
  constexpr __mmask16 kAll16 = 0xffff;
  constexpr __mmask8 kAll8 = 0xff;
  __m512 t[16];
  for (int i = 0; i < 8; ++i) {
    t[2 * i] = _mm512_mask_unpacklo_ps(zs, kAll16, v[2 * i], v[2 * i + 1]);
    t[2 * i + 1] = _mm512_mask_unpackhi_ps(zs, kAll16, v[2 * i], v[2 * i + 1]);
  }
  for (int i = 0; i < 4; ++i) {
    const __m512d a = _mm512_castps_pd(t[4 * i]);
    const __m512d b = _mm512_castps_pd(t[4 * i + 1]);
    const __m512d c = _mm512_castps_pd(t[4 * i + 2]);
    const __m512d d = _mm512_castps_pd(t[4 * i + 3]);
    v[4 * i] = _mm512_castpd_ps(_mm512_mask_unpacklo_pd(zd, kAll8, a, c));
    v[4 * i + 1] = _mm512_castpd_ps(_mm512_mask_unpackhi_pd(zd, kAll8, a, c));
    v[4 * i + 2] = _mm512_castpd_ps(_mm512_mask_unpacklo_pd(zd, kAll8, b, d));
    v[4 * i + 3] = _mm512_castpd_ps(_mm512_mask_unpackhi_pd(zd, kAll8, b, d));
  }
  // Now lane k of v[4i + j] holds rows 4i..4i+3 of column 4k + j.
  for (int j = 0; j < 4; ++j) {
    t[j] = _mm512_mask_shuffle_f32x4(zs, kAll16, v[j], v[4 + j], 0x88);
    t[4 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, v[j], v[4 + j], 0xdd);
    t[8 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, v[8 + j], v[12 + j], 0x88);
    t[12 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, v[8 + j], v[12 + j], 0xdd);
  }
  for (int j = 0; j < 4; ++j) {
    v[j] = _mm512_mask_shuffle_f32x4(zs, kAll16, t[j], t[8 + j], 0x88);
    v[8 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, t[j], t[8 + j], 0xdd);
    v[4 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, t[4 + j], t[12 + j], 0x88);
    v[12 + j] = _mm512_mask_shuffle_f32x4(zs, kAll16, t[4 + j], t[12 + j], 0xdd);
  }
}

}  // namespace transpose_detail

/// AVX-512 copy of transpose_rows (R <= 16): blocks of 16 bins, the rest
/// value by value. Call only where the CPU has AVX-512F. Not inlined: the
/// callers are force-inlined helpers compiled for the baseline first.
template <std::size_t R, std::size_t G, std::size_t kOutStride>
__attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void transpose_rows_avx512(
    const float* __restrict rows, float* __restrict out) {
  if constexpr (R > 16) {
    transpose_rows<R, G, kOutStride>(rows, out);
  } else {
    constexpr __mmask16 kLanes = static_cast<__mmask16>((1u << R) - 1u);
    constexpr std::size_t kBlocks = G / 16;
    for (std::size_t b = 0; b < kBlocks; ++b) {
      __m512 v[16];
      for (std::size_t r = 0; r < 16; ++r) {
        v[r] = r < R ? _mm512_loadu_ps(rows + r * G + 16 * b) : _mm512_setzero_ps();
      }
      transpose_detail::transpose16(v);
      for (std::size_t j = 0; j < 16; ++j) {
        _mm512_mask_storeu_ps(out + (16 * b + j) * kOutStride, kLanes, v[j]);
      }
    }
    transpose_rows<R, G, kOutStride>(rows, out, 16 * kBlocks);
  }
}
#endif

}  // namespace mptrack::dsp
