// Host-only cross-check of mptrack::dsp::Fft against FFTW (single precision).
// FFTW is linked here only, never in core.
#include <doctest/doctest.h>

#include <fftw3.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "mptrack/dsp/fft.h"

namespace {

// Relative max error of our FFT vs FFTW (FFTW_ESTIMATE, forward, unscaled).
template <std::size_t N>
double error_vs_fftw(unsigned seed) {
  auto fft = std::make_unique<mptrack::dsp::Fft<N>>();
  REQUIRE(fft->init() == mptrack::Status::kOk);
  std::vector<float> re(N);
  std::vector<float> im(N);
  fftwf_complex* buf = fftwf_alloc_complex(N);
  fftwf_plan plan = fftwf_plan_dft_1d(static_cast<int>(N), buf, buf, FFTW_FORWARD, FFTW_ESTIMATE);
  unsigned x = seed;
  for (std::size_t i = 0; i < N; ++i) {
    x = x * 1664525u + 1013904223u;
    re[i] = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
    x = x * 1664525u + 1013904223u;
    im[i] = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
    buf[i][0] = re[i];
    buf[i][1] = im[i];
  }
  fftwf_execute(plan);
  fft->forward(re.data(), im.data());
  double max_err = 0.0;
  double energy = 0.0;
  for (std::size_t k = 0; k < N; ++k) {
    const double dr = static_cast<double>(re[k]) - static_cast<double>(buf[k][0]);
    const double di = static_cast<double>(im[k]) - static_cast<double>(buf[k][1]);
    max_err = std::max(max_err, std::hypot(dr, di));
    energy += static_cast<double>(buf[k][0]) * static_cast<double>(buf[k][0]) +
              static_cast<double>(buf[k][1]) * static_cast<double>(buf[k][1]);
  }
  fftwf_destroy_plan(plan);
  fftwf_free(buf);
  return max_err / std::sqrt(energy / static_cast<double>(N));
}

}  // namespace

TEST_CASE("fft agrees with FFTW float to float rounding at the front-end sizes") {
  // Both are ~log2(N) eps accurate; their difference is bounded by the sum.
  CHECK(error_vs_fftw<16>(1) < 1e-6);
  CHECK(error_vs_fftw<32>(2) < 1e-6);
  CHECK(error_vs_fftw<64>(3) < 1e-6);
  CHECK(error_vs_fftw<128>(4) < 1.5e-6);
  CHECK(error_vs_fftw<256>(5) < 1.5e-6);
  CHECK(error_vs_fftw<1024>(6) < 2e-6);
  CHECK(error_vs_fftw<2048>(7) < 2e-6);
}
