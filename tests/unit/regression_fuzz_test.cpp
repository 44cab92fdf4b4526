// Regression tests for the fuzz findings of docs/reliability.md (F1-F14).
// Each test rebuilds the fuzzer's input by hand (values from the harness's
// MPTRACK_FUZZ_TRACE=1 output; the raw crash inputs are in fuzz/corpus/) and
// asserts the documented behaviour. Every finding is fixed and its test
// runs; F11 (duplicates) is in validation_trackers_test.cpp.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

#include <Eigen/Cholesky>

#include "mptrack/frontend/front_end.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"
#include "frontend_test_signals.h"

using mptrack::Status;

namespace {

struct FuzzIggmCaps {  // the caps of fuzz/fuzz_iggm.cpp
  static constexpr std::size_t kMaxTargets = 6;
  static constexpr std::size_t kMaxMeasurements = 16;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 1;
};

struct FuzzRadarCaps {  // the caps of fuzz/fuzz_frontend.cpp
  static constexpr std::size_t kNumTx = 1;
  static constexpr std::size_t kNumRx = 2;
  static constexpr std::size_t kNumSamples = 16;
  static constexpr std::size_t kRangeFftSize = 16;
  static constexpr std::size_t kNumRangeBins = 8;
  static constexpr std::size_t kNumChirps = 4;
  static constexpr std::size_t kNumAngleBins = 4;
  static constexpr std::size_t kMaxDetections = 8;
};

mptrack::Measurement<float> meas(float r, float az, float amp, float dop = 0.0f) {
  mptrack::Measurement<float> m;
  m.range_m = r;
  m.azimuth_rad = az;
  m.amplitude = amp;
  m.doppler_mps = dop;
  return m;
}

template <class T>
bool llt_ok(const Eigen::Matrix<T, 4, 4>& P) {
  Eigen::LLT<Eigen::Matrix<T, 4, 4>> llt(P);
  return llt.info() == Eigen::Success;
}

}  // namespace

TEST_CASE("F6 (fixed): chirp_samples maps NaN and huge products to 0 instead of an undefined cast") {
  mptrack::frontend::FrontEndParams p;
  p.chirp_duration_s = std::numeric_limits<double>::quiet_NaN();
  CHECK(mptrack::frontend::chirp_samples(p) == 0);
  p.chirp_duration_s = 1e30;  // fuzz input: 1.088e46 samples
  CHECK(mptrack::frontend::chirp_samples(p) == 0);
  p.chirp_duration_s = 3.6e-6;  // the default still gives round(3.6e-6 * 32e6) = 115
  CHECK(mptrack::frontend::chirp_samples(p) == 115);
  // and init() reports the unusable chirp as a bad parameter
  static mptrack::frontend::FrontEnd<mptrack::frontend::SmallDopplerRadarCaps> fe;
  p.chirp_duration_s = 1e30;
  CHECK(fe.init(p) == Status::kInvalidArgument);
  CHECK_FALSE(fe.initialized());
}

TEST_CASE("F1: a 2000 s scan gap drops the GNN track (max-gap rule) instead of a singular covariance") {
  // Fuzz: time jump of ~1000 s (fuzz_common.h next_time_us, long-gap mode).
  // cv_predict added q dt^4/4 ~ 4e12 m^2 and P(x, vx) ~ 1e17: the float
  // matrix was singular to working precision. Fix: the max-gap rule of
  // ScanClock (GnnParams::max_gap_s = 60 s): the track is dropped and
  // counted, and the scan starts a new run.
  auto trk = std::make_unique<mptrack::GnnTracker<float, mptrack::SmallBoardCaps>>();
  mptrack::GnnParams<float> p;
  p.report_tentative = true;
  REQUIRE(trk->init(p) == Status::kOk);
  mptrack::GnnTracker<float, mptrack::SmallBoardCaps>::ScanType s;
  s.time_us = 1000000;
  REQUIRE(s.measurements.push_back(meas(50.0f, 0.3f, 10.0f)) == Status::kOk);
  REQUIRE(trk->step(s) == Status::kOk);
  s.time_us += 2000000000u;  // + 2000 s
  REQUIRE(trk->step(s) == Status::kOk);
  CHECK(trk->counters().gap_resets == 1);
  CHECK(trk->counters().tracks_deleted == 1);
  REQUIRE(trk->outputs()[0].tracks.size() == 1);  // the new tentative track
  CHECK(trk->outputs()[0].tracks[0].id == 2);
  CHECK(llt_ok(trk->outputs()[0].tracks[0].covariance));
  s.time_us += 100000u;  // the new run goes on normally
  REQUIRE(trk->step(s) == Status::kOk);
  REQUIRE(trk->outputs()[0].tracks.size() == 1);
  CHECK(trk->outputs()[0].tracks[0].id == 2);
  CHECK(llt_ok(trk->outputs()[0].tracks[0].covariance));
}

