// Angle stage: FFT beamformer and steering-vector refinement.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>

#include "alloc_guard.h"
#include "frontend_test_signals.h"
#include "mptrack/frontend/angle_processor.h"

namespace fe = mptrack::frontend;
using Caps = fe::SmallDopplerRadarCaps;  // 8 virtual channels, 32 angle bins, 16 chirps
using mptrack::Status;

namespace {

struct Stages {
  fe::RangeMatchedFilter<Caps> rmf;
  fe::DopplerProcessor<Caps> dop;
  fe::AngleProcessor<Caps> ang;
  fe::RadarCube<Caps> cube;

  Status init(const fe::FrontEndParams& p) {
    MPTRACK_TRY(rmf.init(p));
    MPTRACK_TRY(dop.init(p));
    return ang.init(p);
  }
  Status run() {
    MPTRACK_TRY(rmf.process(cube));
    MPTRACK_TRY(dop.process(rmf));
    return ang.process(dop);
  }
};

}  // namespace

TEST_CASE("angle: a plane wave at u = 2h/N_A peaks in bin h + N_A/2 with power (A L N_c N_V)^2") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->init(p) == Status::kOk);
  mptrack::test::SynthTarget t;
  t.range_m = 6.0 * fe::range_bin_m(p);
  t.bearing_rad = std::asin(2.0 * 5.0 / 32.0);  // u = 0.3125, h = 5 -> a = 21
  t.amplitude = 0.1;
  mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, s->cube);
  REQUIRE(s->run() == Status::kOk);
  const double peak = 0.1 * 32.0 * 16.0 * 8.0;
  CHECK(static_cast<double>(s->ang.power(6, 8, 21)) == doctest::Approx(peak * peak).epsilon(1e-5));
  // 8 elements zero-padded to 32: Dirichlet kernel |sin(pi 8 k/32) / sin(pi k/32)|^2 per
  // unit element amplitude; zeros at k = 4, 8, ..., and k = 2 gives 1/sin^2(pi/16).
  for (std::size_t a = 1; a < 32; a += 4) {
    if (a != 21) CHECK(static_cast<double>(s->ang.power(6, 8, a)) < 1e-8 * peak * peak);
  }
  const double unit = peak / 8.0;
  const double k2 = 1.0 / std::pow(std::sin(M_PI / 16.0), 2.0);
  CHECK(static_cast<double>(s->ang.power(6, 8, 23)) == doctest::Approx(unit * unit * k2).epsilon(1e-4));
  for (std::size_t a = 0; a < 32; ++a) CHECK(s->ang.power(6, 8, a) <= s->ang.power(6, 8, 21));
  CHECK(s->ang.bin_u(21) == doctest::Approx(0.3125));
}

TEST_CASE("angle: total processing gain on white noise is L * N_c * N_V (rect windows)") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->init(p) == Status::kOk);
  double mean_power = 0.0;
  std::size_t n = 0;
  for (std::uint64_t frame = 0; frame < 4; ++frame) {
    mptrack::test::synthesize<Caps>(p, nullptr, 0, 2.0, 40 + frame, s->cube);
    REQUIRE(s->run() == Status::kOk);
    for (std::size_t i = 0; i < fe::AngleProcessor<Caps>::kMapSize; ++i) {
      mean_power += static_cast<double>(s->ang.power_map()[i]);
      ++n;
    }
  }
  mean_power /= static_cast<double>(n);
  // Noise power per map cell = sigma^2 L N_c N_V; a unit echo's peak power is
  // (L N_c N_V)^2, so the SNR gain is L N_c N_V = 32 * 16 * 8 = 4096 (36.1 dB).
  CHECK(mean_power / 2.0 == doctest::Approx(32.0 * 16.0 * 8.0).epsilon(0.03));
}

TEST_CASE("angle: steering-vector refinement recovers an off-grid direction to 2e-4 in sin(theta)") {
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->init(p) == Status::kOk);
  for (double u_true : {0.3, -0.517, 0.02, 0.81}) {
    mptrack::test::SynthTarget t;
    t.range_m = 11.0 * fe::range_bin_m(p);
    t.bearing_rad = std::asin(u_true);
    mptrack::test::synthesize<Caps>(p, &t, 1, 0.0, 1, s->cube);
    REQUIRE(s->run() == Status::kOk);
    std::size_t best = 0;
    for (std::size_t a = 1; a < 32; ++a) {
      if (s->ang.power(11, 8, a) > s->ang.power(11, 8, best)) best = a;
    }
    CHECK(std::fabs(s->ang.bin_u(best) - u_true) <= 1.0 / 32.0 + 1e-9);  // nearest grid point
    const fe::AngleEstimate e = s->ang.refine(s->dop, 11, 8, best);
    CHECK(std::fabs(static_cast<double>(e.u) - u_true) < 2e-4);
    // At the true direction the MF collects the full coherent gain.
    const double peak = 32.0 * 16.0 * 8.0;
    CHECK(static_cast<double>(e.power) == doctest::Approx(peak * peak).epsilon(1e-4));
  }
}

