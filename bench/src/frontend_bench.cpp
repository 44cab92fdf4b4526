// Front end: full frame time (range matched filter, Doppler, angle FFT
// beamformer, CFAR detection and refinement) for
//   frontend/seed004  the seed 004 cube (3x3 MIMO, 256 samples, 1 chirp),
//                     frame 10 of the built-in seed004-drones ADC scenario;
//   frontend/large    LargeRadarCaps: 12 virtual channels x 256 samples x
//                     128 chirps, three movers in unit-variance noise;
//   frontend/large_int16  the same frame as 12-bit ADC codes in int16 (what a
//                     board's DMA delivers; code / 32768 = the float frame / 8,
//                     rounded to the ADC's step).
//   frontend/large_vs_fft  issue 16's ratio, each FFT stage against its FFTs'
//                     own time, with every frame followed by the FFTs it runs
//                     (3 072 x 256, 1 536 x 128, 16 384 x 32, each on an L1
//                     buffer refilled as fft/ours does): the pair sees the
//                     same machine state, so drifting load from other
//                     processes cancels; p50 and p90 over the frames.
// Counters: detections per frame and the per-stage split (thread CPU time).
#include <benchmark/benchmark.h>

#include <time.h>

#include <array>
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "bench_registry.h"
#include "frontend_test_signals.h"
#include "mptrack/adc/adc_scenario.h"
#include "mptrack/adc/frontend_config.h"
#include "mptrack/adc/synthesizer.h"
#include "mptrack/dsp/fft.h"
#include "mptrack/frontend/front_end.h"

