// Fft::forward() on x86-64 hosts runs a copy of the schedule compiled for
// AVX-512 or AVX2 (fft.h, MPTRACK_FFT_X86_DISPATCH); forward_portable()
// runs the baseline (SSE2) copy. Wider vectors perform the same per-lane
// operations and neither copy may contract a*b+c into an FMA, so the two
// must agree bit for bit: compared with memcmp at every power of two
// 2..4096 on inputs with zeros, signed zeros, subnormals, large values,
// infinities and NaNs. NaN payloads are not compared (any NaN equals any
// NaN): which operand's payload an x86 operation returns depends on operand
// order, which the compiler may commute in + and *, even within one copy;
// no golden vector holds a NaN. Every other value is compared bit for bit.
// On targets without dispatch (aarch64, armhf) both
// calls run the same code and the test checks the plumbing only.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/dsp/fft.h"
#include "fft_test_values.h"

namespace {

// Bit-identical, or both NaN, element by element.
bool same(const std::vector<float>& a, const std::vector<float>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!mptrack::test::same_bits_or_nan(a[i], b[i])) return false;
  }
  return true;
}

// Trials whose outputs differ in any bit between forward_portable() and
// the copy `copy` (forward(), the copy this CPU dispatches to, when
// copy_arg is false; else Fft::forward_copy(copy)). -1: copy not on this CPU.
template <std::size_t N>
int mismatches(bool copy_arg = false, mptrack::dsp::FftCopy copy = mptrack::dsp::FftCopy::kBaseline) {
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  std::vector<float> re(N), im(N), pre(N), pim(N);
  std::uint32_t x = 11u + static_cast<std::uint32_t>(N);
  int bad = 0;
  for (int trial = 0; trial < 12; ++trial) {
    for (std::size_t i = 0; i < N; ++i) {
      re[i] = mptrack::test::fft_test_value(x, trial + static_cast<int>(i % 5 == 0));
      im[i] = mptrack::test::fft_test_value(x, trial);
    }
    pre = re;
    pim = im;
    if (copy_arg) {
      if (!fft->forward_copy(copy, re.data(), im.data())) return -1;
    } else {
      fft->forward(re.data(), im.data());
    }
    fft->forward_portable(pre.data(), pim.data());
    if (!same(re, pre) || !same(im, pim)) {
      ++bad;
    }
  }
  return bad;
}

// Every size 2..4096 through one named copy; mismatching sizes, or -1 when
// this CPU lacks the copy.
int copy_mismatches(mptrack::dsp::FftCopy c) {
  const int results[] = {mismatches<2>(true, c),    mismatches<4>(true, c),
                         mismatches<8>(true, c),    mismatches<16>(true, c),
                         mismatches<32>(true, c),   mismatches<64>(true, c),
                         mismatches<128>(true, c),  mismatches<256>(true, c),
                         mismatches<512>(true, c),  mismatches<1024>(true, c),
                         mismatches<2048>(true, c), mismatches<4096>(true, c)};
  int bad = 0;
  for (const int r : results) {
    if (r < 0) return -1;
    if (r > 0) ++bad;
  }
  return bad;
}

}  // namespace

TEST_CASE("fft dispatch: the AVX copies give the bits of the baseline copy, N = 2..4096") {
  MESSAGE("forward() runs the " << std::string(mptrack::dsp::Fft<256>::dispatch_name()) << " copy for N = 256");
  CHECK(mismatches<2>() == 0);
  CHECK(mismatches<4>() == 0);
  CHECK(mismatches<8>() == 0);
  CHECK(mismatches<16>() == 0);
  CHECK(mismatches<32>() == 0);
  CHECK(mismatches<64>() == 0);
  CHECK(mismatches<128>() == 0);
  CHECK(mismatches<256>() == 0);
  CHECK(mismatches<512>() == 0);
  CHECK(mismatches<1024>() == 0);
  CHECK(mismatches<2048>() == 0);
  CHECK(mismatches<4096>() == 0);
}

TEST_CASE("fft dispatch: sizes below kMinDispatchSize always run the baseline copy") {
  static_assert(mptrack::dsp::Fft<32>::kMinDispatchSize == 32, "the test names the boundary");
  CHECK(std::string(mptrack::dsp::Fft<16>::dispatch_name()) == "baseline");
  CHECK(std::string(mptrack::dsp::Fft<8>::dispatch_name()) == "baseline");
}

// The AVX2 copy has its own register schedules (N = 64 in 8-float rows, 8 x 8
// blocks from N = 128) that forward() never runs on an AVX-512 host, and the
// AVX-512 copy others (N = 64 and 128 in 16-float registers): each copy is
// run by name here, at every size, against the baseline copy.
TEST_CASE("fft dispatch: the baseline copy run by name is forward_portable()") {
  CHECK(copy_mismatches(mptrack::dsp::FftCopy::kBaseline) == 0);
}

#if MPTRACK_FFT_X86_DISPATCH
TEST_CASE("fft dispatch: the AVX2 copy run by name gives the baseline bits, N = 2..4096") {
  const int bad = copy_mismatches(mptrack::dsp::FftCopy::kAvx2);
  if (__builtin_cpu_supports("avx2")) {
    CHECK(bad == 0);
  } else {
    CHECK(bad == -1);
  }
}

TEST_CASE("fft dispatch: the AVX-512 copy run by name gives the baseline bits, N = 2..4096") {
  const int bad = copy_mismatches(mptrack::dsp::FftCopy::kAvx512);
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
    CHECK(bad == 0);
  } else {
    CHECK(bad == -1);
  }
}
#endif

#if MPTRACK_FFT_X86_DISPATCH
TEST_CASE("fft dispatch: on an AVX2 host, N >= 32 runs a wide copy (the test above compares it)") {
  if (__builtin_cpu_supports("avx2")) {
    CHECK(std::string(mptrack::dsp::Fft<32>::dispatch_name()) != "baseline");
    CHECK(std::string(mptrack::dsp::Fft<64>::dispatch_name()) != "baseline");
    CHECK(std::string(mptrack::dsp::Fft<256>::dispatch_name()) != "baseline");
  } else {
    CHECK(std::string(mptrack::dsp::Fft<256>::dispatch_name()) == "baseline");
  }
}
#endif
