// Painted-stack high-water of the entry points that run per scan/frame:
// MfbpTracker::step (online filter and window-7 smoother), GnnTracker::step,
// GmPhdFilter::step (DefaultCaps, float) and FrontEnd<Seed004RadarCaps>::
// process. Each runs on a private stack (ucontext) pre-filled with a
// pattern; afterwards the bytes the pattern still covers, counted from the
// far end, give the deepest use. This is the measured counterpart of the
// Cortex-M7 -fstack-usage call-graph sums in docs/results/bench/footprint.json, and runs
// on every Linux target (host, and aarch64/armhf under qemu-user). The
// objects and the scans live on the heap, so only the call's own frames
// count. The empty-call overhead (makecontext trampoline) is subtracted.
//
// Budgets (bench/README.md "Stack"): each figure must stay under the
// budget below on every target; ./run bench writes the measured bytes to
// build/bench-results/footprint.json ("painted_stack"), via MPTRACK_STACK_JSON=<file>.
#include <doctest/doctest.h>

#include <ucontext.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "../unit/frontend_test_signals.h"
#include "mfbp_scenario.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/phd/phd_filter.h"

namespace {

using mptrack::Status;

// Budgets [bytes] of the deepest step()/process() stack on a Linux target
// (x86-64, aarch64, armhf). Measured (GCC 12, -O3): MF-BP 2936 / 3152 /
// 2912 B, GNN 464 / 640 / 384 B, GM-PHD 672 / 896 / 696 B, front end
// 952 / 1120 / 740 B (x86-64 / aarch64 / armhf). The MF-BP budget is the
// Cortex-M7 call-graph figure's order (docs/results/bench/footprint.json); the others
// leave about 2x headroom over the largest target.
constexpr std::size_t kBudgetMfbp = 6 * 1024;
constexpr std::size_t kBudgetGnn = 1536;
constexpr std::size_t kBudgetPhd = 2 * 1024;
constexpr std::size_t kBudgetFrontEnd = 2 * 1024;

constexpr std::size_t kStackBytes = 256 * 1024;
constexpr unsigned char kPaint = 0xA5;

using Work = void (*)(void*);

struct Call {
  Work fn;
  void* arg;
};

ucontext_t g_main;
ucontext_t g_work;
Call g_call;

void trampoline() { g_call.fn(g_call.arg); }

// Runs fn(arg) on a freshly painted stack; returns the bytes it touched.
std::size_t painted_high_water(Work fn, void* arg) {
  std::vector<unsigned char> stack(kStackBytes, kPaint);
  g_call = Call{fn, arg};
  REQUIRE(getcontext(&g_work) == 0);
  g_work.uc_stack.ss_sp = stack.data();
  g_work.uc_stack.ss_size = stack.size();
  g_work.uc_link = &g_main;
  makecontext(&g_work, &trampoline, 0);
  REQUIRE(swapcontext(&g_main, &g_work) == 0);
  // The stack grows down on every supported target: untouched bytes are at the low end.
  std::size_t untouched = 0;
  while (untouched < stack.size() && stack[untouched] == kPaint) ++untouched;
  return stack.size() - untouched;
}

void nothing(void*) {}

std::size_t overhead() {
  static const std::size_t o = painted_high_water(&nothing, nullptr);
  return o;
}

std::size_t measure(Work fn, void* arg) {
  const std::size_t used = painted_high_water(fn, arg);
  return used > overhead() ? used - overhead() : 0;
}

// --- workloads (everything on the heap; the work function only steps) ---

constexpr int kScans = 40;
constexpr std::size_t kClutter = 30;

template <class Tracker>
struct TrackerRun {
  std::unique_ptr<Tracker> tracker = std::make_unique<Tracker>();
  std::vector<std::unique_ptr<typename Tracker::ScanType>> scans;
  int not_ok = 0;
  void make_scans() {
    mfbp_test::Lcg rng;
    for (int k = 0; k < kScans; ++k) {
      scans.push_back(std::make_unique<typename Tracker::ScanType>());
      mfbp_test::make_scan(rng, k, kClutter, *scans.back());
    }
  }
  static void work(void* p) {
    auto* self = static_cast<TrackerRun*>(p);
    for (const auto& s : self->scans) {
      const Status st = self->tracker->step(*s);
      if (st != Status::kOk && st != Status::kPartial) ++self->not_ok;
    }
  }
};

using Mfbp = mptrack::MfbpTracker<float, mptrack::DefaultCaps>;
using Gnn = mptrack::GnnTracker<float, mptrack::DefaultCaps>;
using Phd = mptrack::GmPhdFilter<float, mptrack::DefaultCaps>;
using FeCaps = mptrack::frontend::Seed004RadarCaps;

std::size_t mfbp_stack(std::size_t window, std::size_t slide) {
  TrackerRun<Mfbp> run;
  mptrack::MfbpParams<float> p = mptrack::seed000_default_params<float>();
  p.window_length = window;
  p.slide = slide;
  p.uniform_rate_per_scan = static_cast<float>(kClutter);
  REQUIRE(run.tracker->init(p) == Status::kOk);
  run.make_scans();
  const std::size_t used = measure(&TrackerRun<Mfbp>::work, &run);
  CHECK(run.not_ok == 0);
  CHECK(run.tracker->live_tracks() >= 2u);  // the path with tracks was exercised
  return used;
}

struct FrontEndRun {
  std::unique_ptr<mptrack::frontend::FrontEnd<FeCaps>> fe =
      std::make_unique<mptrack::frontend::FrontEnd<FeCaps>>();
  std::vector<std::unique_ptr<mptrack::frontend::RadarCube<FeCaps>>> cubes;
  std::unique_ptr<mptrack::Scan<float, FeCaps::kMaxDetections>> scan =
      std::make_unique<mptrack::Scan<float, FeCaps::kMaxDetections>>();
  std::size_t detections = 0;
  int not_ok = 0;
  static void work(void* p) {
    auto* self = static_cast<FrontEndRun*>(p);
    for (const auto& c : self->cubes) {
      if (self->fe->process(*c, *self->scan) != Status::kOk) ++self->not_ok;
      self->detections += self->scan->measurements.size();
    }
  }
};

void report(const char* key, std::size_t bytes, std::size_t budget) {
  MESSAGE(std::string(key) << ": " << bytes << " B (budget " << budget << " B)");
  const char* path = std::getenv("MPTRACK_STACK_JSON");
  if (path == nullptr || *path == '\0') return;
  // One "key": bytes line per figure; ./run bench assembles the object.
  if (std::FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "\"%s\": %zu\n", key, bytes);
    std::fclose(f);
  }
}

}  // namespace

