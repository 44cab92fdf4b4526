// Range matched filter (pulse compression) stage.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <memory>
#include <array>
#include <algorithm>
#include <vector>

#include "alloc_guard.h"
#include "frontend_test_signals.h"
#include "mptrack/frontend/range_matched_filter.h"

namespace fe = mptrack::frontend;
using Caps = fe::Seed004RadarCaps;
using mptrack::Status;

namespace {

double dbl(float x) { return static_cast<double>(x); }

// Delay in samples -> range [m] for the synthesizer.
double range_of_delay(const fe::FrontEndParams& p, double samples) {
  return samples * fe::range_bin_m(p);
}

}  // namespace

TEST_CASE("range MF: the chirp has round(T f_s) = 115 samples at the seed 004 defaults") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  CHECK(rmf->chirp_len() == 115);  // 3.6 us * 32 MHz = 115.2
  CHECK(rmf->coherent_gain() == 115.0f);
  CHECK(rmf->noise_gain() == 115.0f);
  CHECK(fe::range_bin_m(p) == doctest::Approx(4.6842571));  // c / (2 * 32 MHz)
}

TEST_CASE("range MF: an echo delayed by 13 samples peaks at bin 13 with amplitude A*L") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::SynthTarget t;
  t.range_m = range_of_delay(p, 13.0);
  t.amplitude = 0.25;
  mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, *cube);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  for (std::size_t v = 0; v < 9; ++v) {
    std::size_t best = 0;
    double best_mag = 0.0;
    for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) {
      const double mag = std::hypot(dbl(rmf->value_re(0, v, g)), dbl(rmf->value_im(0, v, g)));
      if (mag > best_mag) {
        best_mag = mag;
        best = g;
      }
    }
    CHECK(best == 13);
    CHECK(best_mag == doctest::Approx(0.25 * 115.0).epsilon(1e-5));
  }
}

TEST_CASE("range MF: the profile equals the naive correlation with the reference chirp") {
  fe::FrontEndParams p;
  p.range_window = fe::WindowType::kHamming;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::SynthTarget t[2];
  t[0].range_m = range_of_delay(p, 7.3);
  t[0].amplitude = 0.1;
  t[1].range_m = range_of_delay(p, 30.0);
  t[1].amplitude = 0.05;
  t[1].bearing_rad = 0.3;
  mptrack::test::synthesize<Caps>(p, t, 2, 1e-3, 7, *cube);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  const std::size_t len = fe::chirp_samples(p);
  double max_err = 0.0;
  double max_mag = 0.0;
  for (std::size_t v = 0; v < 9; ++v) {
    for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) {
      std::complex<double> acc(0.0, 0.0);
      for (std::size_t i = 0; i < len && i + g < Caps::kNumSamples; ++i) {
        const std::size_t o = fe::RadarCube<Caps>::offset(0, v / 3, v % 3, i + g);
        double ur = 0.0;
        double ui = 0.0;
        mptrack::test::chirp_sample(p, static_cast<double>(i), ur, ui);
        const double w = 0.54 - 0.46 * std::cos(2.0 * M_PI * static_cast<double>(i) /
                                                static_cast<double>(len - 1));
        acc += std::complex<double>(dbl(cube->iq[o]), dbl(cube->iq[o + 1])) *
               std::conj(std::complex<double>(w * ur, w * ui));
      }
      const std::complex<double> got(dbl(rmf->value_re(0, v, g)), dbl(rmf->value_im(0, v, g)));
      max_err = std::max(max_err, std::abs(got - acc));
      max_mag = std::max(max_mag, std::abs(acc));
    }
  }
  CHECK(max_mag > 5.0);
  CHECK(max_err / max_mag < 2e-6);
}

TEST_CASE("range MF: processing gain on white noise is (sum w)^2 / sum w^2 (rect: L, Hann)") {
  for (fe::WindowType wt : {fe::WindowType::kRectangular, fe::WindowType::kHann}) {
    fe::FrontEndParams p;
    p.range_window = wt;
    auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
    REQUIRE(rmf->init(p) == Status::kOk);
    auto cube = std::make_unique<fe::RadarCube<Caps>>();
    const double noise_var = 0.01;
    double out_var = 0.0;
    std::size_t n = 0;
    for (std::uint64_t frame = 0; frame < 20; ++frame) {
      mptrack::test::synthesize<Caps>(p, nullptr, 0, noise_var, 100 + frame, *cube);
      REQUIRE(rmf->process(*cube) == Status::kOk);
      for (std::size_t v = 0; v < 9; ++v) {
        for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) {
          const double re = dbl(rmf->value_re(0, v, g));
          const double im = dbl(rmf->value_im(0, v, g));
          out_var += re * re + im * im;
          ++n;
        }
      }
    }
    out_var /= static_cast<double>(n);
    const double sw = dbl(rmf->coherent_gain());
    const double sw2 = dbl(rmf->noise_gain());
    // Output noise variance = sigma^2 sum w^2; signal peak = A sum w.
    CHECK(out_var / noise_var == doctest::Approx(sw2).epsilon(0.05));
    const double gain = sw * sw / (out_var / noise_var);
    if (wt == fe::WindowType::kRectangular) {
      CHECK(gain == doctest::Approx(115.0).epsilon(0.05));  // 20.6 dB
    } else {
      // Hann: (sum w)^2 / sum w^2 = (L-1)^2/4 / (3(L-1)/8) = 2(L-1)/3 = 76 for L = 115.
      CHECK(sw * sw / sw2 == doctest::Approx(76.0).epsilon(1e-3));
      CHECK(gain == doctest::Approx(76.0).epsilon(0.05));
    }
  }
}

