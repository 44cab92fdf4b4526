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
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mptrack/dsp/fft.h"

namespace {

float test_value(std::uint32_t& x, int kind) {
  x = x * 1664525u + 1013904223u;
  const float u = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
  switch (kind % 6) {
    case 0: return u;
    case 1: return u * 1e-39f;                                  // subnormal range
    case 2: return (x & 0x100u) != 0u ? -0.0f : 0.0f;           // signed zeros
    case 3: return u * 1e30f;                                   // large (overflows to inf)
    case 4: return (x & 0x7000u) == 0u ? std::numeric_limits<float>::infinity() : u;
    default: return (x & 0x7000u) == 0u ? std::numeric_limits<float>::quiet_NaN() : u;
  }
}

// Bit-identical, or both NaN.
bool same(const std::vector<float>& a, const std::vector<float>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != a[i] && b[i] != b[i]) continue;
    if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0) return false;
  }
  return true;
}

// Trials whose forward() and forward_portable() outputs differ in any bit.
template <std::size_t N>
int mismatches() {
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  std::vector<float> re(N), im(N), pre(N), pim(N);
  std::uint32_t x = 11u + static_cast<std::uint32_t>(N);
  int bad = 0;
  for (int trial = 0; trial < 12; ++trial) {
    for (std::size_t i = 0; i < N; ++i) {
      re[i] = test_value(x, trial + static_cast<int>(i % 5 == 0));
      im[i] = test_value(x, trial);
    }
    pre = re;
    pim = im;
    fft->forward(re.data(), im.data());
    fft->forward_portable(pre.data(), pim.data());
    if (!same(re, pre) || !same(im, pim)) {
      ++bad;
    }
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
  CHECK(std::string(mptrack::dsp::Fft<32>::dispatch_name()) == "baseline");
  CHECK(std::string(mptrack::dsp::Fft<16>::dispatch_name()) == "baseline");
}

#if MPTRACK_FFT_X86_DISPATCH
TEST_CASE("fft dispatch: on an AVX2 host, N >= 64 runs a wide copy (the test above compares it)") {
  if (__builtin_cpu_supports("avx2")) {
    CHECK(std::string(mptrack::dsp::Fft<64>::dispatch_name()) != "baseline");
    CHECK(std::string(mptrack::dsp::Fft<256>::dispatch_name()) != "baseline");
  } else {
    CHECK(std::string(mptrack::dsp::Fft<256>::dispatch_name()) == "baseline");
  }
}
#endif