TEST_CASE("angle: refine_lanes gives every cell the bits of refine(), for 1 to 8 cells") {
  // Two targets in noise; cells over the whole map (on and off the targets,
  // every angle bin from edge to edge), batches of every size.
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  REQUIRE(s->init(p) == Status::kOk);
  mptrack::test::SynthTarget t[2];
  t[0].range_m = 11.0 * fe::range_bin_m(p);
  t[0].bearing_rad = 0.4;
  t[1].range_m = 20.0 * fe::range_bin_m(p);
  t[1].bearing_rad = -0.7;
  t[1].radial_mps = 5.0;
  mptrack::test::synthesize<Caps>(p, t, 2, 0.3, 4, s->cube);
  REQUIRE(s->run() == Status::kOk);
  std::size_t differing = 0;
  std::size_t compared = 0;
  for (std::size_t n = 1; n <= fe::AngleProcessor<Caps>::kRefineLanes; ++n) {
    std::uint16_t g[8];
    std::uint16_t d[8];
    std::uint16_t a[8];
    for (std::size_t l = 0; l < n; ++l) {
      g[l] = static_cast<std::uint16_t>((7 * l + 3 * n) % Caps::kNumRangeBins);
      d[l] = static_cast<std::uint16_t>((5 * l + n) % Caps::kNumChirps);
      a[l] = static_cast<std::uint16_t>((11 * l + 2 * n) % Caps::kNumAngleBins);
    }
    g[0] = 11;  // the targets' cells
    a[0] = 16 + 6;
    fe::AngleEstimate batch[8];
    s->ang.refine_lanes(s->dop, g, d, a, n, batch);
    for (std::size_t l = 0; l < n; ++l) {
      const fe::AngleEstimate one = s->ang.refine(s->dop, g[l], d[l], a[l]);
      const float x[2] = {batch[l].u, batch[l].power};
      const float y[2] = {one.u, one.power};
      if (std::memcmp(x, y, sizeof x) != 0) ++differing;
      ++compared;
    }
  }
  CHECK(compared == 36);
  CHECK(differing == 0);
}

TEST_CASE("angle: bins outside the configured span are flagged untested") {
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  p.max_abs_bearing_rad = std::asin(0.5);  // |u| <= 0.5 -> |h| <= 8
  auto s = std::make_unique<Stages>();
  REQUIRE(s->init(p) == Status::kOk);
  std::size_t tested = 0;
  for (std::size_t a = 0; a < 32; ++a) tested += s->ang.angle_tested(a) ? 1u : 0u;
  CHECK(tested == 17);  // h = -8..8
  CHECK_FALSE(s->ang.angle_tested(7));
  CHECK(s->ang.angle_tested(8));
  CHECK(s->ang.angle_tested(24));
  CHECK_FALSE(s->ang.angle_tested(25));
}

TEST_CASE("angle: init rejects a bad span or spacing, process and refine do not allocate") {
  fe::FrontEndParams p = mptrack::test::small_doppler_params();
  auto s = std::make_unique<Stages>();
  p.max_abs_bearing_rad = 2.0;
  CHECK(s->ang.init(p) == Status::kInvalidArgument);
  p = mptrack::test::small_doppler_params();
  p.element_spacing_wavelengths = 0.0;
  CHECK(s->ang.init(p) == Status::kInvalidArgument);
  p = mptrack::test::small_doppler_params();
  REQUIRE(s->init(p) == Status::kOk);
  mptrack::test::synthesize<Caps>(p, nullptr, 0, 1.0, 2, s->cube);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  REQUIRE(s->dop.process(s->rmf) == Status::kOk);
  mptrack::test::NoAllocScope guard;
  const Status st = s->ang.process(s->dop);
  const fe::AngleEstimate e = s->ang.refine(s->dop, 3, 4, 5);
  CHECK(guard.allocations() == 0);
  CHECK(st == Status::kOk);
  CHECK(e.power >= 0.0f);
}
