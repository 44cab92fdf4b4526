// Doppler (slow-time FFT) stage.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <memory>

#include "alloc_guard.h"
#include "fft_test_values.h"
#include "frontend_test_signals.h"
#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/doppler_processor.h"
#include "mptrack/frontend/window.h"

namespace fe = mptrack::frontend;
using Caps = fe::SmallDopplerRadarCaps;
using mptrack::Status;

namespace {

struct Stages {
  fe::RangeMatchedFilter<Caps> rmf;
  fe::DopplerProcessor<Caps> dop;
  fe::RadarCube<Caps> cube;
};

double mag(const fe::DopplerProcessor<Caps>& d, std::size_t g, std::size_t dd, std::size_t v) {
  return std::hypot(static_cast<double>(d.snapshot_re(g, dd, v)),
                    static_cast<double>(d.snapshot_im(g, dd, v)));
}

}  // namespace

TEST_CASE("doppler: velocity per bin is -lambda / (2 N_c T_c), zero at index N_c/2") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->dop.init(p) == Status::kOk);
  const double lambda = 299792458.0 / 10e9;
  const double bin = lambda / (2.0 * 16.0 * 100e-6);  // 9.368 m/s
  CHECK(s->dop.velocity_mps(8.0) == 0.0);
  CHECK(s->dop.velocity_mps(5.0) == doctest::Approx(3.0 * bin));
  CHECK(s->dop.velocity_mps(10.5) == doctest::Approx(-2.5 * bin));
}

TEST_CASE("doppler: a receding target lands in the predicted bin with coherent gain N_c") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->rmf.init(p) == Status::kOk);
  REQUIRE(s->dop.init(p) == Status::kOk);
  const double bin = (299792458.0 / 10e9) / (2.0 * 16.0 * 100e-6);
  mptrack::test::SynthTarget t;
  t.range_m = 9.0 * fe::range_bin_m(p);
  t.radial_mps = 3.0 * bin;  // h = -3 -> d = 5
  t.amplitude = 0.5;
  mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, s->cube);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  REQUIRE(s->dop.process(s->rmf) == Status::kOk);
  for (std::size_t v = 0; v < 8; ++v) {
    CHECK(mag(s->dop, 9, 5, v) == doctest::Approx(0.5 * 32.0 * 16.0).epsilon(1e-5));
    for (std::size_t d = 0; d < 16; ++d) {
      if (d != 5) CHECK(mag(s->dop, 9, d, v) < 1e-3);
    }
  }
}

TEST_CASE("doppler: a Hann window keeps the peak bin and scales it by sum w") {
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.doppler_window = fe::WindowType::kHann;
  auto s = std::make_unique<Stages>();
  REQUIRE(s->rmf.init(p) == Status::kOk);
  REQUIRE(s->dop.init(p) == Status::kOk);
  const double bin = (299792458.0 / 10e9) / (2.0 * 16.0 * 100e-6);
  mptrack::test::SynthTarget t;
  t.range_m = 4.0 * fe::range_bin_m(p);
  t.radial_mps = -6.0 * bin;  // h = 6 -> d = 14
  mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, s->cube);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  REQUIRE(s->dop.process(s->rmf) == Status::kOk);
  // Symmetric Hann over 16 points: sum w = (N - 1) / 2 = 7.5.
  CHECK(static_cast<double>(s->dop.coherent_gain()) == doctest::Approx(7.5).epsilon(1e-6));
  CHECK(mag(s->dop, 4, 14, 0) == doctest::Approx(32.0 * 7.5).epsilon(1e-5));
  CHECK(mag(s->dop, 4, 13, 0) < mag(s->dop, 4, 14, 0));
}

namespace {

// 3 x 2 = 6 virtual channels, 28 range bins: one full block of 16 bins and
// a partial one of 12 lanes (doppler_processor.h).
struct SixChannelCaps {
  static constexpr std::size_t kNumTx = 3;
  static constexpr std::size_t kNumRx = 2;
  static constexpr std::size_t kNumSamples = 64;
  static constexpr std::size_t kRangeFftSize = 64;
  static constexpr std::size_t kNumRangeBins = 28;
  static constexpr std::size_t kNumChirps = 16;
  static constexpr std::size_t kNumAngleBins = 16;
  static constexpr std::size_t kMaxDetections = 16;
};

struct SixChannelStages {
  fe::RangeMatchedFilter<SixChannelCaps> rmf;
  fe::DopplerProcessor<SixChannelCaps> dop;
  fe::RadarCube<SixChannelCaps> cube;
};

}  // namespace

