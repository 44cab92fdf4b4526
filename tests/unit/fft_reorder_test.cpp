// The optimised Fft (input-order first stages, compile-time passes,
// constexpr swap table; bench/README.md) against the straightforward
// schedule it replaced: bit-reversal first, then every radix-2^2 pass in
// natural order with run-time half-sizes. Both perform the same operations
// on the same operands, so the outputs must be the same bits: compared
// with memcmp, at every power of two 2..4096 (the golden files cover only
// the front-end sizes), on inputs that include zeros, signed zeros,
// subnormals and large values.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "mptrack/dsp/fft.h"
#include "fft_test_values.h"

namespace {

// Reference schedule, written from the algorithm's definition (DIT radix-2^2
// after a bit-reversal permutation), using the object's own twiddles.
template <std::size_t N>
void reference_forward(const mptrack::dsp::Fft<N>& fft, float* re, float* im) {
  constexpr std::size_t kLog2 = mptrack::dsp::log2_exact(N);
  for (std::size_t i = 0; i < N; ++i) {
    std::size_t r = 0;
    for (std::size_t b = 0; b < kLog2; ++b) {
      if ((i >> b) & 1u) r |= std::size_t{1} << (kLog2 - 1 - b);
    }
    if (r > i) {
      const float tr = re[i];
      const float ti = im[i];
      re[i] = re[r];
      im[i] = im[r];
      re[r] = tr;
      im[r] = ti;
    }
  }
  std::size_t h = 1;
  if (kLog2 % 2 == 1) {
    for (std::size_t a = 0; a < N; a += 2) {
      const float tr = re[a + 1];
      const float ti = im[a + 1];
      re[a + 1] = re[a] - tr;
      im[a + 1] = im[a] - ti;
      re[a] = re[a] + tr;
      im[a] = im[a] + ti;
    }
    h = 2;
  } else {
    for (std::size_t a = 0; a < N; a += 4) {
      const float b0r = re[a] + re[a + 1];
      const float b0i = im[a] + im[a + 1];
      const float b1r = re[a] - re[a + 1];
      const float b1i = im[a] - im[a + 1];
      const float b2r = re[a + 2] + re[a + 3];
      const float b2i = im[a + 2] + im[a + 3];
      const float b3r = re[a + 2] - re[a + 3];
      const float b3i = im[a + 2] - im[a + 3];
      re[a] = b0r + b2r;
      im[a] = b0i + b2i;
      re[a + 2] = b0r - b2r;
      im[a + 2] = b0i - b2i;
      re[a + 1] = b1r + b3i;
      im[a + 1] = b1i - b3r;
      re[a + 3] = b1r - b3i;
      im[a + 3] = b1i + b3r;
    }
    h = 4;
  }
  for (; h < N; h *= 4) {
    for (std::size_t base = 0; base < N; base += 4 * h) {
      for (std::size_t j = 0; j < h; ++j) {
        const float w1r = fft.twiddle_re(h, j);
        const float w1i = fft.twiddle_im(h, j);
        const float w2r = fft.twiddle_re(2 * h, j);
        const float w2i = fft.twiddle_im(2 * h, j);
        float* r = re + base + j;
        float* m = im + base + j;
        const float t1r = w1r * r[h] - w1i * m[h];
        const float t1i = w1r * m[h] + w1i * r[h];
        const float t3r = w1r * r[3 * h] - w1i * m[3 * h];
        const float t3i = w1r * m[3 * h] + w1i * r[3 * h];
        const float b0r = r[0] + t1r;
        const float b0i = m[0] + t1i;
        const float b1r = r[0] - t1r;
        const float b1i = m[0] - t1i;
        const float b2r = r[2 * h] + t3r;
        const float b2i = m[2 * h] + t3i;
        const float b3r = r[2 * h] - t3r;
        const float b3i = m[2 * h] - t3i;
        const float u2r = w2r * b2r - w2i * b2i;
        const float u2i = w2r * b2i + w2i * b2r;
        const float u3r = w2r * b3r - w2i * b3i;
        const float u3i = w2r * b3i + w2i * b3r;
        r[0] = b0r + u2r;
        m[0] = b0i + u2i;
        r[2 * h] = b0r - u2r;
        m[2 * h] = b0i - u2i;
        r[h] = b1r + u3i;
        m[h] = b1i - u3r;
        r[3 * h] = b1r - u3i;
        m[3 * h] = b1i + u3r;
      }
    }
  }
}

// Number of trials whose outputs (forward and inverse) differ in any bit.
template <std::size_t N>
int mismatches() {
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  std::vector<float> re(N), im(N), ref_re(N), ref_im(N);
  std::uint32_t x = 7u + static_cast<std::uint32_t>(N);
  int bad = 0;
  for (int trial = 0; trial < 8; ++trial) {
    for (std::size_t i = 0; i < N; ++i) {
      re[i] = mptrack::test::fft_test_value(x, (trial + static_cast<int>(i % 3 == 0)) % 4);
      im[i] = mptrack::test::fft_test_value(x, trial % 4);
    }
    ref_re = re;
    ref_im = im;
    fft->forward(re.data(), im.data());
    reference_forward(*fft, ref_re.data(), ref_im.data());
    if (std::memcmp(re.data(), ref_re.data(), N * sizeof(float)) != 0 ||
        std::memcmp(im.data(), ref_im.data(), N * sizeof(float)) != 0) {
      ++bad;
    }
    fft->inverse(re.data(), im.data());  // = forward with re/im swapped
    reference_forward(*fft, ref_im.data(), ref_re.data());
    if (std::memcmp(re.data(), ref_re.data(), N * sizeof(float)) != 0 ||
        std::memcmp(im.data(), ref_im.data(), N * sizeof(float)) != 0) {
      ++bad;
    }
  }
  return bad;
}

}  // namespace

TEST_CASE("fft: the optimised schedule gives the bits of the permute-first schedule, N = 2..4096") {
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
