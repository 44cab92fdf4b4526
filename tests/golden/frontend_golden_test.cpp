// Bit-exact golden vectors for every front-end stage.
//
// Inputs come from integer patterns or the deterministic synthesizer
// (xorshift + dmath), so they are bit-identical on every target; the
// committed files pin the outputs. Passing on x86-64 and, under qemu, on
// aarch64 and armhf proves the stages are bit-exact across targets.
// Regenerate: MPTRACK_GOLDEN_REGENERATE=1 ctest -R frontend_golden
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../unit/frontend_test_signals.h"
#include "golden.h"
#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/front_end.h"

namespace fe = mptrack::frontend;
using mptrack::Status;
using mptrack::test::GoldenFile;
using Seed = fe::Seed004RadarCaps;
using Small = fe::SmallDopplerRadarCaps;

namespace {

std::string lbl(const char* base, std::size_t i) { return std::string(base) + std::to_string(i); }

// The seed 004 scene used by the range/angle/pipeline goldens.
void seed_scene(const fe::FrontEndParams& p, fe::RadarCube<Seed>& cube) {
  mptrack::test::SynthTarget t[3];
  t[0].range_m = 28.9;
  t[0].bearing_rad = 0.785;
  t[0].amplitude = 0.8;
  t[1].range_m = 47.2;
  t[1].bearing_rad = -0.31;
  t[1].amplitude = 0.5;
  t[1].phase_rad = 2.0;
  t[2].range_m = 74.0;
  t[2].bearing_rad = 0.05;
  t[2].amplitude = 0.35;
  t[2].phase_rad = -1.0;
  mptrack::test::synthesize<Seed>(p, t, 3, 1.0, 2024, cube);
  cube.time_us = 100000;
}

void doppler_scene(const fe::FrontEndParams& p, fe::RadarCube<Small>& cube) {
  mptrack::test::SynthTarget t[2];
  t[0].range_m = 40.0;
  t[0].bearing_rad = 0.4;
  t[0].radial_mps = 12.5;
  t[0].amplitude = 0.4;
  t[1].range_m = 90.0;
  t[1].bearing_rad = -0.2;
  t[1].radial_mps = -30.0;
  t[1].amplitude = 0.3;
  mptrack::test::synthesize<Small>(p, t, 2, 0.05, 77, cube);
  cube.time_us = 5;
}

fe::FrontEndParams seed_params() {
  fe::FrontEndParams p;
  p.range_window = fe::WindowType::kHamming;
  p.angle_window = fe::WindowType::kHann;
  return p;
}

}  // namespace

TEST_CASE("frontend golden: FFT outputs (64 and 1024 points) and twiddles") {
  GoldenFile g("frontend_fft");
  auto f64 = std::make_unique<mptrack::dsp::Fft<64>>();
  auto f1k = std::make_unique<mptrack::dsp::Fft<1024>>();
  REQUIRE(f64->init() == Status::kOk);
  REQUIRE(f1k->init() == Status::kOk);
  for (std::size_t j = 0; j < 512; j += 37) {
    g.add(lbl("tw1024_re_", j), f1k->twiddle_re(512, j));
    g.add(lbl("tw1024_im_", j), f1k->twiddle_im(512, j));
  }
  mptrack::test::DetRng rng(1);
  std::array<float, 64> re{};
  std::array<float, 64> im{};
  for (std::size_t i = 0; i < 64; ++i) {
    re[i] = static_cast<float>(static_cast<std::int32_t>(rng.next_u64() >> 40) - 8388608) * 0x1p-23f;
    im[i] = static_cast<float>(static_cast<std::int32_t>(rng.next_u64() >> 40) - 8388608) * 0x1p-23f;
  }
  f64->forward(re.data(), im.data());
  for (std::size_t k = 0; k < 64; ++k) {
    g.add(lbl("fft64_re_", k), re[k]);
    g.add(lbl("fft64_im_", k), im[k]);
  }
  std::vector<float> br(1024);
  std::vector<float> bi(1024);
  for (std::size_t i = 0; i < 1024; ++i) {
    br[i] = static_cast<float>(static_cast<std::int32_t>(rng.next_u64() >> 40) - 8388608) * 0x1p-23f;
    bi[i] = static_cast<float>(static_cast<std::int32_t>(rng.next_u64() >> 40) - 8388608) * 0x1p-23f;
  }
  f1k->forward(br.data(), bi.data());
  f1k->inverse(br.data(), bi.data());
  for (std::size_t k = 0; k < 1024; k += 13) {
    g.add(lbl("fft1024_rt_re_", k), br[k]);
    g.add(lbl("fft1024_rt_im_", k), bi[k]);
  }
  CHECK(g.matches());
}

TEST_CASE("frontend golden: windows and range matched filter profiles") {
  GoldenFile g("frontend_range");
  for (fe::WindowType w : {fe::WindowType::kHann, fe::WindowType::kHamming,
                           fe::WindowType::kBlackman}) {
    std::array<float, 9> tab{};
    fe::fill_window(w, tab.data(), 9);
    for (std::size_t i = 0; i < 9; ++i) {
      g.add(lbl("win", static_cast<std::size_t>(w) * 100 + i), tab[i]);
    }
  }
  const fe::FrontEndParams p = seed_params();
  auto rmf = std::make_unique<fe::RangeMatchedFilter<Seed>>();
  auto cube = std::make_unique<fe::RadarCube<Seed>>();
  REQUIRE(rmf->init(p) == Status::kOk);
  seed_scene(p, *cube);
  g.add("cube_iq_0", cube->iq[0]);
  g.add("cube_iq_1001", cube->iq[1001]);
  g.add("coherent_gain", rmf->coherent_gain());
  REQUIRE(rmf->process(*cube) == Status::kOk);
  for (std::size_t v : {std::size_t{0}, std::size_t{8}}) {
    for (std::size_t r = 0; r < Seed::kNumRangeBins; ++r) {
      g.add(lbl("rp_re_", v * 1000 + r), rmf->profile_re(0, v)[r]);
      g.add(lbl("rp_im_", v * 1000 + r), rmf->profile_im(0, v)[r]);
    }
  }
  CHECK(g.matches());
}

