// Build configuration of the FFT (fft.h): which vector paths and which x86
// dispatch copies exist on this target, and the compile-time size helpers.
// Data movement and code generation only: no macro here changes an operation.
#pragma once

#include <cstddef>

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

/// The copies of an FFT schedule a build may hold (Fft::forward_copy,
/// FftBatch::forward_copy): the baseline build's code and, on x86-64 hosts,
/// the same schedule compiled for AVX2 or AVX-512 (same operations per
/// element, so the same bits).
enum class FftCopy { kBaseline, kAvx2, kAvx512 };

/// True when this build holds `copy` and this CPU can run it.
inline bool fft_copy_available(FftCopy copy) {
  switch (copy) {
    case FftCopy::kBaseline:
      return true;
#if MPTRACK_FFT_X86_DISPATCH
    case FftCopy::kAvx2:
      return __builtin_cpu_supports("avx2");
    case FftCopy::kAvx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
#endif
    default:
      return false;
  }
}

/// The widest copy this build and CPU can run: what forward() dispatches to.
inline FftCopy widest_fft_copy() {
  if (fft_copy_available(FftCopy::kAvx512)) return FftCopy::kAvx512;
  if (fft_copy_available(FftCopy::kAvx2)) return FftCopy::kAvx2;
  return FftCopy::kBaseline;
}

/// The copy's name in reports: "avx512", "avx2" or "baseline".
constexpr const char* fft_copy_name(FftCopy copy) {
  return copy == FftCopy::kAvx512 ? "avx512" : copy == FftCopy::kAvx2 ? "avx2" : "baseline";
}

/// Compile-time check: n is a power of two >= 2.
constexpr bool is_power_of_two(std::size_t n) { return n >= 2 && (n & (n - 1)) == 0; }

/// log2 of a power of two.
constexpr std::size_t log2_exact(std::size_t n) {
  std::size_t l = 0;
  while ((std::size_t{1} << l) < n) ++l;
  return l;
}

/// j's low `bits` bits in reverse order: the bit-reversal index, also of
/// the block indices the blocked permutations pair up.
constexpr std::size_t reverse_low_bits(std::size_t j, std::size_t bits) {
  std::size_t r = 0;
  for (std::size_t b = 0; b < bits; ++b) {
    if ((j >> b) & 1u) r |= std::size_t{1} << (bits - 1 - b);
  }
  return r;
}

}  // namespace mptrack::dsp
