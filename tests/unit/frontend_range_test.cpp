// Range matched filter (pulse compression) stage.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <memory>
#include <array>
#include <algorithm>
#include <cstring>
#include <limits>
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

TEST_CASE("range MF: a NaN profile is skipped, every other profile is compressed and tallied") {
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::SynthTarget t;
  t.range_m = range_of_delay(p, 12.0);
  mptrack::test::synthesize<Caps>(p, &t, 1, 1e-3, 4, *cube);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  std::vector<float> clean(Caps::kNumRangeBins);
  for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) clean[g] = rmf->value_re(0, 7, g);
  // Channel 5 = (Tx 1, Rx 2) holds the NaN; channel 7, read after it, must not be stale.
  cube->iq[fe::RadarCube<Caps>::offset(0, 1, 2, 40)] = std::nanf("");
  CHECK(rmf->process(*cube) == Status::kInvalidInput);
  CHECK(rmf->tally().nonfinite == 1);
  for (std::size_t g = 0; g < Caps::kNumRangeBins; ++g) CHECK(rmf->value_re(0, 7, g) == clean[g]);
}

TEST_CASE("range MF: the float tally counts zeros, samples beyond the ceiling and NaN/Inf") {
  fe::FrontEndParams p;
  p.max_abs_sample = 10.0;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  cube->iq.fill(0.5f);
  const std::size_t n = cube->iq.size();
  cube->iq[3] = 0.0f;
  cube->iq[n / 2] = -0.0f;  // -0 == 0
  cube->iq[n - 1] = 0.0f;
  cube->iq[10] = 11.0f;     // beyond the ceiling
  cube->iq[11] = -11.5f;    // beyond it, negative
  cube->iq[12] = 10.0f;     // at it: not beyond
  cube->iq[13] = -10.0f;
  cube->iq[700] = std::numeric_limits<float>::infinity();  // beyond, and not finite
  cube->iq[900] = std::nanf("");                           // not finite, not beyond
  CHECK(rmf->process(*cube) == Status::kInvalidInput);
  CHECK(rmf->tally().zero == 3);
  CHECK(rmf->tally().over_ceiling == 3);
  CHECK(rmf->tally().nonfinite == 2);
  CHECK(rmf->tally().full_scale == 0);
}

TEST_CASE("range MF: channel by channel, the tally covers the channels run since begin_frame") {
  // Caps: 9 channels of 256 complex samples, one chirp. Channel 2 holds 3 zero
  // values, channel 5 one NaN; begin_frame() clears what an earlier frame left.
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Caps>>();
  cube->iq.fill(0.25f);
  const std::size_t profile = 2 * Caps::kNumSamples;
  cube->iq[2 * profile + 7] = 0.0f;
  cube->iq[2 * profile + 8] = 0.0f;
  cube->iq[2 * profile + 9] = 0.0f;
  cube->iq[5 * profile + 1] = std::nanf("");
  CHECK(rmf->process(*cube) == Status::kInvalidInput);  // leaves a tally behind
  rmf->begin_frame();
  CHECK(rmf->tally().zero == 0);
  CHECK(rmf->process_channel(*cube, 2) == Status::kOk);
  CHECK(rmf->tally().zero == 3);
  CHECK(rmf->process_channel(*cube, 5) == Status::kInvalidInput);
  CHECK(rmf->tally().nonfinite == 1);
  CHECK(rmf->tally().zero == 3);
  CHECK(rmf->process_channel(*cube, 9) == Status::kInvalidArgument);  // 9 channels: 0..8
  CHECK(rmf->tally().zero == 3);
}

TEST_CASE("range MF: the int16 tally counts zeros and codes at either rail of the ADC") {
  fe::FrontEndParams p;
  p.adc_bits = 12;  // rails -32768 and 32768 - 16 = 32752
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Caps>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCubeInt16<Caps>>();
  cube->iq.fill(100);
  const std::size_t n = cube->iq.size();
  cube->iq[0] = 0;
  cube->iq[n - 1] = 0;
  cube->iq[5] = -32768;
  cube->iq[6] = 32752;
  cube->iq[7] = 32767;
  cube->iq[8] = 32751;   // one code below the rail
  cube->iq[9] = -32767;  // one code above the negative rail
  CHECK(rmf->process(*cube) == Status::kOk);
  CHECK(rmf->tally().zero == 2);
  CHECK(rmf->tally().full_scale == 3);
  CHECK(rmf->tally().over_ceiling == 0);
  CHECK(rmf->tally().nonfinite == 0);
}

