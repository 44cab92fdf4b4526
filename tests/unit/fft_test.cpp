// Unit tests of mptrack::dsp::Fft against a naive DFT evaluated in double.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/dsp/fft.h"

namespace {

struct Signal {
  std::vector<float> re;
  std::vector<float> im;
};

Signal test_signal(std::size_t n, unsigned seed) {
  Signal s;
  s.re.resize(n);
  s.im.resize(n);
  unsigned x = seed;
  for (std::size_t i = 0; i < n; ++i) {
    x = x * 1664525u + 1013904223u;
    s.re[i] = static_cast<float>(static_cast<int>(x >> 8) % 2001 - 1000) / 1000.0f;
    x = x * 1664525u + 1013904223u;
    s.im[i] = static_cast<float>(static_cast<int>(x >> 8) % 2001 - 1000) / 1000.0f;
  }
  return s;
}

// Naive DFT in double; sign -1 forward, +1 inverse (unscaled).
void naive_dft(const Signal& in, int sign, std::vector<double>& out_re, std::vector<double>& out_im) {
  const std::size_t n = in.re.size();
  out_re.assign(n, 0.0);
  out_im.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t t = 0; t < n; ++t) {
      const double a = sign * 2.0 * M_PI * static_cast<double>((k * t) % n) / static_cast<double>(n);
      const double c = std::cos(a);
      const double s = std::sin(a);
      const double xr = static_cast<double>(in.re[t]);
      const double xi = static_cast<double>(in.im[t]);
      out_re[k] += xr * c - xi * s;
      out_im[k] += xr * s + xi * c;
    }
  }
}

// Max abs error relative to the RMS of the exact output.
template <std::size_t N>
double fft_error(bool inverse, unsigned seed) {
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  Signal s = test_signal(N, seed);
  std::vector<double> er;
  std::vector<double> ei;
  naive_dft(s, inverse ? +1 : -1, er, ei);
  if (inverse) {
    fft->inverse(s.re.data(), s.im.data());
  } else {
    fft->forward(s.re.data(), s.im.data());
  }
  double max_err = 0.0;
  double energy = 0.0;
  for (std::size_t k = 0; k < N; ++k) {
    max_err = std::max(max_err, std::hypot(static_cast<double>(s.re[k]) - er[k], static_cast<double>(s.im[k]) - ei[k]));
    energy += er[k] * er[k] + ei[k] * ei[k];
  }
  return max_err / std::sqrt(energy / static_cast<double>(N));
}

}  // namespace

TEST_CASE("fft forward matches a naive DFT for every size 2..1024") {
  // Error bound for radix-2 float FFT ~ c * log2(N) * eps; eps = 6e-8.
  CHECK(fft_error<2>(false, 1) < 1e-7);
  CHECK(fft_error<4>(false, 2) < 2e-7);
  CHECK(fft_error<8>(false, 3) < 3e-7);
  CHECK(fft_error<16>(false, 4) < 4e-7);
  CHECK(fft_error<32>(false, 5) < 5e-7);
  CHECK(fft_error<64>(false, 6) < 6e-7);
  CHECK(fft_error<128>(false, 7) < 7e-7);
  CHECK(fft_error<256>(false, 8) < 8e-7);
  CHECK(fft_error<512>(false, 9) < 9e-7);
  CHECK(fft_error<1024>(false, 10) < 1e-6);
}

TEST_CASE("fft inverse matches a naive inverse DFT (unscaled)") {
  CHECK(fft_error<8>(true, 11) < 3e-7);
  CHECK(fft_error<64>(true, 12) < 6e-7);
  CHECK(fft_error<256>(true, 13) < 8e-7);
}

TEST_CASE("fft of a unit impulse is all ones, exactly") {
  mptrack::dsp::Fft<64> fft;
  REQUIRE(fft.init() == mptrack::Status::kOk);
  std::vector<float> re(64, 0.0f);
  std::vector<float> im(64, 0.0f);
  re[0] = 1.0f;
  fft.forward(re.data(), im.data());
  for (std::size_t k = 0; k < 64; ++k) {
    CHECK(re[k] == 1.0f);
    CHECK(im[k] == 0.0f);
  }
}

TEST_CASE("fft of a bin-centred complex tone puts N*A in exactly one bin") {
  constexpr std::size_t kN = 128;
  mptrack::dsp::Fft<kN> fft;
  REQUIRE(fft.init() == mptrack::Status::kOk);
  std::vector<float> re(kN);
  std::vector<float> im(kN);
  const std::size_t bin = 37;
  for (std::size_t t = 0; t < kN; ++t) {
    const double a = 2.0 * M_PI * static_cast<double>((bin * t) % kN) / kN;
    re[t] = static_cast<float>(0.5 * std::cos(a));
    im[t] = static_cast<float>(0.5 * std::sin(a));
  }
  fft.forward(re.data(), im.data());
  for (std::size_t k = 0; k < kN; ++k) {
    const double mag = std::hypot(static_cast<double>(re[k]), static_cast<double>(im[k]));
    if (k == bin) {
      CHECK(mag == doctest::Approx(0.5 * kN).epsilon(1e-6));
    } else {
      CHECK(mag < 1e-4);
    }
  }
}

TEST_CASE("fft round trip: inverse(forward(x)) == N x within float rounding") {
  constexpr std::size_t kN = 512;
  mptrack::dsp::Fft<kN> fft;
  REQUIRE(fft.init() == mptrack::Status::kOk);
  Signal s = test_signal(kN, 99);
  Signal t = s;
  fft.forward(t.re.data(), t.im.data());
  fft.inverse(t.re.data(), t.im.data());
  for (std::size_t i = 0; i < kN; ++i) {
    CHECK(std::fabs(t.im[i] / kN - s.im[i]) < 2e-6f);
    CHECK(std::fabs(t.re[i] / kN - s.re[i]) < 2e-6f);
  }
}

TEST_CASE("fft twiddles: exact at 0 and -pi/2, and within 1 ulp of the exact value elsewhere") {
  mptrack::dsp::Fft<256> fft;
  REQUIRE(fft.init() == mptrack::Status::kOk);
  CHECK(fft.twiddle_re(128, 0) == 1.0f);
  CHECK(fft.twiddle_im(128, 0) == 0.0f);
  CHECK(fft.twiddle_re(128, 64) == 0.0f);
  CHECK(fft.twiddle_im(128, 64) == -1.0f);
  for (std::size_t j = 0; j < 128; ++j) {
    const double a = -2.0 * M_PI * static_cast<double>(j) / 256.0;
    CHECK(std::fabs(static_cast<double>(fft.twiddle_re(128, j)) - std::cos(a)) <= 6e-8);
    CHECK(std::fabs(static_cast<double>(fft.twiddle_im(128, j)) - std::sin(a)) <= 6e-8);
  }
}

TEST_CASE("fft forward and inverse do not allocate") {
  auto fft = std::make_unique<mptrack::dsp::Fft<1024>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  Signal s = test_signal(1024, 5);
  mptrack::test::NoAllocScope guard;
  fft->forward(s.re.data(), s.im.data());
  fft->inverse(s.re.data(), s.im.data());
  CHECK(guard.allocations() == 0);
}
