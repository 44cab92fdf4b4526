// The ADC model between the synthesised volts and the int16 ring
// (adc/adc_model.h): quantisation, clipping, the rails and the saturated-
// frame rule, values worked out by hand.
#include <doctest/doctest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "mptrack/adc/adc_json.h"
#include "mptrack/adc/adc_model.h"
#include "mptrack/adc/adc_scenario.h"

namespace adc = mptrack::adc;

namespace {

adc::AdcModelSpec model(std::uint32_t bits, double full_scale_v) {
  adc::AdcModelSpec m;
  m.sample_format = "int16";
  m.bits = bits;
  m.full_scale_v = full_scale_v;
  return m;
}

}  // namespace

TEST_CASE("adc model: 12 bits, 1 V full scale: lsb 1/2048 V, codes left-justified (x 16)") {
  const adc::AdcModelSpec m = model(12, 1.0);
  // 0.3 V = 614.4 lsb -> 614 -> 614 x 16 = 9824
  CHECK(adc::adc_code(0.3, m) == 9824);
  CHECK(adc::adc_code(-0.3, m) == -9824);
  // mid-tread, halves round up: 1.5 lsb -> 2, -1.5 lsb -> -1
  CHECK(adc::adc_code(1.5 / 2048.0, m) == 32);
  CHECK(adc::adc_code(-1.5 / 2048.0, m) == -16);
  CHECK(adc::adc_code(0.49 / 2048.0, m) == 0);
}

TEST_CASE("adc model: values beyond full scale clip to the rails and say so") {
  const adc::AdcModelSpec m = model(12, 1.0);
  bool clipped = false;
  // +1 V = 2048 lsb > 2047: clipped to 2047 x 16 = 32752
  CHECK(adc::adc_code(1.0, m, &clipped) == 32752);
  CHECK(clipped);
  // -1 V = -2048 lsb is the negative rail itself, representable
  CHECK(adc::adc_code(-1.0, m, &clipped) == -32768);
  CHECK_FALSE(clipped);
  CHECK(adc::adc_code(-5.0, m, &clipped) == -32768);
  CHECK(clipped);
  CHECK(adc::adc_code(2047.0 / 2048.0, m, &clipped) == 32752);  // at the rail, not beyond
  CHECK_FALSE(clipped);
  // 16 bits: the rails are the int16 limits
  const adc::AdcModelSpec m16 = model(16, 2.0);
  CHECK(adc::adc_code(3.0, m16, &clipped) == 32767);
  CHECK(clipped);
  CHECK(adc::adc_code(1.0, m16) == 16384);  // 1 V of 2 V = 2^14
}

TEST_CASE("adc model: quantise counts clipped values; codes_to_volts returns the quantised volts") {
  const adc::AdcModelSpec m = model(12, 1e-4);
  auto volts = std::make_unique<adc::AdcCube>();
  auto codes = std::make_unique<adc::AdcCube16>();
  volts->time_us = 123;
  volts->iq[0] = 0.3e-4f;   // 614.4 lsb -> 614
  volts->iq[1] = 2e-4f;     // clipped high
  volts->iq[2] = -3e-4f;    // clipped low
  CHECK(adc::quantise(*volts, m, *codes) == 2);
  CHECK(codes->time_us == 123);
  CHECK(codes->iq[0] == 9824);
  CHECK(codes->iq[1] == 32752);
  CHECK(codes->iq[2] == -32768);
  CHECK(codes->iq[3] == 0);
  auto back = std::make_unique<adc::AdcCube>();
  adc::codes_to_volts(*codes, m, *back);
  CHECK(back->time_us == 123);
  // 614 lsb of 1e-4 / 2048 V, computed as code x (1e-4 / 32768) in float
  CHECK(back->iq[0] == 9824.0f * static_cast<float>(1e-4 / 32768.0));
  CHECK(back->iq[0] == doctest::Approx(614.0 * 1e-4 / 2048.0).epsilon(1e-6));
  CHECK(back->iq[2] == doctest::Approx(-1e-4).epsilon(1e-6));
}

TEST_CASE("adc model: a frame is saturated above saturation_fraction of its values at a rail") {
  adc::AdcModelSpec m = model(12, 1.0);
  m.saturation_fraction = 0.01;
  auto codes = std::make_unique<adc::AdcCube16>();
  const std::size_t n = codes->iq.size();
  const std::size_t limit = n / 100;  // floor(0.01 n): at the limit is not saturated
  for (std::size_t i = 0; i < limit; ++i) codes->iq[i] = (i % 2u) ? std::int16_t{32752} : std::int16_t{-32768};
  CHECK(adc::codes_at_rail(*codes, 12) == limit);
  CHECK_FALSE(adc::frame_saturated(*codes, m));
  codes->iq[limit] = 32752;
  CHECK(adc::frame_saturated(*codes, m));
  // 32736 is one 12-bit lsb below the rail; 32767 would be the 16-bit rail only
  codes->iq[limit] = 32736;
  CHECK_FALSE(adc::frame_saturated(*codes, m));
  CHECK(adc::codes_at_rail(*codes, 16) == limit / 2);  // only the -32768 codes
}

TEST_CASE("adc model: the scenario's adc fields are range-checked and named") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  CHECK(adc::validate(s).empty());
  CHECK(s.adc.sample_format == "float");  // the built-ins keep the float path
  adc::AdcScenario b = s;
  b.adc.bits = 20;
  CHECK(adc::validate(b) == "adc.bits = 20: expected 2..16");
  b = s;
  b.adc.full_scale_v = 0.0;
  CHECK(adc::validate(b) == "adc.full_scale_v: expected a number in (0, 1000] V");
  b = s;
  b.adc.sample_format = "int12";
  CHECK(adc::validate(b) == "adc.sample_format: expected \"float\" or \"int16\"");
  b = s;
  b.adc.saturation_policy = "blank";
  CHECK(adc::validate(b) == "adc.saturation_policy: expected \"keep\" or \"drop\"");
  b = s;
  b.adc.saturation_fraction = 1.5;
  CHECK(adc::validate(b) == "adc.saturation_fraction: expected a number in [0, 1]");
}

TEST_CASE("adc model: the adc object round-trips through the scenario JSON; unknown keys are refused") {
  adc::AdcScenario s;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", s));
  s.adc = model(14, 3e-5);
  s.adc.saturation_policy = "drop";
  s.adc.saturation_fraction = 0.02;
  auto j = adc::adc_scenario_to_json(s);
  CHECK(adc::adc_scenario_from_json(j) == s);
  j["adc"]["gain_db"] = 3;
  std::string err;
  try {
    (void)adc::adc_scenario_from_json(j);
  } catch (const adc::AdcScenarioError& e) {
    err = e.what();
  }
  CHECK(err == "adc.gain_db: unknown field");
}
