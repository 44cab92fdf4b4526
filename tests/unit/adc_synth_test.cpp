// Raw-ADC synthesizer (host-sim/adc): echoes land where the front end says,
// noise has the calibrated power, the SNR table of docs/algorithms/scenarios.md §Seed 004.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/frontend_config.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/frontend/front_end.h"

namespace adc = mptrack::adc;
namespace fe = mptrack::frontend;
using mptrack::Status;

namespace {

constexpr double kC = 299792458.0;

/// One drone, stationary, no noise, no fluctuation: a deterministic echo.
adc::AdcScenario one_target(double x, double y) {
  adc::AdcScenario s;
  adc::builtin_adc_scenario("seed004-drones", s);
  s.drones.resize(1);
  s.drones[0].start_m = {x, y};
  s.drones[0].velocity_mps = {0.0, 0.0};
  s.drones[0].legs.clear();
  s.phases.clear();
  return s;
}

struct Rig {
  fe::FrontEnd<adc::AdcCaps> fe;
  adc::AdcCube cube;
  mptrack::Scan<float, adc::AdcCaps::kMaxDetections> scan;
};

}  // namespace

TEST_CASE("adc: a single echo lands at its range bin and angle bin after the front end") {
  // Range bin 10 <-> delay 10 samples at 32 MHz: r = 10 c / (2 f_s) = 46.8426 m.
  // sin(theta) = 0.25 <-> angle bin h = 0.25 * 64 * 0.5 = 8, i.e. a = 8 + 32 = 40.
  const double r = 10.0 * kC / (2.0 * 32e6);
  const double u = 0.25;
  const adc::AdcScenario s = one_target(r * u, r * std::sqrt(1.0 - u * u));
  adc::FrameSynthesizer syn;
  adc::SynthOptions opt;
  opt.noise = false;
  opt.fluctuate = false;
  REQUIRE(syn.init(s, 1, 0, opt) == Status::kOk);
  auto rig = std::make_unique<Rig>();
  REQUIRE(rig->fe.init(adc::frontend_params_for(s)) == Status::kOk);
  std::vector<adc::DroneTruth> truth;
  REQUIRE(syn.synthesize(1, rig->cube, truth) == Status::kOk);
  REQUIRE(truth.size() == 1);
  CHECK(truth[0].range_m == doctest::Approx(r).epsilon(1e-12));
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);

  // Power map maximum over the whole map is at (g = 10, a = 40).
  const auto& ang = rig->fe.angle_stage();
  std::size_t best_g = 0, best_a = 0;
  float best = -1.0f;
  for (std::size_t a = 0; a < adc::AdcCaps::kNumAngleBins; ++a) {
    for (std::size_t g = 0; g < adc::AdcCaps::kNumRangeBins; ++g) {
      if (ang.power(g, 0, a) > best) {
        best = ang.power(g, 0, a);
        best_g = g;
        best_a = a;
      }
    }
  }
  CHECK(best_g == 10);
  CHECK(best_a == 40);

  // Matched-filter peak of one channel = echo amplitude x L (rectangular window;
  // docs/algorithms/frontend.md §Range matched filter):
  // |alpha| = sqrt(0.05 m^2) * A lambda / ((4 pi)^1.5 r^2).
  const double lambda = kC / 10e9;
  const double four_pi = 4.0 * M_PI;
  const double amp = std::sqrt(0.05) * 0.53 * lambda / (four_pi * std::sqrt(four_pi) * r * r);
  CHECK(syn.chirp_samples() == 115);  // round(3.6 us * 32 MHz) = round(115.2)
  const auto& rmf = rig->fe.range_stage();
  const double pr = static_cast<double>(rmf.value_re(0, 4, 10));
  const double pi = static_cast<double>(rmf.value_im(0, 4, 10));
  CHECK(std::sqrt(pr * pr + pi * pi) == doctest::Approx(amp * 115.0).epsilon(1e-4));

  // The strongest detection (noise-free: range/angle sidelobes are local
  // maxima too): range and azimuth (phi = pi/2 - asin(0.25)).
  REQUIRE(rig->scan.measurements.size() >= 1);
  const auto& m = rig->scan.measurements[0];
  CHECK(static_cast<double>(m.range_m) == doctest::Approx(r).epsilon(2e-3));
  CHECK(static_cast<double>(m.azimuth_rad) == doctest::Approx(M_PI / 2 - std::asin(0.25)).epsilon(1e-4));
}

