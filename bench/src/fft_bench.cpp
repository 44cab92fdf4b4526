// FFT: mptrack::dsp::Fft (planar, bit-exact) against FFTW float at every
// size the front end uses (radar_caps.h: range 256, Doppler 128, angle 64
// and 32; 16 for the small test configuration; 512 and 1024 for larger
// cubes), same machine, same run.
//
// FFTW setup, documented because it decides the reference: single thread
// (no fftwf_init_threads), FFTW_MEASURE planning (FFTW times candidate
// codelets and keeps the fastest: its best case, as a deployed system would
// use a wisdom file), out-of-place interleaved complex (FFTW's preferred
// layout; out-of-place c2c preserves its input, so each run transforms the
// same data). Ours is in place, so each iteration first copies the
// pristine input (2 N floats, a few ns; included, a slight handicap for
// ours). The same input values for both.
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "mptrack/dsp/fft.h"

namespace mptrack::bench {
namespace {

// Deterministic inputs in [-1, 1] (an LCG; the values do not matter for
// timing, only that they are ordinary normal floats).
void fill_input(std::size_t n, std::vector<float>& re, std::vector<float>& im) {
  re.resize(n);
  im.resize(n);
  std::uint32_t x = 12345u;
  for (std::size_t i = 0; i < n; ++i) {
    x = x * 1664525u + 1013904223u;
    re[i] = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
    x = x * 1664525u + 1013904223u;
    im[i] = static_cast<float>(static_cast<int>(x >> 9) % 20001 - 10000) * 1e-4f;
  }
}

template <std::size_t N>
void bm_fft_ours(benchmark::State& state) {
  auto fft = std::make_unique<dsp::Fft<N>>();
  if (fft->init() != Status::kOk) {
    state.SkipWithError("Fft::init failed");
    return;
  }
  std::vector<float> src_re, src_im;
  fill_input(N, src_re, src_im);
  alignas(64) static float re[N];
  alignas(64) static float im[N];
  for (auto _ : state) {
    std::memcpy(re, src_re.data(), N * sizeof(float));
    std::memcpy(im, src_im.data(), N * sizeof(float));
    fft->forward(re, im);
    benchmark::DoNotOptimize(re);
    benchmark::DoNotOptimize(im);
    benchmark::ClobberMemory();
  }
  state.counters["N"] = static_cast<double>(N);
}

template <std::size_t N>
void bm_fft_fftw(benchmark::State& state) {
  fftwf_complex* in = fftwf_alloc_complex(N);
  fftwf_complex* out = fftwf_alloc_complex(N);
  fftwf_plan plan = fftwf_plan_dft_1d(static_cast<int>(N), in, out, FFTW_FORWARD, FFTW_MEASURE);
  std::vector<float> src_re, src_im;
  fill_input(N, src_re, src_im);  // planning with FFTW_MEASURE overwrites in: fill after
  for (std::size_t i = 0; i < N; ++i) {
    in[i][0] = src_re[i];
    in[i][1] = src_im[i];
  }
  for (auto _ : state) {
    fftwf_execute(plan);
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  fftwf_destroy_plan(plan);
  fftwf_free(in);
  fftwf_free(out);
  state.counters["N"] = static_cast<double>(N);
}

template <std::size_t N>
void register_size() {
  const std::string n = std::to_string(N);
  // Interleaved ours/FFTW repetitions, so both see the same machine state;
  // the writer reports the median of each (issue 16: median of >= 5).
  for (int rep = 0; rep < 5; ++rep) {
    benchmark::RegisterBenchmark(("fft/ours/" + n).c_str(), bm_fft_ours<N>)->MinTime(0.05);
    benchmark::RegisterBenchmark(("fft/fftw/" + n).c_str(), bm_fft_fftw<N>)->MinTime(0.05);
  }
}

}  // namespace

void register_fft_benchmarks() {
  register_size<16>();
  register_size<32>();
  register_size<64>();
  register_size<128>();
  register_size<256>();
  register_size<512>();
  register_size<1024>();
}

}  // namespace mptrack::bench