TEST_CASE("F8: GM-CPHD (known uniform clutter) keeps finite weights across a 23.8 s scan gap") {
  // Fuzz (fuzz_iggm, crash-66d0e897): the second scan with a gated
  // measurement after a 23.8 s gap makes a component weight +Inf;
  // extract() then casts Inf to size_t (UBSan: phd_filter.h:302).
  // Cause: the amplitude 1e6 measurement has ln kappa(z) ~ -1e12 under the
  // known clutter scale, so ln R'_z ~ 1e12 and the CPHD factors cancel to
  // nothing in float. Fix: ln R'_z capped at 200 (phd_filter.h,
  // cphd_factors). The amplitude ceiling (F4) would reject 1e6 by default,
  // so it is raised here to reach the cause.
  using Filter = mptrack::GmCphdFilter<float, FuzzIggmCaps>;
  auto f = std::make_unique<Filter>();
  mptrack::RfsFilterParams<float> p;
  p.clutter_mode = mptrack::ClutterMode::kKnownUniform;
  p.amplitude.max_amplitude = 1e6f;
  REQUIRE(f->init(p) == Status::kOk);
  Filter::ScanType s;
  s.time_us = 1000076000u;
  REQUIRE(s.measurements.push_back(meas(-1.0f, 0.0f, 3.0f)) == Status::kOk);
  CHECK(f->step(s) == Status::kOk);
  s.time_us = 1000095000u;
  s.measurements.clear();
  CHECK(f->step(s) == Status::kOk);
  s.time_us = 1023863000u;
  REQUIRE(s.measurements.push_back(meas(72.7489014f, 1197.87598f, 12.75f, 37.5f)) == Status::kOk);
  REQUIRE(s.measurements.push_back(meas(648.844116f, 654.117676f, 0.0f)) == Status::kOk);
  REQUIRE(s.measurements.push_back(meas(5.60519386e-45f, -6312.75f, 1000000.0f, 4.8e30f)) ==
          Status::kOk);
  REQUIRE(s.measurements.push_back(meas(-127.058777f, -127.058777f, 5.70000029f, 171.0f)) ==
          Status::kOk);
  CHECK(f->step(s) == Status::kPartial);  // the zero amplitude is invalid
  float total = 0.0f;
  for (const auto& c : f->components()) {
    CHECK(mptrack::is_finite(c.weight));
    total += c.weight;
  }
  // the weights still sum to the mean cardinality (they did not before:
  // 0.06 against 3.0 with an amplitude of 9999)
  CHECK(total == doctest::Approx(static_cast<double>(f->expected_targets())).epsilon(1e-3));
  REQUIRE(f->outputs()[0].tracks.size() == 3);
  for (const auto& t : f->outputs()[0].tracks) CHECK(mptrack::is_finite(t.state(0)));
}