TEST_CASE("adc: an off-grid echo is located to a fraction of a range bin") {
  // r = 30 m, bearing 45 deg (track 1 near the crossing): 6.405 samples of delay.
  const double r = 30.0;
  const adc::AdcScenario s = one_target(r * std::sqrt(0.5), r * std::sqrt(0.5));
  adc::FrameSynthesizer syn;
  adc::SynthOptions opt;
  opt.noise = false;
  opt.fluctuate = false;
  REQUIRE(syn.init(s, 1, 0, opt) == Status::kOk);
  auto rig = std::make_unique<Rig>();
  REQUIRE(rig->fe.init(adc::frontend_params_for(s)) == Status::kOk);
  std::vector<adc::DroneTruth> truth;
  REQUIRE(syn.synthesize(1, rig->cube, truth) == Status::kOk);
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  REQUIRE(rig->scan.measurements.size() >= 1);
  const auto& m = rig->scan.measurements[0];
  // Bin 4.68 m; the log-parabolic interpolation is good to a few tenths of a metre.
  CHECK(std::fabs(static_cast<double>(m.range_m) - r) < 0.5);
  CHECK(std::fabs(static_cast<double>(m.azimuth_rad) - M_PI / 4) < 0.002);
}

TEST_CASE("adc: thermal noise power per sample is k_b T0 f_s (model A) or k_b T0 BW (literal)") {
  adc::AdcScenario s;
  adc::builtin_adc_scenario("seed004-drones", s);
  s.drones.clear();
  s.phases.clear();
  for (int model = 0; model < 2; ++model) {
    s.radar.noise_model = model == 0 ? adc::NoiseModel::kModelA : adc::NoiseModel::kLiteral;
    const double expect = 1.380649e-23 * 290.0 * (model == 0 ? 32e6 : 20e6);
    adc::FrameSynthesizer syn;
    REQUIRE(syn.init(s, 7, 0) == Status::kOk);
    CHECK(syn.noise_variance() == doctest::Approx(expect).epsilon(1e-12));
    auto cube = std::make_unique<adc::AdcCube>();
    std::vector<adc::DroneTruth> truth;
    double sum = 0.0, sum_re = 0.0;
    std::size_t n = 0;
    for (std::uint32_t k = 1; k <= 10; ++k) {
      REQUIRE(syn.synthesize(k, *cube, truth) == Status::kOk);
      for (std::size_t i = 0; i < cube->iq.size(); i += 2) {
        const double re = static_cast<double>(cube->iq[i]);
        const double im = static_cast<double>(cube->iq[i + 1]);
        sum += re * re + im * im;
        sum_re += re * re;
        ++n;
      }
    }
    // 23040 complex samples: relative standard error 1/sqrt(n) = 0.66 %.
    CHECK(sum / static_cast<double>(n) == doctest::Approx(expect).epsilon(0.03));
    CHECK(sum_re / static_cast<double>(n) == doctest::Approx(expect / 2).epsilon(0.03));  // circular
  }
}

TEST_CASE("adc: mean component SNR reproduces the seed 004 table (model A)") {
  adc::AdcScenario s;
  adc::builtin_adc_scenario("seed004-drones", s);
  // docs/algorithms/scenarios.md §Seed 004: 37.1 dB at 10 m, 18.0 dB at 30 m, 1.0 dB at 80 m,
  // -2.9 dB at 100 m.
  const double db10 = 10.0 * std::log10(adc::mean_component_snr(s, 10.0, 0.05));
  const double db30 = 10.0 * std::log10(adc::mean_component_snr(s, 30.0, 0.05));
  const double db80 = 10.0 * std::log10(adc::mean_component_snr(s, 80.0, 0.05));
  const double db100 = 10.0 * std::log10(adc::mean_component_snr(s, 100.0, 0.05));
  CHECK(db10 == doctest::Approx(37.1).epsilon(0.003));
  CHECK(db30 == doctest::Approx(18.0).epsilon(0.005));
  CHECK(db80 == doctest::Approx(1.0).epsilon(0.1));
  CHECK(db100 == doctest::Approx(-2.9).epsilon(0.03));
}

TEST_CASE("adc: frames are reproducible from (seed, run, frame) and differ between runs") {
  adc::AdcScenario s;
  adc::builtin_adc_scenario("mimo-interference", s);
  adc::FrameSynthesizer a, b, c;
  REQUIRE(a.init(s, 5, 2) == Status::kOk);
  REQUIRE(b.init(s, 5, 2) == Status::kOk);
  REQUIRE(c.init(s, 5, 3) == Status::kOk);
  auto ca = std::make_unique<adc::AdcCube>();
  auto cb = std::make_unique<adc::AdcCube>();
  auto cc = std::make_unique<adc::AdcCube>();
  std::vector<adc::DroneTruth> t;
  REQUIRE(a.synthesize(45, *ca, t) == Status::kOk);
  REQUIRE(b.synthesize(44, *cb, t) == Status::kOk);  // another frame first: no effect on frame 45
  REQUIRE(b.synthesize(45, *cb, t) == Status::kOk);
  REQUIRE(c.synthesize(45, *cc, t) == Status::kOk);
  CHECK(ca->iq == cb->iq);
  CHECK(ca->iq != cc->iq);
  CHECK(ca->time_us == 4400000);
  CHECK(a.synthesize(101, *ca, t) == Status::kInvalidArgument);
}
