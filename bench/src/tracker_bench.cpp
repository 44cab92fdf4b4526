// Tracker per-scan latency.
//
//   s2/<tracker>/<scalar>              seed 000 S2, all 340 scans, run 0, seed 0:
//                                      init untimed, every step timed.
//   grid/<tracker>/<scalar>/T../M../C..  steady state on a synthetic workload
//                                      (workload.h): 15 warm-up scans once, then
//                                      per iteration the warmed tracker is copied
//                                      (untimed) and 30 scans are stepped (timed).
//
// Trackers: mfbp-filter (MF-BP online, window 1), mfbp (window 7, slide 3:
// the time per scan is the cost per output scan), mfbp-s1 (window 7, slide
// 1, every_scan_smoother_params(); S2 only), gmphd, gmcphd, gnn.
// Manual timing: only step() calls are on the clock (the thread's CPU time
// around each call); counters give the mean, p50, p99 and max per scan [us].
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "bench_registry.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"
#include "workload.h"

namespace mptrack::bench {
namespace {

constexpr std::uint64_t kSeed = 0;
constexpr std::uint32_t kWarmScans = 15;
constexpr std::uint32_t kTimedScans = 30;  // a multiple of the smoother's slide (3)

enum class Kind { kMfbpFilter, kMfbpSmoother, kMfbpEveryScan, kGmPhd, kGmCphd, kGnn };

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::kMfbpFilter: return "mfbp-filter";
    case Kind::kMfbpSmoother: return "mfbp";
    case Kind::kMfbpEveryScan: return "mfbp-s1";
    case Kind::kGmPhd: return "gmphd";
    case Kind::kGmCphd: return "gmcphd";
    case Kind::kGnn: return "gnn";
  }
  return "?";
}

template <class Tracker, class T>
typename Tracker::Params params_for(Kind k, const scenario::ScenarioSpec& s) {
  if constexpr (std::is_same_v<typename Tracker::Params, MfbpParams<T>>) {
    if (k == Kind::kMfbpEveryScan) return mfbp_params_for<T>(s, 7, every_scan_smoother_params<T>());
    return mfbp_params_for<T>(s, k == Kind::kMfbpFilter ? 1 : 7);
  } else if constexpr (std::is_same_v<typename Tracker::Params, RfsFilterParams<T>>) {
    return phd_params_for<T>(s);
  } else {
    return gnn_params_for<T>(s);
  }
}

// Scans of the current workload, shared by the trackers benchmarked on it
// (benchmarks run in registration order, so one cached key suffices).
template <class T, std::size_t N>
struct ScanCache {
  using ScanPtr = std::unique_ptr<Scan<T, N>>;
  static const std::vector<ScanPtr>& get(const std::string& key, const scenario::ScenarioSpec& spec,
                                         std::uint32_t count) {
    static std::string cached_key;
    static std::vector<ScanPtr> scans;
    if (key != cached_key) {
      scans = generate_scans<T, N>(spec, kSeed, 1, count);
      cached_key = key;
    }
    return scans;
  }
};

struct StepStats {
  std::vector<double> step_s;  ///< every timed step of every iteration [s]
  std::uint64_t bad_status = 0;
  void report(benchmark::State& state, std::size_t scans_per_iter, double meas_per_scan) const {
    std::vector<double> v = step_s;
    std::sort(v.begin(), v.end());
    auto pct = [&v](double q) {
      if (v.empty()) return 0.0;
      const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
      return v[i] * 1e6;
    };
    double sum = 0.0;
    for (double x : step_s) sum += x;
    state.counters["scan_us"] = v.empty() ? 0.0 : sum / static_cast<double>(v.size()) * 1e6;
    state.counters["p50_us"] = pct(0.50);
    state.counters["p99_us"] = pct(0.99);
    state.counters["max_us"] = v.empty() ? 0.0 : v.back() * 1e6;
    state.counters["scans"] = static_cast<double>(scans_per_iter);
    state.counters["meas"] = meas_per_scan;
    state.counters["not_ok"] = static_cast<double>(bad_status);
  }
};

