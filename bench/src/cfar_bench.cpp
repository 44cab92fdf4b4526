// CFAR cost per cell (issue 16): the whole-line detector cfar_line() (sliding
// integer sums for CA, sorted window or order-statistic heaps for OS) against Cfar::test() called at
// every cell (O(T) gather per cell), on unit exponential noise.
//   cfar/<line|test>/<ca|os>/cells:<n>/T:<t>   guard 2
// Sweeps: cells 256..65535 at T 8 (cost linear in cells = flat per cell),
// T 2..64 at 4096 cells, and for cfar_line T 2..64 at 65535 cells (flat per
// cell for CA; OS: sorted window up to 2T = 32, O(log T) heaps above).
// Every iteration runs at least kCellsPerIteration cells as distinct lines of
// `cells` (fresh noise in each): with one short line repeated, the branch
// predictor learned the line across iterations and flattered the branchy OS
// paths on short lines (session 14: OS 33 ns a cell at 256-4 096 cells, 51 at
// 65 535), which is not what a front end sees.
//   cfar/screen/ca/cells:<n>/T:<t>   CfarScreen (cfar_screen.h), the
//     detector's threshold-first pass: cells that may pass CA-CFAR, guard 2
// Counter ns_per_cell: CPU time per cell.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "mptrack/frontend/cfar_line.h"
#include "mptrack/frontend/cfar_screen.h"

namespace mptrack::bench {
namespace {

// Detector of `type` with guard 2 and T = state.range(1), pfa 1e-4; false
// (benchmark skipped) if init fails.
bool make_cfar(benchmark::State& state, frontend::CfarType type, frontend::Cfar& cfar) {
  frontend::CfarParams p;
  p.type = type;
  p.pfa = 1e-4;
  p.guard_cells = 2;
  p.training_cells = static_cast<std::size_t>(state.range(1));
  if (cfar.init(p) == Status::kOk) return true;
  state.SkipWithError("cfar init failed");
  return false;
}

/// Unit exponential noise (the power of complex Gaussian noise).
std::vector<float> noise_line(std::size_t cells) {
  std::mt19937_64 rng(16);
  std::exponential_distribution<float> expo(1.0f);
  std::vector<float> line(cells);
  for (float& x : line) x = expo(rng);
  return line;
}

constexpr std::size_t kCellsPerIteration = 65536;

void bm_cfar(benchmark::State& state, bool line_mode, frontend::CfarType type) {
  const auto cells = static_cast<std::size_t>(state.range(0));
  frontend::Cfar cfar;
  if (!make_cfar(state, type, cfar)) return;
  const std::size_t lines = (kCellsPerIteration + cells - 1) / cells;
  const std::vector<float> data = noise_line(lines * cells);
  std::vector<frontend::CfarResult> out(lines * cells);
  for (auto _ : state) {
    for (std::size_t l = 0; l < lines; ++l) {
      const float* line = data.data() + l * cells;
      frontend::CfarResult* res = out.data() + l * cells;
      if (line_mode) {
        benchmark::DoNotOptimize(frontend::cfar_line(cfar, line, cells, res));
      } else {
        for (std::size_t i = 0; i < cells; ++i) res[i] = cfar.test(line, cells, i);
      }
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_cell"] = benchmark::Counter(static_cast<double>(lines * cells) * 1e-9,
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

template <std::size_t kCells>
void bm_cfar_screen(benchmark::State& state) {
  frontend::Cfar cfar;
  if (!make_cfar(state, frontend::CfarType::kCellAveraging, cfar)) return;
  const std::vector<float> line = noise_line(kCells);
  auto screen = std::make_unique<frontend::CfarScreen<kCells>>();
  for (auto _ : state) {
    benchmark::DoNotOptimize(screen->run(cfar, line.data(), 0, kCells));
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_cell"] = benchmark::Counter(
      static_cast<double>(kCells) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <std::size_t kCells>
void register_screen(std::initializer_list<long> trains) {
  auto* b = benchmark::RegisterBenchmark("cfar/screen/ca", bm_cfar_screen<kCells>);
  b->ArgNames({"cells", "T"})->Unit(benchmark::kMicrosecond);
  for (long t : trains) b->Args({static_cast<long>(kCells), t});
}

}  // namespace

void register_cfar_benchmarks() {
  register_screen<128>({8});
  register_screen<1024>({8});
  register_screen<4096>({2, 4, 8, 16, 32, 64});
  register_screen<16384>({8});
  register_screen<65535>({8});
  for (bool line_mode : {true, false}) {
    for (frontend::CfarType type : {frontend::CfarType::kCellAveraging, frontend::CfarType::kOrderedStatistic}) {
      const std::string name = std::string("cfar/") + (line_mode ? "line" : "test") + "/" +
                               (type == frontend::CfarType::kOrderedStatistic ? "os" : "ca");
      auto* b = benchmark::RegisterBenchmark(name.c_str(), [line_mode, type](benchmark::State& s) {
        bm_cfar(s, line_mode, type);
      });
      b->ArgNames({"cells", "T"})->Unit(benchmark::kMicrosecond);
      for (long n : {256L, 1024L, 4096L, 16384L, 65535L}) b->Args({n, 8});
      for (long t : {2L, 4L, 16L, 32L, 64L}) b->Args({4096, t});
      // The same T sweep on single long lines (per-line set-up amortised).
      if (line_mode) {
        for (long t : {2L, 4L, 8L, 16L, 24L, 32L, 64L}) b->Args({65535, t});
      }
    }
  }
}

}  // namespace mptrack::bench