TEST_CASE("range MF: a frame (Doppler caps) equals its profiles compressed one by one") {
  // process() runs channel by channel, chirps inner, in the dispatch copy
  // this CPU has; process_profile() compresses one profile in the portable
  // code. Same bits expected at every (chirp, channel, bin).
  using Small = fe::SmallDopplerRadarCaps;
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto frame = std::make_unique<fe::RangeMatchedFilter<Small>>();
  auto single = std::make_unique<fe::RangeMatchedFilter<Small>>();
  REQUIRE(frame->init(p) == Status::kOk);
  REQUIRE(single->init(p) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Small>>();
  mptrack::test::SynthTarget t;
  t.range_m = 25.0;
  t.radial_mps = 6.0;
  mptrack::test::synthesize<Small>(p, &t, 1, 0.1, 5, *cube);
  REQUIRE(frame->process(*cube) == Status::kOk);
  constexpr std::size_t kV = Small::kNumTx * Small::kNumRx;
  std::vector<float> re(Small::kNumSamples);
  std::vector<float> im(Small::kNumSamples);
  std::size_t differing = 0;
  for (std::size_t c = 0; c < Small::kNumChirps; ++c) {
    for (std::size_t v = 0; v < kV; ++v) {
      const std::size_t o = fe::RadarCube<Small>::offset(c, v / Small::kNumRx, v % Small::kNumRx, 0);
      for (std::size_t i = 0; i < Small::kNumSamples; ++i) {
        re[i] = cube->iq[o + 2 * i];
        im[i] = cube->iq[o + 2 * i + 1];
      }
      REQUIRE(single->process_profile(re.data(), im.data(), c * kV + v) == Status::kOk);
      for (std::size_t g = 0; g < Small::kNumRangeBins; ++g) {
        const float a[2] = {frame->value_re(c, v, g), frame->value_im(c, v, g)};
        const float b[2] = {single->value_re(c, v, g), single->value_im(c, v, g)};
        if (std::memcmp(a, b, sizeof a) != 0) ++differing;
      }
    }
  }
  CHECK(differing == 0);
}

TEST_CASE("range MF: every dispatch copy gives the baseline copy's bits") {
  // Calibration, DC removal and a target in noise, float and int16 cubes:
  // every operation of the stage outside the FFT (which has its own test).
  using Small = fe::SmallDopplerRadarCaps;
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.remove_dc = true;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Small>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  constexpr std::size_t kV = Small::kNumTx * Small::kNumRx;
  std::array<float, kV> cr{};
  std::array<float, kV> ci{};
  for (std::size_t v = 0; v < kV; ++v) {
    cr[v] = 0.8f + 0.05f * static_cast<float>(v);
    ci[v] = -0.3f + 0.07f * static_cast<float>(v);
  }
  REQUIRE(rmf->set_channel_calibration(cr, ci) == Status::kOk);
  auto cube = std::make_unique<fe::RadarCube<Small>>();
  auto cube16 = std::make_unique<fe::RadarCubeInt16<Small>>();
  mptrack::test::SynthTarget t;
  t.range_m = 40.0;
  t.amplitude = 0.2;
  mptrack::test::synthesize<Small>(p, &t, 1, 0.05, 9, *cube);
  for (std::size_t i = 0; i < cube->iq.size(); ++i) {
    cube16->iq[i] = static_cast<std::int16_t>(std::lround(static_cast<double>(cube->iq[i]) * 32768.0));
  }
  const auto outputs = [&](std::vector<float>& out) {
    out.clear();
    for (std::size_t g = 0; g < Small::kNumRangeBins; ++g) {
      for (std::size_t c = 0; c < Small::kNumChirps; ++c) {
        for (std::size_t v = 0; v < kV; ++v) {
          out.push_back(rmf->value_re(c, v, g));
          out.push_back(rmf->value_im(c, v, g));
        }
      }
    }
  };
  std::vector<float> base;
  std::vector<float> base16;
  REQUIRE(rmf->process_copy(mptrack::dsp::FftCopy::kBaseline, *cube) == Status::kOk);
  outputs(base);
  REQUIRE(rmf->process_copy(mptrack::dsp::FftCopy::kBaseline, *cube16) == Status::kOk);
  outputs(base16);
  for (const auto copy : {mptrack::dsp::FftCopy::kAvx2, mptrack::dsp::FftCopy::kAvx512}) {
    if (!mptrack::dsp::fft_copy_available(copy)) continue;
    CAPTURE(mptrack::dsp::fft_copy_name(copy));
    std::vector<float> got;
    REQUIRE(rmf->process_copy(copy, *cube) == Status::kOk);
    outputs(got);
    CHECK(std::memcmp(got.data(), base.data(), base.size() * sizeof(float)) == 0);
    REQUIRE(rmf->process_copy(copy, *cube16) == Status::kOk);
    outputs(got);
    CHECK(std::memcmp(got.data(), base16.data(), base16.size() * sizeof(float)) == 0);
  }
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