TEST_CASE("frontend golden: Doppler snapshots and angle power map") {
  GoldenFile g("frontend_doppler_angle");
  const fe::FrontEndParams p = mptrack::test::small_doppler_params();
  struct S {
    fe::RangeMatchedFilter<Small> rmf;
    fe::DopplerProcessor<Small> dop;
    fe::AngleProcessor<Small> ang;
    fe::RadarCube<Small> cube;
  };
  auto s = std::make_unique<S>();
  REQUIRE(s->rmf.init(p) == Status::kOk);
  REQUIRE(s->dop.init(p) == Status::kOk);
  REQUIRE(s->ang.init(p) == Status::kOk);
  doppler_scene(p, s->cube);
  REQUIRE(s->rmf.process(s->cube) == Status::kOk);
  REQUIRE(s->dop.process(s->rmf) == Status::kOk);
  REQUIRE(s->ang.process(s->dop) == Status::kOk);
  for (std::size_t g_bin = 0; g_bin < Small::kNumRangeBins; g_bin += 3) {
    for (std::size_t d = 0; d < Small::kNumChirps; d += 5) {
      g.add(lbl("snap_re_", g_bin * 100 + d), s->dop.snapshot_re(g_bin, d)[3]);
      g.add(lbl("snap_im_", g_bin * 100 + d), s->dop.snapshot_im(g_bin, d)[3]);
    }
  }
  for (std::size_t i = 0; i < fe::AngleProcessor<Small>::kMapSize; i += 97) {
    g.add(lbl("map_", i), s->ang.power_map()[i]);
  }
  const fe::AngleEstimate e = s->ang.refine(s->dop, 9, 5, 20);
  g.add("refine_u", e.u);
  g.add("refine_power", e.power);
  CHECK(g.matches());
}

TEST_CASE("frontend golden: CFAR thresholds and noise estimates") {
  GoldenFile g("frontend_cfar");
  mptrack::test::DetRng rng(5);
  std::array<float, 200> line{};
  for (float& x : line) x = static_cast<float>(-mptrack::dmath::dlog(rng.uniform()));
  line[100] = 40.0f;
  for (fe::CfarType t : {fe::CfarType::kCellAveraging, fe::CfarType::kGreatestOf,
                         fe::CfarType::kSmallestOf, fe::CfarType::kOrderedStatistic}) {
    fe::CfarParams cp;
    cp.type = t;
    cp.pfa = 1e-5;
    fe::Cfar cfar;
    REQUIRE(cfar.init(cp) == Status::kOk);
    const std::size_t k = static_cast<std::size_t>(t);
    g.add(lbl("alpha_", k), cfar.alpha());
    for (std::size_t i : {std::size_t{0}, std::size_t{3}, std::size_t{100}, std::size_t{199}}) {
      const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
      g.add(lbl("noise_", k * 1000 + i), r.noise);
      g.add(lbl("det_", k * 1000 + i), r.detected ? 1 : 0);
    }
  }
  CHECK(g.matches());
}

TEST_CASE("frontend golden: end-to-end measurements (seed 004 and Doppler configurations)") {
  GoldenFile g("frontend_pipeline");
  {
    struct R {
      fe::FrontEnd<Seed> fe;
      fe::RadarCube<Seed> cube;
      mptrack::Scan<float, 64> scan;
    };
    auto r = std::make_unique<R>();
    const fe::FrontEndParams p = seed_params();
    REQUIRE(r->fe.init(p) == Status::kOk);
    seed_scene(p, r->cube);
    REQUIRE(r->fe.process(r->cube, r->scan) == Status::kOk);
    g.add("seed_count", static_cast<std::uint64_t>(r->scan.measurements.size()));
    for (std::size_t i = 0; i < r->scan.measurements.size(); ++i) {
      const mptrack::Measurement<float>& m = r->scan.measurements[i];
      g.add(lbl("seed_range_", i), m.range_m);
      g.add(lbl("seed_az_", i), m.azimuth_rad);
      g.add(lbl("seed_amp_", i), m.amplitude);
    }
  }
  {
    struct R {
      fe::FrontEnd<Small> fe;
      fe::RadarCube<Small> cube;
      mptrack::Scan<float, 16> scan;
    };
    auto r = std::make_unique<R>();
    fe::FrontEndParams p = mptrack::test::small_doppler_params();
    p.doppler_window = fe::WindowType::kHann;
    p.cfar.type = fe::CfarType::kOrderedStatistic;
    REQUIRE(r->fe.init(p) == Status::kOk);
    doppler_scene(p, r->cube);
    REQUIRE(r->fe.process(r->cube, r->scan) == Status::kOk);
    g.add("dop_count", static_cast<std::uint64_t>(r->scan.measurements.size()));
    for (std::size_t i = 0; i < r->scan.measurements.size(); ++i) {
      const mptrack::Measurement<float>& m = r->scan.measurements[i];
      g.add(lbl("dop_range_", i), m.range_m);
      g.add(lbl("dop_az_", i), m.azimuth_rad);
      g.add(lbl("dop_amp_", i), m.amplitude);
      g.add(lbl("dop_vel_", i), m.doppler_mps);
    }
  }
  CHECK(g.matches());
}
