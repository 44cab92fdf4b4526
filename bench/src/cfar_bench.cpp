// CFAR cost per cell (issue 16): the whole-line detector cfar_line() (sliding
// integer sums for CA, sorted window for OS) against Cfar::test() called at
// every cell (O(T) gather per cell), on unit exponential noise.
//   cfar/<line|test>/<ca|os>/cells:<n>/T:<t>   guard 2
// Sweeps: cells 256..65535 at T 8 (cost linear in cells = flat per cell),
// T 2..64 at 4096 cells (flat per cell for CA; OS per-cell moves grow with T).
// Counter ns_per_cell: CPU time per cell.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "mptrack/frontend/cfar_line.h"

namespace mptrack::bench {
namespace {

void bm_cfar(benchmark::State& state, bool line_mode, frontend::CfarType type) {
  const auto cells = static_cast<std::size_t>(state.range(0));
  const auto train = static_cast<std::size_t>(state.range(1));
  frontend::CfarParams p;
  p.type = type;
  p.pfa = 1e-4;
  p.guard_cells = 2;
  p.training_cells = train;
  frontend::Cfar cfar;
  if (cfar.init(p) != Status::kOk) {
    state.SkipWithError("cfar init failed");
    return;
  }
  std::mt19937_64 rng(16);
  std::exponential_distribution<float> expo(1.0f);
  std::vector<float> line(cells);
  for (float& x : line) x = expo(rng);
  std::vector<frontend::CfarResult> out(cells);
  for (auto _ : state) {
    if (line_mode) {
      benchmark::DoNotOptimize(frontend::cfar_line(cfar, line.data(), cells, out.data()));
    } else {
      for (std::size_t i = 0; i < cells; ++i) out[i] = cfar.test(line.data(), cells, i);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_cell"] = benchmark::Counter(
      static_cast<double>(cells) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

void register_cfar_benchmarks() {
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
    }
  }
}

}  // namespace mptrack::bench
