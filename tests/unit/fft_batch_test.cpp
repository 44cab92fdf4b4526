// FftBatch<N, L> (core/include/mptrack/dsp/fft_batch.h): L transforms at
// once, lane as the innermost index. Each lane must give the bits of
// Fft<N>::forward() on the same input (the angle stage's goldens rely on
// it), for every copy of the schedule this build and CPU hold; and the
// input rows must be the bit-reversal permutation (an impulse at n in one
// lane gives exp(-j 2 pi k n / N) in that lane and zeros elsewhere).
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "fft_test_values.h"
#include "mptrack/dsp/fft_batch.h"
#include "mptrack/math/constants.h"
#include "mptrack/math/detmath.h"

namespace {

using mptrack::dsp::FftCopy;

// Lanes (over 6 trials) whose output differs in any bit (NaN: any payload)
// from Fft<N>::forward() of the same input, after FftBatch's copy `copy`;
// -1 when this CPU lacks the copy.
template <std::size_t N, std::size_t L>
int lane_mismatches(FftCopy copy) {
  auto batch = std::make_unique<mptrack::dsp::FftBatch<N, L>>();
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(batch->init() == mptrack::Status::kOk);
  REQUIRE(fft->init() == mptrack::Status::kOk);
  std::vector<float> re(N * L), im(N * L);  // lane l at [l N, (l + 1) N)
  std::uint32_t x = 3u + static_cast<std::uint32_t>(N * 7 + L);
  int bad = 0;
  for (int trial = 0; trial < 6; ++trial) {
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t n = 0; n < N; ++n) {
        const int kind = trial + static_cast<int>((n + l) % 4 == 0);
        re[l * N + n] = mptrack::test::fft_test_value(x, kind);
        im[l * N + n] = mptrack::test::fft_test_value(x, trial);
        batch->input_re(n)[l] = re[l * N + n];
        batch->input_im(n)[l] = im[l * N + n];
      }
      fft->forward(&re[l * N], &im[l * N]);
    }
    if (!batch->forward_copy(copy)) return -1;
    for (std::size_t l = 0; l < L; ++l) {
      bool lane_ok = true;
      for (std::size_t k = 0; k < N; ++k) {
        lane_ok = lane_ok && mptrack::test::same_bits_or_nan(batch->output_re(k)[l], re[l * N + k]) &&
                  mptrack::test::same_bits_or_nan(batch->output_im(k)[l], im[l * N + k]);
      }
      if (!lane_ok) ++bad;
    }
  }
  return bad;
}

// Sizes 2..1024 with 16 lanes (one 64-byte row: the angle stage's block)
// and with 3 lanes (a run shorter than any vector).
int copy_mismatches(FftCopy c) {
  const int results[] = {
      lane_mismatches<2, 16>(c),   lane_mismatches<4, 16>(c),   lane_mismatches<8, 16>(c),
      lane_mismatches<16, 16>(c),  lane_mismatches<32, 16>(c),  lane_mismatches<64, 16>(c),
      lane_mismatches<128, 16>(c), lane_mismatches<256, 16>(c), lane_mismatches<1024, 16>(c),
      lane_mismatches<32, 3>(c),   lane_mismatches<64, 3>(c)};
  int bad = 0;
  for (const int r : results) {
    if (r < 0) return -1;
    bad += r;
  }
  return bad;
}

}  // namespace

TEST_CASE("fft batch: every lane gives the bits of Fft::forward, baseline copy") {
  CHECK(copy_mismatches(FftCopy::kBaseline) == 0);
}

TEST_CASE("fft batch: every lane gives the bits of Fft::forward, AVX2 copy (where the CPU has it)") {
  const int bad = copy_mismatches(FftCopy::kAvx2);
  CHECK(bad == (mptrack::dsp::fft_copy_available(FftCopy::kAvx2) ? 0 : -1));
}

TEST_CASE("fft batch: every lane gives the bits of Fft::forward, AVX-512 copy (where the CPU has it)") {
  const int bad = copy_mismatches(FftCopy::kAvx512);
  CHECK(bad == (mptrack::dsp::fft_copy_available(FftCopy::kAvx512) ? 0 : -1));
}

TEST_CASE("fft batch: an impulse at n in one lane gives exp(-j 2 pi k n / N) there, zeros elsewhere") {
  constexpr std::size_t kN = 32;
  constexpr std::size_t kL = 5;
  constexpr std::size_t kLane = 3;
  constexpr std::size_t kAt = 5;
  auto batch = std::make_unique<mptrack::dsp::FftBatch<kN, kL>>();
  REQUIRE(batch->init() == mptrack::Status::kOk);
  for (std::size_t n = 0; n < kN; ++n) {
    for (std::size_t l = 0; l < kL; ++l) {
      batch->input_re(n)[l] = (l == kLane && n == kAt) ? 1.0f : 0.0f;
      batch->input_im(n)[l] = 0.0f;
    }
  }
  batch->forward();
  for (std::size_t k = 0; k < kN; ++k) {
    // core's own sine and cosine (no libm: qemu-ppc cannot run glibc's).
    const double a = -mptrack::dmath::kTwoPi<double> * static_cast<double>(k * kAt) /
                     static_cast<double>(kN);
    double s = 0.0;
    double c = 1.0;
    mptrack::dmath::dsincos(a, s, c);
    CHECK(std::fabs(static_cast<double>(batch->output_re(k)[kLane]) - c) <= 1e-6);
    CHECK(std::fabs(static_cast<double>(batch->output_im(k)[kLane]) - s) <= 1e-6);
    for (std::size_t l = 0; l < kL; ++l) {
      if (l == kLane) continue;
      CHECK(batch->output_re(k)[l] == 0.0f);
      CHECK(batch->output_im(k)[l] == 0.0f);
    }
  }
}

TEST_CASE("fft batch: forward does not allocate") {
  auto batch = std::make_unique<mptrack::dsp::FftBatch<64, 16>>();
  REQUIRE(batch->init() == mptrack::Status::kOk);
  mptrack::test::NoAllocScope guard;
  batch->forward();
  CHECK(guard.allocations() == 0);
}
