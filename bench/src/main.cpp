// mptrack-bench: the benchmark suite behind `./run bench`.
//
//   mptrack-bench [--out DIR] [--quick] [--no-write] [--benchmark_* flags]
//
// Runs every benchmark group (FFT vs FFTW, front-end frame, tracker
// latency on seed 000 S2 and on the workload grid), prints Google
// Benchmark's console output, then writes DIR/results.json and
// DIR/latency.svg (DIR defaults to <build>/bench/results, created if
// missing; never the source tree) and prints a
// summary table with the goals of the performance issue.
// --quick: a reduced workload grid (about a minute).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "results_writer.h"

namespace {

// Console output as usual, and a copy of every non-aggregate run for the writer.
class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& reports) override {
    for (const Run& r : reports) {
      if (r.run_type != Run::RT_Iteration) continue;
      mptrack::bench::RunRecord rec;
      rec.name = r.benchmark_name();
      rec.error = r.error_occurred;
      rec.iterations = static_cast<double>(r.iterations);
      rec.time_ns = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9;
      rec.cpu_ns = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9;
      for (const auto& kv : r.counters) rec.counters[kv.first] = kv.second.value;
      records.push_back(rec);
    }
    ConsoleReporter::ReportRuns(reports);
  }
  std::vector<mptrack::bench::RunRecord> records;
};

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = MPTRACK_BENCH_DIR;
  bool quick = false;
  bool write = true;
  bool has_min_time = false;
  std::vector<char*> args;
  args.push_back(argv[0]);
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--no-write") == 0) {
      write = false;
    } else {
      if (std::strncmp(argv[i], "--benchmark_min_time", 20) == 0) has_min_time = true;
      args.push_back(argv[i]);
    }
  }
  // Short default: the tracker benchmarks time 30-340 scans per iteration,
  // so 0.1 s per benchmark already averages thousands of steps.
  static char min_time[] = "--benchmark_min_time=0.1";
  if (!has_min_time) args.push_back(min_time);
  int n = static_cast<int>(args.size());
  args.push_back(nullptr);

  mptrack::bench::register_fft_benchmarks();
  mptrack::bench::register_frontend_benchmarks();
  mptrack::bench::register_cfar_benchmarks();
  mptrack::bench::register_tracker_benchmarks(quick);

  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 2;
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  if (!write) return 0;
  mptrack::bench::MachineInfo machine;
  const benchmark::CPUInfo& cpu = benchmark::CPUInfo::Get();
  machine.num_cpus = cpu.num_cpus;
  machine.mhz_per_cpu = cpu.cycles_per_second * 1e-6;
#ifdef NDEBUG
  machine.build_type = "Release";
#else
  machine.build_type = "Debug";
#endif
  machine.compiler = __VERSION__;
  machine.timestamp_utc = utc_now();
  return mptrack::bench::write_results(out_dir, reporter.records, machine) ? 0 : 1;
}