TEST_CASE("F4: a finite but huge amplitude (3.4e38) is rejected and leaves the clutter estimate finite") {
  // Fuzz (fuzz_iggm, crash-acf45904): CPHD with estimated uniform clutter;
  // one measurement of amplitude 3.4e38 passes the input check (finite,
  // above threshold) and its amplitude moments overflow: the uniform
  // clutter's expected_count and cnr become NaN for good. CBMeMBer with
  // the clutter map shows the same (crash-b0164cfb, amplitude 2.96e27).
  // Suggested fix: an amplitude ceiling in MeasurementBatch::load
  // (counted in measurements_invalid).
  using Filter = mptrack::GmCphdFilter<float, FuzzIggmCaps>;
  auto f = std::make_unique<Filter>();
  mptrack::RfsFilterParams<float> p;
  p.clutter_mode = mptrack::ClutterMode::kEstimatedUniform;
  REQUIRE(f->init(p) == Status::kOk);
  Filter::ScanType s;
  s.time_us = 1000005000u;
  REQUIRE(s.measurements.push_back(meas(0.0f, 0.0f, 3.4e38f)) == Status::kOk);
  const Status st = f->step(s);
  CHECK(st == Status::kPartial);
  CHECK(f->counters().measurements_invalid == 1);
  for (const auto& c : f->outputs()[0].clutter) {
    CHECK(mptrack::is_finite(c.expected_count));
    CHECK(mptrack::is_finite(c.cnr));
  }
}

TEST_CASE("F5/F9: MF-BP init rejects params whose clutter seed grid or threshold overflow") {
  // Fuzz (fuzz_params, crash-02d87a06 and crash-0f9926f4): validate()
  // accepted any finite positive region.range_max_m / clutter_cell_range_m /
  // clutter_seed_factor and a region of ~zero volume, and spawn_components()
  // then casts span / cell = 1.7e35 (mfbp_tracker.h:1090) or an Inf seed
  // threshold (mfbp_tracker.h:1107) to size_t: undefined behaviour.
  mptrack::MfbpParams<float> p;
  p.clutter_cell_range_m = 1e-30f;
  CHECK(p.validate() == Status::kInvalidArgument);
  p = mptrack::MfbpParams<float>{};
  p.clutter_seed_factor = 3e38f;
  CHECK(p.validate() == Status::kInvalidArgument);
  p = mptrack::MfbpParams<float>{};
  p.region.azimuth_min_rad = 0.0f;  // crash-0f9926f4: a region of ~zero volume
  p.region.azimuth_max_rad = 1e-40f;
  CHECK(p.validate() == Status::kInvalidArgument);
  // F12 follow-ups (seeds f12-mfbp-*): the uniform clutter count became NaN
  p = mptrack::MfbpParams<float>{};
  p.dirichlet_kappa = 3.4e38f;
  CHECK(p.validate() == Status::kInvalidArgument);
  // A rate that small (or 0: a scene without uniform clutter) is now valid: every use goes
  // through the uniform_rate_floor_per_scan floor (effective_uniform_rate), which itself
  // must stay >= 1e-6.
  p = mptrack::MfbpParams<float>{};
  p.uniform_rate_per_scan = 2.4e-41f;
  CHECK(p.validate() == Status::kOk);
  CHECK(mptrack::effective_uniform_rate(p.uniform_rate_per_scan, p) == p.uniform_rate_floor_per_scan);
  p.uniform_rate_floor_per_scan = 2.4e-41f;
  CHECK(p.validate() == Status::kInvalidArgument);
  CHECK(mptrack::MfbpParams<float>{}.validate() == Status::kOk);  // defaults pass
}

