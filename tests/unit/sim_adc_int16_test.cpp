// The int16 ADC path end to end (stream/adc_source.h): the ring carries the
// ADC model's codes, saturated frames are counted and follow the scenario's
// saturation policy, and summary.json reports them.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "mptrack/adc/adc_scenario.h"
#include "stream/adc_runner.h"

namespace sim = mptrack::sim;
namespace adc = mptrack::adc;

namespace {

sim::AdcRunConfig int16_config(const char* tracker, double full_scale_v, const char* policy) {
  sim::AdcRunConfig cfg;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", cfg.scenario));
  cfg.scenario.adc.sample_format = "int16";
  cfg.scenario.adc.full_scale_v = full_scale_v;
  cfg.scenario.adc.saturation_policy = policy;
  cfg.tracker = tracker;
  cfg.frames = 6;
  cfg.progress = false;
  return cfg;
}

// Full scale 5e-7 V is two noise standard deviations (2.5e-7 V per
// component): ~4.6 % of the values clip, above the 1 % of a saturated frame.
constexpr double kTinyFullScale_v = 5e-7;

}  // namespace

TEST_CASE("int16 path: at the default full scale nothing clips and the CFAR tracker sees the drones") {
  const sim::AdcSummary s = sim::run_adc_monte_carlo(int16_config("gnn", 1e-4, "keep"));
  CHECK(s.ring.frames_processed == 6);
  CHECK(s.clipped_samples == 0);
  CHECK(s.frames_saturated == 0);
  CHECK(s.drone_detection_rate > 0.9);
  CHECK(s.mean_detections > 0.0);
}

TEST_CASE("int16 path: a saturated frame is counted and, with policy keep, its detections reach the tracker") {
  const sim::AdcSummary s = sim::run_adc_monte_carlo(int16_config("gnn", kTinyFullScale_v, "keep"));
  CHECK(s.clipped_samples > 0);
  CHECK(s.frames_saturated == 6);
  CHECK(s.saturated_frames_dropped == 0);
  CHECK(static_cast<double>(s.saturated_detections) == doctest::Approx(s.mean_detections * 6.0));
  CHECK(s.base.mean_measurements > 0.0);  // given to the tracker
  const auto j = sim::adc_summary_to_json(s);
  CHECK(j["adc"]["frames_saturated"] == 6);
  CHECK(j["adc"]["saturation_policy"] == "keep");
}

TEST_CASE("int16 path: with policy drop a saturated frame reaches no tracker, counted") {
  const sim::AdcSummary s = sim::run_adc_monte_carlo(int16_config("gnn", kTinyFullScale_v, "drop"));
  CHECK(s.frames_saturated == 6);
  CHECK(s.saturated_frames_dropped == 6);
  CHECK(s.ring.frames_processed == 6);      // the ring delivered them
  CHECK(s.base.mean_confirmed_tracks == 0.0);  // no tracker step, no track
  CHECK(s.base.mean_ospa == doctest::Approx(10.0));  // c on every frame (two drones, no estimate)
  CHECK(sim::adc_summary_to_json(s)["adc"]["saturated_frames_dropped"] == 6);
}

TEST_CASE("int16 path: VMP reads the codes back in volts and tracks; the SBL detector detects") {
  const sim::AdcSummary v = sim::run_adc_monte_carlo(int16_config("vmp", 1e-4, "keep"));
  CHECK(v.frames_saturated == 0);
  CHECK(std::isfinite(v.base.mean_ospa));
  CHECK(v.base.mean_ospa < 10.0);
  const sim::AdcSummary b = sim::run_adc_monte_carlo(int16_config("sbl-gnn", kTinyFullScale_v, "keep"));
  CHECK(b.frames_saturated == 6);  // the harness's rail count, the front end's rule
  CHECK(b.mean_detections > 0.0);
}

TEST_CASE("float path: no adc block in summary.json and no saturation counts") {
  sim::AdcRunConfig cfg;
  REQUIRE(adc::builtin_adc_scenario("seed004-drones", cfg.scenario));
  cfg.tracker = "gnn";
  cfg.frames = 3;
  cfg.progress = false;
  const sim::AdcSummary s = sim::run_adc_monte_carlo(cfg);
  CHECK(s.frames_saturated == 0);
  CHECK_FALSE(sim::adc_summary_to_json(s).contains("adc"));
}
