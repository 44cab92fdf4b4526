// L independent FFTs of length N computed together, one per lane, with the
// same bits as L calls of Fft<N>::forward().
//
// Why: the angle stage transforms a short snapshot (N = 32..64 bins) for
// every range-Doppler cell. One Fft<N> call per cell costs the call, the
// bit-reversal swaps and vectors only N/4 long, and its output must then be
// scattered down a map column (stride kNumRangeBins). With the lane as the
// innermost index (row k holds element k of every lane's transform), every
// butterfly is a run of L adjacent floats: a whole vector register per row
// on any SIMD target, no permutation at all (the caller writes input n
// straight into row rev(n)), and output row k is already the L adjacent
// range bins of one map line (docs/algorithms/frontend.md §FFT).
//
// Bit-exactness: the schedule is the textbook one of tests/unit/
// fft_reorder_test.cpp (bit reversal, then radix 2 when log2 N is odd or
// the twiddle-free radix-4 pass when even, then the radix-2^2 passes of
// half-sizes 2 or 4, x4, ...), with Fft<N>'s own twiddles and the butterfly
// kernels of fft_kernels.h; each lane sees exactly the operations of
// Fft<N>::forward(), which that test proves bit-equal to the same schedule.
// tests/unit/fft_batch_test.cpp compares every lane with Fft<N>::forward()
// bit for bit, for every copy.
//
// Footprint: 2 N L floats of rows plus Fft<N>'s 2 N floats of twiddles.
#pragma once

#include <array>
#include <cstddef>

#include "mptrack/dsp/fft.h"
#include "mptrack/dsp/fft_config.h"
#include "mptrack/dsp/fft_kernels.h"
#include "mptrack/status.h"

namespace mptrack::dsp {

template <std::size_t N, std::size_t L>
class FftBatch {
  static_assert(L >= 1, "FftBatch needs at least one lane");

 public:
  static constexpr std::size_t kSize = N;
  static constexpr std::size_t kLanes = L;
  static constexpr std::size_t kLog2 = log2_exact(N);

  /// Builds the twiddles (those of Fft<N>). Always kOk.
  Status init() { return fft_.init(); }
  bool initialized() const { return fft_.initialized(); }

  /// Where lane l's input element n goes: input_re(n)[l], input_im(n)[l].
  /// (Row rev(n): the bit-reversal permutation is done by the writes.)
  float* input_re(std::size_t n) { return re_[kInputRow[n]].data(); }
  float* input_im(std::size_t n) { return im_[kInputRow[n]].data(); }

  /// Input element n of every lane = 0 (zero padding).
  void zero_input(std::size_t n) { zero_run(input_re(n), input_im(n)); }

  /// Output element k of lane l after forward(): output_re(k)[l].
  const float* output_re(std::size_t k) const { return re_[k].data(); }
  const float* output_im(std::size_t k) const { return im_[k].data(); }

  /// Forward DFT of every lane, unscaled, as Fft<N>::forward() (in place:
  /// the input rows become the output rows). Precondition: init() succeeded.
  void forward() { static_cast<void>(forward_copy(widest_fft_copy())); }

  /// Runs one copy of the schedule (tests: every copy gives the same
  /// bits). False, nothing done, when this build or CPU lacks that copy.
  bool forward_copy(FftCopy copy) {
    if (!fft_copy_available(copy)) return false;
#if MPTRACK_FFT_X86_DISPATCH
    if (copy == FftCopy::kAvx512) {
      forward_avx512();
      return true;
    }
    if (copy == FftCopy::kAvx2) {
      forward_avx2();
      return true;
    }
#endif
    forward_schedule();
    return true;
  }

 private:
  using Row = std::array<float, L>;

  // Row of input element n: rev(n), tabulated (callers write in inner loops).
  static constexpr std::array<std::size_t, N> input_rows() {
    std::array<std::size_t, N> rows{};
    for (std::size_t n = 0; n < N; ++n) rows[n] = reverse_low_bits(n, kLog2);
    return rows;
  }
  static constexpr std::array<std::size_t, N> kInputRow = input_rows();

#if MPTRACK_FFT_X86_DISPATCH
  // The schedule compiled for wider vectors (no FMA; see Fft<N>).
  __attribute__((target("avx2"), noinline)) void forward_avx2() { forward_schedule(); }
  __attribute__((target("avx512f,avx512vl,prefer-vector-width=512"), noinline)) void
  forward_avx512() {
    forward_schedule();
  }
#endif

  // __restrict parameters: GCC then emits vector stores (with the rows as
  // plain pointers it left the loop scalar).
  static void zero_run(float* __restrict re, float* __restrict im) {
    for (std::size_t l = 0; l < L; ++l) {
      re[l] = 0.0f;
      im[l] = 0.0f;
    }
  }

  float* r(std::size_t k) { return re_[k].data(); }
  float* m(std::size_t k) { return im_[k].data(); }

  MPTRACK_FFT_INLINE void forward_schedule() {
    std::size_t h = 0;
    if constexpr (kLog2 % 2 == 1) {  // half-size 1 (twiddle 1)
      for (std::size_t a = 0; a < N; a += 2) {
        fft_detail::radix2_run<L>(r(a), m(a), r(a + 1), m(a + 1));
      }
      h = 2;
    } else {  // half-sizes 1 and 2 (twiddles 1, -j)
      for (std::size_t a = 0; a < N; a += 4) {
        fft_detail::radix4_first_run<L>(r(a), m(a), r(a + 1), m(a + 1), r(a + 2), m(a + 2),
                                        r(a + 3), m(a + 3));
      }
      h = 4;
    }
    // Half-sizes h and 2h fused, twiddles W_{2h}^j and W_{4h}^j, one pair
    // per row group (the same for every lane).
    for (; h < N; h *= 4) {
      for (std::size_t base = 0; base < N; base += 4 * h) {
        for (std::size_t j = 0; j < h; ++j) {
          const std::size_t k = base + j;
          fft_detail::radix4_run<L, float>(
              r(k), m(k), r(k + h), m(k + h), r(k + 2 * h), m(k + 2 * h), r(k + 3 * h),
              m(k + 3 * h), fft_.twiddle_re(h, j), fft_.twiddle_im(h, j),
              fft_.twiddle_re(2 * h, j), fft_.twiddle_im(2 * h, j));
        }
      }
    }
  }

  Fft<N> fft_{};  // twiddle table only
  alignas(64) std::array<Row, N> re_{};
  alignas(64) std::array<Row, N> im_{};
};

}  // namespace mptrack::dsp
