// End-to-end front end: cube -> Scan of measurements.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>

#include "alloc_guard.h"
#include "frontend_test_signals.h"
#include "mptrack/frontend/front_end.h"

namespace fe = mptrack::frontend;
using mptrack::Status;
using Seed = fe::Seed004RadarCaps;
using Small = fe::SmallDopplerRadarCaps;

namespace {

fe::FrontEndParams seed_params() {
  fe::FrontEndParams p;
  p.range_window = fe::WindowType::kHamming;
  p.angle_window = fe::WindowType::kHann;
  return p;
}

double dbl(float x) { return static_cast<double>(x); }

template <class Caps>
struct Rig {
  fe::FrontEnd<Caps> fe;
  fe::RadarCube<Caps> cube;
  mptrack::Scan<float, Caps::kMaxDetections> scan;
};

std::uint32_t fake_clock() {
  static std::uint32_t t = 0;
  t += 10;
  return t;
}

}  // namespace

TEST_CASE("frontend: bearing/azimuth conventions (seed 004 vs seed 000)") {
  // theta_b from +y towards +x; phi CCW from +x: phi = pi/2 - theta_b.
  CHECK(fe::bearing_to_azimuth(0.0) == doctest::Approx(M_PI / 2));
  CHECK(fe::bearing_to_azimuth(M_PI / 6) == doctest::Approx(M_PI / 3));    // x > 0: 60 deg
  CHECK(fe::bearing_to_azimuth(-M_PI / 4) == doctest::Approx(3 * M_PI / 4));
  CHECK(fe::bearing_to_azimuth(-M_PI * 0.75) == doctest::Approx(-M_PI * 0.75));  // wraps
  CHECK(fe::azimuth_to_bearing(fe::bearing_to_azimuth(0.3)) == doctest::Approx(0.3));
  // Point (x, y) = (3, 4): theta_b = atan2(3, 4), phi = atan2(4, 3).
  CHECK(fe::bearing_to_azimuth(std::atan2(3.0, 4.0)) == doctest::Approx(std::atan2(4.0, 3.0)));
}

TEST_CASE("frontend: two seed 004 targets give measurements at their range and azimuth") {
  auto rig = std::make_unique<Rig<Seed>>();
  const fe::FrontEndParams p = seed_params();
  REQUIRE(rig->fe.init(p) == Status::kOk);
  mptrack::test::SynthTarget t[2];
  t[0].range_m = 28.3;
  t[0].bearing_rad = 0.25;
  t[0].amplitude = 1.0;
  t[1].range_m = 61.0;
  t[1].bearing_rad = -0.6;
  t[1].amplitude = 0.7;
  t[1].phase_rad = 1.0;
  mptrack::test::synthesize<Seed>(p, t, 2, 1.0, 11, rig->cube);
  rig->cube.time_us = 123456;
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  CHECK(rig->scan.time_us == 123456);
  CHECK_FALSE(rig->scan.has_doppler);
  REQUIRE(rig->scan.measurements.size() >= 2);
  // Strongest first: target 0 then target 1.
  for (std::size_t k = 0; k < 2; ++k) {
    const mptrack::Measurement<float>& m = rig->scan.measurements[k];
    CHECK(std::fabs(dbl(m.range_m) - t[k].range_m) < 0.8);  // bin 4.68 m, res 7.5 m
    CHECK(std::fabs(dbl(m.azimuth_rad) - (M_PI / 2 - t[k].bearing_rad)) < 0.02);
    CHECK(m.doppler_mps == 0.0f);
  }
  CHECK(rig->scan.measurements[0].amplitude > rig->scan.measurements[1].amplitude);
  CHECK(rig->fe.counters().frames == 1);
}