// The calling thread's CPU time [s]: on a shared machine, time slices
// given to other processes do not count (wall time would add them to
// whichever step was running). The clock read costs well under 1 us.
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

template <class Tracker>
double time_steps(Tracker& tr, const std::vector<std::unique_ptr<typename Tracker::ScanType>>& scans,
                  std::size_t first, StepStats& stats) {
  double total = 0.0;
  for (std::size_t k = first; k < scans.size(); ++k) {
    const double t0 = thread_cpu_s();
    const Status s = tr.step(*scans[k]);
    const double t1 = thread_cpu_s();
    benchmark::DoNotOptimize(s);
    if (s != Status::kOk) ++stats.bad_status;
    const double dt = t1 - t0;
    stats.step_s.push_back(dt);
    total += dt;
  }
  return total;
}

template <class Scans>
double mean_measurements(const Scans& scans, std::size_t first) {
  double n = 0.0;
  for (std::size_t k = first; k < scans.size(); ++k) n += static_cast<double>(scans[k]->measurements.size());
  return scans.size() > first ? n / static_cast<double>(scans.size() - first) : 0.0;
}

// Seed 000 S2: the whole run per iteration.
template <class Tracker, class T>
void bm_s2(benchmark::State& state, Kind kind) {
  using Caps = DefaultCaps;
  const scenario::ScenarioSpec spec = seed000_s2();
  const auto& scans = ScanCache<T, Caps::kMaxMeasurements>::get("s2", spec, spec.num_scans);
  auto tr = std::make_unique<Tracker>();
  const auto params = params_for<Tracker, T>(kind, spec);
  StepStats stats;
  for (auto _ : state) {
    if (tr->init(params) != Status::kOk) {
      state.SkipWithError("init failed");
      return;
    }
    double t = time_steps(*tr, scans, 0, stats);
    t += [&] {
      const double t0 = thread_cpu_s();
      benchmark::DoNotOptimize(tr->flush());
      return thread_cpu_s() - t0;
    }();
    state.SetIterationTime(t);
  }
  stats.report(state, scans.size(), mean_measurements(scans, 0));
}

// Workload grid: steady-state latency.
template <class Tracker, class T>
void bm_grid(benchmark::State& state, Kind kind, Workload w) {
  using Caps = BenchCaps;
  const scenario::ScenarioSpec spec = workload_spec(w, kWarmScans + kTimedScans);
  const auto& scans = ScanCache<T, Caps::kMaxMeasurements>::get(spec.name, spec, spec.num_scans);
  auto warmed = std::make_unique<Tracker>();
  auto tr = std::make_unique<Tracker>();
  if (warmed->init(params_for<Tracker, T>(kind, spec)) != Status::kOk) {
    state.SkipWithError("init failed");
    return;
  }
  for (std::uint32_t k = 0; k < kWarmScans; ++k) (void)warmed->step(*scans[k]);
  StepStats stats;
  for (auto _ : state) {
    *tr = *warmed;
    state.SetIterationTime(time_steps(*tr, scans, kWarmScans, stats));
  }
  stats.report(state, kTimedScans, mean_measurements(scans, kWarmScans));
  state.counters["targets"] = w.targets;
  state.counters["comps"] = w.clutter_components;
  state.counters["meas_nominal"] = w.measurements;
}

template <class T>
const char* scalar_name() {
  return std::is_same_v<T, float> ? "float" : "double";
}