TEST_CASE("F2: a float cube with samples beyond max_abs_sample is refused and counted") {
  // Fuzz (fuzz_frontend, crash-b0c832fc): float samples around 1e35 are
  // finite (so passed the NaN/Inf check) but the power map overflowed and
  // a detection got amplitude +Inf. Fix: FrontEndParams::max_abs_sample
  // (default 1e6): the frame is refused as kInvalidInput.
  using Caps = mptrack::frontend::SmallDopplerRadarCaps;
  static mptrack::frontend::FrontEnd<Caps> fe;
  static mptrack::frontend::RadarCube<Caps> cube;
  static mptrack::Scan<float, 16> scan;
  mptrack::frontend::FrontEndParams p;
  p.chirp_duration_s = 1e-6;
  p.chirp_repetition_s = 100e-6;
  p.max_range_m = 150.0;
  p.cfar.guard_cells = 1;
  p.cfar.training_cells = 4;
  p.max_detections = 16;
  REQUIRE(fe.init(p) == Status::kOk);
  for (std::size_t i = 0; i < cube.iq.size(); ++i) cube.iq[i] = (i % 7u == 0u) ? 1e35f : 0.0f;
  CHECK(fe.process(cube, scan) == Status::kInvalidInput);
  CHECK(scan.measurements.empty());
  CHECK(fe.counters().frames_over_ceiling == 1);
  CHECK(fe.counters().frames_rejected == 1);
  // a strong target just under the ceiling is processed, with finite amplitudes
  cube.iq.fill(0.0f);
  mptrack::test::SynthTarget t;
  t.range_m = 60.0;
  t.amplitude = 4e5;  // peak |sample| ~4e5 + noise, < 1e6
  mptrack::test::synthesize<Caps>(p, &t, 1, 1e6, 3, cube);
  const Status s = fe.process(cube, scan);
  CHECK((s == Status::kOk || s == Status::kCapacityExceeded));
  CHECK_FALSE(scan.measurements.empty());
  CHECK(fe.counters().frames_over_ceiling == 1);
  for (const auto& m : scan.measurements) CHECK(mptrack::is_finite(m.amplitude));
}