TEST_CASE("frontend: amplitude^2 estimates the post-processing SNR (noise-normalised)") {
  auto rig = std::make_unique<Rig<Seed>>();
  fe::FrontEndParams p = seed_params();
  REQUIRE(rig->fe.init(p) == Status::kOk);
  // On-grid target (integer delay 8 bins, grid bearing u = 4/32): no straddle loss.
  mptrack::test::SynthTarget t;
  t.range_m = 8.0 * fe::range_bin_m(p);
  t.bearing_rad = std::asin(4.0 / 32.0);
  t.amplitude = 0.6;
  // SNR = A^2 (sum w_r)^2 (sum w_a)^2 / (sigma^2 sum w_r^2 sum w_a^2).
  const double sw_r = dbl(rig->fe.range_stage().coherent_gain());
  const double sw2_r = dbl(rig->fe.range_stage().noise_gain());
  double sw_a = 0.0;
  double sw2_a = 0.0;
  for (std::size_t v = 0; v < 9; ++v) {
    const double w = 0.5 - 0.5 * std::cos(2 * M_PI * static_cast<double>(v) / 8.0);
    sw_a += w;
    sw2_a += w * w;
  }
  const double snr = 0.36 * sw_r * sw_r * sw_a * sw_a / (sw2_r * sw2_a);
  double mean_a2 = 0.0;
  const int frames = 12;
  for (int f = 0; f < frames; ++f) {
    mptrack::test::synthesize<Seed>(p, &t, 1, 1.0, 300 + static_cast<std::uint64_t>(f), rig->cube);
    REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
    REQUIRE(rig->scan.measurements.size() >= 1);
    mean_a2 += dbl(rig->scan.measurements[0].amplitude) * dbl(rig->scan.measurements[0].amplitude);
  }
  mean_a2 /= frames;
  // CA with 2T = 16 cells: E[1/z] = 16/15 per unit noise; +1 for the noise in the peak cell.
  // Hann over 9 elements: sum w = 4, sum w^2 = 3 (hand-derived).
  CHECK(sw_a == doctest::Approx(4.0));
  CHECK(sw2_a == doctest::Approx(3.0));
  CHECK(mean_a2 == doctest::Approx(snr * 16.0 / 15.0 + 1.0).epsilon(0.15));
}

TEST_CASE("frontend: a moving target in the Doppler configuration reports its radial velocity") {
  auto rig = std::make_unique<Rig<Small>>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.doppler_window = fe::WindowType::kHann;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  const double bin = (299792458.0 / 10e9) / (2.0 * 16.0 * 100e-6);
  mptrack::test::SynthTarget t;
  t.range_m = 51.0;
  t.bearing_rad = -0.2;
  t.radial_mps = -2.3 * bin;  // approaching, off-grid
  t.amplitude = 0.5;
  mptrack::test::synthesize<Small>(p, &t, 1, 0.05, 21, rig->cube);
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  CHECK(rig->scan.has_doppler);
  REQUIRE(rig->scan.measurements.size() >= 1);
  const mptrack::Measurement<float>& m = rig->scan.measurements[0];
  CHECK(std::fabs(dbl(m.doppler_mps) - t.radial_mps) < 0.15 * bin);
  CHECK(std::fabs(dbl(m.range_m) - t.range_m) < 1.0);
  CHECK(std::fabs(dbl(m.azimuth_rad) - (M_PI / 2 + 0.2)) < 0.02);
}

TEST_CASE("frontend: over the detection cap the strongest are kept and the rest counted") {
  auto rig = std::make_unique<Rig<Seed>>();
  // Six echoes 40 m apart on one bearing; a short CFAR window (5 bins = 23 m
  // each side) keeps each echo out of the others' training cells.
  fe::FrontEndParams p = seed_params();
  p.max_range_m = 290.0;
  p.cfar.guard_cells = 1;
  p.cfar.training_cells = 4;
  p.max_detections = 3;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  mptrack::test::SynthTarget t[6];
  const double amps[6] = {0.5, 1.0, 0.3, 0.8, 0.4, 0.6};
  for (std::size_t k = 0; k < 6; ++k) {
    t[k].range_m = 20.0 + 40.0 * static_cast<double>(k);
    t[k].bearing_rad = 0.2;
    t[k].amplitude = amps[k];
  }
  mptrack::test::synthesize<Seed>(p, t, 6, 0.1, 5, rig->cube);
  REQUIRE(rig->fe.process(rig->cube, rig->scan) == Status::kCapacityExceeded);
  REQUIRE(rig->scan.measurements.size() == 3);
  CHECK(rig->fe.last_frame_dropped() >= 3);
  CHECK(rig->fe.counters().detections_over_cap == rig->fe.last_frame_dropped());
  // Kept: targets 1 (1.0), 3 (0.8), 5 (0.6), strongest first.
  CHECK(std::fabs(dbl(rig->scan.measurements[0].range_m) - t[1].range_m) < 1.0);
  CHECK(std::fabs(dbl(rig->scan.measurements[1].range_m) - t[3].range_m) < 1.0);
  CHECK(std::fabs(dbl(rig->scan.measurements[2].range_m) - t[5].range_m) < 1.0);
  CHECK(rig->scan.measurements[0].amplitude >= rig->scan.measurements[1].amplitude);
  CHECK(rig->scan.measurements[1].amplitude >= rig->scan.measurements[2].amplitude);
}

