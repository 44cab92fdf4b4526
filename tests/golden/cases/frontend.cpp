// Golden cases of every front-end stage (five golden files). Inputs come
// from integer patterns or the deterministic synthesizer (xorshift + dmath),
// so they are bit-identical on every target.
#include <array>
#include <cstddef>
#include <cstdint>

#include "../../unit/frontend_test_signals.h"
#include "golden_cases.h"
#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/front_end.h"

namespace mptrack::test {

namespace fe = mptrack::frontend;
using Seed = fe::Seed004RadarCaps;
using Small = fe::SmallDopplerRadarCaps;

namespace {

Label lbl(const char* base, std::size_t i) { return Label(base) + i; }

// The seed 004 scene used by the range/angle/pipeline goldens.
void seed_scene(const fe::FrontEndParams& p, fe::RadarCube<Seed>& cube) {
  SynthTarget t[3];
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
  synthesize<Seed>(p, t, 3, 1.0, 2024, cube);
  cube.time_us = 100000;
}

void doppler_scene(const fe::FrontEndParams& p, fe::RadarCube<Small>& cube) {
  SynthTarget t[2];
  t[0].range_m = 40.0;
  t[0].bearing_rad = 0.4;
  t[0].radial_mps = 12.5;
  t[0].amplitude = 0.4;
  t[1].range_m = 90.0;
  t[1].bearing_rad = -0.2;
  t[1].radial_mps = -30.0;
  t[1].amplitude = 0.3;
  synthesize<Small>(p, t, 2, 0.05, 77, cube);
  cube.time_us = 5;
}

fe::FrontEndParams seed_params() {
  fe::FrontEndParams p;
  p.range_window = fe::WindowType::kHamming;
  p.angle_window = fe::WindowType::kHann;
  return p;
}

struct FftState {
  dsp::Fft<64> f64;
  dsp::Fft<1024> f1k;
  std::array<float, 1024> br;
  std::array<float, 1024> bi;
};
struct RangeState {
  fe::RangeMatchedFilter<Seed> rmf;
  fe::RadarCube<Seed> cube;
};
struct DopplerState {
  fe::RangeMatchedFilter<Small> rmf;
  fe::DopplerProcessor<Small> dop;
  fe::AngleProcessor<Small> ang;
  fe::RadarCube<Small> cube;
};
struct SeedPipeline {
  fe::FrontEnd<Seed> fe;
  fe::RadarCube<Seed> cube;
  Scan<float, 64> scan;
};
struct DopplerPipeline {
  fe::FrontEnd<Small> fe;
  fe::RadarCube<Small> cube;
  Scan<float, 16> scan;
};
Slot<FftState> g_fft;
Slot<RangeState> g_range;
Slot<DopplerState> g_doppler;
Slot<SeedPipeline> g_seed_pipeline;
Slot<DopplerPipeline> g_doppler_pipeline;

float unit_sample(DetRng& rng) {
  return static_cast<float>(static_cast<std::int32_t>(rng.next_u64() >> 40) - 8388608) * 0x1p-23f;
}

}  // namespace

void golden_case_frontend_fft(GoldenSink& g) {
  FftState& s = g_fft.make();
  g.require(s.f64.init() == Status::kOk, "fft64 init");
  g.require(s.f1k.init() == Status::kOk, "fft1024 init");
  for (std::size_t j = 0; j < 512; j += 37) {
    g.add(lbl("tw1024_re_", j), s.f1k.twiddle_re(512, j));
    g.add(lbl("tw1024_im_", j), s.f1k.twiddle_im(512, j));
  }
  DetRng rng(1);
  std::array<float, 64> re{};
  std::array<float, 64> im{};
  for (std::size_t i = 0; i < 64; ++i) {
    re[i] = unit_sample(rng);
    im[i] = unit_sample(rng);
  }
  s.f64.forward(re.data(), im.data());
  for (std::size_t k = 0; k < 64; ++k) {
    g.add(lbl("fft64_re_", k), re[k]);
    g.add(lbl("fft64_im_", k), im[k]);
  }
  for (std::size_t i = 0; i < 1024; ++i) {
    s.br[i] = unit_sample(rng);
    s.bi[i] = unit_sample(rng);
  }
  s.f1k.forward(s.br.data(), s.bi.data());
  s.f1k.inverse(s.br.data(), s.bi.data());
  for (std::size_t k = 0; k < 1024; k += 13) {
    g.add(lbl("fft1024_rt_re_", k), s.br[k]);
    g.add(lbl("fft1024_rt_im_", k), s.bi[k]);
  }
}

void golden_case_frontend_range(GoldenSink& g) {
  for (fe::WindowType w : {fe::WindowType::kHann, fe::WindowType::kHamming, fe::WindowType::kBlackman}) {
    std::array<float, 9> tab{};
    fe::fill_window(w, tab.data(), 9);
    for (std::size_t i = 0; i < 9; ++i) g.add(lbl("win", static_cast<std::size_t>(w) * 100 + i), tab[i]);
  }
  const fe::FrontEndParams p = seed_params();
  RangeState& s = g_range.make();
  g.require(s.rmf.init(p) == Status::kOk, "range filter init");
  seed_scene(p, s.cube);
  g.add("cube_iq_0", s.cube.iq[0]);
  g.add("cube_iq_1001", s.cube.iq[1001]);
  g.add("coherent_gain", s.rmf.coherent_gain());
  g.require(s.rmf.process(s.cube) == Status::kOk, "range filter process");
  for (std::size_t v : {std::size_t{0}, std::size_t{8}}) {
    for (std::size_t r = 0; r < Seed::kNumRangeBins; ++r) {
      g.add(lbl("rp_re_", v * 1000 + r), s.rmf.value_re(0, v, r));
      g.add(lbl("rp_im_", v * 1000 + r), s.rmf.value_im(0, v, r));
    }
  }
}

void golden_case_frontend_doppler_angle(GoldenSink& g) {
  const fe::FrontEndParams p = small_doppler_params();
  DopplerState& s = g_doppler.make();
  g.require(s.rmf.init(p) == Status::kOk, "range filter init");
  g.require(s.dop.init(p) == Status::kOk, "doppler init");
  g.require(s.ang.init(p) == Status::kOk, "angle init");
  doppler_scene(p, s.cube);
  g.require(s.rmf.process(s.cube) == Status::kOk, "range filter process");
  g.require(s.dop.process(s.rmf) == Status::kOk, "doppler process");
  g.require(s.ang.process(s.dop) == Status::kOk, "angle process");
  for (std::size_t g_bin = 0; g_bin < Small::kNumRangeBins; g_bin += 3) {
    for (std::size_t d = 0; d < Small::kNumChirps; d += 5) {
      g.add(lbl("snap_re_", g_bin * 100 + d), s.dop.snapshot_re(g_bin, d, 3));
      g.add(lbl("snap_im_", g_bin * 100 + d), s.dop.snapshot_im(g_bin, d, 3));
    }
  }
  for (std::size_t i = 0; i < fe::AngleProcessor<Small>::kMapSize; i += 97) {
    g.add(lbl("map_", i), s.ang.power_map()[i]);
  }
  const fe::AngleEstimate e = s.ang.refine(s.dop, 9, 5, 20);
  g.add("refine_u", e.u);
  g.add("refine_power", e.power);
}

void golden_case_frontend_cfar(GoldenSink& g) {
  DetRng rng(5);
  std::array<float, 200> line{};
  for (float& x : line) x = static_cast<float>(-dmath::dlog(rng.uniform()));
  line[100] = 40.0f;
  for (fe::CfarType t : {fe::CfarType::kCellAveraging, fe::CfarType::kGreatestOf, fe::CfarType::kSmallestOf,
                         fe::CfarType::kOrderedStatistic}) {
    fe::CfarParams cp;
    cp.type = t;
    cp.pfa = 1e-5;
    fe::Cfar cfar;
    g.require(cfar.init(cp) == Status::kOk, "cfar init");
    const std::size_t k = static_cast<std::size_t>(t);
    g.add(lbl("alpha_", k), cfar.alpha());
    for (std::size_t i : {std::size_t{0}, std::size_t{3}, std::size_t{100}, std::size_t{199}}) {
      const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
      g.add(lbl("noise_", k * 1000 + i), r.noise);
      g.add(lbl("det_", k * 1000 + i), r.detected ? 1 : 0);
    }
  }
}

void golden_case_frontend_pipeline(GoldenSink& g) {
  {
    SeedPipeline& r = g_seed_pipeline.make();
    const fe::FrontEndParams p = seed_params();
    g.require(r.fe.init(p) == Status::kOk, "seed front end init");
    seed_scene(p, r.cube);
    g.require(r.fe.process(r.cube, r.scan) == Status::kOk, "seed front end process");
    g.add("seed_count", static_cast<std::uint64_t>(r.scan.measurements.size()));
    for (std::size_t i = 0; i < r.scan.measurements.size(); ++i) {
      const Measurement<float>& m = r.scan.measurements[i];
      g.add(lbl("seed_range_", i), m.range_m);
      g.add(lbl("seed_az_", i), m.azimuth_rad);
      g.add(lbl("seed_amp_", i), m.amplitude);
    }
  }
  {
    DopplerPipeline& r = g_doppler_pipeline.make();
    fe::FrontEndParams p = small_doppler_params();
    p.doppler_window = fe::WindowType::kHann;
    p.cfar.type = fe::CfarType::kOrderedStatistic;
    g.require(r.fe.init(p) == Status::kOk, "doppler front end init");
    doppler_scene(p, r.cube);
    g.require(r.fe.process(r.cube, r.scan) == Status::kOk, "doppler front end process");
    g.add("dop_count", static_cast<std::uint64_t>(r.scan.measurements.size()));
    for (std::size_t i = 0; i < r.scan.measurements.size(); ++i) {
      const Measurement<float>& m = r.scan.measurements[i];
      g.add(lbl("dop_range_", i), m.range_m);
      g.add(lbl("dop_az_", i), m.azimuth_rad);
      g.add(lbl("dop_amp_", i), m.amplitude);
      g.add(lbl("dop_vel_", i), m.doppler_mps);
    }
  }
}

}  // namespace mptrack::test
