// The SBL detector on frames of the raw-ADC synthesiser (host-sim/adc) with the
// parameters sbl_params_for() derives from the scenario: the atoms must match
// the synthesised echoes (positions) and their scale the scenario's mean
// component SNR.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/sbl_config.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/sbl/sbl_detector.h"

using mptrack::Status;

TEST_CASE("adc + SBL: sbl_params_for(seed004-drones) is valid and matches the synthesiser's noise") {
  mptrack::adc::AdcScenario s;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", s));
  const mptrack::SblParams p = mptrack::adc::sbl_params_for(s);
  mptrack::ParamError where;
  CHECK(mptrack::SblDetector<float>::validate(p, &where) == Status::kOk);
  mptrack::adc::FrameSynthesizer syn;
  REQUIRE(syn.init(s, 1, 0) == Status::kOk);
  CHECK(p.noise_variance_v2 == syn.noise_variance());
  CHECK(p.max_abs_bearing_rad == doctest::Approx(75.0 * 3.141592653589793 / 180.0));
}

TEST_CASE("adc + SBL: noiseless mean-RCS drones are found at the truth with SNR = the scenario's mean SNR") {
  mptrack::adc::AdcScenario s;
  REQUIRE(mptrack::adc::builtin_adc_scenario("seed004-drones", s));
  mptrack::adc::SynthOptions opt;
  opt.noise = false;
  opt.fluctuate = false;  // every RCS at its mean, phase 0
  mptrack::adc::FrameSynthesizer syn;
  REQUIRE(syn.init(s, 1, 0, opt) == Status::kOk);
  auto det = std::make_unique<mptrack::SblDetector<double>>();
  REQUIRE(det->init(mptrack::adc::sbl_params_for(s)) == Status::kOk);
  auto cube = std::make_unique<mptrack::adc::AdcCube>();
  std::vector<mptrack::adc::DroneTruth> truth;
  // Frame 10: drones 1 (~28 dB) and 2 (~17 dB) far apart, both above eta.
  // (Where an alive drone is below eta, e.g. drone 1 at frame 60, its unmodelled
  // echo biases the others by decimetres even without noise.)
  REQUIRE(syn.synthesize(10, *cube, truth) == Status::kOk);
  mptrack::Scan<double, 16> scan;
  REQUIRE(det->process(*cube, scan) == Status::kOk);
  for (const auto& t : truth) {
    if (10.0 * std::log10(t.snr_mean) < 13.0) continue;  // below eta + margin: may be pruned
    bool found = false;
    for (std::size_t i = 0; i < det->num_detections(); ++i) {
      const auto& d = det->detection(i);
      if (std::hypot(d.x_m - t.state.x, d.y_m - t.state.y) < 0.05) {
        found = true;
        // Estimated SNR (|mu|^2 + C) ||s||^2 against ||s||^2 at the mean RCS:
        // the in-band energy (99 %) and C ||s||^2 ~ 1.
        CHECK(d.snr == doctest::Approx(t.snr_mean).epsilon(0.05));
      }
    }
    CHECK(found);
  }
}