#if defined(MPTRACK_SANITIZE) || defined(__SANITIZE_ADDRESS__)
#error "stack_test is not built with the sanitizers (tests/CMakeLists.txt)"
#endif
TEST_CASE("stack: the painted-stack probe sees a known 16 KiB frame") {
  struct Probe {
    static void work(void*) {
      volatile unsigned char big[16 * 1024];
      for (std::size_t i = 0; i < sizeof big; i += 64) big[i] = 0;
      big[sizeof big - 1] = 0;
    }
  };
  const std::size_t used = measure(&Probe::work, nullptr);
  // Within the empty-call overhead (a few hundred bytes of trampoline and
  // saved registers, which the subtraction removes approximately).
  CHECK(used >= 16u * 1024u - 512u);
  CHECK(used < 17u * 1024u);
}

TEST_CASE("stack: MF-BP online filter step() stays within its budget") {
  const std::size_t used = mfbp_stack(1, 1);
  report("mfbp_filter_step_default", used, kBudgetMfbp);
  CHECK(used > 0u);
  CHECK(used <= kBudgetMfbp);
}

TEST_CASE("stack: MF-BP window-7 smoother step() stays within its budget") {
  const std::size_t used = mfbp_stack(7, 3);
  report("mfbp_window7_step_default", used, kBudgetMfbp);
  CHECK(used > 0u);
  CHECK(used <= kBudgetMfbp);
}

TEST_CASE("stack: GNN step() stays within its budget") {
  TrackerRun<Gnn> run;
  REQUIRE(run.tracker->init(Gnn::Params{}) == Status::kOk);
  run.make_scans();
  const std::size_t used = measure(&TrackerRun<Gnn>::work, &run);
  CHECK(run.not_ok == 0);
  report("gnn_step_default", used, kBudgetGnn);
  CHECK(used > 0u);
  CHECK(used <= kBudgetGnn);
}

TEST_CASE("stack: GM-PHD step() stays within its budget") {
  TrackerRun<Phd> run;
  mptrack::RfsFilterParams<float> p;
  p.clutter_rate = static_cast<float>(kClutter);
  REQUIRE(run.tracker->init(p) == Status::kOk);
  run.make_scans();
  const std::size_t used = measure(&TrackerRun<Phd>::work, &run);
  CHECK(run.not_ok == 0);
  report("gmphd_step_default", used, kBudgetPhd);
  CHECK(used > 0u);
  CHECK(used <= kBudgetPhd);
}

TEST_CASE("stack: front end process() (seed 004 cube) stays within its budget") {
  FrontEndRun run;
  mptrack::frontend::FrontEndParams p;
  p.range_window = mptrack::frontend::WindowType::kHamming;
  p.angle_window = mptrack::frontend::WindowType::kHann;
  REQUIRE(run.fe->init(p) == Status::kOk);
  for (int f = 0; f < 4; ++f) {
    mptrack::test::SynthTarget t[2];
    t[0].range_m = 28.3 + f;
    t[0].bearing_rad = 0.25;
    t[0].amplitude = 1.0;
    t[1].range_m = 61.0 - f;
    t[1].bearing_rad = -0.6;
    t[1].amplitude = 0.7;
    run.cubes.push_back(std::make_unique<mptrack::frontend::RadarCube<FeCaps>>());
    mptrack::test::synthesize<FeCaps>(p, t, 2, 1.0, 11 + static_cast<std::uint64_t>(f), *run.cubes.back());
    run.cubes.back()->time_us = 100000u * static_cast<std::uint64_t>(f + 1);
  }
  const std::size_t used = measure(&FrontEndRun::work, &run);
  CHECK(run.not_ok == 0);
  CHECK(run.detections >= 4u);
  report("frontend_process_seed004", used, kBudgetFrontEnd);
  CHECK(used > 0u);
  CHECK(used <= kBudgetFrontEnd);
}
