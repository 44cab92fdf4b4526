// Bare-metal smoke image: places core objects in .bss and exercises them so
// the linker keeps real core code (and the nm check sees what it needs).
//
// It is also the image the footprint report sizes (bench/footprint.sh):
// the seed 004 front end feeding GNN, and MF-BP with the DefaultCaps and
// SmallBoardCaps presets, all float, all statically placed. GM-PHD/CPHD
// with DefaultCaps (~240 KB each) would not fit next to them in the 512 KiB
// SRAM of cortex_m7.ld; their sizeof is reported from bench/m7_sizeof.cpp.
#include <cstdint>

#include "mptrack/caps.h"
#include "mptrack/frontend/front_end.h"
#include "mptrack/gnn/gnn_tracker.h"
#include "mptrack/measurement.h"
#include "mptrack/mfbp/mfbp_tracker.h"
#include "mptrack/status.h"

namespace {
using Fe = mptrack::frontend::FrontEnd<mptrack::frontend::Seed004RadarCaps>;
using FeCube = mptrack::frontend::RadarCubeInt16<mptrack::frontend::Seed004RadarCaps>;

// Every top-level object in .bss (zero-initialised, no constructors run).
mptrack::Scan<float, mptrack::DefaultCaps::kMaxMeasurements> g_scan;
mptrack::Scan<float, mptrack::SmallBoardCaps::kMaxMeasurements> g_scan_small;
mptrack::MfbpTracker<float, mptrack::DefaultCaps> g_mfbp_default;
mptrack::MfbpTracker<float, mptrack::SmallBoardCaps> g_mfbp_small;
mptrack::GnnTracker<float, mptrack::SmallBoardCaps> g_gnn_small;
Fe g_frontend;
FeCube g_cube;
mptrack::Scan<float, mptrack::frontend::Seed004RadarCaps::kMaxDetections> g_fe_scan;
volatile std::uint32_t g_result = 0;  // observable by a debugger

// A deterministic scan of n measurements at scan k (two slow movers + clutter).
template <std::size_t N>
void fill_scan(mptrack::Scan<float, N>& s, std::uint32_t k, std::uint32_t n) {
  s.measurements.clear();
  s.time_us = 1250000u * static_cast<std::uint64_t>(k + 1);
  std::uint32_t x = 2463534242u + k;
  for (std::uint32_t j = 0; j < n; ++j) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    mptrack::Measurement<float> m;
    if (j < 2) {
      m.range_m = 20000.0f + 9000.0f * static_cast<float>(j) + 50.0f * static_cast<float>(k);
      m.azimuth_rad = 0.5f + 0.2f * static_cast<float>(j);
      m.amplitude = 4.0f;
    } else {
      m.range_m = 10000.0f + static_cast<float>(x % 40000u);
      m.azimuth_rad = 0.1745f + 0.0000167f * static_cast<float>((x >> 8) % 52000u);
      m.amplitude = 1.0f + 0.001f * static_cast<float>((x >> 4) % 1000u);
    }
    (void)s.measurements.push_back(m);
  }
}

// One non-inlined entry per core call, so the footprint report can read the
// worst-case stack of each from GCC's call graph (-fcallgraph-info=su):
// the wrapper adds only its own few bytes.
__attribute__((noinline)) mptrack::Status stack_root_mfbp_default_step() { return g_mfbp_default.step(g_scan); }
__attribute__((noinline)) mptrack::Status stack_root_mfbp_small_step() { return g_mfbp_small.step(g_scan_small); }
__attribute__((noinline)) mptrack::Status stack_root_gnn_small_step() { return g_gnn_small.step(g_fe_scan); }
__attribute__((noinline)) mptrack::Status stack_root_frontend_process() { return g_frontend.process(g_cube, g_fe_scan); }
}  // namespace

extern "C" int app_main() {
  std::uint32_t failures = 0;
  // Capacity overflow is reported, never silent (256 + 44 over the cap).
  for (std::uint32_t j = 0; j < 300; ++j) {
    mptrack::Measurement<float> m;
    m.range_m = 100.0f + static_cast<float>(j);
    m.azimuth_rad = 0.01f * static_cast<float>(j);
    m.amplitude = 3.0f;
    if (g_scan.measurements.push_back(m) != mptrack::Status::kOk) ++failures;  // 44 overflow
  }
  // Front end -> GNN (seed 004 chain) on a zero cube: runs every stage.
  if (g_frontend.init(mptrack::frontend::FrontEndParams{}) != mptrack::Status::kOk) ++failures;
  if (g_gnn_small.init(mptrack::GnnParams<float>{}) != mptrack::Status::kOk) ++failures;
  for (std::uint32_t f = 0; f < 3; ++f) {
    g_cube.time_us = 100000u * (f + 1u);
    (void)stack_root_frontend_process();
    (void)stack_root_gnn_small_step();
  }
  // MF-BP, both presets, a few scans each.
  const auto params = mptrack::seed000_default_params<float>();
  if (g_mfbp_default.init(params) != mptrack::Status::kOk) ++failures;
  auto params_small = params;  // SmallBoardCaps: window <= 4 (caps.h)
  params_small.window_length = 4;
  params_small.slide = 2;
  if (g_mfbp_small.init(params_small) != mptrack::Status::kOk) ++failures;
  for (std::uint32_t k = 0; k < 8; ++k) {
    fill_scan(g_scan, k, 40);
    (void)stack_root_mfbp_default_step();
    fill_scan(g_scan_small, k, 20);
    (void)stack_root_mfbp_small_step();
  }
  (void)g_mfbp_default.flush();
  (void)g_mfbp_small.flush();
  g_result = failures + static_cast<std::uint32_t>(g_mfbp_default.outputs().size()) +
             static_cast<std::uint32_t>(g_mfbp_small.outputs().size());
  return 0;
}