TEST_CASE("doppler: every snapshot value has the bits of Fft<N_c> on the windowed chirps") {
  // The batch (lane = range bin, 16 per block) must give, for every (range bin,
  // channel), the bits of one Fft<N_c>::forward() of w[c] r_c, fftshift-ed,
  // in every dispatch copy of the stage this CPU can run.
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.doppler_window = fe::WindowType::kHann;
  auto s = std::make_unique<SixChannelStages>();
  REQUIRE(s->rmf.init(p) == Status::kOk);
  REQUIRE(s->dop.init(p) == Status::kOk);
  mptrack::test::SynthTarget t[2];
  t[0].range_m = 7.0 * fe::range_bin_m(p);
  t[0].radial_mps = 11.0;
  t[1].range_m = 20.3 * fe::range_bin_m(p);
  t[1].radial_mps = -4.0;
  t[1].amplitude = 0.3;
  mptrack::test::synthesize<SixChannelCaps>(p, t, 2, 1e-3, 7, s->cube);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  constexpr std::size_t kNc = SixChannelCaps::kNumChirps;
  mptrack::dsp::Fft<kNc> fft;
  REQUIRE(fft.init() == Status::kOk);
  float w[kNc];
  fe::fill_window(p.doppler_window, w, kNc);
  for (const auto copy : {mptrack::dsp::FftCopy::kBaseline, mptrack::dsp::FftCopy::kAvx2,
                          mptrack::dsp::FftCopy::kAvx512}) {
    if (!mptrack::dsp::fft_copy_available(copy)) continue;
    CAPTURE(mptrack::dsp::fft_copy_name(copy));
    REQUIRE(s->dop.process_copy(copy, s->rmf) == Status::kOk);
    std::size_t differing = 0;
    for (std::size_t g = 0; g < SixChannelCaps::kNumRangeBins; ++g) {
      for (std::size_t v = 0; v < 6; ++v) {
        float re[kNc];
        float im[kNc];
        for (std::size_t c = 0; c < kNc; ++c) {
          re[c] = s->rmf.value_re(c, v, g) * w[c];
          im[c] = s->rmf.value_im(c, v, g) * w[c];
        }
        fft.forward(re, im);
        for (std::size_t k = 0; k < kNc; ++k) {
          const std::size_t d = (k + kNc / 2) % kNc;
          const bool same = mptrack::test::same_bits_or_nan(s->dop.snapshot_re(g, d, v), re[k]) &&
                            mptrack::test::same_bits_or_nan(s->dop.snapshot_im(g, d, v), im[k]);
          if (!same) ++differing;
        }
      }
    }
    CHECK(differing == 0);
  }
}

TEST_CASE("doppler: with one chirp the stage is a transpose (seed 004, no Doppler axis)") {
  using C1 = fe::Seed004RadarCaps;
  fe::FrontEndParams p;
  auto rmf = std::make_unique<fe::RangeMatchedFilter<C1>>();
  auto dop = std::make_unique<fe::DopplerProcessor<C1>>();
  auto cube = std::make_unique<fe::RadarCube<C1>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  REQUIRE(dop->init(p) == Status::kOk);
  mptrack::test::synthesize<C1>(p, nullptr, 0, 1.0, 9, *cube);
  REQUIRE(rmf->process(*cube) == Status::kOk);
  REQUIRE(dop->process(*rmf) == Status::kOk);
  CHECK_FALSE(fe::DopplerProcessor<C1>::kHasDoppler);
  CHECK(dop->velocity_mps(0.0) == 0.0);
  for (std::size_t v = 0; v < 9; ++v) {
    CHECK(dop->snapshot_re(17, 0, v) == rmf->value_re(0, v, 17));
    CHECK(dop->snapshot_im(17, 0, v) == rmf->value_im(0, v, 17));
  }
}

TEST_CASE("doppler: process does not allocate and refuses to run before init") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  CHECK(s->dop.process(s->rmf) == Status::kNotInitialized);
  REQUIRE(s->rmf.init(p) == Status::kOk);
  REQUIRE(s->dop.init(p) == Status::kOk);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  mptrack::test::NoAllocScope guard;
  const Status st = s->dop.process(s->rmf);
  CHECK(guard.allocations() == 0);
  CHECK(st == Status::kOk);
}