TEST_CASE("frontend: a NaN sample rejects the frame, empties the scan and is counted") {
  auto rig = std::make_unique<Rig<Seed>>();
  REQUIRE(rig->fe.init(seed_params()) == Status::kOk);
  REQUIRE(rig->scan.measurements.push_back(mptrack::Measurement<float>{}) == Status::kOk);
  rig->cube.iq[100] = std::numeric_limits<float>::infinity();
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kInvalidInput);
  CHECK(rig->scan.measurements.empty());
  CHECK(rig->fe.counters().frames_rejected == 1);
  CHECK(rig->fe.counters().frames == 0);
}

TEST_CASE("frontend: init validates the parameters and process refuses to run before it") {
  auto rig = std::make_unique<Rig<Seed>>();
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kNotInitialized);
  fe::FrontEndParams p = seed_params();
  p.max_detections = 0;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.max_detections = Seed::kMaxDetections + 1;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p = seed_params();
  p.min_range_m = 50.0;
  p.max_range_m = 40.0;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p = seed_params();
  p.cfar.training_cells = 40;  // window 2 (2 + 40) + 1 = 85 > 64 range bins
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  CHECK_FALSE(rig->fe.initialized());
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kNotInitialized);
}

TEST_CASE("frontend: stage times come from the caller's clock") {
  auto rig = std::make_unique<Rig<Seed>>();
  REQUIRE(rig->fe.init(seed_params()) == Status::kOk);
  fe::FrontEndStageTimes times;
  times.clock = &fake_clock;
  rig->cube.iq[0] = 1e-3f;  // an all-zero frame is refused before any stage runs
  REQUIRE(rig->fe.process(rig->cube, rig->scan, &times) == Status::kOk);
  // The clock advances 10 a call. Range and Doppler run channel by channel,
  // each channel's share between two adjacent calls: 10 per channel, summed.
  constexpr std::uint32_t kChannels = Seed::kNumTx * Seed::kNumRx;
  CHECK(times.ticks[static_cast<std::size_t>(fe::FrontEndStage::kRange)] == 10u * kChannels);
  CHECK(times.ticks[static_cast<std::size_t>(fe::FrontEndStage::kDoppler)] == 10u * kChannels);
  CHECK(times.ticks[static_cast<std::size_t>(fe::FrontEndStage::kAngle)] == 10u);
  CHECK(times.ticks[static_cast<std::size_t>(fe::FrontEndStage::kDetect)] == 10u);
}

TEST_CASE("frontend: process does not allocate (seed 004 and Doppler configurations)") {
  auto seed = std::make_unique<Rig<Seed>>();
  auto small = std::make_unique<Rig<Small>>();
  REQUIRE(seed->fe.init(seed_params()) == Status::kOk);
  REQUIRE(small->fe.init(mptrack::test::small_doppler_params()) == Status::kOk);
  mptrack::test::SynthTarget t;
  t.range_m = 30.0;
  mptrack::test::synthesize<Seed>(seed_params(), &t, 1, 1.0, 1, seed->cube);
  mptrack::test::synthesize<Small>(mptrack::test::small_doppler_params(), &t, 1, 1.0, 1,
                                   small->cube);
  mptrack::test::NoAllocScope guard;
  const Status s1 = seed->fe.process(seed->cube, seed->scan);
  const Status s2 = small->fe.process(small->cube, small->scan);
  CHECK(guard.allocations() == 0);
  CHECK(s1 == Status::kOk);
  CHECK(s2 == Status::kOk);
  CHECK(seed->scan.measurements.size() >= 1);
}