namespace mptrack::bench {
namespace {

std::uint32_t thread_cpu_ticks() {
  // Nanoseconds of this thread's CPU time, wrapping: the front end stores
  // per-stage differences. CPU time, not wall time: on the shared host the
  // wall clock also counts the time slices other processes take.
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(ts.tv_sec) * 1000000000ull +
                                    static_cast<std::uint64_t>(ts.tv_nsec));
}

template <class Caps, class Sample = float>
struct Rig {
  frontend::FrontEnd<Caps> fe;
  frontend::RadarCubeT<Caps, Sample> cube;
  Scan<float, Caps::kMaxDetections> scan;
};

template <class Caps, class Sample>
void run_frames(benchmark::State& state, Rig<Caps, Sample>& rig) {
  frontend::FrontEndStageTimes times;
  times.clock = &thread_cpu_ticks;
  std::array<double, 4> stage_ns{};
  std::size_t detections = 0;
  for (auto _ : state) {
    const Status s = rig.fe.process(rig.cube, rig.scan, &times);
    benchmark::DoNotOptimize(s);
    detections = rig.scan.measurements.size();
    for (std::size_t i = 0; i < 4; ++i) stage_ns[i] += static_cast<double>(times.ticks[i]);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["detections"] = static_cast<double>(detections);
  state.counters["range_us"] = stage_ns[0] / n * 1e-3;
  state.counters["doppler_us"] = stage_ns[1] / n * 1e-3;
  state.counters["angle_us"] = stage_ns[2] / n * 1e-3;
  state.counters["detect_us"] = stage_ns[3] / n * 1e-3;
}

void bm_frontend_seed004(benchmark::State& state) {
  adc::AdcScenario sc;
  if (!adc::builtin_adc_scenario("seed004-drones", sc)) {
    state.SkipWithError("seed004-drones scenario missing");
    return;
  }
  auto rig = std::make_unique<Rig<frontend::Seed004RadarCaps>>();
  adc::FrameSynthesizer synth;
  std::vector<adc::DroneTruth> truth;
  if (synth.init(sc, 4, 0) != Status::kOk || synth.synthesize(10, rig->cube, truth) != Status::kOk ||
      rig->fe.init(adc::frontend_params_for(sc)) != Status::kOk) {
    state.SkipWithError("seed 004 set-up failed");
    return;
  }
  run_frames(state, *rig);
}

// 77 GHz, 60 us chirp repetition, 590 m gate (as frontend_test's large
// case); three movers in unit-variance noise.
frontend::FrontEndParams large_params(frontend::RadarCube<frontend::LargeRadarCaps>& cube) {
  frontend::FrontEndParams p;
  p.carrier_hz = 77e9;
  p.chirp_repetition_s = 60e-6;
  p.max_range_m = 590.0;
  p.max_detections = 256;
  const double bin = (299792458.0 / 77e9) / (2.0 * 128.0 * 60e-6);  // Doppler bin [m/s]
  std::array<test::SynthTarget, 3> t{};
  t[0].range_m = 212.0;
  t[0].bearing_rad = 0.35;
  t[0].radial_mps = 17.3 * bin;
  t[0].amplitude = 0.05;
  t[1].range_m = 95.0;
  t[1].bearing_rad = -0.2;
  t[1].radial_mps = -5.6 * bin;
  t[1].amplitude = 0.08;
  t[2].range_m = 410.0;
  t[2].bearing_rad = 0.05;
  t[2].radial_mps = 30.2 * bin;
  t[2].amplitude = 0.04;
  test::synthesize<frontend::LargeRadarCaps>(p, t.data(), t.size(), 1.0, 8, cube);
  return p;
}

void bm_frontend_large(benchmark::State& state) {
  using Large = frontend::LargeRadarCaps;
  auto rig = std::make_unique<Rig<Large>>();
  const frontend::FrontEndParams p = large_params(rig->cube);
  if (rig->fe.init(p) != Status::kOk) {
    state.SkipWithError("large front-end init failed");
    return;
  }
  run_frames(state, *rig);
}

void bm_frontend_large_int16(benchmark::State& state) {
  using Large = frontend::LargeRadarCaps;
  auto f = std::make_unique<frontend::RadarCube<Large>>();
  frontend::FrontEndParams p = large_params(*f);
  p.adc_bits = 12;
  auto rig = std::make_unique<Rig<Large, std::int16_t>>();
  // 12-bit codes left-justified in int16 (steps of 16): unit noise at 256
  // LSB (1/8 of full scale, code / 32768 = f / 8), clipped at the rails.
  for (std::size_t i = 0; i < f->iq.size(); ++i) {
    double code = std::nearbyint(static_cast<double>(f->iq[i]) * 256.0) * 16.0;
    code = code < -32768.0 ? -32768.0 : (code > 32752.0 ? 32752.0 : code);
    rig->cube.iq[i] = static_cast<std::int16_t>(code);
  }
  if (rig->fe.init(p) != Status::kOk) {
    state.SkipWithError("large int16 front-end init failed");
    return;
  }
  run_frames(state, *rig);
}

// Thread CPU ns of `count` forward FFTs of N, each on an aligned buffer
// refilled from src first (what fft/ours/N times per transform).
template <std::size_t N>
std::uint32_t time_ffts(const dsp::Fft<N>& fft, std::size_t count, const float* src_re,
                        const float* src_im) {
  alignas(64) static float re[N];
  alignas(64) static float im[N];
  const std::uint32_t t0 = thread_cpu_ticks();
  for (std::size_t i = 0; i < count; ++i) {
    std::memcpy(re, src_re, N * sizeof(float));
    std::memcpy(im, src_im, N * sizeof(float));
    fft.forward(re, im);
    benchmark::DoNotOptimize(re);
    benchmark::DoNotOptimize(im);
    benchmark::ClobberMemory();
  }
  return thread_cpu_ticks() - t0;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

void bm_frontend_large_vs_fft(benchmark::State& state) {
  using Large = frontend::LargeRadarCaps;
  auto rig = std::make_unique<Rig<Large>>();
  const frontend::FrontEndParams p = large_params(rig->cube);
  auto fft256 = std::make_unique<dsp::Fft<256>>();
  auto fft128 = std::make_unique<dsp::Fft<128>>();
  auto fft32 = std::make_unique<dsp::Fft<32>>();
  if (rig->fe.init(p) != Status::kOk || fft256->init() != Status::kOk ||
      fft128->init() != Status::kOk || fft32->init() != Status::kOk) {
    state.SkipWithError("large front-end or FFT init failed");
    return;
  }
  // FFT inputs: the first profile of the cube (ordinary normal floats).
  std::vector<float> src_re(256), src_im(256);
  for (std::size_t i = 0; i < 256; ++i) {
    src_re[i] = rig->cube.iq[2 * i];
    src_im[i] = rig->cube.iq[2 * i + 1];
  }
  frontend::FrontEndStageTimes times;
  times.clock = &thread_cpu_ticks;
  std::vector<double> range, doppler, angle;
  for (auto _ : state) {
    const Status s = rig->fe.process(rig->cube, rig->scan, &times);
    benchmark::DoNotOptimize(s);
    const double f256 = time_ffts(*fft256, 3072, src_re.data(), src_im.data());
    const double f128 = time_ffts(*fft128, 1536, src_re.data(), src_im.data());
    const double f32 = time_ffts(*fft32, 16384, src_re.data(), src_im.data());
    range.push_back(static_cast<double>(times.ticks[0]) / f256);
    doppler.push_back(static_cast<double>(times.ticks[1]) / f128);
    angle.push_back(static_cast<double>(times.ticks[2]) / f32);
  }
  state.counters["range_vs_fft_p50"] = percentile(range, 0.5);
  state.counters["range_vs_fft_p90"] = percentile(range, 0.9);
  state.counters["doppler_vs_fft_p50"] = percentile(doppler, 0.5);
  state.counters["doppler_vs_fft_p90"] = percentile(doppler, 0.9);
  state.counters["angle_vs_fft_p50"] = percentile(angle, 0.5);
  state.counters["angle_vs_fft_p90"] = percentile(angle, 0.9);
}

}  // namespace

void register_frontend_benchmarks() {
  benchmark::RegisterBenchmark("frontend/seed004", bm_frontend_seed004)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("frontend/large", bm_frontend_large)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("frontend/large_int16", bm_frontend_large_int16)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("frontend/large_vs_fft", bm_frontend_large_vs_fft)
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace mptrack::bench