TEST_CASE("range MF: an int16 cube gives the same profile as the float cube of code/32768") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cf = std::make_unique<fe::RadarCube<Caps>>();
  auto ci = std::make_unique<fe::RadarCubeInt16<Caps>>();
  mptrack::test::SynthTarget t;
  t.range_m = range_of_delay(p, 20.0);
  t.amplitude = 0.3;
  mptrack::test::synthesize<Caps>(p, &t, 1, 1e-4, 3, *cf);
  for (std::size_t i = 0; i < cf->iq.size(); ++i) {
    const long code = std::lround(static_cast<double>(cf->iq[i]) * 32768.0);
    ci->iq[i] = static_cast<std::int16_t>(code);
    cf->iq[i] = static_cast<float>(code) / 32768.0f;
  }
  REQUIRE(rmf->process(*ci) == Status::kOk);
  std::vector<float> a(Caps::kNumRangeBins);
  for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) a[g] = rmf->value_re(0, 4, g);
  REQUIRE(rmf->process(*cf) == Status::kOk);
  for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) CHECK(a[g] == rmf->value_re(0, 4, g));
}

TEST_CASE("range MF: channel calibration multiplies each channel's profile by its complex gain") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::SynthTarget t;
  t.range_m = range_of_delay(p, 10.0);
  mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, *cube);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  const float r0 = rmf->value_re(0, 2, 10);
  const float i0 = rmf->value_im(0, 2, 10);
  const float r5 = rmf->value_re(0, 5, 10);
  std::array<float, 9> cr{};
  std::array<float, 9> ci{};
  cr.fill(1.0f);
  cr[2] = 0.0f;
  ci[2] = 2.0f;  // c_2 = 2j
  REQUIRE(rmf->set_channel_calibration(cr, ci) == Status::kOk);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  CHECK(rmf->value_re(0, 2, 10) == -2.0f * i0);
  CHECK(rmf->value_im(0, 2, 10) == 2.0f * r0);
  CHECK(rmf->value_re(0, 5, 10) == r5);  // c = 1 reproduces the bits
  ci[4] = std::nanf("");
  CHECK(rmf->set_channel_calibration(cr, ci) == Status::kInvalidArgument);
}

TEST_CASE("range MF: remove_dc cancels a constant offset on every sample") {
  fe::FrontEndParams p;
  p.remove_dc = true;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  for (std::size_t i = 0; i < cube->iq.size(); i += 2) {
    cube->iq[i] = 0.75f;   // DC leakage 0.75 - 0.5j
    cube->iq[i + 1] = -0.5f;
  }
  REQUIRE(rmf->process(*cube) == Status::kOk);
  double max_mag = 0.0;
  for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) {
    max_mag = std::max(max_mag, std::hypot(dbl(rmf->value_re(0, 0, g)), dbl(rmf->value_im(0, 0, g))));
  }
  CHECK(max_mag < 1e-5);
  p.remove_dc = false;
  REQUIRE(rmf->init(p) == Status::kOk);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  // Without removal the DC correlates with the chirp: |sum u| is far from 0.
  CHECK(std::hypot(dbl(rmf->value_re(0, 0, 0)), dbl(rmf->value_im(0, 0, 0))) > 1.0);
}

TEST_CASE("range MF: NaN input is rejected with kInvalidInput") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  cube->iq[fe::RadarCube<Caps>::offset(0, 2, 1, 17) + 1] = std::nanf("");
  CHECK(rmf->process(*cube) == Status::kInvalidInput);
}

TEST_CASE("range MF: init rejects a chirp that does not fit and non-positive waveform values") {
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  fe::FrontEndParams p;
  p.chirp_duration_s = 8e-6;  // 256 samples: 256 + 63 > 256
  CHECK(rmf->init(p) == Status::kInvalidArgument);
  p = fe::FrontEndParams{};
  p.bandwidth_hz = -1.0;
  CHECK(rmf->init(p) == Status::kInvalidArgument);
  p = fe::FrontEndParams{};
  p.sample_rate_hz = std::nan("");
  CHECK(rmf->init(p) == Status::kInvalidArgument);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  CHECK(rmf->process(*cube) == Status::kNotInitialized);
}

TEST_CASE("range MF: process does not allocate") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::synthesize<Caps>(p, nullptr, 0, 1.0, 5, *cube);
  mptrack::test::NoAllocScope guard;
  const Status s = rmf->process(*cube);
  CHECK(guard.allocations() == 0);
  CHECK(s == Status::kOk);
}