TEST_CASE("frontend: the large configuration (12 channels x 256 x 128 chirps) finds a mover") {
  using Large = fe::LargeRadarCaps;
  auto rig = std::make_unique<Rig<Large>>();
  fe::FrontEndParams p;
  p.carrier_hz = 77e9;
  p.chirp_repetition_s = 60e-6;
  p.max_range_m = 590.0;
  p.max_detections = 256;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  const double bin = (299792458.0 / 77e9) / (2.0 * 128.0 * 60e-6);  // 0.2535 m/s
  mptrack::test::SynthTarget t;
  t.range_m = 212.0;
  t.bearing_rad = 0.35;
  t.radial_mps = 17.3 * bin;
  t.amplitude = 0.05;  // SNR 0.0025 * 115 * 128 * 12 = 442 (26 dB) after Hann in Doppler
  mptrack::test::synthesize<Large>(p, &t, 1, 1.0, 8, rig->cube);
  mptrack::test::NoAllocScope guard;
  const Status s = rig->fe.process(rig->cube, rig->scan);
  CHECK(guard.allocations() == 0);
  REQUIRE(s == Status::kOk);
  REQUIRE(rig->scan.measurements.size() >= 1);
  const mptrack::Measurement<float>& m = rig->scan.measurements[0];
  CHECK(std::fabs(dbl(m.range_m) - 212.0) < 1.0);
  CHECK(std::fabs(dbl(m.azimuth_rad) - (M_PI / 2 - 0.35)) < 0.03);
  CHECK(std::fabs(dbl(m.doppler_mps) - t.radial_mps) < 0.2 * bin);
}

namespace {

template <class Caps>
struct Int16Rig {
  fe::FrontEnd<Caps> fe;
  fe::RadarCubeInt16<Caps> cube;
  mptrack::Scan<float, Caps::kMaxDetections> scan;
};

// An int16 frame with one target at 60 m in noise, well below full
// scale: the float synthesizer's cube quantised to codes (x 32768).
template <class Caps>
void fill_target(const fe::FrontEndParams& p, fe::RadarCubeInt16<Caps>& cube) {
  auto f = std::make_unique<fe::RadarCube<Caps>>();
  mptrack::test::SynthTarget t;
  t.range_m = 60.0;
  t.amplitude = 0.02;
  mptrack::test::synthesize<Caps>(p, &t, 1, 1e-4, 7, *f);
  for (std::size_t i = 0; i < cube.iq.size(); ++i) {
    cube.iq[i] = static_cast<std::int16_t>(std::lround(static_cast<double>(f->iq[i]) * 32768.0));
  }
}

}  // namespace

TEST_CASE("frontend: an all-zero int16 frame is refused as kInvalidInput and counted") {
  auto rig = std::make_unique<Int16Rig<Small>>();
  REQUIRE(rig->fe.init(mptrack::test::small_doppler_params()) == Status::kOk);
  rig->cube.iq.fill(0);
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kInvalidInput);
  CHECK(rig->scan.measurements.empty());
  CHECK(rig->fe.counters().frames_all_zero == 1);
  CHECK(rig->fe.counters().frames_rejected == 1);
  CHECK(rig->fe.counters().frames == 0);
  rig->cube.iq[5] = 1;  // one non-zero code: processed
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kOk);
  CHECK(rig->fe.counters().frames_all_zero == 1);
  CHECK(rig->fe.counters().frames == 1);
}

TEST_CASE("frontend: an all-zero float frame is refused too") {
  auto rig = std::make_unique<Rig<Small>>();
  REQUIRE(rig->fe.init(mptrack::test::small_doppler_params()) == Status::kOk);
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kInvalidInput);
  CHECK(rig->fe.counters().frames_all_zero == 1);
}