TEST_CASE("F3: a detection whose amplitude is not finite is dropped, counted and flagged kPartial") {
  // Fuzz (fuzz_frontend, seed fuzz/corpus/frontend/f3-amplitude-inf-noise-floor):
  // tiny samples (~1e-25) with exact-zero CFAR training cells put the
  // noise estimate at min_noise_power = 1e-30, and sqrt(P / 1e-30)
  // overflowed to +Inf. The cube below is that seed decoded the way
  // fuzz_frontend.cpp does (float mode, bytes tiled over the cube, finite
  // values beyond 1e6 scaled by 1e-32).
  using Caps = FuzzRadarCaps;
  static const std::uint8_t kSeed[] = {
      0x16, 0x00, 0x37, 0xfb, 0x02, 0x25, 0x27, 0x2d, 0x00, 0xeb, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96,
      0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96,
      0x00, 0x00, 0x00, 0x00, 0x56, 0x1c, 0x09, 0x9d, 0xc7, 0xa0, 0x96, 0x96, 0x96, 0x96, 0x96,
      0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x96, 0x3b, 0x96, 0x96, 0x96, 0x96, 0x96,
      0x96, 0x96, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x2a, 0x9a, 0x9a, 0x99, 0x0d, 0x99};
  static mptrack::frontend::FrontEnd<Caps> fe;
  static mptrack::frontend::RadarCube<Caps> cube;
  static mptrack::Scan<float, 6> scan;
  namespace fe_ns = mptrack::frontend;
  fe_ns::FrontEndParams p;
  p.chirp_duration_s = 0.25e-6;
  p.max_range_m = 40.0;
  p.max_detections = 8;
  const std::uint8_t c0 = kSeed[0];
  const std::uint8_t c1 = kSeed[1];
  p.cfar.type = static_cast<fe_ns::CfarType>(c0 % 4u);
  p.cfar.edge = static_cast<fe_ns::CfarEdge>((c0 >> 2) % 3u);
  p.cfar.guard_cells = (c0 >> 4) & 1u;
  p.cfar.training_cells = 1u + ((c0 >> 5) & 1u);
  p.cfar.pfa = (c1 & 1u) != 0 ? 0.3 : 1e-3;
  p.remove_dc = (c1 & 2u) != 0;
  p.range_window = static_cast<fe_ns::WindowType>((c1 >> 2) % 4u);
  p.doppler_window = static_cast<fe_ns::WindowType>((c1 >> 4) % 4u);
  p.angle_window = static_cast<fe_ns::WindowType>((c1 >> 6) % 4u);
  REQUIRE(fe.init(p) == Status::kOk);
  REQUIRE((kSeed[2] & 1u) == 1u);  // float mode
  const std::size_t avail = sizeof(kSeed) - 3;
  const std::uint8_t* bytes = kSeed + 3;
  for (std::size_t i = 0; i < cube.iq.size(); ++i) {
    const std::size_t k = (4 * i) % (avail - 3);
    // The seed's bytes are little-endian floats (fuzz_frontend.cpp), also
    // on big-endian targets: assemble the bits, then reinterpret.
    const std::uint8_t* b = bytes + k;
    const std::uint32_t bits = static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
                               (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
    float f;
    std::memcpy(&f, &bits, 4);
    if (mptrack::is_finite(f) && (f > 1e6f || f < -1e6f)) f *= 1e-32f;
    cube.iq[i] = f;
  }
  const Status s = fe.process(cube, scan);
  CHECK(s == Status::kPartial);
  CHECK(fe.counters().detections_nonfinite == 1);
  CHECK(fe.counters().frames == 1);
  CHECK(fe.counters().detections == scan.measurements.size());
  for (const auto& m : scan.measurements) CHECK(mptrack::is_finite(m.amplitude));
}

TEST_CASE("F12: GnnParams rejects standard deviations whose square overflows float") {
  // Fuzz (fuzz_params, crash-e2803da3): init_velocity_std_mps = 3.4e38 is
  // accepted (check_positive has no upper bound); the first track's
  // velocity variance is +Inf and reported as such.
  mptrack::GnnParams<float> p;
  p.init_velocity_std_mps = 3.4e38f;
  CHECK(p.validate() == Status::kInvalidArgument);
  p = mptrack::GnnParams<float>{};
  p.noise.range_std_m = 1e-40f;  // seed f12-*: a singular position covariance
  CHECK(p.validate() == Status::kInvalidArgument);
  p = mptrack::GnnParams<float>{};
  p.region.range_max_m = 3.4e38f;  // (r sigma_az)^2 overflows
  CHECK(p.validate() == Status::kInvalidArgument);
  p = mptrack::GnnParams<float>{};
  p.init_velocity_std_mps = 1e-40f;  // seed f12-gnn-init-velocity-std-denormal: variance 0
  CHECK(p.validate() == Status::kInvalidArgument);
  CHECK(mptrack::GnnParams<float>{}.validate() == Status::kOk);  // the defaults still pass
}

TEST_CASE("F12: a GNN track born near range 0 has a positive definite covariance") {
  // Fuzz (fuzz_params, seed f12-gnn-tiny-region-rank-one-cov): a region
  // with max_range_m = 1.8e-38 m; the measurement's cross-range variance
  // (r sigma_az)^2 underflowed to 0 and the initial position covariance
  // was rank one. polar_initiate floors the cross-range std at 1e-3 x the
  // range std.
  mptrack::model::CvState<float> x;
  mptrack::model::CvCovariance<float> P;
  for (const float r : {0.0f, 1e-20f, 1e-3f}) {
    mptrack::gnn::polar_initiate(r, 0.7f, 0.2f, 0.01f, 10.0f, x, P);
    CHECK(llt_ok(P));
    const float det = P(0, 0) * P(2, 2) - P(0, 2) * P(2, 0);
    CHECK(det > 0.0f);
  }
  // far from 0 the floor does not bind: cross-range variance (r sigma_az)^2
  mptrack::gnn::polar_initiate(100.0f, 0.0f, 0.2f, 0.01f, 10.0f, x, P);
  CHECK(P(2, 2) == doctest::Approx(1.0));
  CHECK(P(0, 0) == doctest::Approx(0.04));
}

TEST_CASE("F12: RfsFilterParams rejects a polar azimuth std whose derived clutter count overflows") {
  // Fuzz (fuzz_params, seed f13-*): CPHD, polar noise.azimuth_std_rad = 5.5e11.
  mptrack::RfsFilterParams<float> p;
  p.space = mptrack::MeasurementSpace::kPolar;
  p.region.range_min_m = 10.0f;
  p.region.range_max_m = 1000.0f;
  p.region.azimuth_min_rad = -1.0f;
  p.region.azimuth_max_rad = 1.0f;
  REQUIRE(p.validate() == Status::kOk);
  p.noise.azimuth_std_rad = 5.5e11f;
  CHECK(p.validate() == Status::kInvalidArgument);
  p.noise.azimuth_std_rad = 0.0104720f;
  p.noise.range_std_m = 1e-40f;
  CHECK(p.validate() == Status::kInvalidArgument);
  p.noise.range_std_m = 10.0f;
  p.birth_velocity_std_mps = 3.4e38f;
  CHECK(p.validate() == Status::kInvalidArgument);
}

TEST_CASE("F10: RfsFilterParams rejects a region whose volume overflows, and a negative polar range") {
  // Fuzz (fuzz_params): polar space with the then default range bound
  // -1000 and a range maximum of 3.4e38 was accepted; the region volume overflowed
  // and the clutter intensity and expected_count became NaN.
  mptrack::RfsFilterParams<float> p;
  p.space = mptrack::MeasurementSpace::kPolar;
  p.region.azimuth_min_rad = -1.0f;
  p.region.azimuth_max_rad = 1.0f;
  p.region.range_min_m = 0.0f;
  p.region.range_max_m = 1000.0f;
  REQUIRE(p.validate() == Status::kOk);
  p.region.range_min_m = -1000.0f;  // a negative range bound
  CHECK(p.validate() == Status::kInvalidArgument);
  p.region.range_min_m = 0.0f;
  p.region.range_max_m = 3.4e38f;  // volume 6.8e38 = +Inf in float
  CHECK(p.validate() == Status::kInvalidArgument);
  p.region.range_max_m = 1000.0f;
  p.region.azimuth_max_rad = -1.0f + 1e-12f;  // rounds to -1: empty region
  CHECK(p.validate() == Status::kInvalidArgument);
  // Cartesian: both axes in metres, a huge but finite volume is refused too
  mptrack::RfsFilterParams<float> c;
  REQUIRE(c.validate() == Status::kOk);
  c.cartesian_region.x_min_m = -2e19f;
  c.cartesian_region.x_max_m = 2e19f;
  c.cartesian_region.y_min_m = -2e19f;
  c.cartesian_region.y_max_m = 2e19f;
  CHECK(c.validate() == Status::kInvalidArgument);
}

namespace {
struct FuzzMfbpCaps {  // the caps of fuzz/fuzz_mfbp.cpp
  static constexpr std::size_t kMaxTargets = 4;
  static constexpr std::size_t kMaxMeasurements = 12;
  static constexpr std::size_t kMaxClutterComponents = 2;
  static constexpr std::size_t kMaxWindow = 7;
};
}  // namespace

TEST_CASE("F13: MF-BP tracks born from scans 1 ms apart keep an SPD covariance") {
  // fuzz_mfbp (mfbp-crash-84c83c48): the same detection at 30 km in scans
  // 1 ms apart starts a track whose two-point velocity std is ~1e5 m/s;
  // a few updates later the float covariance had position-velocity
  // correlation 1 and failed LLT. Scans 0-8 of the trace, every window.
  struct In {
    std::uint64_t t_us;
    float r, az, amp;
    bool present;
  };
  const In trace[] = {{1000106000u, 25764.707f, 0.518465519f, 5.25f, true},
                      {1000212000u, 29964.707f, 0.522828817f, 5.25f, true},
                      {1000213000u, 0.0f, 0.0f, 0.0f, false},
                      {1000214000u, 25764.707f, 0.198146209f, 1.35000002f, true},
                      {1000274000u, 30000.0f, 0.610865235f, 3.0f, true},
                      {1000275000u, 30000.0f, 0.610865235f, 3.0f, true},
                      {1000276000u, 30000.0f, 0.610865235f, 3.0f, true},
                      {1000382000u, 34200.0f, 0.720821023f, 3.0f, true},
                      {1000509000u, 39240.0f, 0.720821023f, 3.0f, true}};
  for (const std::size_t window : {std::size_t{1}, std::size_t{3}, std::size_t{7}}) {
    for (const bool amplitude : {true, false}) {
      auto trk = std::make_unique<mptrack::MfbpTracker<float, FuzzMfbpCaps>>();
      mptrack::MfbpParams<float> p;
      p.window_length = window;
      p.slide = window == 7 ? 3 : 1;
      p.amplitude.use_amplitude = amplitude;
      REQUIRE(trk->init(p) == Status::kOk);
      std::size_t reports = 0;
      auto check_outputs = [&]() {
        for (const auto& est : trk->outputs()) {
          for (const auto& r : est.tracks) {
            ++reports;
            const Eigen::Matrix4f S = (r.covariance + r.covariance.transpose()) * 0.5f;
            Eigen::LLT<Eigen::Matrix4f> llt(S);
            CHECK(llt.info() == Eigen::Success);
            CHECK(r.covariance.allFinite());
          }
        }
      };
      mptrack::MfbpTracker<float, FuzzMfbpCaps>::ScanType scan;
      for (const In& in : trace) {
        scan.time_us = in.t_us;
        scan.measurements.clear();
        if (in.present) REQUIRE(scan.measurements.push_back(meas(in.r, in.az, in.amp)) == Status::kOk);
        const Status s = trk->step(scan);
        CHECK((s == Status::kOk || s == Status::kPartial));
        check_outputs();
      }
      REQUIRE(trk->flush() == Status::kOk);
      check_outputs();
      CHECK(trk->counters().tracks_born >= 1u);  // the 1 ms pair did start a track
    }
  }
}

TEST_CASE("F14: MF-BP covariance stays SPD after a 28 s gap and a 4 km jump") {
  // fuzz_mfbp (mfbp-crash-1d438ff6, online filter, no amplitude, known
  // uniform clutter): a track on one repeated detection, a 28 s gap, then a
  // detection 4.2 km away 0.1 s later. The position covariance reached
  // x-y correlation 0.99998, which make_spd's Cholesky accepted and
  // Eigen's LLT did not.
  struct In {
    std::uint64_t t_us;
    float r, az;
    bool present;
  };
  const In trace[] = {{1000106000u, 25764.707f, 0.109397657f, true}, {1000107000u, 0.0f, 0.0f, false},
                      {1000135000u, 30000.0f, 0.610865235f, true},   {1000195000u, 30000.0f, 0.610865235f, true},
                      {1000221000u, 30000.0f, 0.610865235f, true},   {1028221000u, 30000.0f, 0.610865235f, true},
                      {1028327000u, 34200.0f, 0.720821023f, true}};
  auto trk = std::make_unique<mptrack::MfbpTracker<float, FuzzMfbpCaps>>();
  mptrack::MfbpParams<float> p;
  p.window_length = 1;
  p.slide = 1;
  p.amplitude.use_amplitude = false;
  p.clutter_mode = mptrack::ClutterMode::kUniformKnownRate;
  p.bp_max_iterations = 50;
  REQUIRE(trk->init(p) == Status::kOk);
  mptrack::MfbpTracker<float, FuzzMfbpCaps>::ScanType scan;
  std::size_t reports = 0;
  for (const In& in : trace) {
    scan.time_us = in.t_us;
    scan.measurements.clear();
    if (in.present) REQUIRE(scan.measurements.push_back(meas(in.r, in.az, 3.0f)) == Status::kOk);
    const Status s = trk->step(scan);
    CHECK((s == Status::kOk || s == Status::kPartial));
    for (const auto& est : trk->outputs()) {
      for (const auto& r : est.tracks) {
        ++reports;
        const Eigen::Matrix4f S = (r.covariance + r.covariance.transpose()) * 0.5f;
        Eigen::LLT<Eigen::Matrix4f> llt(S);
        CHECK(llt.info() == Eigen::Success);
      }
    }
  }
  CHECK(reports >= 1u);
}