template <class T>
void register_s2(Kind kind) {
  const std::string name = std::string("s2/") + kind_name(kind) + "/" + scalar_name<T>();
  auto fn = [kind](benchmark::State& st) {
    switch (kind) {
      case Kind::kMfbpFilter:
      case Kind::kMfbpSmoother:
      case Kind::kMfbpEveryScan: bm_s2<MfbpTracker<T, DefaultCaps>, T>(st, kind); break;
      case Kind::kGmPhd: bm_s2<GmPhdFilter<T, DefaultCaps>, T>(st, kind); break;
      case Kind::kGmCphd: bm_s2<GmCphdFilter<T, DefaultCaps>, T>(st, kind); break;
      case Kind::kGnn: bm_s2<GnnTracker<T, DefaultCaps>, T>(st, kind); break;
    }
  };
  benchmark::RegisterBenchmark(name.c_str(), fn)->UseManualTime()->Unit(benchmark::kMicrosecond);
}

template <class T>
void register_grid(Kind kind, const Workload& w) {
  const std::string name = std::string("grid/") + kind_name(kind) + "/" + scalar_name<T>() + "/T" +
                           std::to_string(w.targets) + "/M" + std::to_string(w.measurements) + "/C" +
                           std::to_string(w.clutter_components);
  auto fn = [kind, w](benchmark::State& st) {
    switch (kind) {
      case Kind::kMfbpFilter:
      case Kind::kMfbpSmoother:
      case Kind::kMfbpEveryScan: bm_grid<MfbpTracker<T, BenchCaps>, T>(st, kind, w); break;
      case Kind::kGmPhd: bm_grid<GmPhdFilter<T, BenchCaps>, T>(st, kind, w); break;
      case Kind::kGmCphd: bm_grid<GmCphdFilter<T, BenchCaps>, T>(st, kind, w); break;
      case Kind::kGnn: bm_grid<GnnTracker<T, BenchCaps>, T>(st, kind, w); break;
    }
  };
  benchmark::RegisterBenchmark(name.c_str(), fn)->UseManualTime()->Unit(benchmark::kMicrosecond);
}

}  // namespace

void register_tracker_benchmarks(bool quick) {
  const Kind all[] = {Kind::kMfbpFilter, Kind::kMfbpSmoother, Kind::kGmPhd, Kind::kGmCphd, Kind::kGnn};
  // mfbp-s1 (the hard-clutter configuration) on S2 only: on the grid it
  // would double the smoother's share of the run for one more curve.
  for (Kind k : all) register_s2<float>(k);
  register_s2<float>(Kind::kMfbpEveryScan);
  for (Kind k : all) register_s2<double>(k);
  register_s2<double>(Kind::kMfbpEveryScan);

  // One-axis sweeps around (T 8, M 128, C 2): what each axis costs on its own.
  std::vector<Workload> grid;
  const std::vector<std::uint32_t> ts = quick ? std::vector<std::uint32_t>{1, 8, 64}
                                              : std::vector<std::uint32_t>{1, 2, 4, 8, 16, 32, 64};
  const std::vector<std::uint32_t> ms = quick ? std::vector<std::uint32_t>{10, 128, 512}
                                              : std::vector<std::uint32_t>{10, 32, 64, 128, 256, 512};
  const std::vector<std::uint32_t> cs = quick ? std::vector<std::uint32_t>{0, 2, 8}
                                              : std::vector<std::uint32_t>{0, 1, 2, 4, 8};
  for (std::uint32_t t : ts) grid.push_back({t, 128, 2});
  for (std::uint32_t m : ms) {
    if (m != 128) grid.push_back({8, m, 2});
  }
  for (std::uint32_t c : cs) {
    if (c != 2) grid.push_back({8, 128, c});
  }
  for (const Workload& w : grid) {
    for (Kind k : all) register_grid<float>(k, w);
  }
  // Double on the measurement sweep for the online filters (host harness precision).
  for (std::uint32_t m : ms) {
    register_grid<double>(Kind::kMfbpFilter, {8, m, 2});
    register_grid<double>(Kind::kGmPhd, {8, m, 2});
  }
}

}  // namespace mptrack::bench