TEST_CASE("frontend: a frame with a NaN and a sample beyond the ceiling counts once, as over it") {
  // The range stage tallies the whole frame; the front end decides in the
  // order of the frame checks: ceiling, then all zero, then NaN/Inf.
  auto rig = std::make_unique<Rig<Small>>();
  REQUIRE(rig->fe.init(mptrack::test::small_doppler_params()) == Status::kOk);
  rig->cube.iq.fill(0.25f);
  rig->cube.iq[17] = std::nanf("");
  rig->cube.iq[rig->cube.iq.size() - 3] = 2e6f;  // default ceiling 1e6
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kInvalidInput);
  CHECK(rig->fe.counters().frames_over_ceiling == 1);
  CHECK(rig->fe.counters().frames_all_zero == 0);
  CHECK(rig->fe.counters().frames_rejected == 1);
  rig->cube.iq[rig->cube.iq.size() - 3] = 0.25f;  // NaN alone: rejected, not over the ceiling
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kInvalidInput);
  CHECK(rig->fe.counters().frames_over_ceiling == 1);
  CHECK(rig->fe.counters().frames_rejected == 2);
  CHECK(rig->scan.measurements.empty());
}

TEST_CASE("frontend: a saturated int16 frame is processed, flagged kPartial and counted") {
  auto rig = std::make_unique<Int16Rig<Small>>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.saturation_fraction = 0.01;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  fill_target<Small>(p, rig->cube);
  const std::size_t n = rig->cube.iq.size();
  const std::size_t limit = n / 100;  // 1 %: at the limit is not saturated
  for (std::size_t i = 0; i < limit; ++i) rig->cube.iq[i * 97u % n] = (i % 2u) ? 32767 : -32768;
  const Status at_limit = rig->fe.process(rig->cube, rig->scan);
  CHECK((at_limit == Status::kOk || at_limit == Status::kCapacityExceeded));
  CHECK(rig->fe.counters().frames_saturated == 0);
  CHECK_FALSE(rig->scan.measurements.empty());
  // well above the limit: 10 % of the codes at full scale
  for (std::size_t i = 0; i < n; i += 10u) rig->cube.iq[i] = (i % 20u) ? 32767 : -32768;
  const Status s = rig->fe.process(rig->cube, rig->scan);
  CHECK(s == Status::kPartial);
  CHECK(rig->fe.counters().frames_saturated == 1);
  CHECK(rig->fe.counters().frames == 2);
  CHECK_FALSE(rig->scan.measurements.empty());  // still processed
  for (const auto& m : rig->scan.measurements) CHECK(mptrack::is_finite(m.amplitude));
}

TEST_CASE("frontend: max_abs_sample and saturation_fraction are validated") {
  auto rig = std::make_unique<Rig<Small>>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.max_abs_sample = 0.0;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.max_abs_sample = 1e30;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.max_abs_sample = 1e6;
  p.saturation_fraction = 1.5;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.saturation_fraction = std::numeric_limits<double>::quiet_NaN();
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.saturation_fraction = 0.0;
  CHECK(rig->fe.init(p) == Status::kOk);
}

TEST_CASE("frontend: a 12-bit ADC's positive rail (32752 = 2047 x 16, left-justified) counts as full scale") {
  auto rig = std::make_unique<Int16Rig<Small>>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.saturation_fraction = 0.01;
  p.adc_bits = 12;
  REQUIRE(rig->fe.init(p) == Status::kOk);
  fill_target<Small>(p, rig->cube);
  const std::size_t n = rig->cube.iq.size();
  // 10 % of the values at the positive rail only: 32767 is not a 12-bit code.
  for (std::size_t i = 0; i < n; i += 10u) rig->cube.iq[i] = 32752;
  CHECK(rig->fe.process(rig->cube, rig->scan) == Status::kPartial);
  CHECK(rig->fe.counters().frames_saturated == 1);
  // One LSB (16 codes) below the rail is not full scale.
  for (std::size_t i = 0; i < n; i += 10u) rig->cube.iq[i] = 32736;
  const Status below = rig->fe.process(rig->cube, rig->scan);
  CHECK((below == Status::kOk || below == Status::kCapacityExceeded));
  CHECK(rig->fe.counters().frames_saturated == 1);
}

TEST_CASE("frontend: adc_bits is validated (2..16)") {
  auto rig = std::make_unique<Rig<Small>>();
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  mptrack::ParamError where;
  p.adc_bits = 1;
  CHECK(fe::FrontEnd<Small>::validate(p, &where) == Status::kInvalidArgument);
  CHECK(std::string(where.field) == "adc_bits");
  p.adc_bits = 17;
  CHECK(rig->fe.init(p) == Status::kInvalidArgument);
  p.adc_bits = 2;
  CHECK(rig->fe.init(p) == Status::kOk);
}
